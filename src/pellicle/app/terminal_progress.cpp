#include "pellicle/app/terminal_progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pellicle {

namespace {
void format_duration(char* out, std::size_t n, double seconds) {
  if (!std::isfinite(seconds)) {
    std::snprintf(out, n, "--:--");
    return;
  }
  const long s = std::lround(seconds);
  if (s >= 3600)
    std::snprintf(out, n, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(out, n, "%02ld:%02ld", s / 60, s % 60);
}
}  // namespace

void TerminalProgress::draw(const ProgressReport& r) {
  constexpr int width = 30;
  const int filled = static_cast<int>(r.fraction * width);
  char bar[width + 1];
  for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '.';
  bar[width] = '\0';
  char elapsed[32], eta[32];
  format_duration(elapsed, sizeof elapsed, r.wall_seconds);
  format_duration(eta, sizeof eta,
                  r.fraction > 0.0 ? r.wall_seconds * (1.0 - r.fraction) / r.fraction : NAN);
  std::fprintf(stderr, "\r[%s] %5.1f%%  t=%-10.4g step %-8ld elapsed %s  ETA %s ", bar,
               100.0 * r.fraction, r.time, r.step, elapsed, eta);
  std::fflush(stderr);
}

void TerminalProgress::update(const ProgressReport& r) {
  if (interactive_) {
    if (r.wall_seconds - last_draw_ < 0.2) return;  // redraw at most five times a second
    last_draw_ = r.wall_seconds;
    draw(r);
    return;
  }
  constexpr double kLineEvery = 60.0;  // seconds of wall time
  const int decile = static_cast<int>(r.fraction * 10.0 + 1e-9);
  const bool next_decile = decile > last_decile_ && decile < 10;
  if (!next_decile && r.wall_seconds - last_line_ < kLineEvery) return;
  last_decile_ = std::max(last_decile_, decile);
  last_line_ = r.wall_seconds;
  char eta[32];
  format_duration(eta, sizeof eta,
                  r.fraction > 0.0 ? r.wall_seconds * (1.0 - r.fraction) / r.fraction : NAN);
  std::fprintf(stderr, "progress: %5.1f%%  t=%.6g  step %ld  elapsed %.1f s  ETA %s\n",
               100.0 * r.fraction, r.time, r.step, r.wall_seconds, eta);
}

void TerminalProgress::finish(const ProgressReport& r) {
  if (interactive_) {
    draw(r);
    std::fputc('\n', stderr);
  } else {
    std::fprintf(stderr, "progress: %3.0f%%  t=%.6g  step %ld  elapsed %.1f s\n",
                 100.0 * r.fraction, r.time, r.step, r.wall_seconds);
  }
}

}  // namespace pellicle
