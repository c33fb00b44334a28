#include "pellicle/normals/mirror_images.hpp"

#include <cmath>

namespace pellicle {

template <int D>
std::vector<MirrorPlane> planes_ended_on(const std::vector<Vec<D>>& x, long begin, long end,
                                         const std::vector<MirrorPlane>& mirrors, double cell) {
  // One per axis at most: a membrane cannot end on both faces of an axis and be mirrored in
  // both without repeating itself.
  std::vector<MirrorPlane> used;
  for (const auto& m : mirrors) {
    bool on = false;
    for (long p = begin; p < end && !on; ++p)
      on = std::abs(x[p][m.axis] - m.position) <= 0.01 * cell;
    bool axis_taken = false;
    for (const auto& u : used) axis_taken = axis_taken || u.axis == m.axis;
    if (on && !axis_taken) used.push_back(m);
  }
  return used;
}

template <int D>
std::vector<Vec<D>> with_mirror_images(const std::vector<Vec<D>>& x, long begin, long end,
                                       const std::vector<MirrorPlane>& mirrors, double cell,
                                       double band) {
  std::vector<Vec<D>> cloud(x.begin() + begin, x.begin() + end);
  const std::vector<MirrorPlane> used = planes_ended_on<D>(x, begin, end, mirrors, cell);
  const int planes = static_cast<int>(used.size());
  for (int subset = 1; subset < (1 << planes); ++subset) {
    for (long p = begin; p < end; ++p) {
      Vec<D> image = x[p];
      bool near = true;
      for (int k = 0; k < planes && near; ++k) {
        if (!(subset & (1 << k))) continue;
        const MirrorPlane& m = used[k];
        const double distance = std::abs(x[p][m.axis] - m.position);
        // A point on the plane is its own image: no second copy.
        near = distance <= band && distance > 1e-9 * cell;
        image[m.axis] = 2.0 * m.position - image[m.axis];
      }
      if (near) cloud.push_back(image);
    }
  }
  return cloud;
}

template std::vector<MirrorPlane> planes_ended_on<2>(const std::vector<Vec<2>>&, long, long,
                                                     const std::vector<MirrorPlane>&, double);
template std::vector<MirrorPlane> planes_ended_on<3>(const std::vector<Vec<3>>&, long, long,
                                                     const std::vector<MirrorPlane>&, double);
template std::vector<Vec<2>> with_mirror_images<2>(const std::vector<Vec<2>>&, long, long,
                                                   const std::vector<MirrorPlane>&, double, double);
template std::vector<Vec<3>> with_mirror_images<3>(const std::vector<Vec<3>>&, long, long,
                                                   const std::vector<MirrorPlane>&, double, double);

}  // namespace pellicle
