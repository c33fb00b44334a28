#include "pellicle/normals/mirror_images.hpp"

#include <cmath>

namespace pellicle {

template <int D>
unsigned mirrors_touched(const std::vector<Vec<D>>& x, long begin, long end,
                         const std::vector<MirrorPlane>& mirrors, double cell) {
  unsigned touched = 0;
  for (std::size_t k = 0; k < mirrors.size(); ++k) {
    const MirrorPlane& m = mirrors[k];
    bool on = false;
    for (long p = begin; p < end && !on; ++p)
      on = std::abs(x[p][m.axis] - m.position) <= 0.01 * cell;
    if (on) touched |= 1u << k;
  }
  return touched;
}

std::vector<MirrorPlane> planes_ended_on(unsigned touched,
                                         const std::vector<MirrorPlane>& mirrors) {
  // One per axis at most: a membrane cannot end on both faces of an axis and be mirrored in
  // both without repeating itself.
  std::vector<MirrorPlane> used;
  for (std::size_t k = 0; k < mirrors.size(); ++k) {
    bool axis_taken = false;
    for (const auto& u : used) axis_taken = axis_taken || u.axis == mirrors[k].axis;
    if ((touched >> k & 1u) && !axis_taken) used.push_back(mirrors[k]);
  }
  return used;
}

template <int D>
std::vector<Vec<D>> with_mirror_images(const std::vector<Vec<D>>& x, long begin, long end,
                                       const std::vector<MirrorPlane>& mirrors, double cell,
                                       double band) {
  return with_images_in<D>(x, begin, end, planes_ended_on<D>(x, begin, end, mirrors, cell), cell,
                           band);
}

template <int D>
std::vector<Vec<D>> with_images_in(const std::vector<Vec<D>>& x, long begin, long end,
                                   const std::vector<MirrorPlane>& used, double cell, double band) {
  std::vector<Vec<D>> cloud(x.begin() + begin, x.begin() + end);
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

template unsigned mirrors_touched<2>(const std::vector<Vec<2>>&, long, long,
                                     const std::vector<MirrorPlane>&, double);
template unsigned mirrors_touched<3>(const std::vector<Vec<3>>&, long, long,
                                     const std::vector<MirrorPlane>&, double);
template std::vector<Vec<2>> with_images_in<2>(const std::vector<Vec<2>>&, long, long,
                                               const std::vector<MirrorPlane>&, double, double);
template std::vector<Vec<3>> with_images_in<3>(const std::vector<Vec<3>>&, long, long,
                                               const std::vector<MirrorPlane>&, double, double);
template std::vector<Vec<2>> with_mirror_images<2>(const std::vector<Vec<2>>&, long, long,
                                                   const std::vector<MirrorPlane>&, double, double);
template std::vector<Vec<3>> with_mirror_images<3>(const std::vector<Vec<3>>&, long, long,
                                                   const std::vector<MirrorPlane>&, double, double);

}  // namespace pellicle
