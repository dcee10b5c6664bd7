// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSION_H

// Whether a face of a remesh is inverted with respect to the input surface, the one test of
// tessellate_flat_metric(), polyhedron_remesh() and untangle_remesh().

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

// A polygon of `n` corners, `corner(k)` its k-th corner and `normal(k)` the input's unit normal
// under it, is inverted when its area vector points against the sum of those normals.
template <typename Corner, typename Normal>
bool turns_against_input(std::size_t n, const Corner& corner, const Normal& normal)
{
  double area[3] = {0, 0, 0}, under[3] = {0, 0, 0};
  for(std::size_t k = 0; k < n; ++k) {
    const Vec3 p = corner(k), q = corner((k + 1) % n), m = normal(k);
    area[0] += p[1] * q[2] - p[2] * q[1];
    area[1] += p[2] * q[0] - p[0] * q[2];
    area[2] += p[0] * q[1] - p[1] * q[0];
    for(int d = 0; d < 3; ++d) under[d] += m[std::size_t(d)];
  }
  return area[0] * under[0] + area[1] * under[1] + area[2] * under[2] <= 0;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSION_H
