// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_STREAMLINES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_STREAMLINES_H

/// \file streamlines.h
/// Evenly spaced streamlines of a face-based N-RoSy field, traced on the surface: the strokes
/// of pen-and-ink hatching (Lai et al. 2010, Figs. 14 and 15).

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// One streamline: a polyline on the surface, straight inside each face it crosses.
template <typename TriangleMesh>
struct Streamline
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::vector<std::array<double, 3>> points;   ///< on the edges it crosses (its ends inside faces)
  std::vector<face_descriptor> faces;           ///< `faces[i]` holds the piece from `points[i]` to `points[i + 1]`
  double length = 0;                            ///< its length in 3D
};

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// Parameters of trace_streamlines().
struct Streamline_options
{
  /// distance between neighbouring parallel streamlines, in model units (0: 1/60 of the
  /// diagonal of the bounding box)
  double separation = 0;
  /// a streamline stops when it comes closer than this fraction of `separation` to a parallel
  /// one (or to an earlier part of itself)
  double stop_fraction = 0.5;
  /// a streamline stops after this length, in units of `separation`
  double max_length = 400;
  /// streamlines shorter than this, in units of `separation`, are dropped
  double min_length = 1;
};

namespace internal {

struct Streamline_grid
{
  struct Sample { std::array<double, 3> p, d; std::size_t line; double arc; };
  double cell;
  std::unordered_map<std::uint64_t, std::vector<Sample>> cells;
  explicit Streamline_grid(double c) : cell(c) {}
  std::uint64_t key(long i, long j, long k) const
  {
    return (std::uint64_t(i & 0x1fffff) << 42) | (std::uint64_t(j & 0x1fffff) << 21) | std::uint64_t(k & 0x1fffff);
  }
  long coordinate(double x) const { return long(std::floor(x / cell)); }
  void add(const Sample& s) { cells[key(coordinate(s.p[0]), coordinate(s.p[1]), coordinate(s.p[2]))].push_back(s); }
  // is a sample parallel to direction d (|cos| above `parallel`) within `radius` of p, other
  // than those of line `line` less than `own_arc` behind `arc`?
  bool near(const std::array<double, 3>& p, const std::array<double, 3>& d, double radius, double parallel, std::size_t line,
            double arc, double own_arc) const
  {
    const long i = coordinate(p[0]), j = coordinate(p[1]), k = coordinate(p[2]);
    for(long a = i - 1; a <= i + 1; ++a)
      for(long b = j - 1; b <= j + 1; ++b)
        for(long c = k - 1; c <= k + 1; ++c) {
          auto it = cells.find(key(a, b, c));
          if(it == cells.end()) continue;
          for(const Sample& s : it->second) {
            if(s.line == line && std::abs(arc - s.arc) < own_arc) continue;
            const double dx = s.p[0] - p[0], dy = s.p[1] - p[1], dz = s.p[2] - p[2];
            if(dx * dx + dy * dy + dz * dz > radius * radius) continue;
            if(std::abs(s.d[0] * d[0] + s.d[1] * d[1] + s.d[2] * d[2]) > parallel) return true;
          }
        }
    return false;
  }
};

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// Traces evenly spaced streamlines of a face-based N-RoSy field (one 3D vector per face, its
/// N directions that vector turned by \f$2\pi k/N\f$ about the face normal, e.g. from
/// `field_angles_to_vectors()` or `Trivial_connection::angles_to_vectors()`). A streamline
/// goes straight across a face along one of the field's directions; entering the next face
/// across an edge, its direction is unfolded about the edge into that face's plane and
/// replaced by the nearest of the N directions there (so it follows every direction family of
/// the field, as a hatching stroke does: the two families of a cross field cross each other).
/// Seeds are the face centroids in a fixed pseudo-random order, each direction family from
/// each seed; a streamline is traced both ways from its seed and stops at the boundary, at a
/// face whose field vector is zero or not finite, where it would turn by more than 60 degrees
/// (next to a singularity, for N < 3), after `max_length`, or when it comes within
/// `stop_fraction` times `separation` of a parallel streamline (directions within
/// \f$\pi/(2N)\f$ of each other, as lines) or of an earlier part of itself. Runs in time
/// linear in the total number of face crossings.
///
/// Named parameter: `vertex_point_map`. Throws `Input_error` for \f$N < 1\f$ and invalid
/// options (non-finite or negative sizes).
template <typename TriangleMesh, typename FaceVectorMap, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Streamline<TriangleMesh>> trace_streamlines(const TriangleMesh& tm, const FaceVectorMap& field, int N,
                                                        const Streamline_options& options = Streamline_options(),
                                                        const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef std::array<double, 3> V3;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  for(double x : {options.separation, options.stop_fraction, options.max_length, options.min_length})
    if(!std::isfinite(x) || x < 0) throw Input_error(Input_error::INVALID_ARGUMENT, "streamline options must be finite and non-negative");
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  auto fim = CGAL::get_initialized_face_index_map(tm);
  auto sub = [](const V3& a, const V3& b) { return V3{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; };
  auto dot = [](const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto cross = [](const V3& a, const V3& b) { return V3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}}; };
  auto unit = [&](V3 a) { const double l = std::sqrt(dot(a, a)); if(l > 0) for(double& x : a) x /= l; return a; };
  auto point = [&](typename GT::vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return V3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };

  // per face: corners, unit normal, field vector in the plane (zero: no field)
  const std::size_t nf = num_faces(tm);
  std::vector<face_descriptor> face_of(nf);
  std::vector<std::array<V3, 3>> corner(nf);
  std::vector<V3> normal(nf), vec(nf);
  std::vector<std::array<halfedge_descriptor, 3>> side(nf);   // side k: corner k -> corner k+1
  V3 lo{{1e300, 1e300, 1e300}}, hi{{-1e300, -1e300, -1e300}};
  for(face_descriptor f : faces(tm)) {
    const std::size_t fi = std::size_t(get(fim, f));
    face_of[fi] = f;
    halfedge_descriptor h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm)) {
      corner[fi][std::size_t(k)] = point(source(h, tm));
      side[fi][std::size_t(k)] = h;
      for(std::size_t i = 0; i < 3; ++i) {
        lo[i] = (std::min)(lo[i], corner[fi][std::size_t(k)][i]);
        hi[i] = (std::max)(hi[i], corner[fi][std::size_t(k)][i]);
      }
    }
    const V3 n = cross(sub(corner[fi][1], corner[fi][0]), sub(corner[fi][2], corner[fi][0]));
    normal[fi] = unit(n);
    const auto& x = get(field, f);
    V3 v{{CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2])}};
    const bool finite = std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) && dot(n, n) > 0;
    if(finite) { const double vn = dot(v, normal[fi]); for(std::size_t i = 0; i < 3; ++i) v[i] -= vn * normal[fi][i]; }
    vec[fi] = finite ? unit(v) : V3{{0, 0, 0}};
  }
  const double diagonal = nf ? std::sqrt(dot(sub(hi, lo), sub(hi, lo))) : 0;
  const double sep = options.separation > 0 ? options.separation : diagonal / 60;
  std::vector<Streamline<TriangleMesh>> lines;
  if(nf == 0 || !(sep > 0)) return lines;
  const double stop = options.stop_fraction * sep, parallel = std::cos(CGAL_PI / (2 * N));
  // (a sample every half stop distance: nothing passes between two samples unseen)
  const double sample_step = (std::max)(stop, 1e-9 * sep) / 2;
  internal::Streamline_grid grid(sep);
  // the direction among the N of face f nearest to d, or zero
  auto snap = [&](std::size_t f, const V3& d) {
    const V3& v = vec[f];
    if(dot(v, v) == 0) return V3{{0, 0, 0}};
    const V3 w = cross(normal[f], v);
    const double a = std::atan2(dot(d, w), dot(d, v));
    const double k = std::round(a / (2 * CGAL_PI / N));
    const double b = k * 2 * CGAL_PI / N;
    return V3{{std::cos(b) * v[0] + std::sin(b) * w[0], std::cos(b) * v[1] + std::sin(b) * w[1], std::cos(b) * v[2] + std::sin(b) * w[2]}};
  };
  // one way from (p, f, d): the points and faces, stopping as documented
  struct Half { std::vector<V3> points; std::vector<std::size_t> faces; double length = 0; };
  // `sign` orients the arc length of the samples: +1 forward from the seed, -1 backward, so
  // that the samples of one line are told apart by their distance along it
  auto trace = [&](V3 p, std::size_t f, V3 d, std::size_t line, double sign) {
    Half h;
    h.points.push_back(p);
    int entry = -1;   // side of f crossed to enter it
    const double limit = options.max_length * sep;
    double next_sample = 0;
    for(std::size_t steps = 0; steps < 4 * nf + 16; ++steps) {
      // the exit: the side hit first by p + t d (in the face's plane)
      const V3& n = normal[f];
      double best_t = 1e300;
      int best = -1;
      for(int k = 0; k < 3; ++k) {
        if(k == entry) continue;
        const V3& a = corner[f][std::size_t(k)];
        const V3& b = corner[f][std::size_t((k + 1) % 3)];
        const V3 m = cross(n, sub(b, a));   // points into the face
        const double den = dot(d, m);
        if(den >= 0) continue;              // moving into the face across this side, not out
        const double t = dot(sub(a, p), m) / den;
        if(t < best_t) { best_t = (std::max)(t, 0.); best = k; }
      }
      if(best < 0) break;
      const V3 q{{p[0] + best_t * d[0], p[1] + best_t * d[1], p[2] + best_t * d[2]}};
      // samples along the piece, each tested against the streamlines before it is kept
      bool blocked = false;
      for(; next_sample <= h.length + best_t; next_sample += sample_step) {
        const double t = next_sample - h.length;
        const V3 x{{p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2]}};
        if(grid.near(x, d, stop, parallel, line, sign * next_sample, 2 * sep)) { blocked = true; break; }
        grid.add(internal::Streamline_grid::Sample{x, d, line, sign * next_sample});
      }
      if(blocked) break;
      h.points.push_back(q);
      h.faces.push_back(f);
      h.length += best_t;
      p = q;
      if(h.length > limit) break;
      // into the face across side `best`
      const halfedge_descriptor out = opposite(side[f][std::size_t(best)], tm);
      if(is_border(out, tm)) break;
      const std::size_t g = std::size_t(get(fim, face(out, tm)));
      const V3 e = unit(sub(corner[f][std::size_t((best + 1) % 3)], corner[f][std::size_t(best)]));
      const V3 mf = cross(normal[f], e), mg = cross(normal[g], e);
      const double along = dot(d, e), across = dot(d, mf);
      const V3 unfolded = unit(V3{{along * e[0] + across * mg[0], along * e[1] + across * mg[1], along * e[2] + across * mg[2]}});
      const V3 nd = snap(g, unfolded);
      if(dot(nd, nd) == 0 || dot(nd, unfolded) < 0.5) break;   // no field, or a turn of more than 60 degrees
      entry = -1;
      for(int k = 0; k < 3; ++k) if(side[g][std::size_t(k)] == out) entry = k;
      if(entry < 0) break;
      // a direction grazing the edge may snap to one that leaves g where it came in: stop there
      const V3 in = cross(normal[g], sub(corner[g][std::size_t((entry + 1) % 3)], corner[g][std::size_t(entry)]));
      if(!(dot(nd, in) > 0)) break;
      f = g;
      d = nd;
    }
    return h;
  };
  // seeds: the faces in a fixed pseudo-random order (a multiplicative permutation)
  std::uint64_t stride = 2654435761u % nf;
  auto gcd = [](std::uint64_t a, std::uint64_t b) { while(b) { const std::uint64_t t = a % b; a = b; b = t; } return a; };
  while(stride == 0 || gcd(stride, nf) != 1) stride = (stride + 1) % nf;
  const int families = N % 2 == 0 ? N / 2 : N;
  std::size_t next_id = 0;
  for(std::uint64_t i = 0; i < nf; ++i) {
    const std::size_t f = std::size_t((i * stride) % nf);
    if(dot(vec[f], vec[f]) == 0) continue;
    const V3 c{{(corner[f][0][0] + corner[f][1][0] + corner[f][2][0]) / 3, (corner[f][0][1] + corner[f][1][1] + corner[f][2][1]) / 3,
                (corner[f][0][2] + corner[f][1][2] + corner[f][2][2]) / 3}};
    const V3 w = cross(normal[f], vec[f]);
    for(int j = 0; j < families; ++j) {
      const double a = 2 * CGAL_PI * j / N;
      const V3 d{{std::cos(a) * vec[f][0] + std::sin(a) * w[0], std::cos(a) * vec[f][1] + std::sin(a) * w[1],
                  std::cos(a) * vec[f][2] + std::sin(a) * w[2]}};
      if(grid.near(c, d, sep, parallel, std::size_t(-1), 0, 0)) continue;   // a seed keeps a full separation
      const std::size_t id = next_id++;
      const Half fwd = trace(c, f, d, id, 1.);
      const Half bwd = trace(c, f, V3{{-d[0], -d[1], -d[2]}}, id, -1.);
      Streamline<TriangleMesh> s;
      for(std::size_t k = bwd.points.size(); k-- > 1;) { s.points.push_back(bwd.points[k]); s.faces.push_back(face_of[bwd.faces[k - 1]]); }
      for(std::size_t k = 0; k < fwd.points.size(); ++k) {
        s.points.push_back(fwd.points[k]);
        if(k < fwd.faces.size()) s.faces.push_back(face_of[fwd.faces[k]]);
      }
      // the seed splits the seed face's piece in two: join them
      if(!bwd.faces.empty() && !fwd.faces.empty()) {
        const std::size_t at = bwd.points.size() - 1;   // index of the seed point in s.points
        s.points.erase(s.points.begin() + std::ptrdiff_t(at));
        s.faces.erase(s.faces.begin() + std::ptrdiff_t(at));
      }
      s.length = fwd.length + bwd.length;
      // a short line is dropped, its samples stay: a seed there would find the same short line
      if(s.length >= options.min_length * sep && !s.faces.empty()) lines.push_back(std::move(s));
    }
  }
  return lines;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_STREAMLINES_H
