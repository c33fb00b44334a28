#pragma once
//! Factories of the kernel-specialised transfers; each is compiled in its own file
//! (shape/transfer_<kernel>.cpp) so the four kernels build in parallel.

#include <memory>

#include "pellicle/mpm/transfer.hpp"

namespace pellicle {

template <int D>
std::unique_ptr<Transfer<D>> make_linear_transfer(const TransferOptions& options, double ppc);
template <int D>
std::unique_ptr<Transfer<D>> make_ugimp_transfer(const TransferOptions& options, double ppc);
template <int D>
std::unique_ptr<Transfer<D>> make_quadratic_transfer(const TransferOptions& options, double ppc);
template <int D>
std::unique_ptr<Transfer<D>> make_cubic_transfer(const TransferOptions& options, double ppc);

}  // namespace pellicle
