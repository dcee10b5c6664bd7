// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSION_H

// Whether a face of a remesh is inverted with respect to the input surface, the one test of
// tessellate_flat_metric(), polyhedron_remesh() and untangle_remesh().

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

typedef std::array<double, 3> Vec3;

// The unit normal of the triangle (a, b, c), counterclockwise; 0 for a degenerate one.
inline Vec3 unit_triangle_normal(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  Vec3 n{{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for(double& x : n) x /= (l > 0 ? l : 1);
  return n;
}

// The input's unit normal at a point of its surface (Mesh_arrays `m`, `point3(v)` the position
// of vertex v): inside face f, the face's (face_normal()); on the edge of halfedge h, the
// normalised sum of the unit normals of the faces beside it (edge_normal()); at vertex v, that of
// the faces around it (vertex_normal()). A remesh corner on an input edge or vertex (a cone) thus
// gets one normal, rather than that of whichever face was picked.
template <typename Arrays, typename Point3>
Vec3 face_normal(const Arrays& m, int f, const Point3& point3)
{
  const int g = m.face_halfedge[std::size_t(f)];
  return unit_triangle_normal(point3(m.source(g)), point3(m.target[std::size_t(g)]), point3(m.target[std::size_t(m.next[std::size_t(g)])]));
}

inline Vec3 normalized(Vec3 n)
{
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for(double& x : n) x /= (l > 0 ? l : 1);
  return n;
}

template <typename Arrays, typename Point3>
Vec3 edge_normal(const Arrays& m, int h, const Point3& point3)
{
  Vec3 sum{{0, 0, 0}};
  for(int g : {h, h ^ 1}) {
    if(m.face[std::size_t(g)] < 0) continue;
    const Vec3 n = face_normal(m, m.face[std::size_t(g)], point3);
    for(std::size_t d = 0; d < 3; ++d) sum[d] += n[d];
  }
  return normalized(sum);
}

template <typename Arrays, typename Point3>
Vec3 vertex_normal(const Arrays& m, int v, const Point3& point3)
{
  Vec3 sum{{0, 0, 0}};
  const int first = m.vertex_out[std::size_t(v)];
  if(first < 0) return sum;
  int h = first;
  do {
    if(m.is_border(h)) break;
    const Vec3 n = face_normal(m, m.face[std::size_t(h)], point3);
    for(std::size_t d = 0; d < 3; ++d) sum[d] += n[d];
    h = m.ccw_out(h);
  } while(h != first);
  return normalized(sum);
}

// A polygon of `n` corners (`corner(k)`) and the input's unit normals under them (`normal(k)`):
// its area vector and the sum of those normals, with their lengths.
template <typename Corner, typename Normal>
void area_and_normals(std::size_t n, const Corner& corner, const Normal& normal, Vec3& area, Vec3& under, double& la, double& lu)
{
  area = Vec3{{0, 0, 0}};
  under = Vec3{{0, 0, 0}};
  for(std::size_t k = 0; k < n; ++k) {
    const Vec3 p = corner(k), q = corner((k + 1) % n), m = normal(k);
    area[0] += p[1] * q[2] - p[2] * q[1];
    area[1] += p[2] * q[0] - p[0] * q[2];
    area[2] += p[0] * q[1] - p[1] * q[0];
    for(std::size_t d = 0; d < 3; ++d) under[d] += m[d];
  }
  la = std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]);
  lu = std::sqrt(under[0] * under[0] + under[1] * under[1] + under[2] * under[2]);
}

// How a polygon of `n` corners faces the input, `corner(k)` its k-th corner and `normal(k)` the
// input's unit normal under it: the cosine between its area vector and the sum of those normals
// (-1 when either vanishes).
template <typename Corner, typename Normal>
double facing_input(std::size_t n, const Corner& corner, const Normal& normal)
{
  Vec3 area, under;
  double la, lu;
  area_and_normals(n, corner, normal, area, under, la, lu);
  return la > 0 && lu > 0 ? (area[0] * under[0] + area[1] * under[1] + area[2] * under[2]) / (la * lu) : -1.;
}

// How the polygon turns at its worst corner: the least, over its corners k, of the cosine between
// (corner(k + 1) - corner(k)) x (corner(k - 1) - corner(k)) and either the polygon's own area
// vector (the scaled Jacobian at k, as quality measures take it) or the sum of the input's
// normals under the polygon (the same against the surface); -1 when an edge or a reference
// vanishes. At most 0: the polygon is folded at that corner (a quad that is not convex, or an
// inverted one). `at`, if given, receives that corner.
template <typename Corner, typename Normal>
double worst_corner_turn(std::size_t n, const Corner& corner, const Normal& normal, std::size_t* at = nullptr)
{
  if(at) *at = 0;
  Vec3 area, under;
  double la, lu;
  area_and_normals(n, corner, normal, area, under, la, lu);
  if(!(la > 0) || !(lu > 0)) return -1.;
  double worst = 1;
  for(std::size_t k = 0; k < n; ++k) {
    const Vec3 p = corner(k), q = corner((k + 1) % n), r = corner((k + n - 1) % n);
    const double a[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, b[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    if(!(l > 0)) { if(at) *at = k; return -1.; }
    const double own = (c[0] * area[0] + c[1] * area[1] + c[2] * area[2]) / (l * la);
    const double input = (c[0] * under[0] + c[1] * under[1] + c[2] * under[2]) / (l * lu);
    const double turn = (std::min)(own, input);
    if(turn < worst) { worst = turn; if(at) *at = k; }
  }
  return worst;
}

// The polygon is inverted when its area vector points against the sum of the normals under it.
template <typename Corner, typename Normal>
bool turns_against_input(std::size_t n, const Corner& corner, const Normal& normal)
{
  return facing_input(n, corner, normal) <= 0;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSION_H
