#include "pellicle/app/stop_signals.hpp"

namespace pellicle {
namespace {
volatile std::sig_atomic_t stop_signal = 0;
extern "C" void request_stop(int signal) {
  stop_signal = signal;
}
}  // namespace

const volatile std::sig_atomic_t* catch_stop_signals() {
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  return &stop_signal;
}

}  // namespace pellicle
