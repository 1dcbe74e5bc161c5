// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// expmap-evaluate: the quality evaluation of Herholz & Alexa 2019, section
// 7.2, for the heat method and the baselines (DEM, DGPC, exact polyhedral
// geodesics), plus CGAL's Heat_method_3 for the distance part.
//
//   --accuracy      Table 1: sphere, Gaussian bump and saddle at three mean
//                   edge lengths; E_d and E_a against analytic / ODE references.
//   --mesh-quality  Fig. 13: regular, edge-flipped and anisotropic planar grids.
//   --folds         Figs. 9, 14: fold-overs and distortion of 5% patches on
//                   real meshes, and the effect of the time factor.
//   (none of the three: all of them)
//   --out DIR       where the Markdown tables go (default doc); the CSVs go to
//                   DIR/evaluation/
//   --meshes DIR    the libcgal-demo meshes (default data/meshes)
//   --svg-dir DIR   the SVG pictures (default build/evaluation-svg); one
//                   combined SVG per figure, for rsvg-convert
//   --sources N     random sources per real mesh (default 50, seed 1)
//   --quick         a smoke run: coarse resolutions, 4 sources, 2 meshes
//
// Everything is deterministic: random sources come from std::mt19937(1)
// with rejection sampling on its raw output (portable), the meshes are
// generated or read from the data folder.
//
// CSV columns are described in doc/results.md (section "Files").

#include "evaluation/Common.h"
#include "evaluation/Formatting.h"
#include "evaluation/Studies.h"

#include <chrono>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

namespace {

using namespace expmap_evaluation;

void usage() {
  std::cout << "usage: expmap-evaluate [--accuracy] [--mesh-quality] [--folds] [--out DIR]\n"
               "                       [--meshes DIR] [--svg-dir DIR] [--sources N] [--quick]\n"
               "Without --accuracy/--mesh-quality/--folds, runs all three.\n";
}

}  // namespace

int main(int argc, char** argv) {
  Settings settings;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--accuracy") settings.accuracy = true;
      else if (a == "--mesh-quality") settings.mesh_quality = true;
      else if (a == "--folds") settings.folds = true;
      else if (a == "--quick") settings.quick = true;
      else if (a == "--out") settings.out = value();
      else if (a == "--meshes") settings.meshes = value();
      else if (a == "--svg-dir") settings.svg_dir = value();
      else if (a == "--sources") settings.sources = std::stoi(value());
      else if (a == "--help" || a == "-h") {
        usage();
        return 0;
      } else {
        std::cerr << "unknown argument " << a << "\n";
        usage();
        return 2;
      }
    } catch (const std::exception& e) {
      std::cerr << e.what() << "\n";
      return 2;
    }
  }
  if (!settings.accuracy && !settings.mesh_quality && !settings.folds)
    settings.accuracy = settings.mesh_quality = settings.folds = true;
  const auto start = std::chrono::steady_clock::now();
  try {
    // figures.txt lists the pictures this run drew (one SVG each), for the script.
    fs::create_directories(settings.svg_dir);
    std::ofstream(settings.svg_dir / "figures.txt", std::ios::trunc);
    if (settings.mesh_quality) run_mesh_quality(settings);
    if (settings.folds) run_folds(settings);
    if (settings.accuracy) run_accuracy(settings);
  } catch (const std::exception& e) {
    std::cerr << "expmap-evaluate: " << e.what() << "\n";
    return 1;
  }
  std::cout << "done in " << fixed(seconds_since(start), 0) << " s\n";
  return 0;
}
