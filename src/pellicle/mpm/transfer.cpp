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

template const std::vector<KernelChoice<2>>& kernel_choices<2>();
template const std::vector<KernelChoice<3>>& kernel_choices<3>();

}  // namespace pellicle
