// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_PROPAGATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_PROPAGATION_H

// A face-based field that is parallel for a trivial connection, by propagation along a
// breadth-first spanning forest of the faces (Crane et al. 2010, Eq. 3), and the 3D frames of
// the faces.
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Breadth-first spanning forest of the faces, rooted at the first constrained face of each
// component, else its first guide face, else its first face; order_ lists parents before
// children, parent_cross_[f] is the halfedge crossed from the parent into f.
struct Face_tree
{
  std::vector<int> parent_cross_, parent_face_, order_, roots_;

  template <typename TM>
  void build(const Mesh_arrays<TM>& m_, const std::vector<int>& constrained_faces_,
             const std::vector<int>& guide_faces_)
  {
    const int nf = int(m_.number_of_faces());
    parent_cross_.assign(nf, -1);
    parent_face_.assign(nf, -1);
    roots_.clear();
    order_.clear();
    order_.reserve(nf);
    std::vector<char> visited(nf, 0);
    auto grow = [&](int root) {
      std::size_t head = order_.size();
      visited[root] = 1;
      order_.push_back(root);
      roots_.push_back(root);
      while(head < order_.size()) {
        const int f = order_[head++];
        int h = m_.face_halfedge[f];
        for(int k = 0; k < 3; ++k, h = m_.next[h]) {
          const int g = m_.face[h ^ 1];
          if(g < 0 || visited[g]) continue;
          visited[g] = 1;
          parent_cross_[g] = h ^ 1;
          parent_face_[g] = f;
          order_.push_back(g);
        }
      }
    };
    for(int f : constrained_faces_) if(!visited[f]) grow(f);
    for(int f : guide_faces_) if(!visited[f]) grow(f);   // so that every other guide has a partner
    for(int f = 0; f < nf; ++f) if(!visited[f]) grow(f);
  }
};

// Per face, the linear map from the metric's triangle to the embedded one: the embedded edge
// vectors E1 = p1 - p0, E2 = p2 - p0 (p0 = source(halfedge(f))) and the metric's layout of the
// same corners, p1 = (l0, 0), p2 = (x2, y2). A direction of angle beta in the face frame is
// a (l0, 0) + b (x2, y2) and maps to a E1 + b E2; when the metric is the embedding's this is
// cos(beta) e1 + sin(beta) e2 with the unit frame of the embedded face.
struct Face_map
{
  double E1[3], E2[3];
  double l0, x2, y2;
};

template <typename TM, typename VPM>
void face_maps(const Mesh_arrays<TM>& m_, VPM vpm, std::vector<Face_map>& maps)
{
  maps.resize(m_.number_of_faces());
  for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
    const int h0 = m_.face_halfedge[f], h1 = m_.next[h0], h2 = m_.next[h1];
    double p[3][3];
    const int vs[3] = {m_.source(h0), m_.target[h0], m_.target[h1]};
    for(int i = 0; i < 3; ++i) {
      const auto& q = get(vpm, m_.vertices[vs[i]]);
      p[i][0] = CGAL::to_double(q.x()); p[i][1] = CGAL::to_double(q.y()); p[i][2] = CGAL::to_double(q.z());
    }
    Face_map& fm = maps[f];
    for(int k = 0; k < 3; ++k) { fm.E1[k] = p[1][k] - p[0][k]; fm.E2[k] = p[2][k] - p[0][k]; }
    const double l0 = m_.edge_length(h0), l1 = m_.edge_length(h1), l2 = m_.edge_length(h2);
    fm.l0 = l0;
    fm.x2 = (l0 * l0 + l2 * l2 - l1 * l1) / (2 * l0);
    fm.y2 = 2 * triangle_area(l0, l1, l2) / l0;
  }
}

// The unit 3D direction of angle beta of face map fm (see Face_map).
inline std::array<double, 3> embedded_direction(const Face_map& fm, double beta)
{
  const double b = std::sin(beta) / fm.y2, a = (std::cos(beta) - b * fm.x2) / fm.l0;
  std::array<double, 3> v = {{a * fm.E1[0] + b * fm.E2[0], a * fm.E1[1] + b * fm.E2[1], a * fm.E1[2] + b * fm.E2[2]}};
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if(l > 0) for(double& x : v) x /= l;
  return v;
}

// Angles into [0, 2pi). Subtracting 2pi floor(b / 2pi) rather than std::fmod, which took a
// quarter of an edit at 400k faces; the rounding is eps |b|, that of the propagation itself.
inline void wrap_field(std::vector<double>& beta)
{
  const double two_pi = 2 * CGAL_PI;
  for(double& b : beta) {
    if(b >= 0 && b < two_pi) continue;
    b -= two_pi * std::floor(b / two_pi);
    if(b >= two_pi) b -= two_pi;
    if(b < 0) b += two_pi;
    if(b >= two_pi) b = 0;   // b was -0 or a negative value that rounds to 2 pi
  }
}

// Rotates each component without hard constraints so that its guides fit best.
inline void fit_rotation_to_guides(const Topology_arrays& topo_, int N_, const std::vector<int>& constrained_faces_,
                                   const std::vector<int>& guide_faces_, const std::vector<double>& guide_angles_,
                                   std::vector<double>& beta)
{
  if(guide_faces_.empty()) return;
  const std::size_t nc = topo_.components.size();
  std::vector<char> hard(nc, 0);
  for(int f : constrained_faces_) hard[topo_.face_component[f]] = 1;
  std::vector<double> sx(nc, 0.), sy(nc, 0.);
  for(std::size_t i = 0; i < guide_faces_.size(); ++i) {
    const int c = topo_.face_component[guide_faces_[i]];
    const double d = N_ * (guide_angles_[i] - beta[guide_faces_[i]]);
    sx[c] += std::cos(d);
    sy[c] += std::sin(d);
  }
  std::vector<double> rot(nc, 0.);
  for(std::size_t c = 0; c < nc; ++c)
    if(!hard[c] && (sx[c] != 0 || sy[c] != 0)) rot[c] = std::atan2(sy[c], sx[c]) / N_;
  for(std::size_t f = 0; f < beta.size(); ++f) beta[f] += rot[topo_.face_component[f]];
}


// The field parallel for the connection whose angle across halfedge h (from face(h ^ 1) into
// face(h)) is connection_angle(h), before wrapping: each tree root gets its constraint angle or
// start_angle. With special_root >= 0, the component of that face is then propagated again,
// from it with start_angle, along a breadth-first tree rooted there.
template <typename TM, typename ConnectionAngle>
void propagate_field(const Mesh_arrays<TM>& m_, const Face_tree& tree, const ConnectionAngle& connection_angle,
                     const std::vector<int>& constrained_faces_, const std::vector<double>& constraint_angles_,
                     double start_angle, int special_root, std::vector<double>& beta)
{
  const int nf = int(m_.number_of_faces());
  beta.assign(nf, 0.);
  std::vector<int> constraint_of(nf, -1);
  for(std::size_t i = 0; i < constrained_faces_.size(); ++i) constraint_of[constrained_faces_[i]] = int(i);
  for(int f : tree.order_) {
    const int h = tree.parent_cross_[f];
    if(h < 0) beta[f] = constraint_of[f] >= 0 ? constraint_angles_[constraint_of[f]] : start_angle;
    else beta[f] = beta[tree.parent_face_[f]] + connection_angle(h);
  }
  if(special_root < 0) return;
  std::vector<int> queue = {special_root};
  std::vector<char> visited(nf, 0);
  visited[special_root] = 1;
  beta[special_root] = start_angle;
  for(std::size_t head = 0; head < queue.size(); ++head) {
    const int f = queue[head];
    int h = m_.face_halfedge[f];
    for(int k = 0; k < 3; ++k, h = m_.next[h]) {
      const int g = m_.face[h ^ 1];
      if(g < 0 || visited[g]) continue;
      visited[g] = 1;
      beta[g] = beta[f] + connection_angle(h ^ 1);
      queue.push_back(g);
    }
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_PROPAGATION_H
