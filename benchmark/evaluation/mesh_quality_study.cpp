// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh-quality study of expmap-evaluate (--mesh-quality): Fig. 13 of
// Herholz & Alexa 2019. Regular, edge-flipped and anisotropic planar grids;
// errors of every method against the exact map of the plane, and a picture
// of the heat map on the three grids.

#include "Analytic_exponential_maps.h"
#include "Analytic_surfaces.h"
#include "Common.h"
#include "Figures.h"
#include "Formatting.h"
#include "Meshes.h"
#include "Methods.h"
#include "Reference_maps.h"
#include "Statistics.h"
#include "Studies.h"

#include <expmap/Discrete_exponential_map.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace expmap_evaluation {

void run_mesh_quality(const Settings& settings) {
  std::cout << "== mesh quality (Fig. 13) ==\n";
  const auto run_start = std::chrono::steady_clock::now();
  const int rings = settings.quick ? 70 : 100;
  const double edge = 0.02, radius = 0.5;
  const double stretch = std::sqrt(3.0);  // area-preserving, aspect ratio 3

  struct Case {
    std::string key, label;
    expmap_analytic::Triangle_soup soup;
    std::string note;
  };
  std::vector<Case> cases;
  {
    Case regular{"regular", "regular", expmap_analytic::make_equilateral_grid(rings, edge), ""};
    Case flipped{"flipped", "~50% edges flipped", regular.soup, ""};
    // Interior edges of the regular grid.
    std::size_t directed = 0, boundary = 0;
    {
      std::map<std::pair<int, int>, int> count;
      for (const auto& t : regular.soup.triangles)
        for (int k = 0; k < 3; ++k) {
          ++directed;
          count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}]++;
        }
      for (const auto& [e, c] : count) boundary += c == 1;
    }
    const std::size_t interior = (directed - boundary) / 2;
    const std::size_t n_flipped = expmap_analytic::flip_random_edges(flipped.soup, 0.5, 1);
    flipped.note = std::to_string(n_flipped) + " of " + std::to_string(interior) +
                   " interior edges flipped (" + percent(double(n_flipped) / double(interior)) +
                   "; flip_random_edges(0.5, seed 1) saturates there)";
    Case aniso{"anisotropic", "anisotropic (x*sqrt3, y/sqrt3)", regular.soup, ""};
    expmap_analytic::scale_anisotropically(aniso.soup, stretch, 1 / stretch, 1.0);
    aniso.note = "regular grid scaled by (sqrt 3, 1/sqrt 3): aspect ratio 3, 120-degree angles";
    regular.note = "equilateral triangles, valence 6";
    cases.push_back(std::move(regular));
    cases.push_back(std::move(flipped));
    cases.push_back(std::move(aniso));
  }

  // Sources: the centre and 9 random vertices within 0.1 of it.
  std::vector<std::size_t> sources = {0};
  {
    std::mt19937 rng(1);
    const auto& pts = cases[0].soup.points;
    while (sources.size() < (settings.quick ? 3u : 10u)) {
      const std::size_t v = uniform_below(rng, pts.size());
      if (std::hypot(pts[v][0], pts[v][1]) < 0.1) sources.push_back(v);
    }
  }

  struct Row {
    std::string mesh, method_key, method_label;
    double h;
    Errors errors;
    double seconds;
    std::size_t failed = 0;
    std::string failure;
  };
  std::vector<Row> rows;
  std::ostringstream detail;
  detail << "mesh,source,method,E_d,E_a,E_d_max,E_a_max,status\n";
  std::vector<Panel> panels_for_figure;
  std::vector<std::unique_ptr<Mesh>> keep_meshes;
  for (const Case& c : cases) {
    keep_meshes.push_back(std::make_unique<Mesh>(to_mesh(c.soup)));
    const Mesh& mesh = *keep_meshes.back();
    const double h = mean_edge_length(mesh);
    std::cout << c.label << ": " << c.soup.points.size() << " vertices, h = " << h << " (" << c.note
              << ")\n";
    Method_set set(mesh);
    set.add_heat("heat_m10", "heat m=10", 10.0);
    set.add_heat("heat_m10_idt", "heat m=10, intrinsic Delaunay", 10.0,
                 expmap::Laplacian_mode::intrinsic_delaunay);
    set.add_heat("heat_m1", "heat m=1", 1.0);
    set.add_heat("heat_m1_idt", "heat m=1, intrinsic Delaunay", 1.0,
                 expmap::Laplacian_mode::intrinsic_delaunay);
    set.add<expmap::Discrete_exponential_map>("dem", "DEM");
    set.add<expmap::Geodesic_polar_coordinates>("dgpc", "DGPC");
    set.add<expmap::Exact_exponential_map>("exact", "exact");
    const expmap::Patch patch = expmap::Patch::geodesic_radius(radius + 3 * h);
    for (const Method& method : set.methods) {
      Error_average average;
      double seconds = method.precompute_seconds;
      std::size_t failed = 0;
      std::string failure;
      for (std::size_t s : sources) {
        const std::vector<Reference_point> ref =
            vertex_references(c.soup, s, radius, [&](const Vec3& q) {
              return expmap_analytic::plane_exponential_map(c.soup.points[s], q, {{1, 0, 0}});
            });
        const auto start = std::chrono::steady_clock::now();
        Map map;
        try {
          map = method.compute(s, patch);
        } catch (const std::exception& e) {
          ++failed;
          if (failure.empty()) failure = e.what();
          detail << c.key << ',' << s << ',' << method.key << ",,,,,failed\n";
          continue;
        }
        seconds += seconds_since(start);
        const Errors e = map_errors(map, c.soup.points.size(), ref);
        detail << c.key << ',' << s << ',' << method.key << ',' << general(e.distance) << ','
               << general(e.angle) << ',' << general(e.distance_max) << ',' << general(e.angle_max)
               << ",ok\n";
        average.add(e);
        if (s == 0 && (method.key == "heat_m10" || method.key == "heat_m10_idt"))
          panels_for_figure.push_back({&mesh, map, "heat " + std::string(method.key == "heat_m10" ? "" : "iDT ") + "(" + c.key + ")"});
      }
      Row row{c.key, method.key, method.label, h, average.result(), seconds, failed, failure};
      rows.push_back(row);
      if (failed) std::cout << "  " << method.label << ": " << failed << " of " << sources.size() << " sources failed: " << failure << "\n";
      std::cout << "  " << std::setw(32) << std::left << method.label << std::right << " E_d "
                << paper_style(row.errors.distance) << "  E_a " << paper_style(row.errors.angle)
                << "  (max " << paper_style(row.errors.distance_max) << ", "
                << paper_style(row.errors.angle_max) << ")\n";
    }
  }
  // Figure: heat (direct) on the three meshes, then with intrinsic Delaunay.
  {
    std::vector<Panel> direct, idt;
    for (auto& p : panels_for_figure) (p.caption.find("iDT") != std::string::npos ? idt : direct).push_back(p);
    direct.insert(direct.end(), idt.begin(), idt.end());
    // Only the inner part of the patch: 0.25 of radius 0.5 keeps the picture readable.
    for (auto& p : direct) {
      Map cut;
      cut.source = p.map.source;
      cut.normal = p.map.normal;
      cut.axis_u = p.map.axis_u;
      cut.axis_v = p.map.axis_v;
      for (std::size_t i = 0; i < p.map.size(); ++i)
        if (p.map.distance[i] <= 0.25) {
          cut.vertices.push_back(p.map.vertices[i]);
          cut.indices.push_back(p.map.indices[i]);
          cut.distance.push_back(p.map.distance[i]);
          cut.angle.push_back(p.map.angle[i]);
        }
      p.map = cut;
    }
    write_figure(settings.svg_dir / "mesh_quality.svg", direct, 360, 3);
    std::ofstream(settings.svg_dir / "figures.txt", std::ios::app) << "mesh_quality\n";
  }

  std::ostringstream csv;
  csv << "mesh,method,h,sources,failed,E_d,E_a,E_d_over_h,E_d_max,E_a_max,seconds\n";
  for (const auto& r : rows)
    csv << r.mesh << ',' << r.method_key << ',' << general(r.h) << ',' << sources.size() << ','
        << r.failed << ','
        << general(r.errors.distance) << ',' << general(r.errors.angle) << ','
        << general(r.errors.distance / r.h) << ',' << general(r.errors.distance_max) << ','
        << general(r.errors.angle_max) << ',' << general(r.seconds, 4) << '\n';
  write_text(settings.out / "evaluation" / "mesh_quality.csv", csv.str());
  write_text(settings.out / "evaluation" / "mesh_quality_detail.csv", detail.str());

  auto find = [&](const std::string& mesh, const std::string& key) -> const Row* {
    for (const auto& r : rows)
      if (r.mesh == mesh && r.method_key == key) return &r;
    return nullptr;
  };
  std::ostringstream md;
  md << "# Influence of mesh quality (Fig. 13 of Herholz & Alexa 2019)\n\n"
     << "Generated by `expmap-evaluate --mesh-quality`; raw numbers in\n"
     << "[evaluation/mesh_quality.csv](evaluation/mesh_quality.csv). Discussion in [results.md](results.md).\n\n"
     << "Planar hexagonal patches of equilateral triangles (`make_equilateral_grid(" << rings << ", "
     << edge << ")`, " << cases[0].soup.points.size() << " vertices, h = " << edge << "):\n\n";
  for (const auto& c : cases) md << "* **" << c.key << "**: " << c.note << ";\n";
  md << "\nErrors against the exact map of the plane (r = |p - s|, theta = polar angle), every vertex\n"
     << "within distance " << radius << " of the source, constant rotation removed; mean over "
     << sources.size() << " sources (the centre\nand " << sources.size() - 1
     << " random vertices within 0.1 of it, std::mt19937 seed 1). E_d is absolute (the patch radius is "
     << radius << ");\nE_a in radians.\n\n";
  const std::vector<std::string> keys = {"heat_m10", "heat_m10_idt", "heat_m1", "heat_m1_idt",
                                         "dem", "dgpc", "exact"};
  md << "| method | regular E_d | regular E_a | flipped E_d | flipped E_a | anisotropic E_d | "
        "anisotropic E_a |\n|---|---|---|---|---|---|---|\n";
  // A table row per method: its label, then what `cells(method key)` writes.
  auto method_rows = [&](auto cells) {
    for (const auto& k : keys) {
      const Row* any = find("regular", k);
      md << "| " << (any ? any->method_label : k) << " |";
      cells(k);
      md << "\n";
    }
  };
  const std::vector<std::string> meshes = {"regular", "flipped", "anisotropic"};
  // A cell per mesh: `value(row)` (empty without a row).
  auto mesh_cells = [&](const std::string& k, auto value) {
    for (const auto& mesh : meshes) {
      const Row* r = find(mesh, k);
      md << ' ' << (r ? value(*r) : std::string()) << " |";
    }
  };
  method_rows([&](const std::string& k) {
    for (const auto& mesh : meshes) {
      const Row* r = find(mesh, k);
      md << ' ' << (r ? paper_style(r->errors.distance) : "") << " | "
         << (r ? paper_style(r->errors.angle) : "") << " |";
    }
  });
  md << "| paper, heat (t = h^2) | 0.910e-3 | 0.900e-3 | 0.720e-2 | 0.205e-2 | 0.770e-2 | 0.230e-2 |\n";
  for (const auto& r : rows)
    if (r.failed) {
      std::string first_line = r.failure.substr(0, r.failure.find('\n'));
      std::string rest = r.failure.find("Expr:") != std::string::npos
                             ? r.failure.substr(r.failure.find("Expr:"), r.failure.find('\n', r.failure.find("Expr:")) - r.failure.find("Expr:"))
                             : std::string();
      md << "\n**" << r.method_label << " failed on " << r.failed << " of " << sources.size() << " sources of the "
         << r.mesh << " mesh** (`" << first_line << (rest.empty() ? "" : " " + rest)
         << "`); its errors are over the other sources.\n";
    }
  md << "\nDistance relative to h (E_d / h) and worst errors:\n\n"
     << "| method | regular E_d/h | flipped E_d/h | anisotropic E_d/h | regular max E_a | flipped max E_a | "
        "anisotropic max E_a |\n|---|---|---|---|---|---|---|\n";
  method_rows([&](const std::string& k) {
    mesh_cells(k, [](const Row& r) { return fixed(r.errors.distance / r.h, 3); });
    mesh_cells(k, [](const Row& r) { return paper_style(r.errors.angle_max); });
  });
  md << "\nThe paper does not give its grids' edge length or patch radius, so its absolute distance\n"
        "errors compare only in order of magnitude; the ratios between the three meshes (flipped /\n"
        "regular: 7.9x in distance, 2.3x in angle; anisotropic / regular: 8.5x and 2.6x) are the\n"
        "comparable quantity.\n\n"
     << "![heat maps on the three grids](figures/mesh_quality.png)\n\n"
     << "*Inner part (r <= 0.25) of the heat map (m = 10) from the centre: regular, flipped, anisotropic;\n"
        "top row with the mesh's own cotan Laplacian, bottom row with the intrinsic Delaunay one. Red:\n"
        "flipped triangles.*\n\n"
     << "Run time of this part: " << fixed(seconds_since(run_start), 0) << " s.\n";
  write_text(settings.out / "mesh_quality.md", md.str());
}

}  // namespace expmap_evaluation
