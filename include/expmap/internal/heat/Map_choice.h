// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_MAP_CHOICE_H
#define EXPMAP_INTERNAL_HEAT_MAP_CHOICE_H

// Step 8 (manual, section 2): where the heat's reading of the angles is
// blind, the geodesic front's map. The heat reads every vertex's direction
// at the source, by symmetry; where the heat from far-apart vertices
// reaches the source from nearly one direction (the tip of a thin part) or
// around an obstacle (a hole, a boundary, the rim of a thin sheet), that
// reading cannot tell them apart at any diffusion time, and the map folds.
// The front carries the angles outward with its own, accurate distances
// and has the information. Where the heat's map is sound it is kept: there
// it is smoother than the front's (fewer folds at eyes and on irregular
// meshes). Where it folds, away from boundaries, the front is held to it
// inside its fold-free disk and carries its angles on beyond; next to a
// boundary the front's own map is the candidate. The candidate is returned
// if it folds over fewer triangles (next to a boundary: not clearly more).

#include <expmap/Errors.h>
#include <expmap/Fold_free_radius.h>
#include <expmap/Heat_options.h>
#include <expmap/Local_map.h>
#include <expmap/Patch.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Query_validation.h>
#include <expmap/internal/front/Geodesic_front.h>
#include <expmap/internal/heat/Query_workspace.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

// The front is held to the heat's map fully inside this share of the
// heat's fold-free disk, and blended out by the disk's edge (tip study: 0.5
// and 0.8 within 3% of each other in flipped triangles).
constexpr double held_core = 0.5;

// The workspace's front and its anchor, made by the first query that needs
// them: O(n) memory that most workspaces never hold.
inline void make_front(const Mesh_arrays& mesh, Workspace& ws) {
  if (ws.front) return;
  ws.front = std::make_unique<Geodesic_front>(mesh.number_of_vertices());
  ws.anchor.position.resize(mesh.number_of_vertices());
}

// Holds the front to the heat's map `heat` inside its fold-free disk of
// radius `fold_free_radius`: fully up to `inner` of it, blended out by its
// edge. `reference_angle`: the front's native angle of the frame's axis.
template <class VertexDescriptor>
void hold_to_heat(const Context& c, const Local_map<VertexDescriptor>& heat,
                  double fold_free_radius, double reference_angle, Front_anchor& anchor) {
  anchor.position.next_query();
  anchor.weight.clear();
  anchor.angle.clear();
  anchor.distance.clear();
  const double outer = fold_free_radius;
  const double inner = held_core * outer;
  for (std::size_t i = 0; i < heat.size(); ++i) {
    const double r = heat.distance[i];
    if (!(r > 0) || !(r < outer)) continue;
    double w = 1;
    if (r > inner) {
      const double x = (outer - r) / (outer - inner);
      w = x * x * (3 - 2 * x);
    }
    anchor.position.mark(c.mesh.from_original(heat.indices[i]), static_cast<int>(anchor.weight.size()));
    anchor.weight.push_back(w);
    anchor.angle.push_back(heat.angle[i] + reference_angle);
    anchor.distance.push_back(r);
  }
}

// The geodesic front's map of the query's patch around c.source, from
// `start`, in the user's vertex indices; held to `anchor` if given.
template <class VertexDescriptor>
Local_map<VertexDescriptor> geodesic_front_map(const Context& c, const Checked_query& q,
                                               const Patch& patch, const Front_start& start,
                                               const std::vector<VertexDescriptor>& descriptors,
                                               Workspace& ws, const Front_anchor* anchor = nullptr) {
  const Mesh_arrays& mesh = c.mesh;
  make_front(mesh, ws);
  ws.front_entries.clear();
  const bool at_vertex = c.source.is_vertex();
  const double radius = q.kind == Patch::Kind::geodesic_radius ? patch.radius() : 0.0;
  ws.front->propagate(mesh, at_vertex ? c.source.lead : -1, start, q, radius, ws.front_entries,
                      anchor);
  for (Polar_entry& e : ws.front_entries) e.vertex = static_cast<int>(mesh.to_original(e.vertex));
  return sorted_local_map(static_cast<int>(mesh.to_original(c.source.lead)), ws.front_entries,
                          descriptors, q.frame, at_vertex);
}

// Next to a boundary the front's map is taken if it folds over at most this
// many times the heat's triangles plus this share of the patch's.
constexpr double boundary_fold_ratio = 2;
constexpr double boundary_fold_share = 0.02;

// Whether the front's map, with fold-free disk `front`, is sounder than the
// heat's, with `heat`: it folds fewer triangles over. Next to a boundary
// the heat's angles are biased (its mirror image is exact only for a
// straight boundary) where the front's are not, and the front's map is
// taken unless it folds over clearly more.
inline bool front_is_sounder(const Fold_free_disk& front, const Fold_free_disk& heat,
                             bool boundary) {
  if (!boundary) return front.flipped < heat.flipped;
  return static_cast<double>(front.flipped) <=
         boundary_fold_ratio * static_cast<double>(heat.flipped) +
             boundary_fold_share * static_cast<double>(heat.triangles);
}

// A boundary farther than this many sqrt(t) from the patch bends the heat's
// reading there by less than exp(-4), the weight of its mirror image.
constexpr double boundary_reach = 2;

// Whether v lies on a boundary loop of the mesh, however short: its fan of
// faces is open (it has more neighbours than faces).
inline bool on_boundary(const Mesh_arrays& mesh, int v) {
  return mesh.neighbor_start[v + 1] - mesh.neighbor_start[v] >
         mesh.vertex_face_start[v + 1] - mesh.vertex_face_start[v];
}

// Whether a boundary is near enough to the patch of `map` to bend the
// heat's reading: a vertex of the query's region on a boundary loop, within
// `boundary_reach` sqrt(t) of the patch's largest distance.
template <class VertexDescriptor>
bool boundary_near(const Context& c, const Local_map<VertexDescriptor>& map,
                   const Workspace& ws) {
  const double reach =
      (map.size() ? map.distance.back() : 0.0) + boundary_reach * std::sqrt(c.factors.time_step);
  for (std::size_t i = 0; i < ws.region.size(); ++i)
    if (ws.potential[i] <= reach && on_boundary(c.mesh, ws.region[i])) return true;
  return false;
}

// Whether the heat's map turns a patch triangle over (or collapses one),
// from the (u, v) step 7 left in ws.patch_uv: the faces `fold_free_disk()`
// reads, stopping at the first that folds.
inline bool folds(const Mesh_arrays& mesh, Workspace& ws) {
  const std::vector<Workspace::Patch_uv>& patch = ws.patch_uv;
  const auto uv_of = [&](std::size_t k) { return patch[k].uv; };
  return visit_patch_faces(
      mesh.owned_faces, patch.size(), [&](std::size_t k) { return patch[k].vertex; }, ws.map_position,
      [&](const std::array<std::size_t, 3>& corner) { return !(signed_uv_area2(uv_of, corner) > 0); });
}

// The map a heat query returns: `heat_map` (empty if the heat failed), or
// the geodesic front's where the query's fallback asks for it and it is
// sounder (`Heat_fallback::geodesic_front`), with the fold-free disk the
// query asks for. `make_start()` gives the front's start around the source.
template <class VertexDescriptor, class MakeStart>
Local_map<VertexDescriptor> sounder_map(const Context& c, const Checked_query& q,
                                        const Patch& patch,
                                        std::optional<Local_map<VertexDescriptor>> heat_map,
                                        MakeStart make_start,
                                        const std::vector<VertexDescriptor>& descriptors,
                                        Workspace& ws, Solve_statistics& stats) {
  const bool asks_disk = c.query.trim_folds || c.query.find_fold_free_radius;
  std::optional<Fold_free_disk> heat_disk;
  if (c.query.fallback == Heat_fallback::geodesic_front) {
    const bool boundary = heat_map && boundary_near(c, *heat_map, ws);
    if (!heat_map || boundary || folds(c.mesh, ws)) {
      ++stats.front_checks;
      if (heat_map) heat_disk = fold_free_disk(c.mesh, *heat_map, ws.map_position);
      const Front_start start = make_start();
      // Away from boundaries the heat's map is kept where it is one-to-one
      // and the front carries its angles on beyond; next to one, the heat's
      // angles are biased everywhere and the front's own are taken.
      const bool held = heat_map && !boundary;
      if (held) {
        make_front(c.mesh, ws);
        hold_to_heat(c, *heat_map, heat_disk->radius, start.ring.reference_angle, ws.anchor);
      }
      Local_map<VertexDescriptor> front =
          geodesic_front_map(c, q, patch, start, descriptors, ws, held ? &ws.anchor : nullptr);
      const Fold_free_disk front_disk = fold_free_disk(c.mesh, front, ws.map_position);
      if (!heat_map || front_is_sounder(front_disk, *heat_disk, boundary)) {
        ++stats.front_maps;
        apply_fold_options(front, front_disk, c.query);
        return front;
      }
    }
  }
  if (asks_disk) {
    if (!heat_disk) heat_disk = fold_free_disk(c.mesh, *heat_map, ws.map_position);
    apply_fold_options(*heat_map, *heat_disk, c.query);
  }
  return std::move(*heat_map);
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_MAP_CHOICE_H
