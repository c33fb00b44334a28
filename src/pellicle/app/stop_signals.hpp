#pragma once
//! SIGINT and SIGTERM during a run: the handler only records the signal; the run pipeline
//! (io/run.hpp) stops after the current step, writes its checkpoint and summary, and the
//! command exits 128 + the signal (130, 143).

#include <csignal>

namespace pellicle {

//! Install the handlers; returns the flag the run pipeline watches (0 until a signal).
const volatile std::sig_atomic_t* catch_stop_signals();

}  // namespace pellicle
