// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_COMMON_SUBDIVISION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_COMMON_SUBDIVISION_H

// The correspondence between the input triangulation and the intrinsic Delaunay triangulation
// of a discrete conformal metric (Gillespie, Springborn, Crane 2021), kept through the flips.
//
// Both triangulations are ideal triangulations of one decorated hyperbolic surface: a vertex v
// is a light-like vector p_v of R^{2,1} and <p_a, p_b> = -l_ab^2 / 2 for the Penner coordinate
// l_ab of an edge (its length at u = 0; Ptolemy flips keep the decoration). The Euclidean
// triangle of lengths l is the affine triangle spanned by the p's, so a point with barycentric
// coordinates b is the ray of sum b_i p_i: the maps between the two triangulations are
// projective on every piece of their common subdivision, and vertex scaling by e^u turns the
// barycentric coordinates b into b_i e^{-u_i} (normalised).
//
// Combinatorics as normal coordinates (Gillespie, Sharp, Crane 2021): every intrinsic edge keeps
// the ordered list of the input edges it crosses; inside a triangle the crossings pair up as
// corner arcs and arcs emanating from a corner, which the counts alone determine. A flip
// recomputes the new diagonal's list from the arcs of its quadrilateral; the crossing points
// are intersections of geodesics computed in a frame of the quadrilateral's four p's.

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/ricci_flow.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Where an input edge crosses an intrinsic edge e: t along the input halfedge 2 * input_edge
// from its source, s along the intrinsic halfedge 2e from its source (barycentric coordinates
// of the Penner decoration, u = 0), dir = +1 if the input edge, going by increasing t, passes
// from face(2e + 1) into face(2e), -1 otherwise. rest_t = 1 - t and rest_s = 1 - s are kept
// apart: a crossing next to a vertex loses them to rounding when computed from t and s.
struct Edge_crossing
{
  int input_edge;
  double t, s;
  int dir;
  double rest_t, rest_s;
};

// A failure of the correspondence's own consistency checks (caught by compute_cone_metric(),
// which then reports the triangulation without a common subdivision).
inline std::runtime_error internal_correspondence_error(const std::string& what)
{
  return std::runtime_error("the correspondence with the input failed: " + what);
}

// An end of an arc of an input edge inside a triangle with halfedges g0, g1, g2: a crossing at
// position pos along g_side (from its source), or corner `side - 3` (the source of g_{side-3}).
struct Arc_end
{
  int side, pos;
  bool is_corner() const { return side >= 3; }
};

// The arcs of the input edges inside a triangle whose halfedges are crossed n0, n1, n2 times:
// corner arcs and arcs emanating from a corner to the opposite side (at most one corner has
// them), as pairs of ends.
inline void triangle_arcs(int n0, int n1, int n2, std::vector<std::pair<Arc_end, Arc_end>>& arcs)
{
  arcs.clear();
  const int e0 = (std::max)(0, n1 - n0 - n2), e1 = (std::max)(0, n2 - n0 - n1), e2 = (std::max)(0, n0 - n1 - n2);
  const int s0 = n0 + n2 - n1 - e2 - e1 + e0, s1 = n0 + n1 - n2 - e2 - e0 + e1, s2 = n1 + n2 - n0 - e0 - e1 + e2;
  if((s0 & 1) || (s1 & 1) || (s2 & 1) || s0 < 0 || s1 < 0 || s2 < 0)
    throw internal_correspondence_error("crossing counts " + std::to_string(n0) + ", " + std::to_string(n1) + ", " +
                                        std::to_string(n2) + " of a triangle are not those of arcs");
  const int c0 = s0 / 2, c1 = s1 / 2, c2 = s2 / 2;
  for(int m = 0; m < c0; ++m) arcs.push_back({{0, m}, {2, n2 - 1 - m}});
  for(int m = 0; m < c1; ++m) arcs.push_back({{0, n0 - 1 - m}, {1, m}});
  for(int m = 0; m < c2; ++m) arcs.push_back({{1, n1 - 1 - m}, {2, m}});
  for(int m = 0; m < e0; ++m) arcs.push_back({{3, 0}, {1, c1 + m}});
  for(int m = 0; m < e1; ++m) arcs.push_back({{4, 0}, {2, c2 + m}});
  for(int m = 0; m < e2; ++m) arcs.push_back({{5, 0}, {0, c0 + m}});
}

// Intrinsic Delaunay flips of the input triangulation for the conformal factors u, by Ptolemy on
// the Penner coordinates (the test and update of Vertex_scaling_flow::make_delaunay()), each
// flip carrying the crossings of the input edges over to the new diagonal.
template <typename TM>
class Tracked_delaunay_flips
{
public:
  Flippable_triangulation tri;
  std::vector<double> l0;                         // per edge: Penner coordinate
  std::vector<std::vector<Edge_crossing>> cross;  // per edge, ordered along halfedge 2e
  std::vector<long> coincident;                   // per edge: the input edge it is, or -1
  std::size_t flips = 0;

  explicit Tracked_delaunay_flips(const Mesh_arrays<TM>& m) : m_(&m)
  {
    tri.next = m.next;
    tri.target = m.target;
    tri.face = m.face;
    tri.face_halfedge = m.face_halfedge;
    l0 = m.length;
    cross.assign(m.number_of_edges(), {});
    coincident.resize(m.number_of_edges());
    for(std::size_t e = 0; e < coincident.size(); ++e) coincident[e] = long(e);
  }

  // Flips until Delaunay for the lengths l0_e e^{(u_a + u_b) / 2}; returns the lengths. Without
  // `track`, the crossings are not kept (the correspondence is then lost).
  std::vector<double> make_delaunay(const std::vector<double>& u, bool track = true)
  {
    const int ne = int(l0.size());
    std::vector<double> half_exp(u.size());
    for(std::size_t v = 0; v < u.size(); ++v) half_exp[v] = std::exp(0.5 * u[v]);
    std::vector<double> len(ne);
    for(int e = 0; e < ne; ++e) len[e] = l0[e] * half_exp[tri.target[2 * e]] * half_exp[tri.target[2 * e + 1]];
    std::vector<int> queue;
    std::vector<char> in_queue(ne, 1);
    for(int e = ne - 1; e >= 0; --e) queue.push_back(e);
    const std::size_t budget = 100 * std::size_t(ne) + 1000;
    while(!queue.empty()) {
      const int e = queue.back();
      queue.pop_back();
      in_queue[e] = 0;
      if(!tri.is_flippable(e)) continue;
      if(!tri.needs_delaunay_flip(e, len)) continue;
      if(++flips > budget) throw internal_correspondence_error("Delaunay flips do not terminate");
      const int h = 2 * e, o = h + 1;
      const int h1 = tri.next[h], h2 = tri.next[h1], o1 = tri.next[o], o2 = tri.next[o1];
      if(track) flip(e, {{half_exp[tri.target[o]], half_exp[tri.target[h]], half_exp[tri.target[h1]], half_exp[tri.target[o1]]}});
      else { l0[e] = tri.ptolemy(e, l0); tri.flip(e); coincident[e] = -1; }
      len[e] = l0[e] * half_exp[tri.target[h]] * half_exp[tri.target[o]];
      for(int g : {h1, h2, o1, o2})
        if(!in_queue[g >> 1]) { in_queue[g >> 1] = 1; queue.push_back(g >> 1); }
    }
    return len;
  }

  // Makes the flips of `log` in order (a flow's flip_log()), carrying the crossings (computed at
  // u = 0: the flow's factors at each flip are not kept).
  void replay(const std::vector<int>& log)
  {
    for(int e : log) {
      if(!tri.is_flippable(e)) throw internal_correspondence_error("a logged flip of an edge that cannot flip");
      flip(e, {{1., 1., 1., 1.}});
      ++flips;
    }
  }

  // Empty, or what is wrong with the crossings of face f: every arc joins two ends of one input
  // edge, enters the face at one end and leaves it at the other, t increasing along it.
  std::string face_error(int f) const
  {
    const int g[3] = {tri.face_halfedge[std::size_t(f)], tri.next[std::size_t(tri.face_halfedge[std::size_t(f)])],
                      tri.next[std::size_t(tri.next[std::size_t(tri.face_halfedge[std::size_t(f)])])]};
    std::vector<std::pair<Arc_end, Arc_end>> arcs;
    try {
      triangle_arcs(int(cross[std::size_t(g[0] >> 1)].size()), int(cross[std::size_t(g[1] >> 1)].size()),
                    int(cross[std::size_t(g[2] >> 1)].size()), arcs);
    } catch(const std::runtime_error& e) { return e.what(); }
    for(const auto& a : arcs) {
      int edge[2], dir[2];
      double t[2];
      const Arc_end* ends[2] = {&a.first, &a.second};
      for(int i = 0; i < 2; ++i) {
        if(ends[i]->is_corner()) { edge[i] = -1; continue; }
        const Edge_crossing c = crossing_along(g[ends[i]->side], ends[i]->pos);
        edge[i] = c.input_edge; dir[i] = c.dir; t[i] = c.t;
      }
      for(int i = 0; i < 2; ++i) {
        if(edge[i] >= 0) continue;
        const int E = edge[1 - i];
        const int v = tri.target[std::size_t(g[(ends[i]->side - 3 + 2) % 3])];
        const bool src = v == m_->target[std::size_t(2 * E + 1)], dst = v == m_->target[std::size_t(2 * E)];
        if(!src && !dst) return "an arc from a corner that is no end of its input edge";
        edge[i] = E; dir[i] = src ? +1 : -1; t[i] = src ? 0. : 1.;
      }
      if(edge[0] != edge[1]) return "an arc joins two input edges " + std::to_string(edge[0]) + " and " + std::to_string(edge[1]);
      if(dir[0] != -dir[1]) return "an arc enters (or leaves) at both ends";
      if((dir[0] > 0) != (t[0] < t[1])) return "t decreases along an arc";
    }
    return "";
  }

  // The crossing at position pos along halfedge g, seen from that halfedge.
  Edge_crossing crossing_along(int g, int pos) const
  {
    const std::vector<Edge_crossing>& list = cross[g >> 1];
    if(!(g & 1)) return list[std::size_t(pos)];
    Edge_crossing c = list[list.size() - 1 - std::size_t(pos)];
    std::swap(c.s, c.rest_s);
    c.dir = -c.dir;
    return c;
  }

private:
  const Mesh_arrays<TM>* m_;

  // A point of the quadrilateral's boundary: its representative r = sum_k r_k p_k over the
  // corners k = a, b, c, d (at most two nonzero: the ends of its side), and (for a crossing) the
  // norm ratio kappa between r and the input edge's representative (1 - t) p_x + t p_y of the
  // same point. Kept on the four corners, not reduced to the frame (p_a, p_b, p_c): with p_d far
  // from the others the frame's coefficients reach 1e8 and a point near d lost its side.
  struct Frame_point
  {
    std::array<double, 4> r;
    double t, rest_t, kappa;
    int input_edge;
    int dir;   // +1 if the input edge enters the quadrilateral here (by increasing t)
  };

  // Flips e, carrying the crossings over; half_exp: e^{u/2} at the corners a, b, c, d (below) in
  // the metric where the flip was decided. The crossings are computed in the frame of that
  // metric's vectors e^{u} p (the Euclidean quadrilateral that failed the Delaunay test): at
  // u = 0 the Penner coordinates of a metric far from the input's span seven orders of
  // magnitude, and so did the frame's coefficients.
  void flip(int e, const std::array<double, 4>& half_exp)
  {
    const int h = 2 * e, o = h + 1;
    const int h1 = tri.next[h], h2 = tri.next[h1], o1 = tri.next[o], o2 = tri.next[o1];
    // slots: a = source(h), b = target(h), c = target(h1), d = target(o1)
    const int va = tri.target[o], vb = tri.target[h], vc = tri.target[h1], vd = tri.target[o1];
    const double ab = l0[e], bc = l0[h1 >> 1], ca = l0[h2 >> 1], ad = l0[o1 >> 1], db = l0[o2 >> 1];
    const double cd = tri.ptolemy(e, l0);
    if(!std::isfinite(cd) || !(cd > 0)) throw internal_correspondence_error("Ptolemy flip out of range");
    // frame: p_d from <p_d, p_x> = -l_xd^2 / 2 (x = a, b, c), Cramer on the Gram matrix of a, b, c
    // squared lengths of the scaled vectors q_x = e^{u_x} p_x: <q_x, q_y> = -(l_xy e^{(u_x + u_y) / 2})^2 / 2
    const std::array<double, 4> w = {{half_exp[0] * half_exp[0], half_exp[1] * half_exp[1], half_exp[2] * half_exp[2], half_exp[3] * half_exp[3]}};
    const double AB = ab * ab * w[0] * w[1], BC = bc * bc * w[1] * w[2], CA = ca * ca * w[2] * w[0];
    const double r0 = ad * ad * w[0] * w[3], r1 = db * db * w[3] * w[1], r2 = cd * cd * w[2] * w[3];
    const double det = 2 * AB * BC * CA;
    const double X = (r0 * (-BC * BC) - AB * (r1 * 0 - BC * r2) + CA * (r1 * BC - 0 * r2)) / det;
    const double Y = (0 * (r1 * 0 - BC * r2) - r0 * (AB * 0 - BC * CA) + CA * (AB * r2 - r1 * CA)) / det;
    const double Z = (0 * (0 * r2 - r1 * BC) - AB * (AB * r2 - r1 * CA) + r0 * (AB * BC - 0 * CA)) / det;
    const std::array<int, 4> vid = {{va, vb, vc, vd}};

    // the arcs of the two triangles (abc: h, h1, h2; bad: o, o1, o2), glued across ab
    const int nab = int(cross[e].size());
    const int nh1 = int(cross[h1 >> 1].size()), nh2 = int(cross[h2 >> 1].size());
    const int no1 = int(cross[o1 >> 1].size()), no2 = int(cross[o2 >> 1].size());
    std::vector<std::pair<Arc_end, Arc_end>> arcs1, arcs2;
    triangle_arcs(nab, nh1, nh2, arcs1);
    triangle_arcs(nab, no1, no2, arcs2);
    // quadrilateral ends: slot (0..3) of a corner, or a crossing on halfedge g at pos
    struct Quad_end { int slot, g, pos; };
    auto end1 = [&](const Arc_end& x) -> Quad_end {
      static const int slots[3] = {0, 1, 2};
      if(x.is_corner()) return {slots[x.side - 3], -1, 0};
      return {-1, x.side == 1 ? h1 : h2, x.pos};
    };
    auto end2 = [&](const Arc_end& x) -> Quad_end {
      static const int slots[3] = {1, 0, 3};
      if(x.is_corner()) return {slots[x.side - 3], -1, 0};
      return {-1, x.side == 1 ? o1 : o2, x.pos};
    };
    std::vector<int> t2_at(std::size_t(nab), -1);   // T2 arc through each crossing of ab (T1 order)
    for(std::size_t i = 0; i < arcs2.size(); ++i)
      for(const Arc_end* x : {&arcs2[i].first, &arcs2[i].second})
        if(x->side == 0) t2_at[std::size_t(nab - 1 - x->pos)] = int(i);
    struct Quad_arc { Quad_end x, y; int ab_pos; };
    std::vector<Quad_arc> quad_arcs;
    for(const auto& a : arcs1) {
      if(a.first.side == 0 || a.second.side == 0) {
        const Arc_end& mid = a.first.side == 0 ? a.first : a.second;
        const Arc_end& out = a.first.side == 0 ? a.second : a.first;
        const auto& b = arcs2[std::size_t(t2_at[std::size_t(mid.pos)])];
        const Arc_end& out2 = b.first.side == 0 ? b.second : b.first;
        quad_arcs.push_back({end1(out), end2(out2), mid.pos});
      } else {
        quad_arcs.push_back({end1(a.first), end1(a.second), -1});
      }
    }
    for(const auto& b : arcs2)
      if(b.first.side != 0 && b.second.side != 0) quad_arcs.push_back({end2(b.first), end2(b.second), -1});
    if(coincident[e] >= 0) quad_arcs.push_back({{0, -1, 0}, {1, -1, 0}, -1});

    // cyclic position from c: c, h2 crossings, a, o1 crossings, d, o2 crossings, b, h1 crossings
    const int pos_a = 1 + nh2, pos_d = pos_a + 1 + no1, pos_b = pos_d + 1 + no2;
    auto position = [&](const Quad_end& x) {
      if(x.slot == 0) return pos_a;
      if(x.slot == 1) return pos_b;
      if(x.slot == 2) return 0;
      if(x.slot == 3) return pos_d;
      if(x.g == h2) return 1 + x.pos;
      if(x.g == o1) return pos_a + 1 + x.pos;
      if(x.g == o2) return pos_d + 1 + x.pos;
      return pos_b + 1 + x.pos;   // h1
    };
    auto on_a_side = [&](int p) { return p > 0 && p < pos_d; };

    long new_coincident = -1;
    std::vector<std::pair<std::pair<int, int>, Edge_crossing>> found;   // ((a-side end, -(b-side end)), crossing)
    for(const Quad_arc& q : quad_arcs) {
      const int px = position(q.x), py = position(q.y);
      if((px == 0 && py == pos_d) || (px == pos_d && py == 0)) {   // an input edge from c to d
        new_coincident = cross[e][std::size_t(q.ab_pos)].input_edge;
        continue;
      }
      if(px == 0 || py == 0 || px == pos_d || py == pos_d || on_a_side(px) == on_a_side(py)) continue;
      const Quad_end& A = on_a_side(px) ? q.x : q.y;
      const Quad_end& B = on_a_side(px) ? q.y : q.x;
      int input_edge = -1;
      if(q.ab_pos >= 0) input_edge = cross[e][std::size_t(q.ab_pos)].input_edge;
      else if(A.slot < 0) input_edge = crossing_along(A.g, A.pos).input_edge;
      else if(B.slot < 0) input_edge = crossing_along(B.g, B.pos).input_edge;
      else input_edge = int(coincident[e]);
      const Frame_point fa = frame_point(A, vid, input_edge, h1, h2, o1, o2);
      const Frame_point fb = frame_point(B, vid, input_edge, h1, h2, o1, o2);
      // the points on the scaled corners: r = sum_k r_k p_k = sum_k (r_k / w_k) q_k
      std::array<double, 4> ra, rb;
      for(std::size_t i = 0; i < 4; ++i) { ra[i] = fa.r[i] / w[i]; rb[i] = fb.r[i] / w[i]; }
      // the side of span(q_c, q_d): det(q_c, q_d, r) in the frame (q_a, q_b, q_c), where q_d =
      // X q_a + Y q_b + Z q_c; q_c and q_d have none, so a side's point has a single term
      auto side = [&](const std::array<double, 4>& r) { return X * r[1] - Y * r[0]; };
      const double alpha = std::abs(side(rb)), beta = std::abs(side(ra));
      std::array<double, 4> Q;
      for(std::size_t i = 0; i < 4; ++i) Q[i] = alpha * ra[i] + beta * rb[i];
      // Q = gamma q_c + delta q_d: its (q_a, q_b) part is (delta - Q_d) (X, Y); back on the p's,
      // the coefficients of p_c and p_d are gamma w_c and delta w_d
      const double ab_part = (X * Q[0] + Y * Q[1]) / (X * X + Y * Y);
      const double delta = (Q[3] + ab_part) * w[3], gamma = (Q[2] - Z * ab_part) * w[2];
      if(!(gamma > 0) || !(delta > 0) || !(alpha + beta > 0))
        throw internal_correspondence_error("an input edge misses the flipped edge");
      Edge_crossing c;
      c.input_edge = input_edge;
      c.s = gamma / (gamma + delta);   // along d -> c, the new halfedge 2e
      c.rest_s = delta / (gamma + delta);
      const double wa = alpha * fa.kappa, wb = beta * fb.kappa;
      c.t = (wa * fa.t + wb * fb.t) / (wa + wb);
      c.rest_t = (wa * fa.rest_t + wb * fb.rest_t) / (wa + wb);
      // from the a side (left of d -> c) to the b side: from face(2e) to face(2e + 1)
      c.dir = fa.dir > 0 ? -1 : +1;
      if(fb.dir != -fa.dir) throw internal_correspondence_error("inconsistent crossing directions");
      found.emplace_back(std::make_pair(position(A), -position(B)), c);
    }
    // from d: the a-side end farthest from c first; arcs from one corner by their other end
    std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    tri.flip(e);
    l0[e] = cd;
    coincident[e] = new_coincident;
    cross[e].clear();
    if(new_coincident < 0)
      for(const auto& x : found) cross[e].push_back(x.second);
    else if(!found.empty())
      throw internal_correspondence_error("an input edge crosses another one");
  }

  template <typename QuadEnd>
  Frame_point frame_point(const QuadEnd& x, const std::array<int, 4>& vid, int input_edge, int h1, int h2, int o1, int o2) const
  {
    Frame_point f;
    f.input_edge = input_edge;
    const double L = m_->length[std::size_t(input_edge)];
    if(x.slot >= 0) {
      f.r = {{0, 0, 0, 0}};
      f.r[std::size_t(x.slot)] = 1;
      const int src = m_->target[std::size_t(2 * input_edge + 1)];
      f.t = vid[std::size_t(x.slot)] == src ? 0. : 1.;
      f.rest_t = 1 - f.t;
      f.kappa = 1;
      f.dir = f.t == 0 ? +1 : -1;   // leaves the vertex into the quadrilateral by increasing t
      return f;
    }
    const Edge_crossing c = crossing_along(x.g, x.pos);
    if(c.input_edge != input_edge) throw internal_correspondence_error("an arc changes input edge");
    // the halfedge's end slots
    int sx, sy;
    if(x.g == h1) { sx = 1; sy = 2; }
    else if(x.g == h2) { sx = 2; sy = 0; }
    else if(x.g == o1) { sx = 0; sy = 3; }
    else { sx = 3; sy = 1; }
    (void)o2;
    f.r = {{0, 0, 0, 0}};
    f.r[std::size_t(sx)] = c.rest_s;
    f.r[std::size_t(sy)] = c.s;
    f.t = c.t;
    f.rest_t = c.rest_t;
    const double rho_r = std::sqrt(c.s * c.rest_s) * l0[std::size_t(x.g >> 1)];
    const double rho_x = std::sqrt(c.t * c.rest_t) * L;
    f.kappa = rho_r / rho_x;
    if(!std::isfinite(f.kappa) || !(f.kappa > 0)) throw internal_correspondence_error("a crossing at a vertex");
    f.dir = c.dir;   // seen from the quadrilateral's boundary halfedge, whose left is inside
    return f;
  }
};


// The pieces of the common subdivision of the input (m) and the triangulation of `tf`, with the
// lengths `len` of the conformal factors u, into `it`: in every intrinsic face, the arcs of the
// input edges cut the triangle into convex pieces, found by walking around each one (along the
// triangle's boundary counterclockwise, turning into every arc met); a piece's input face is the
// side of one of its arcs that it lies on.
template <typename TM>
void build_common_subdivision(const Mesh_arrays<TM>& m, const Tracked_delaunay_flips<TM>& tf,
                              const std::vector<double>& u, const std::vector<double>& len,
                              Intrinsic_triangulation& it)
{
  const Flippable_triangulation& tri = tf.tri;
  std::vector<Common_subdivision_piece> pieces;
  std::vector<std::array<double, 9>> maps;
  std::size_t crossings = 0;
  std::vector<std::size_t> first_crossing(tf.cross.size());
  for(std::size_t e = 0; e < tf.cross.size(); ++e) { first_crossing[e] = crossings; crossings += tf.cross[e].size(); }
  const long nv = long(m.number_of_vertices());
  double residual = 0;
  std::vector<std::pair<Arc_end, Arc_end>> arcs;
  std::vector<std::vector<int>> chords;
  std::vector<char> visited;
  std::vector<int> pts, moves;   // the piece's points, and the chord taken from each (-1: boundary)
  for(std::size_t g = 0; g < tri.face_halfedge.size(); ++g) {
    const std::string error = tf.face_error(int(g));
    if(!error.empty()) throw internal_correspondence_error(error);
    const std::array<int, 3> gh = {{tri.face_halfedge[g], tri.next[std::size_t(tri.face_halfedge[g])],
                                    tri.next[std::size_t(tri.next[std::size_t(tri.face_halfedge[g])])]}};
    std::array<int, 3> n, start;
    for(int i = 0; i < 3; ++i) n[std::size_t(i)] = int(tf.cross[std::size_t(gh[std::size_t(i)] >> 1)].size());
    start[0] = 0; start[1] = n[0] + 1; start[2] = n[0] + n[1] + 2;
    const int M = n[0] + n[1] + n[2] + 3;
    triangle_arcs(n[0], n[1], n[2], arcs);
    auto point_of = [&](const Arc_end& x) { return x.is_corner() ? start[std::size_t(x.side - 3)] : start[std::size_t(x.side)] + 1 + x.pos; };
    auto is_corner = [&](int q) { return q == start[0] || q == start[1] || q == start[2]; };
    auto side_of = [&](int q) { return q > start[2] ? 2 : q > start[1] ? 1 : 0; };   // halfedge of a crossing
    auto crossing_at = [&](int q) {
      const int i = side_of(q);
      return tf.crossing_along(gh[std::size_t(i)], q - start[std::size_t(i)] - 1);
    };
    chords.assign(std::size_t(M), {});
    for(const auto& a : arcs) {
      const int x = point_of(a.first), y = point_of(a.second);
      chords[std::size_t(x)].push_back(y);
      chords[std::size_t(y)].push_back(x);
    }
    for(int q = 0; q < M; ++q)
      std::sort(chords[std::size_t(q)].begin(), chords[std::size_t(q)].end(),
                [&](int x, int y) { return (x - q + M) % M < (y - q + M) % M; });
    // the corner of intrinsic face g at a point, and the vertex there
    auto corner_vertex = [&](int q) { return tri.target[std::size_t(gh[std::size_t(q == start[0] ? 2 : q == start[1] ? 0 : 1)])]; };
    visited.assign(std::size_t(M), 0);
    for(int s0 = 0; s0 < M; ++s0) {
      if(visited[std::size_t(s0)]) continue;
      pts.clear();
      moves.clear();
      int q = s0, from = -2;   // from: -2 start, -1 arrived along the boundary, else the chord's other end
      int chord_q = -1, chord_r = -1;   // a chord side of the piece, traversed q -> r
      while(true) {
        int r = -1;   // the chord taken, -1 for the boundary
        const std::vector<int>& ch = chords[std::size_t(q)];
        if(from == -1) { if(!ch.empty()) r = ch.back(); }
        else if(from >= 0 && is_corner(q)) {
          const auto k = std::find(ch.begin(), ch.end(), from) - ch.begin();
          if(k > 0) r = ch[std::size_t(k - 1)];
        }
        if(r < 0 && q == s0 && from != -2) break;
        pts.push_back(q);
        moves.push_back(r);
        if(r < 0) { visited[std::size_t(q)] = 1; q = (q + 1) % M; from = -1; }
        else { if(chord_q < 0) { chord_q = q; chord_r = r; } from = q; q = r; }
        if(pts.size() > std::size_t(4 * M + 8)) throw internal_correspondence_error("a piece does not close");
      }
      // the input face: the side of a chord (q -> r, the piece on its left), else of an edge
      int f = -1;
      if(chord_q >= 0) {
        const bool q_crossing = !is_corner(chord_q);
        const Edge_crossing c = crossing_at(q_crossing ? chord_q : chord_r);
        const bool along = q_crossing ? c.dir > 0 : c.dir < 0;   // q -> r by increasing t
        f = m.face[std::size_t(2 * c.input_edge + (along ? 0 : 1))];
      } else {
        const long E = tf.coincident[std::size_t(gh[0] >> 1)];
        if(E < 0) throw internal_correspondence_error("a face without crossings has an edge that is no input edge");
        const bool along = tri.target[std::size_t(gh[0] ^ 1)] == m.target[std::size_t(2 * E + 1)];
        f = m.face[std::size_t(2 * E + (along ? 0 : 1))];
      }
      if(f < 0) throw internal_correspondence_error("a piece outside the input faces");
      const std::array<int, 3> fh = {{m.face_halfedge[std::size_t(f)], m.next[std::size_t(m.face_halfedge[std::size_t(f)])],
                                      m.next[std::size_t(m.next[std::size_t(m.face_halfedge[std::size_t(f)])])]}};
      Common_subdivision_piece piece;
      piece.input_face = f;
      piece.intrinsic_face = int(g);
      std::vector<std::array<double, 3>> penner;
      std::vector<double> rho_g, rho_f;
      for(int q2 : pts) {
        std::array<double, 3> b = {{0, 0, 0}}, c = {{0, 0, 0}};
        double rg = 0, rf = 0;
        if(is_corner(q2)) {
          c[std::size_t(q2 == start[0] ? 0 : q2 == start[1] ? 1 : 2)] = 1;
          const int v = corner_vertex(q2);
          int j = 0;
          while(j < 3 && m.target[std::size_t(fh[std::size_t(j)] ^ 1)] != v) ++j;
          if(j == 3) throw internal_correspondence_error("a piece's corner is no corner of its input face");
          b[std::size_t(j)] = 1;
        } else {
          const int i = side_of(q2);
          const Edge_crossing x = crossing_at(q2);
          c[std::size_t(i)] = x.rest_s;
          c[std::size_t((i + 1) % 3)] = x.s;
          rg = std::sqrt(x.s * x.rest_s) * tf.l0[std::size_t(gh[std::size_t(i)] >> 1)];
          const int E = x.input_edge;
          int j = 0;
          while(j < 3 && (fh[std::size_t(j)] >> 1) != E) ++j;
          if(j == 3) throw internal_correspondence_error("a piece's input edge is no edge of its input face");
          const bool same = fh[std::size_t(j)] == 2 * E;
          b[std::size_t(j)] = same ? x.rest_t : x.t;
          b[std::size_t((j + 1) % 3)] = same ? x.t : x.rest_t;
          rf = std::sqrt(x.t * x.rest_t) * m.length[std::size_t(E)];
        }
        if(is_corner(q2)) piece.corner_ids.push_back(corner_vertex(q2));
        else {
          const int i = side_of(q2), pos = q2 - start[std::size_t(i)] - 1;
          const int e = gh[std::size_t(i)] >> 1;
          piece.corner_ids.push_back(nv + long(first_crossing[std::size_t(e)]) +
                                     long((gh[std::size_t(i)] & 1) ? n[std::size_t(i)] - 1 - pos : pos));
        }
        penner.push_back(c);
        rho_g.push_back(rg);
        rho_f.push_back(rf);
        piece.input_corners.push_back(b);
      }
      // the sides: along an intrinsic halfedge of g (boundary moves), along an input edge (chords),
      // or both (an intrinsic edge that is an input edge)
      auto input_halfedge = [&](long E) {
        if(m.face[std::size_t(2 * E)] == f) return int(2 * E);
        if(m.face[std::size_t(2 * E + 1)] == f) return int(2 * E + 1);
        throw internal_correspondence_error("a piece's side is on an input edge of another face");
      };
      for(std::size_t i = 0; i < pts.size(); ++i) {
        const int q2 = pts[i];
        if(moves[i] < 0) {
          const int hg = gh[std::size_t(is_corner(q2) ? (q2 == start[0] ? 0 : q2 == start[1] ? 1 : 2) : side_of(q2))];
          piece.intrinsic_sides.push_back(hg);
          const long E = tf.coincident[std::size_t(hg >> 1)];
          piece.input_sides.push_back(E >= 0 ? input_halfedge(E) : -1);
        } else {
          piece.intrinsic_sides.push_back(-1);
          piece.input_sides.push_back(input_halfedge(crossing_at(is_corner(q2) ? moves[i] : q2).input_edge));
        }
      }
      // intrinsic coordinates in the metric of u: c_i e^{-u_i}, normalised
      std::array<double, 3> eu;
      for(int i = 0; i < 3; ++i) eu[std::size_t(i)] = std::exp(u[std::size_t(tri.target[std::size_t(gh[std::size_t((i + 2) % 3)])])]);
      for(const auto& c : penner) {
        std::array<double, 3> x;
        double sum = 0;
        for(int i = 0; i < 3; ++i) { x[std::size_t(i)] = c[std::size_t(i)] / eu[std::size_t(i)]; sum += x[std::size_t(i)]; }
        for(double& y : x) y /= sum;
        piece.intrinsic_corners.push_back(x);
      }
      // the projective map: A = V W^{-1} diag(e^u) on three corners (W, V: representatives)
      const std::size_t k = pts.size();
      std::array<double, 9> W, V;
      for(std::size_t col = 0; col < 3; ++col) {
        const double wg = rho_g[col] > 0 ? rho_g[col] : 1, wf = rho_f[col] > 0 ? rho_f[col] : 1;
        for(std::size_t row = 0; row < 3; ++row) {
          W[3 * row + col] = penner[col][row] / wg;
          V[3 * row + col] = piece.input_corners[col][row] / wf;
        }
      }
      std::array<double, 9> Winv;
      {
        const auto& a = W;
        Winv[0] = a[4] * a[8] - a[5] * a[7]; Winv[1] = a[2] * a[7] - a[1] * a[8]; Winv[2] = a[1] * a[5] - a[2] * a[4];
        Winv[3] = a[5] * a[6] - a[3] * a[8]; Winv[4] = a[0] * a[8] - a[2] * a[6]; Winv[5] = a[2] * a[3] - a[0] * a[5];
        Winv[6] = a[3] * a[7] - a[4] * a[6]; Winv[7] = a[1] * a[6] - a[0] * a[7]; Winv[8] = a[0] * a[4] - a[1] * a[3];
        const double det = a[0] * Winv[0] + a[1] * Winv[3] + a[2] * Winv[6];
        for(double& x : Winv) x /= det;
      }
      std::array<double, 9> A;
      for(int r = 0; r < 3; ++r)
        for(int c = 0; c < 3; ++c) {
          double x = 0;
          for(int j = 0; j < 3; ++j) x += V[std::size_t(3 * r + j)] * Winv[std::size_t(3 * j + c)];
          A[std::size_t(3 * r + c)] = x * eu[std::size_t(c)];
        }
      // check: every corner's intrinsic coordinates mapped onto its input ones
      for(std::size_t i = 0; i < k; ++i) {
        const auto& c = piece.intrinsic_corners[i];
        std::array<double, 3> b;
        double sum = 0;
        for(int r = 0; r < 3; ++r) { b[std::size_t(r)] = A[std::size_t(3 * r)] * c[0] + A[std::size_t(3 * r + 1)] * c[1] + A[std::size_t(3 * r + 2)] * c[2]; sum += b[std::size_t(r)]; }
        for(int r = 0; r < 3; ++r) residual = (std::max)(residual, std::abs(b[std::size_t(r)] / sum - piece.input_corners[i][std::size_t(r)]));
        if(!std::isfinite(sum)) residual = std::numeric_limits<double>::infinity();
      }
      // areas: twice the triangle's area times the polygon's in barycentric space
      auto polygon_area = [&](const std::vector<std::array<double, 3>>& cs, double triangle) {
        double a = 0;
        for(std::size_t i = 0; i < cs.size(); ++i) {
          const auto& p = cs[i];
          const auto& q3 = cs[(i + 1) % cs.size()];
          a += p[1] * q3[2] - p[2] * q3[1];
        }
        return a * triangle;
      };
      piece.input_area = polygon_area(piece.input_corners, triangle_area(m.length[std::size_t(fh[0] >> 1)], m.length[std::size_t(fh[1] >> 1)],
                                                                         m.length[std::size_t(fh[2] >> 1)]));
      piece.intrinsic_area = polygon_area(piece.intrinsic_corners, triangle_area(len[std::size_t(gh[0] >> 1)], len[std::size_t(gh[1] >> 1)],
                                                                                 len[std::size_t(gh[2] >> 1)]));
      pieces.push_back(std::move(piece));
      maps.push_back(A);
    }
  }
  it.set_common_subdivision(std::move(pieces), std::move(maps), m.number_of_faces(), crossings, residual);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_COMMON_SUBDIVISION_H
