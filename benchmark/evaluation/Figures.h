// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_FIGURES_H
#define EXPMAP_BENCHMARK_EVALUATION_FIGURES_H

/// \file Figures.h
/// Pictures: several write_svg() panels side by side in one SVG.

#include "Common.h"

#include <expmap/IO/write_svg.h>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace expmap_evaluation {

struct Panel {
  const Mesh* mesh;
  Map map;
  std::string caption;
};

inline void write_figure(const fs::path& path, const std::vector<Panel>& panels, double size = 400,
                         std::size_t columns = 0) {
  if (columns == 0) columns = panels.size();
  const std::size_t rows = (panels.size() + columns - 1) / columns;
  fs::create_directories(path.parent_path());
  std::ostringstream body;
  std::vector<std::string> panel_svgs;
  double height = 0;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    expmap::IO::Svg_options options;
    options.method = panels[k].caption;
    options.size = size;
    std::ostringstream one;
    expmap::IO::write_svg(one, *panels[k].mesh, panels[k].map, options);
    std::string svg = one.str();
    if (svg.rfind("<?xml", 0) == 0) svg = svg.substr(svg.find('\n') + 1);
    // The panel's own height (caption strip included).
    const auto h_at = svg.find("height=\"");
    if (h_at != std::string::npos) height = std::max(height, std::stod(svg.substr(h_at + 8)));
    panel_svgs.push_back(svg);
  }
  for (std::size_t k = 0; k < panel_svgs.size(); ++k)
    body << "<g transform=\"translate(" << (k % columns) * size << ',' << (k / columns) * height
         << ")\">\n" << panel_svgs[k] << "</g>\n";
  std::ofstream out(path);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size * columns
      << "\" height=\"" << height * rows << "\" viewBox=\"0 0 " << size * columns << ' ' << height * rows
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fcfcfa\"/>\n"
      << body.str() << "</svg>\n";
  std::cout << "wrote " << path.string() << "\n";
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_FIGURES_H
