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
#include "evaluation/Figures.h"
#include "evaluation/Formatting.h"
#include "evaluation/Geodesic_shooting.h"
#include "evaluation/Meshes.h"
#include "evaluation/Methods.h"
#include "evaluation/Reference_maps.h"
#include "evaluation/Statistics.h"
#include "evaluation/Surfaces.h"

#include <expmap/Analytic_surfaces.h>
#include <expmap/Discrete_exponential_map.h>
#include <expmap/Errors.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Fold_overs.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace expmap_evaluation;

/// Distances from `source` to every vertex by CGAL's Heat_method_3.
std::vector<double> cgal_heat_distances(Mesh& mesh, std::size_t source) {
  auto d = mesh.add_property_map<Vertex, double>("v:evaluate_cgal_distance", 0.0).first;
  {
    CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mesh> cgal(mesh);
    cgal.add_source(Vertex(static_cast<Mesh::size_type>(source)));
    cgal.estimate_geodesic_distances(d);
  }
  std::vector<double> field(num_vertices(mesh));
  for (auto v : vertices(mesh)) field[std::size_t(v)] = get(d, v);
  mesh.remove_property_map(d);
  return field;
}

// ---------------------------------------------------------------------------
// Settings
// ---------------------------------------------------------------------------

struct Settings {
  bool accuracy = false, mesh_quality = false, folds = false, quick = false;
  fs::path out = "doc", meshes = "data/meshes", svg_dir = "build/evaluation-svg";
  int sources = 50;
  std::vector<std::string> mesh_names = {"armadillo.off", "bunny00.off", "refined_elephant.off",
                                         "camel.off", "bull.off", "dino.off"};
};

// ---------------------------------------------------------------------------
// 1. Accuracy (Table 1)
// ---------------------------------------------------------------------------

// The paper's Table 1 (columns: sphere, Gauss, saddle at 0.001, 0.002, 0.005).
const std::map<std::string, std::array<double, 9>> paper_distance = {
    {"heat", {0.612e-3, 0.211e-2, 0.174e-2, 0.593e-3, 0.584e-3, 0.142e-2, 0.324e-3, 0.928e-3, 0.173e-2}},
    {"DEM", {0.125e-2, 0.148e-2, 0.912e-3, 0.453e-2, 0.364e-2, 0.863e-2, 0.287e-3, 0.963e-3, 0.197e-2}},
    {"DGPC", {0.9e-4, 0.174e-3, 0.279e-3, 0.523e-3, 0.221e-3, 0.138e-2, 0.524e-4, 0.135e-3, 0.440e-3}}};
const std::map<std::string, std::array<double, 9>> paper_angle = {
    {"heat", {0.186e-3, 0.255e-3, 0.107e-2, 0.212e-3, 0.629e-3, 0.461e-2, 0.384e-2, 0.848e-2, 0.187e-1}},
    {"DEM", {0.325e-3, 0.538e-3, 0.138e-3, 0.129e-2, 0.168e-2, 0.829e-2, 0.323e-1, 0.376e-1, 0.402e-1}},
    {"DGPC", {0.409e-4, 0.871e-4, 0.21e-3, 0.179e-3, 0.408e-4, 0.168e-2, 0.111e-2, 0.314e-2, 0.106e-1}}};

struct Accuracy_row {
  std::string surface, column, method_key, method_label, reference;
  double target_h = 0, h = 0;
  std::size_t vertices = 0, sources = 0;
  Errors errors;  // averaged over sources
  double seconds = 0;
  double non_delaunay = 0;  // fraction of interior edges whose opposite angles sum to more than pi
};

void run_accuracy(const Settings& settings) {
  std::cout << "== accuracy (Table 1) ==\n";
  const auto run_start = std::chrono::steady_clock::now();
  const std::vector<std::pair<std::string, double>> columns =
      settings.quick ? std::vector<std::pair<std::string, double>>{{"0.002", 0.04}, {"0.005", 0.05}}
                     : std::vector<std::pair<std::string, double>>{
                           {"0.001", 0.01}, {"0.002", 0.02}, {"0.005", 0.05}};
  const double radius = 1.0;              // geodesic patch radius on every surface
  const double bump_amplitude = 0.8, bump_sigma = 0.5;
  const double saddle_amplitude = 0.5;
  const double half_width = 1.6;          // height-field domain [-1.6, 1.6]^2
  const int sphere_sources = settings.quick ? 1 : 3;
  const int directions = 72, per_geodesic = 50;

  std::vector<Accuracy_row> rows;
  std::ostringstream ode_notes;
  Ode_report saddle_ode, bump_ode;
  const Height_field saddle = saddle_field(saddle_amplitude);
  const Height_field bump = gaussian_bump_field(bump_amplitude, bump_sigma);
  const auto saddle_samples = shoot_geodesics(saddle, directions, per_geodesic, radius, saddle_ode);
  const auto bump_samples = shoot_geodesics(bump, directions, per_geodesic, radius, bump_ode);
  // Cross-check of the geodesic integrator on the bump, where the answer is
  // known: a geodesic from the apex is a meridian.
  double bump_ode_distance = 0, bump_ode_angle = 0;
  for (const auto& g : bump_samples) {
    bump_ode_distance = std::max(
        bump_ode_distance,
        std::abs(expmap::gaussian_bump_meridian_length(std::hypot(g.x, g.y), bump_amplitude,
                                                       bump_sigma) - g.s));
    bump_ode_angle = std::max(bump_ode_angle, std::abs(wrap_angle(std::atan2(g.y, g.x) - g.theta)));
  }
  std::cout << "saddle geodesics: speed residual " << saddle_ode.speed_residual
            << ", tolerance change " << saddle_ode.tolerance_change << "\n"
            << "bump geodesics: speed residual " << bump_ode.speed_residual
            << ", max |arc length - meridian length| " << bump_ode_distance
            << ", max azimuth drift " << bump_ode_angle << "\n";

  // gauss / saddle: height fields on a hexagonal lattice (equilateral in the
  // plane, valence 6, Delaunay with margin once lifted); gauss_grid /
  // saddle_grid: the library's make_gaussian_bump / make_saddle (union-jack
  // right triangles, whose diagonals are only just Delaunay in the plane and
  // turn non-Delaunay wherever the surface bends).
  // *_irregular: the same surfaces with jittered vertices, Delaunay
  // triangulated (irregular, isotropic on average, still Delaunay).
  const std::vector<std::string> surface_list = {"sphere", "gauss", "saddle",
                                                 "sphere_irregular", "gauss_irregular", "saddle_irregular",
                                                 "gauss_grid", "saddle_grid"};
  const double jitter = 0.35;  // of the lattice spacing
  for (const std::string& surface : surface_list) {
    const bool is_sphere = surface.rfind("sphere", 0) == 0;
    const bool is_gauss = surface.rfind("gauss", 0) == 0;
    const bool union_jack = surface.find("_grid") != std::string::npos;
    const bool irregular = surface.find("_irregular") != std::string::npos;
    auto height = [&](double x, double y) {
      return is_gauss ? bump.eval(x, y)[0] : saddle.eval(x, y)[0];
    };
    for (const auto& [column, target] : columns) {
      // The mesh at this resolution.
      expmap::Triangle_soup soup;
      std::string parameter;
      std::size_t origin = 0;  // the source of the height fields
      if (is_sphere) {
        const int k = closest_resolution(target, 4, 1, [](int k) { return geodesic_sphere(k); });
        soup = irregular ? jittered_sphere(k, jitter, 1) : geodesic_sphere(k);
        parameter = "frequency " + std::to_string(k) + (irregular ? ", jittered, convex hull" : "");
      } else if (union_jack) {
        auto make = [&](int n) {
          return is_gauss ? expmap::make_gaussian_bump(n, half_width, bump_amplitude, bump_sigma)
                          : expmap::make_saddle(n, half_width, saddle_amplitude);
        };
        const int n = closest_resolution(target, 16, 2, make);
        soup = make(n);
        origin = expmap::grid_origin_vertex(n, n);
        parameter = std::to_string(n) + "x" + std::to_string(n) + " cells";
      } else {
        // Hexagon of inradius >= half_width; edge tuned so the lifted mean
        // edge length hits the target.
        auto make = [&](double edge) {
          const int rings = static_cast<int>(std::ceil(half_width / (edge * std::sqrt(3.0) / 2)));
          expmap::Triangle_soup hex = expmap::make_equilateral_grid(rings, edge);
          for (auto& p : hex.points) p[2] = height(p[0], p[1]);
          return hex;
        };
        double edge = target;
        for (int iteration = 0; iteration < 3; ++iteration)
          edge *= target / mean_edge_length(make(edge));
        if (irregular) {
          // Jittering lengthens the Delaunay edges a little; re-tune.
          auto make_irregular = [&](double e) { return jittered_height_field(e, half_width, jitter, 1, height); };
          for (int iteration = 0; iteration < 2; ++iteration)
            edge *= target / mean_edge_length(make_irregular(edge));
          soup = make_irregular(edge);
        } else {
          soup = make(edge);
        }
        origin = 0;
        parameter = std::string(irregular ? "jittered " : "") + "hexagonal lattice, edge " +
                    general(edge, 4) + " in the plane" + (irregular ? ", Delaunay in the plane" : "");
      }
      Mesh mesh = to_mesh(soup);
      const std::size_t nv = soup.points.size();
      const double h = mean_edge_length(mesh);
      const double non_delaunay = non_delaunay_fraction(soup);
      std::cout << surface << " " << column << ": " << parameter << ", " << nv
                << " vertices, h = " << h << ", non-Delaunay edges " << percent(non_delaunay, 2)
                << std::endl;

      // Reference points per source.
      std::vector<std::size_t> sources;
      std::vector<std::vector<Reference_point>> references;
      std::vector<Reference_point> bump_ode_points;  // gauss: the ODE samples too
      if (is_sphere) {
        std::mt19937 rng(1);
        for (int i = 0; i < sphere_sources; ++i) sources.push_back(uniform_below(rng, nv));
        for (std::size_t s : sources) {
          std::vector<Reference_point> ref;
          // Any tangent reference direction: the rotation is removed anyway.
          const Vec3& n = soup.points[s];
          const Vec3 e1 = std::abs(n[2]) < 0.9 ? Vec3{{-n[1], n[0], 0.0}} : Vec3{{1.0, 0.0, 0.0}};
          for (std::size_t v = 0; v < nv; ++v) {
            if (v == s) continue;
            const auto polar = expmap::sphere_exponential_map(soup.points[s], soup.points[v], 1.0, e1);
            if (polar.r > radius) continue;
            Reference_point p;
            p.vertex = int(v);
            p.r = polar.r;
            p.theta = polar.theta_unrotated;
            ref.push_back(p);
          }
          references.push_back(std::move(ref));
        }
      } else {
        const std::size_t s = origin;
        sources.push_back(s);
        std::vector<Reference_point> ref;
        const Xy_locator locator(soup);
        if (is_gauss) {
          for (std::size_t v = 0; v < nv; ++v) {
            if (v == s) continue;
            const auto polar =
                expmap::gaussian_bump_exponential_map(soup.points[v], bump_amplitude, bump_sigma, {{1, 0, 0}});
            if (polar.r > radius) continue;
            Reference_point p;
            p.vertex = int(v);
            p.r = polar.r;
            p.theta = polar.theta_unrotated;
            ref.push_back(p);
          }
          for (const auto& g : bump_samples) {
            Reference_point p;
            if (!locator.locate(g.x, g.y, p)) continue;
            p.r = g.s;
            p.theta = g.theta;
            bump_ode_points.push_back(p);
          }
        } else {
          for (const auto& g : saddle_samples) {
            Reference_point p;
            if (!locator.locate(g.x, g.y, p)) continue;
            p.r = g.s;
            p.theta = g.theta;
            ref.push_back(p);
          }
        }
        references.push_back(std::move(ref));
      }
      const std::string reference_kind =
          is_sphere ? "vertices, analytic"
          : is_gauss          ? "vertices, meridian length"
                              : "geodesic samples (ODE), interpolated";

      // Methods.
      Method_set set(mesh);
      set.add_heat("heat_m10", "heat (m = 10, default)", 10.0);
      set.add_heat("heat_m1", "heat (m = 1, paper's t = h^2)", 1.0);
      set.add_heat("heat_m10_idt", "heat (m = 10, intrinsic Delaunay)", 10.0,
                   expmap::Laplacian_mode::intrinsic_delaunay);
      set.add<expmap::Discrete_exponential_map>("dem", "DEM");
      set.add<expmap::Geodesic_polar_coordinates>("dgpc", "DGPC");
      set.add<expmap::Exact_exponential_map>("exact", "exact polyhedral");
      const expmap::Patch patch = expmap::Patch::geodesic_radius(radius + 3 * h);

      for (const Method& method : set.methods) {
        Accuracy_row row{surface, column, method.key, method.label, reference_kind, target, h, nv,
                         sources.size(), {}, method.precompute_seconds, non_delaunay};
        std::vector<double> ed, ea, edm, eam, edi, eai;
        std::size_t points = 0, missing = 0;
        Errors ode_errors;
        for (std::size_t i = 0; i < sources.size(); ++i) {
          const auto start = std::chrono::steady_clock::now();
          const Map map = method.compute(sources[i], patch);
          row.seconds += seconds_since(start);
          const Errors e = map_errors(map, nv, references[i], 0.5 * radius);
          ed.push_back(e.distance);
          ea.push_back(e.angle);
          edm.push_back(e.distance_max);
          eam.push_back(e.angle_max);
          edi.push_back(e.distance_inner);
          eai.push_back(e.angle_inner);
          points += e.points;
          missing += e.missing;
          if (is_gauss) ode_errors = map_errors(map, nv, bump_ode_points, 0.5 * radius);
        }
        row.errors.distance = mean(ed);
        row.errors.angle = mean(ea);
        row.errors.distance_max = *std::max_element(edm.begin(), edm.end());
        row.errors.angle_max = *std::max_element(eam.begin(), eam.end());
        row.errors.points = points;
        row.errors.missing = missing;
        row.errors.distance_inner = mean(edi);
        row.errors.angle_inner = mean(eai);
        rows.push_back(row);
        std::cout << "  " << std::setw(32) << std::left << method.label << std::right
                  << " E_d " << paper_style(row.errors.distance) << "  E_a "
                  << paper_style(row.errors.angle) << "  (" << points << " points, " << missing
                  << " outside the patch, " << fixed(row.seconds, 2) << " s)" << std::endl;
        if (is_gauss) {
          Accuracy_row alt = row;
          alt.reference = "geodesic samples (ODE), interpolated";
          alt.method_key = method.key + "_ode_samples";
          alt.errors = ode_errors;
          rows.push_back(alt);
          std::cout << "  " << std::setw(32) << std::left << (method.label + " [ODE samples]")
                    << std::right << " E_d " << paper_style(ode_errors.distance) << "  E_a "
                    << paper_style(ode_errors.angle) << std::endl;
        }
      }
      // CGAL's heat method (whole mesh, t = h^2): distances only.
      {
        const auto start = std::chrono::steady_clock::now();
        std::vector<double> ed, edm;
        std::size_t points = 0;
        for (std::size_t i = 0; i < sources.size(); ++i) {
          const auto field = cgal_heat_distances(mesh, sources[i]);
          const Errors e = field_errors(field, references[i]);
          ed.push_back(e.distance);
          edm.push_back(e.distance_max);
          points += e.points;
        }
        Accuracy_row row{surface, column, "cgal_heat", "CGAL Heat_method_3 (t = h^2)",
                         reference_kind, target, h, nv, sources.size(), {}, seconds_since(start),
                         non_delaunay};
        row.errors.distance = mean(ed);
        row.errors.distance_max = *std::max_element(edm.begin(), edm.end());
        row.errors.points = points;
        rows.push_back(row);
        std::cout << "  " << std::setw(32) << std::left << row.method_label << std::right
                  << " E_d " << paper_style(row.errors.distance) << "  ("
                  << fixed(row.seconds, 2) << " s)" << std::endl;
      }
    }
  }

  // CSV.
  std::ostringstream csv;
  csv << "surface,paper_column,target_h,h,vertices,non_delaunay_edges,method,reference,sources,points,missing,"
         "E_d,E_a,E_d_over_h,E_d_max,E_a_max,E_d_inner_half,E_a_inner_half,seconds\n";
  for (const auto& r : rows)
    csv << r.surface << ',' << r.column << ',' << r.target_h << ',' << general(r.h) << ','
        << r.vertices << ',' << general(r.non_delaunay) << ',' << r.method_key << ",\"" << r.reference << "\"," << r.sources << ','
        << r.errors.points << ',' << r.errors.missing << ',' << general(r.errors.distance) << ','
        << general(r.errors.angle) << ',' << general(r.errors.distance / r.h) << ','
        << general(r.errors.distance_max) << ',' << general(r.errors.angle_max) << ','
        << general(r.errors.distance_inner) << ',' << general(r.errors.angle_inner) << ','
        << general(r.seconds, 4) << '\n';
  write_text(settings.out / "evaluation" / "accuracy.csv", csv.str());

  // Markdown.
  auto find = [&](const std::string& surface, const std::string& column,
                  const std::string& key) -> const Accuracy_row* {
    for (const auto& r : rows)
      if (r.surface == surface && r.column == column && r.method_key == key) return &r;
    return nullptr;
  };
  std::vector<std::string> labels;
  for (const auto& c : columns) labels.push_back(c.first);
  auto paper_index = [&](const std::string& surface, const std::string& column) {
    const int s = surface.rfind("sphere", 0) == 0 ? 0 : surface.rfind("gauss", 0) == 0 ? 1 : 2;
    const int c = column == "0.001" ? 0 : column == "0.002" ? 1 : 2;
    return std::size_t(3 * s + c);
  };
  auto surface_name = [](const std::string& s) {
    const std::string base = s.rfind("sphere", 0) == 0 ? "Sphere" : s.rfind("gauss", 0) == 0 ? "Gauss" : "Saddle";
    return base + (s.find("_grid") != std::string::npos        ? " (union jack)"
                   : s.find("_irregular") != std::string::npos ? " (irregular)"
                                                               : "");
  };
  const std::vector<std::pair<std::string, std::string>> method_rows = {
      {"heat_m10", "heat m=10"}, {"heat_m1", "heat m=1"}, {"heat_m10_idt", "heat m=10 iDT"},
      {"dem", "DEM"},            {"dgpc", "DGPC"},        {"exact", "exact"},
      {"cgal_heat", "CGAL heat"}};
  // One table in the paper's layout: a row per (quantity, method), a column
  // per (surface, resolution).
  auto table = [&](std::ostringstream& out, const std::vector<std::string>& surfaces, bool relative,
                   bool inner = false) {
    out << "| |";
    for (const auto& s : surfaces)
      for (const auto& l : labels) out << ' ' << surface_name(s) << ' ' << l << " |";
    out << "\n|---|";
    for (std::size_t i = 0; i < surfaces.size() * labels.size(); ++i) out << "---|";
    out << "\n";
    auto info = [&](const char* name, auto value) {
      out << "| " << name << " |";
      for (const auto& s : surfaces)
        for (const auto& l : labels) {
          const auto* r = find(s, l, "heat_m10");
          out << ' ' << (r ? value(*r) : std::string()) << " |";
        }
      out << "\n";
    };
    info("h (mean edge length)", [](const Accuracy_row& r) { return fixed(r.h, 4); });
    info("vertices", [](const Accuracy_row& r) { return std::to_string(r.vertices); });
    if (relative) {
      for (const auto& [key, name] : method_rows) {
        out << "| E_d/h " << name << " |";
        for (const auto& s : surfaces)
          for (const auto& l : labels) {
            const auto* r = find(s, l, key);
            out << ' ' << (r ? fixed(r->errors.distance / r->h, 3) : std::string()) << " |";
          }
        out << "\n";
      }
      return;
    }
    for (const char* what : {"distance", "angle"})
      for (const auto& [key, name] : method_rows) {
        if ((std::string(what) == "angle" || inner) && key == "cgal_heat") continue;
        out << "| " << what << " " << name << " |";
        for (const auto& s : surfaces)
          for (const auto& l : labels) {
            const auto* r = find(s, l, key);
            const bool d = std::string(what) == "distance";
            out << ' '
                << (r ? paper_style(inner ? (d ? r->errors.distance_inner : r->errors.angle_inner)
                                          : (d ? r->errors.distance : r->errors.angle))
                      : std::string())
                << " |";
          }
        out << "\n";
      }
  };

  const std::vector<std::string> main_surfaces = {"sphere", "gauss", "saddle"};
  std::ostringstream md;
  md << "# Accuracy on analytic surfaces (Table 1 of Herholz & Alexa 2019)\n\n"
     << "Generated by `expmap-evaluate --accuracy` (benchmark/expmap_evaluate.cpp); raw numbers in\n"
     << "[evaluation/accuracy.csv](evaluation/accuracy.csv). Discussion in [results.md](results.md).\n\n"
     << "## Setup\n\n"
     << "* **Resolutions.** The paper's columns 0.001, 0.002, 0.005 are read as *mean edge lengths*\n"
     << "  (its text: \"we compare results for different mean edge lengths\") on surfaces about ten times\n"
     << "  smaller than ours, i.e. h / L = 0.01, 0.02, 0.05 for surfaces of unit size L (unit sphere;\n"
     << "  height fields over about [-1.6, 1.6]^2; patch radius 1). Taken literally (h = 0.001 on a unit\n"
     << "  sphere) the finest sphere would need ~14 million vertices, far more than the paper's exact-\n"
     << "  geodesics reference could handle. Each mesh is the member of its family whose measured mean\n"
     << "  edge length h is closest to the target (row `h`). Angles are scale free, so E_a compares with the\n"
     << "  paper directly under this reading; E_d scales with the surface and is also given as E_d / h, to\n"
     << "  compare with the paper's E_d / column label.\n"
     << "* **Sphere**: unit sphere, geodesic (class I) icosahedral subdivision of frequency k (any\n"
     << "  resolution, nearly regular, Delaunay); " << sphere_sources
     << " random source vertices (std::mt19937 seed 1); every vertex within\n"
     << "  geodesic distance 1 compared with the analytic map.\n"
     << "* **Gauss**: z = " << bump_amplitude << " exp(-(x^2 + y^2) / (2 * " << bump_sigma
     << "^2)), source at the apex; every vertex within distance 1\n"
     << "  compared with the surface-of-revolution reference (distance = meridian arc length, angle = azimuth).\n"
     << "* **Saddle**: z = " << saddle_amplitude << " sin(x) sin(y), source at the saddle point. Reference: "
     << directions << " geodesics shot from the\n"
     << "  origin with Boost.Odeint (Dormand-Prince 5(4), tolerance 1e-13) on the geodesic equations of the\n"
     << "  metric g = I + grad f grad f^T (Christoffel symbols f_k f_ij / (1 + |grad f|^2)), unit initial speed\n"
     << "  at angle theta in the tangent plane z = 0; " << per_geodesic
     << " samples per geodesic at arc lengths 0.02 ... 1.0, each located\n"
     << "  on the mesh by its (x, y) and compared with the barycentric interpolation of the computed map\n"
     << "  (r interpolated; angle of the interpolated (u, v): no wrap-around, and right next to the source).\n"
     << "* **Height-field meshes.** The paper restricts its accuracy study to Delaunay meshes. The main\n"
     << "  tables lift a hexagonal lattice (equilateral triangles in the plane, valence 6; the hexagon's\n"
     << "  inradius is 1.6) onto the height fields: its opposite angles sum to about 120 degrees, so it stays\n"
     << "  Delaunay when lifted. The library's `make_gaussian_bump` / `make_saddle` (union-jack grid of right\n"
     << "  triangles over [-1.6, 1.6]^2) are measured too, in a separate table: their diagonals are exactly\n"
     << "  on the Delaunay limit in the plane and become non-Delaunay where the surface bends (row\n"
     << "  `non-Delaunay edges`).\n"
     << "* **Irregular meshes.** The same three surfaces with jittered vertices, Delaunay triangulated\n"
     << "  (section below), to show how much the methods depend on a regular triangulation.\n"
     << "* **Errors**: E_d = mean |r - r_exact| (absolute, unit-size surfaces), E_a = mean |theta -\n"
     << "  theta_exact| in radians after removing the constant rotation between the maps (circular mean of\n"
     << "  the differences); averaged over the sources. Every method maps a geodesic disk of radius 1 + 3h,\n"
     << "  so every reference point lies inside every patch.\n"
     << "* **Methods**: heat at the library default m = 10 (t = 10 h^2), at the paper's t = h^2 (m = 1), and\n"
     << "  at m = 10 on the intrinsic Delaunay triangulation (iDT); DEM; DGPC; exact polyhedral geodesics\n"
     << "  (CGAL Surface_mesh_shortest_path); CGAL's Heat_method_3 (Direct, t = h^2, whole mesh; distances).\n\n";
  md << "Geodesic integrator: max speed residual |g(x', x') - 1| = "
     << general(saddle_ode.speed_residual, 2) << " (saddle), " << general(bump_ode.speed_residual, 2)
     << " (bump); max position change between tolerances 1e-10 and 1e-13: "
     << general(saddle_ode.tolerance_change, 2) << " (saddle). On the bump, where the geodesics from the\n"
     << "apex are meridians, the shot geodesics agree with the closed form to "
     << general(bump_ode_distance, 2) << " in arc length and " << general(bump_ode_angle, 2)
     << " rad in azimuth.\n\n";

  md << "## Measured (Delaunay meshes)\n\n";
  table(md, main_surfaces, false);
  md << "\nDistance relative to the mean edge length, E_d / h:\n\n";
  table(md, main_surfaces, true);

  md << "\nThe inner half of the patches only (reference points with r <= 0.5; same maps, same\n"
        "rotation), to show how much the patch radius, which the paper does not state, matters:\n\n";
  table(md, main_surfaces, false, true);
  md << "\n## The paper's Table 1\n\n| |";
  for (const auto& s : main_surfaces)
    for (const auto& l : labels) md << ' ' << surface_name(s) << ' ' << l << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < main_surfaces.size() * labels.size(); ++i) md << "---|";
  md << "\n";
  for (const char* what : {"distance", "angle"})
    for (const char* m : {"heat", "DEM", "DGPC"}) {
      md << "| " << what << " " << m << " |";
      const auto& paper = std::string(what) == "distance" ? paper_distance : paper_angle;
      for (const auto& s : main_surfaces)
        for (const auto& l : labels) md << ' ' << paper_style(paper.at(m)[paper_index(s, l)]) << " |";
      md << "\n";
    }
  md << "| E_d/label heat (labels read as h) |";
  for (const auto& s : main_surfaces)
    for (const auto& l : labels)
      md << ' ' << fixed(paper_distance.at("heat")[paper_index(s, l)] / std::stod(l), 3) << " |";
  md << "\n";

  md << "\n## Union-jack height fields (the library's make_gaussian_bump / make_saddle)\n\n";
  table(md, {"gauss_grid", "saddle_grid"}, false);
  md << "| non-Delaunay edges (hexagonal lattice for comparison) |";
  for (const auto& s : {"gauss_grid", "saddle_grid"})
    for (const auto& l : labels) {
      const auto* r = find(s, l, "heat_m10");
      const auto* hex = find(std::string(s).substr(0, std::string(s).find('_')), l, "heat_m10");
      md << ' ' << (r ? percent(r->non_delaunay, 1) : std::string()) << " ("
         << (hex ? percent(hex->non_delaunay, 1) : std::string()) << ") |";
    }
  md << "\n";

  md << "\n## Irregular Delaunay meshes (jittered vertices)\n\n"
     << "The same surfaces with every vertex moved by a random vector of up to " << jitter
     << " lattice spacings (std::mt19937\n"
        "seed 1) and re-triangulated: the sphere as the convex hull of its points (its spherical Delaunay\n"
        "triangulation), the height fields by a planar Delaunay triangulation lifted onto the surface (row\n"
        "`non-Delaunay edges`: the few edges the lift makes non-Delaunay). Sources, patches and references\n"
        "as above.\n\n";
  const std::vector<std::string> irregular_surfaces = {"sphere_irregular", "gauss_irregular", "saddle_irregular"};
  table(md, irregular_surfaces, false);
  md << "| non-Delaunay edges |";
  for (const auto& s : irregular_surfaces)
    for (const auto& l : labels) {
      const auto* r = find(s, l, "heat_m10");
      md << ' ' << (r ? percent(r->non_delaunay, 1) : std::string()) << " |";
    }
  md << "\n| largest E_a heat m=10 (next to the source) |";
  for (const auto& s : irregular_surfaces)
    for (const auto& l : labels) {
      const auto* r = find(s, l, "heat_m10");
      md << ' ' << (r ? paper_style(r->errors.angle_max) : std::string()) << " |";
    }
  md << "\n\nInner half only (r <= 0.5):\n\n";
  table(md, irregular_surfaces, false, true);

  // Targets.
  auto check = [&](const std::string& name, const std::string& col, double value, double bound) {
    md << "| " << name << " | " << col << " | " << paper_style(value) << " | " << paper_style(bound)
       << " | " << (value <= bound ? "yes (x" + fixed(value / bound, 4) + ")" : "**no** (x" + fixed(value / bound, 4) + ")")
       << " |\n";
  };
  const std::vector<std::pair<std::string, std::string>> heats = {{"heat_m10", "heat m=10"},
                                                                  {"heat_m1", "heat m=1"}};
  auto targets = [&](const std::vector<std::string>& family) {
    md << "| check | column | measured | bound | met |\n|---|---|---|---|---|\n";
    for (const auto& [key, name] : heats)
      for (const auto& s : family)
        for (const auto& l : labels)
          if (const auto* r = find(s, l, key))
            check("E_a " + name + " <= paper's heat E_a", surface_name(s) + " " + l, r->errors.angle,
                  paper_angle.at("heat")[paper_index(s, l)]);
    for (const auto& [key, name] : heats)
      for (const auto& s : family) {
        if (s.rfind("saddle", 0) == 0) continue;
        for (const auto& l : labels) {
          const auto* dem = find(s, l, "dem");
          if (const auto* r = find(s, l, key); r && dem)
            check("E_a " + name + " <= E_a DEM", surface_name(s) + " " + l, r->errors.angle, dem->errors.angle);
        }
      }
    for (const auto& [key, name] : heats)
      for (const auto& s : family)
        for (const auto& l : labels) {
          const auto* cgal = find(s, l, "cgal_heat");
          if (const auto* r = find(s, l, key); r && cgal)
            check("E_d " + name + " <= E_d CGAL heat (t = h^2)", surface_name(s) + " " + l,
                  r->errors.distance, cgal->errors.distance);
        }
  };
  md << "\n## Targets\n\n### Main (regular Delaunay) meshes\n\n";
  targets(main_surfaces);
  md << "\n### Irregular Delaunay meshes\n\n";
  targets(irregular_surfaces);
  md << "\nThe x factor is measured / bound.\n";

  md << "\n## Cross-check on the Gauss bump: vertices vs. interpolated ODE samples\n\n"
     << "The same maps evaluated at the shot geodesics' samples (interpolated, as for the saddle) instead\n"
     << "of at the vertices:\n\n"
     << "| method | column | E_d vertices | E_d samples | E_a vertices | E_a samples |\n"
        "|---|---|---|---|---|---|\n";
  for (const auto& l : labels)
    for (const auto& [key, name] : method_rows) {
      const auto* a = find("gauss", l, key);
      const auto* b = find("gauss", l, key + "_ode_samples");
      if (!a || !b) continue;
      md << "| " << name << " | " << l << " | " << paper_style(a->errors.distance) << " | "
         << paper_style(b->errors.distance) << " | " << paper_style(a->errors.angle) << " | "
         << paper_style(b->errors.angle) << " |\n";
    }
  md << "\nRun time of this part: " << fixed(seconds_since(run_start), 0) << " s.\n";
  write_text(settings.out / "accuracy_table.md", md.str());
}

// ---------------------------------------------------------------------------
// 2. Mesh quality (Fig. 13)
// ---------------------------------------------------------------------------

void run_mesh_quality(const Settings& settings) {
  std::cout << "== mesh quality (Fig. 13) ==\n";
  const auto run_start = std::chrono::steady_clock::now();
  const int rings = settings.quick ? 70 : 100;
  const double edge = 0.02, radius = 0.5;
  const double stretch = std::sqrt(3.0);  // area-preserving, aspect ratio 3

  struct Case {
    std::string key, label;
    expmap::Triangle_soup soup;
    std::string note;
  };
  std::vector<Case> cases;
  {
    Case regular{"regular", "regular", expmap::make_equilateral_grid(rings, edge), ""};
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
    const std::size_t n_flipped = expmap::flip_random_edges(flipped.soup, 0.5, 1);
    flipped.note = std::to_string(n_flipped) + " of " + std::to_string(interior) +
                   " interior edges flipped (" + percent(double(n_flipped) / double(interior)) +
                   "; flip_random_edges(0.5, seed 1) saturates there)";
    Case aniso{"anisotropic", "anisotropic (x*sqrt3, y/sqrt3)", regular.soup, ""};
    expmap::scale_anisotropically(aniso.soup, stretch, 1 / stretch, 1.0);
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
      std::vector<double> ed, ea, edm, eam;
      double seconds = method.precompute_seconds;
      std::size_t failed = 0;
      std::string failure;
      for (std::size_t s : sources) {
        std::vector<Reference_point> ref;
        for (std::size_t v = 0; v < c.soup.points.size(); ++v) {
          if (v == s) continue;
          const auto polar = expmap::plane_exponential_map(c.soup.points[s], c.soup.points[v], {{1, 0, 0}});
          if (polar.r > radius) continue;
          Reference_point p;
          p.vertex = int(v);
          p.r = polar.r;
          p.theta = polar.theta_unrotated;
          ref.push_back(p);
        }
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
        ed.push_back(e.distance);
        ea.push_back(e.angle);
        edm.push_back(e.distance_max);
        eam.push_back(e.angle_max);
        if (s == 0 && (method.key == "heat_m10" || method.key == "heat_m10_idt"))
          panels_for_figure.push_back({&mesh, map, "heat " + std::string(method.key == "heat_m10" ? "" : "iDT ") + "(" + c.key + ")"});
      }
      Row row{c.key, method.key, method.label, h, {}, seconds, failed, failure};
      row.errors.distance = mean(ed);
      row.errors.angle = mean(ea);
      row.errors.distance_max = edm.empty() ? std::nan("") : *std::max_element(edm.begin(), edm.end());
      row.errors.angle_max = eam.empty() ? std::nan("") : *std::max_element(eam.begin(), eam.end());
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
  for (const auto& k : keys) {
    const Row* any = find("regular", k);
    md << "| " << (any ? any->method_label : k) << " |";
    for (const char* mesh : {"regular", "flipped", "anisotropic"}) {
      const Row* r = find(mesh, k);
      md << ' ' << (r ? paper_style(r->errors.distance) : "") << " | "
         << (r ? paper_style(r->errors.angle) : "") << " |";
    }
    md << "\n";
  }
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
  for (const auto& k : keys) {
    const Row* any = find("regular", k);
    md << "| " << (any ? any->method_label : k) << " |";
    for (const char* mesh : {"regular", "flipped", "anisotropic"}) {
      const Row* r = find(mesh, k);
      md << ' ' << (r ? fixed(r->errors.distance / r->h, 3) : "") << " |";
    }
    for (const char* mesh : {"regular", "flipped", "anisotropic"}) {
      const Row* r = find(mesh, k);
      md << ' ' << (r ? paper_style(r->errors.angle_max) : "") << " |";
    }
    md << "\n";
  }
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

// ---------------------------------------------------------------------------
// 3. Fold-overs and distortion on real meshes (Figs. 9, 14)
// ---------------------------------------------------------------------------

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

struct Patch_result {
  bool ok = false, broken = false;
  std::size_t flipped = 0, inverted = 0, triangles = 0;
};

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
                << "), flipped triangles " << percent(double(st.flipped) / double(std::max<std::size_t>(1, st.triangles)), 3)
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
        return v.ok ? double(v.flipped) / double(std::max<std::size_t>(1, v.triangles)) : -1.0;
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
          << general(double(st.patches_with_flips) / double(std::max<std::size_t>(1, st.patches)))
          << ',' << st.triangles << ',' << st.flipped << ','
          << general(double(st.flipped) / double(std::max<std::size_t>(1, st.triangles))) << ','
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

  const std::vector<std::pair<std::string, std::string>> main_methods = {
      {"heat_m10", "heat (m=10)"}, {"heat_m10_idt", "heat (m=10, iDT)"}, {"dem", "DEM"},
      {"dgpc", "DGPC"}, {"exact", "exact"}};
  auto flips_cell = [](const Fold_stats& st) {
    std::string note;
    if (st.failed) note += std::to_string(st.failed) + " failed";
    if (st.broken) note += (note.empty() ? "" : ", ") + std::to_string(st.broken) + " broken";
    return std::to_string(st.patches_with_flips) + "/" + std::to_string(st.patches) +
           (note.empty() ? "" : " (" + note + ")");
  };
  md << "\n## Patches with fold-overs\n\n| mesh |";
  for (const auto& m : main_methods) md << ' ' << m.second << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < main_methods.size(); ++i) md << "---|";
  md << "\n";
  std::size_t total_patches = 0;
  std::map<std::string, std::size_t> total_flips;
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    md << "| " << r.name << " |";
    for (const auto& m : main_methods) {
      md << ' ' << flips_cell(r.stats.at(m.first)) << " |";
      total_flips[m.first] += r.stats.at(m.first).patches_with_flips;
    }
    total_patches += r.sources.size();
    md << "\n";
  }
  md << "| all |";
  for (const auto& m : main_methods) md << ' ' << total_flips[m.first] << "/" << total_patches << " |";
  md << "\n\n*broken*: patches whose distance field collapsed (vertices other than the source at r = 0);\n"
        "all their triangles are degenerate, so they count as patches with fold-overs.\n";
  md << "\n## Patches with strictly inverted triangles\n\n"
        "Only triangles with signed (u, v) area below -1e-9 times their squared (u, v) edge lengths;\n"
        "collapsed (zero-area) triangles are not counted here.\n\n| mesh |";
  for (const auto& m : main_methods) md << ' ' << m.second << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < main_methods.size(); ++i) md << "---|";
  md << "\n";
  std::map<std::string, std::size_t> total_inversions;
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    md << "| " << r.name << " |";
    for (const auto& m : main_methods) {
      const auto& st = r.stats.at(m.first);
      md << ' ' << st.patches_with_inversions << "/" << st.patches << " |";
      total_inversions[m.first] += st.patches_with_inversions;
    }
    md << "\n";
  }
  md << "| all |";
  for (const auto& m : main_methods) md << ' ' << total_inversions[m.first] << "/" << total_patches << " |";
  md << "\n\n## Flipped triangles (fraction of all patch triangles; strictly inverted in brackets)\n\n| mesh |";
  for (const auto& m : main_methods) md << ' ' << m.second << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < main_methods.size(); ++i) md << "---|";
  md << "\n";
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    md << "| " << r.name << " |";
    for (const auto& m : main_methods) {
      const auto& st = r.stats.at(m.first);
      md << ' ' << percent(double(st.flipped) / double(std::max<std::size_t>(1, st.triangles)), 3) << " ("
         << percent(double(st.inverted) / double(std::max<std::size_t>(1, st.triangles)), 3) << ") |";
    }
    md << "\n";
  }
  auto distortion_table = [&](const char* title, bool angle) {
    md << "\n## " << title << " (median / 95th percentile)\n\n| mesh |";
    for (const auto& m : main_methods) md << ' ' << m.second << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < main_methods.size(); ++i) md << "---|";
    md << "\n";
    for (const auto& r : results) {
      if (!r.skipped.empty()) continue;
      md << "| " << r.name << " |";
      for (const auto& m : main_methods) {
        const auto& v = angle ? r.stats.at(m.first).angle_distortion : r.stats.at(m.first).area_distortion;
        md << ' ' << fixed(median(v), 3) << " / " << fixed(percentile(v, 95), 3) << " |";
      }
      md << "\n";
    }
  };
  distortion_table("Angle distortion s1/s2", true);
  distortion_table("Area distortion |log(s1 s2)|", false);
  md << "\n## Where the folds are: nearest corner's r / patch's largest r, per flipped triangle "
        "(median / 10th percentile)\n\n"
        "Near 1: at the rim of the patch (where it reaches a cut locus); small: near the source.\n\n| mesh |";
  for (const auto& m : main_methods) md << ' ' << m.second << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < main_methods.size(); ++i) md << "---|";
  md << "\n";
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    md << "| " << r.name << " |";
    for (const auto& m : main_methods) {
      const auto& v = r.stats.at(m.first).flip_position;
      md << ' ' << (v.empty() ? std::string("-") : fixed(median(v), 2) + " / " + fixed(percentile(v, 10), 2)) << " |";
    }
    md << "\n";
  }
  md << "\n## Accuracy against the exact map (E_d / h and E_a)\n\n| mesh |";
  for (const auto& m : main_methods)
    if (m.first != "exact") md << ' ' << m.second << " |";
  md << "\n|---|---|---|---|---|\n";
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    md << "| " << r.name << " |";
    for (const auto& m : main_methods) {
      if (m.first == "exact") continue;
      const auto& st = r.stats.at(m.first);
      md << ' ' << fixed(mean_finite(st.distance_error), 3) << " / " << paper_style(mean_finite(st.angle_error)) << " |";
    }
    md << "\n";
  }
  md << "\n## Mean query time per patch (s, one core)\n\n| mesh |";
  for (const auto& m : main_methods) md << ' ' << m.second << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < main_methods.size(); ++i) md << "---|";
  md << "\n";
  for (const auto& r : results) {
    if (!r.skipped.empty()) continue;
    md << "| " << r.name << " |";
    for (const auto& m : main_methods)
      md << ' ' << general(r.stats.at(m.first).seconds / double(r.sources.size()), 3) << " |";
    md << "\n";
  }

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
         << percent(double(st.flipped) / double(std::max<std::size_t>(1, st.triangles)), 3) << " | "
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
