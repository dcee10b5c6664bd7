// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: what its JSON says of the remesh besides the library's read-back (valences,
// inverted faces): corner angles and scaled Jacobians, two-sided distances to the input, area.

#ifndef SMDF_CLI_REMESH_MEASURES_H
#define SMDF_CLI_REMESH_MEASURES_H

#include "common.h"

namespace smdf_cli {

// {min_corner_angle_deg, max_corner_angle_deg} (degrees) and, when the remesh has quads,
// {min_scaled_jacobian, mean_scaled_jacobian, nonconvex_quads} of their corners (the last: quads
// with a scaled Jacobian of at most 0 at some corner, against their own area vector).
Json remesh_quality(const Mesh& out);

// The number of quads whose scaled Jacobian is at most 0 at some corner (remesh_quality()).
std::size_t nonconvex_quads(const Mesh& out);

// {remesh_to_input, input_to_remesh, vertices_to_input}: the largest distance from the remesh
// (its vertices, edge midpoints and face-fan centroids) to the input surface, from the input's
// vertices to the remesh (its faces fanned into triangles), and from the remesh's vertices alone
// to the input, over the edge length h.
Json remesh_distances(const Mesh& input, const Mesh& out, double h);

// The remesh's faces whose area vector points against the normal of the input face nearest to
// their centroid (flipped against the input).
std::size_t faces_flipped_at_closest_point(const Mesh& input, const Mesh& out);

// Area of the remesh (its faces fanned into triangles) over that of the input.
double remesh_area_ratio(const Mesh& input, const Mesh& out);

// The area of a mesh under the metric `l` (Heron's formula per face).
double metric_area(const Mesh& mesh, const Edge_length_property& l);

// Per vertex of a quad / triangle / mixed remesh: 2 pi minus the grid's angles of its faces
// (pi/2 per quad, pi/3 per triangle): 0 at regular vertices, the cone's curvature elsewhere.
std::vector<double> grid_curvatures(const Mesh& remesh);

} // namespace smdf_cli

#endif // SMDF_CLI_REMESH_MEASURES_H
