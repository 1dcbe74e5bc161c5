// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_WRITE_SVG_H
#define EXPMAP_IO_WRITE_SVG_H

/// \file write_svg.h
/// A picture of a flattened patch: every patch triangle drawn in the (u, v)
/// plane, so fold-overs and distortion are visible at a glance.

#include <expmap/Fold_overs.h>
#include <expmap/Local_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace expmap {
namespace IO {

/// \ingroup PkgExpmapIO
/// Settings of `write_svg()`.
struct Svg_options {
  /// Named in the caption, e.g. "heat method (time factor 10)".
  std::string method = "exponential map";
  /// Width of the drawing in pixels; the caption adds a strip below it.
  double size = 800;
  /// Number of distance rings the triangles are shaded by (at least 1).
  int rings = 10;
};

namespace internal {

inline std::string svg_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// One decimal of a pixel: about four significant digits on an 800 px
// drawing, finer than any screen shows, and it keeps big patches small.
inline std::string svg_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", x);
  return buffer;
}

// Light fill of distance ring `ring` of `rings`: a pale blue at the source
// turning to pale sand at the rim, alternate rings slightly darker so the
// geodesic circles read as contours.
inline std::string ring_colour(int ring, int rings) {
  const double t = rings > 1 ? static_cast<double>(ring) / (rings - 1) : 0.0;
  const double from[3] = {205, 225, 244}, to[3] = {248, 230, 196};
  const double shade = ring % 2 ? 0.93 : 1.0;
  char buffer[8];
  int c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = static_cast<int>(std::lround(shade * ((1 - t) * from[k] + t * to[k])));
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", c[0], c[1], c[2]);
  return buffer;
}

}  // namespace internal

/// \ingroup PkgExpmapIO
/// Draws the patch of `map` flattened into the (u, v) plane as an SVG
/// picture: each face of `tm` with three patch vertices is a filled
/// triangle with thin dark edges, shaded by distance rings; triangles the
/// map folds over (see `count_flipped_triangles()`) are drawn on top in red.
/// The source is a black dot at the centre, u points right and v up (the
/// SVG y axis is flipped), and a dashed circle marks the largest distance.
/// A caption names the method and gives the vertex, triangle and flipped
/// triangle counts.
///
/// Each triangle is one `<polygon>` with coordinates rounded to 0.1 pixel,
/// about 50 bytes per triangle.
///
/// \tparam TriangleMesh a model of `FaceGraph`.
/// \returns `out`, whose state tells whether writing succeeded.
///
/// \code
/// std::ofstream out("patch.svg");
/// expmap::IO::Svg_options options;
/// options.method = "heat method";
/// expmap::IO::write_svg(out, mesh, map, options);
/// \endcode
template <class TriangleMesh, class VertexDescriptor>
std::ostream& write_svg(std::ostream& out, const TriangleMesh& tm,
                        const Local_map<VertexDescriptor>& map, const Svg_options& options = {}) {
  using internal::svg_number;
  const auto triangles = patch_triangles(tm, map);
  const double max_distance =
      map.size() == 0 ? 0.0 : *std::max_element(map.distance.begin(), map.distance.end());
  const double size = options.size > 0 ? options.size : 800;
  const int rings = std::max(1, options.rings);
  const double margin = 0.04 * size;
  const double centre = 0.5 * size;
  const double radius_px = centre - margin;
  const double scale = max_distance > 0 ? radius_px / max_distance : 1.0;
  const double caption_height = 0.115 * size;
  const double font = 0.02 * size;

  // Triangles by ring of their mean distance; flipped ones last, on top.
  std::vector<std::vector<std::size_t>> ring_members(static_cast<std::size_t>(rings));
  std::vector<std::size_t> flipped;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (is_flipped(map, triangles[t])) {
      flipped.push_back(t);
      continue;
    }
    double mean = 0;
    for (std::size_t c : triangles[t].corner) mean += map.distance[c] / 3;
    const double unit = max_distance > 0 ? mean / max_distance : 0.0;
    const int ring = std::min(rings - 1, static_cast<int>(unit * rings));
    ring_members[static_cast<std::size_t>(ring)].push_back(t);
  }

  // Edges a twentieth of a typical triangle's side: visible on small patches,
  // not a black smear on large ones. Typical: equilateral, with the mean
  // area of the triangles sharing the disk (side^2 = 4 area / sqrt(3)).
  const double mean_area = triangles.empty() ? size * size
                                             : std::acos(-1.0) * radius_px * radius_px /
                                                   static_cast<double>(triangles.size());
  const double typical_side = std::sqrt(4 * mean_area / std::sqrt(3.0));
  const double stroke = std::clamp(0.05 * typical_side, 0.05, 0.8);

  auto polygon = [&](std::size_t t) {
    out << "<polygon points=\"";
    for (int k = 0; k < 3; ++k) {
      const auto uv = map.uv(triangles[t].corner[k]);
      out << (k ? " " : "") << svg_number(centre + scale * uv[0]) << ','
          << svg_number(centre - scale * uv[1]);
    }
    out << "\"/>\n";
  };

  const std::string width = svg_number(size), height = svg_number(size + caption_height);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#fcfcfa\"/>\n";
  if (max_distance > 0)
    out << "<circle cx=\"" << svg_number(centre) << "\" cy=\"" << svg_number(centre) << "\" r=\""
        << svg_number(radius_px) << "\" fill=\"none\" stroke=\"#b0b0b0\" stroke-width=\"1\" "
        << "stroke-dasharray=\"6 4\"/>\n";
  char stroke_text[32];
  std::snprintf(stroke_text, sizeof stroke_text, "%.2g", stroke);
  out << "<g stroke=\"#3a3a3a\" stroke-width=\"" << stroke_text
      << "\" stroke-linejoin=\"round\">\n";
  for (int r = 0; r < rings; ++r) {
    if (ring_members[static_cast<std::size_t>(r)].empty()) continue;
    out << "<g fill=\"" << internal::ring_colour(r, rings) << "\">\n";
    for (std::size_t t : ring_members[static_cast<std::size_t>(r)]) polygon(t);
    out << "</g>\n";
  }
  if (!flipped.empty()) {
    out << "<g fill=\"#e03c2c\" stroke=\"#8a1208\">\n";
    for (std::size_t t : flipped) polygon(t);
    out << "</g>\n";
  }
  out << "</g>\n";

  // Axes from the source, so orientation is never ambiguous; a white halo
  // keeps them readable over dense edges.
  const double axis = 0.08 * size;
  const std::string c = svg_number(centre);
  const std::string axes = "M" + c + ',' + c + "H" + svg_number(centre + axis) + "M" + c + ',' + c +
                           "V" + svg_number(centre - axis);
  out << "<g fill=\"none\" stroke-linecap=\"round\">\n"
      << "<path d=\"" << axes << "\" stroke=\"#fff\" stroke-width=\"4\"/>\n"
      << "<path d=\"" << axes << "\" stroke=\"#1f4e79\" stroke-width=\"1.6\"/>\n</g>\n"
      << "<g fill=\"#1f4e79\" font-size=\"" << svg_number(font) << "\" font-weight=\"bold\" "
      << "stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">\n"
      << "<text x=\"" << svg_number(centre + axis + 0.3 * font) << "\" y=\""
      << svg_number(centre + 0.35 * font) << "\">u</text>\n"
      << "<text x=\"" << svg_number(centre - 0.3 * font) << "\" y=\""
      << svg_number(centre - axis - 0.3 * font) << "\">v</text>\n</g>\n"
      << "<circle cx=\"" << c << "\" cy=\"" << c << "\" r=\"" << svg_number(0.006 * size + 1)
      << "\" fill=\"#111\" stroke=\"#fff\" stroke-width=\"1.5\"/>\n";

  // Caption: what was computed, then what to look at.
  char radius_text[32];
  std::snprintf(radius_text, sizeof radius_text, "%.4g", max_distance);
  auto caption_line = [&](int line, double font_size, const char* colour) -> std::ostream& {
    return out << "<text x=\"" << svg_number(margin) << "\" y=\""
               << svg_number(size + (0.01 + 0.032 * line) * size) << "\" font-size=\""
               << svg_number(font_size) << "\" fill=\"" << colour << "\">";
  };
  caption_line(1, 1.1 * font, "#222") << internal::svg_escape(options.method) << "</text>\n";
  caption_line(2, font, "#222") << map.size() << " vertices \xc2\xb7 " << triangles.size()
                                << " triangles \xc2\xb7 <tspan font-weight=\"bold\" fill=\""
                                << (flipped.empty() ? "#222" : "#c0281a") << "\">" << flipped.size()
                                << " flipped" << (flipped.empty() ? "" : " (red)")
                                << "</tspan></text>\n";
  caption_line(3, 0.9 * font, "#555")
      << "source vertex " << (map.size() ? std::to_string(map.indices[0]) : std::string("-"))
      << " (dot) \xc2\xb7 dashed circle: max r = " << radius_text << " \xc2\xb7 shading: " << rings
      << " distance rings</text>\n"
      << "</svg>\n";
  return out;
}

}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_WRITE_SVG_H
