// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_FLAT_DEVELOPMENT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_FLAT_DEVELOPMENT_H

// Cut and develop (Lai et al. 2010, section 4.1.3.2 and 5): a flat cone metric opened along a
// cut graph through its cones and handles into one planar layout per component, with the rigid
// motion that glues the layout across every seam.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// A flat cone metric cut open and laid out in the plane, see develop_flat_metric().
///
/// Every face has one position per corner in the layout of its component (the development
/// along a breadth-first spanning tree of the faces, rooted at a face without cones). An
/// interior edge not crossed by the tree is glued by a rigid motion: the positions of its two
/// vertices in the layout of `face(h)` are the motion of their positions in the layout of
/// `face(opposite(h))`. The cut graph is the set of those edges after pruning, repeatedly, the
/// edges that end at an interior vertex without curvature and without other cut edges: what
/// remains runs through every cone and around every handle, and opens each component into a
/// disk. Away from the cut graph the motions are the identity (up to the metric's flatness);
/// on it they are the generalised holonomy of Lai et al. (Theorem 3.5 tests them).
template <typename TriangleMesh>
class Flat_development
{
  typedef boost::graph_traits<TriangleMesh> GT;

public:
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;

  /// Positions of the corners `source(halfedge(f))`, `target(halfedge(f))` and
  /// `target(next(halfedge(f)))` in the layout.
  std::array<Point_2, 3> corners(face_descriptor f) const { return corners_[std::size_t(im_.arrays().face_index(f))]; }

  /// Whether the edge is on the cut graph.
  bool is_cut(edge_descriptor e) const { return cut_[std::size_t(im_.arrays().edge_index(e, *tm_))] != 0; }

  /// The motion from the layout of `face(opposite(h))` to that of `face(h)` (identity for edges
  /// crossed by the spanning tree and for boundary edges).
  Rigid_motion_2 motion(halfedge_descriptor h) const
  {
    const int hi = im_.arrays().halfedge_index(h, *tm_);
    const Rigid_motion_2& r = motions_[std::size_t(hi >> 1)];
    return (hi & 1) ? r.inverse() : r;
  }

  /// Number of edges on the cut graph.
  std::size_t number_of_cut_edges() const { return cut_edges_; }

  /// The cones: interior vertices whose angle defect exceeds the cone tolerance.
  const std::vector<vertex_descriptor>& cones() const { return cones_; }

  /// The largest angle defect of an interior vertex that is not a cone (how flat the metric is).
  double max_flatness_error() const { return flatness_error_; }

  /// The largest rotation or translation (relative to the mesh's mean edge length) of a motion on
  /// an edge pruned from the cut graph: 0 for an exactly flat metric.
  double max_pruned_motion() const { return pruned_motion_; }

  /// The intrinsic mesh the layout was made of.
  const Intrinsic_mesh<TriangleMesh>& intrinsic_mesh() const { return im_; }

  /// \cond SKIP_IN_MANUAL
  Flat_development(const TriangleMesh& tm, Intrinsic_mesh<TriangleMesh> im) : tm_(&tm), im_(std::move(im)) {}
  const TriangleMesh* tm_;
  Intrinsic_mesh<TriangleMesh> im_;
  std::vector<std::array<Point_2, 3>> corners_;   // per face
  std::vector<Rigid_motion_2> motions_;           // per edge, from face(2e + 1) to face(2e)
  std::vector<char> cut_, tree_;                  // per edge: on the cut graph; crossed by the spanning tree
  std::vector<int> cone_index_;                   // per vertex: its place in cones_, or -1
  std::vector<vertex_descriptor> cones_;
  std::size_t cut_edges_ = 0;
  double flatness_error_ = 0, pruned_motion_ = 0;
  /// \endcond
};

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Cuts a flat cone metric open and lays it out in the plane (Lai et al. 2010, section 5):
/// breadth-first over the faces of every component, each face unfolded across the edge to its
/// parent with the metric's lengths, then the rigid motion of every edge the tree does not cross
/// and the cut graph (see `Flat_development`).
///
/// Named parameters: `edge_length_map` (the flat cone metric on `tm`'s own triangulation, e.g.
/// from compute_cone_metric() with `intrinsic_edge_flips(false)`; default: Euclidean lengths) or
/// `intrinsic_mesh`, the index maps, and `curvature_tolerance` (angle defects up to it are flat;
/// default \f$10^{-6}\f$). Throws `Input_error` as `Intrinsic_mesh` does.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Flat_development<TriangleMesh> develop_flat_metric(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double tol = choose_parameter(get_parameter(np, internal_np::curvature_tolerance), 1e-6);
  Flat_development<TriangleMesh> d(tm, internal::get_intrinsic_mesh(tm, np));
  const internal::Mesh_arrays<TriangleMesh>& m = d.im_.arrays();
  const std::vector<double>& K = d.im_.curvatures();
  const std::size_t nf = m.number_of_faces(), ne = m.number_of_edges(), nv = m.number_of_vertices();
  d.cone_index_.assign(nv, -1);
  for(std::size_t v = 0; v < nv; ++v) {
    if(m.is_isolated(int(v)) || m.is_boundary_vertex(int(v))) continue;
    if(std::abs(K[v]) > tol) { d.cone_index_[v] = int(d.cones_.size()); d.cones_.push_back(m.vertices[v]); }
    else d.flatness_error_ = (std::max)(d.flatness_error_, std::abs(K[v]));
  }
  // breadth-first layout, each component from a face without a cone corner if there is one
  d.corners_.assign(nf, std::array<Point_2, 3>());
  d.tree_.assign(ne, 0);
  std::vector<char> placed(nf, 0);
  auto has_cone = [&](int f) {
    int h = m.face_halfedge[std::size_t(f)];
    for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) if(d.cone_index_[std::size_t(m.source(h))] >= 0) return true;
    return false;
  };
  auto corner_of = [&](int f, int h) {   // the place of source(h) in face f's corner order
    int k = 0;
    for(int g = m.face_halfedge[std::size_t(f)]; g != h; g = m.next[std::size_t(g)]) ++k;
    return k;
  };
  std::vector<int> order;
  for(int pass = 0; pass < 2; ++pass)
    for(std::size_t s = 0; s < nf; ++s) {
      if(placed[s] || (pass == 0 && has_cone(int(s)))) continue;
      // pass 0 roots only cone-free faces; a component whose faces all touch cones is rooted in pass 1
      std::vector<int> queue(1, int(s));
      placed[s] = 1;
      d.corners_[s] = internal::canonical_layout(m, int(s));
      for(std::size_t q = 0; q < queue.size(); ++q) {
        const int f = queue[q];
        int h = m.face_halfedge[std::size_t(f)];
        for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
          const int g = m.face[std::size_t(h ^ 1)];
          if(g < 0 || placed[std::size_t(g)]) continue;
          placed[std::size_t(g)] = 1;
          d.tree_[std::size_t(h >> 1)] = 1;
          const int o = h ^ 1;   // in g: source(o) = target(h), target(o) = source(h)
          const std::array<Point_2, 3>& pf = d.corners_[std::size_t(f)];
          const int k = corner_of(f, h);
          const Point_2 p = pf[std::size_t((k + 1) % 3)], q2 = pf[std::size_t(k)];   // target(h), source(h)
          const int on = m.next[std::size_t(o)], op = m.next[std::size_t(on)];
          const Point_2 r = unfold_vertex(p, q2, m.edge_length(o), m.edge_length(on), m.edge_length(op));
          const int j = corner_of(g, o);
          std::array<Point_2, 3>& pg = d.corners_[std::size_t(g)];
          pg[std::size_t(j)] = p;
          pg[std::size_t((j + 1) % 3)] = q2;
          pg[std::size_t((j + 2) % 3)] = r;
          queue.push_back(g);
        }
      }
    }
  // the motion of every edge, from face(2e + 1) to face(2e), from the two layouts of its vertices
  d.motions_.assign(ne, Rigid_motion_2());
  auto position = [&](int f, int v) {
    int h = m.face_halfedge[std::size_t(f)];
    for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) if(m.source(h) == v) return d.corners_[std::size_t(f)][std::size_t(i)];
    return Point_2(0, 0);
  };
  double mean_length = 0;
  for(std::size_t e = 0; e < ne; ++e) mean_length += m.edge_length(int(2 * e)) / double(ne);
  std::vector<int> degree(nv, 0);
  d.cut_.assign(ne, 0);
  for(std::size_t e = 0; e < ne; ++e) {
    const int fb = m.face[2 * e], fa = m.face[2 * e + 1];
    if(fa < 0 || fb < 0 || d.tree_[e]) continue;
    const int a = m.source(int(2 * e)), b = m.target[2 * e];
    const Point_2 pa = position(fa, a), qa = position(fa, b), pb = position(fb, a), qb = position(fb, b);
    Rigid_motion_2 r;
    r.rotation = internal::wrap_angle(std::atan2(qb.y() - pb.y(), qb.x() - pb.x()) - std::atan2(qa.y() - pa.y(), qa.x() - pa.x()));
    r.translation = Vector_2(0, 0);
    const Point_2 ra = r(pa), rq = r(qa);   // the translation: the mean over both vertices
    r.translation = Vector_2(0.5 * ((pb.x() - ra.x()) + (qb.x() - rq.x())), 0.5 * ((pb.y() - ra.y()) + (qb.y() - rq.y())));
    d.motions_[e] = r;
    d.cut_[e] = 1;
    ++degree[std::size_t(a)];
    ++degree[std::size_t(b)];
  }
  // prune dangling cut edges at flat interior vertices
  std::vector<int> stack;
  for(std::size_t v = 0; v < nv; ++v)
    if(degree[v] == 1 && d.cone_index_[v] < 0 && !m.is_boundary_vertex(int(v))) stack.push_back(int(v));
  while(!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    if(degree[std::size_t(v)] != 1) continue;
    int h = m.vertex_out[std::size_t(v)];
    const int h0 = h;
    do {
      const int e = h >> 1;
      if(d.cut_[std::size_t(e)]) {
        d.cut_[std::size_t(e)] = 0;
        const Rigid_motion_2& r = d.motions_[std::size_t(e)];
        d.pruned_motion_ = (std::max)(d.pruned_motion_, (std::max)(std::abs(r.rotation), std::sqrt(r.translation.squared_length()) / mean_length));
        --degree[std::size_t(v)];
        const int u = m.target[std::size_t(h)];
        if(--degree[std::size_t(u)] == 1 && d.cone_index_[std::size_t(u)] < 0 && !m.is_boundary_vertex(u)) stack.push_back(u);
        break;
      }
      h = m.ccw_out(h);
    } while(h != h0);
  }
  for(char c : d.cut_) d.cut_edges_ += c != 0;
  return d;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_FLAT_DEVELOPMENT_H
