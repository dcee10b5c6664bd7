// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEGMENT_RICCI_FLOW_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEGMENT_RICCI_FLOW_H

// Step 3 of Lai et al.'s metric compensation (2010, section 4.1.3.2): every segment (a piece of
// the surface cut along P's edges) flattened by Ricci flow to its polygon of P, with boundary
// curvature pi minus the polygon's angle at P's corners and 0 elsewhere on its boundary, which
// makes the segment a polygon with those angles and straight sides. What the charts take from
// it is where each path vertex lies along its side: the Ricci metric's arc length along the side
// over the side's length. The two segments beside a path give two such parameters.

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/polyhedron_paths.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Per P edge k and side s (0: the face that runs along it from pedges[k][0], 1: the other one),
// the parameter in [0, 1] of every vertex of paths[k] along the edge, from pedges[k][0].
typedef std::vector<std::array<std::vector<double>, 2>> Side_parameters;

// Flattens segment j (the piece of P's face j) by Ricci flow and writes the parameters of its
// sides to `sides`. `corner_vertex[c]` is the mesh vertex of P's corner c, `shape[j]` the face's
// polygon (its angles are the targets). Returns false
// with `message` if the segment is not a manifold disk or the flow does not converge.
template <typename TM>
bool ricci_flow_segment(const Mesh_arrays<TM>& m, const std::vector<int>& corner_vertex, const Polyhedron_cut& cut, const std::vector<std::vector<int>>& pfaces,
                        const std::vector<std::vector<Point_2>>& shape, std::size_t j, Side_parameters& sides, std::string& message)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Segment;
  typedef Segment::Vertex_index SV;
  const int r = cut.region_of_face[j];
  const std::vector<int>& fc = pfaces[j];
  const std::string which = "the Ricci flow of segment " + std::to_string(j) + " (face " + std::to_string(j) + " of the polyhedron)";
  // the segment as a mesh of its own; vertex ids in the mesh <-> in the segment
  Segment seg;
  std::vector<int> global;
  std::vector<int> local(m.number_of_vertices(), -1);   // per piece: O(nv) once, against six flows
  auto vertex = [&](int v) {
    if(local[std::size_t(v)] < 0) { local[std::size_t(v)] = int(global.size()); global.push_back(v); seg.add_vertex(); }
    return SV(Segment::size_type(local[std::size_t(v)]));
  };
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    if(cut.region[f] != r) continue;
    const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)];
    const SV a = vertex(m.source(h0)), b = vertex(m.target[std::size_t(h0)]), c = vertex(m.target[std::size_t(h1)]);
    if(seg.add_face(a, b, c) == Segment::null_face()) { message = which + ": the segment is not a manifold disk"; return false; }
  }
  // its lengths (the mesh's metric) and targets: pi minus the polygon's angle at P's corners
  auto length = seg.add_property_map<Segment::Edge_index, double>("e:length", 0.).first;
  auto target = seg.add_property_map<SV, double>("v:target", 0.).first;
  auto u = seg.add_property_map<SV, double>("v:u", 0.).first;
  auto ricci = seg.add_property_map<Segment::Edge_index, double>("e:ricci", 0.).first;
  auto mesh_halfedge = [&](int a, int b) {   // the mesh's halfedge from vertex a to b
    const int h0 = m.vertex_out[std::size_t(a)];
    int h = h0;
    do {
      if(m.target[std::size_t(h)] == b) return h;
      if(m.is_border(h)) break;
      h = m.ccw_out(h);
    } while(h != h0);
    return -1;
  };
  for(auto e : seg.edges()) {
    const auto h = seg.halfedge(e);
    const int g = mesh_halfedge(global[std::size_t(seg.source(h))], global[std::size_t(seg.target(h))]);
    if(g < 0) { message = which + ": an edge of the segment is not an edge of the mesh"; return false; }
    length[e] = m.edge_length(g);
  }
  for(std::size_t i = 0; i < fc.size(); ++i) {
    const std::size_t n = fc.size();
    const Point_2 &p = shape[j][(i + n - 1) % n], &q = shape[j][i], &s = shape[j][(i + 1) % n];
    const double angle = std::atan2((p.x() - q.x()) * (s.y() - q.y()) - (p.y() - q.y()) * (s.x() - q.x()),
                                    (p.x() - q.x()) * (s.x() - q.x()) + (p.y() - q.y()) * (s.y() - q.y()));
    const int c = local[std::size_t(corner_vertex[std::size_t(fc[i])])];
    if(c < 0) { message = which + ": a corner of the polyhedron is not on the segment"; return false; }
    target[SV(Segment::size_type(c))] = CGAL_PI - std::abs(angle);
  }
  Cone_metric_status st;
  try {
    st = compute_cone_metric(seg, target, ricci, parameters::edge_length_map(length).conformal_factor_map(u).curvature_tolerance(1e-10));
  } catch(const Input_error& e) {
    message = which + ": " + e.what();
    return false;
  }
  if(!st.converged) { message = which + " did not converge: " + st.message; return false; }
  // the sides: arc length of the Ricci metric along each (its boundary edges are never flipped:
  // length l e^((u_a + u_b) / 2))
  for(std::size_t i = 0; i < fc.size(); ++i) {
    const int a = fc[i], b = fc[(i + 1) % fc.size()];
    const std::size_t k = std::size_t(cut.edge_of(a, b));
    const bool forward = cut.pedges[k][0] == a;
    const std::vector<int>& path = cut.paths[k];
    std::vector<double>& t = sides[k][forward ? 0 : 1];
    t.assign(path.size(), 0.);
    for(std::size_t q = 1; q < path.size(); ++q) {
      const int x = path[q - 1], y = path[q];
      if(local[std::size_t(x)] < 0 || local[std::size_t(y)] < 0) { message = which + ": a path of its side is not on the segment"; return false; }
      const double ux = u[SV(Segment::size_type(local[std::size_t(x)]))], uy = u[SV(Segment::size_type(local[std::size_t(y)]))];
      t[q] = t[q - 1] + m.edge_length(cut.path_halfedges[k][q - 1]) * std::exp(0.5 * (ux + uy));
    }
    const double total = t.back();
    if(!(total > 0)) { message = which + ": a side has length 0"; return false; }
    for(double& x : t) x /= total;
  }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEGMENT_RICCI_FLOW_H
