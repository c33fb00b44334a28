#pragma once
//! Library logging. Code below `app/` never writes to the terminal; it logs here and the
//! program that uses the library decides where messages go (see `set_log_sink`).

#include <functional>
#include <string_view>

namespace pellicle {

enum class LogLevel { debug, info, warning, error };

using LogSink = std::function<void(LogLevel, std::string_view)>;

//! Install the function that receives every message; an empty sink discards them.
void set_log_sink(LogSink sink);
//! Messages below this level are dropped before formatting reaches the sink.
void set_log_level(LogLevel level);

void log(LogLevel level, std::string_view message);
inline void log_info(std::string_view m) {
  log(LogLevel::info, m);
}
inline void log_warning(std::string_view m) {
  log(LogLevel::warning, m);
}

}  // namespace pellicle
