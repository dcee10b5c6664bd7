// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_SINGULARITIES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_SINGULARITIES_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>

#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Topology of a face-based N-RoSy field, see field_singularities().
template <typename TriangleMesh>
struct Field_topology
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// interior vertices with a non-zero index, with the index (a multiple of \f$1/N\f$)
  std::vector<std::pair<vertex_descriptor, double>> singularities;
  /// turning number of the field around each generator of tree_cotree_generators()
  std::vector<double> generator_turning_numbers;
  /// largest distance of a computed index or turning number to the nearest multiple of
  /// \f$1/N\f$ before rounding (about \f$10^{-12}\f$ for a consistent field)
  double max_rounding_error = 0;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Reads back the singularities of any face-based N-RoSy field given by one angle per face in
/// the face frames (counterclockwise from `halfedge(f)`; the field's directions are that angle
/// plus multiples of \f$2\pi/N\f$).
///
/// Across each edge the field's rotation relative to Levi-Civita transport is given by the
/// `matching` parameter, or else taken as the smallest one modulo \f$2\pi/N\f$,
/// \f$\Delta_h \in (-\pi/N, \pi/N]\f$ (principal matching, what a reader without the
/// matching sees). The index of an interior
/// vertex \f$v\f$ is \f$(K_v + \sum \Delta_h)/2\pi\f$ over its dual cell traversed
/// counterclockwise, so a counterclockwise rotation of the field around \f$v\f$ counts
/// positively (a source or a center has index +1, a saddle -1), and the turning number of a
/// generator is \f$(\mathrm{hol}_{LC} + \sum \Delta_h)/2\pi\f$ with \f$\mathrm{hol}_{LC}\f$ in
/// \f$(-\pi, \pi]\f$ — the conventions of `Trivial_connection`. The indices sum to \f$\chi\f$
/// on closed components. Under principal matching a field can only show rotations below
/// \f$\pi/N\f$ per edge, so an index whose connection turns more than that across some edge
/// (e.g. index +20 on a coarse mesh, or a cotan-weighted solve with large weights) is read
/// correctly only with the field's matching.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{symmetry_order}
///     \cgalParamDescription{\f$N\f$} \cgalParamType{`int`} \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_length_map}
///     \cgalParamDescription{the intrinsic metric} \cgalParamType{readable edge property map}
///     \cgalParamDefault{Euclidean lengths from `vertex_point_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{intrinsic_mesh}
///     \cgalParamDescription{the intrinsic mesh of `tm` to read the field on (e.g. `Trivial_connection::intrinsic_mesh()`), instead of building one; replaces `edge_length_map`, `vertex_point_map` and the index maps}
///     \cgalParamType{`Intrinsic_mesh<TriangleMesh>`}
///     \cgalParamDefault{one built from `tm` and the other parameters}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map, face_index_map, edge_index_map}
///     \cgalParamDescription{the numbering of the simplices, as in `Intrinsic_mesh`}
///   \cgalParamNEnd
///   \cgalParamNBegin{matching}
///     \cgalParamDescription{the period jump \f$k_e\f$ of every interior edge, for `halfedge(e)` (see `Trivial_connection::field_matching()`): the rotation across the edge relative to Levi-Civita is then \f$w(\beta_l - \beta_r - \text{increment}) + 2\pi k_e/N\f$, \f$w\f$ wrapping to \f$(-\pi, \pi]\f$, instead of the smallest one modulo \f$2\pi/N\f$}
///     \cgalParamType{a readable property map with `edge_descriptor` keys and integer values}
///     \cgalParamDefault{principal matching}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename FaceAngleMap,
          typename NamedParameters = parameters::Default_named_parameters>
Field_topology<TriangleMesh> field_singularities(const TriangleMesh& tm, const FaceAngleMap& angles,
                                                 const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const int N = choose_parameter(get_parameter(np, internal_np::symmetry_order), 1);
  if(N < 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1");
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<double> beta(m.number_of_faces());
  for(std::size_t f = 0; f < beta.size(); ++f) {
    beta[f] = double(get(angles, m.faces[f]));
    if(!std::isfinite(beta[f]))
      throw Input_error(Input_error::INVALID_ARGUMENT, "field angle of face " + std::to_string(f) + " is not finite");
  }
  const double period = 2 * CGAL_PI / N;
  // The rotation of the field relative to Levi-Civita across h, from face(h ^ 1) into face(h):
  // beta_l - beta_r - increment plus the period jump of the matching, or the smallest
  // representative modulo 2 pi / N (principal matching).
  std::vector<double> jump;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::matching_t>::value) {
    const auto matching = get_parameter(np, internal_np::matching);
    jump.assign(m.number_of_edges(), 0.);
    for(std::size_t e = 0; e < jump.size(); ++e) jump[e] = period * double(get(matching, m.edges[e]));
  }
  auto delta = [&](int h) {
    if(jump.empty())
      return std::remainder(beta[m.face[h]] - beta[m.face[h ^ 1]] - internal::transport_increment(m, h), period);
    // (the increments of h and h ^ 1 sum to 2 pi, not 0: computed for the edge's halfedge)
    const int g = h & ~1;
    const double d = internal::wrap_angle(beta[m.face[g]] - beta[m.face[g ^ 1]] - internal::transport_increment(m, g));
    return (h & 1) ? -(d + jump[g >> 1]) : d + jump[g >> 1];
  };
  const std::vector<double>& K = im.curvatures();
  Field_topology<TriangleMesh> r;
  auto round_to = [&](double s) {
    const double k = s / (2 * CGAL_PI) * N;
    r.max_rounding_error = (std::max)(r.max_rounding_error, std::abs(k - std::round(k)) / N);
    return std::round(k) / N;
  };
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    if(m.is_isolated(int(v)) || m.is_boundary_vertex(int(v))) continue;
    double s = K[v];
    const int h0 = m.vertex_out[v];
    int h = h0;
    do { s += delta(h); h = m.ccw_out(h); } while(h != h0);
    const double k = round_to(s);
    if(k != 0) r.singularities.push_back(std::make_pair(m.vertices[v], k));
  }
  for(const auto& g : im.generator_arrays()) {
    double s = internal::wrap_angle(internal::transport_along(m, g.dual));
    for(int h : g.dual) s += delta(h);
    r.generator_turning_numbers.push_back(round_to(s));
  }
  return r;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// The principal matching of a face field: for every interior edge \f$e\f$, the period jump
/// \f$k_e\f$ (in the convention of the `matching` parameter of field_singularities(), for
/// `halfedge(e)`) that makes the field's rotation across the edge relative to Levi-Civita the
/// smallest one modulo \f$2\pi/N\f$; 0 on border edges. field_singularities() with this
/// matching reads what it reads without one. This is the matching to hand on with a field whose
/// rotation relative to Levi-Civita stays below \f$\pi/N\f$ on every edge (parallel and
/// rotation-compensated fields, whose read-back then shows only their cones). Returns the
/// largest \f$|\Delta_e|\f$ over the interior edges, to compare with \f$\pi/N\f$. Named
/// parameters: `symmetry_order`, `edge_length_map` or `intrinsic_mesh`, and the index maps, as
/// for field_singularities().
template <typename TriangleMesh, typename FaceAngleMap, typename EdgeMatchingMap,
          typename NamedParameters = parameters::Default_named_parameters>
double principal_matching(const TriangleMesh& tm, const FaceAngleMap& angles, EdgeMatchingMap matching,
                          const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const int N = choose_parameter(get_parameter(np, internal_np::symmetry_order), 1);
  if(N < 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1");
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const double period = 2 * CGAL_PI / N;
  double largest = 0;
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
    const int h = int(2 * e);
    if(m.face[std::size_t(h)] < 0 || m.face[std::size_t(h ^ 1)] < 0) { put(matching, m.edges[e], 0); continue; }
    const double bl = double(get(angles, m.faces[std::size_t(m.face[std::size_t(h)])]));
    const double br = double(get(angles, m.faces[std::size_t(m.face[std::size_t(h ^ 1)])]));
    if(!std::isfinite(bl) || !std::isfinite(br))
      throw Input_error(Input_error::INVALID_ARGUMENT, "field angle of a face next to edge " + std::to_string(e) + " is not finite");
    const double raw = bl - br - internal::transport_increment(m, h);
    const double d = std::remainder(raw, period);
    largest = (std::max)(largest, std::abs(d));
    put(matching, m.edges[e], int(std::lround((d - internal::wrap_angle(raw)) / period)));
  }
  return largest;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Converts 3D tangent vectors (one per face) to angles in the face frames: the angle of the
/// projection of the vector on the face plane, counterclockwise from `halfedge(f)`, in
/// \f$[0, 2\pi)\f$. Named parameter `vertex_point_map` (default: the mesh's points).
template <typename TriangleMesh, typename FaceVectorMap, typename FaceAngleMap,
          typename NamedParameters = parameters::Default_named_parameters>
void vectors_to_face_angles(const TriangleMesh& tm, const FaceVectorMap& vectors, FaceAngleMap angles,
                            const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const auto& p0 = get(vpm, source(h, tm));
    const auto& p1 = get(vpm, target(h, tm));
    const auto& p2 = get(vpm, target(next(h, tm), tm));
    const double e1[3] = {p1.x() - p0.x(), p1.y() - p0.y(), p1.z() - p0.z()};
    const double e2[3] = {p2.x() - p0.x(), p2.y() - p0.y(), p2.z() - p0.z()};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double b[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
    const auto& v = get(vectors, f);
    const double le = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    const double x = (v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2]) / le;
    const double y = (v[0] * b[0] + v[1] * b[1] + v[2] * b[2]) / lb;
    double a = std::atan2(y, x);
    if(a < 0) a += 2 * CGAL_PI;
    put(angles, f, a);
  }
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_SINGULARITIES_H
