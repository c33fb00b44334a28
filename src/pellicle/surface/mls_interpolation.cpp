#include "pellicle/surface/mls_interpolation.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "pellicle/core/error.hpp"

namespace pellicle {

namespace {

//! The points within `radius` of x as offsets from x, the nearest kMaxStencilPoints when
//! there are more; returns their number.
template <int D>
int gather(const PointCloud<D>& cloud, const NeighbourSearch<D>& search, const Vec<D>& x,
           double radius, int part_of, const Vec<D>& n, MlsWeights& w, Vec<D>* offsets) {
  thread_local std::vector<int> found;
  thread_local std::vector<std::pair<double, int>> by_distance;
  search.around(cloud, x, radius, found);
  if (part_of >= 0)
    found.erase(std::remove_if(found.begin(), found.end(),
                               [&](int j) { return !cloud.on_part(j, part_of, n); }),
                found.end());
  int count = static_cast<int>(found.size());
  if (count > kMaxStencilPoints) {
    by_distance.clear();
    for (int j : found) by_distance.emplace_back((cloud.position[j] - x).squaredNorm(), j);
    std::nth_element(by_distance.begin(), by_distance.begin() + kMaxStencilPoints,
                     by_distance.end());
    count = kMaxStencilPoints;
    for (int k = 0; k < count; ++k) found[k] = by_distance[k].second;
    std::sort(found.begin(), found.begin() + count);
  }
  w.count = count;
  for (int k = 0; k < count; ++k) {
    w.index[k] = found[k];
    offsets[k] = cloud.position[found[k]] - x;
  }
  return count;
}

}  // namespace

template <int D>
MlsFit mls_weights(const PointCloud<D>& cloud, const NeighbourSearch<D>& search, const Vec<D>& x,
                   const Mat<D>& frame, double h, double weight_exponent, MlsWeights& w,
                   int part_of) {
  const Vec<D> n = frame.col(D - 1);
  const Eigen::Matrix<double, D, D - 1> tangents = frame.template leftCols<D - 1>();
  Vec<D> offsets[kMaxStencilPoints];
  FitTargets<D, 1> b = FitTargets<D, 1>::Zero();
  b(0, 0) = 1.0;  // the value at the centre: the monomial 1 is 1 there, the others 0
  FitCoefficients<D, 1> c;
  for (const double scale : {1.0, 1.5, 2.0}) {
    const double radius = scale * h;
    const int count = gather(cloud, search, x, radius, part_of, n, w, offsets);
    if (fit_coefficients<D, 1>(offsets, count, tangents, radius, weight_exponent, b, c) ==
        FitStatus::ok) {
      for (int k = 0; k < count; ++k) w.weight[k] = c(k, 0);
      return scale == 1.0 ? MlsFit::second_order : MlsFit::widened;
    }
  }
  // No second-order fit within 2 h: the Gaussian-weighted mean there (exact for constants).
  const double radius = 2.0 * h;
  const int count = gather(cloud, search, x, radius, part_of, n, w, offsets);
  double total = 0.0;
  for (int k = 0; k < count; ++k) {
    w.weight[k] = gaussian_weight(offsets[k].squaredNorm(), radius, weight_exponent);
    total += w.weight[k];
  }
  if (count == 0 || !(total > 0.0)) return MlsFit::none;
  for (int k = 0; k < count; ++k) w.weight[k] /= total;
  return MlsFit::weighted_mean;
}

template <int D>
long interpolate_carried(const PointCloud<D>& cloud, const NeighbourSearch<D>& search,
                         const std::vector<MlsTarget<D>>& targets, double weight_exponent,
                         CarriedValues<D>& values) {
  const long n = static_cast<long>(targets.size());
  const std::size_t fields = cloud.field_names().size();
  values.smoothing_length.assign(n, 0.0);
  values.velocity.assign(n, Vec<D>::Zero());
  values.previous_velocity.assign(n, Vec<D>::Zero());
  values.has_previous_velocity.assign(n, 0);
  values.fields.assign(fields, std::vector<double>(n, 0.0));
  long widened = 0, failed = -1;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : widened)
  for (long q = 0; q < n; ++q) {
    const MlsTarget<D>& target = targets[q];
    MlsWeights w;
    const MlsFit fit = mls_weights(cloud, search, target.position, target.frame, target.h,
                                   weight_exponent, w, target.part_of);
    if (fit == MlsFit::none) {
#pragma omp critical(pellicle_mls_failure)
      failed = q;
      continue;
    }
    if (fit != MlsFit::second_order) ++widened;
    double h = 0.0;
    Vec<D> v = Vec<D>::Zero(), v_previous = Vec<D>::Zero();
    bool all_previous = true;
    for (int k = 0; k < w.count; ++k) {
      const int j = w.index[k];
      h += w.weight[k] * cloud.smoothing_length[j];
      v += w.weight[k] * cloud.velocity[j];
      v_previous += w.weight[k] * cloud.previous_velocity[j];
      all_previous = all_previous && cloud.has_previous_velocity[j];
    }
    values.smoothing_length[q] = h;
    values.velocity[q] = v;
    values.has_previous_velocity[q] = all_previous ? 1 : 0;
    if (all_previous) values.previous_velocity[q] = v_previous;
    for (std::size_t f = 0; f < fields; ++f) {
      const std::vector<double>& u = cloud.field(static_cast<int>(f));
      double value = 0.0;
      for (int k = 0; k < w.count; ++k) value += w.weight[k] * u[w.index[k]];
      values.fields[f][q] = value;
    }
  }
  if (failed >= 0) {
    const Vec<D>& x = targets[failed].position;
    std::string where;
    for (int d = 0; d < D; ++d) where += (d ? ", " : "") + std::to_string(x[d]);
    throw NumericalError({0.0, 0, "surface", -1},
                         "no point within twice the smoothing length of (" + where +
                             "), where point management needs values: the cloud has a hole "
                             "wider than its smoothing length there");
  }
  return widened;
}

template <int D>
void store_carried(const CarriedValues<D>& values, std::size_t q, PointCloud<D>& cloud,
                   std::size_t i) {
  cloud.smoothing_length[i] = values.smoothing_length[q];
  cloud.velocity[i] = values.velocity[q];
  cloud.previous_velocity[i] = values.previous_velocity[q];
  cloud.has_previous_velocity[i] = values.has_previous_velocity[q];
  for (std::size_t f = 0; f < values.fields.size(); ++f)
    cloud.field(static_cast<int>(f))[i] = values.fields[f][q];
}

template MlsFit mls_weights<2>(const PointCloud<2>&, const NeighbourSearch<2>&, const Vec2&,
                               const Mat<2>&, double, double, MlsWeights&, int);
template MlsFit mls_weights<3>(const PointCloud<3>&, const NeighbourSearch<3>&, const Vec3&,
                               const Mat<3>&, double, double, MlsWeights&, int);
template long interpolate_carried<2>(const PointCloud<2>&, const NeighbourSearch<2>&,
                                     const std::vector<MlsTarget<2>>&, double, CarriedValues<2>&);
template long interpolate_carried<3>(const PointCloud<3>&, const NeighbourSearch<3>&,
                                     const std::vector<MlsTarget<3>>&, double, CarriedValues<3>&);
template void store_carried<2>(const CarriedValues<2>&, std::size_t, PointCloud<2>&, std::size_t);
template void store_carried<3>(const CarriedValues<3>&, std::size_t, PointCloud<3>&, std::size_t);

}  // namespace pellicle
