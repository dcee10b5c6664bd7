// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_REFINEMENT_FIELD_TRANSFER_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_REFINEMENT_FIELD_TRANSFER_H

// A face field on a refinement of a mesh (every refined face inside one input face, new
// vertices on the input's edges) brought back to the input faces with its matching: each input
// face takes the direction of one of its pieces, and each input edge the period jump of the
// field's rotation along a path of pieces, so that the read-back is the refinement's.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/field_transfer.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// Brings a face field of `refined`, a refinement of `tm` (conforming_delaunay_refinement() or
/// refine_at_edge_points(), whose status `refinement` describes it), back to the faces of `tm`,
/// both in their embeddings.
///
/// Each input face takes the direction of one of its pieces (the pieces of a face are coplanar
/// with it, so the 3D direction is kept): on a face with a border edge the largest piece along
/// the border (a field that follows the boundary keeps doing so on `tm`), elsewhere the largest.
/// Across an input edge, the field's rotation is the sum of the refinement's rotations
/// (Levi-Civita transport plus the matching) along a path of pieces: inside the first face from
/// its representative piece to a piece on the edge, across the edge, then inside the second face
/// to its representative piece. The input matching is the period jump that gives that rotation,
/// so field_singularities() on `tm` reads back the refinement's singularities at the input
/// vertices, provided the new vertices carry none (checked: all the paths across one input edge
/// must agree).
///
/// `max_distortion` in the status: the largest rotation of the field between two pieces of one
/// input face (how much it turns inside a face that keeps one direction); `mean_distortion` its
/// mean over the input faces. Fails with a message when two paths across one input edge turn the
/// field differently (by more than \f$10^{-6}\f$ rad: a singularity at a new vertex).
///
/// \param refined the refinement, in the vertex order of `refinement` (the input's vertices first)
/// \param tm the input mesh
/// \param refinement the refinement's status: `inserted` and `face_origin`
/// \param N the symmetry order
/// \param angles per face of `refined`: the field's angle in the embedded face frame
/// \param matching per edge of `refined`: its period jump (convention of field_singularities())
/// \param input_angles receives per face of `tm` the angle in its embedded face frame
/// \param input_matching receives per edge of `tm` the period jump (0 on border edges)
template <typename RefinedMesh, typename TriangleMesh, typename FaceAngleMap, typename EdgeMatchingMap,
          typename OutputFaceAngleMap, typename OutputEdgeMatchingMap>
Field_transfer_status transfer_face_field_from_refinement(const RefinedMesh& refined, const TriangleMesh& tm,
                                                          const Delaunay_refinement_status& refinement, int N,
                                                          const FaceAngleMap& angles, const EdgeMatchingMap& matching,
                                                          OutputFaceAngleMap input_angles, OutputEdgeMatchingMap input_matching)
{
  typedef typename boost::property_traits<typename boost::property_map<RefinedMesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel::Vector_3 Vector;
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const Intrinsic_mesh<RefinedMesh> rim(refined, parameters::default_values());
  const Intrinsic_mesh<TriangleMesh> cim(tm, parameters::default_values());
  const internal::Mesh_arrays<RefinedMesh>& r = rim.arrays();
  const internal::Mesh_arrays<TriangleMesh>& c = cim.arrays();
  const std::size_t nv = c.number_of_vertices(), nf = c.number_of_faces();
  Field_transfer_status st;
  if(r.number_of_faces() != refinement.face_origin.size() || r.number_of_vertices() != nv + refinement.inserted.size()) {
    std::ostringstream os;
    os << "the refinement has " << r.number_of_faces() << " faces and " << r.number_of_vertices() << " vertices; its status lists "
       << refinement.face_origin.size() << " faces and " << nv << " + " << refinement.inserted.size() << " vertices";
    throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
  }
  const double period = 2 * CGAL_PI / N;
  std::vector<double> beta(r.number_of_faces());
  for(std::size_t f = 0; f < beta.size(); ++f) beta[f] = double(get(angles, r.faces[f]));
  // the rotation across the refined edge of h, from face(h ^ 1) into face(h)
  auto rotation = [&](int h) {
    const int e2 = h & ~1;
    const double rot = internal::wrap_angle(beta[std::size_t(r.face[std::size_t(e2)])] - beta[std::size_t(r.face[std::size_t(e2 + 1)])] -
                                            internal::transport_increment(r, e2)) +
                       period * double(get(matching, r.edges[std::size_t(e2 >> 1)]));
    return (h & 1) ? -rot : rot;
  };

  // 1. per input face, the rotation from its representative piece to each of its pieces (the
  // pieces of a face are a triangulated polygon: any path inside it gives the same sum)
  // the representative piece: on a face with a border edge the largest piece along the border
  // (a field that follows the boundary keeps doing so), elsewhere the largest piece
  std::vector<int> first(nf, -1);
  std::vector<std::pair<bool, double>> best(nf, std::make_pair(false, -1.));
  auto on_border = [](const auto& a, int f) {
    for(int k = 0, h = a.face_halfedge[std::size_t(f)]; k < 3; ++k, h = a.next[std::size_t(h)])
      if(a.face[std::size_t(h ^ 1)] < 0) return true;
    return false;
  };
  for(std::size_t f = 0; f < refinement.face_origin.size(); ++f) {
    const std::size_t o = refinement.face_origin[f];
    if(o >= nf) throw Input_error(Input_error::INVALID_ARGUMENT, "face_origin lists input face " + std::to_string(o) + " of " + std::to_string(nf));
    const int h = r.face_halfedge[f];
    const double a = r.edge_length(h), b = r.edge_length(r.next[std::size_t(h)]), d = r.edge_length(r.prev(h));
    const double area = std::sqrt((std::max)(0., (a + b + d) * (-a + b + d) * (a - b + d) * (a + b - d)));   // 4x Heron's
    const std::pair<bool, double> score(on_border(r, int(f)) && on_border(c, int(o)), area);
    if(score > best[o]) { best[o] = score; first[o] = int(f); }
  }
  std::vector<double> rho(r.number_of_faces(), 0.);
  std::vector<char> seen(r.number_of_faces(), 0);
  std::vector<int> stack;
  double total = 0;
  for(std::size_t o = 0; o < nf; ++o) {
    if(first[o] < 0) { st.message = "input face " + std::to_string(o) + " has no piece in the refinement"; return st; }
    double widest = 0;
    stack.assign(1, first[o]);
    seen[std::size_t(first[o])] = 1;
    while(!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for(int k = 0, h = r.face_halfedge[std::size_t(f)]; k < 3; ++k, h = r.next[std::size_t(h)]) {
        const int g = r.face[std::size_t(h ^ 1)];
        if(g < 0 || seen[std::size_t(g)] || refinement.face_origin[std::size_t(g)] != o) continue;
        seen[std::size_t(g)] = 1;
        rho[std::size_t(g)] = rho[std::size_t(f)] + rotation(h ^ 1);
        widest = (std::max)(widest, std::abs(rho[std::size_t(g)]));
        stack.push_back(g);
      }
    }
    st.max_distortion = (std::max)(st.max_distortion, widest);
    total += widest;
  }
  st.mean_distortion = nf ? total / double(nf) : 0.;

  // 2. the input faces' directions: their representative pieces' in 3D, in the input face frames
  auto vectors = get(CGAL::dynamic_face_property_t<Vector>(), refined);
  field_angles_to_vectors(refined, angles, vectors);
  auto input_vectors = get(CGAL::dynamic_face_property_t<Vector>(), tm);
  for(std::size_t o = 0; o < nf; ++o) put(input_vectors, c.faces[o], get(vectors, r.faces[std::size_t(first[o])]));
  vectors_to_face_angles(tm, input_vectors, input_angles);
  std::vector<double> alpha(nf);
  for(std::size_t o = 0; o < nf; ++o) alpha[o] = double(get(input_angles, c.faces[o]));

  // 3. the input matching: per refined edge between pieces of two input faces, the input edge it
  // lies on (through a new vertex's edge, else the input halfedge between its two input vertices)
  std::vector<double> input_rotation(c.number_of_edges(), 0.);
  std::vector<char> has_rotation(c.number_of_edges(), 0);
  auto input_vertex = [&](int v) { return c.vertices[std::size_t(v)]; };
  for(std::size_t e = 0; e < r.number_of_edges(); ++e) {
    const int h = int(2 * e);
    const int fl = r.face[std::size_t(h)], fr = r.face[std::size_t(h ^ 1)];
    if(fl < 0 || fr < 0) continue;
    const std::size_t ol = refinement.face_origin[std::size_t(fl)], orr = refinement.face_origin[std::size_t(fr)];
    if(ol == orr) continue;
    const int s = r.source(h), t = r.target[std::size_t(h)];
    long ie = -1;
    if(s >= int(nv)) ie = long(refinement.inserted[std::size_t(s) - nv].first);
    else if(t >= int(nv)) ie = long(refinement.inserted[std::size_t(t) - nv].first);
    else {
      const auto ch = halfedge(input_vertex(s), input_vertex(t), tm);
      if(!ch.second) { st.message = "refined edge " + std::to_string(e) + " joins input vertices that no input edge joins"; return st; }
      ie = long(cim.edge_index(edge(ch.first, tm)));
    }
    const int ch = int(2 * ie);   // input halfedge 2 ie: from face(ch ^ 1) into face(ch)
    const int cl = c.face[std::size_t(ch)], cr = c.face[std::size_t(ch ^ 1)];
    if(cl < 0 || cr < 0 || !((std::size_t(cl) == ol && std::size_t(cr) == orr) || (std::size_t(cl) == orr && std::size_t(cr) == ol))) {
      st.message = "refined edge " + std::to_string(e) + " lies on input edge " + std::to_string(ie) + ", which does not join its pieces' faces";
      return st;
    }
    // from the representative piece of face(ch ^ 1) to the representative piece of face(ch)
    const bool same = std::size_t(cl) == ol;   // refined h enters the piece of face(ch)
    const double across = same ? rotation(h) : rotation(h ^ 1);
    const int into = same ? fl : fr, from = same ? fr : fl;
    const double total_rotation = rho[std::size_t(from)] + across - rho[std::size_t(into)];
    if(!has_rotation[std::size_t(ie)]) { has_rotation[std::size_t(ie)] = 1; input_rotation[std::size_t(ie)] = total_rotation; }
    else if(!(std::abs(total_rotation - input_rotation[std::size_t(ie)]) <= 1e-6)) {
      std::ostringstream os;
      os << "two paths across input edge " << ie << " turn the field by " << input_rotation[std::size_t(ie)] << " and " << total_rotation
         << " rad: the refinement's field has a singularity at a new vertex on it";
      st.message = os.str();
      return st;
    }
  }
  for(std::size_t e = 0; e < c.number_of_edges(); ++e) {
    const int h = int(2 * e);
    if(c.face[std::size_t(h)] < 0 || c.face[std::size_t(h ^ 1)] < 0) { put(input_matching, c.edges[e], 0); continue; }
    if(!has_rotation[e]) { st.message = "input edge " + std::to_string(e) + " has no piece in the refinement"; return st; }
    const double principal = internal::wrap_angle(alpha[std::size_t(c.face[std::size_t(h)])] - alpha[std::size_t(c.face[std::size_t(h ^ 1)])] -
                                                  internal::transport_increment(c, h));
    put(input_matching, c.edges[e], int(std::lround((input_rotation[e] - principal) / period)));
  }
  st.success = true;
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_REFINEMENT_FIELD_TRANSFER_H
