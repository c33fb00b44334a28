#include "pellicle/core/log.hpp"

#include <mutex>

namespace pellicle {
namespace {
struct LogState {
  std::mutex mutex;
  LogSink sink;
  LogLevel level = LogLevel::info;
};
LogState& state() {
  static LogState s;
  return s;
}
}  // namespace

void set_log_sink(LogSink sink) {
  std::lock_guard lock(state().mutex);
  state().sink = std::move(sink);
}

void set_log_level(LogLevel level) {
  std::lock_guard lock(state().mutex);
  state().level = level;
}

void log(LogLevel level, std::string_view message) {
  std::lock_guard lock(state().mutex);
  if (level < state().level || !state().sink) return;
  state().sink(level, message);
}

}  // namespace pellicle
