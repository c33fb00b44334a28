//! The kernel registry: adding a kernel is one struct in shape/kernels.hpp, one
//! instantiation file and one line here.
#include "pellicle/mpm/transfer.hpp"

#include "pellicle/mpm/shape/kernel_transfers.hpp"

namespace pellicle {

template <int D>
const std::vector<KernelChoice<D>>& kernel_choices() {
  static const std::vector<KernelChoice<D>> kernels = {
      {"linear", "linear tent (bi/trilinear), the seeds' kernel", &make_linear_transfer<D>, false},
      {"ugimp", "uniform GIMP, particle size from points per cell", &make_ugimp_transfer<D>, true,
       true},
      {"quadratic-bspline", "quadratic B-spline", &make_quadratic_transfer<D>},
      {"cubic-bspline", "cubic B-spline", &make_cubic_transfer<D>},
  };
  return kernels;
}

template <int D>
long continuity_update(Particles<D>& points, const Mat<D>* gradient, const double* hoop_rate,
                       double dt, long begin, long end) {
  long first_bad = -1;
  for (long p = begin; p < end; ++p) {
    double volumetric = 0.0;
    for (int i = 0; i < D; ++i) volumetric += gradient[p - begin](i, i);
    if (hoop_rate) volumetric += hoop_rate[p - begin];
    if (!continuity_point(points, p, volumetric, dt) && first_bad < 0) first_bad = p;
  }
  return first_bad;
}

template long continuity_update<2>(Particles<2>&, const Mat<2>*, const double*, double, long, long);
template long continuity_update<3>(Particles<3>&, const Mat<3>*, const double*, double, long, long);
template const std::vector<KernelChoice<2>>& kernel_choices<2>();
template const std::vector<KernelChoice<3>>& kernel_choices<3>();

}  // namespace pellicle
