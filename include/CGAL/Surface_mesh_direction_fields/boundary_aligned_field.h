// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_BOUNDARY_ALIGNED_FIELD_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_BOUNDARY_ALIGNED_FIELD_H

// N-RoSy fields parallel or orthogonal to the boundary of an open mesh (Lai et al. 2010,
// section 4.3), by the double cover: the mesh glued to its mirror image along the boundary.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cotan_weights.h>
#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>
#include <CGAL/Surface_mesh_direction_fields/rotation_compensation.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Outcome of boundary_aligned_rosy_field().
struct Boundary_aligned_field_status
{
  /// a flat cone metric of the double cover was found, the field on it is an N-RoSy field, and
  /// along every boundary edge one of its directions is parallel (orthogonal) to the edge
  bool success = false;
  std::string message;                  ///< empty on success
  int N = 1;
  bool orthogonal = false;              ///< the field was asked orthogonal to the boundary
  Cone_metric_status metric;            ///< the Ricci flow on the double cover
  bool rotation_compensation = false;   ///< the double cover has handles and needed rotation compensation
  /// over the boundary edges: the distance of the field's angle with the edge (minus
  /// \f$\pi/2\f$ when orthogonal) to the nearest multiple of \f$2\pi/N\f$ (\f$\pi/N\f$ for odd
  /// \f$N\f$: a direction along the edge in either orientation)
  double max_boundary_deviation = 0;
};

namespace internal {

// Turns a face field (angles beta in the face frames of the flat metric of mf) that is parallel
// along the boundary so that it follows every boundary loop: one rotation for the whole field
// onto the first boundary edge, then, with several loops, a harmonic rotation theta (cotan
// Laplace of the metric) equal on each loop j to minus the constant angle d_j the field makes
// with that loop. theta is an exact 1-form that is constant along every loop, so it adds no
// singularity and keeps the field's angle with each loop (on the double cover: the
// compensation that is odd under the mirror). Faces on a boundary edge take their loop's value,
// so the alignment there is exact. False (and a message) if the factorisation fails.
template <typename TM>
bool align_with_boundary_loops(const Mesh_arrays<TM>& mf, const Topology_arrays& topo, int N, bool orthogonal,
                               std::vector<double>& beta, std::string& message)
{
  const std::size_t nv = mf.number_of_vertices(), nf = mf.number_of_faces(), ne = mf.number_of_edges();
  const double across = orthogonal ? CGAL_PI / 2 : 0.;
  // parallel to an edge = one of the N directions on its line, in either orientation: modulo
  // 2 pi / N for even N, pi / N for odd N (the directions and their opposites)
  const double line_period = N % 2 == 0 ? 2 * CGAL_PI / N : CGAL_PI / N;
  const int hb = topo.loops[0][0] ^ 1;   // the interior halfedge of a boundary edge
  const double offset = halfedge_direction(mf, hb) + across - beta[std::size_t(mf.face[std::size_t(hb)])];
  for(double& a : beta) a += offset;
  if(topo.loops.size() > 1) {
    std::vector<double> fixed(nv, std::numeric_limits<double>::quiet_NaN());
    for(const auto& loop : topo.loops) {
      const int h = loop[0] ^ 1;
      const double d = std::remainder(beta[std::size_t(mf.face[std::size_t(h)])] - halfedge_direction(mf, h) - across, line_period);
      for(int b : loop) fixed[std::size_t(mf.source(b))] = -d;
    }
    std::vector<int> col(nv, -1);
    int n = 0;
    for(std::size_t v = 0; v < nv; ++v) if(std::isnan(fixed[v]) && !mf.is_isolated(int(v))) col[v] = n++;
    std::vector<double> theta(nv, 0.);
    for(std::size_t v = 0; v < nv; ++v) if(!std::isnan(fixed[v])) theta[v] = fixed[v];
    if(n > 0) {
      const std::vector<double> w = floored_cotan_edge_weights(mf);
      std::vector<Eigen::Triplet<double>> t;
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
      for(std::size_t e = 0; e < ne; ++e) {
        const int a = mf.source(int(2 * e)), b = mf.target[2 * e];
        const int ca = col[std::size_t(a)], cb = col[std::size_t(b)];
        if(ca >= 0) t.emplace_back(ca, ca, w[e]);
        if(cb >= 0) t.emplace_back(cb, cb, w[e]);
        if(ca >= 0 && cb >= 0) t.emplace_back((std::max)(ca, cb), (std::min)(ca, cb), -w[e]);
        else if(ca >= 0) rhs[ca] += w[e] * theta[std::size_t(b)];
        else if(cb >= 0) rhs[cb] += w[e] * theta[std::size_t(a)];
      }
      Cholmod_cholesky::Matrix L(n, n);
      L.setFromTriplets(t.begin(), t.end());
      L.makeCompressed();
      Cholmod_cholesky chol;
      if(!chol.factor(L, message)) return false;
      const Eigen::VectorXd x = chol.solve(rhs);
      for(std::size_t v = 0; v < nv; ++v) if(col[v] >= 0) theta[v] = x[col[v]];
    }
    for(std::size_t f = 0; f < nf; ++f) {
      const int h0 = mf.face_halfedge[f];
      double r = 0;
      int on_boundary = -1;
      for(int h = h0, i = 0; i < 3; h = mf.next[std::size_t(h)], ++i) {
        r += theta[std::size_t(mf.source(h))] / 3;
        if(mf.face[std::size_t(h ^ 1)] < 0) on_boundary = h;
      }
      if(on_boundary >= 0) r = theta[std::size_t(mf.source(on_boundary))];
      beta[f] += r;
    }
  }
  for(double& a : beta) a -= 2 * CGAL_PI * std::floor(a / (2 * CGAL_PI));
  return true;
}

// Over the faces with a border edge: the distance of the field's angle with the edge (minus
// pi/2 when orthogonal) to the nearest direction of the field's line (a multiple of 2 pi / N,
// of pi / N for odd N); a face with two border edges (a corner face) counts the nearer one, as
// no constant field in a face follows two sides that meet at an angle off that lattice.
template <typename TM>
double boundary_deviation(const Mesh_arrays<TM>& mf, const Topology_arrays& topo, int N, bool orthogonal,
                          const std::vector<double>& beta)
{
  const double line_period = N % 2 == 0 ? 2 * CGAL_PI / N : CGAL_PI / N;
  std::vector<double> per_face(mf.number_of_faces(), -1.);
  for(const auto& loop : topo.loops)
    for(int b : loop) {
      const int h = b ^ 1;
      const std::size_t f = std::size_t(mf.face[std::size_t(h)]);
      const double d = std::abs(std::remainder(beta[f] - halfedge_direction(mf, h) - (orthogonal ? CGAL_PI / 2 : 0.), line_period));
      per_face[f] = per_face[f] < 0 ? d : (std::min)(per_face[f], d);
    }
  double worst = 0;
  for(double d : per_face) worst = (std::max)(worst, d);
  return worst;
}

inline std::string boundary_deviation_message(double deviation)
{
  return "the field does not follow the boundary everywhere (deviation " + std::to_string(deviation) +
         " rad): do the boundary corners turn by multiples of 2 pi / N?";
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// The largest deviation of a face field from the boundary of an open mesh: over the faces with
/// a border edge, the distance of the angle between the field in the face and the edge (minus
/// \f$\pi/2\f$ with `orthogonal_to_boundary(true)`) to the nearest multiple of \f$2\pi/N\f$
/// (\f$\pi/N\f$ for odd \f$N\f$: a direction along the edge in either orientation); a face with
/// two border edges (a corner face) counts the nearer one, as no constant field in a face
/// follows two sides that meet at an angle off that lattice. `face_angles`
/// are in the face frames of the metric given by `edge_length_map` (default: Euclidean lengths)
/// or `intrinsic_mesh`. 0 for a closed mesh.
template <typename TriangleMesh, typename FaceAngleMap, typename NamedParameters = parameters::Default_named_parameters>
double max_boundary_deviation(const TriangleMesh& tm, int N, const FaceAngleMap& face_angles,
                              const NamedParameters& np = parameters::default_values())
{
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<double> beta(m.number_of_faces());
  for(std::size_t f = 0; f < beta.size(); ++f) beta[f] = double(get(face_angles, m.faces[f]));
  return internal::boundary_deviation(m, im.topology_arrays(), N,
                                      parameters::choose_parameter(parameters::get_parameter(np, internal_np::orthogonal_to_boundary), false),
                                      beta);
}

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// The N-RoSy field parallel (or, with `orthogonal_to_boundary(true)`, orthogonal) to the
/// boundary of an open mesh of genus 0 with any number of boundary loops, on a flat cone metric
/// whose boundary loops are geodesics with corners that turn by multiples of \f$2\pi/N\f$
/// (e.g. the metric of compute_cone_metric() with boundary targets rounded so, on the input or
/// on its intrinsic triangulation): the parallel field of the metric (parallel_rosy_field()),
/// turned onto the first boundary edge, then by a harmonic rotation that is constant on every
/// boundary loop onto the others. This is the restriction to one half of Lai et al.'s double
/// cover (section 4.3): the mirror-symmetric metric of the double cover is the mirror double of
/// this one, and the harmonic rotation is its compensation that is odd under the mirror.
///
/// `face_angles` receives the field in the face frames of the metric, like
/// parallel_rosy_field(); its only singularities are the interior cones. Named parameters:
/// `orthogonal_to_boundary` (`bool`, default `false`), `edge_length_map` (the flat metric) or
/// `intrinsic_mesh`, `holonomy_tolerance` and the index maps. The status (its `metric` is left
/// empty) fails with a message when the metric has no parallel field (a cone or a boundary
/// corner that is no multiple of \f$2\pi/N\f$) or when the deviation from the boundary exceeds
/// \f$10^{-6}\f$. Throws `Input_error` for closed meshes, several components, handles and
/// \f$N < 1\f$ (meshes with handles: boundary_aligned_rosy_field()).
template <typename TriangleMesh, typename FaceAngleMap, typename NamedParameters = parameters::Default_named_parameters>
Boundary_aligned_field_status boundary_aligned_parallel_field(const TriangleMesh& tm, int N, FaceAngleMap face_angles,
                                                              const NamedParameters& np = parameters::default_values())
{
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  Boundary_aligned_field_status st;
  st.N = N;
  st.orthogonal = parameters::choose_parameter(parameters::get_parameter(np, internal_np::orthogonal_to_boundary), false);
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1 || topo.loops.empty() || topo.components[0].genus() != 0)
    throw Input_error(Input_error::INVALID_ARGUMENT, "boundary_aligned_parallel_field() needs a mesh of genus 0, one component, "
                                                     "with a boundary (meshes with handles: boundary_aligned_rosy_field())");
  const std::size_t nf = m.number_of_faces();
  auto tmp = get(CGAL::dynamic_face_property_t<double>(), tm);
  const Parallel_rosy_status ps = parallel_rosy_field(tm, N, tmp, np);
  if(!ps.success) { st.message = ps.message; return st; }
  std::vector<double> beta(nf);
  for(std::size_t f = 0; f < nf; ++f) beta[f] = get(tmp, m.faces[f]);
  if(!internal::align_with_boundary_loops(m, topo, N, st.orthogonal, beta, st.message)) return st;
  for(std::size_t f = 0; f < nf; ++f) put(face_angles, m.faces[f], beta[f]);
  st.max_boundary_deviation = internal::boundary_deviation(m, topo, N, st.orthogonal, beta);
  st.success = st.max_boundary_deviation <= 1e-6;
  if(!st.success) st.message = internal::boundary_deviation_message(st.max_boundary_deviation);
  return st;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// An N-RoSy field on an open mesh that is parallel to its boundary, or orthogonal to it with
/// the named parameter `orthogonal_to_boundary(true)` (Lai et al. 2010, section 4.3), on the
/// mesh's own triangulation. On genus 0 the flat metric with a geodesic boundary is computed on
/// the mesh itself and the field is boundary_aligned_parallel_field() (the restriction of the
/// double cover's, below); with handles the mesh
/// is glued to a mirrored copy of itself along its boundary (the double cover, a closed surface
/// on which every interior cone appears twice); a flat cone metric of the double cover is
/// computed with curvature `target_curvature(v)` at the interior vertices of both copies and
/// twice `target_curvature(v)` (the boundary's turning angle at v, \f$\pi - \sum\theta\f$) at the
/// boundary vertices, which become interior; the field of that metric (parallel, or rotation
/// compensated when the double cover has handles), turned so that it follows one boundary edge,
/// is kept on the original half. By the mirror symmetry the boundary is then a geodesic between
/// its corners, and the field follows it when every corner turns by a multiple of \f$2\pi/N\f$
/// (e.g. four corners of \f$\pi/2\f$ for a cross field on a disk). The targets must satisfy
/// Gauss-Bonnet on the mesh (\f$\sum K + \sum\kappa = 2\pi\chi\f$).
///
/// Outputs: `output_lengths` (per edge of `tm`: the flat metric restricted to it) and
/// `face_angles` (per face, in the face frames of that metric). The status checks every boundary
/// edge; with handles, an interior edge joining two boundary vertices (an "ear") makes it fail
/// with a message, as the double cover would join those vertices twice: split such edges first.
/// The metric is computed without edge flips (it must live on `tm`'s edges); for metrics that
/// need flips, compose compute_cone_metric(), copy_intrinsic_triangulation(),
/// boundary_aligned_parallel_field() and transfer_face_field_to_input() as `smdf rosy` does. Named
/// parameters: `orthogonal_to_boundary` (`bool`, default `false`), `edge_length_map`
/// (the input metric, default Euclidean) and the index maps. Throws `Input_error` for closed
/// meshes, several components, \f$N < 1\f$ and the errors of compute_cone_metric().
template <typename TriangleMesh, typename VertexCurvatureMap, typename OutputEdgeLengthMap, typename FaceAngleMap,
          typename NamedParameters = parameters::Default_named_parameters>
Boundary_aligned_field_status boundary_aligned_rosy_field(const TriangleMesh& tm, int N, const VertexCurvatureMap& target_curvature,
                                                          OutputEdgeLengthMap output_lengths, FaceAngleMap face_angles,
                                                          const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef CGAL::Simple_cartesian<double>::Point_3 P3;
  typedef CGAL::Surface_mesh<P3> Cover;
  typedef typename Cover::Vertex_index CV;
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  Boundary_aligned_field_status st;
  st.N = N;
  st.orthogonal = choose_parameter(get_parameter(np, internal_np::orthogonal_to_boundary), false);
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1 || topo.loops.empty())
    throw Input_error(Input_error::INVALID_ARGUMENT, "boundary_aligned_rosy_field() needs a mesh of one component with a boundary");
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces(), ne = m.number_of_edges();
  // genus 0: the double cover's metric is the mirror double of the mesh's own flat metric with
  // these targets, and its parallel field restricted to one half is the mesh's (half the size)
  if(topo.components[0].genus() == 0) {
    st.metric = compute_cone_metric(tm, target_curvature, output_lengths, np.intrinsic_edge_flips(false));
    if(!st.metric.converged) {
      st.message = "no flat cone metric with a geodesic boundary on the mesh's triangulation: " + st.metric.message;
      return st;
    }
    const Boundary_aligned_field_status fs =
        boundary_aligned_parallel_field(tm, N, face_angles, np.edge_length_map(output_lengths).orthogonal_to_boundary(st.orthogonal));
    st.success = fs.success;
    st.message = fs.message;
    st.max_boundary_deviation = fs.max_boundary_deviation;
    return st;
  }

  // an interior edge between two boundary vertices would become two edges joining the same
  // vertices in the double cover
  for(std::size_t e = 0; e < ne; ++e) {
    const int h = int(2 * e);
    if(m.face[std::size_t(h)] >= 0 && m.face[std::size_t(h ^ 1)] >= 0 && m.is_boundary_vertex(m.source(h)) &&
       m.is_boundary_vertex(m.target[std::size_t(h)])) {
      st.message = "interior edge " + std::to_string(e) + " joins two boundary vertices (" + std::to_string(m.source(h)) + ", " +
                   std::to_string(m.target[std::size_t(h)]) + "): the double cover needs it split first (e.g. CGAL::Euler::split_edge())";
      return st;
    }
  }
  // the double cover: vertex v, and its mirror v' = copy[v] (v itself on the boundary); built
  // from a polygon soup (adding the faces one by one would pinch the boundary vertices on the way)
  std::vector<std::size_t> copy_index(nv);
  std::size_t count = nv;
  for(std::size_t v = 0; v < nv; ++v) copy_index[v] = m.is_boundary_vertex(int(v)) ? v : count++;
  std::vector<P3> points(count, P3(0, 0, 0));
  std::vector<std::array<std::size_t, 3>> polygons;
  std::vector<std::array<int, 3>> corner(nf);
  for(std::size_t f = 0; f < nf; ++f) {
    const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)];
    corner[f] = {{m.source(h0), m.target[std::size_t(h0)], m.target[std::size_t(h1)]}};
    polygons.push_back({{std::size_t(corner[f][0]), std::size_t(corner[f][1]), std::size_t(corner[f][2])}});
  }
  for(std::size_t f = 0; f < nf; ++f)
    polygons.push_back({{copy_index[std::size_t(corner[f][2])], copy_index[std::size_t(corner[f][1])], copy_index[std::size_t(corner[f][0])]}});
  Cover cover;
  if(Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, cover);
  std::vector<CV> copy(nv);
  for(std::size_t v = 0; v < nv; ++v) copy[v] = CV(Cover::size_type(copy_index[v]));
  if(cover.number_of_faces() != 2 * nf || cover.number_of_vertices() != count || !CGAL::is_closed(cover)) {
    st.message = "the double cover could not be built (is every boundary loop simple?)";
    return st;
  }
  // its initial lengths and targets
  auto cover_length = cover.template add_property_map<typename Cover::Edge_index, double>("e:initial", 0.).first;
  for(std::size_t e = 0; e < ne; ++e) {   // every input edge and its mirror get the input length
    const int h = int(2 * e);
    const int a = m.source(h), b = m.target[std::size_t(h)];
    for(int side = 0; side < 2; ++side) {
      const CV ca = side ? copy[std::size_t(a)] : CV(Cover::size_type(a)), cb = side ? copy[std::size_t(b)] : CV(Cover::size_type(b));
      const auto hh = cover.halfedge(ca, cb);
      if(hh != Cover::null_halfedge()) cover_length[cover.edge(hh)] = m.length[e];
    }
  }
  auto cover_target = cover.template add_property_map<CV, double>("v:target", 0.).first;
  for(std::size_t v = 0; v < nv; ++v) {
    const double k = double(get(target_curvature, m.vertices[v]));
    if(m.is_boundary_vertex(int(v))) cover_target[CV(Cover::size_type(v))] = 2 * k;
    else { cover_target[CV(Cover::size_type(v))] = k; cover_target[copy[v]] = k; }
  }
  auto flat = cover.template add_property_map<typename Cover::Edge_index, double>("e:flat", 0.).first;
  st.metric = compute_cone_metric(cover, cover_target, flat,
                                  parameters::edge_length_map(cover_length).intrinsic_edge_flips(false));
  if(!st.metric.converged) {
    st.message = "no flat cone metric of the double cover on its triangulation: " + st.metric.message;
    return st;
  }
  // the field on the cover
  auto cover_angle = cover.template add_property_map<typename Cover::Face_index, double>("f:angle", 0.).first;
  const Parallel_rosy_status ps = parallel_rosy_field(cover, N, cover_angle, parameters::edge_length_map(flat));
  if(!ps.success) {
    st.rotation_compensation = true;
    auto va = cover.template add_property_map<CV, double>("v:angle", 0.).first;
    const Rotation_compensation_status rc = rotation_compensated_field(cover, N, va, cover_angle, parameters::edge_length_map(flat));
    if(!rc.success) { st.message = "no N-RoSy field on the double cover: " + rc.message; return st; }
  }
  // back to the input: its edges get the flat lengths, its faces the field in their frames
  std::vector<double> len(ne);
  for(std::size_t e = 0; e < ne; ++e) {
    const int h = int(2 * e);
    const auto hh = cover.halfedge(CV(Cover::size_type(m.source(h))), CV(Cover::size_type(m.target[std::size_t(h)])));
    len[e] = flat[cover.edge(hh)];
    put(output_lengths, m.edges[e], len[e]);
  }
  const Intrinsic_mesh<TriangleMesh> imf = im.with_edge_lengths(output_lengths);
  const internal::Mesh_arrays<TriangleMesh>& mf = imf.arrays();
  const Intrinsic_mesh<Cover> cim(cover, parameters::edge_length_map(flat));
  const internal::Mesh_arrays<Cover>& mc = cim.arrays();
  std::vector<double> beta(nf);
  for(std::size_t f = 0; f < nf; ++f) {
    // the halfedge corner[f][0] -> corner[f][1] in both frames
    const int hi = m.face_halfedge[f];
    const auto ch = cover.halfedge(CV(Cover::size_type(corner[f][0])), CV(Cover::size_type(corner[f][1])));
    const int hc = mc.halfedge_index(ch, cover);
    beta[f] = cover_angle[typename Cover::Face_index(Cover::size_type(f))] - internal::halfedge_direction(mc, hc) +
              internal::halfedge_direction(mf, hi);
  }
  // The cover has handles (several boundary loops, or handles of the mesh): its compensated
  // field need not be symmetric under the mirror and may turn along the boundary. Where the mesh
  // itself carries a parallel field of the restricted metric (no handles, and boundary loops
  // that turn by multiples of 2 pi / N), that one is taken: it runs along every boundary loop
  // at a constant angle, which the harmonic rotation below removes.
  if(st.rotation_compensation) {
    auto tmp = get(CGAL::dynamic_face_property_t<double>(), tm);
    const Parallel_rosy_status own_ps = parallel_rosy_field(tm, N, tmp, parameters::edge_length_map(output_lengths));
    if(own_ps.success)
      for(std::size_t f = 0; f < nf; ++f) beta[f] = get(tmp, m.faces[f]);
  }
  if(!internal::align_with_boundary_loops(mf, topo, N, st.orthogonal, beta, st.message)) return st;
  for(std::size_t f = 0; f < nf; ++f) put(face_angles, m.faces[f], beta[f]);
  st.max_boundary_deviation = internal::boundary_deviation(mf, topo, N, st.orthogonal, beta);
  st.success = st.max_boundary_deviation <= 1e-6;
  if(!st.success) st.message = internal::boundary_deviation_message(st.max_boundary_deviation);
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_BOUNDARY_ALIGNED_FIELD_H
