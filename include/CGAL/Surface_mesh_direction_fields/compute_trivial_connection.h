// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMPUTE_TRIVIAL_CONNECTION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMPUTE_TRIVIAL_CONNECTION_H

#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cholesky_solver_traits.h>

#include <CGAL/boost/graph/helpers.h>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Computes the trivial connection with the given singularities in one call (see
/// `Trivial_connection`) and writes the adjustment angle of each edge, for crossing in the
/// direction of `halfedge(e)` (0 on boundary edges), to `adjustment`.
/// \tparam SingularityRange a range of `std::pair<vertex_descriptor, double>` (vertex, index);
///         may be empty when `singularity_index_map` is given
/// \tparam EdgeAngleMap a writable property map, `edge_descriptor` keys, `double` values
///
/// Named parameters: those of the `Trivial_connection` constructor, and
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{singularity_index_map}
///     \cgalParamDescription{the index of every vertex (0 for regular vertices), read at interior vertices; pairs of `singularities` override it}
///     \cgalParamType{a readable property map with `vertex_descriptor` keys and `double` values}
///     \cgalParamDefault{all indices 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{generator_turning_numbers}
///     \cgalParamDescription{turning number around each generator of `tree_cotree_generators()`, in that order}
///     \cgalParamType{a range of `double` (multiples of \f$1/N\f$)}
///     \cgalParamDefault{all 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothest_generator_turning_numbers}
///     \cgalParamDescription{if `true`, the turning numbers that minimise the energy, see `Trivial_connection::choose_smoothest_generator_turning_numbers()` (not with `generator_turning_numbers` or `guide_directions`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{directional_constraints}
///     \cgalParamDescription{faces with a fixed field angle, see `Trivial_connection::set_directional_constraints()`}
///     \cgalParamType{a range of `std::pair<face_descriptor, double>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{guide_directions}
///     \cgalParamDescription{soft guide directions, see `Trivial_connection::set_guide_directions()`}
///     \cgalParamType{a range of `std::pair<face_descriptor, double>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{guide_weight}
///     \cgalParamDescription{the weight \f$\lambda\f$ of the guide directions}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_angle_map}
///     \cgalParamDescription{if given, receives the field angle of every face (`Trivial_connection::field_angles()`)}
///     \cgalParamType{a writable property map with `face_descriptor` keys and `double` values}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// Throws as `Trivial_connection::set_singularity()` and `Trivial_connection::solve()` do.
template <typename TriangleMesh, typename SingularityRange, typename EdgeAngleMap,
          typename NamedParameters = parameters::Default_named_parameters>
Trivial_connection_status compute_trivial_connection(const TriangleMesh& tm,
                                                     const SingularityRange& singularities,
                                                     EdgeAngleMap adjustment,
                                                     const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Trivial_connection<TriangleMesh, typename internal::Get_cholesky_solver<NamedParameters>::type> tc(tm, np);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::singularity_index_t>::value) {
    const auto index = get_parameter(np, internal_np::singularity_index);
    for(auto v : vertices(tm))
      if(!is_border(v, tm) && halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge()) {
        const double k = double(get(index, v));
        if(k != 0) tc.set_singularity(v, k);
      }
  }
  for(const auto& s : singularities) tc.set_singularity(s.first, s.second);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::generator_turning_numbers_t>::value) {
    std::size_t i = 0;
    for(double t : get_parameter(np, internal_np::generator_turning_numbers)) tc.set_generator_turning_number(i++, t);
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::directional_constraints_t>::value)
    tc.set_directional_constraints(get_parameter(np, internal_np::directional_constraints));
  if(choose_parameter(get_parameter(np, internal_np::smoothest_generator_turning_numbers), false)) {
    if constexpr(!is_default_parameter<NamedParameters, internal_np::generator_turning_numbers_t>::value)
      throw Input_error(Input_error::INVALID_ARGUMENT,
                        "generator_turning_numbers and smoothest_generator_turning_numbers exclude each other");
    tc.choose_smoothest_generator_turning_numbers();
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::guide_directions_t>::value)
    tc.set_guide_directions(get_parameter(np, internal_np::guide_directions),
                            choose_parameter(get_parameter(np, internal_np::guide_weight), 1.));
  Trivial_connection_status st = tc.solve();
  if(st.success) {
    for(auto e : edges(tm)) put(adjustment, e, tc.adjustment_angle(halfedge(e, tm)));
    if constexpr(!is_default_parameter<NamedParameters, internal_np::face_angle_t>::value)
      tc.field_angles(get_parameter(np, internal_np::face_angle));
  }
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMPUTE_TRIVIAL_CONNECTION_H
