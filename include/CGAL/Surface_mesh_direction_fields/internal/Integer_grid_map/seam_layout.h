// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAM_LAYOUT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAM_LAYOUT_H

// The combinatorial half of integer_grid_map() (integer_grid_map.h): the cross field combed
// along a tree of faces, its matching and singularities, the cut graph and its arcs, and on open
// meshes the boundary's corners and straight runs; plus the affine corner expressions the map's
// unknowns are written in.

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>

#include <cmath>
#include <complex>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

typedef std::complex<double> Cplx;

// i^k
inline Cplx unit_power(int k)
{
  switch(((k % 4) + 4) % 4) {
    case 0: return Cplx(1, 0);
    case 1: return Cplx(0, 1);
    case 2: return Cplx(-1, 0);
    default: return Cplx(0, -1);
  }
}

// A corner's image as an affine function of the unknowns: coefficient `a` times the vertex
// unknown plus sum c_k s_k over small unknowns (seam translations, singularity positions).
struct Corner_expression
{
  int vertex = -1;                    // big unknown (-1: none, e.g. a singularity's own corner)
  Cplx a = Cplx(1, 0);
  std::vector<std::pair<int, Cplx>> small;

  void add(int k, Cplx c)
  {
    for(auto& s : small) if(s.first == k) { s.second += c; return; }
    small.emplace_back(k, c);
  }
  // this expression mapped by P -> m P + t_k (t_k the small unknown k, scaled by tc)
  Corner_expression mapped(Cplx m, int k, Cplx tc) const
  {
    Corner_expression e = *this;
    e.a *= m;
    for(auto& s : e.small) s.second *= m;
    if(k >= 0) e.add(k, tc);
    return e;
  }
};


// What lay_out_seams() finds; per edge e, halfedge 2e crosses from face(2e + 1) into face(2e).
struct Seam_layout
{
  std::vector<double> theta;        // per face: the field combed (its direction angle)
  std::vector<int> r;               // per edge: the matching, quarter turns
  std::vector<int> turns;           // per vertex: quarter turns around it (modulo 4 meaningful)
  std::vector<char> singular;       // per vertex: an interior singularity
  std::vector<char> cut;            // per edge: on the cut graph (a seam)
  std::vector<int> degree;          // per vertex: its cut edges
  std::vector<int> arc;             // per edge: its arc, -1 off the cut graph
  std::vector<char> arc_forward;    // per edge: halfedge 2e runs along its arc
  std::vector<int> arc_q;           // per arc: image on its left = i^q image on its right + t
  int narcs = 0;
  std::size_t cut_edges = 0;
  std::vector<char> boundary_corner;   // per vertex: the boundary turns there under the metric
  std::vector<int> turn_quarters;      // per boundary corner: its turning, quarter turns
  std::vector<Cplx> border_dir;        // per border edge: its direction in its face's target frame
  std::vector<int> line_of;            // per border edge: its straight run (grid line)
  int nlines = 0;
};

// Fills s from the field `theta` (per face, in the faces' frames of m's metric). False, with a
// message, when the field's matching changes along a seam between regular vertices or the field
// does not follow the boundary.
template <typename TM>
bool lay_out_seams(const Mesh_arrays<TM>& m, const Topology_arrays& topo, std::vector<double> theta, Seam_layout& s, std::string& message)
{
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  const double quarter = CGAL_PI / 2;
  // 1. the field combed along a breadth-first tree of the faces: matching 0 across tree edges
  std::vector<char> tree_edge(ne, 0), seen(nf, 0);
  std::vector<int> queue{0};
  seen[0] = 1;
  for(std::size_t q = 0; q < queue.size(); ++q) {
    int x = m.face_halfedge[std::size_t(queue[q])];
    for(int i = 0; i < 3; ++i, x = m.next[std::size_t(x)]) {
      const int g = m.face[std::size_t(x ^ 1)];
      if(g < 0 || seen[std::size_t(g)]) continue;
      seen[std::size_t(g)] = 1;
      tree_edge[std::size_t(x >> 1)] = 1;
      // the field carried into g, and g's direction nearest to it
      const double carried = theta[std::size_t(queue[q])] + internal::transport_increment(m, x ^ 1);
      theta[std::size_t(g)] += quarter * std::round((carried - theta[std::size_t(g)]) / quarter);
      queue.push_back(g);
    }
  }
  // matching r_e: crossing from face(2e+1) into face(2e), theta_L = theta_R + transport + r pi/2
  std::vector<int>& r = s.r;
  r.assign(ne, 0);
  for(std::size_t e = 0; e < ne; ++e) {
    if(tree_edge[e] || m.face[2 * e] < 0 || m.face[2 * e + 1] < 0) continue;   // border edges: no matching
    const double d = theta[std::size_t(m.face[2 * e])] - theta[std::size_t(m.face[2 * e + 1])] - internal::transport_increment(m, int(2 * e));
    r[e] = int(std::lround(d / quarter));
  }
  // 2. the cut graph: the edges the tree does not cross, pruned of branches to regular vertices
  std::vector<int>& turns = s.turns;   // quarter turns of the rotation around each vertex
  turns.assign(nv, 0);
  for(std::size_t e = 0; e < ne; ++e) {
    // around the source of halfedge 2e counterclockwise, the walk crosses from face(2e) ... the
    // sign only matters modulo 4 for the test below; the exact rotation comes from the walk
    turns[std::size_t(m.source(int(2 * e)))] += r[e];
    turns[std::size_t(m.target[2 * e])] -= r[e];
  }
  std::vector<char>& singular = s.singular;
  singular.assign(nv, 0);
  for(std::size_t v = 0; v < nv; ++v)
    singular[v] = !m.is_isolated(int(v)) && !m.is_boundary_vertex(int(v)) && ((turns[v] % 4) + 4) % 4 != 0;
  std::vector<char>& cut = s.cut;
  std::vector<int>& degree = s.degree;
  cut.assign(ne, 0);
  degree.assign(nv, 0);
  for(std::size_t e = 0; e < ne; ++e)
    if(!tree_edge[e] && m.face[2 * e] >= 0 && m.face[2 * e + 1] >= 0) { cut[e] = 1; ++degree[std::size_t(m.source(int(2 * e)))]; ++degree[std::size_t(m.target[2 * e])]; }
  {
    std::vector<int> leaves;
    // a seam that reaches the boundary stays: it ends there
    auto prunable = [&](int v) { return !singular[std::size_t(v)] && !m.is_boundary_vertex(v); };
    for(std::size_t v = 0; v < nv; ++v) if(degree[v] == 1 && prunable(int(v))) leaves.push_back(int(v));
    while(!leaves.empty()) {
      const int v = leaves.back();
      leaves.pop_back();
      if(degree[std::size_t(v)] != 1) continue;
      // its one cut edge
      int x = m.vertex_out[std::size_t(v)], x0 = x;
      do { if(cut[std::size_t(x >> 1)]) break; x = m.ccw_out(x); } while(x != x0);
      cut[std::size_t(x >> 1)] = 0;
      degree[std::size_t(v)] = 0;
      const int w = m.target[std::size_t(x)];
      if(--degree[std::size_t(w)] == 1 && prunable(w)) leaves.push_back(w);
    }
  }
  for(std::size_t e = 0; e < ne; ++e) s.cut_edges += cut[e];
  // 3. arcs: chains of cut edges between nodes (degree != 2 or singular); one small unknown each
  std::vector<int>& arc = s.arc;
  arc.assign(ne, -1);
  std::vector<char>& arc_forward = s.arc_forward;   // halfedge 2e runs along its arc
  arc_forward.assign(ne, 1);
  int& narcs = s.narcs;
  auto is_node = [&](int v) { return degree[std::size_t(v)] != 2 || singular[std::size_t(v)] || m.is_boundary_vertex(v); };
  auto next_cut_out = [&](int x) {   // at target(x), the other cut edge (degree-2 vertex)
    const int v = m.target[std::size_t(x)];
    int y = m.vertex_out[std::size_t(v)], y0 = y;
    do { if(cut[std::size_t(y >> 1)] && (y >> 1) != (x >> 1)) return y; y = m.ccw_out(y); } while(y != y0);
    return -1;
  };
  auto trace = [&](int x) {   // an arc from halfedge x
    for(;;) {
      arc[std::size_t(x >> 1)] = narcs;
      arc_forward[std::size_t(x >> 1)] = (x & 1) == 0;
      if(is_node(m.target[std::size_t(x)])) break;
      x = next_cut_out(x);
      if(x < 0 || arc[std::size_t(x >> 1)] >= 0) break;
    }
    ++narcs;
  };
  for(std::size_t v = 0; v < nv; ++v) {
    if(!is_node(int(v)) || degree[v] == 0) continue;
    int x = m.vertex_out[v], x0 = x;
    do { if(cut[std::size_t(x >> 1)] && arc[std::size_t(x >> 1)] < 0) trace(x); x = m.ccw_out(x); } while(x != x0);
  }
  for(std::size_t e = 0; e < ne; ++e)   // closed loops without a node (a cut graph that is one circle)
    if(cut[e] && arc[e] < 0) trace(int(2 * e));
  // per arc its rotation q: image on its left = i^q image on its right + t
  std::vector<int>& arc_q = s.arc_q;
  arc_q.assign(std::size_t(narcs), 0);
  std::vector<char> arc_q_set(std::size_t(narcs), 0);
  for(std::size_t e = 0; e < ne; ++e) {
    if(!cut[e]) continue;
    // across e from face(2e+1) (R) into face(2e) (L): P_L = i^{-r} P_R + t
    const int q = arc_forward[e] ? -r[e] : r[e];
    const std::size_t a = std::size_t(arc[e]);
    if(!arc_q_set[a]) { arc_q[a] = q; arc_q_set[a] = 1; }
    else if(((arc_q[a] - q) % 4 + 4) % 4 != 0) {
      message = "the field's matching changes along a seam between two regular vertices (a singularity the cut graph misses)";
      return false;
    }
  }
  // 4. the boundary (open meshes): corners where it turns under the metric, and each border
  // edge's direction in its face's target frame (the field rotated onto U: a power of i)
  std::vector<char>& bcorner = s.boundary_corner;
  std::vector<int>& turn_quarters = s.turn_quarters;
  bcorner.assign(nv, 0);
  turn_quarters.assign(nv, 0);
  for(std::size_t v = 0; v < nv; ++v) {
    if(!m.is_boundary_vertex(int(v))) continue;
    double sum = 0;
    int x = m.vertex_out[v];
    for(;;) {
      sum += m.angle[std::size_t(x)];
      const int y = m.ccw_out(x);
      if(m.face[std::size_t(y)] < 0) break;
      x = y;
    }
    const double turning = CGAL_PI - sum;
    if(std::abs(turning) > quarter / 2) { bcorner[v] = 1; turn_quarters[v] = int(std::lround(turning / quarter)); }
  }
  std::vector<Cplx>& border_dir = s.border_dir;   // per border edge, its direction in the frame of its face
  border_dir.assign(ne, Cplx(0, 0));
  for(const auto& loop : topo.loops)
    for(int b : loop) {
      const int x = b ^ 1;   // the edge's halfedge in its face
      const double a = internal::halfedge_direction(m, x) - theta[std::size_t(m.face[std::size_t(x)])];
      const double k = std::round(a / quarter);
      if(std::abs(a - k * quarter) > 1e-3) {
        message = "the field is not aligned with the boundary at edge " + std::to_string(x >> 1) + " (" + std::to_string(std::abs(a - k * quarter)) +
                     " rad off): an open mesh needs a cross field that follows its boundary";
        return false;
      }
      border_dir[std::size_t(x >> 1)] = unit_power(int(k));
    }
  // boundary lines: runs of border edges between corners and seam ends, one small unknown each
  std::vector<int>& line_of = s.line_of;
  line_of.assign(ne, -1);
  int& nlines = s.nlines;
  for(const auto& loop : topo.loops) {
    const std::size_t n = loop.size();
    auto breaks = [&](int b) {   // the run stops at the source of border halfedge b
      const int v = m.target[std::size_t(b ^ 1)];
      return bcorner[std::size_t(v)] || degree[std::size_t(v)] > 0;
    };
    std::size_t first = 0;
    while(first < n && !breaks(loop[first])) ++first;
    if(first == n) first = 0;   // a loop with neither corner nor seam: one line
    for(std::size_t i = 0; i < n; ++i) {
      const int b = loop[(first + i) % n];
      if(i == 0 || breaks(b)) ++nlines;
      line_of[std::size_t(b >> 1)] = nlines - 1;
    }
  }
  s.theta = std::move(theta);
  return true;
}

// The map's unknowns and what ties them (write_corner_expressions()): small unknowns 0..narcs-1
// the arcs' translations, then the boundary lines, then one position per singularity and per
// boundary corner; big unknowns the other vertices, complex inside, real along its line on the
// boundary (big_dir != 0); every corner an affine expression in them.
struct Corner_layout
{
  struct Closing { std::vector<std::pair<int, Cplx>> t; };                  // sum c_k s_k = 0
  struct Line_condition { std::vector<std::pair<int, Cplx>> t; int line; };   // Im(sum t) = Re(line)
  std::vector<int> sing_index, big;   // per vertex: its small unknown (a point), its big one
  std::vector<Cplx> big_dir;          // per big unknown: 0 (complex) or its line's direction (real)
  int nsmall = 0, nbig = 0;
  std::vector<Corner_expression> corner;   // per halfedge with a face: the corner at its source
  std::vector<Closing> closings;
  std::vector<Line_condition> line_conditions;
};

// Fills c from the seams. False, with a message, when the field turns around a vertex the seams
// found regular or the boundary turns by an angle off the grid's at a vertex that is no corner.
template <typename TM>
bool write_corner_expressions(const Mesh_arrays<TM>& m, const Topology_arrays& topo, const Seam_layout& seams, Corner_layout& c, std::string& message)
{
  typedef Corner_expression Expr;
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges();
  const std::vector<char>& singular = seams.singular;
  const std::vector<char>& cut = seams.cut;
  const std::vector<int>& arc = seams.arc;
  const std::vector<char>& arc_forward = seams.arc_forward;
  const std::vector<int>& arc_q = seams.arc_q;
  const int narcs = seams.narcs, nlines = seams.nlines;
  const std::vector<char>& bcorner = seams.boundary_corner;
  const std::vector<Cplx>& border_dir = seams.border_dir;
  const std::vector<int>& line_of = seams.line_of;
  // 5. corner expressions. Small unknowns: 0..narcs-1 the arcs' translations, then the boundary
  // lines (the real part their integer coordinate), then one position per singularity and per
  // boundary corner. The other vertices are the big unknowns: a complex one inside, a real one
  // (the position along its line, in the direction d) on the boundary: P = d (s + i line).
  // Walking counterclockwise around v from a corner, crossing the edge of halfedge y (from
  // face(y) into face of ccw_out... ) applies that edge's motion.
  std::vector<int>& sing_index = c.sing_index;
  sing_index.assign(nv, -1);
  int& nsmall = c.nsmall;
  nsmall = narcs + nlines;
  for(std::size_t v = 0; v < nv; ++v) if(singular[v] || bcorner[v]) sing_index[v] = nsmall++;
  std::vector<int>& big = c.big;
  big.assign(nv, -1);
  std::vector<Cplx>& big_dir = c.big_dir;
  std::vector<int> big_line;
  int& nbig = c.nbig;
  for(std::size_t v = 0; v < nv; ++v) {
    if(sing_index[v] >= 0 || m.is_isolated(int(v))) continue;
    big[v] = nbig++;
    const bool on_border = m.is_boundary_vertex(int(v));
    big_dir.push_back(on_border ? border_dir[std::size_t(m.vertex_out[v] >> 1)] : Cplx(0, 0));
    big_line.push_back(on_border ? line_of[std::size_t(m.vertex_out[v] >> 1)] : -1);
  }
  std::vector<Expr>& corner = c.corner;
  corner.assign(2 * ne, Expr());
  std::vector<Corner_layout::Closing>& closings = c.closings;
  for(std::size_t v = 0; v < nv; ++v) {
    if(m.is_isolated(int(v))) continue;
    const bool on_border = m.is_boundary_vertex(int(v));
    // start right after a cut edge if there is one, so no wedge wraps around; on the boundary at
    // the fan's first face
    int start = m.vertex_out[v];
    if(!on_border) {
      int x = start;
      do { if(cut[std::size_t(x >> 1)]) { start = x; break; } x = m.ccw_out(x); } while(x != start);
    }
    Expr e;
    if(sing_index[v] >= 0) { e.vertex = -1; e.add(sing_index[v], Cplx(1, 0)); }
    else {
      e.vertex = big[v];
      if(on_border) e.add(narcs + big_line[std::size_t(big[v])], big_dir[std::size_t(big[v])] * Cplx(0, 1));
    }
    int x = start;
    do {
      corner[std::size_t(x)] = e;   // corner of face(x) at v = source(x)
      // next corner counterclockwise: in the face of ccw_out(x) = opposite(prev(x)), across the
      // edge of prev(x), from face(x) into face(prev(x) ^ 1)
      const int y = m.prev(x);
      if(m.face[std::size_t(y ^ 1)] < 0) break;   // the fan ends at the boundary
      const std::size_t ey = std::size_t(y >> 1);
      if(cut[ey]) {
        // crossing from face(y) into face(y ^ 1); y = 2e crosses L -> R, y = 2e + 1 crosses R -> L
        const bool from_left_of_arc = ((y & 1) == 0) == bool(arc_forward[ey]);
        const int q = arc_q[std::size_t(arc[ey])];
        if(from_left_of_arc)   // P_R = i^{-q} (P_L - t)
          e = e.mapped(unit_power(-q), arc[ey], -unit_power(-q));
        else                   // P_L = i^{q} P_R + t
          e = e.mapped(unit_power(q), arc[ey], Cplx(1, 0));
      }
      x = m.ccw_out(x);
    } while(x != start);
    if(on_border) continue;   // no fan to close: the seams that end here are free
    // closing: the expression reached must equal the start one
    Corner_layout::Closing cl;
    // e = a Z + sum, s0 = Z (big) or the singularity's small unknown
    if(!singular[v]) {
      if(std::abs(e.a - Cplx(1, 0)) > 1e-9) {
        message = "vertex " + std::to_string(v) + ": the field turns around it but it was not found singular";
        return false;
      }
      for(const auto& s : e.small) if(std::abs(s.second) > 1e-9) cl.t.push_back(s);
      if(!cl.t.empty()) closings.push_back(cl);
    } else {
      // e.small holds (a) times the singularity's own unknown plus the translations: e - s0 = 0
      Expr d = e;
      d.add(sing_index[v], Cplx(-1, 0));
      for(const auto& s : d.small) if(std::abs(s.second) > 1e-9) cl.t.push_back(s);
      closings.push_back(cl);
    }
  }
  // the boundary's conditions, real rows on the small unknowns: at both ends of every border
  // edge, Im(conj(d) P) is its line's value (d its direction in its face)
  std::vector<Corner_layout::Line_condition>& line_conditions = c.line_conditions;
  for(const auto& loop : topo.loops)
    for(int b : loop) {
      const int x = b ^ 1;
      const Cplx dc = std::conj(border_dir[std::size_t(x >> 1)]);
      for(int cx : {x, m.next[std::size_t(x)]}) {
        const Expr& p = corner[std::size_t(cx)];
        if(p.vertex >= 0 && std::abs((dc * p.a * big_dir[std::size_t(p.vertex)]).imag()) > 1e-9) {
          message = "the boundary turns at vertex " + std::to_string(m.source(cx)) + " by an angle that is not a multiple of pi/2 under the metric";
          return false;
        }
        Corner_layout::Line_condition lc;
        lc.line = narcs + line_of[std::size_t(x >> 1)];
        for(const auto& s : p.small) lc.t.emplace_back(s.first, dc * s.second);
        line_conditions.push_back(lc);
      }
    }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAM_LAYOUT_H
