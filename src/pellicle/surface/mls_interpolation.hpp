#pragma once
//! Interpolation of what the points carry to a new place, for points created in holes and
//! points merged into one (Suchde & Kuhnert §3.4–3.5): a second-order moving least-squares
//! fit in the tangent plane of the place's frame. It is the constrained weighted least
//! squares of the GFDM stencils (pointcloud/local_fit.hpp, eqs 18–19) with the value at the centre
//! as the only target (b = e_0): the coefficients reproduce every monomial up to order 2 in the
//! tangent coordinates, so quadratic fields on a plane are interpolated exactly.

#include <vector>

#include "pellicle/pointcloud/local_fit.hpp"
#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

//! The interpolation's coefficients at one place: value = Σ_k weight[k] u(index[k]).
struct MlsWeights {
  int count = 0;
  int index[kMaxStencilPoints];
  double weight[kMaxStencilPoints];
};

//! How the coefficients were found: the second-order fit within h, within 1.5 h or 2 h when
//! the h-neighbourhood does not fix it (too few points, all on a line), or — when none does —
//! the Gaussian-weighted mean of the points within 2 h (first order).
enum class MlsFit { second_order, widened, weighted_mean, none };

//! Coefficients at x from the points of `cloud` within h of x (the nearest
//! kMaxStencilPoints of them when there are more), with W = exp(−c r²/h²) (c =
//! `weight_exponent`) and the tangent plane of `frame` (columns t_1, …, n). `search` must
//! hold the cloud as it is now (see NeighbourSearch::around). Safe to call from several
//! threads at once. `none` means no point within 2 h. With `part_of` ≥ 0 only the points on
//! that point's part (with the frame's normal) take part.
template <int D>
MlsFit mls_weights(const PointCloud<D>& cloud, const NeighbourSearch<D>& search, const Vec<D>& x,
                   const Mat<D>& frame, double h, double weight_exponent, MlsWeights& weights,
                   int part_of = -1);

//! Every per-point quantity besides position, frame and boundary data, at a set of places:
//! smoothing length, velocity, previous velocity (valid where has_previous_velocity) and
//! each field of the cloud, in the cloud's field order.
template <int D>
struct CarriedValues {
  std::vector<double> smoothing_length;
  std::vector<Vec<D>> velocity;
  std::vector<Vec<D>> previous_velocity;
  std::vector<std::uint8_t> has_previous_velocity;
  std::vector<std::vector<double>> fields;
  std::size_t size() const { return smoothing_length.size(); }
};

//! The place of an interpolation: position, frame, and the h of its fit.
template <int D>
struct MlsTarget {
  Vec<D> position;
  Mat<D> frame;
  double h;
  //! A point of the part the new point belongs to: the fit takes only points on that part
  //! (PointCloud::on_part with the frame's normal). −1: every point.
  int part_of = -1;
};

//! Interpolate every quantity of `cloud` to `targets` (in parallel). A previous velocity is
//! interpolated where every point the fit uses has one; elsewhere the target gets none
//! (eq 3 then falls back to eq 2 there). Returns the number of targets whose fit fell back
//! to a widened neighbourhood or the weighted mean. Throws NumericalError when a target has
//! no point within 2 h.
template <int D>
long interpolate_carried(const PointCloud<D>& cloud, const NeighbourSearch<D>& search,
                         const std::vector<MlsTarget<D>>& targets, double weight_exponent,
                         CarriedValues<D>& values);

//! Write target q of `values` into point i of `cloud`.
template <int D>
void store_carried(const CarriedValues<D>& values, std::size_t q, PointCloud<D>& cloud,
                   std::size_t i);

}  // namespace pellicle
