// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_FORMATTING_H
#define EXPMAP_BENCHMARK_EVALUATION_FORMATTING_H

/// \file Formatting.h
/// Number formats of the tables (the paper's 0.612e-3 style, fixed,
/// general, percent) and writing a finished text file.

#include "Common.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace expmap_evaluation {

/// The paper's number format: 0.612e-3 (mantissa in [0.1, 1)).
inline std::string paper_style(double x) {
  if (!std::isfinite(x)) return "n/a";
  if (x == 0) return "0";
  const int e = static_cast<int>(std::floor(std::log10(std::abs(x)))) + 1;
  double m = x / std::pow(10.0, e);
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.3f", m);
  if (std::string(buffer) == "1.000" || std::string(buffer) == "-1.000") {
    std::snprintf(buffer, sizeof buffer, "%.3fe%d", m / 10, e + 1);
    return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%.3fe%d", m, e);
  return buffer;
}

inline std::string fixed(double x, int digits) {
  if (!std::isfinite(x)) return "n/a";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

inline std::string general(double x, int digits = 6) {
  if (!std::isfinite(x)) return "nan";
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

inline std::string percent(double x, int digits = 1) {
  if (!std::isfinite(x)) return "n/a";
  return fixed(100 * x, digits) + "%";
}

inline void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!(out << text)) throw std::runtime_error("cannot write " + path.string());
  std::cout << "wrote " << path.string() << "\n";
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_FORMATTING_H
