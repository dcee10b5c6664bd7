// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Umbrella header: includes every public header of the core (no I/O). Mesh reading and SVG
// pictures are in <CGAL/Surface_mesh_direction_fields/IO.h>; define
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_WITH_IO before including this header to get them too.

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_H

#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/Euclidean_edge_length_map.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Eigen_sparse_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/homotopy_basis.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy_group.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>
#include <CGAL/Surface_mesh_direction_fields/field_editing.h>
#include <CGAL/Surface_mesh_direction_fields/rotation_compensation.h>
#include <CGAL/Surface_mesh_direction_fields/boundary_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/flat_development.h>
#include <CGAL/Surface_mesh_direction_fields/grid_tessellation.h>
#include <CGAL/Surface_mesh_direction_fields/polycube_metric.h>
#include <CGAL/Surface_mesh_direction_fields/polyhedron_remeshing.h>
#include <CGAL/Surface_mesh_direction_fields/remeshing_cones.h>
#include <CGAL/Surface_mesh_direction_fields/integer_grid_map.h>
#include <CGAL/Surface_mesh_direction_fields/seamless_metric.h>
#include <CGAL/Surface_mesh_direction_fields/huge_pages.h>
#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/compute_trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/streamlines.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/field_transfer.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/refinement_field_transfer.h>
#include <CGAL/Surface_mesh_direction_fields/curvature_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/vertex_field_from_faces.h>

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_WITH_IO
#include <CGAL/Surface_mesh_direction_fields/IO.h>
#endif

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_H
