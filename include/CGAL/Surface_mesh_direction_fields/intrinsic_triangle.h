// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_TRIANGLE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_TRIANGLE_H

#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// The planar point type of layouts and developments.
typedef CGAL::Simple_cartesian<double>::Point_2 Point_2;
/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// The planar vector type of layouts and developments.
typedef CGAL::Simple_cartesian<double>::Vector_2 Vector_2;

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns `true` if `a`, `b`, `c` are finite, positive and satisfy the strict triangle
/// inequalities, i.e. they are the side lengths of a non-degenerate Euclidean triangle.
inline bool is_valid_triangle(double a, double b, double c)
{
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) &&
         a > 0 && b > 0 && c > 0 && a < b + c && b < a + c && c < a + b;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the three interior angles of the triangle with side lengths `l0`, `l1`, `l2`; the
/// i-th angle is the one opposite to side `li`.
///
/// Uses the half-angle form of the law of cosines,
/// \f$\tan\frac{\gamma}{2} = \sqrt{\frac{(s-a)(s-b)}{s(s-c)}}\f$ with \f$c\f$ the opposite side
/// and \f$s\f$ the half perimeter, with the factors \f$s - a\f$ evaluated in Kahan's order (sides
/// sorted \f$x \ge y \ge z\f$, the difference \f$x - y\f$ first, which is exact): every angle keeps
/// full relative accuracy for needle and cap triangles, where \f$\arccos\f$ of the cosine rule
/// loses digits and so does the naive \f$s - a\f$ (a needle with sides \f$10^6\f$ times its short
/// side: \f$5\cdot10^{-11}\f$ absolute error). Lengths that violate the triangle inequality are
/// clamped: the angle opposite the too long side is \f$\pi\f$ and the two others are \f$0\f$.
inline std::array<double, 3> triangle_angles(double l0, double l1, double l2)
{
  const double l[3] = {l0, l1, l2};
  int i = 0, j = 1, k = 2;   // l[i] >= l[j] >= l[k]
  if(l[i] < l[j]) std::swap(i, j);
  if(l[j] < l[k]) std::swap(j, k);
  if(l[i] < l[j]) std::swap(i, j);
  const double x = l[i], y = l[j], z = l[k];
  const double d = x - y;   // exact by Sterbenz's lemma whenever y >= x / 2, i.e. in every valid triangle
  double t[3];              // t[m] = 2 (s - l[m])
  t[i] = z - d;
  t[j] = z + d;
  t[k] = x + (y - z);
  std::array<double, 3> angle;
  if(!(t[i] > 0)) {
    angle[i] = CGAL_PI;
    angle[j] = angle[k] = 0.;
    return angle;
  }
  const double s = x + (y + z);   // 2s
  for(int m = 0; m < 3; ++m) {
    const int p = (m + 1) % 3, q = (m + 2) % 3;
    angle[m] = 2. * std::atan(std::sqrt((t[p] * t[q]) / (s * t[m])));
  }
  return angle;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the interior angle opposite to the side of length `opposite` in the triangle with
/// side lengths `opposite`, `a`, `b`, as triangle_angles(): full relative accuracy for needle
/// and cap triangles; \f$\pi\f$ if the opposite side is too long for a triangle, \f$0\f$ if
/// another side is.
inline double corner_angle(double opposite, double a, double b)
{
  return triangle_angles(opposite, a, b)[0];
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the area of the triangle with side lengths `a`, `b`, `c` by Kahan's
/// cancellation-free form of Heron's formula; 0 for lengths violating the triangle inequality.
inline double triangle_area(double a, double b, double c)
{
  std::array<double, 3> l = {a, b, c};
  std::sort(l.begin(), l.end(), [](double x, double y) { return x > y; });
  const double x = l[0], y = l[1], z = l[2];
  const double p = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
  return p > 0 ? 0.25 * std::sqrt(p) : 0.;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the cotangent of the angle opposite to the side `opposite` in the triangle with
/// side lengths `opposite`, `a`, `b`: \f$\cot\gamma = \frac{a^2 + b^2 - c^2}{4A}\f$ with
/// \f$A\f$ from triangle_area(). Degenerate triangles give \f$\pm\infty\f$.
inline double corner_cotangent(double opposite, double a, double b)
{
  const double area = triangle_area(opposite, a, b);
  const double num = a * a + b * b - opposite * opposite;
  if(area <= 0) return num >= 0 ? HUGE_VAL : -HUGE_VAL;
  return num / (4. * area);
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Lays out the triangle with side lengths `l01` (from vertex 0 to 1), `l12` and `l20` in the
/// plane: vertex 0 at the origin, vertex 1 on the positive x axis, vertex 2 in the upper half
/// plane (counterclockwise order).
inline std::array<Point_2, 3> lay_out_triangle(double l01, double l12, double l20)
{
  const double alpha = corner_angle(l12, l01, l20);
  return {{ Point_2(0, 0), Point_2(l01, 0),
            Point_2(l20 * std::cos(alpha), l20 * std::sin(alpha)) }};
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Unfolds a triangle across the planar segment from `p` to `q`: returns the point `r` to the
/// left of the directed line \f$pq\f$ with \f$|pr| = \f$ `l_pr` and \f$|qr| = \f$ `l_qr`.
/// The length of the segment is `l_pq` (the metric's value, which may differ from the planar
/// distance by rounding in a long development).
inline Point_2 unfold_vertex(const Point_2& p, const Point_2& q,
                             double l_pq, double l_qr, double l_pr)
{
  const double alpha = corner_angle(l_qr, l_pq, l_pr);
  const double dx = q.x() - p.x(), dy = q.y() - p.y();
  const double n = std::sqrt(dx * dx + dy * dy);
  const double ux = dx / n, uy = dy / n;
  const double c = std::cos(alpha), s = std::sin(alpha);
  return Point_2(p.x() + l_pr * (c * ux - s * uy), p.y() + l_pr * (s * ux + c * uy));
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_TRIANGLE_H
