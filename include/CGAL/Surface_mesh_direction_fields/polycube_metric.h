// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H

// Metric compensation by a polycube (Lai et al. 2010, section 4.1.3.2) for the simplest
// polycube, a box: a genus-0 surface with eight corner vertices is cut along paths between
// them into the six faces of a box, each face mapped onto a rectangle, and the metric is that
// of the box, whose holonomy lies in the square grid's symmetry group.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>

#include <CGAL/boost/graph/helpers.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of box_polycube_metric().
struct Polycube_metric_status
{
  bool success = false;
  std::string message;                         ///< empty on success
  std::array<double, 3> dimensions{{0, 0, 0}}; ///< the box's side lengths (multiples of the edge length)
  std::size_t path_edges = 0;                  ///< mesh edges on the twelve paths between the corners
  /// the largest ratio, over the box's twelve edges, between the path's length on the surface
  /// and the box edge it is mapped to (1: no stretch along the cut)
  double max_path_stretch = 0;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Metric compensation with a box (Lai et al. 2010, section 4.1.3.2, for the polycube with one
/// cube): the eight `corners` of a closed genus-0 mesh (corner \f$i\f$ goes to the box corner
/// \f$(i \& 1, (i \gg 1) \& 1, (i \gg 2) \& 1)\f$) are joined by the twelve shortest edge paths
/// of the box's edges (Dijkstra on the edge lengths, each path avoiding the earlier ones and
/// the other corners; lengths of the metric of `edge_length_map`, for Lai et al. the flat cone
/// metric with cones of \f$\pi/2\f$ at the corners), which cut the mesh into six disks; each disk is mapped onto its face of
/// the box by a Tutte embedding with mean value weights (Floater 2003: bijective onto the convex
/// rectangle), its boundary placed by arc length along the four paths. The box's sides are the
/// mean lengths of its four parallel paths, rounded to multiples of `edge_length`. The output
/// metric (`lengths`, on `tm`'s triangulation) is the box's: flat but for cones of \f$\pi/2\f$ at
/// the corners, with cut-graph motions that are symmetries of the square grid of edge length
/// `edge_length`, so tessellate_flat_metric() accepts it.
///
/// Departure from the paper: Lai et al. flatten each disk to a rectangle by Ricci flow with
/// corner curvatures \f$\pi/2\f$ and then scale the rectangles; the two sides of a path then
/// disagree on where its vertices go. Placing each path once by arc length and embedding the
/// disks with fixed boundaries keeps the sides consistent by construction.
///
/// Named parameters: `edge_length_map` (the metric of the path lengths and of the angles of the
/// mean value weights; default: Euclidean lengths) or `intrinsic_mesh`, and the index maps. Failures (a path that cannot avoid the earlier ones, disks that do not match
/// the box's faces, a degenerate triangle) are in the status.
template <typename TriangleMesh, typename EdgeLengthMap, typename NamedParameters = parameters::Default_named_parameters>
Polycube_metric_status box_polycube_metric(const TriangleMesh& tm,
                                           const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 8>& corners,
                                           double edge_length, EdgeLengthMap lengths,
                                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Polycube_metric_status st;
  if(!(edge_length > 0) || !std::isfinite(edge_length))
    throw Input_error(Input_error::INVALID_ARGUMENT, "the edge length must be positive, got " + std::to_string(edge_length));
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  const internal::Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1 || !topo.loops.empty() || nv + nf != ne + 2)
    throw Input_error(Input_error::INVALID_ARGUMENT, "box_polycube_metric() needs a closed connected mesh of genus 0");
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  typedef std::array<double, 3> V3;
  auto point = [&](int v) {
    const auto& p = get(vpm, m.vertices[std::size_t(v)]);
    return V3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  auto dist = [](const V3& a, const V3& b) { return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2])); };
  std::array<int, 8> c;
  std::vector<int> corner_of(nv, -1);
  for(int i = 0; i < 8; ++i) {
    c[std::size_t(i)] = m.vertex_index(corners[std::size_t(i)]);
    if(c[std::size_t(i)] < 0 || m.is_isolated(c[std::size_t(i)]) || corner_of[std::size_t(c[std::size_t(i)])] >= 0)
      throw Input_error(Input_error::INVALID_ARGUMENT, "box corners must be eight distinct vertices of the mesh");
    corner_of[std::size_t(c[std::size_t(i)])] = i;
  }
  // 1. the twelve box edges (corners differing in one bit), shortest first, as disjoint paths
  std::vector<std::array<int, 2>> box_edges;
  for(int i = 0; i < 8; ++i)
    for(int b = 0; b < 3; ++b) if(!(i & (1 << b))) box_edges.push_back({{i, i | (1 << b)}});
  std::vector<char> used;           // vertices inside earlier paths
  std::vector<int> path_of_edge;    // per mesh edge: the box edge whose path it is on
  std::vector<std::vector<int>> paths(12);   // vertex sequences, from the lower corner to the upper
  std::vector<std::vector<double>> steps(12);  // the metric's lengths of their edges
  // paths in three orders until one lets every path avoid the earlier ones: shortest first,
  // longest first, then the twelve edges grouped by axis
  for(int attempt = 0; attempt < 3; ++attempt) {
  if(attempt < 2)
    std::stable_sort(box_edges.begin(), box_edges.end(), [&](const std::array<int, 2>& x, const std::array<int, 2>& y) {
      const double dx = dist(point(c[std::size_t(x[0])]), point(c[std::size_t(x[1])])), dy = dist(point(c[std::size_t(y[0])]), point(c[std::size_t(y[1])]));
      return attempt == 0 ? dx < dy : dx > dy;
    });
  else
    std::stable_sort(box_edges.begin(), box_edges.end(), [](const std::array<int, 2>& x, const std::array<int, 2>& y) { return (x[0] ^ x[1]) < (y[0] ^ y[1]); });
  used.assign(nv, 0);
  path_of_edge.assign(ne, -1);
  st.path_edges = 0;
  st.message.clear();
  for(std::size_t k = 0; k < box_edges.size() && st.message.empty(); ++k) {
    const int s = c[std::size_t(box_edges[k][0])], t = c[std::size_t(box_edges[k][1])];
    std::vector<double> d(nv, std::numeric_limits<double>::infinity());
    std::vector<int> from(nv, -1);
    typedef std::pair<double, int> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    d[std::size_t(s)] = 0;
    queue.push({0., s});
    while(!queue.empty()) {
      const Item it = queue.top();
      queue.pop();
      if(it.first > d[std::size_t(it.second)] || it.second == t) continue;
      const int v = it.second;
      const int h0 = m.vertex_out[std::size_t(v)];
      int h = h0;
      do {
        const int u = m.target[std::size_t(h)];
        const bool blocked = used[std::size_t(u)] || (corner_of[std::size_t(u)] >= 0 && u != t) || path_of_edge[std::size_t(h >> 1)] >= 0;
        const double du = d[std::size_t(v)] + m.edge_length(h);
        if(!blocked && du < d[std::size_t(u)]) { d[std::size_t(u)] = du; from[std::size_t(u)] = h; queue.push({du, u}); }
        h = m.ccw_out(h);
      } while(h != h0);
    }
    if(from[std::size_t(t)] < 0) {
      std::ostringstream os;
      os << "no path from corner " << box_edges[k][0] << " (vertex " << s << ") to corner " << box_edges[k][1] << " (vertex " << t
         << ") avoids the earlier paths (place the corners farther apart, or refine the mesh)";
      st.message = os.str();
      break;
    }
    std::vector<int> p(1, t);
    std::vector<double> len;
    for(int v = t; v != s;) {
      const int h = from[std::size_t(v)];
      path_of_edge[std::size_t(h >> 1)] = int(k);
      ++st.path_edges;
      len.push_back(m.edge_length(h));
      v = m.source(h);
      p.push_back(v);
    }
    std::reverse(p.begin(), p.end());
    std::reverse(len.begin(), len.end());
    steps[k] = len;
    for(std::size_t i = 1; i + 1 < p.size(); ++i) used[std::size_t(p[i])] = 1;
    paths[k] = p;
  }
  if(st.message.empty()) break;
  }
  if(!st.message.empty()) return st;
  // 2. the six disks: faces connected without crossing a path
  std::vector<int> region(nf, -1);
  int regions = 0;
  for(std::size_t f0 = 0; f0 < nf; ++f0) {
    if(region[f0] >= 0) continue;
    std::vector<int> stack(1, int(f0));
    region[f0] = regions;
    while(!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      int h = m.face_halfedge[std::size_t(f)];
      for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
        const int g = m.face[std::size_t(h ^ 1)];
        if(g >= 0 && region[std::size_t(g)] < 0 && path_of_edge[std::size_t(h >> 1)] < 0) { region[std::size_t(g)] = regions; stack.push_back(g); }
      }
    }
    ++regions;
  }
  if(regions != 6) {
    st.message = "the twelve paths cut the mesh into " + std::to_string(regions) + " pieces, not the six faces of a box";
    return st;
  }
  // each disk's face of the box: the axis on which its four corners agree
  std::vector<std::array<int, 2>> face_of(6, {{-1, -1}});   // (axis, side)
  std::vector<int> corner_mask(6, 0);
  for(std::size_t h = 0; h < m.number_of_halfedges(); ++h) {
    const int f = m.face[h];
    if(f < 0) continue;
    const int v = m.source(int(h));
    if(corner_of[std::size_t(v)] >= 0) corner_mask[std::size_t(region[std::size_t(f)])] |= 1 << corner_of[std::size_t(v)];
  }
  for(int r = 0; r < 6; ++r) {
    for(int axis = 0; axis < 3; ++axis)
      for(int side = 0; side < 2; ++side) {
        int mask = 0;
        for(int i = 0; i < 8; ++i) if(((i >> axis) & 1) == side) mask |= 1 << i;
        if(mask == corner_mask[std::size_t(r)]) face_of[std::size_t(r)] = {{axis, side}};
      }
    if(face_of[std::size_t(r)][0] < 0) {
      st.message = "a piece cut by the paths does not have the four corners of a box face (the corners are not placed like a box's)";
      return st;
    }
  }
  // 3. box dimensions: mean path length per axis, in multiples of the edge length
  double total[3] = {0, 0, 0};
  for(std::size_t k = 0; k < 12; ++k) {
    const int axis = box_edges[k][0] ^ box_edges[k][1];
    double L = 0;
    for(double x : steps[k]) L += x;
    total[axis == 1 ? 0 : axis == 2 ? 1 : 2] += L / 4;
  }
  for(int a = 0; a < 3; ++a) st.dimensions[std::size_t(a)] = edge_length * (std::max)(1., std::round(total[a] / edge_length));
  auto corner_position = [&](int i) { return V3{{(i & 1) * st.dimensions[0], ((i >> 1) & 1) * st.dimensions[1], ((i >> 2) & 1) * st.dimensions[2]}}; };
  // the box position of every path vertex, by arc length
  std::vector<V3> box(nv, V3{{0, 0, 0}});
  std::vector<char> fixed(nv, 0);
  for(int i = 0; i < 8; ++i) { box[std::size_t(c[std::size_t(i)])] = corner_position(i); fixed[std::size_t(c[std::size_t(i)])] = 1; }
  for(std::size_t k = 0; k < 12; ++k) {
    const std::vector<int>& p = paths[k];
    std::vector<double> s(p.size(), 0.);
    for(std::size_t i = 1; i < p.size(); ++i) s[i] = s[i - 1] + steps[k][i - 1];
    const V3 a = corner_position(box_edges[k][0]), b = corner_position(box_edges[k][1]);
    st.max_path_stretch = (std::max)(st.max_path_stretch, (std::max)(s.back() / dist(a, b), dist(a, b) / s.back()));
    for(std::size_t i = 1; i + 1 < p.size(); ++i) {
      const double t = s[i] / s.back();
      for(int j = 0; j < 3; ++j) box[std::size_t(p[i])][std::size_t(j)] = (1 - t) * a[std::size_t(j)] + t * b[std::size_t(j)];
      fixed[std::size_t(p[i])] = 1;
    }
  }
  // 4. every disk onto its face: Tutte embedding with mean value weights, boundary fixed
  std::vector<int> vertex_region(nv, -1);
  for(std::size_t h = 0; h < m.number_of_halfedges(); ++h)
    if(m.face[h] >= 0 && !fixed[std::size_t(m.source(int(h)))]) vertex_region[std::size_t(m.source(int(h)))] = region[std::size_t(m.face[h])];
  for(int r = 0; r < 6; ++r) {
    const int axis = face_of[std::size_t(r)][0], side = face_of[std::size_t(r)][1];
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    std::vector<int> column(nv, -1), unknowns;
    for(std::size_t v = 0; v < nv; ++v) if(vertex_region[v] == r) { column[v] = int(unknowns.size()); unknowns.push_back(int(v)); }
    if(!unknowns.empty()) {
      const int n = int(unknowns.size());
      std::vector<Eigen::Triplet<double>> t;
      Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, 2);
      for(int i = 0; i < n; ++i) {
        const int v = unknowns[std::size_t(i)];
        double sum = 0;
        const int h0 = m.vertex_out[std::size_t(v)];
        int h = h0;
        do {   // mean value weight of edge (v, q): (tan(a/2) + tan(b/2)) / |vq|, a and b the metric's angles at v beside it
          const int q = m.target[std::size_t(h)];
          const double wgt = (std::tan(0.5 * m.angle[std::size_t(h)]) + std::tan(0.5 * m.angle[std::size_t(m.next[std::size_t(h ^ 1)])])) /
                             (std::max)(m.edge_length(h), 1e-300);
          sum += wgt;
          if(column[std::size_t(q)] >= 0) t.emplace_back(i, column[std::size_t(q)], -wgt);
          else {
            const V3& bq = box[std::size_t(q)];
            b(i, 0) += wgt * bq[std::size_t(u)];
            b(i, 1) += wgt * bq[std::size_t(w)];
          }
          h = m.ccw_out(h);
        } while(h != h0);
        t.emplace_back(i, i, sum);
      }
      Eigen::SparseMatrix<double> A(n, n);
      A.setFromTriplets(t.begin(), t.end());
      Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
      lu.compute(A);
      if(lu.info() != Eigen::Success) { st.message = "the Tutte embedding of a box face could not be factored"; return st; }
      const Eigen::MatrixXd x = lu.solve(b);
      for(int i = 0; i < n; ++i) {
        V3& p = box[std::size_t(unknowns[std::size_t(i)])];
        p[std::size_t(axis)] = side * st.dimensions[std::size_t(axis)];
        p[std::size_t(u)] = x(i, 0);
        p[std::size_t(w)] = x(i, 1);
      }
    }
  }
  // 5. the metric of the box, and its validity: every triangle non-degenerate, all on the same
  // side of their faces (the corners may be given mirrored: the lengths do not see it)
  std::size_t positive = 0, negative = 0;
  for(std::size_t f = 0; f < nf; ++f) {
    const int r = region[f], axis = face_of[std::size_t(r)][0], side = face_of[std::size_t(r)][1];
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    const int h0 = m.face_halfedge[f];
    const V3 &a = box[std::size_t(m.source(h0))], &b = box[std::size_t(m.target[std::size_t(h0)])], &cc = box[std::size_t(m.target[std::size_t(m.next[std::size_t(h0)])])];
    const double area = (b[std::size_t(u)] - a[std::size_t(u)]) * (cc[std::size_t(w)] - a[std::size_t(w)]) -
                        (cc[std::size_t(u)] - a[std::size_t(u)]) * (b[std::size_t(w)] - a[std::size_t(w)]);
    const double orient = side == 1 ? area : -area;   // the outward normal is +axis on side 1
    if(!(std::abs(orient) > 1e-12 * edge_length * edge_length)) {
      st.message = "face " + std::to_string(f) + " is degenerate on the box (refine the mesh near the paths)";
      return st;
    }
    (orient > 0 ? positive : negative) += 1;
  }
  if(positive && negative) {
    st.message = std::to_string((std::min)(positive, negative)) + " faces fold over on the box (the paths meet the corners in the wrong order)";
    return st;
  }
  for(std::size_t e = 0; e < ne; ++e) put(lengths, m.edges[e], dist(box[std::size_t(m.source(int(2 * e)))], box[std::size_t(m.target[2 * e])]));
  st.success = true;
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H
