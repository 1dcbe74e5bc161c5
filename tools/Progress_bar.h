// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_PROGRESS_BAR_H
#define EXPMAP_TOOLS_PROGRESS_BAR_H

/// \file Progress_bar.h
/// One-line progress displays on stderr: the maps of `expmap batch` (maps
/// done, maps per second and the time left) and the steps of the heat
/// method's precomputation. Only when stderr is a terminal: a log file or a
/// pipe gets nothing, not a stream of carriage returns.

#include <expmap/Precomputation_progress.h>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace expmap_cli {

class Progress_bar {
 public:
  explicit Progress_bar(std::size_t total)
      : m_total(total), m_shown(isatty(fileno(stderr)) != 0), m_start(Clock::now()) {}

  /// Redraws the bar, at most ten times a second (and always for the last
  /// map). Not thread safe: the batch serializes its progress calls.
  void update(std::size_t done) {
    if (!m_shown) return;
    const Clock::time_point now = Clock::now();
    if (done < m_total && now - m_last_draw < std::chrono::milliseconds(100)) return;
    m_last_draw = now;
    const double seconds = std::chrono::duration<double>(now - m_start).count();
    const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0;
    const int width = 30;
    const int filled = m_total ? static_cast<int>(width * done / m_total) : width;
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r[%s] %zu/%zu maps  %.0f maps/s  %s left ", bar.c_str(), done, m_total,
                 rate, rate > 0 ? clock_time((m_total - done) / rate).c_str() : "--:--");
    std::fflush(stderr);
  }

  /// Ends the bar's line, so that what follows starts on a line of its own.
  void finish() {
    if (m_shown && m_last_draw != Clock::time_point()) std::fputc('\n', stderr);
    m_last_draw = Clock::time_point();
  }

 private:
  using Clock = std::chrono::steady_clock;

  static std::string clock_time(double seconds) {
    const long s = static_cast<long>(seconds + 0.5);
    char text[32];
    if (s >= 3600)
      std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
      std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
  }

  std::size_t m_total;
  bool m_shown;
  Clock::time_point m_start, m_last_draw;
};

/// The heat method's precomputation as one line, redrawn at each step:
/// "precomputing: Poisson factorization (about 41% done, 4.2 s)", and
/// erased when it is done.
class Precomputation_line {
 public:
  Precomputation_line() : m_shown(isatty(fileno(stderr)) != 0) {}

  /// The callback for `Heat_options::progress`; it refers to this object,
  /// which must outlive the precomputation.
  expmap::Precomputation_callback callback() {
    return [this](const char* step, double fraction) {
      if (!m_shown) return;
      const double seconds = std::chrono::duration<double>(Clock::now() - m_start).count();
      char line[width + 1];
      if (fraction >= 1)
        std::snprintf(line, sizeof line, "%s", "");
      else
        std::snprintf(line, sizeof line, "precomputing: %s (about %.0f%% done, %.1f s)", step,
                      100 * fraction, seconds);
      std::fprintf(stderr, "\r%-*s%s", width, line, fraction >= 1 ? "\r" : "");
      std::fflush(stderr);
    };
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr int width = 79;
  bool m_shown;
  Clock::time_point m_start = Clock::now();
};

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_PROGRESS_BAR_H
