#include "pellicle/mpm/shape/kernel_transfers.hpp"
#include "pellicle/mpm/transfer_impl.hpp"

namespace pellicle {

template <int D>
std::unique_ptr<Transfer<D>> make_linear_transfer(const TransferOptions& options,
                                                  double /*points_per_cell*/) {
  return std::make_unique<TransferImpl<D, shape::Linear>>(options, shape::Linear{});
}

template std::unique_ptr<Transfer<2>> make_linear_transfer<2>(const TransferOptions&, double);
template std::unique_ptr<Transfer<3>> make_linear_transfer<3>(const TransferOptions&, double);

}  // namespace pellicle
