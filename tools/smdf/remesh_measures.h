// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: what its JSON says of the remesh besides the library's read-back (valences,
// inverted faces): corner angles and scaled Jacobians, two-sided distances to the input, area.

#ifndef SMDF_CLI_REMESH_MEASURES_H
#define SMDF_CLI_REMESH_MEASURES_H

#include "common.h"

#include <memory>

namespace smdf_cli {

// {min_corner_angle_deg, max_corner_angle_deg} (degrees) and, when the remesh has quads,
// {min_scaled_jacobian, mean_scaled_jacobian, nonconvex_quads} of their corners (the last: quads
// with a scaled Jacobian of at most 0 at some corner, against their own area vector).
Json remesh_quality(const Mesh& out);

// The number of quads whose scaled Jacobian is at most 0 at some corner (remesh_quality()).
std::size_t nonconvex_quads(const Mesh& out);

// The input's faces in an AABB tree, built on the first query and shared by the checks below (at
// 1M input faces a build took about a second, and a remesh is checked two or three times).
class Input_faces_tree
{
public:
  explicit Input_faces_tree(const Mesh& input);
  ~Input_faces_tree();
  Input_faces_tree(const Input_faces_tree&) = delete;
  Input_faces_tree& operator=(const Input_faces_tree&) = delete;
  const Mesh& mesh() const { return input_; }
  // the input face nearest to p
  face_descriptor closest_face(const K::Point_3& p) const;
  // the squared distance from p to the input
  double squared_distance(const K::Point_3& p) const;

private:
  const Mesh& input_;
  struct Tree;
  mutable std::unique_ptr<Tree> tree_;
  const Tree& tree() const;
};

// {remesh_to_input, input_to_remesh, vertices_to_input}: the largest distance from the remesh
// (its vertices, edge midpoints and face-fan centroids) to the input surface, from the input's
// vertices to the remesh (its faces fanned into triangles), and from the remesh's vertices alone
// to the input, over the edge length h.
Json remesh_distances(const Input_faces_tree& input, const Mesh& out, double h);

// The remesh against the input's normal n at the input point nearest each face's centroid (the
// normal of the input face found there), as quality measures of remeshes take it.
struct On_input_measures
{
  std::size_t flipped_faces = 0;   // area vector against n
  std::size_t folded_faces = 0;    // some corner's scaled Jacobian along n at most 0
  // per face its worst corner's scaled Jacobian along n, (a x b) . n / (|a| |b| |n|) with a and
  // b the corner's edges: the least over the faces and the mean
  double min_scaled_jacobian = 0, mean_scaled_jacobian = 0;
};
On_input_measures measures_on_input(const Input_faces_tree& input, const Mesh& out);

// Area of the remesh (its faces fanned into triangles) over that of the input.
double remesh_area_ratio(const Mesh& input, const Mesh& out);

// The area of a mesh under the metric `l` (Heron's formula per face).
double metric_area(const Mesh& mesh, const Edge_length_property& l);

// Per vertex of a quad / triangle / mixed remesh: 2 pi minus the grid's angles of its faces
// (pi/2 per quad, pi/3 per triangle): 0 at regular vertices, the cone's curvature elsewhere.
std::vector<double> grid_curvatures(const Mesh& remesh);

} // namespace smdf_cli

#endif // SMDF_CLI_REMESH_MEASURES_H
