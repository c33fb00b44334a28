#include "pellicle/normals/colour_function.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <unordered_map>

#include "pellicle/core/bspline.hpp"
#include "pellicle/normals/mirror_images.hpp"
#include "pellicle/normals/principal_directions.hpp"
#include "pellicle/pointcloud/cell_groups.hpp"

namespace pellicle {

namespace {

using Spline = int (*)(double, double*, double*);

//! Visit the tensor-product stencil of a spline at ξ (unit spacing): f(index, N, ∇N).
template <int D, int W, class F>
void stencil(Spline spline, const Vec<D>& xi, F&& f) {
  double w[D][W], dw[D][W];
  IVec<D> base;
  for (int d = 0; d < D; ++d) base[d] = spline(xi[d], w[d], dw[d]);
  for (int k = 0; k < static_cast<int>(std::pow(W, D)); ++k) {
    IVec<D> index;
    int rest = k;
    double N = 1.0;
    Vec<D> g = Vec<D>::Ones();
    for (int d = 0; d < D; ++d) {
      const int a = rest % W;
      rest /= W;
      index[d] = base[d] + a;
      N *= w[d][a];
      for (int e = 0; e < D; ++e) g[e] *= e == d ? dw[d][a] : w[d][a];
    }
    f(index, N, g);
  }
}

enum class Colour { simple, quadratic, cubic };

template <int D>
class ColourFunction final : public FrameEstimator<D> {
 public:
  ColourFunction(const FrameSetup<D>& setup, Colour kind) : setup_(setup), kind_(kind) {}

  void estimate(const std::vector<Vec<D>>& position, long begin, long end,
                std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) override {
    frames(position, begin, end, normal, tangent,
           planes_ended_on<D>(position, begin, end, setup_.mirrors, setup_.cell));
  }

  //! A point's normal takes the node values of its cell's corners (simple), which sum the
  //! points of the cells around them, or of the 4^D nodes of its cubic stencil, which sum
  //! the points within two cells of them. The quadratic variant sums node normals over cells
  //! in hash-table order, which depends on every cell the body covers.
  int reach() const override {
    return kind_ == Colour::simple ? 1 : kind_ == Colour::cubic ? 3 : -1;
  }
  unsigned planes_touched(const std::vector<Vec<D>>& position, long begin,
                          long end) const override {
    return mirrors_touched<D>(position, begin, end, setup_.mirrors, setup_.cell);
  }
  bool estimate_part(const BodyPart& part, const std::vector<Vec<D>>& position,
                     std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) override {
    if (reach() < 0) return false;
    frames(position, 0, static_cast<long>(position.size()), normal, tangent,
           planes_ended_on(part.planes, setup_.mirrors));
    return true;
  }

 private:
  FrameSetup<D> setup_;
  Colour kind_;

  void frames(const std::vector<Vec<D>>& position, long begin, long end,
              std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent,
              const std::vector<MirrorPlane>& ended_on) {
    const std::vector<Vec<D>> previous = normal;
    const double h = setup_.cell;
    // The colour of the points and of their images beyond the planes the membrane ends on
    // (mirror_images.hpp), as wide as the widest (cubic) stencil.
    const std::vector<Vec<D>> x = with_images_in<D>(position, begin, end, ended_on, h, 2.0 * h);
    const long cloud = static_cast<long>(x.size()), n = end - begin;
    auto xi = [&](long p) { return Vec<D>((x[p] - setup_.grid_origin) / h); };
    using Key = std::int64_t;
    std::unordered_map<Key, Vec<D>> node_normal;
    std::unordered_map<Key, double> colour;
    if (kind_ == Colour::simple) {  // eq 7.2
      for (long p = 0; p < cloud; ++p)
        stencil<D, 2>(&linear_bspline, xi(p), [&](const IVec<D>& i, double, const Vec<D>& g) {
          auto [it, fresh] = node_normal.try_emplace(CellGroups<D>::key(i), Vec<D>::Zero());
          it->second += g / h;
        });
    } else if (kind_ == Colour::quadratic) {  // eqs 7.4–7.5: cell centres at integer ξ − ½
      std::unordered_map<Key, IVec<D>> where;
      for (long p = 0; p < cloud; ++p)
        stencil<D, 3>(&quadratic_bspline, Vec<D>(xi(p) - Vec<D>::Constant(0.5)),
                      [&](const IVec<D>& c, double N, const Vec<D>&) {
                        colour[CellGroups<D>::key(c)] += N;
                        where[CellGroups<D>::key(c)] = c;
                      });
      for (const auto& [key, c] : where) {  // ∇N_i at the centre of cell c, for its corners
        const Vec<D> centre = c.template cast<double>() + Vec<D>::Constant(0.5);
        stencil<D, 2>(&linear_bspline, centre, [&](const IVec<D>& i, double, const Vec<D>& g) {
          auto [it, fresh] = node_normal.try_emplace(CellGroups<D>::key(i), Vec<D>::Zero());
          it->second += colour[key] * g / h;
        });
      }
    } else {  // eq 7.6: node colours with cubic B-splines
      for (long p = 0; p < cloud; ++p)
        stencil<D, 4>(&cubic_bspline, xi(p), [&](const IVec<D>& i, double N, const Vec<D>&) {
          colour[CellGroups<D>::key(i)] += N;
        });
    }
    for (long p = 0; p < n; ++p) {
      Vec<D> g = Vec<D>::Zero();
      if (kind_ == Colour::cubic) {  // eq 7.7
        stencil<D, 4>(&cubic_bspline, xi(p), [&](const IVec<D>& i, double, const Vec<D>& grad) {
          const auto it = colour.find(CellGroups<D>::key(i));
          if (it != colour.end()) g += it->second * grad / h;
        });
      } else {  // eq 7.3
        stencil<D, 2>(&linear_bspline, xi(p), [&](const IVec<D>& i, double N, const Vec<D>&) {
          const auto it = node_normal.find(CellGroups<D>::key(i));
          if (it != node_normal.end()) g += N * it->second;
        });
      }
      normal[begin + p] = g.norm() > 0.0 ? Vec<D>(-g.normalized()) : Vec<D>::Unit(D - 1);
    }
    complete_frames<D>(position, begin, end, setup_.orientation, previous, normal, tangent, h);
  }
};

template <int D>
class PrincipalComponents final : public FrameEstimator<D> {
 public:
  explicit PrincipalComponents(const FrameSetup<D>& setup) : setup_(setup) {}
  void estimate(const std::vector<Vec<D>>& position, long begin, long end,
                std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) override {
    const std::vector<Vec<D>> previous = normal;
    // Neighbours include the images beyond the planes the membrane ends on (mirror_images.hpp).
    const std::vector<Vec<D>> x =
        with_mirror_images<D>(position, begin, end, setup_.mirrors, setup_.cell, 1.5 * setup_.cell);
    const PrincipalDirections<D> directions(x, setup_.cell);
#pragma omp parallel for schedule(static)
    for (long p = 0; p < end - begin; ++p) normal[begin + p] = directions.least_spread(p);
    complete_frames<D>(position, begin, end, setup_.orientation, previous, normal, tangent,
                       setup_.cell);
  }

 private:
  FrameSetup<D> setup_;
};

}  // namespace

template <int D>
std::unique_ptr<FrameEstimator<D>> make_colour_simple(const FrameSetup<D>& setup) {
  return std::make_unique<ColourFunction<D>>(setup, Colour::simple);
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_colour_quadratic(const FrameSetup<D>& setup) {
  return std::make_unique<ColourFunction<D>>(setup, Colour::quadratic);
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_colour_cubic(const FrameSetup<D>& setup) {
  return std::make_unique<ColourFunction<D>>(setup, Colour::cubic);
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_pca(const FrameSetup<D>& setup) {
  return std::make_unique<PrincipalComponents<D>>(setup);
}

#define PELLICLE_COLOUR_INSTANTIATE(D)                                                        \
  template std::unique_ptr<FrameEstimator<D>> make_colour_simple<D>(const FrameSetup<D>&);    \
  template std::unique_ptr<FrameEstimator<D>> make_colour_quadratic<D>(const FrameSetup<D>&); \
  template std::unique_ptr<FrameEstimator<D>> make_colour_cubic<D>(const FrameSetup<D>&);     \
  template std::unique_ptr<FrameEstimator<D>> make_pca<D>(const FrameSetup<D>&);
PELLICLE_COLOUR_INSTANTIATE(2)
PELLICLE_COLOUR_INSTANTIATE(3)
#undef PELLICLE_COLOUR_INSTANTIATE

}  // namespace pellicle
