// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

/*!
\ingroup PkgSurfaceMeshDirectionFieldsConcepts
\brief An intrinsic metric of a triangle mesh, given as one length per edge.

\cgalConcept

The type of the `edge_length_map` named parameter of every geometric function of the package (see
\ref SMDFSecMetric).

It is a readable property map (in the sense of the Boost Property Map Library) whose key type
is `boost::graph_traits<TriangleMesh>::%edge_descriptor` and whose value type is `double`, or
a type that `static_cast<double>` converts. Algorithms take the map by value, as property maps
are passed in \cgal, and read it once for every edge with `get(map, e)`: a map that changes
afterwards does not change an `CGAL::Surface_mesh_direction_fields::Intrinsic_mesh` or an
object already built from it.

<b>Validity.</b> The lengths define a metric when they are finite and strictly positive and
the three lengths of every face satisfy the strict triangle inequalities (Lai et al. 2010,
section 3.2: "a configuration of edge lengths, such that the triangle inequality holds on all
faces"). Functions that work on the whole mesh validate this and throw
`CGAL::Surface_mesh_direction_fields::Input_error`: kind
`CGAL::Surface_mesh_direction_fields::Input_error::INVALID_GEOMETRY` for a non-finite length,
kind `CGAL::Surface_mesh_direction_fields::Input_error::DEGENERATE_FACE` for a face with a zero length, lengths that violate the triangle
inequality, or an area below \f$10^{-14}\f$ times the square of its longest edge. Queries on a
single element (`CGAL::Surface_mesh_direction_fields::corner_angle()`,
`CGAL::Surface_mesh_direction_fields::cotangent_weight()`,
`CGAL::Surface_mesh_direction_fields::vertex_curvature()`) do not validate
and clamp instead (see \ref SMDFSecAngles).

\cgalHasModelsBegin
\cgalHasModels{`CGAL::Surface_mesh_direction_fields::Euclidean_edge_length_map`, the default:
  the lengths of the embedding given by `vertex_point_map`}
\cgalHasModels{any readable \cgal or Boost property map with edge keys and `double` values:
  a property map of `CGAL::Surface_mesh` (`Mesh::Property_map<Mesh::Edge_index, double>`),
  `get(CGAL::dynamic_edge_property_t<double>(), tm)`,
  `boost::associative_property_map<std::map<edge_descriptor, double>>`, or
  `CGAL::Constant_property_map<edge_descriptor, double>` (the equilateral metric)}
\cgalHasModels{the `output_lengths` map filled by `CGAL::Surface_mesh_direction_fields::compute_cone_metric()`,
  when the returned `CGAL::Surface_mesh_direction_fields::Cone_metric_status` has
  `triangulation_changed == false` and no `punched_vertices`
  (otherwise some of its values are NaN: use the map filled by
  `CGAL::Surface_mesh_direction_fields::copy_intrinsic_triangulation()` on the copied mesh)}
\cgalHasModelsEnd

\sa `CGAL::Surface_mesh_direction_fields::GetEdgeLengthMap`,
`CGAL::Surface_mesh_direction_fields::get_edge_length_map()`,
`CGAL::Surface_mesh_direction_fields::Intrinsic_mesh::with_edge_lengths()`
*/
class EdgeLengthMap
{
public:
  /// \name Types
  /// @{

  /// `boost::graph_traits<TriangleMesh>::%edge_descriptor`
  typedef unspecified_type key_type;

  /// `double`, or a type convertible to `double` with `static_cast`
  typedef unspecified_type value_type;

  /// @}

  /// \name Creation
  /// @{

  /// Copy constructor (property maps are passed by value).
  EdgeLengthMap(const EdgeLengthMap& other);

  /// @}
};

/// \relates EdgeLengthMap
/// Returns the length of the edge `e`.
value_type get(const EdgeLengthMap& map, key_type e);
