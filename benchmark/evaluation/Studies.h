// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_STUDIES_H
#define EXPMAP_BENCHMARK_EVALUATION_STUDIES_H

/// \file Studies.h
/// The three studies of expmap-evaluate, one source file each, and the
/// settings they share (parsed from the command line in expmap_evaluate.cpp).

#include "Common.h"

#include <string>
#include <vector>

namespace expmap_evaluation {

struct Settings {
  bool accuracy = false, mesh_quality = false, folds = false, quick = false;
  fs::path out = "doc", meshes = "data/meshes", svg_dir = "build/evaluation-svg";
  int sources = 50;
  std::vector<std::string> mesh_names = {"armadillo.off", "bunny00.off", "refined_elephant.off",
                                         "camel.off", "bull.off", "dino.off"};
};

/// Table 1: E_d and E_a on the sphere, Gaussian bump and saddle
/// (accuracy_study.cpp); writes accuracy_table.md and evaluation/accuracy.csv.
void run_accuracy(const Settings& settings);

/// Fig. 13: regular, edge-flipped and anisotropic planar grids
/// (mesh_quality_study.cpp); writes mesh_quality.md, its CSVs and a picture.
void run_mesh_quality(const Settings& settings);

/// Figs. 9, 14: fold-overs and distortion of 5% patches on real meshes, and
/// the effect of the time factor (folds_study.cpp); writes folds.md, its
/// CSVs and pictures.
void run_folds(const Settings& settings);

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_STUDIES_H
