// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_TRANSFER_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_TRANSFER_H

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// Outcome of transfer_face_field_to_input().
struct Field_transfer_status
{
  bool success = false;          ///< every input face and interior edge received the field
  std::string message;           ///< why not, when `success` is `false`
  /// largest angle (radians) by which the \f$N\f$ directions carried to an input face's
  /// representative point depart from evenly spaced ones (the map between the two metrics is
  /// projective, not conformal, inside each piece); the matching stays exact below \f$\pi/N\f$
  double max_distortion = 0;
  double mean_distortion = 0;    ///< the mean of that angle over the input faces
};

namespace internal {

// The unit direction of angle `angle` in the frame of a triangle laid out as V, as a change of
// barycentric coordinates (summing to 0).
inline std::array<double, 3> barycentric_direction(const std::array<Point_2, 3>& V, double angle)
{
  const double ux = std::cos(angle), uy = std::sin(angle);
  const double e1x = V[1].x() - V[0].x(), e1y = V[1].y() - V[0].y(), e2x = V[2].x() - V[0].x(), e2y = V[2].y() - V[0].y();
  const double det = e1x * e2y - e1y * e2x;
  const double d1 = (ux * e2y - uy * e2x) / det, d2 = (e1x * uy - e1y * ux) / det;
  return {{-d1 - d2, d1, d2}};
}

// A piece's map and the layouts of its two triangles: directions of the intrinsic field at a
// point of the input face, as angles in the input face's frame.
struct Piece_directions
{
  std::array<double, 9> to_input, from_input;
  std::array<Point_2, 3> intrinsic_layout, input_layout;

  // intrinsic barycentric coordinates of a point given in input ones
  std::array<double, 3> intrinsic_point(const std::array<double, 3>& b) const
  {
    std::array<double, 3> c;
    double s = 0;
    for(int i = 0; i < 3; ++i) {
      c[std::size_t(i)] = from_input[std::size_t(3 * i)] * b[0] + from_input[std::size_t(3 * i + 1)] * b[1] + from_input[std::size_t(3 * i + 2)] * b[2];
      s += c[std::size_t(i)];
    }
    for(double& x : c) x /= s;
    return c;
  }

  // The angle, in the input face's frame, of the image of the intrinsic direction `angle` (in
  // the intrinsic face's frame) at the point with input coordinates b: the differential of the
  // projective map b = A c / 1^T A c applied to the direction's barycentric form.
  double input_angle(const std::array<double, 3>& b, double angle) const
  {
    const std::array<double, 3> c = intrinsic_point(b);
    const auto& V = intrinsic_layout;
    const std::array<double, 3> dc = barycentric_direction(V, angle);
    std::array<double, 3> Ac, Adc;
    double sAc = 0, sAdc = 0;
    for(int i = 0; i < 3; ++i) {
      Ac[std::size_t(i)] = to_input[std::size_t(3 * i)] * c[0] + to_input[std::size_t(3 * i + 1)] * c[1] + to_input[std::size_t(3 * i + 2)] * c[2];
      Adc[std::size_t(i)] = to_input[std::size_t(3 * i)] * dc[0] + to_input[std::size_t(3 * i + 1)] * dc[1] + to_input[std::size_t(3 * i + 2)] * dc[2];
      sAc += Ac[std::size_t(i)];
      sAdc += Adc[std::size_t(i)];
    }
    std::array<double, 3> db;
    for(int i = 0; i < 3; ++i) db[std::size_t(i)] = (Adc[std::size_t(i)] - Ac[std::size_t(i)] / sAc * sAdc) / sAc;
    const auto& W = input_layout;
    const double x = db[1] * (W[1].x() - W[0].x()) + db[2] * (W[2].x() - W[0].x());
    const double y = db[1] * (W[1].y() - W[0].y()) + db[2] * (W[2].y() - W[0].y());
    return std::atan2(y, x);
  }
};

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// Carries a face-based N-RoSy field of an intrinsic triangulation (the field of a cone metric
/// that needed flips) to the input mesh, through the common subdivision of the two
/// (`Intrinsic_triangulation::has_common_subdivision()`).
///
/// The direction of an input face is the field at the face's centroid, mapped by the
/// differential of the piece's projective map; a face that no intrinsic edge crosses and that is
/// an intrinsic face too takes the affine map between the two triangles, and a face on the
/// border keeps the field's angle with its border edge (an edge of both triangulations), as
/// field_angles_to_vectors() maps a metric's directions: fields parallel or orthogonal to the
/// boundary stay exactly so. The matching of an input edge follows the field
/// from one face's centroid to the other's through the pieces of the two faces: the branch of
/// the \f$N\f$ directions changes by the intrinsic matching wherever the path crosses an
/// intrinsic edge, and the rotation is summed piece by piece: inside a piece in steps of less than
/// a radian, and across an intrinsic edge as the field's intrinsic rotation there (wrapped as
/// field_singularities() wraps it, its half turns kept) seen through the next piece's map. So field_singularities() of the result, with its matching, reads the indices of
/// the intrinsic field at the vertices (they are shared) as long as `max_distortion` stays below
/// \f$\pi/N\f$ (the status says it).
///
/// \param tm the input mesh (the one the cone metric was computed for)
/// \param it the intrinsic triangulation, with its common subdivision
/// \param N the symmetry order
/// \param intrinsic_angles per face of `it`: the field's angle, counterclockwise from
///   `it.halfedge(f)`, in the intrinsic metric
/// \param intrinsic_matching per edge of `it`: the period jump for halfedge \f$2e\f$, in the
///   convention of the `matching` parameter of field_singularities() (0 on border edges)
/// \param input_angles receives, per face of `tm`, the field's angle counterclockwise from
///   `halfedge(f)`, in the input metric
/// \param input_matching receives the period jump of every edge of `tm`, for `halfedge(e)` (0
///   on border edges)
/// \param np the input metric: `edge_length_map` or `vertex_point_map` (and the index maps) as
///   given to compute_cone_metric()
///
/// Throws `Input_error` if `it` has no common subdivision, or the sizes do not match.
template <typename TriangleMesh, typename FaceAngleMap, typename EdgeMatchingMap,
          typename NamedParameters = parameters::Default_named_parameters>
Field_transfer_status transfer_face_field_to_input(const TriangleMesh& tm, const Intrinsic_triangulation& it, int N,
                                                   const std::vector<double>& intrinsic_angles,
                                                   const std::vector<int>& intrinsic_matching,
                                                   FaceAngleMap input_angles, EdgeMatchingMap input_matching,
                                                   const NamedParameters& np = parameters::default_values())
{
  if(!it.has_common_subdivision())
    throw Input_error(Input_error::INVALID_ARGUMENT, "transfer_face_field_to_input(): the triangulation has no common subdivision with the input");
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "transfer_face_field_to_input(): N must be at least 1");
  if(intrinsic_angles.size() != it.number_of_faces() || intrinsic_matching.size() != it.number_of_edges())
    throw Input_error(Input_error::INVALID_ARGUMENT, "transfer_face_field_to_input(): one angle per intrinsic face and one period jump per intrinsic edge are needed");
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  if(m.number_of_faces() != it.number_of_faces() || m.number_of_vertices() != it.number_of_vertices())
    throw Input_error(Input_error::INVALID_ARGUMENT, "transfer_face_field_to_input(): the mesh is not the one of the triangulation");
  const auto& pieces = it.common_subdivision();
  const double period = 2 * CGAL_PI / N;
  Field_transfer_status st;

  // the layouts of both triangulations' faces, once (every piece on a path needs its two)
  std::vector<std::array<Point_2, 3>> intrinsic_layouts(it.number_of_faces()), input_layouts(m.number_of_faces());
  for(std::size_t f = 0; f < it.number_of_faces(); ++f) {
    const int g0 = it.halfedge(int(f)), g1 = it.next(g0), g2 = it.next(g1);
    intrinsic_layouts[f] = lay_out_triangle(it.length(g0 >> 1), it.length(g1 >> 1), it.length(g2 >> 1));
    input_layouts[f] = internal::canonical_layout(m, int(f));
  }
  auto directions = [&](std::size_t i) {
    internal::Piece_directions d;
    d.to_input = it.piece_map(i, true);
    d.from_input = it.piece_map(i, false);
    d.intrinsic_layout = intrinsic_layouts[std::size_t(pieces[i].intrinsic_face)];
    d.input_layout = input_layouts[std::size_t(pieces[i].input_face)];
    return d;
  };
  // the branch J of the intrinsic field in piece i, at input point b
  auto angle_at = [&](std::size_t i, const internal::Piece_directions& d, const std::array<double, 3>& b, int J) {
    return d.input_angle(b, intrinsic_angles[std::size_t(pieces[i].intrinsic_face)] + J * period);
  };
  const std::array<double, 3> centroid = {{1. / 3, 1. / 3, 1. / 3}};
  // How much branch J turns from input point x to y inside piece i: a projective map of a strong
  // distortion turns a constant direction by any amount across a piece, so the segment is halved
  // until every part turns by less than a radian (wrapped differences alone lose full turns).
  std::function<double(std::size_t, const internal::Piece_directions&, const std::array<double, 3>&,
                       const std::array<double, 3>&, int, int)>
      turn_within = [&](std::size_t i, const internal::Piece_directions& d, const std::array<double, 3>& x,
                        const std::array<double, 3>& y, int J, int depth) -> double {
    const double step = internal::wrap_angle(angle_at(i, d, y, J) - angle_at(i, d, x, J));
    if(std::abs(step) < 1 || depth == 0) return step;
    std::array<double, 3> mid;
    for(std::size_t k = 0; k < 3; ++k) mid[k] = 0.5 * (x[k] + y[k]);
    return turn_within(i, d, x, mid, J, depth - 1) + turn_within(i, d, mid, y, J, depth - 1);
  };

  // A face that is one piece in both triangulations (no intrinsic edge crosses it and it is an
  // intrinsic face too) takes the affine map between the two triangles, as the package maps a
  // metric's face directions to the embedding everywhere else (field_angles_to_vectors()): it
  // keeps directions along the face's edges along them.
  std::vector<char> whole(pieces.size(), 0);   // computed once: the test runs for every face and edge
  for(std::size_t i = 0; i < pieces.size(); ++i)
    whole[i] = it.input_face_pieces(pieces[i].input_face).size() == 1 && it.intrinsic_face_pieces(pieces[i].intrinsic_face).size() == 1;
  auto whole_face = [&](std::size_t i) { return whole[i] != 0; };
  auto affine_angle = [&](std::size_t i, const internal::Piece_directions& d, double angle) {
    using internal::barycentric_direction;
    const auto& P = pieces[i];
    const auto& V = d.intrinsic_layout;
    const auto& W = d.input_layout;
    // corner k of the input face is corner to_intrinsic[k] of the intrinsic one
    std::array<std::size_t, 3> to_intrinsic = {{0, 1, 2}};
    for(std::size_t k = 0; k < 3; ++k) {
      const auto& ci = P.intrinsic_corners[k];
      const auto& bi = P.input_corners[k];
      to_intrinsic[bi[0] > 0.5 ? 0 : bi[1] > 0.5 ? 1 : 2] = ci[0] > 0.5 ? 0 : ci[1] > 0.5 ? 1 : 2;
    }
    const std::array<double, 3> dc = barycentric_direction(V, angle);
    std::array<double, 3> db = {{0, 0, 0}};
    for(std::size_t k = 0; k < 3; ++k) db[k] = dc[to_intrinsic[k]];
    const double x = db[1] * (W[1].x() - W[0].x()) + db[2] * (W[2].x() - W[0].x());
    const double y = db[1] * (W[1].y() - W[0].y()) + db[2] * (W[2].y() - W[0].y());
    return std::atan2(y, x);
  };

  // The angle, in input face f's frame, of the intrinsic direction `angle` of piece i carried
  // across the border halfedge hb of f (an edge of both triangulations) with its angle to it kept.
  auto border_angle = [&](std::size_t i, const internal::Piece_directions& d, int hb, double angle) {
    const auto& P = pieces[i];
    const std::size_t s = std::size_t(std::find(P.input_sides.begin(), P.input_sides.end(), hb) - P.input_sides.begin());
    const std::size_t ns = P.corner_ids.size();
    auto at = [](const std::array<Point_2, 3>& L, const std::array<double, 3>& b) {
      return Point_2(b[0] * L[0].x() + b[1] * L[1].x() + b[2] * L[2].x(), b[0] * L[0].y() + b[1] * L[1].y() + b[2] * L[2].y());
    };
    const Point_2 a = at(d.intrinsic_layout, P.intrinsic_corners[s]), b = at(d.intrinsic_layout, P.intrinsic_corners[(s + 1) % ns]);
    const Point_2 p = at(d.input_layout, P.input_corners[s]), q = at(d.input_layout, P.input_corners[(s + 1) % ns]);
    return angle - std::atan2(b.y() - a.y(), b.x() - a.x()) + std::atan2(q.y() - p.y(), q.x() - p.x());
  };

  // 1. the representative of every input face: at its centroid, in the piece containing it; on a
  //    border face, in the piece along the border edge (at that piece's centroid), with the angle
  //    to the border kept; the distortion of its N directions
  std::vector<double> beta(m.number_of_faces());
  std::vector<std::size_t> home(m.number_of_faces());
  std::vector<std::array<double, 3>> xrep(m.number_of_faces(), centroid);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const int hb = internal::followed_border_halfedge(m, int(f));   // the face's border halfedge, if any
    std::size_t best = 0;
    double best_depth = -1e300;
    for(std::size_t i : it.input_face_pieces(int(f))) {
      const auto& P = pieces[i];
      if(hb >= 0) {
        if(std::find(P.input_sides.begin(), P.input_sides.end(), hb) != P.input_sides.end()) { best = i; best_depth = 0; }
        continue;
      }
      const auto& cs = P.input_corners;   // the piece containing the centroid: the deepest
      double depth = 1e300;
      for(std::size_t k = 0; k < cs.size(); ++k) {
        const auto& a = cs[k];
        const auto& b = cs[(k + 1) % cs.size()];
        const double ex = b[1] - a[1], ey = b[2] - a[2], n = std::sqrt(ex * ex + ey * ey);
        if(n > 0) depth = (std::min)(depth, (ex * (centroid[2] - a[2]) - ey * (centroid[1] - a[1])) / n);
      }
      if(depth > best_depth) { best_depth = depth; best = i; }
    }
    if(best_depth == -1e300) {
      st.message = "input face " + std::to_string(f) + " has no piece along its border edge";
      return st;
    }
    home[f] = best;
    if(hb >= 0) {
      std::array<double, 3> c = {{0, 0, 0}};
      for(const auto& x : pieces[best].input_corners)
        for(int k = 0; k < 3; ++k) c[std::size_t(k)] += x[std::size_t(k)] / double(pieces[best].input_corners.size());
      xrep[f] = c;
    }
    const internal::Piece_directions d = directions(best);
    const double base = intrinsic_angles[std::size_t(pieces[best].intrinsic_face)];
    auto representative = [&](int J) {
      if(hb >= 0) return border_angle(best, d, hb, base + J * period);
      return whole_face(best) ? affine_angle(best, d, base + J * period) : angle_at(best, d, xrep[f], J);
    };
    beta[f] = representative(0);
    double distortion = 0;
    for(int J = 1; J < N; ++J)
      distortion = (std::max)(distortion, std::abs(internal::wrap_angle(representative(J) - beta[f] - J * period)));
    st.max_distortion = (std::max)(st.max_distortion, distortion);
    st.mean_distortion += distortion / double(m.number_of_faces());
    put(input_angles, m.faces[f], beta[f]);
  }

  // Directions of intrinsic halfedges in their face frames (counterclockwise from
  // it.halfedge(face)) and the Levi-Civita transport across them, as internal::halfedge_direction()
  // and internal::transport_increment() for the input.
  auto intrinsic_corner = [&](int g) {   // angle of face(g) at source(g)
    const int g1 = it.next(g), g2 = it.next(g1);
    return corner_angle(it.length(g1 >> 1), it.length(g >> 1), it.length(g2 >> 1));
  };
  auto intrinsic_direction = [&](int g) {
    const int g0 = it.halfedge(it.face(g)), g1 = it.next(g0);
    if(g == g0) return 0.;
    const double t1 = CGAL_PI - intrinsic_corner(g1);
    return g == g1 ? t1 : t1 + CGAL_PI - intrinsic_corner(it.next(g1));
  };
  auto intrinsic_transport = [&](int g) { return intrinsic_direction(g) + CGAL_PI - intrinsic_direction(g ^ 1); };

  // 2. the matching of every interior input edge: a path of pieces from one centroid to the other
  struct Side { long a, b; std::size_t piece; int index; };
  std::vector<Side> sides;
  std::vector<std::size_t> local, queue, path;   // reused from edge to edge
  std::vector<int> parent, parent_side;
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
    const int h = int(2 * e);
    const int fl = m.face[std::size_t(h)], fr = m.face[std::size_t(h ^ 1)];
    if(fl < 0 || fr < 0) { put(input_matching, m.edges[e], 0); continue; }
    // two whole faces (one piece each in both triangulations) meet along an edge of both: the
    // path is their two pieces (most edges, away from the flips: no search)
    const std::size_t A0 = home[std::size_t(fr)], B0 = home[std::size_t(fl)];
    if(whole[A0] && whole[B0]) {
      // each face's map keeps the shared edge's line: the input rotation is the intrinsic one
      // plus the turns of the two maps relative to that edge (as face_field_in_embedding())
      const auto& sides_A = pieces[A0].input_sides;
      const int gA = pieces[A0].intrinsic_sides[std::size_t(std::find(sides_A.begin(), sides_A.end(), h ^ 1) - sides_A.begin())];
      const int gB = gA ^ 1;   // in fl's intrinsic face
      const double bl = intrinsic_angles[std::size_t(it.face(gB))], br = intrinsic_angles[std::size_t(it.face(gA))];
      const double el = beta[std::size_t(fl)], er = beta[std::size_t(fr)];
      const int k = intrinsic_matching[std::size_t(gB >> 1)];   // for the intrinsic halfedge 2e'
      const double rotation = (gB & 1) ? -(internal::wrap_angle(br - bl - intrinsic_transport(gA)) + period * k)
                                       : internal::wrap_angle(bl - br - intrinsic_transport(gB)) + period * k;
      const double tl = internal::wrap_angle((el - internal::halfedge_direction(m, h)) - (bl - intrinsic_direction(gB)));
      const double tr = internal::wrap_angle((er - internal::halfedge_direction(m, h ^ 1)) - (br - intrinsic_direction(gA)));
      const double principal = internal::wrap_angle(el - er - internal::transport_increment(m, h));
      put(input_matching, m.edges[e], int(std::lround((rotation + tl - tr - principal) / period)));
      continue;
    }
    const auto rr = it.input_face_pieces(fr), rl = it.input_face_pieces(fl);
    local.assign(rr.begin(), rr.end());
    const std::size_t nr = local.size();
    local.insert(local.end(), rl.begin(), rl.end());
    sides.clear();
    for(std::size_t k = 0; k < local.size(); ++k) {
      const auto& ids = pieces[local[k]].corner_ids;
      for(std::size_t s = 0; s < ids.size(); ++s) {
        const long a = ids[s], b = ids[(s + 1) % ids.size()];
        sides.push_back({(std::min)(a, b), (std::max)(a, b), k, int(s)});
      }
    }
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    // breadth-first search from the home piece of fr to that of fl
    parent.assign(local.size(), -1);
    parent_side.assign(local.size(), -1);
    std::size_t start = 0, goal = 0;
    for(std::size_t k = 0; k < local.size(); ++k) {
      if(k < nr && local[k] == A0) start = k;
      if(k >= nr && local[k] == B0) goal = k;
    }
    queue.assign(1, start);
    parent[start] = int(start);
    for(std::size_t qi = 0; qi < queue.size() && parent[goal] < 0; ++qi) {
      const std::size_t k = queue[qi];
      const auto& ids = pieces[local[k]].corner_ids;
      for(std::size_t s = 0; s < ids.size(); ++s) {
        const long a = (std::min)(ids[s], ids[(s + 1) % ids.size()]), b = (std::max)(ids[s], ids[(s + 1) % ids.size()]);
        auto it2 = std::lower_bound(sides.begin(), sides.end(), Side{a, b, 0, 0},
                                    [](const Side& x, const Side& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
        for(; it2 != sides.end() && it2->a == a && it2->b == b; ++it2) {
          if(it2->piece == k || parent[it2->piece] >= 0) continue;
          parent[it2->piece] = int(k);
          parent_side[it2->piece] = int(s);
          queue.push_back(it2->piece);
        }
      }
    }
    if(parent[goal] < 0) {
      st.message = "no path of pieces across input edge " + std::to_string(e);
      return st;
    }
    path.assign(1, goal);
    while(path.back() != start) path.push_back(std::size_t(parent[path.back()]));
    std::reverse(path.begin(), path.end());
    // follow the field along the path: a, the accumulated angle (fr's frame, then fl's)
    const double inc = internal::transport_increment(m, h);   // fr's frame -> fl's frame
    int J = 0;
    std::array<double, 3> x = xrep[std::size_t(fr)];
    // from the representative to the projective image of branch 0 at its point (the same
    // unless the face took the affine or the border map)
    double a = beta[std::size_t(fr)];
    {
      const std::size_t A = local[path.front()];
      const internal::Piece_directions dA = directions(A);
      a += internal::wrap_angle(angle_at(A, dA, x, 0) - beta[std::size_t(fr)]);
    }
    for(std::size_t step = 0; step + 1 < path.size(); ++step) {
      const std::size_t A = local[path[step]], B = local[path[step + 1]];
      const int s = parent_side[path[step + 1]];
      const auto& P = pieces[A];
      const std::size_t ns = P.corner_ids.size();
      // the middle of the shared side, in A's input face, then in B's
      std::array<double, 3> y;
      for(int i = 0; i < 3; ++i)
        y[std::size_t(i)] = 0.5 * (P.input_corners[std::size_t(s)][std::size_t(i)] + P.input_corners[(std::size_t(s) + 1) % ns][std::size_t(i)]);
      const internal::Piece_directions dA = directions(A), dB = directions(B);
      const double at_y = angle_at(A, dA, y, J);
      a += turn_within(A, dA, x, y, J, 24);
      // across an intrinsic edge: the branch changes by its matching, and the field turns by the
      // rotation the intrinsic read-back counts (wrapped, plus the matching's periods)
      const int hg = P.intrinsic_sides[std::size_t(s)];
      int J_next = J;
      double intrinsic_rotation = 0;
      if(hg >= 0) {
        const int k = intrinsic_matching[std::size_t(hg >> 1)];
        J_next += (hg & 1) ? k : -k;   // k is for halfedge 2e, from face(2e + 1) into face(2e)
        const double tA = intrinsic_angles[std::size_t(P.intrinsic_face)], tB = intrinsic_angles[std::size_t(pieces[B].intrinsic_face)];
        intrinsic_rotation = (hg & 1) ? internal::wrap_angle(tB - tA - intrinsic_transport(hg ^ 1)) + period * k
                                      : -(internal::wrap_angle(tA - tB - intrinsic_transport(hg)) + period * k);
      }
      // across the input edge: the point in fl's coordinates, the frame changes
      std::array<double, 3> y2 = y;
      double shift = 0;
      if(pieces[B].input_face != P.input_face) {
        const int kA = P.input_sides[std::size_t(s)];
        const int hA = m.face_halfedge[std::size_t(P.input_face)];
        const int jA = kA == hA ? 0 : kA == m.next[std::size_t(hA)] ? 1 : 2;
        const int hB = m.face_halfedge[std::size_t(pieces[B].input_face)];
        const int kB = kA ^ 1;
        const int jB = kB == hB ? 0 : kB == m.next[std::size_t(hB)] ? 1 : 2;
        y2 = {{0, 0, 0}};
        y2[std::size_t(jB)] = y[std::size_t((jA + 1) % 3)];
        y2[std::size_t((jB + 1) % 3)] = y[std::size_t(jA)];
        shift = inc;
      }
      x = y2;
      if(hg < 0) {
        a += shift + internal::wrap_angle(angle_at(B, dB, y2, J) - (at_y + shift));
        continue;
      }
      // A's direction carried into B's intrinsic frame: both maps send it alike up to less than a
      // half turn (they agree on the shared side), then B's map turns it by the field's rotation.
      // An orientation-preserving linear map turns a rotation in [0, pi) by one in [0, pi) and a
      // half turn by a half turn: the intrinsic rotation's half turns are kept, not wrapped (a
      // connection that turns by nearly pi across an edge lost a full turn to the wrap).
      const double carried = dB.input_angle(y2, intrinsic_angles[std::size_t(P.intrinsic_face)] + J * period + intrinsic_transport(hg ^ 1));
      a += shift + internal::wrap_angle(carried - (at_y + shift));
      const double half_turns = std::floor(intrinsic_rotation / CGAL_PI);
      double rest = angle_at(B, dB, y2, J_next) - carried - half_turns * CGAL_PI;
      rest -= 2 * CGAL_PI * std::floor((rest + 0.5 * CGAL_PI) / (2 * CGAL_PI));   // in [-pi/2, 3pi/2): [0, pi) up to rounding
      a += half_turns * CGAL_PI + rest;
      J = J_next;
    }
    const std::size_t last = local[path.back()];
    const internal::Piece_directions dL = directions(last);
    const std::array<double, 3>& xl = xrep[std::size_t(fl)];
    a += turn_within(last, dL, x, xl, J, 24);
    // a: the branch J at fl's point; the evenly spaced field there has beta_l + J period
    const double corr = internal::wrap_angle(angle_at(last, dL, xl, J) - beta[std::size_t(fl)] - J * period);
    const double rotation = a - corr - beta[std::size_t(fr)] - inc;
    const double principal = internal::wrap_angle(beta[std::size_t(fl)] - beta[std::size_t(fr)] - inc);
    put(input_matching, m.edges[e], int(std::lround((rotation - principal) / period)));
  }
  st.success = true;
  return st;
}


/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// The rotation between the vertex frames of an intrinsic triangulation and those of the input
/// mesh: per vertex, the angle (in the intrinsic metric, counterclockwise) from the reference
/// halfedge of the vertex frames of rotation_compensated_field() on the mesh built by
/// copy_intrinsic_triangulation() to the input mesh's reference halfedge, found through the
/// common subdivision. A vertex field of angle \f$a\f$ in the intrinsic frames has angle
/// \f$a - \delta_v\f$ in the input's (the convention of vertex_field_to_vectors(): angles of
/// the metric measured from the reference halfedge), and a direction given on the input (e.g.
/// by vertex_vectors_to_angles()) has \f$a + \delta_v\f$ in the intrinsic frames. 0 at
/// isolated vertices.
///
/// Named parameters: the input metric and index maps, as given to compute_cone_metric().
/// Throws `Input_error` if `it` has no common subdivision.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<double> input_vertex_frame_angles(const TriangleMesh& tm, const Intrinsic_triangulation& it,
                                              const NamedParameters& np = parameters::default_values())
{
  if(!it.has_common_subdivision())
    throw Input_error(Input_error::INVALID_ARGUMENT, "input_vertex_frame_angles(): the triangulation has no common subdivision with the input");
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const std::size_t nv = it.number_of_vertices(), nh = 2 * it.number_of_edges();
  // the intrinsic reference halfedges, chosen as Mesh_arrays chooses them: the first outgoing
  // halfedge, or the one whose opposite is a border halfedge
  std::vector<int> ref(nv, -1);
  for(std::size_t h = 0; h < nh; ++h) {
    const int v = it.source(int(h));
    if(ref[std::size_t(v)] < 0) ref[std::size_t(v)] = int(h);
    if(it.face(int(h ^ 1)) < 0) ref[std::size_t(v)] = int(h);
  }
  auto corner = [&](int h) {   // angle of face(h) at source(h)
    const int h1 = it.next(h), h2 = it.next(h1);
    return corner_angle(it.length(h1 >> 1), it.length(h >> 1), it.length(h2 >> 1));
  };
  // from the reference halfedge counterclockwise to halfedge `to` (leaving the same vertex)
  auto angle_to = [&](int from, int to) {
    double a = 0;
    for(int h = from, steps = 0; h != to; h = it.next(it.next(h)) ^ 1) {
      if(it.face(h) < 0 || ++steps > int(nh)) return std::numeric_limits<double>::quiet_NaN();
      a += corner(h);
    }
    return a;
  };
  const auto& pieces = it.common_subdivision();
  std::vector<double> delta(nv, 0.);
  for(std::size_t v = 0; v < nv; ++v) {
    const int k = m.vertex_out[v];
    if(k < 0 || ref[v] < 0) continue;
    double a = std::numeric_limits<double>::quiet_NaN();
    // the input halfedge is an intrinsic one
    for(int h = ref[v], steps = 0; steps <= int(nh); h = it.next(it.next(h)) ^ 1, ++steps) {
      if(it.input_edge(h >> 1) == long(k >> 1) && it.source(h) == int(v)) { a = angle_to(ref[v], h); break; }
      if(it.face(h) < 0 || (steps > 0 && h == ref[v])) break;
    }
    if(std::isnan(a)) {
      // else its first segment, a side of a piece of face(k) from the corner at v
      for(std::size_t i : it.input_face_pieces(m.face[std::size_t(k)])) {
        const auto& P = pieces[i];
        for(std::size_t s = 0; s < P.corner_ids.size(); ++s) {
          if(P.input_sides[s] != k || P.corner_ids[s] != long(v)) continue;
          const auto& c0 = P.intrinsic_corners[s];
          const auto& c1 = P.intrinsic_corners[(s + 1) % P.corner_ids.size()];
          const int j = c0[0] > 0.5 ? 0 : c0[1] > 0.5 ? 1 : 2;
          const int g0 = it.halfedge(P.intrinsic_face);
          const int gj = j == 0 ? g0 : j == 1 ? it.next(g0) : it.next(it.next(g0));
          const auto V = lay_out_triangle(it.length(g0 >> 1), it.length(it.next(g0) >> 1), it.length(it.next(it.next(g0)) >> 1));
          const double px = c1[0] * V[0].x() + c1[1] * V[1].x() + c1[2] * V[2].x(), py = c1[0] * V[0].y() + c1[1] * V[1].y() + c1[2] * V[2].y();
          const auto& A = V[std::size_t(j)];
          const auto& B = V[std::size_t((j + 1) % 3)];
          const double ex = B.x() - A.x(), ey = B.y() - A.y(), dx = px - A.x(), dy = py - A.y();
          a = angle_to(ref[v], gj) + std::atan2(ex * dy - ey * dx, ex * dx + ey * dy);
        }
      }
    }
    delta[v] = std::isnan(a) ? 0. : a;
  }
  return delta;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// A face field of another metric on the same triangulation (e.g. a flat cone metric that
/// needed no flips, given as `edge_length_map`), with its matching, in the embedding: the
/// directions mapped as field_angles_to_vectors() maps them (the linear map of each triangle; a
/// border face keeps the angle with its border edge), as angles in the embedded face frames, and
/// the matching that gives the same rotations in the embedding's Levi-Civita connection. Across
/// an edge, each face's map turns a direction by less than \f$\pi\f$ relative to that edge (it
/// keeps the edge's line and the orientation), so the embedded rotation is the metric's plus the
/// two faces' turns, and the read-back of the result (field_singularities() on the embedding)
/// equals the read-back on the metric.
///
/// \param tm the mesh
/// \param N the symmetry order
/// \param angles per face: the field's angle in the metric's face frame
/// \param matching per edge: its period jump (convention of field_singularities())
/// \param metric_lengths per edge: the metric
/// \param embedded_angles receives the angle of every face in the embedded face frame
/// \param embedded_matching receives the period jump of every edge in the embedding
template <typename TriangleMesh, typename FaceAngleMap, typename EdgeMatchingMap, typename EdgeLengthMap,
          typename OutputFaceAngleMap, typename OutputEdgeMatchingMap>
void face_field_in_embedding(const TriangleMesh& tm, int N, const FaceAngleMap& angles, const EdgeMatchingMap& matching,
                             const EdgeLengthMap& metric_lengths, OutputFaceAngleMap embedded_angles,
                             OutputEdgeMatchingMap embedded_matching)
{
  typedef typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel::Vector_3 Vector;
  const Intrinsic_mesh<TriangleMesh> metric(tm, parameters::edge_length_map(metric_lengths));
  const Intrinsic_mesh<TriangleMesh> embedded(tm, parameters::default_values());
  const internal::Mesh_arrays<TriangleMesh>& mm = metric.arrays();
  const internal::Mesh_arrays<TriangleMesh>& me = embedded.arrays();
  auto vectors = get(CGAL::dynamic_face_property_t<Vector>(), tm);
  field_angles_to_vectors(tm, angles, vectors, parameters::edge_length_map(metric_lengths));
  vectors_to_face_angles(tm, vectors, embedded_angles);
  const double period = 2 * CGAL_PI / N;
  for(std::size_t e = 0; e < mm.number_of_edges(); ++e) {
    const int h = int(2 * e);
    const int l = mm.face[std::size_t(h)], r = mm.face[std::size_t(h ^ 1)];
    if(l < 0 || r < 0) { put(embedded_matching, mm.edges[e], 0); continue; }
    const double bl = double(get(angles, mm.faces[std::size_t(l)])), br = double(get(angles, mm.faces[std::size_t(r)]));
    const double el = double(get(embedded_angles, me.faces[std::size_t(l)])), er = double(get(embedded_angles, me.faces[std::size_t(r)]));
    // the turn of each face's map relative to the shared edge
    const double tl = internal::wrap_angle((el - internal::halfedge_direction(me, h)) - (bl - internal::halfedge_direction(mm, h)));
    const double tr = internal::wrap_angle((er - internal::halfedge_direction(me, h ^ 1)) - (br - internal::halfedge_direction(mm, h ^ 1)));
    const double rotation = internal::wrap_angle(bl - br - internal::transport_increment(mm, h)) + period * double(get(matching, mm.edges[e]));
    const double embedded_rotation = rotation + tl - tr;
    const double principal = internal::wrap_angle(el - er - internal::transport_increment(me, h));
    put(embedded_matching, mm.edges[e], int(std::lround((embedded_rotation - principal) / period)));
  }
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_TRANSFER_H
