// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The viewer's soak test needs a mesh of more than 100,000 vertices, and the
// demo meshes have at most 44,460: this writes one, Loop-subdividing a demo
// mesh as the benchmarks do (and reusing a file written before).
//
// usage: test_viewer_loop_mesh INPUT LEVELS OUTPUT

#include "Loop_subdivided_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: test_viewer_loop_mesh INPUT LEVELS OUTPUT\n";
    return 2;
  }
  try {
    using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
    const Mesh mesh = expmap_bench::loop_subdivided_mesh<Mesh>(
        argv[1], static_cast<unsigned>(std::stoul(argv[2])), argv[3], std::cout);
    std::cout << argv[3] << ": " << mesh.number_of_vertices() << " vertices\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "test_viewer_loop_mesh: " << e.what() << "\n";
    return 1;
  }
}
