// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: the polyhedra of --polycube: the corners of the presets (box, octahedron, the
// obelisk's directions), a polyhedron read from a file, and --cones checked against or assigned
// to their corners.

#ifndef SMDF_CLI_REMESH_POLYHEDRA_H
#define SMDF_CLI_REMESH_POLYHEDRA_H

#include "common.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace smdf_cli {

// Distinct vertices extreme in the given directions from the centroid (ties: the one nearest
// to the ray, then the first), for the corners of the presets.
std::vector<vertex_descriptor> extreme_vertices(const Mesh& mesh, const std::vector<K::Vector_3>& directions);

// The box's corners: extreme in the directions (+-1, +-1, +-1), corner i at (i & 1, i & 2, i & 4).
std::array<vertex_descriptor, 8> box_corners(const Mesh& mesh);

// The octahedron's corners: extreme along +x, -x, +y, -y, +z, -z.
std::vector<vertex_descriptor> axis_corners(const Mesh& mesh);

// --cones with a polyhedron: its corners must be exactly the given cones, each with the
// curvature 2 pi minus the angles of its faces there (`curvature`, per corner).
void check_polyhedron_cones(const std::string& polycube, const std::vector<vertex_descriptor>& corners,
                            const std::vector<double>& curvature, const std::vector<std::pair<vertex_descriptor, double>>& cones);

// A polyhedron file: one face per line, its corner vertex ids counterclockwise seen from
// outside; the corners are the distinct ids in order of appearance. Throws for a malformed
// file or a polyhedron that is not a closed oriented sphere.
void read_polyhedron(const std::string& file, const Mesh& mesh, std::vector<vertex_descriptor>& corners, std::vector<std::vector<int>>& faces);

// The cones of --cones assigned to the corners of a preset polyhedron: corner i takes the cone
// farthest from the centroid along direction i. All must have curvature K; each must lie on the
// side of its direction (positive dot product), else the assignment is ambiguous.
std::vector<vertex_descriptor> assign_cones(const std::string& preset, const Mesh& mesh, const std::vector<std::pair<vertex_descriptor, double>>& cones,
                                            const std::vector<K::Vector_3>& directions, double K, const char* K_name);

} // namespace smdf_cli

#endif // SMDF_CLI_REMESH_POLYHEDRA_H
