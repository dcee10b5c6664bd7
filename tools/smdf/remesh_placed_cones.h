// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh --place-cones: the metric of an automatic quad remesh of a closed mesh of any
// genus (placed cones, their flat cone metric, the trivial connection's cross field on it, an
// integer-grid map), and the JSON of a conforming Delaunay refinement.

#ifndef SMDF_CLI_REMESH_PLACED_CONES_H
#define SMDF_CLI_REMESH_PLACED_CONES_H

#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace smdf_cli {

// Whether the input's own metric may already be one to tessellate with quads: every vertex's
// curvature (angle defect, or boundary turning) a multiple of pi/2 (a cube, an L-shaped plate).
// Otherwise `remesh` places cones for quads when no metric is given.
bool embedding_fits_quads(const Mesh& mesh);

// The JSON of a conforming Delaunay refinement made because the input's edges could not carry
// a metric (`message`: why not).
Json refinement_json(const std::string& message, const SMDF::Delaunay_refinement_status& rs);

// A flat cone metric that needed intrinsic edge flips: the triangulation carrying it (with its
// common subdivision with `of`), a mesh copy of it (copy_intrinsic_triangulation()) that the map
// and the tessellation are made on, and the triangulation of the surface it was computed on (the
// input or its refinement), onto which place_tessellation_on_input() brings the remesh back.
struct Intrinsic_surface
{
  SMDF::Intrinsic_triangulation triangulation;
  Mesh mesh;
  Mesh* of = nullptr;   // null: no intrinsic triangulation is used
};

// The flat cone metric with curvature `curvatures` (vertex, K) on `base` with intrinsic flips.
// Converged with flips: `intrinsic` receives the triangulation and its copy, and `surface` and
// `lengths` point to the copy and its lengths; converged without: to `base` and its lengths.
// Returns the status (not converged: nothing set). Records in `metric` intrinsic_edge_flips,
// intrinsic_triangulation (whether the copy carries it) and without_flips_message (why the
// metric without flips failed: `without_flips`).
SMDF::Cone_metric_status intrinsic_cone_metric(const std::string& file, Mesh& base, const std::vector<std::pair<vertex_descriptor, double>>& curvatures,
                                               const std::string& without_flips, Intrinsic_surface& intrinsic, Mesh*& surface,
                                               Edge_length_property& lengths, Json& metric);

// Places the cones (place_remeshing_cones()), computes their flat cone metric without flips on
// `mesh` or, where its edges cannot carry it, on its conforming Delaunay refinement `refined`
// (then `surface` points to it) or, where neither can, with intrinsic flips (then `surface`
// points to `intrinsic.mesh`), the trivial connection's cross field with those singularities,
// and the integer-grid map for about `requested_faces` quads (or grid edges of `requested_h`
// under the metric). Returns the map's edge lengths (grid units) on `*surface`; adds
// placed_cones, placement and integer_grid_map to `out` and the metric's fields to `metric`.
// Cones are kept `cone_spacing` grid edges apart where the placement can (measured on the input);
// a negative `cone_spacing` tries 4, 2, 0 and 6 in turn; then, if `tighten_bound`, the bound
// halved and quartered at spacings 4, 2 and 6 (or `cone_spacing`). `finish` tessellates the map and reads
// the remesh back (it throws Failed_result when the remesh fails): an attempt whose map or
// remesh fails is followed by the next spacing, each recorded in placement_attempts. A metric
// that needed intrinsic flips is used on its intrinsic triangulation, unless `keep_input_faces`
// (--uv-out: the map must lie on the input's faces or its refinement's) asks for the conforming
// Delaunay refinement first. Throws Failed_result (exit 3) when the last attempt fails.
Edge_length_property placed_cones_metric(const std::string& file, Mesh& mesh, Mesh& refined, Intrinsic_surface& intrinsic, Mesh*& surface, double requested_h,
                                         long requested_faces, double distortion_bound, long max_cones, double cone_spacing, Json& out, Json& metric,
                                         const std::function<void(const char*)>& stage,
                                         const std::function<void(Edge_length_property)>& finish, bool keep_input_faces, bool tighten_bound);

// The integer-grid map made by placed_cones_metric() on `on` (the input, or its refinement) as
// OBJ text: the vertices, one `vt` per face corner (grid units), faces `v/vt`.
std::string uv_obj_text(const Mesh& on);

} // namespace smdf_cli

#endif // SMDF_CLI_REMESH_PLACED_CONES_H
