// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_WINDING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_WINDING_H

// A map can be locally non-injective with every triangle counterclockwise: its image may wrap
// twice around an interior vertex (a branch point), or the boundary may fold back on its grid
// line at a vertex that is no corner (the image angle 2 pi instead of pi). Both show in the sum
// of the image's corner angles around the vertex, which must be the angle the field and the
// boundary ask for.

#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/seam_layout.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The angle the map must have around each vertex: on the boundary pi minus its corner's turning
// (0 off the corners: the boundary runs straight); inside, the value congruent modulo 2 pi to
// 2 pi minus the field's rotation around it that is nearest to the metric's angle sum (the
// metric's own for a flat cone metric whose cones are the singularities).
template <typename TM>
std::vector<double> map_angle_sums_expected(const Mesh_arrays<TM>& m, const Seam_layout& s)
{
  const std::size_t nv = m.number_of_vertices();
  const double quarter = CGAL_PI / 2;
  std::vector<double> expected(nv, 0.);
  for(std::size_t v = 0; v < nv; ++v) {
    if(m.is_isolated(int(v))) continue;
    if(m.is_boundary_vertex(int(v))) { expected[v] = CGAL_PI - s.turn_quarters[v] * quarter; continue; }
    double sum = 0;
    const int x0 = m.vertex_out[v];
    int x = x0;
    do { sum += m.angle[std::size_t(x)]; x = m.ccw_out(x); } while(x != x0);
    const double base = 2 * CGAL_PI + (((s.turns[v] % 4) + 4) % 4) * quarter;
    expected[v] = base + 2 * CGAL_PI * std::round((sum - base) / (2 * CGAL_PI));
  }
  return expected;
}

// The vertices whose image angle (the sum, over the faces around them, of the map's corner
// angles, signed) is more than an eighth of a turn from `expected`. `image(x)` is the map's
// image of the corner at source(x) in face(x).
template <typename TM, typename CornerImage>
std::vector<int> winding_faults(const Mesh_arrays<TM>& m, const std::vector<double>& expected, const CornerImage& image)
{
  typedef std::complex<double> C;
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces();
  std::vector<double> sum(nv, 0.);
  for(std::size_t f = 0; f < nf; ++f) {
    const int x0 = m.face_halfedge[f], x1 = m.next[std::size_t(x0)], x2 = m.next[std::size_t(x1)];
    const C p[3] = {image(x0), image(x1), image(x2)};
    const int x[3] = {x0, x1, x2};
    for(int i = 0; i < 3; ++i) sum[std::size_t(m.source(x[i]))] += std::arg((p[(i + 2) % 3] - p[i]) / (p[(i + 1) % 3] - p[i]));
  }
  std::vector<int> faults;
  for(std::size_t v = 0; v < nv; ++v)
    if(!m.is_isolated(int(v)) && !(std::abs(sum[v] - expected[v]) <= CGAL_PI / 4)) faults.push_back(int(v));
  return faults;
}

// The faces around the vertices `vs` (a face around two of them twice).
template <typename TM>
std::vector<std::size_t> faces_around(const Mesh_arrays<TM>& m, const std::vector<int>& vs)
{
  std::vector<std::size_t> faces;
  for(int v : vs) {
    int g = m.vertex_out[std::size_t(v)], g0 = g;
    do { if(m.face[std::size_t(g)] >= 0) faces.push_back(std::size_t(m.face[std::size_t(g)])); g = m.ccw_out(g); } while(g != g0);
  }
  return faces;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_WINDING_H
