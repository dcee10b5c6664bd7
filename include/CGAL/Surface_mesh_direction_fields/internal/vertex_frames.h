// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VERTEX_FRAMES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VERTEX_FRAMES_H

// Vertex-based fields (Lai et al. 2010, section 4.1): a direction per vertex, measured in a
// frame of its one-ring scaled to span 2 pi, its transport along edges, and its face version.

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Direction of outgoing halfedge h at its source v, measured counterclockwise from vertex_out[v]
// in the metric, scaled by 2 pi / (angle sum) so that the directions at v span 2 pi.
template <typename TM>
struct Vertex_frames
{
  std::vector<double> direction;   // per halfedge (outgoing at its source)
  template <typename M>
  explicit Vertex_frames(const M& m) : direction(m.number_of_halfedges(), 0.)
  {
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
      if(m.is_isolated(int(v)) || m.is_boundary_vertex(int(v))) continue;
      const int h0 = m.vertex_out[v];
      double total = 0;
      int h = h0;
      do { total += m.angle[std::size_t(h)]; h = m.ccw_out(h); } while(h != h0);
      double a = 0;
      h = h0;
      do { direction[std::size_t(h)] = a * 2 * CGAL_PI / total; a += m.angle[std::size_t(h)]; h = m.ccw_out(h); } while(h != h0);
    }
  }
  // carrying a direction at source(h) across h to target(h): added to its angle
  double transport(int h) const { return direction[std::size_t(h ^ 1)] + CGAL_PI - direction[std::size_t(h)]; }
};

// The face version of a vertex field alpha (angles in the frames above), in [0, 2 pi): each face
// takes it from a corner that is not a cone (angle defect below 1e-6); a face whose corners are
// all cones takes it, by Levi-Civita transport, from a neighbouring face that has it (the field
// is parallel across the edge up to the small rotation of the 1-form), and faces with no way to
// such a face (a mesh of cones only) from their first corner.
template <typename TM, typename FaceAngleMap>
void vertex_field_to_face_angles(const Mesh_arrays<TM>& m, const Vertex_frames<TM>& frames, const std::vector<double>& K,
                                 const std::vector<double>& alpha, FaceAngleMap face_angles)
{
  const std::size_t nf = m.number_of_faces();
  std::vector<double> angle(nf, 0.);
  std::vector<char> has(nf, 0);
  std::vector<int> queue;
  for(std::size_t f = 0; f < nf; ++f) {
    const int h0 = m.face_halfedge[f];
    int h = h0, pick = -1;
    for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)])
      if(std::abs(K[std::size_t(m.source(h))]) < 1e-6) { pick = h; break; }
    if(pick < 0) continue;
    // a direction of vertex angle a at source(pick) makes angle (a - direction(pick)) with pick,
    // which has direction halfedge_direction(pick) in the face frame
    angle[f] = alpha[std::size_t(m.source(pick))] - frames.direction[std::size_t(pick)] + halfedge_direction(m, pick);
    has[f] = 1;
    queue.push_back(int(f));
  }
  for(std::size_t q = 0; q < queue.size(); ++q) {
    const int g = queue[q];
    const int h0 = m.face_halfedge[std::size_t(g)];
    int h = h0;
    for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
      const int f = m.face[std::size_t(h ^ 1)];
      if(f < 0 || has[std::size_t(f)]) continue;
      angle[std::size_t(f)] = angle[std::size_t(g)] + transport_increment(m, h ^ 1);   // from face(h) = g into f
      has[std::size_t(f)] = 1;
      queue.push_back(f);
    }
  }
  for(std::size_t f = 0; f < nf; ++f) {
    const int h0 = m.face_halfedge[f];
    const double a = has[f] ? angle[f] : alpha[std::size_t(m.source(h0))] - frames.direction[std::size_t(h0)];
    put(face_angles, m.faces[f], a - 2 * CGAL_PI * std::floor(a / (2 * CGAL_PI)));
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VERTEX_FRAMES_H
