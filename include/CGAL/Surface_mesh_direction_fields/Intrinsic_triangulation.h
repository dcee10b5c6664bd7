// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_TRIANGULATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_TRIANGULATION_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// A triangulation of the vertices of an input mesh by intrinsic edges, with a length per
/// edge: the result of compute_cone_metric() when it had to flip edges.
///
/// It has the vertices, the number of edges and the number of faces of the input mesh, and
/// vertex \f$i\f$ is the \f$i\f$-th vertex of `vertices(tm)`. Edges and faces are numbered
/// \f$0 \dots n-1\f$; edge \f$e\f$ has the halfedges \f$2e\f$ and \f$2e+1\f$, faces are
/// counterclockwise (with the input's orientation), and border halfedges (face \f$-1\f$) are the
/// input's: only interior edges are ever flipped. Several edges may join the same two vertices
/// and an edge may join a vertex to itself, as in any intrinsic triangulation; the lengths
/// satisfy the triangle inequalities on every face.
///
/// `input_edge(e)` relates it to the input: the index (in `edges(tm)` order) of the input edge
/// that edge \f$e\f$ is, or \f$-1\f$ for an edge created by a flip. To use the metric with the
/// rest of the package, build a mesh with copy_intrinsic_triangulation() and pass its lengths
/// as `edge_length_map`.
class Intrinsic_triangulation
{
public:
  /// An empty triangulation.
  Intrinsic_triangulation() = default;

  /// Builds it from halfedge arrays (indices as described above); used by compute_cone_metric().
  Intrinsic_triangulation(std::size_t number_of_vertices, std::vector<int> next, std::vector<int> target,
                          std::vector<int> face, std::vector<int> face_halfedge,
                          std::vector<double> length, std::vector<long> input_edge)
    : nv_(number_of_vertices), next_(std::move(next)), target_(std::move(target)), face_(std::move(face)),
      face_halfedge_(std::move(face_halfedge)), length_(std::move(length)), input_edge_(std::move(input_edge))
  {}

  /// number of vertices (that of the input mesh)
  std::size_t number_of_vertices() const { return nv_; }
  /// number of edges (that of the input mesh)
  std::size_t number_of_edges() const { return length_.size(); }
  /// number of faces (that of the input mesh)
  std::size_t number_of_faces() const { return face_halfedge_.size(); }
  /// `true` if it has no faces
  bool empty() const { return face_halfedge_.empty(); }

  /// next halfedge in the same face (or along the same border loop)
  int next(int h) const { return next_[h]; }
  /// vertex that halfedge `h` points to
  int target(int h) const { return target_[h]; }
  /// vertex that halfedge `h` starts from
  int source(int h) const { return target_[h ^ 1]; }
  /// face of halfedge `h`, -1 for a border halfedge
  int face(int h) const { return face_[h]; }
  /// a halfedge of face `f`
  int halfedge(int f) const { return face_halfedge_[f]; }
  /// the three vertices of face `f`, counterclockwise from `source(halfedge(f))`
  std::array<int, 3> face_vertices(int f) const
  {
    const int h = face_halfedge_[f];
    return {{source(h), target(h), target(next(h))}};
  }
  /// length of edge `e`
  double length(int e) const { return length_[e]; }
  /// index of the input edge that edge `e` is, or -1 if `e` was created by a flip
  long input_edge(int e) const { return input_edge_[e]; }
  /// number of edges that are not input edges
  std::size_t number_of_new_edges() const
  {
    std::size_t n = 0;
    for(long i : input_edge_) n += (i < 0);
    return n;
  }

private:
  std::size_t nv_ = 0;
  std::vector<int> next_, target_, face_, face_halfedge_;
  std::vector<double> length_;
  std::vector<long> input_edge_;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// Builds `out` as a copy of an intrinsic triangulation and writes its edge lengths, so that
/// every function of the package can work on the metric (pass `out_lengths` as
/// `edge_length_map`). The vertices of `out` are created in the order of the triangulation's
/// vertices, i.e. of `vertices(tm)`, with the points of `tm` (they only serve display: the
/// geometry is in the lengths); edges and faces are created in the triangulation's order.
/// Halfedge-level construction: multiple edges and loops are kept.
///
/// \tparam TriangleMesh a model of `VertexListGraph` with a `vertex_point` property
/// \tparam OutputMesh a model of `MutableFaceGraph` with a `vertex_point` property
/// \tparam OutputEdgeLengthMap a writable property map with `edge_descriptor` keys of `OutputMesh`
///   and `double` values
/// \param it the triangulation
/// \param tm the mesh it was computed for (same number of vertices)
/// \param out an empty mesh, receives the triangulation
/// \param out_lengths receives the length of every edge of `out`
/// \return the edges of `out`, indexed like the edges of `it`
///
/// Throws `Input_error` if `it` and `tm` do not have the same number of vertices or `out` is
/// not empty.
template <typename TriangleMesh, typename OutputMesh, typename OutputEdgeLengthMap>
std::vector<typename boost::graph_traits<OutputMesh>::edge_descriptor>
copy_intrinsic_triangulation(const Intrinsic_triangulation& it, const TriangleMesh& tm,
                             OutputMesh& out, OutputEdgeLengthMap out_lengths)
{
  typedef boost::graph_traits<OutputMesh> GT;
  if(num_vertices(tm) != it.number_of_vertices())
    throw Input_error(Input_error::INVALID_ARGUMENT,
                      "copy_intrinsic_triangulation(): the mesh has " + std::to_string(num_vertices(tm)) +
                          " vertices, the triangulation " + std::to_string(it.number_of_vertices()));
  if(num_vertices(out) != 0 || num_faces(out) != 0)
    throw Input_error(Input_error::INVALID_ARGUMENT, "copy_intrinsic_triangulation(): the output mesh is not empty");

  auto in_points = get(CGAL::vertex_point, tm);
  auto out_points = get(CGAL::vertex_point, out);
  std::vector<typename GT::vertex_descriptor> vs;
  vs.reserve(it.number_of_vertices());
  for(auto v : vertices(tm)) {
    vs.push_back(add_vertex(out));
    put(out_points, vs.back(), get(in_points, v));
  }
  const std::size_t ne = it.number_of_edges(), nh = 2 * ne;
  std::vector<typename GT::edge_descriptor> es(ne);
  std::vector<typename GT::halfedge_descriptor> hs(nh);
  for(std::size_t e = 0; e < ne; ++e) {
    es[e] = add_edge(out);
    hs[2 * e] = CGAL::halfedge(es[e], out);
    hs[2 * e + 1] = CGAL::opposite(hs[2 * e], out);
    put(out_lengths, es[e], it.length(int(e)));
  }
  std::vector<typename GT::face_descriptor> fs(it.number_of_faces());
  for(auto& f : fs) f = add_face(out);
  for(std::size_t h = 0; h < nh; ++h) {
    set_target(hs[h], vs[it.target(int(h))], out);
    set_next(hs[h], hs[it.next(int(h))], out);
    set_face(hs[h], it.face(int(h)) < 0 ? GT::null_face() : fs[it.face(int(h))], out);
  }
  for(std::size_t f = 0; f < fs.size(); ++f) set_halfedge(fs[f], hs[it.halfedge(int(f))], out);
  // halfedge(v): an incoming halfedge, a border one for boundary vertices
  std::vector<char> has(vs.size(), 0);
  for(std::size_t h = 0; h < nh; ++h) {
    const int v = it.target(int(h));
    if(!has[v] || it.face(int(h)) < 0) { set_halfedge(vs[v], hs[h], out); has[v] = 1; }
  }
  return es;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_TRIANGULATION_H
