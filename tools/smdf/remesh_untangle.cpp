// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: untangling (see remesh_untangle.h).

#include "remesh_untangle.h"
#include "remesh_measures.h"

#include <CGAL/Surface_mesh_direction_fields/remesh_untangling.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace smdf_cli {

Json untangle_inverted(const Mesh& input, Mesh& remesh, bool& ok, std::size_t& left, std::string& message)
{
  const std::size_t grid_inverted = left;
  const std::vector<double> curvature = grid_curvatures(remesh);
  auto held = remesh.add_property_map<vertex_descriptor, bool>("v:smdf_cone_held", false).first;
  std::vector<std::pair<vertex_descriptor, K::Point_3>> cones;
  for(vertex_descriptor v : vertices(remesh)) {
    held[v] = std::abs(curvature[index(v)]) > 1e-9;
    if(held[v]) cones.emplace_back(v, remesh.point(v));
  }
  SMDF::Untangle_status us = SMDF::untangle_remesh(input, remesh, SMDF::parameters::vertex_is_constrained_map(held));
  const bool cones_held = us.success || us.faces_at_held_vertices == 0;
  if(!cones_held) {   // a failed untangling moved nothing: start again from the grid, the cones free
    for(const auto& c : cones) held[c.first] = false;
    const SMDF::Untangle_status free = SMDF::untangle_remesh(input, remesh, SMDF::parameters::vertex_is_constrained_map(held));
    if(free.success || free.inverted_after < us.inverted_after) us = free;
  }
  remesh.remove_property_map(held);
  std::size_t cones_moved = 0;
  for(const auto& c : cones) cones_moved += remesh.point(c.first) != c.second;
  // called for folded quads alone (the grid inverted nothing), a failure is the untangler's
  // stricter normals finding what it cannot unfold: the grid stands, unmoved, and stays valid
  ok = us.success || grid_inverted == 0;
  left = us.success ? 0 : grid_inverted;   // a failed untangling moves nothing
  message = us.message;
  Json u = Json::object();
  u["grid_inverted_faces"] = grid_inverted;     // the tessellation's count (normals of the faces the corners were placed in)
  u["inverted_before"] = us.inverted_before;    // the untangler's (normals of the faces nearest the corners)
  u["inverted_after"] = us.inverted_after;
  u["moved_vertices"] = us.moved_vertices;
  u["cones_moved"] = cones_moved;               // 0 unless holding the cones left faces inverted
  u["folded_before"] = us.folded_before;        // quads folded at a corner against the input's normals ...
  u["folded_after"] = us.folded_after;          // ... and after the moves
  u["max_displacement_over_edge_length"] = us.max_displacement;
  u["straddling_faces"] = us.straddling_faces;
  u["faces_at_held_vertices"] = us.faces_at_held_vertices;
  u["rounds"] = us.rounds;
  return u;
}

} // namespace smdf_cli
