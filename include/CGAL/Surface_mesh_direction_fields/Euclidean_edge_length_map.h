// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_EUCLIDEAN_EDGE_LENGTH_MAP_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_EUCLIDEAN_EDGE_LENGTH_MAP_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// A readable property map from the edges of a mesh to their Euclidean lengths, computed on
/// the fly from a vertex point map: \f$\sqrt{d^2}\f$ with the squared distance \f$d^2\f$ of
/// the kernel `GeomTraits` (exact for exact kernels) converted once by `CGAL::to_double()`.
/// It is the default `edge_length_map` of every function of the package.
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexPointMap a readable property map from vertices to 3D points
/// \tparam GeomTraits a kernel with `Compute_squared_distance_3` for those points (default:
///         the points' kernel; functions pass their `geom_traits` parameter)
/// \cgalModels `EdgeLengthMap`
template <typename TriangleMesh, typename VertexPointMap,
          typename GeomTraits = typename CGAL::Kernel_traits<
              typename boost::property_traits<VertexPointMap>::value_type>::Kernel>
class Euclidean_edge_length_map
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor key_type;
  typedef double value_type;
  typedef double reference;
  typedef boost::readable_property_map_tag category;

  Euclidean_edge_length_map() : tm_(nullptr) {}
  Euclidean_edge_length_map(const TriangleMesh& tm, VertexPointMap vpm, const GeomTraits& gt = GeomTraits())
    : tm_(&tm), vpm_(vpm), gt_(gt) {}

  friend double get(const Euclidean_edge_length_map& m, key_type e)
  {
    const auto h = halfedge(e, *m.tm_);
    return std::sqrt(CGAL::to_double(m.gt_.compute_squared_distance_3_object()(
        get(m.vpm_, source(h, *m.tm_)), get(m.vpm_, target(h, *m.tm_)))));
  }

private:
  const TriangleMesh* tm_;
  VertexPointMap vpm_;
  GeomTraits gt_;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// The type of the edge-length map that functions use for a mesh and a named-parameter pack:
/// the `edge_length_map` parameter if given, else a `Euclidean_edge_length_map` on the
/// `vertex_point_map` parameter (default: the internal point map of the mesh).
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
struct GetEdgeLengthMap
{
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef Euclidean_edge_length_map<TriangleMesh, VPM, Geom_traits> Default_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::edge_length_t,
                                                             NamedParameters,
                                                             Default_map>::type type;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the edge-length map that functions use for `tm` and `np` (see `GetEdgeLengthMap`).
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
typename GetEdgeLengthMap<TriangleMesh, NamedParameters>::type
get_edge_length_map(const TriangleMesh& tm,
                    const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef GetEdgeLengthMap<TriangleMesh, NamedParameters> Get;
  typename Get::VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                           get_const_property_map(CGAL::vertex_point, tm));
  const typename Get::Geom_traits gt = choose_parameter<typename Get::Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  return choose_parameter(get_parameter(np, internal_np::edge_length),
                          typename Get::Default_map(tm, vpm, gt));
}

namespace internal {

// Reads the metric of `np` into `out` (indexed like `edges`); rejects non-finite lengths.
template <typename TriangleMesh, typename EdgeRange, typename NamedParameters>
void fill_edge_lengths(const TriangleMesh& tm, const EdgeRange& edges,
                       std::vector<double>& out, const NamedParameters& np)
{
  auto lengths = get_edge_length_map(tm, np);
  std::size_t i = 0;
  for(const auto& e : edges) {
    const double l = static_cast<double>(get(lengths, e));
    if(!std::isfinite(l)) {
      std::ostringstream os;
      os << "edge " << i << " has a non-finite length (NaN or infinite coordinates or lengths)";
      throw Input_error(Input_error::INVALID_GEOMETRY, os.str());
    }
    out[i++] = l;
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_EUCLIDEAN_EDGE_LENGTH_MAP_H
