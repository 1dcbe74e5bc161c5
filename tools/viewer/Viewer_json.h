// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_VIEWER_JSON_H
#define EXPMAP_TOOLS_VIEWER_VIEWER_JSON_H

/// \file Viewer_json.h
/// The JSON of the viewer's API, written by hand: a few flat objects of
/// number arrays, where a JSON library would add a dependency and time.
/// Numbers are written in the shortest form that reads back to the same
/// double, so a script gets the library's values exactly.

#include "Map_service.h"
#include "Method_cache.h"
#include "Viewer_methods.h"

#include <expmap/Errors.h>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace expmap_view {

/// Appends JSON values to a string.
class Json {
 public:
  Json& raw(const char* text) {
    m_text += text;
    return *this;
  }
  /// \throws expmap::Computation_error for NaN or infinity, naming the
  ///         key written last: JSON has no such numbers, and writing null
  ///         instead would pass a broken map off as one with gaps.
  Json& number(double x) {
    if (!std::isfinite(x))
      throw expmap::Computation_error("a value of \"" + m_key +
                                      "\" is not finite (NaN or infinity): the computation failed");
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
    m_text.append(buffer, end);
    return *this;
  }
  Json& integer(std::size_t n) {
    char buffer[24];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, n).ptr;
    m_text.append(buffer, end);
    return *this;
  }
  Json& boolean(bool b) { return raw(b ? "true" : "false"); }
  /// `s` as a JSON string; a byte that is no part of a valid UTF-8
  /// sequence becomes '?', so that the response stays valid JSON whatever
  /// a message holds.
  Json& string(const std::string& s) {
    m_text += '"';
    for (std::size_t i = 0; i < s.size();) {
      const char c = s[i];
      const auto u = static_cast<unsigned char>(c);
      if (u >= 0x80) {
        const std::size_t n = utf8_length(s, i);
        m_text.append(n ? s.substr(i, n) : std::string("?"));
        i += n ? n : 1;
        continue;
      }
      if (c == '"' || c == '\\') {
        m_text += '\\';
        m_text += c;
      } else if (u < 0x20) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", u);
        m_text += escaped;
      } else {
        m_text += c;
      }
      ++i;
    }
    m_text += '"';
    return *this;
  }
  /// `"name":`, preceded by a comma unless it opens the object.
  Json& key(const char* name) {
    if (m_text.back() != '{') m_text += ',';
    m_key = name;
    return string(name).raw(":");
  }
  template <class Range, class Write>
  Json& array(const Range& range, Write write) {
    m_text += '[';
    bool first = true;
    for (const auto& x : range) {
      if (!first) m_text += ',';
      first = false;
      write(*this, x);
    }
    m_text += ']';
    return *this;
  }
  const std::string& text() const { return m_text; }

 private:
  // The length of the valid UTF-8 sequence starting at s[i] (a byte of at
  // least 0x80), or 0 if none starts there: no overlong forms, no
  // surrogates, nothing beyond U+10FFFF (RFC 3629).
  static std::size_t utf8_length(const std::string& s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char lead = byte(i);
    std::size_t n = 0;
    unsigned char low = 0x80, high = 0xbf;  // the range of the second byte
    if (lead >= 0xc2 && lead <= 0xdf) n = 2;
    else if (lead >= 0xe0 && lead <= 0xef) {
      n = 3;
      if (lead == 0xe0) low = 0xa0;
      if (lead == 0xed) high = 0x9f;
    } else if (lead >= 0xf0 && lead <= 0xf4) {
      n = 4;
      if (lead == 0xf0) low = 0x90;
      if (lead == 0xf4) high = 0x8f;
    } else {
      return 0;
    }
    if (i + n > s.size() || byte(i + 1) < low || byte(i + 1) > high) return 0;
    for (std::size_t k = 2; k < n; ++k)
      if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
    return n;
  }

  std::string m_text;
  std::string m_key;  // the key written last, for number()'s message
};

/// `{"error": message}`.
inline std::string error_json(const std::string& message) {
  Json j;
  j.raw("{").key("error").string(message).raw("}");
  return j.text();
}

/// `{"error": message, "limit": {...}}` for a request too large: the
/// method, the `quantity` limited ("patch_vertices" or "region_faces"), its
/// `maximum` and what was `asked` (counted up to `maximum` + 1).
inline std::string too_large_json(const Too_large& e) {
  Json j;
  j.raw("{").key("error").string(e.what());
  j.key("limit").raw("{").key("method").string(e.method).key("quantity").string(e.quantity);
  j.key("maximum").integer(e.maximum).key("asked").integer(e.asked).raw("}}");
  return j.text();
}

/// The mesh for drawing: vertex coordinates x0,y0,z0,x1,... and the
/// corners of each face i0,j0,k0,i1,..., flat.
inline std::string mesh_json(const Mesh& mesh) {
  std::vector<double> xyz;
  xyz.reserve(3 * mesh.number_of_vertices());
  for (const auto v : mesh.vertices())
    for (int d = 0; d < 3; ++d) xyz.push_back(CGAL::to_double(mesh.point(v)[d]));
  std::vector<std::size_t> corners;
  corners.reserve(3 * mesh.number_of_faces());
  for (const auto f : mesh.faces())
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corners.push_back(static_cast<std::size_t>(v));
  Json j;
  j.raw("{").key("vertex_count").integer(mesh.number_of_vertices());
  j.key("face_count").integer(mesh.number_of_faces());
  j.key("vertices").array(xyz, [](Json& o, double x) { o.number(x); });
  j.key("faces").array(corners, [](Json& o, std::size_t i) { o.integer(i); });
  j.raw("}");
  return j.text();
}

/// A map: the patch vertices (mesh indices, nearest first) with r, theta,
/// u, v; the flipped faces, the fold-free radius, the query time, and the
/// source as located.
/// \throws expmap::Computation_error if a value of the map is not finite.
inline std::string map_json(const Map_response& r) {
  const Map& map = r.map;
  std::vector<double> u(map.size()), v(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) {
    const auto uv = map.uv(i);
    u[i] = uv[0];
    v[i] = uv[1];
  }
  const auto num = [](Json& o, double x) { o.number(x); };
  const auto index = [](Json& o, std::size_t i) { o.integer(i); };
  Json j;
  j.raw("{").key("method").string(r.method);
  if (r.time_factor > 0) j.key("m").number(r.time_factor);
  j.key("source").raw("{").key("face").integer(static_cast<std::size_t>(r.source.face));
  j.key("barycentric").array(r.source.barycentric, num);
  j.key("position").array(r.position, num);
  j.key("nearest_vertex").integer(static_cast<std::size_t>(map.source)).raw("}");
  j.key("vertices").array(map.indices, index);
  j.key("r").array(map.distance, num);
  j.key("theta").array(map.angle, num);
  j.key("u").array(u, num);
  j.key("v").array(v, num);
  j.key("triangles").integer(r.triangles);
  j.key("flipped").integer(r.flipped_faces.size());
  j.key("flipped_faces").array(r.flipped_faces, index);
  j.key("fold_free_radius").number(map.fold_free_radius.value_or(0.0));
  j.key("query_ms").number(r.query_ms);
  j.raw("}");
  return j.text();
}

/// The methods (which take heat's time factor, the largest patch each
/// maps, for exact the largest submesh and the memory its map may take),
/// the mesh's size, the request limits, and every precomputation kept
/// with its state, its step while running and its queries once ready: the
/// page polls it to show progress.
inline std::string status_json(const Map_service& service) {
  Json j;
  j.raw("{").key("methods").array(viewer_methods(), [](Json& o, const Method_info& m) {
    o.raw("{").key("name").string(m.name).key("label").string(m.label);
    o.key("takes_time_factor").boolean(m.takes_time_factor);
    if (m.takes_time_factor) o.key("default_m").number(default_time_factor());
    o.key("max_patch_vertices").integer(m.max_patch_vertices);
    if (m.max_region_faces) {
      o.key("max_region_faces").integer(m.max_region_faces);
      o.key("max_map_mib").number(
          std::round(expmap_cli::exact_query_mib(static_cast<double>(m.max_region_faces))));
    }
    o.raw("}");
  });
  j.key("mesh").raw("{").key("vertex_count").integer(service.mesh().number_of_vertices());
  j.key("face_count").integer(service.mesh().number_of_faces()).raw("}");
  const Request_limits& l = service.limits();
  const Cache_limits& c = service.cache().limits();
  j.key("limits").raw("{").key("max_fraction").number(l.max_fraction);
  j.key("max_radius").number(l.max_radius).key("min_m").number(l.min_time_factor);
  j.key("max_m").number(l.max_time_factor);
  j.key("queries_per_method").integer(c.queries_per_method);
  j.key("waiting_per_method").integer(c.waiting_per_method);
  j.key("max_wait_seconds").number(c.max_wait_seconds).raw("}");
  j.key("precomputations").array(service.cache().status(), [](Json& o, const Precomputation_status& s) {
    using State = Precomputation_status::State;
    o.raw("{").key("method").string(s.method);
    if (s.time_factor > 0) o.key("m").number(s.time_factor);
    o.key("state").string(s.state == State::running ? "running" : s.state == State::ready ? "ready" : "failed");
    o.key("seconds").number(s.seconds);
    if (s.state == State::running) o.key("step").string(s.step).key("fraction").number(s.fraction);
    if (s.state == State::ready)
      o.key("queries_running").integer(s.queries_running).key("waiting").integer(s.waiting);
    if (s.state == State::failed) o.key("error").string(s.error);
    o.raw("}");
  });
  j.raw("}");
  return j.text();
}

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_VIEWER_JSON_H
