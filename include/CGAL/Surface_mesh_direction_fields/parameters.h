// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_PARAMETERS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Surface_mesh_direction_fields {

namespace internal_np {
#define CGAL_SMDF_add_named_parameter(X, Y, Z) enum X { Y };
#include <CGAL/Surface_mesh_direction_fields/internal/parameters_interface.h>
#undef CGAL_SMDF_add_named_parameter
} // namespace internal_np

/// \ingroup PkgSurfaceMeshDirectionFieldsRef
/// A named-parameter pack that accepts both CGAL's parameters and the package's own
/// (`edge_length_map`, `symmetry_order`, `connection_weights`, ...), so that they can be chained in any order.
/// Users never name this type; they start a pack with a function of
/// `CGAL::Surface_mesh_direction_fields::parameters`.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> CGAL_np;
  typedef typename CGAL_np::base base;
  typedef Named_function_parameters self;

  Named_function_parameters(const T& v) : CGAL_np(v) {}
  Named_function_parameters(const T& v, const Base& b) : CGAL_np(v, b) {}
  Named_function_parameters(const CGAL_np& np) : CGAL_np(np) {}

#ifndef DOXYGEN_RUNNING
#define CGAL_add_named_parameter(X, Y, Z)                                         \
  template <typename K>                                                           \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const    \
  { return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this); }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_SMDF_add_named_parameter(X, Y, Z)                                    \
  template <typename K>                                                           \
  Named_function_parameters<K, internal_np::X, self> Z(const K& k) const          \
  { return Named_function_parameters<K, internal_np::X, self>(k, *this); }
#include <CGAL/Surface_mesh_direction_fields/internal/parameters_interface.h>
#undef CGAL_SMDF_add_named_parameter
#endif
};

/// Named-parameter starters: `parameters::edge_length_map(m).vertex_point_map(vpm)`.
namespace parameters {

using CGAL::parameters::Default_named_parameters;
using CGAL::parameters::default_values;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::is_default_parameter;

#ifndef DOXYGEN_RUNNING
#define CGAL_add_named_parameter(X, Y, Z)                                         \
  template <typename K>                                                           \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& k)                \
  { return Named_function_parameters<K, CGAL::internal_np::X>(k); }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_SMDF_add_named_parameter(X, Y, Z)                                    \
  template <typename K>                                                           \
  Named_function_parameters<K, internal_np::X> Z(const K& k)                      \
  { return Named_function_parameters<K, internal_np::X>(k); }
#include <CGAL/Surface_mesh_direction_fields/internal/parameters_interface.h>
#undef CGAL_SMDF_add_named_parameter
#endif

/// Adopts a pack built with `CGAL::parameters` so that package parameters can be chained to it.
template <typename T, typename Tag, typename Base>
Named_function_parameters<T, Tag, Base>
extend(const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return Named_function_parameters<T, Tag, Base>(np);
}

} // namespace parameters
} // namespace Surface_mesh_direction_fields

#ifndef DOXYGEN_RUNNING
// PMP/measure.h specialises GetGeomTraits on CGAL's exact pack type; mirror it for ours.
template <typename T, typename Tag, typename Base, typename NP>
class GetGeomTraits<Surface_mesh_direction_fields::Named_function_parameters<T, Tag, Base>, NP>
{
public:
  struct type {};
};
#endif

} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_PARAMETERS_H
