// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_REFERENCE_MAPS_H
#define EXPMAP_BENCHMARK_EVALUATION_REFERENCE_MAPS_H

/// \file Reference_maps.h
/// Reference points (where the exact map is known: vertices, or points inside
/// triangles) and the error measures E_d and E_a of a computed map or
/// distance field at them; point location in the xy projection of a height
/// field, to place reference points given by (x, y).

#include "Analytic_exponential_maps.h"
#include "Analytic_surfaces.h"
#include "Common.h"
#include "Statistics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace expmap_evaluation {

/// Position of each mesh vertex in `map` (-1 outside the patch).
inline std::vector<int> positions(const Map& map, std::size_t n) {
  std::vector<int> pos(n, -1);
  for (std::size_t i = 0; i < map.size(); ++i) pos[map.indices[i]] = static_cast<int>(i);
  return pos;
}

/// A point where the exact map is known: a vertex, or a point inside a
/// triangle given by barycentric weights.
struct Reference_point {
  int vertex = -1;                  // >= 0: a mesh vertex
  std::array<int, 3> corner{};      // otherwise: the triangle's vertices
  std::array<double, 3> weight{};   // and the barycentric weights
  double r = 0, theta = 0;          // exact polar coordinates (theta unrotated)
};

/// The computed map at a reference point: at a vertex its values; inside a
/// triangle the barycentric interpolation of r and of (u, v), the angle
/// being that of the interpolated (u, v) (no wrap-around problem, and
/// correct in the triangles around the source, whose angle is undefined).
inline bool evaluate(const Map& map, const std::vector<int>& pos, const Reference_point& p, double& r,
                     double& theta) {
  if (p.vertex >= 0) {
    const int i = pos[std::size_t(p.vertex)];
    if (i < 0) return false;
    r = map.distance[std::size_t(i)];
    theta = map.angle[std::size_t(i)];
    return true;
  }
  r = 0;
  double u = 0, v = 0;
  for (int k = 0; k < 3; ++k) {
    const int i = pos[std::size_t(p.corner[k])];
    if (i < 0) return false;
    const auto uv = map.uv(std::size_t(i));
    r += p.weight[k] * map.distance[std::size_t(i)];
    u += p.weight[k] * uv[0];
    v += p.weight[k] * uv[1];
  }
  theta = std::atan2(v, u);
  return true;
}

struct Errors {
  double distance = std::nan("");  // mean |r - r_exact|
  double angle = std::nan("");     // mean |theta - theta_exact - rotation|
  double distance_max = std::nan("");
  double angle_max = std::nan("");
  double rotation = 0;             // the constant rotation removed
  std::size_t points = 0, missing = 0;
  // The same over the points with r_exact <= inner_radius (the inner half of
  // the patch in the accuracy study), same rotation.
  double distance_inner = std::nan(""), angle_inner = std::nan("");
  // The largest angle error over the points with r_exact <= near_radius
  // (about two rings of the source), where a heat kernel is least resolved.
  double angle_max_near = std::nan("");
};

/// Errors of `map` at the reference points; the constant rotation between
/// computed and exact angles (their circular mean difference) is removed,
/// as the maps may use different reference directions.
inline Errors map_errors(const Map& map, std::size_t n, const std::vector<Reference_point>& points,
                         double inner_radius = 0, double near_radius = 0) {
  const std::vector<int> pos = positions(map, n);
  std::vector<double> dr, computed, exact, radius;
  Errors e;
  for (const auto& p : points) {
    double r, theta;
    if (!evaluate(map, pos, p, r, theta)) {
      ++e.missing;
      continue;
    }
    dr.push_back(std::abs(r - p.r));
    computed.push_back(theta);
    exact.push_back(p.theta);
    radius.push_back(p.r);
  }
  e.points = dr.size();
  if (dr.empty()) return e;
  const std::vector<double> da = angle_errors_up_to_rotation(computed, exact, e.rotation);
  e.distance = mean(dr);
  e.angle = mean(da);
  e.distance_max = *std::max_element(dr.begin(), dr.end());
  e.angle_max = *std::max_element(da.begin(), da.end());
  std::vector<double> dr_inner, da_inner;
  for (std::size_t i = 0; i < dr.size(); ++i)
    if (radius[i] <= inner_radius) {
      dr_inner.push_back(dr[i]);
      da_inner.push_back(da[i]);
    }
  e.distance_inner = mean(dr_inner);
  e.angle_inner = mean(da_inner);
  for (std::size_t i = 0; i < dr.size(); ++i)
    if (radius[i] <= near_radius && !(da[i] <= e.angle_max_near)) e.angle_max_near = da[i];
  return e;
}

/// Errors of one method over several sources: the mean of the per-source
/// means, the largest of the per-source maxima (NaN without sources), and
/// the total number of points and of points outside the patch.
class Error_average {
 public:
  void add(const Errors& e) {
    m_distance.push_back(e.distance);
    m_angle.push_back(e.angle);
    m_distance_max.push_back(e.distance_max);
    m_angle_max.push_back(e.angle_max);
    m_distance_inner.push_back(e.distance_inner);
    m_angle_inner.push_back(e.angle_inner);
    if (!std::isnan(e.angle_max_near)) m_angle_max_near.push_back(e.angle_max_near);
    m_points += e.points;
    m_missing += e.missing;
  }

  Errors result() const {
    Errors e;
    e.distance = mean(m_distance);
    e.angle = mean(m_angle);
    e.distance_max = largest(m_distance_max);
    e.angle_max = largest(m_angle_max);
    e.points = m_points;
    e.missing = m_missing;
    e.distance_inner = mean(m_distance_inner);
    e.angle_inner = mean(m_angle_inner);
    e.angle_max_near = largest(m_angle_max_near);
    return e;
  }

 private:
  static double largest(const std::vector<double>& v) {
    return v.empty() ? std::nan("") : *std::max_element(v.begin(), v.end());
  }
  std::vector<double> m_distance, m_angle, m_distance_max, m_angle_max, m_distance_inner, m_angle_inner,
      m_angle_max_near;
  std::size_t m_points = 0, m_missing = 0;
};

/// Distance error of a whole-mesh distance field (CGAL's heat method).
inline Errors field_errors(const std::vector<double>& field, const std::vector<Reference_point>& points) {
  std::vector<double> dr;
  for (const auto& p : points) {
    double r = 0;
    if (p.vertex >= 0) {
      r = field[std::size_t(p.vertex)];
    } else {
      for (int k = 0; k < 3; ++k) r += p.weight[k] * field[std::size_t(p.corner[k])];
    }
    dr.push_back(std::abs(r - p.r));
  }
  Errors e;
  e.points = dr.size();
  e.distance = mean(dr);
  e.distance_max = dr.empty() ? std::nan("") : *std::max_element(dr.begin(), dr.end());
  return e;
}

/// The vertices of `soup` within geodesic distance `radius` of `source`
/// (not the source itself) as reference points, with the polar coordinates
/// `exact(point)` (an expmap_analytic::Polar) of an analytic map.
template <class Exact>
std::vector<Reference_point> vertex_references(const expmap_analytic::Triangle_soup& soup,
                                               std::size_t source, double radius, Exact exact) {
  std::vector<Reference_point> ref;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (v == source) continue;
    const auto polar = exact(soup.points[v]);
    if (polar.r > radius) continue;
    Reference_point p;
    p.vertex = int(v);
    p.r = polar.r;
    p.theta = polar.theta_unrotated;
    ref.push_back(p);
  }
  return ref;
}

/// Point location in the xy projection of a height-field (or planar) mesh.
class Xy_locator {
 public:
  explicit Xy_locator(const expmap_analytic::Triangle_soup& soup) : m_soup(soup) {
    double x1 = -1e300, y1 = -1e300;
    m_x0 = m_y0 = 1e300;
    for (const auto& p : soup.points) {
      m_x0 = std::min(m_x0, p[0]);
      m_y0 = std::min(m_y0, p[1]);
      x1 = std::max(x1, p[0]);
      y1 = std::max(y1, p[1]);
    }
    const double cells = std::max(1.0, std::sqrt(static_cast<double>(soup.triangles.size()) / 2));
    m_cell = std::max(x1 - m_x0, y1 - m_y0) / cells * 1.0001;
    m_nx = static_cast<int>((x1 - m_x0) / m_cell) + 1;
    m_ny = static_cast<int>((y1 - m_y0) / m_cell) + 1;
    m_buckets.resize(std::size_t(m_nx) * std::size_t(m_ny));
    for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
      double a = 1e300, b = 1e300, c = -1e300, d = -1e300;
      for (int v : soup.triangles[t]) {
        a = std::min(a, soup.points[std::size_t(v)][0]);
        b = std::min(b, soup.points[std::size_t(v)][1]);
        c = std::max(c, soup.points[std::size_t(v)][0]);
        d = std::max(d, soup.points[std::size_t(v)][1]);
      }
      for (int j = cell_y(b); j <= cell_y(d); ++j)
        for (int i = cell_x(a); i <= cell_x(c); ++i)
          m_buckets[std::size_t(j) * std::size_t(m_nx) + std::size_t(i)].push_back(int(t));
    }
  }

  /// The triangle containing (x, y) and the barycentric weights (the
  /// triangle with the largest smallest weight among those containing it).
  bool locate(double x, double y, Reference_point& p) const {
    const int i = cell_x(x), j = cell_y(y);
    double best = -1e-9;
    bool found = false;
    for (int t : m_buckets[std::size_t(j) * std::size_t(m_nx) + std::size_t(i)]) {
      const auto& tri = m_soup.triangles[std::size_t(t)];
      const auto& a = m_soup.points[std::size_t(tri[0])];
      const auto& b = m_soup.points[std::size_t(tri[1])];
      const auto& c = m_soup.points[std::size_t(tri[2])];
      const double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      const double wb = ((x - a[0]) * (c[1] - a[1]) - (y - a[1]) * (c[0] - a[0])) / det;
      const double wc = ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / det;
      const double wa = 1 - wb - wc;
      const double least = std::min({wa, wb, wc});
      if (least > best) {
        best = least;
        found = true;
        p.vertex = -1;
        p.corner = tri;
        p.weight = {{wa, wb, wc}};
      }
    }
    return found;
  }

 private:
  int cell_x(double x) const {
    return std::clamp(static_cast<int>((x - m_x0) / m_cell), 0, m_nx - 1);
  }
  int cell_y(double y) const {
    return std::clamp(static_cast<int>((y - m_y0) / m_cell), 0, m_ny - 1);
  }
  const expmap_analytic::Triangle_soup& m_soup;
  double m_x0, m_y0, m_cell;
  int m_nx, m_ny;
  std::vector<std::vector<int>> m_buckets;
};

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_REFERENCE_MAPS_H
