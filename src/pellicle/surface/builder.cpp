#include "pellicle/surface/builder.hpp"

namespace pellicle {

template <int D>
std::unique_ptr<SurfaceSimulation<D>> build_surface_simulation(
    const PointSample<D>& sample, double smoothing_length, const SurfaceSettings& settings,
    std::array<PointFormula, D> velocity, std::unique_ptr<SurfacePde<D>> pde,
    const std::vector<int>* surface_of_point) {
  PointCloud<D> cloud;
  for (std::size_t i = 0; i < sample.size(); ++i) {
    cloud.add_point(sample.points[i], smoothing_length, sample.boundary[i] != 0);
    if (surface_of_point) cloud.chamber[i] = cloud.surface[i] = (*surface_of_point)[i];
  }
  return std::make_unique<SurfaceSimulation<D>>(std::move(cloud), settings, std::move(velocity),
                                                std::move(pde), &sample.normals);
}

template std::unique_ptr<SurfaceSimulation<2>> build_surface_simulation<2>(
    const PointSample<2>&, double, const SurfaceSettings&, std::array<PointFormula, 2>,
    std::unique_ptr<SurfacePde<2>>, const std::vector<int>*);
template std::unique_ptr<SurfaceSimulation<3>> build_surface_simulation<3>(
    const PointSample<3>&, double, const SurfaceSettings&, std::array<PointFormula, 3>,
    std::unique_ptr<SurfacePde<3>>, const std::vector<int>*);

}  // namespace pellicle
