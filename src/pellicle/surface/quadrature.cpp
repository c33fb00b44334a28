#include "pellicle/surface/quadrature.hpp"

#include <Eigen/Geometry>

#include "pellicle/surface/one_ring.hpp"

namespace pellicle {

template <int D>
void point_areas(const PointCloud<D>& cloud, const NeighbourLists& nb, std::vector<double>& area) {
  const long n = static_cast<long>(cloud.size());
  area.assign(n, 0.0);
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < n; ++i) {
    OneRingSimplex ring[kMaxOneRing];
    const int count = one_ring(cloud, nb, i, cloud.smoothing_length[i], ring);
    const Vec<D>& x = cloud.position[i];
    double sum = 0.0;
    for (int k = 0; k < count; ++k) {
      const Vec<D> a = cloud.position[ring[k].first] - x;
      if constexpr (D == 3) {
        sum += a.cross(cloud.position[ring[k].second] - x).norm() / 6.0;  // a third of ½|a × b|
      } else {
        sum += a.norm() / 2.0;
      }
    }
    area[i] = sum;
  }
}

template <int D>
SurfaceIntegrals integrate(const PointCloud<D>& cloud, const NeighbourLists& neighbours,
                           const std::vector<double>* u, std::vector<double>& areas) {
  point_areas(cloud, neighbours, areas);
  SurfaceIntegrals out;
  for (std::size_t i = 0; i < areas.size(); ++i) {
    out.area += areas[i];
    out.enclosed += areas[i] * cloud.position[i].dot(cloud.normal(i)) / D;
    if (u) out.integral += areas[i] * (*u)[i];
  }
  return out;
}

template void point_areas<2>(const PointCloud<2>&, const NeighbourLists&, std::vector<double>&);
template void point_areas<3>(const PointCloud<3>&, const NeighbourLists&, std::vector<double>&);
template SurfaceIntegrals integrate<2>(const PointCloud<2>&, const NeighbourLists&,
                                       const std::vector<double>*, std::vector<double>&);
template SurfaceIntegrals integrate<3>(const PointCloud<3>&, const NeighbourLists&,
                                       const std::vector<double>*, std::vector<double>&);

}  // namespace pellicle
