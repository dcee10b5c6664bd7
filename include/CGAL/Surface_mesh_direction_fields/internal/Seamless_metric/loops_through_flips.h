// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEAMLESS_METRIC_LOOPS_THROUGH_FLIPS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEAMLESS_METRIC_LOOPS_THROUGH_FLIPS_H

// Penner coordinates made Delaunay by Ptolemy flips, and the loops whose holonomy a seamless
// metric fixes carried through those flips.
//
// A loop is the list of turns it makes in the faces it crosses (holonomy_loops.h). A flip of edge
// e only changes the two faces A and B beside e: a stretch of a loop that enters that quadrilateral
// by one of its four sides, crosses e any number of times and leaves by a side, is a path inside
// the quadrilateral, which holds no vertex; after the flip it becomes the one or two turns from the
// same entry side to the same exit side (crossing the new diagonal if they lie in different new
// faces), a homotopy that keeps the loop's holonomy up to multiples of 2 pi. A stretch that leaves
// by the side it entered is a U-turn, removed with the turns on either side merged.

#include <CGAL/Surface_mesh_direction_fields/internal/holonomy_loops.h>
#include <CGAL/Surface_mesh_direction_fields/internal/ricci_flow.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// A flip of edge e between faces A = face(2e) and B = face(2e + 1), with the quadrilateral's sides
// before it: h1, h2 after 2e in A, o1, o2 after 2e + 1 in B. After it (Flippable_triangulation::
// flip()), A holds 2e, h2, o1 and B holds 2e + 1, o2, h1.
struct Flip_record
{
  int e, A, B, h1, h2, o1, o2;
};

// The length of the diagonal that a flip of e creates in the flat metric of the lengths `len`
// (the quadrilateral laid out: its two sides at a and their angles with ab); the metric is kept.
inline double euclidean_flip_length(const Flippable_triangulation& tri, int e, const std::vector<double>& len)
{
  const int h = 2 * e, o = h + 1;
  const int h1 = tri.next[std::size_t(h)], h2 = tri.next[std::size_t(h1)];
  const int o1 = tri.next[std::size_t(o)], o2 = tri.next[std::size_t(o1)];
  const double ab = len[std::size_t(e)], bc = len[std::size_t(h1 >> 1)], ca = len[std::size_t(h2 >> 1)];
  const double ad = len[std::size_t(o1 >> 1)], db = len[std::size_t(o2 >> 1)];
  auto angle = [](double opposite, double x, double y) {
    return std::acos((std::max)(-1., (std::min)(1., (x * x + y * y - opposite * opposite) / (2 * x * y))));
  };
  const double at_a = angle(bc, ab, ca) + angle(db, ab, ad);
  return std::sqrt((std::max)(0., ca * ca + ad * ad - 2 * ca * ad * std::cos(at_a)));
}

// Flips until every interior edge is Delaunay for the lengths `len` (updated), each flip appended
// to `log`: by Ptolemy's relation on Penner coordinates (`ptolemy`; the metric is that of the
// Delaunay triangulation reached, Gillespie, Springborn, Crane 2021), or keeping the flat metric
// of valid triangles. Returns false if the flips do not end within `budget`.
inline bool delaunay_flips(Flippable_triangulation& tri, std::vector<double>& len, std::vector<Flip_record>& log,
                           std::size_t budget, bool ptolemy = true)
{
  const int ne = int(len.size());
  std::vector<int> queue;
  std::vector<char> in_queue(std::size_t(ne), 1);
  for(int e = ne - 1; e >= 0; --e) queue.push_back(e);
  std::size_t flips = 0;
  while(!queue.empty()) {
    const int e = queue.back();
    queue.pop_back();
    in_queue[std::size_t(e)] = 0;
    if(!tri.is_flippable(e) || !tri.needs_delaunay_flip(e, len)) continue;
    if(++flips > budget) return false;
    const int h = 2 * e, o = h + 1;
    const Flip_record r = {e, tri.face[std::size_t(h)], tri.face[std::size_t(o)], tri.next[std::size_t(h)],
                           tri.next[std::size_t(tri.next[std::size_t(h)])], tri.next[std::size_t(o)],
                           tri.next[std::size_t(tri.next[std::size_t(o)])]};
    const double l = ptolemy ? tri.ptolemy(e, len) : euclidean_flip_length(tri, e, len);
    if(!std::isfinite(l) || !(l > 0)) return false;
    len[std::size_t(e)] = l;
    tri.flip(e);
    log.push_back(r);
    for(int g : {r.h1, r.h2, r.o1, r.o2})
      if(!in_queue[std::size_t(g >> 1)]) { in_queue[std::size_t(g >> 1)] = 1; queue.push_back(g >> 1); }
  }
  return true;
}

// Removes the U-turns (a turn leaving by the halfedge it entered by) of a loop, merging the turns
// before and after each; `closed` loops wrap around. Throws if a path's end turns back.
inline void remove_u_turns(std::vector<Loop_turn>& t, bool closed)
{
  for(;;) {
    std::size_t i = 0;
    while(i < t.size() && t[i].a != t[i].b) ++i;
    if(i == t.size()) return;
    if(t.size() < 3) throw std::runtime_error("a loop carried through flips became contractible");
    const std::size_t n = t.size();
    if(!closed && (i == 0 || i + 1 == n)) throw std::runtime_error("a boundary path carried through flips turns back at its end");
    const std::size_t p = (i + n - 1) % n, q = (i + 1) % n;
    const Loop_turn merged = {t[p].a, t[q].b, t[p].face};
    // erase i and q, put the merged turn at p (indices taken in decreasing order)
    std::vector<Loop_turn> r;
    r.reserve(n - 2);
    for(std::size_t k = 0; k < n; ++k) {
      if(k == i || k == q) continue;
      r.push_back(k == p ? merged : t[k]);
    }
    t.swap(r);
  }
}

// Carries loop `t` through the flips of `log` (in order). `count` is per face, all zero, and is
// left so: the loop's turns per face, to skip the flips it does not meet in O(1).
inline void carry_loop_through_flips(std::vector<Loop_turn>& t, bool closed, const std::vector<Flip_record>& log,
                                     std::vector<int>& count)
{
  for(const Loop_turn& x : t) ++count[std::size_t(x.face)];
  std::vector<Loop_turn> r;
  for(const Flip_record& f : log) {
    if(count[std::size_t(f.A)] == 0 && count[std::size_t(f.B)] == 0) continue;
    const int h = 2 * f.e, o = h + 1;
    auto in_quad = [&](const Loop_turn& x) { return x.face == f.A || x.face == f.B; };
    auto crosses_e = [&](int g) { return (g >> 1) == f.e; };
    auto face_after = [&](int g) { return g == h || g == f.h2 || g == f.o1 ? f.A : f.B; };
    const std::size_t n = t.size();
    // a closed loop starts at a turn that does not continue a stretch across e
    std::size_t start = 0;
    if(closed) {
      while(start < n && crosses_e(t[start].a)) ++start;
      if(start == n) throw std::runtime_error("a loop carried through flips only crosses one edge");
    }
    r.clear();
    for(std::size_t k = 0; k < n;) {
      const Loop_turn& x = t[(start + k) % n];
      if(!in_quad(x)) { r.push_back(x); ++k; continue; }
      const int s = x.a;
      std::size_t j = k;
      while(crosses_e(t[(start + j) % n].b)) {
        if(++j == n) throw std::runtime_error("a loop carried through flips does not leave a flipped quadrilateral");
      }
      const int exit = t[(start + j) % n].b;
      k = j + 1;
      const int fs = face_after(s), fe = face_after(exit);
      if(s == exit || fs == fe) {
        r.push_back({s, exit, fs});   // s == exit: a U-turn, removed below
      } else {
        const int d = fs == f.A ? h : o;   // the new diagonal's halfedge in s's face
        r.push_back({s, d, fs});
        r.push_back({d ^ 1, exit, fe});
      }
    }
    for(const Loop_turn& x : t) --count[std::size_t(x.face)];
    remove_u_turns(r, closed);
    t.swap(r);
    for(const Loop_turn& x : t) ++count[std::size_t(x.face)];
  }
  for(const Loop_turn& x : t) --count[std::size_t(x.face)];
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEAMLESS_METRIC_LOOPS_THROUGH_FLIPS_H
