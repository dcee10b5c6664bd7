// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_PARALLEL_ROSY_FIELD_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_PARALLEL_ROSY_FIELD_H

// The parallel N-RoSy field of a flat cone metric (Lai et al. 2010, Theorem 3.2, Corollary 3.3,
// section 4.1.1), and the map of face angles of any metric to 3D vectors of the embedding.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/homotopy_basis.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/field_propagation.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Outcome of parallel_rosy_field().
struct Parallel_rosy_status
{
  /// `true` if the field is parallel across every interior edge: its rotation there, relative
  /// to the metric's Levi-Civita transport, is a multiple of \f$2\pi/N\f$ within the tolerance.
  /// By Theorem 3.2 of Lai et al. this holds exactly when every rotational holonomy of the
  /// metric is a multiple of \f$2\pi/N\f$ (see parallel_rosy_compatibility()).
  bool success = false;
  std::string message;          ///< empty on success
  int N = 1;                    ///< the symmetry order
  double max_deviation = 0;     ///< the largest distance of an edge's rotation to the nearest multiple of \f$2\pi/N\f$
  std::size_t inconsistent_edges = 0;   ///< interior edges farther than the tolerance
};

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// The parallel N-RoSy field of the metric: a direction in the first face of each component
/// (angle 0 in its frame), carried to every other face by the Levi-Civita transport of the
/// metric along a breadth-first tree of the faces. On a flat cone metric whose rotational
/// holonomies are multiples of \f$2\pi/N\f$ (on a sphere: cone curvatures multiples of
/// \f$2\pi/N\f$, Corollary 3.3) the field is then parallel across every edge, and its only
/// singularities are the cones, of index \f$K/2\pi\f$; it equals the field of the trivial
/// connection computed on the same metric with those indices (whose adjustment angles vanish,
/// see the manual). Otherwise the status says across how many edges it is not.
///
/// `angles` receives one angle per face, in the face frames (counterclockwise from
/// `halfedge(f)`, measured in the metric's triangle; field_angles_to_vectors() maps them to the
/// embedding), in \f$[0, 2\pi)\f$.
///
/// Named parameters: `edge_length_map` (the flat cone metric, default: Euclidean lengths) or
/// `intrinsic_mesh`, the index maps as for `Intrinsic_mesh`, and `holonomy_tolerance` (radians,
/// default \f$10^{-6}\f$). Throws `Input_error` for \f$N < 1\f$ and the errors of `Intrinsic_mesh`.
template <typename TriangleMesh, typename FaceAngleMap, typename NamedParameters = parameters::Default_named_parameters>
Parallel_rosy_status parallel_rosy_field(const TriangleMesh& tm, int N, FaceAngleMap angles,
                                         const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const double tolerance = choose_parameter(get_parameter(np, internal_np::holonomy_tolerance), 1e-6);
  if(!(tolerance >= 0)) throw Input_error(Input_error::INVALID_ARGUMENT, "holonomy_tolerance must be non-negative");
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const std::size_t nf = m.number_of_faces();
  std::vector<double> beta(nf, 0.);
  std::vector<char> done(nf, 0);
  std::vector<int> queue;
  for(std::size_t root = 0; root < nf; ++root) {   // one breadth-first tree per component
    if(done[root]) continue;
    done[root] = 1;
    queue.assign(1, int(root));
    for(std::size_t k = 0; k < queue.size(); ++k) {
      const int f = queue[k];
      int h = m.face_halfedge[std::size_t(f)];
      for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
        const int g = m.face[std::size_t(h ^ 1)];
        if(g < 0 || done[std::size_t(g)]) continue;
        done[std::size_t(g)] = 1;
        beta[std::size_t(g)] = beta[std::size_t(f)] + internal::transport_increment(m, h ^ 1);
        queue.push_back(g);
      }
    }
  }
  Parallel_rosy_status st;
  st.N = N;
  const double period = 2 * CGAL_PI / N;
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
    const int h = int(2 * e);
    if(m.face[std::size_t(h)] < 0 || m.face[std::size_t(h ^ 1)] < 0) continue;
    const double r = beta[std::size_t(m.face[std::size_t(h)])] - beta[std::size_t(m.face[std::size_t(h ^ 1)])] - internal::transport_increment(m, h);
    const double d = std::abs(std::remainder(r, period));
    st.max_deviation = (std::max)(st.max_deviation, d);
    if(!(d <= tolerance)) ++st.inconsistent_edges;
  }
  internal::wrap_field(beta);
  for(std::size_t f = 0; f < nf; ++f) put(angles, m.faces[f], beta[f]);
  st.success = st.inconsistent_edges == 0;
  if(!st.success) {
    std::ostringstream os;
    os.precision(3);
    os << "no parallel " << N << "-RoSy field: across " << st.inconsistent_edges << " edges the transported field differs by up to "
       << st.max_deviation << " rad from a multiple of 2 pi / " << N << " (the holonomy group is not in the rotations by 2 pi / " << N << ")";
    st.message = os.str();
  }
  return st;
}

namespace internal {

// The embedded direction e of side k of a face map (0: corner 0 -> 1, 1: 1 -> 2, 2: 2 -> 0) and
// t = n x e, n the face normal.
struct Face_map_axes
{
  double e[3], t[3];
  Face_map_axes(const Face_map& fm, int k)
  {
    double s[3];
    for(int i = 0; i < 3; ++i) s[i] = k == 0 ? fm.E1[i] : k == 1 ? fm.E2[i] - fm.E1[i] : -fm.E2[i];
    const double n[3] = {fm.E1[1] * fm.E2[2] - fm.E1[2] * fm.E2[1], fm.E1[2] * fm.E2[0] - fm.E1[0] * fm.E2[2],
                         fm.E1[0] * fm.E2[1] - fm.E1[1] * fm.E2[0]};
    const double sl = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]), nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for(int i = 0; i < 3; ++i) e[i] = sl > 0 ? s[i] / sl : 0;
    const double c[3] = {n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2], n[0] * e[1] - n[1] * e[0]};
    for(int i = 0; i < 3; ++i) t[i] = nl > 0 ? c[i] / nl : 0;
  }
};

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Maps a face field given by angles in the face frames of a metric (counterclockwise from
/// `halfedge(f)`, measured in the metric's triangle, as parallel_rosy_field() and
/// `Trivial_connection` on an `edge_length_map` produce them) to unit 3D vectors in the
/// embedded faces, by the linear map from each metric triangle to the embedded one (the identity
/// when the metric is the embedding's). A face with a border edge is mapped instead by the
/// similarity that keeps the direction of its border edge (of two, the one that ends at
/// their common corner): directions along or across
/// the boundary stay so (the fields of boundary_aligned_rosy_field()), and the N directions
/// stay \f$2\pi/N\f$ apart in 3D, which the linear map of a triangle that is not similar to
/// its image does not keep. Named parameters: `edge_length_map` or `intrinsic_mesh` (the metric
/// of the angles), `vertex_point_map` (the embedding) and the index maps.
template <typename TriangleMesh, typename FaceAngleMap, typename FaceVectorMap,
          typename NamedParameters = parameters::Default_named_parameters>
void field_angles_to_vectors(const TriangleMesh& tm, const FaceAngleMap& angles, FaceVectorMap vectors,
                             const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::property_traits<FaceVectorMap>::value_type Vector;
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  std::vector<internal::Face_map> frames;
  internal::face_maps(m, vpm, frames);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const double beta = double(get(angles, m.faces[f]));
    std::array<double, 3> v = internal::embedded_direction(frames[f], beta);
    const int h = internal::followed_border_halfedge(m, int(f));
    if(h >= 0) {
      // the unit border edge e and n x e in the face plane, turned by the angle to the edge
      const internal::Face_map_axes axes(frames[f], h == m.face_halfedge[f] ? 0 : h == m.next[std::size_t(m.face_halfedge[f])] ? 1 : 2);
      const double a = beta - internal::halfedge_direction(m, h);
      for(int i = 0; i < 3; ++i) v[std::size_t(i)] = std::cos(a) * axes.e[i] + std::sin(a) * axes.t[i];
    }
    put(vectors, m.faces[f], Vector(v[0], v[1], v[2]));
  }
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_PARALLEL_ROSY_FIELD_H
