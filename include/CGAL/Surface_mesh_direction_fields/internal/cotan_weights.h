// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_COTAN_WEIGHTS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_COTAN_WEIGHTS_H

#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Per edge, the cotan weight (cot alpha + cot beta) / 2 of the metric (one term on boundary
// edges), each cotangent raised to lowest_cot first; per face the cotangent of the corner
// opposite a side of length a is (b^2 + c^2 - a^2) / 4A.
template <typename TM>
std::vector<double> cotan_edge_weights(const Mesh_arrays<TM>& m,
                                       double lowest_cot = -std::numeric_limits<double>::infinity())
{
  std::vector<double> w(m.number_of_edges(), 0.);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
    const double l0 = m.edge_length(h0), l1 = m.edge_length(h1), l2 = m.edge_length(h2);
    const double q0 = l0 * l0, q1 = l1 * l1, q2 = l2 * l2;
    const double inv4A = 1. / (4. * triangle_area(l0, l1, l2));
    w[std::size_t(h0 >> 1)] += 0.5 * (std::max)((q1 + q2 - q0) * inv4A, lowest_cot);
    w[std::size_t(h1 >> 1)] += 0.5 * (std::max)((q2 + q0 - q1) * inv4A, lowest_cot);
    w[std::size_t(h2 >> 1)] += 0.5 * (std::max)((q0 + q1 - q2) * inv4A, lowest_cot);
  }
  return w;
}

// The cotan weights with every weight below 1e-3 times the mean of the positive ones (or not
// finite) raised to that floor: positive weights for a Laplacian that is positive definite
// once one value per component is fixed.
template <typename TM>
std::vector<double> floored_cotan_edge_weights(const Mesh_arrays<TM>& m)
{
  std::vector<double> w = cotan_edge_weights(m);
  double sum = 0;
  std::size_t count = 0;
  for(double x : w) if(x > 0 && std::isfinite(x)) { sum += x; ++count; }
  const double floor = 1e-3 * (count ? sum / double(count) : 1.);
  for(double& x : w) x = (x >= floor && std::isfinite(x)) ? x : floor;
  return w;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_COTAN_WEIGHTS_H
