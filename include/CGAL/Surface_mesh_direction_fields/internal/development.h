// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DEVELOPMENT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DEVELOPMENT_H

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>

#include <array>
#include <cmath>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Wraps an angle to (-pi, pi].
inline double wrap_angle(double a)
{
  a = std::remainder(a, 2 * CGAL_PI);
  if(a <= -CGAL_PI) a += 2 * CGAL_PI;
  return a;
}

// Angle-defect / geodesic-curvature of every vertex (0 for isolated vertices).
template <typename TM>
void vertex_curvatures(const Mesh_arrays<TM>& m, std::vector<double>& k)
{
  const std::size_t nv = m.number_of_vertices();
  k.assign(nv, 0.);
  std::vector<char> boundary(nv, 0);
  for(std::size_t h = 0; h < m.number_of_halfedges(); ++h) {
    if(m.face[h] >= 0) k[m.source(int(h))] += m.angle[h];
    else boundary[m.source(int(h))] = 1;
  }
  for(std::size_t v = 0; v < nv; ++v)
    if(!m.is_isolated(int(v))) k[v] = (boundary[v] ? CGAL_PI : 2 * CGAL_PI) - k[v];
}

// Direction of halfedge h in the frame of face(h), whose x axis is face_halfedge[face(h)]
// and whose orientation is counterclockwise (the face's own orientation).
template <typename TM>
double halfedge_direction(const Mesh_arrays<TM>& m, int h)
{
  const int h0 = m.face_halfedge[m.face[h]];
  if(h == h0) return 0.;
  const int h1 = m.next[h0];
  const double t1 = CGAL_PI - m.angle[h1];
  if(h == h1) return t1;
  return t1 + CGAL_PI - m.angle[m.next[h1]];
}

// The border edge a face's field is drawn against (its interior halfedge in face f), -1 if f has
// none: the only one, or of two (a corner face, whose tip is on no other face) the one that
// ends at the tip (its next halfedge is the other). Around every boundary vertex one of
// its two border edges is then the one of its face (a strip of corner faces included).
template <typename TM>
int followed_border_halfedge(const Mesh_arrays<TM>& m, int f)
{
  const int h0 = m.face_halfedge[std::size_t(f)];
  int first = -1;
  for(int i = 0, h = h0; i < 3; ++i, h = m.next[std::size_t(h)]) {
    if(m.face[std::size_t(h ^ 1)] >= 0) continue;
    if(first < 0) first = h;
    if(m.face[std::size_t(m.next[std::size_t(h)] ^ 1)] < 0 && m.face[std::size_t(m.next[std::size_t(m.next[std::size_t(h)])] ^ 1)] >= 0)
      return h;
  }
  return first;
}

// Change of a tangent direction's angle when it is carried by the Levi-Civita connection
// across the edge of h, from face(opposite(h)) into face(h): alpha_j = alpha_i + increment.
template <typename TM>
double transport_increment(const Mesh_arrays<TM>& m, int h)
{
  return halfedge_direction(m, h) + CGAL_PI - halfedge_direction(m, h ^ 1);
}

// Validates a dual path: no border crossing, consecutive crossings share a face, and (if
// `closed`) the last crossing enters the first face.
template <typename TM>
void check_dual_path(const Mesh_arrays<TM>& m, const std::vector<int>& path, bool closed)
{
  if(path.empty())
    throw Input_error(Input_error::INVALID_CYCLE, "empty dual path");
  for(std::size_t i = 0; i < path.size(); ++i) {
    const int h = path[i];
    if(m.face[h] < 0 || m.face[h ^ 1] < 0) {
      std::ostringstream os;
      os << "dual path element " << i << " crosses the boundary edge " << (h >> 1);
      throw Input_error(Input_error::INVALID_CYCLE, os.str());
    }
    if(i + 1 < path.size() && m.face[h] != m.face[path[i + 1] ^ 1]) {
      std::ostringstream os;
      os << "dual path elements " << i << " and " << i + 1 << " do not share a face";
      throw Input_error(Input_error::INVALID_CYCLE, os.str());
    }
  }
  if(closed && m.face[path.back()] != m.face[path.front() ^ 1])
    throw Input_error(Input_error::INVALID_CYCLE,
                      "dual cycle is not closed: the last crossing does not enter the first face");
}

// Sum of the Levi-Civita transport increments along a dual path (not wrapped).
template <typename TM>
double transport_along(const Mesh_arrays<TM>& m, const std::vector<int>& path)
{
  double a = 0;
  for(int h : path) a += transport_increment(m, h);
  return a;
}

// Positions of a face's vertices (sources of face_halfedge, next, next-next) in its
// canonical layout.
template <typename TM>
std::array<Point_2, 3> canonical_layout(const Mesh_arrays<TM>& m, int f)
{
  const int h0 = m.face_halfedge[f], h1 = m.next[h0], h2 = m.next[h1];
  return lay_out_triangle(m.edge_length(h0), m.edge_length(h1), m.edge_length(h2));
}

// Develops the faces of a dual path; calls visit(face, positions) for the first face and after
// each crossing (positions ordered as in canonical_layout()).
template <typename TM, typename Visitor>
void develop(const Mesh_arrays<TM>& m, const std::vector<int>& path, Visitor visit)
{
  int f = m.face[path.front() ^ 1];
  std::array<Point_2, 3> pos = canonical_layout(m, f);
  visit(f, pos);
  for(int h : path) {
    // locate opposite(h) in the current face
    const int o = h ^ 1;
    int i = 0;
    for(int g = m.face_halfedge[f]; g != o; g = m.next[g]) ++i;
    const Point_2 p = pos[(i + 1) % 3];   // source(h) = target(o)
    const Point_2 q = pos[i];             // target(h) = source(o)
    const int hn = m.next[h], hp = m.next[hn];
    const Point_2 r = unfold_vertex(p, q, m.edge_length(h), m.edge_length(hn), m.edge_length(hp));
    f = m.face[h];
    int j = 0;
    for(int g = m.face_halfedge[f]; g != h; g = m.next[g]) ++j;
    pos[j] = p;
    pos[(j + 1) % 3] = q;
    pos[(j + 2) % 3] = r;
    visit(f, pos);
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DEVELOPMENT_H
