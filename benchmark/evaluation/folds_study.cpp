// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fold-over study of expmap-evaluate (--folds): Figs. 9 and 14 of
// Herholz & Alexa 2019. 5% patches from random sources on real meshes:
// fold-overs, angle and area distortion, accuracy against the exact
// polyhedral map, the effect of the time factor, and pictures of chosen
// patches.

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
#include <expmap/Fold_overs.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace expmap_evaluation {

namespace {

/// Singular values s1 >= s2 of the Jacobian of the map from a 3D triangle
/// to its (u, v) image; false if the image is flipped or degenerate.
bool jacobian_singular_values(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                              const std::array<double, 2>& q0, const std::array<double, 2>& q1,
                              const std::array<double, 2>& q2, double& s1, double& s2) {
  const Vec3 e{{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]}};
  const Vec3 f{{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]}};
  const double le = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  const Vec3 x{{e[0] / le, e[1] / le, e[2] / le}};
  const double fx = f[0] * x[0] + f[1] * x[1] + f[2] * x[2];
  const Vec3 fy_vec{{f[0] - fx * x[0], f[1] - fx * x[1], f[2] - fx * x[2]}};
  const double fy = std::sqrt(fy_vec[0] * fy_vec[0] + fy_vec[1] * fy_vec[1] + fy_vec[2] * fy_vec[2]);
  if (!(fy > 0) || !(le > 0)) return false;
  // P = [[le, fx], [0, fy]] (columns: the edges in the triangle's frame),
  // Q = the same edges in (u, v); J = Q P^-1.
  const double q11 = q1[0] - q0[0], q21 = q1[1] - q0[1];
  const double q12 = q2[0] - q0[0], q22 = q2[1] - q0[1];
  // P^-1 = [[1/le, -fx/(le fy)], [0, 1/fy]]
  const double a = q11 / le, c = q21 / le;
  const double b = (q12 - q11 * fx / le) / fy, d = (q22 - q21 * fx / le) / fy;
  const double det = a * d - b * c;
  if (!(det > 0)) return false;
  const double E = 0.5 * (a + d), F = 0.5 * (a - d), G = 0.5 * (c + b), H = 0.5 * (c - b);
  const double Q = std::hypot(E, H), R = std::hypot(F, G);
  s1 = Q + R;
  s2 = Q - R;
  return s2 > 0;
}

struct Fold_stats {
  std::size_t patches = 0, failed = 0, patches_with_flips = 0;
  std::size_t triangles = 0, flipped = 0;
  // Strictly inverted: signed (u, v) area below -1e-9 times the squared
  // (u, v) edge lengths; the rest of `flipped` is collapsed to (numerically)
  // zero area, e.g. the exact map's fans of equal angles behind a saddle vertex.
  std::size_t inverted = 0, patches_with_inversions = 0;
  // Patches whose distance field collapsed: vertices other than the source
  // at r = 0 (the heat method's clamp of a distance field whose minimum is
  // not at the source).
  std::size_t broken = 0;
  std::vector<double> angle_distortion, area_distortion;  // per valid (not flipped, not collapsed) triangle
  std::vector<double> flip_position;  // per flipped triangle: its nearest corner's r / the patch's largest r
  std::vector<double> distance_error, angle_error;        // per patch, vs exact
  double seconds = 0;
  std::string failure;
};

/// part / whole, as a fraction of at least one (0 for an empty whole).
double share(std::size_t part, std::size_t whole) {
  return double(part) / double(std::max<std::size_t>(1, whole));
}

struct Patch_result {
  bool ok = false, broken = false;
  std::size_t flipped = 0, inverted = 0, triangles = 0;
};

}  // namespace

void run_folds(const Settings& settings) {
  std::cout << "== fold-overs and distortion (Figs. 9, 14) ==\n";
  const auto run_start = std::chrono::steady_clock::now();
  const double fraction = 0.05;
  const std::vector<double> time_factors = {0.1, 1, 10, 100};

  struct Mesh_result {
    std::string name;
    std::size_t vertices = 0;
    double h = 0, non_delaunay = 0;
    std::vector<std::string> method_keys, method_labels;
    std::map<std::string, Fold_stats> stats;
    std::vector<std::size_t> sources;
    std::map<std::string, std::vector<Patch_result>> per_source;
    std::string skipped;
  };
  std::vector<Mesh_result> results;
  std::ostringstream detail;
  detail << "mesh,source,method,vertices,triangles,flipped,inverted,E_d_over_h,E_a,status\n";

  std::vector<std::string> names = settings.mesh_names;
  if (settings.quick) names = {"bull.off", "dino.off"};
  std::vector<std::unique_ptr<Mesh>> meshes;
  for (const std::string& name : names) {
    Mesh_result res;
    res.name = fs::path(name).stem().string();
    meshes.push_back(std::make_unique<Mesh>());
    Mesh& mesh = *meshes.back();
    const fs::path path = settings.meshes / name;
    if (!CGAL::IO::read_polygon_mesh(path.string(), mesh) || mesh.is_empty()) {
      res.skipped = "cannot read " + path.string();
    } else if (!CGAL::is_triangle_mesh(mesh)) {
      res.skipped = "not a triangle mesh";
    } else if (!CGAL::is_closed(mesh)) {
      res.skipped = "not closed";
    } else if (!CGAL::is_valid_polygon_mesh(mesh)) {
      res.skipped = "not a valid (manifold) polygon mesh";
    }
    if (!res.skipped.empty()) {
      std::cout << name << ": skipped, " << res.skipped << "\n";
      results.push_back(res);
      continue;
    }
    res.vertices = num_vertices(mesh);
    res.h = mean_edge_length(mesh);
    res.non_delaunay = non_delaunay_fraction(to_soup(mesh));
    std::cout << res.name << ": " << res.vertices << " vertices, " << num_faces(mesh)
              << " faces, closed manifold, h = " << res.h << std::endl;

    Method_set set(mesh);
    try {
      for (double m : time_factors)
        set.add_heat("heat_m" + general(m), "heat m=" + general(m), m);
      set.add_heat("heat_m10_idt", "heat m=10 iDT", 10.0, expmap::Laplacian_mode::intrinsic_delaunay);
      set.add<expmap::Discrete_exponential_map>("dem", "DEM");
      set.add<expmap::Geodesic_polar_coordinates>("dgpc", "DGPC");
      set.add<expmap::Exact_exponential_map>("exact", "exact");
    } catch (const std::exception& e) {
      res.skipped = std::string("a method rejects it: ") + e.what();
      std::cout << "  skipped: " << res.skipped << "\n";
      results.push_back(res);
      continue;
    }
    for (const auto& m : set.methods) {
      res.method_keys.push_back(m.key);
      res.method_labels.push_back(m.label);
      res.stats[m.key].seconds = 0;
    }

    std::mt19937 rng(1);
    while (res.sources.size() < std::size_t(settings.quick ? 4 : settings.sources)) {
      const std::size_t v = uniform_below(rng, res.vertices);
      if (!CGAL::is_border(Vertex(Mesh::size_type(v)), mesh) &&
          mesh.halfedge(Vertex(Mesh::size_type(v))) != Mesh::null_halfedge())
        res.sources.push_back(v);
    }
    std::vector<Vec3> points(res.vertices);
    for (auto v : vertices(mesh)) {
      const Point& p = mesh.point(v);
      points[std::size_t(v)] = {{p.x(), p.y(), p.z()}};
    }

    for (std::size_t s : res.sources) {
      // Exact first: the reference for the accuracy columns.
      std::map<std::string, Map> maps;
      for (const Method& method : set.methods) {
        Fold_stats& st = res.stats[method.key];
        Patch_result pr;
        const auto start = std::chrono::steady_clock::now();
        try {
          maps[method.key] = method.compute(s, expmap::Patch::fraction(fraction));
          pr.ok = true;
        } catch (const std::exception& e) {
          ++st.failed;
          if (st.failure.empty()) st.failure = e.what();
        }
        const double seconds = seconds_since(start);
        st.seconds += seconds;
        if (!pr.ok) {
          res.per_source[method.key].push_back(pr);
          detail << res.name << ',' << s << ',' << method.key << ",,,,,,failed\n";
          continue;
        }
        const Map& map = maps[method.key];
        ++st.patches;
        for (std::size_t i = 1; i < map.size(); ++i) pr.broken = pr.broken || !(map.distance[i] > 0);
        const double reach = map.size() ? *std::max_element(map.distance.begin(), map.distance.end()) : 0.0;
        for (const auto& t : expmap::patch_triangles(mesh, map)) {
          ++pr.triangles;
          double scale = 0;
          for (int k = 0; k < 3; ++k) {
            const auto a = map.uv(t.corner[k]), b = map.uv(t.corner[(k + 1) % 3]);
            scale += (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
          }
          const double area2 = expmap::signed_uv_area2(map, t);
          if (expmap::is_flipped(map, t)) {
            ++pr.flipped;
            if (area2 < -1e-9 * scale) ++pr.inverted;
            if (reach > 0)
              st.flip_position.push_back(
                  std::min({map.distance[t.corner[0]], map.distance[t.corner[1]], map.distance[t.corner[2]]}) / reach);
            continue;
          }
          if (!(area2 > 1e-9 * scale)) continue;  // collapsed: no meaningful distortion
          double s1, s2;
          if (jacobian_singular_values(points[map.indices[t.corner[0]]], points[map.indices[t.corner[1]]],
                                       points[map.indices[t.corner[2]]], map.uv(t.corner[0]),
                                       map.uv(t.corner[1]), map.uv(t.corner[2]), s1, s2)) {
            st.angle_distortion.push_back(s1 / s2);
            st.area_distortion.push_back(std::abs(std::log(s1 * s2)));
          }
        }
        st.triangles += pr.triangles;
        st.flipped += pr.flipped;
        st.patches_with_flips += pr.flipped > 0;
        st.inverted += pr.inverted;
        st.patches_with_inversions += pr.inverted > 0;
        st.broken += pr.broken;
        res.per_source[method.key].push_back(pr);
      }
      // Accuracy against the exact map, on the vertices both patches share.
      const auto exact_it = maps.find("exact");
      for (const Method& method : set.methods) {
        const auto it = maps.find(method.key);
        double ed = std::nan(""), ea = std::nan("");
        if (it != maps.end() && exact_it != maps.end()) {
          const std::vector<int> pos = positions(exact_it->second, res.vertices);
          const Map& map = it->second;
          std::vector<double> dr, computed, exact;
          for (std::size_t i = 1; i < map.size(); ++i) {
            const int j = pos[map.indices[i]];
            if (j <= 0) continue;
            dr.push_back(std::abs(map.distance[i] - exact_it->second.distance[std::size_t(j)]));
            computed.push_back(map.angle[i]);
            exact.push_back(exact_it->second.angle[std::size_t(j)]);
          }
          double rotation = 0;
          const std::vector<double> da = angle_errors_up_to_rotation(computed, exact, rotation);
          ed = mean(dr) / res.h;
          ea = mean(da);
          res.stats[method.key].distance_error.push_back(ed);
          res.stats[method.key].angle_error.push_back(ea);
        }
        if (it != maps.end()) {
          const Patch_result& pr = res.per_source[method.key].back();
          detail << res.name << ',' << s << ',' << method.key << ',' << it->second.size() << ','
                 << pr.triangles << ',' << pr.flipped << ',' << pr.inverted << ',' << general(ed)
                 << ',' << general(ea) << ',' << (pr.broken ? "broken" : "ok") << '\n';
        }
      }
    }
    for (const auto& key : res.method_keys) {
      const Fold_stats& st = res.stats[key];
      std::cout << "  " << std::setw(14) << std::left << key << std::right << " patches with flips "
                << st.patches_with_flips << "/" << st.patches << " (failed " << st.failed
                << "), flipped triangles " << percent(share(st.flipped, st.triangles), 3)
                << ", angle distortion median " << fixed(median(st.angle_distortion), 3)
                << ", E_d/h " << fixed(mean_finite(st.distance_error), 3) << ", E_a "
                << paper_style(mean_finite(st.angle_error)) << ", inverted patches "
                << st.patches_with_inversions << ", broken " << st.broken << ", "
                << fixed(st.seconds, 2) << " s"
                << std::endl;
    }

    // Pictures of this mesh are chosen after all meshes ran (below), so keep
    // the method set alive through the result only by recomputation.
    results.push_back(std::move(res));
  }

  // --- Pictures: recompute the chosen patches (cheap) and draw them. ---
  std::ofstream figure_list;
  {
    fs::create_directories(settings.svg_dir);
    figure_list.open(settings.svg_dir / "figures.txt", std::ios::app);
  }
  struct Choice {
    std::size_t mesh = 0, source = 0;
    double score = -1;
  };
  Choice folds_choice, folds_small_choice, smooth_choice, time_choice;
  auto is_big = [](const std::string& name) {
    return name == "armadillo" || name == "bunny00" || name == "refined_elephant";
  };
  for (std::size_t mi = 0; mi < results.size(); ++mi) {
    const auto& r = results[mi];
    if (!r.skipped.empty()) continue;
    for (std::size_t k = 0; k < r.sources.size(); ++k) {
      auto flips = [&](const std::string& key) {
        const auto& v = r.per_source.at(key)[k];
        return v.ok ? share(v.flipped, v.triangles) : -1.0;
      };
      const double heat = flips("heat_m10"), dem = flips("dem"), dgpc = flips("dgpc");
      // Folds for both Dijkstra methods, none for heat.
      Choice& folds = is_big(r.name) ? folds_choice : folds_small_choice;
      if (heat == 0 && dem > 0 && dgpc > 0 && std::min(dem, dgpc) > folds.score)
        folds = {mi, r.sources[k], std::min(dem, dgpc)};
      // All clean: a low-curvature region (take the one with the most triangles).
      if (heat == 0 && dem == 0 && dgpc == 0 && flips("exact") == 0) {
        const double size = double(r.per_source.at("heat_m10")[k].triangles) / 1e9;
        if (smooth_choice.score < 0 || (results[smooth_choice.mesh].name != "bunny00" && r.name == "bunny00") ||
            (r.name == results[smooth_choice.mesh].name && size > smooth_choice.score))
          smooth_choice = {mi, r.sources[k], size};
      }
      // Time factor: folds at m = 1, none at m = 100.
      const double m1 = flips("heat_m1"), m100 = flips("heat_m100");
      if (m1 > 0 && m100 == 0 && m1 > time_choice.score) time_choice = {mi, r.sources[k], m1};
    }
  }
  auto draw = [&](const Choice& choice, const std::string& file, const std::vector<std::string>& keys) {
    if (choice.score < 0) {
      std::cout << "no source qualifies for " << file << "\n";
      return std::string();
    }
    const auto& r = results[choice.mesh];
    const Mesh& mesh = *meshes[choice.mesh];
    Method_set set(mesh);
    std::vector<Panel> panels;
    for (const auto& key : keys) {
      if (key.rfind("heat_m", 0) == 0) {
        const double m = std::stod(key.substr(6));
        set.add_heat(key, "heat m=" + general(m), m);
      } else if (key == "dem") {
        set.add<expmap::Discrete_exponential_map>(key, "DEM");
      } else if (key == "dgpc") {
        set.add<expmap::Geodesic_polar_coordinates>(key, "DGPC");
      } else {
        set.add<expmap::Exact_exponential_map>(key, "exact polyhedral");
      }
      const Method& method = set.methods.back();
      try {
        panels.push_back({&mesh, method.compute(choice.source, expmap::Patch::fraction(fraction)),
                          method.label + ", " + r.name + " vertex " + std::to_string(choice.source)});
      } catch (const std::exception& e) {
        std::cout << "  " << key << " fails: " << e.what() << "\n";
      }
    }
    write_figure(settings.svg_dir / (file + ".svg"), panels, 360);
    figure_list << file << "\n";
    return r.name + " vertex " + std::to_string(choice.source);
  };
  const std::string folds_where =
      draw(folds_choice, "folds", {"heat_m10", "exact", "dem", "dgpc"});
  const std::string folds_small_where =
      draw(folds_small_choice, "folds_small", {"heat_m10", "exact", "dem", "dgpc"});
  const std::string smooth_where =
      draw(smooth_choice, "smooth", {"heat_m10", "exact", "dem", "dgpc"});
  const std::string time_where =
      draw(time_choice, "time_factor", {"heat_m0.1", "heat_m1", "heat_m10", "heat_m100", "exact"});

  // --- CSVs ---
  std::ostringstream csv;
  csv << "mesh,vertices,h,method,sources,failed,patches_with_flips,patches_with_flips_fraction,"
         "triangles,flipped_triangles,flipped_fraction,angle_distortion_median,angle_distortion_p95,"
         "log_area_distortion_median,log_area_distortion_p95,E_d_over_h_vs_exact,E_a_vs_exact,"
         "query_seconds_mean,inverted_triangles,patches_with_inversions,broken_patches,"
         "flip_position_median,flip_position_p10\n";
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    for (const auto& key : r.method_keys) {
      const Fold_stats& st = r.stats.at(key);
      csv << r.name << ',' << r.vertices << ',' << general(r.h) << ',' << key << ','
          << r.sources.size() << ',' << st.failed << ',' << st.patches_with_flips << ','
          << general(share(st.patches_with_flips, st.patches))
          << ',' << st.triangles << ',' << st.flipped << ','
          << general(share(st.flipped, st.triangles)) << ','
          << general(median(st.angle_distortion)) << ',' << general(percentile(st.angle_distortion, 95))
          << ',' << general(median(st.area_distortion)) << ','
          << general(percentile(st.area_distortion, 95)) << ',' << general(mean_finite(st.distance_error))
          << ',' << general(mean_finite(st.angle_error)) << ','
          << general(st.seconds / double(std::max<std::size_t>(1, r.sources.size())), 4) << ','
          << st.inverted << ',' << st.patches_with_inversions << ',' << st.broken << ','
          << general(median(st.flip_position)) << ',' << general(percentile(st.flip_position, 10)) << '\n';
    }
  }
  write_text(settings.out / "evaluation" / "folds.csv", csv.str());
  write_text(settings.out / "evaluation" / "folds_detail.csv", detail.str());

  // --- Markdown ---
  std::ostringstream md;
  md << "# Fold-overs and distortion on real meshes (Figs. 9 and 14 of Herholz & Alexa 2019)\n\n"
     << "Generated by `expmap-evaluate --folds`; raw numbers in [evaluation/folds.csv](evaluation/folds.csv)\n"
     << "(one row per mesh and method) and [evaluation/folds_detail.csv](evaluation/folds_detail.csv)\n"
     << "(one row per patch). Discussion in [results.md](results.md).\n\n"
     << "Setup: " << (settings.quick ? 4 : settings.sources)
     << " random source vertices per mesh (std::mt19937 seed 1, reseeded per mesh), each method\n"
     << "maps the nearest 5% of the mesh's vertices (`Patch::fraction(0.05)`, by its own distances).\n"
     << "A patch *has fold-overs* if any of its triangles (faces with three patch vertices) has\n"
     << "non-positive signed area in (u, v) (`expmap::count_flipped_triangles`).\n\n"
     << "Distortion, per valid patch triangle (signed (u, v) area above 1e-9 times its squared (u, v)\n"
     << "edge lengths: neither flipped nor collapsed), from the Jacobian J of the affine map from the 3D\n"
     << "triangle to its (u, v) image, with singular values s1 >= s2 > 0:\n\n"
     << "* angle distortion s1 / s2 (1 = conformal),\n"
     << "* area distortion |log(s1 s2)| (0 = area preserving; s1 s2 = area in (u, v) / area in 3D).\n\n"
     << "Medians and 95th percentiles pool all triangles of all patches of a mesh. E_d / h and E_a\n"
     << "compare with the exact polyhedral map on the vertices both patches share (mean over patches of\n"
     << "the mean |r - r_exact| / h, h the mean edge length, and of the mean angle difference in\n"
     << "radians after removing the constant rotation).\n\n";
  md << "Meshes (non-Delaunay: interior edges whose opposite angles sum to more than pi):\n\n"
        "| mesh | vertices | h | non-Delaunay edges | status |\n|---|---|---|---|---|\n";
  for (const auto& r : results)
    md << "| " << r.name << " | " << (r.skipped.empty() ? std::to_string(r.vertices) : "") << " | "
       << (r.skipped.empty() ? general(r.h, 3) : "") << " | "
       << (r.skipped.empty() ? percent(r.non_delaunay, 1) : "") << " | "
       << (r.skipped.empty() ? "closed manifold triangle mesh" : "skipped: " + r.skipped) << " |\n";

  using Method_column = std::pair<std::string, std::string>;  // key, heading
  const std::vector<Method_column> main_methods = {
      {"heat_m10", "heat (m=10)"}, {"heat_m10_idt", "heat (m=10, iDT)"}, {"dem", "DEM"},
      {"dgpc", "DGPC"}, {"exact", "exact"}};
  std::vector<Method_column> vs_exact;  // the methods compared with the exact map
  for (const auto& m : main_methods)
    if (m.first != "exact") vs_exact.push_back(m);
  // The rest of a table's head after "| mesh |": a column per method.
  auto method_head = [&](const std::vector<Method_column>& methods) {
    for (const auto& m : methods) md << ' ' << m.second << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < methods.size(); ++i) md << "---|";
    md << "\n";
  };
  // A row per mesh that ran, a cell per method; `cell(stats of the method,
  // mesh result, method key)` writes the cell's content.
  auto mesh_rows = [&](const std::vector<Method_column>& methods, auto cell) {
    for (const auto& r : results) {
      if (!r.skipped.empty()) continue;
      md << "| " << r.name << " |";
      for (const auto& m : methods) {
        md << ' ';
        cell(r.stats.at(m.first), r, m.first);
        md << " |";
      }
      md << "\n";
    }
  };
  std::size_t total_patches = 0;
  for (const auto& r : results)
    if (r.skipped.empty()) total_patches += r.sources.size();
  auto totals_row = [&](std::map<std::string, std::size_t>& totals) {
    md << "| all |";
    for (const auto& m : main_methods) md << ' ' << totals[m.first] << "/" << total_patches << " |";
  };
  auto flips_cell = [](const Fold_stats& st) {
    std::string note;
    if (st.failed) note += std::to_string(st.failed) + " failed";
    if (st.broken) note += (note.empty() ? "" : ", ") + std::to_string(st.broken) + " broken";
    return std::to_string(st.patches_with_flips) + "/" + std::to_string(st.patches) +
           (note.empty() ? "" : " (" + note + ")");
  };
  md << "\n## Patches with fold-overs\n\n| mesh |";
  method_head(main_methods);
  std::map<std::string, std::size_t> total_flips;
  mesh_rows(main_methods, [&](const Fold_stats& st, const Mesh_result&, const std::string& key) {
    md << flips_cell(st);
    total_flips[key] += st.patches_with_flips;
  });
  totals_row(total_flips);
  md << "\n\n*broken*: patches whose distance field collapsed (vertices other than the source at r = 0);\n"
        "all their triangles are degenerate, so they count as patches with fold-overs.\n";
  md << "\n## Patches with strictly inverted triangles\n\n"
        "Only triangles with signed (u, v) area below -1e-9 times their squared (u, v) edge lengths;\n"
        "collapsed (zero-area) triangles are not counted here.\n\n| mesh |";
  method_head(main_methods);
  std::map<std::string, std::size_t> total_inversions;
  mesh_rows(main_methods, [&](const Fold_stats& st, const Mesh_result&, const std::string& key) {
    md << st.patches_with_inversions << "/" << st.patches;
    total_inversions[key] += st.patches_with_inversions;
  });
  totals_row(total_inversions);
  md << "\n\n## Flipped triangles (fraction of all patch triangles; strictly inverted in brackets)\n\n| mesh |";
  method_head(main_methods);
  mesh_rows(main_methods, [&](const Fold_stats& st, const Mesh_result&, const std::string&) {
    md << percent(share(st.flipped, st.triangles), 3) << " (" << percent(share(st.inverted, st.triangles), 3)
       << ")";
  });
  auto distortion_table = [&](const char* title, bool angle) {
    md << "\n## " << title << " (median / 95th percentile)\n\n| mesh |";
    method_head(main_methods);
    mesh_rows(main_methods, [&](const Fold_stats& st, const Mesh_result&, const std::string&) {
      const auto& v = angle ? st.angle_distortion : st.area_distortion;
      md << fixed(median(v), 3) << " / " << fixed(percentile(v, 95), 3);
    });
  };
  distortion_table("Angle distortion s1/s2", true);
  distortion_table("Area distortion |log(s1 s2)|", false);
  md << "\n## Where the folds are: nearest corner's r / patch's largest r, per flipped triangle "
        "(median / 10th percentile)\n\n"
        "Near 1: at the rim of the patch (where it reaches a cut locus); small: near the source.\n\n| mesh |";
  method_head(main_methods);
  mesh_rows(main_methods, [&](const Fold_stats& st, const Mesh_result&, const std::string&) {
    const auto& v = st.flip_position;
    md << (v.empty() ? std::string("-") : fixed(median(v), 2) + " / " + fixed(percentile(v, 10), 2));
  });
  md << "\n## Accuracy against the exact map (E_d / h and E_a)\n\n| mesh |";
  method_head(vs_exact);
  mesh_rows(vs_exact, [&](const Fold_stats& st, const Mesh_result&, const std::string&) {
    md << fixed(mean_finite(st.distance_error), 3) << " / " << paper_style(mean_finite(st.angle_error));
  });
  md << "\n## Mean query time per patch (s, one core)\n\n| mesh |";
  method_head(main_methods);
  mesh_rows(main_methods, [&](const Fold_stats& st, const Mesh_result& r, const std::string&) {
    md << general(st.seconds / double(r.sources.size()), 3);
  });

  // Time factor.
  md << "\n## Effect of the time factor m (t = m h^2)\n\n"
     << "| mesh | m | patches with flips | patches with inversions | flipped triangles | angle distortion median / p95 | "
        "E_d / h vs exact | E_a vs exact |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    for (double m : time_factors) {
      const auto& st = r.stats.at("heat_m" + general(m));
      md << "| " << r.name << " | " << general(m) << " | " << flips_cell(st) << " | "
         << st.patches_with_inversions << "/" << st.patches << " | "
         << percent(share(st.flipped, st.triangles), 3) << " | "
         << fixed(median(st.angle_distortion), 3) << " / " << fixed(percentile(st.angle_distortion, 95), 3)
         << " | " << fixed(mean_finite(st.distance_error), 3) << " | " << paper_style(mean_finite(st.angle_error))
         << " |\n";
    }
  }
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    const auto& st = r.stats.at("heat_m0.1");
    if (!st.failure.empty()) {
      md << "\nm = 0.1 failures (e.g. " << r.name << "): `" << st.failure << "`\n";
      break;
    }
  }

  // Targets.
  md << "\n## Target: heat has fewer patches with fold-overs than DEM and than DGPC on every mesh\n\n"
     << "Patches with fold-overs (`count_flipped_triangles`), and in the last four columns with strictly\n"
        "inverted triangles only.\n\n"
     << "| mesh | heat m=10 | DEM | DGPC | met | heat m=10 iDT | met (iDT) | strict: heat | DEM | DGPC | met |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    const auto h = r.stats.at("heat_m10").patches_with_flips, d = r.stats.at("dem").patches_with_flips,
               g = r.stats.at("dgpc").patches_with_flips, hi = r.stats.at("heat_m10_idt").patches_with_flips;
    const auto sh = r.stats.at("heat_m10").patches_with_inversions,
               sd = r.stats.at("dem").patches_with_inversions,
               sg = r.stats.at("dgpc").patches_with_inversions;
    md << "| " << r.name << " | " << h << " | " << d << " | " << g << " | "
       << (h < d && h < g ? "yes" : "**no**") << " | " << hi << " | " << (hi < d && hi < g ? "yes" : "**no**")
       << " | " << sh << " | " << sd << " | " << sg << " | " << (sh < sd && sh < sg ? "yes" : "**no**")
       << " |\n";
  }

  md << "\n## Pictures\n\n";
  if (!folds_where.empty())
    md << "![fold-overs](figures/folds.png)\n\n*" << folds_where
       << ", 5% patch: heat (m = 10), exact polyhedral, DEM, DGPC. Red: flipped triangles. The source with\n"
          "the most flipped triangles for both DEM and DGPC among those where heat has none (armadillo,\n"
          "bunny00, refined_elephant).*\n\n";
  if (!folds_small_where.empty())
    md << "![fold-overs on a smaller mesh](figures/folds_small.png)\n\n*" << folds_small_where
       << ", 5% patch: heat (m = 10), exact, DEM, DGPC; the same choice among camel, bull and dino.*\n\n";
  if (!time_where.empty())
    md << "![time factor](figures/time_factor.png)\n\n*" << time_where
       << ": heat at m = 0.1, 1, 10, 100 and the exact map (Fig. 14 right). The source with the most flipped\n"
          "triangles at m = 1 among those without flips at m = 100.*\n\n";
  if (!smooth_where.empty())
    md << "![smooth region](figures/smooth.png)\n\n*" << smooth_where
       << ": a patch where no method folds (Fig. 9, last row): heat, exact, DEM, DGPC.*\n\n";
  md << "Run time of this part: " << fixed(seconds_since(run_start), 0) << " s.\n";
  write_text(settings.out / "folds.md", md.str());
}

}  // namespace expmap_evaluation
