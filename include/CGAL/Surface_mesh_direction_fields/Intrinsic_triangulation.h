// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_TRIANGULATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_TRIANGULATION_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// A point of a triangulated surface: a face and its barycentric coordinates. For an input face
/// the coordinates are those of the corners `source(halfedge(f))`, `target(halfedge(f))`,
/// `target(next(halfedge(f)))` (faces numbered in `faces(tm)` order); for a face of an
/// `Intrinsic_triangulation`, those of `face_vertices(f)` in its metric.
struct Surface_point
{
  int face = -1;   ///< the face, -1 for no point
  std::array<double, 3> barycentric = {{0., 0., 0.}};   ///< non-negative, summing to 1
};

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// A piece of the common subdivision of an input mesh and an `Intrinsic_triangulation`: a
/// convex polygon that lies in one input face and in one intrinsic face, with its corners
/// (counterclockwise) in the barycentric coordinates of both and its area under both metrics.
struct Common_subdivision_piece
{
  int input_face = -1;       ///< the input face (index in `faces(tm)` order)
  int intrinsic_face = -1;   ///< the face of the intrinsic triangulation
  double input_area = 0;     ///< area under the input metric
  double intrinsic_area = 0; ///< area under the intrinsic metric
  std::vector<std::array<double, 3>> input_corners;     ///< barycentric coordinates in `input_face`
  std::vector<std::array<double, 3>> intrinsic_corners; ///< barycentric coordinates in `intrinsic_face`
  /// per corner: a vertex (its index), or the number of vertices plus the index of a crossing of
  /// an input edge with an intrinsic edge (a point shared by the pieces around it)
  std::vector<long> corner_ids;
  /// per side (from corner i to corner i + 1): the halfedge of `intrinsic_face` it lies on, or -1
  std::vector<int> intrinsic_sides;
  /// per side: the halfedge of `input_face` it lies on (\f$2e\f$ for `halfedge(e)` of the input
  /// edge \f$e\f$, \f$2e + 1\f$ for its opposite), or -1
  std::vector<int> input_sides;
};

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
///
/// <b>Correspondence.</b> compute_cone_metric() also hands on the common subdivision of the
/// two triangulations (`has_common_subdivision()`), built as the flips are made: both are ideal
/// triangulations of one decorated hyperbolic surface (Gillespie, Springborn, Crane 2021), the
/// input edges crossing every intrinsic edge are tracked through each flip (normal coordinates,
/// Gillespie, Sharp, Crane 2021), and the map between the two is projective on every piece:
/// the discrete conformal map of the metric. `locate_on_input()` and `locate_on_intrinsic()` map
/// points both ways, `common_subdivision()` lists the pieces with their areas under both metrics.
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

  /// `true` if the correspondence with the input (the common subdivision) is available
  bool has_common_subdivision() const { return !pieces_.empty(); }
  /// the pieces of the common subdivision
  const std::vector<Common_subdivision_piece>& common_subdivision() const { return pieces_; }
  /// the pieces in input face `f` (indices into `common_subdivision()`)
  std::vector<std::size_t> pieces_of_input_face(int f) const { return range(input_first_, input_list_, f); }
  /// the pieces in intrinsic face `f` (indices into `common_subdivision()`)
  std::vector<std::size_t> pieces_of_intrinsic_face(int f) const { return range(intrinsic_first_, intrinsic_list_, f); }
  /// A range of piece indices, viewed in place (valid while the triangulation lives).
  struct Piece_range
  {
    const std::size_t* first = nullptr;
    const std::size_t* last = nullptr;
    const std::size_t* begin() const { return first; }
    const std::size_t* end() const { return last; }
    std::size_t size() const { return std::size_t(last - first); }
  };
  /// as pieces_of_input_face(), without a copy (for loops over every face)
  Piece_range input_face_pieces(int f) const { return view(input_first_, input_list_, f); }
  /// as pieces_of_intrinsic_face(), without a copy
  Piece_range intrinsic_face_pieces(int f) const { return view(intrinsic_first_, intrinsic_list_, f); }
  /// number of points where an input edge crosses an intrinsic edge
  std::size_t number_of_crossings() const { return crossings_; }
  /// largest error of the correspondence's own check: the corners of every piece mapped by its
  /// projective map against the same corners located on the input (about 1e-12 when sound)
  double correspondence_residual() const { return residual_; }

  /// The point of the input mesh at point `p` of this triangulation (intrinsic face and its
  /// barycentric coordinates). Throws `Input_error` if there is no common subdivision or `p` is
  /// not a point of a face.
  Surface_point locate_on_input(const Surface_point& p) const { return locate(p, true); }
  /// The point of this triangulation at point `p` of the input mesh (input face and its
  /// barycentric coordinates). Throws `Input_error` as `locate_on_input()`.
  Surface_point locate_on_intrinsic(const Surface_point& p) const { return locate(p, false); }

  /// The projective map of piece `i` in homogeneous barycentric coordinates: the input
  /// coordinates of the point with intrinsic coordinates \f$c\f$ are \f$Ac / \mathbf{1}^T Ac\f$
  /// (`to_input`), and back with the inverse matrix (`to_input == false`). Row-major.
  const std::array<double, 9>& piece_map(std::size_t i, bool to_input) const
  {
    return to_input ? to_input_[i] : from_input_[i];
  }

  /// Sets the common subdivision (used by compute_cone_metric()): the pieces, the map of each
  /// (see `piece_map()`), the number of input faces, of crossings, and the residual of the
  /// builder's check.
  void set_common_subdivision(std::vector<Common_subdivision_piece> pieces, std::vector<std::array<double, 9>> to_input,
                              std::size_t number_of_input_faces, std::size_t crossings, double residual)
  {
    pieces_ = std::move(pieces);
    to_input_ = std::move(to_input);
    from_input_.resize(to_input_.size());
    for(std::size_t i = 0; i < to_input_.size(); ++i) from_input_[i] = inverse(to_input_[i]);
    crossings_ = crossings;
    residual_ = residual;
    index(number_of_input_faces, true, input_first_, input_list_);
    index(number_of_faces(), false, intrinsic_first_, intrinsic_list_);
  }

private:
  std::size_t nv_ = 0;
  std::vector<int> next_, target_, face_, face_halfedge_;
  std::vector<double> length_;
  std::vector<long> input_edge_;
  std::vector<Common_subdivision_piece> pieces_;
  std::vector<std::array<double, 9>> to_input_, from_input_;
  std::vector<std::size_t> input_first_, input_list_, intrinsic_first_, intrinsic_list_;
  std::size_t crossings_ = 0;
  double residual_ = 0;

  static std::array<double, 9> inverse(const std::array<double, 9>& a)
  {
    std::array<double, 9> r;
    r[0] = a[4] * a[8] - a[5] * a[7]; r[1] = a[2] * a[7] - a[1] * a[8]; r[2] = a[1] * a[5] - a[2] * a[4];
    r[3] = a[5] * a[6] - a[3] * a[8]; r[4] = a[0] * a[8] - a[2] * a[6]; r[5] = a[2] * a[3] - a[0] * a[5];
    r[6] = a[3] * a[7] - a[4] * a[6]; r[7] = a[1] * a[6] - a[0] * a[7]; r[8] = a[0] * a[4] - a[1] * a[3];
    return r;   // the adjugate: a multiple of the inverse is all homogeneous coordinates need
  }

  void index(std::size_t n, bool input, std::vector<std::size_t>& first, std::vector<std::size_t>& list) const
  {
    first.assign(n + 1, 0);
    for(const auto& p : pieces_) ++first[std::size_t(input ? p.input_face : p.intrinsic_face) + 1];
    for(std::size_t f = 0; f < n; ++f) first[f + 1] += first[f];
    list.resize(pieces_.size());
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t i = 0; i < pieces_.size(); ++i)
      list[fill[std::size_t(input ? pieces_[i].input_face : pieces_[i].intrinsic_face)]++] = i;
  }

  static Piece_range view(const std::vector<std::size_t>& first, const std::vector<std::size_t>& list, int f)
  {
    Piece_range r;
    if(f < 0 || std::size_t(f) + 1 >= first.size()) return r;
    r.first = list.data() + first[std::size_t(f)];
    r.last = list.data() + first[std::size_t(f) + 1];
    return r;
  }
  static std::vector<std::size_t> range(const std::vector<std::size_t>& first, const std::vector<std::size_t>& list, int f)
  {
    if(f < 0 || std::size_t(f) + 1 >= first.size()) return {};
    return std::vector<std::size_t>(list.begin() + long(first[std::size_t(f)]), list.begin() + long(first[std::size_t(f) + 1]));
  }

  // The piece of face p.face (input or intrinsic side) that contains p: the one whose corners
  // leave p the least outside (signed distances in barycentric space), then its map.
  Surface_point locate(const Surface_point& p, bool to_input) const
  {
    if(pieces_.empty())
      throw Input_error(Input_error::INVALID_ARGUMENT, "Intrinsic_triangulation: no common subdivision with the input");
    const std::vector<std::size_t>& first = to_input ? intrinsic_first_ : input_first_;
    const std::vector<std::size_t>& list = to_input ? intrinsic_list_ : input_list_;
    if(p.face < 0 || std::size_t(p.face) + 1 >= first.size())
      throw Input_error(Input_error::INVALID_ARGUMENT, "Intrinsic_triangulation: face " + std::to_string(p.face) + " does not exist");
    const double sum = p.barycentric[0] + p.barycentric[1] + p.barycentric[2];
    if(!std::isfinite(sum) || !(std::abs(sum - 1) <= 1e-6))
      throw Input_error(Input_error::INVALID_ARGUMENT, "Intrinsic_triangulation: barycentric coordinates must sum to 1");
    std::size_t best = list[first[std::size_t(p.face)]];
    double best_depth = -std::numeric_limits<double>::infinity();
    for(std::size_t k = first[std::size_t(p.face)]; k < first[std::size_t(p.face) + 1]; ++k) {
      const auto& cs = to_input ? pieces_[list[k]].intrinsic_corners : pieces_[list[k]].input_corners;
      double depth = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < cs.size(); ++i) {
        const auto& a = cs[i];
        const auto& b = cs[(i + 1) % cs.size()];
        const double ex = b[1] - a[1], ey = b[2] - a[2];
        const double norm = std::sqrt(ex * ex + ey * ey);
        if(norm == 0) continue;
        depth = (std::min)(depth, (ex * (p.barycentric[2] - a[2]) - ey * (p.barycentric[1] - a[1])) / norm);
      }
      if(depth > best_depth) { best_depth = depth; best = list[k]; }
    }
    const std::array<double, 9>& A = to_input ? to_input_[best] : from_input_[best];
    const auto& c = p.barycentric;
    Surface_point q;
    q.face = to_input ? pieces_[best].input_face : pieces_[best].intrinsic_face;
    double s = 0;
    for(int i = 0; i < 3; ++i) {
      q.barycentric[std::size_t(i)] = A[3 * i] * c[0] + A[3 * i + 1] * c[1] + A[3 * i + 2] * c[2];
      s += q.barycentric[std::size_t(i)];
    }
    for(double& x : q.barycentric) x = (std::max)(0., x / s);
    s = q.barycentric[0] + q.barycentric[1] + q.barycentric[2];
    for(double& x : q.barycentric) x /= s;
    return q;
  }
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
