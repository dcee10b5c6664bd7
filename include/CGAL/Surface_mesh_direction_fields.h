// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Umbrella header: includes every public header of the package.

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_H

#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/Euclidean_edge_length_map.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_H
