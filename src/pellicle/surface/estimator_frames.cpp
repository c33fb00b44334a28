#include "pellicle/surface/estimator_frames.hpp"

#include "pellicle/pointcloud/local_frame.hpp"

namespace pellicle {

template <int D>
void estimate_frames(FrameEstimator<D>& estimator, PointCloud<D>& cloud, bool keep_side) {
  const long n = static_cast<long>(cloud.size());
  std::vector<Vec<D>> normal(n, Vec<D>::Zero()), tangent(n, Vec<D>::Zero());
  if (keep_side)
    for (long i = 0; i < n; ++i)
      normal[i] = normal_of<D>(cloud.frame[i]), tangent[i] = tangent_of<D>(cloud.frame[i]);
  estimator.estimate(cloud.position, 0, n, normal, tangent);
  for (long i = 0; i < n; ++i) cloud.frame[i] = frame_of<D>(normal[i], tangent[i]);
}

template void estimate_frames<2>(FrameEstimator<2>&, PointCloud<2>&, bool);
template void estimate_frames<3>(FrameEstimator<3>&, PointCloud<3>&, bool);

}  // namespace pellicle
