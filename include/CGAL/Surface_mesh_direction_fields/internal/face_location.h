// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FACE_LOCATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FACE_LOCATION_H

// The input face under a point that lies on the input surface, searched among the faces near a
// face known to be close (the face under a neighbouring vertex of a remesh): a few
// point-triangle distances instead of a tree query per point.

#include <CGAL/Surface_mesh_direction_fields/internal/inversion.h>
#include <CGAL/Surface_mesh_direction_fields/internal/packed_lists.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The point of the triangle (a, b, c) closest to p, found by the Voronoi regions of its
// vertices, edges and interior (Ericson, Real-Time Collision Detection, 5.1.5).
inline Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  auto sub = [](const Vec3& x, const Vec3& y) { return Vec3{{x[0] - y[0], x[1] - y[1], x[2] - y[2]}}; };
  auto dot = [](const Vec3& x, const Vec3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  auto at = [&](double s, double t) {   // a + s (b - a) + t (c - a)
    Vec3 q;
    for(std::size_t d = 0; d < 3; ++d) q[d] = a[d] + s * (b[d] - a[d]) + t * (c[d] - a[d]);
    return q;
  };
  const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if(d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if(d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0 && d1 >= 0 && d3 <= 0) return at(d1 / (d1 - d3), 0);
  const Vec3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if(d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0 && d2 >= 0 && d6 <= 0) return at(0, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(1 - w, w);
  }
  const double denom = va + vb + vc;
  if(!(denom > 0)) return a;   // a degenerate triangle: its first corner
  return at(vb / denom, vc / denom);
}

// The squared distance from p to the triangle (a, b, c).
inline double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 q = closest_point_on_triangle(p, a, b, c);
  const double e[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
  return e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
}

// The faces of a triangle mesh as indices, with their corners, unit normals and the faces
// around every vertex.
template <typename TriangleMesh>
class Input_faces
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

public:
  template <typename VPM>
  Input_faces(const TriangleMesh& tm, const VPM& vpm)
  {
    auto vim = get(CGAL::dynamic_vertex_property_t<int>(), tm);
    int nv = 0;
    for(vertex_descriptor v : vertices(tm)) {
      put(vim, v, nv++);
      const auto& p = get(vpm, v);
      point_.push_back(Vec3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
    }
    fim_ = get(CGAL::dynamic_face_property_t<int>(), tm);
    Packed_lists<int> corners;
    for(face_descriptor f : faces(tm)) {
      put(fim_, f, int(face_.size()));
      face_.push_back(f);
      std::array<int, 3> c{{0, 0, 0}};
      int k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) if(k < 3) c[std::size_t(k++)] = get(vim, target(h, tm));
      corner_.push_back(c);
      for(int v : c) corners.push_back(v);
      corners.close_list();
      normal_.push_back(unit_triangle_normal(point_[std::size_t(c[0])], point_[std::size_t(c[1])], point_[std::size_t(c[2])]));
    }
    around_ = corners.transposed(std::size_t(nv));
    adjacent_.assign(corner_.size(), std::array<int, 3>{{-1, -1, -1}});   // across side k, from corner k to k + 1
    for(std::size_t f = 0; f < corner_.size(); ++f)
      for(std::size_t k = 0; k < 3; ++k) {
        const int a = corner_[f][k], b = corner_[f][(k + 1) % 3];
        for(std::size_t g : around_[std::size_t(a)]) {
          const std::array<int, 3>& e = corner_[g];
          if(g != f && (e[0] == b || e[1] == b || e[2] == b)) { adjacent_[f][k] = int(g); break; }
        }
      }
    vertex_normal_.assign(std::size_t(nv), Vec3{{0, 0, 0}});   // as internal::vertex_normal()
    for(std::size_t f = 0; f < corner_.size(); ++f)
      for(int v : corner_[f]) for(std::size_t d = 0; d < 3; ++d) vertex_normal_[std::size_t(v)][d] += normal_[f][d];
    for(Vec3& n : vertex_normal_) n = normalized(n);
    mark_.assign(face_.size(), 0);
  }

  std::size_t size() const { return face_.size(); }
  int index(face_descriptor f) const { return get(fim_, f); }
  face_descriptor face(int f) const { return face_[std::size_t(f)]; }
  // The input's unit normal at p, a point of face f, as internal::face_normal(), edge_normal()
  // and vertex_normal() define it: p is at a corner of f, or on a side, when within squared
  // distance `tol2` of it.
  Vec3 normal_at(const Vec3& p, int f, double tol2) const
  {
    const std::array<int, 3>& c = corner_[std::size_t(f)];
    for(int v : c) {
      const Vec3& q = point_[std::size_t(v)];
      const double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
      if(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= tol2) return vertex_normal_[std::size_t(v)];
    }
    for(std::size_t k = 0; k < 3; ++k) {
      const int a = c[k], b = c[(k + 1) % 3];
      if(squared_distance_to_triangle(p, point_[std::size_t(a)], point_[std::size_t(b)], point_[std::size_t(b)]) > tol2) continue;   // to the segment
      Vec3 sum = normal_[std::size_t(f)];
      for(std::size_t g : around_[std::size_t(a)]) {   // the face on the other side of (a, b)
        const std::array<int, 3>& e = corner_[g];
        if(int(g) != f && (e[0] == b || e[1] == b || e[2] == b))
          for(std::size_t d = 0; d < 3; ++d) sum[d] += normal_[g][d];
      }
      return normalized(sum);
    }
    return normal_[std::size_t(f)];
  }

  // The least dot product of `a` with the unit normals of the faces that p, a point of face f,
  // touches: at a corner of f (within squared distance `tol2`), every face around it; on a side,
  // the two beside it; else f's. A direction positive against all of them faces the input
  // whichever face a search for p's nearest point returns.
  double least_dot_with_normals_at(const Vec3& p, int f, double tol2, const Vec3& a) const
  {
    auto dot = [&](std::size_t g) { return a[0] * normal_[g][0] + a[1] * normal_[g][1] + a[2] * normal_[g][2]; };
    const std::array<int, 3>& c = corner_[std::size_t(f)];
    double least = dot(std::size_t(f));
    for(int v : c) {
      const Vec3& q = point_[std::size_t(v)];
      const double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
      if(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= tol2) {
        for(std::size_t g : around_[std::size_t(v)]) least = (std::min)(least, dot(g));
        return least;
      }
    }
    for(std::size_t k = 0; k < 3; ++k) {
      const int a0 = c[k], b0 = c[(k + 1) % 3];
      if(adjacent_[std::size_t(f)][k] >= 0 &&
         squared_distance_to_triangle(p, point_[std::size_t(a0)], point_[std::size_t(b0)], point_[std::size_t(b0)]) <= tol2)
        least = (std::min)(least, dot(std::size_t(adjacent_[std::size_t(f)][k])));
    }
    return least;
  }

  // The point of face f closest to p.
  Vec3 closest_point(const Vec3& p, int f) const
  {
    const std::array<int, 3>& c = corner_[std::size_t(f)];
    return closest_point_on_triangle(p, point_[std::size_t(c[0])], point_[std::size_t(c[1])], point_[std::size_t(c[2])]);
  }

  double squared_distance(const Vec3& p, int f) const
  {
    const std::array<int, 3>& c = corner_[std::size_t(f)];
    return squared_distance_to_triangle(p, point_[std::size_t(c[0])], point_[std::size_t(c[1])], point_[std::size_t(c[2])]);
  }

  // The face nearest to p, by trying every face (for the first point of a search).
  int nearest_face(const Vec3& p) const
  {
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < corner_.size(); ++f) {
      const double d2 = squared_distance(p, int(f));
      if(d2 < best_d2) { best_d2 = d2; best = int(f); }
    }
    return best;
  }

  // The face under p by walking from face `start` towards p: across the side beyond which p's
  // projection onto the face's plane lies (its most negative barycentric coordinate) until it
  // lies inside; -1 if that face is farther than `tol2` (squared) from p, or after `steps`
  // faces, or at the border. A few faces at most where the remesh is about as fine as the input.
  int walk_to(const Vec3& p, int start, double tol2, int steps = 16) const
  {
    int f = start;
    for(int step = 0; step < steps && f >= 0; ++step) {
      const std::array<int, 3>& c = corner_[std::size_t(f)];
      const Vec3 &a = point_[std::size_t(c[0])], &b = point_[std::size_t(c[1])], &q = point_[std::size_t(c[2])];
      const Vec3& n = normal_[std::size_t(f)];
      // twice the signed areas of the sub-triangles seen along the normal, opposite each corner
      auto twice_area = [&](const Vec3& x, const Vec3& y) {
        const double u[3] = {y[0] - x[0], y[1] - x[1], y[2] - x[2]}, v[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
        return (u[1] * v[2] - u[2] * v[1]) * n[0] + (u[2] * v[0] - u[0] * v[2]) * n[1] + (u[0] * v[1] - u[1] * v[0]) * n[2];
      };
      const double w[3] = {twice_area(b, q), twice_area(q, a), twice_area(a, b)};   // opposite corners 0, 1, 2
      const int worst = w[0] <= w[1] && w[0] <= w[2] ? 0 : w[1] <= w[2] ? 1 : 2;
      if(w[worst] >= 0) return squared_distance(p, f) <= tol2 ? f : -1;
      f = adjacent_[std::size_t(f)][std::size_t((worst + 1) % 3)];   // the side opposite that corner
    }
    return -1;
  }

  // A face within `rings` vertex rings of `hint` whose squared distance to p is at most `tol2`
  // (the first found, ring by ring), or -1; then `nearest`, if given, receives the nearest face
  // examined (a hint for the next search). Not thread-safe (marks faces).
  int face_under(const Vec3& p, int hint, double tol2, int rings = 2, int* nearest = nullptr)
  {
    double best_d2 = squared_distance(p, hint);
    if(best_d2 <= tol2) return hint;
    int best = hint;
    ++stamp_;
    mark_[std::size_t(hint)] = stamp_;
    std::vector<int>& front = front_;
    front.assign(1, hint);
    for(int r = 0; r < rings; ++r) {
      const std::size_t end = front.size();
      for(std::size_t i = 0; i < end; ++i)
        for(int v : corner_[std::size_t(front[i])])
          for(std::size_t h : around_[std::size_t(v)]) {
            const int g = int(h);
            if(mark_[std::size_t(g)] == stamp_) continue;
            mark_[std::size_t(g)] = stamp_;
            front.push_back(g);
            const double d2 = squared_distance(p, g);
            if(d2 <= tol2) return g;   // the first found: ties lie on shared edges
            if(d2 < best_d2) { best_d2 = d2; best = g; }
          }
      front.erase(front.begin(), front.begin() + std::ptrdiff_t(end));
    }
    if(nearest) *nearest = best;
    return -1;
  }

private:
  std::vector<Vec3> point_, normal_, vertex_normal_;
  std::vector<face_descriptor> face_;
  std::vector<std::array<int, 3>> corner_;
  Packed_lists<std::size_t> around_;   // per vertex: its faces
  std::vector<std::array<int, 3>> adjacent_;   // per face: the face across each side (-1: none)
  std::vector<int> front_;
  std::vector<unsigned> mark_;
  unsigned stamp_ = 0;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<int>>::const_type fim_;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FACE_LOCATION_H
