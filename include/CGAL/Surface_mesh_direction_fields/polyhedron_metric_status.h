// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_METRIC_STATUS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_METRIC_STATUS_H

// What box_polycube_metric(), polyhedron_metric() and polyhedron_remesh() report about the
// metric they build, and how they map the segments onto the polyhedron's faces.

#include <array>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of box_polycube_metric().
struct Polycube_metric_status
{
  bool success = false;
  std::string message;                         ///< empty on success
  std::array<double, 3> dimensions{{0, 0, 0}}; ///< box_polycube_metric(): the box's side lengths (multiples of the edge length)
  std::size_t path_edges = 0;                  ///< mesh edges on the twelve paths between the corners
  /// the largest ratio, over the polyhedron's edges, between the path's length on the surface
  /// and the edge it is mapped to (1: no stretch along the cut)
  double max_path_stretch = 0;
  /// steps of the as-rigid-as-possible relaxation taken (0: the Tutte embedding as it is)
  int relaxation_steps = 0;
  /// vertices near the paths relaxed a second time across the polyhedron's edges, the two faces
  /// beside each edge unfolded into one plane (so that the zigzag of an edge path does not shear
  /// its triangles); 0 without relaxation and for polyhedron_remesh(), whose grid follows the paths
  std::size_t seam_relaxed_vertices = 0;
  /// with `RICCI_FLOW_SEGMENTS`: the largest difference between the places along P's edge that
  /// the two segments beside it give a path vertex, as a fraction of the edge (how far apart Lai
  /// et al.'s assembly of the segments leaves the two sides; the charts take their mean); 0 otherwise
  double max_side_parameter_gap = 0;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// How box_polycube_metric(), polyhedron_metric() and polyhedron_remesh() map the pieces of the
/// surface between P's edges (Lai et al.'s segments) onto P's faces (named parameter
/// `segment_flattening`).
enum Segment_flattening
{
  /// a stretch-minimising Tutte embedding, its sides by arc length, relaxed as rigidly as
  /// possible with the paths sliding along P's edges (the default: close to the input's own
  /// triangles, so grid cells of about the same size everywhere)
  RELAXED_SEGMENTS,
  /// Lai et al.'s step 3: each segment flattened by Ricci flow to a polygon with P's face's
  /// angles (boundary curvature \f$\pi\f$ minus the angle at P's corners, 0 elsewhere) and
  /// straight sides, the vertices of each side placed where that metric puts them (the mean of
  /// the two segments beside the path, which disagree: `max_side_parameter_gap` in the status),
  /// the inside by a Tutte embedding with the mean value weights of the mesh's metric and that
  /// boundary (a discrete harmonic map; harmonic maps do not change under conformal scaling, so
  /// with the conformal boundary it approximates the segment's conformal map onto its polygon,
  /// stretched to the polygon's sides); no relaxation. Conformal maps shrink protrusions
  /// exponentially, so the grid's cells vary in size on the surface.
  RICCI_FLOW_SEGMENTS
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_METRIC_STATUS_H
