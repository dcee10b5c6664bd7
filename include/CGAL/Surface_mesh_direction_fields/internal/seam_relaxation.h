// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEAM_RELAXATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEAM_RELAXATION_H

// The paths of a polyhedron's edges are edge paths of the mesh: they zigzag at the scale of its
// triangles, and the charts hold them straight on P's edges, which shears the triangles beside
// them (at an output edge length close to the input's, cells beside the paths fold). Here the two
// faces of P beside each path are unfolded into one plane and the vertices near the path relaxed
// in it without the path: P's edge then crosses the mesh's triangles like any straight line of
// the polyhedron. The metric stays P's own flat metric (every moved vertex keeps its triangles in
// one plane, the corners stay), only drawn on the mesh with less distortion.

#include <CGAL/Surface_mesh_direction_fields/internal/chart_relaxation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_threads.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Relaxes, for every P edge, the mesh vertices within `rings` edges of its path (not nearer to
// another path, and with all their faces in the two faces of P beside the path) as-rigidly-as-
// possible towards `reference`'s triangles, in 3 x `iterations` sweeps, in the plane where the
// second face of P is unfolded onto the first across their edge. Every triangle stays on the
// side of `sign` (as in relax_polyhedron_charts()).
// Rewrites `chart` of every face at a moved vertex in the frame of the first face: the lengths
// it gives are P's metric; the faces' frames are no longer their own face of P. Returns the
// number of vertices relaxed.
template <typename TM>
std::size_t relax_across_polyhedron_edges(const Mesh_arrays<TM>& m, const Polyhedron_cut_view& cut, const std::vector<double>& reference,
                                          int rings, int iterations, double sign, std::vector<std::array<Point_2, 3>>& chart)
{
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces();
  const std::vector<int>& corner_of = *cut.corner_of;
  const std::vector<int>& pface = *cut.pface;
  const std::vector<std::array<int, 2>>& pedges = *cut.pedges;
  const std::size_t np = pedges.size();
  if(rings <= 0 || iterations <= 0 || np == 0) return 0;
  // per P edge: its two faces, the first running from pedges[k][0] to [1], and the rigid motion
  // (c, s, tx, ty) that takes the second face's frame to the first's across the edge
  std::vector<std::array<int, 2>> sides(np, {{-1, -1}});
  std::vector<std::array<double, 4>> motion(np);
  auto corner_at = [&](int j, int c) {
    const std::vector<int>& f = (*cut.pfaces)[std::size_t(j)];
    for(std::size_t i = 0; i < f.size(); ++i) if(f[i] == c) return (*cut.shape)[std::size_t(j)][i];
    return Point_2(0, 0);
  };
  for(std::size_t j = 0; j < cut.pfaces->size(); ++j) {
    const std::vector<int>& f = (*cut.pfaces)[j];
    for(std::size_t i = 0; i < f.size(); ++i)
      for(std::size_t k = 0; k < np; ++k) {
        if(pedges[k][0] == f[i] && pedges[k][1] == f[(i + 1) % f.size()]) sides[k][0] = int(j);
        if(pedges[k][1] == f[i] && pedges[k][0] == f[(i + 1) % f.size()]) sides[k][1] = int(j);
      }
  }
  for(std::size_t k = 0; k < np; ++k) {
    if(sides[k][0] < 0 || sides[k][1] < 0) return 0;
    const Point_2 a0 = corner_at(sides[k][0], pedges[k][0]), b0 = corner_at(sides[k][0], pedges[k][1]);
    const Point_2 a1 = corner_at(sides[k][1], pedges[k][0]), b1 = corner_at(sides[k][1], pedges[k][1]);
    const double t0 = std::atan2(b0.y() - a0.y(), b0.x() - a0.x()), t1 = std::atan2(b1.y() - a1.y(), b1.x() - a1.x());
    const double c = std::cos(t0 - t1), s = std::sin(t0 - t1);
    motion[k] = {{c, s, a0.x() - (c * a1.x() - s * a1.y()), a0.y() - (s * a1.x() + c * a1.y())}};
  }
  // the bands: breadth-first from each path's inner vertices, through vertices that are not corners
  std::vector<std::vector<int>> star(nv);   // per vertex: its faces
  for(std::size_t f = 0; f < nf; ++f) {
    int h = m.face_halfedge[f];
    for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) star[std::size_t(m.source(h))].push_back(int(f));
  }
  std::vector<int> band(nv, -1), depth(nv, -1);
  std::vector<int> touched;   // vertices some band reached
  for(std::size_t k = 0; k < np; ++k) {
    std::vector<int> frontier;
    for(std::size_t i = 1; i + 1 < (*cut.paths)[k].size(); ++i) frontier.push_back((*cut.paths)[k][i]);
    std::vector<int> mine;
    for(int v : frontier) { mine.push_back(v); depth[std::size_t(v)] = 0; }
    for(int r = 0; r < rings && !frontier.empty(); ++r) {
      std::vector<int> next;
      for(int v : frontier) {
        const int h0 = m.vertex_out[std::size_t(v)];
        int h = h0;
        do {
          const int q = m.target[std::size_t(h)];
          if(corner_of[std::size_t(q)] < 0 && depth[std::size_t(q)] < 0) { depth[std::size_t(q)] = r + 1; next.push_back(q); mine.push_back(q); }
          h = m.ccw_out(h);
        } while(h != h0);
      }
      frontier.swap(next);
    }
    for(int v : mine) {
      depth[std::size_t(v)] = -1;
      band[std::size_t(v)] = band[std::size_t(v)] == -1 ? int(k) : -2;   // reached from two paths: left alone
      touched.push_back(v);
    }
  }
  // a band vertex needs all its faces in the two faces of P beside its path; no face may have
  // vertices of two bands (it would need two frames)
  for(int v : touched) {
    const int k = band[std::size_t(v)];
    if(k < 0) continue;
    for(int f : star[std::size_t(v)])
      if(pface[std::size_t(f)] != sides[std::size_t(k)][0] && pface[std::size_t(f)] != sides[std::size_t(k)][1]) { band[std::size_t(v)] = -3; break; }
  }
  std::vector<int> face_band(nf, -1);
  for(int v : touched)
    if(band[std::size_t(v)] >= 0)
      for(int f : star[std::size_t(v)]) {
        int& b = face_band[std::size_t(f)];
        b = b == -1 || b == band[std::size_t(v)] ? band[std::size_t(v)] : -2;
      }
  for(int v : touched)
    if(band[std::size_t(v)] >= 0)
      for(int f : star[std::size_t(v)]) if(face_band[std::size_t(f)] == -2) { band[std::size_t(v)] = -3; break; }
  // the faces of the problem (at a band vertex) in their band's frame, and the unknowns
  std::fill(face_band.begin(), face_band.end(), -1);
  // numbered band after band, so that the two threads write apart (interleaved, they shared
  // cache lines: sweeps 0.66 -> 0.28 s at 433k faces)
  std::vector<std::vector<int>> band_vertices(np);
  for(std::size_t v = 0; v < nv; ++v) if(band[v] >= 0) band_vertices[std::size_t(band[v])].push_back(int(v));
  std::vector<int> column(nv, -1), unknown;
  for(const std::vector<int>& vs : band_vertices)
    for(int v : vs) {
      column[std::size_t(v)] = int(unknown.size());
      unknown.push_back(v);
      for(int f : star[std::size_t(v)]) face_band[std::size_t(f)] = band[std::size_t(v)];
    }
  const int n = int(unknown.size());
  if(n == 0) return 0;
  std::vector<int> faces;
  for(std::size_t f = 0; f < nf; ++f) if(face_band[f] >= 0) faces.push_back(int(f));
  std::stable_sort(faces.begin(), faces.end(), [&](int f, int g) { return face_band[std::size_t(f)] < face_band[std::size_t(g)]; });
  for(int f : faces) {
    const int k = face_band[std::size_t(f)];
    if(pface[std::size_t(f)] == sides[std::size_t(k)][1]) {
      const std::array<double, 4>& t = motion[std::size_t(k)];
      for(Point_2& p : chart[f]) p = Point_2(t[0] * p.x() - t[1] * p.y() + t[2], t[1] * p.x() + t[0] * p.y() + t[3]);
    }
  }
  // corner k of face f: unknown column (or -1) and, for fixed vertices, the position
  std::vector<std::array<int, 3>> col(faces.size());
  std::vector<std::array<Point_2, 3>> ref(faces.size());
  std::vector<std::array<double, 3>> weight(faces.size());
  Eigen::VectorXd x(n), y(n);
  for(std::size_t i = 0; i < faces.size(); ++i) {
    const int f = faces[i];
    const int h0 = m.face_halfedge[std::size_t(f)], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
    const int hs[3] = {h0, h1, h2};
    for(int k = 0; k < 3; ++k) {
      const int c = column[std::size_t(m.source(hs[k]))];
      col[i][std::size_t(k)] = c;
      if(c >= 0) { x[c] = chart[std::size_t(f)][std::size_t(k)].x(); y[c] = chart[std::size_t(f)][std::size_t(k)].y(); }
    }
    const double l[3] = {reference[std::size_t(h0 >> 1)], reference[std::size_t(h1 >> 1)], reference[std::size_t(h2 >> 1)]};
    ref[i] = reference_triangle(l[0], l[1], l[2], sign);
    weight[i] = clamped_cotan_weights(l, std::abs(ref[i][2].y()) * l[0]);
  }
  // Nonlinear Gauss-Seidel on the as-rigid-as-possible energy sum over the faces' edges of
  // w |x_a - x_b - R (p_a - p_b)|^2: per sweep the rotations (local step), then every vertex in
  // turn to its optimum with its neighbours fixed, moved only as far as each of its triangles
  // keeps half its area and a tenth of its reference's (or half its start, if less). A vertex
  // about to fold a triangle stops only itself, not the band (a global step is cut short for
  // all: on Spot at 100k faces, to 1e-3 of its length after ten steps).
  std::vector<int> first(std::size_t(n) + 1, 0), incident;   // per unknown: (face, corner) pairs, as i * 3 + k
  for(std::size_t i = 0; i < faces.size(); ++i) for(int k = 0; k < 3; ++k) if(col[i][std::size_t(k)] >= 0) ++first[std::size_t(col[i][std::size_t(k)]) + 1];
  for(int c = 0; c < n; ++c) first[std::size_t(c) + 1] += first[std::size_t(c)];
  incident.resize(std::size_t(first[std::size_t(n)]));
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for(std::size_t i = 0; i < faces.size(); ++i)
      for(int k = 0; k < 3; ++k) if(col[i][std::size_t(k)] >= 0) incident[std::size_t(fill[std::size_t(col[i][std::size_t(k)])]++)] = int(i) * 3 + k;
  }
  std::vector<std::array<Point_2, 3>> fixed_at(faces.size());   // the faces' corners in band order (fixed ones are read here)
  for(std::size_t i = 0; i < faces.size(); ++i) fixed_at[i] = chart[std::size_t(faces[i])];
  auto at = [&](std::size_t i, int k) {
    const int c = col[i][std::size_t(k)];
    return c >= 0 ? Point_2(x[c], y[c]) : fixed_at[i][std::size_t(k)];
  };
  // per (face, corner) of an unknown: the weights and reference edges to its two other corners
  struct Pull { int o[2]; double w[2], ex[2], ey[2]; };
  std::vector<Pull> pull(incident.size());
  for(std::size_t j = 0; j < incident.size(); ++j) {
    const std::size_t i = std::size_t(incident[j] / 3);
    const int k = incident[j] % 3;
    for(int a = 0; a < 2; ++a) {   // the edges to the two other corners: x_k = x_o + R (p_k - p_o)
      const int o = (k + 1 + a) % 3;
      pull[j].o[a] = o;
      pull[j].w[a] = weight[i][std::size_t(a == 0 ? k : o)];
      pull[j].ex[a] = ref[i][std::size_t(k)].x() - ref[i][std::size_t(o)].x();
      pull[j].ey[a] = ref[i][std::size_t(k)].y() - ref[i][std::size_t(o)].y();
    }
  }
  std::vector<double> floor(faces.size());
  std::vector<std::vector<int>> band_faces(np), band_columns(np);   // the bands are independent problems
  for(std::size_t i = 0; i < faces.size(); ++i) {
    const Point_2 p[3] = {at(i, 0), at(i, 1), at(i, 2)};
    floor[i] = (std::min)(0.5 * signed_doubled_area(p, sign), 0.1 * std::abs(ref[i][1].x() * ref[i][2].y()));
    band_faces[std::size_t(face_band[std::size_t(faces[i])])].push_back(int(i));
  }
  for(int c = 0; c < n; ++c) band_columns[std::size_t(band[std::size_t(unknown[std::size_t(c)])])].push_back(c);
  std::vector<std::array<double, 2>> rotation(faces.size());
  auto relax_band = [&](std::size_t b) {
    std::vector<std::array<Point_2, 3>> corners;   // of the faces at the vertex being moved
    for(int sweep = 0; sweep < 3 * iterations; ++sweep) {
      for(int i : band_faces[b]) {
        const Point_2 p[3] = {at(std::size_t(i), 0), at(std::size_t(i), 1), at(std::size_t(i), 2)};
        rotation[std::size_t(i)] = closest_rotation(p, ref[std::size_t(i)], weight[std::size_t(i)]);
      }
      for(int c : band_columns[b]) {
        double sx = 0, sy = 0, sw = 0;
        corners.clear();
        for(int j = first[std::size_t(c)]; j < first[std::size_t(c) + 1]; ++j) {
          const std::size_t i = std::size_t(incident[std::size_t(j)] / 3);
          const std::array<double, 2>& r = rotation[i];
          const Pull& u = pull[std::size_t(j)];
          std::array<Point_2, 3> p;
          p[std::size_t(incident[std::size_t(j)] % 3)] = Point_2(x[c], y[c]);
          for(int a = 0; a < 2; ++a) {
            const Point_2 q = at(i, u.o[a]);
            p[std::size_t(u.o[a])] = q;
            sx += u.w[a] * (q.x() + r[0] * u.ex[a] - r[1] * u.ey[a]);
            sy += u.w[a] * (q.y() + r[1] * u.ex[a] + r[0] * u.ey[a]);
            sw += u.w[a];
          }
          corners.push_back(p);   // for the step bound below (the other corners do not move)
        }
        const double dx = sx / sw - x[c], dy = sy / sw - y[c];
        double alpha = 1;
        for(int j = first[std::size_t(c)]; j < first[std::size_t(c) + 1]; ++j) {
          const std::size_t i = std::size_t(incident[std::size_t(j)] / 3);
          const int k = incident[std::size_t(j)] % 3;
          const Point_2* p = corners[std::size_t(j - first[std::size_t(c)])].data();
          Point_2 v[3] = {Point_2(0, 0), Point_2(0, 0), Point_2(0, 0)};
          v[k] = Point_2(dx, dy);
          alpha = (std::min)(alpha, area_floor_step(p, v, sign, (std::max)(0.5 * signed_doubled_area(p, sign), floor[i])));
        }
        x[c] += alpha * dx;
        y[c] += alpha * dy;
      }
    }
  };
  std::vector<std::size_t> share[2];
  std::size_t load[2] = {0, 0};
  for(std::size_t b = 0; b < np; ++b) { const int t = load[1] < load[0] ? 1 : 0; share[t].push_back(b); load[t] += band_columns[b].size(); }
  run_on_two_threads([&](int t) { for(std::size_t b : share[t]) relax_band(b); }, n >= 5000);
  for(std::size_t i = 0; i < faces.size(); ++i)
    for(int k = 0; k < 3; ++k) chart[std::size_t(faces[i])][std::size_t(k)] = at(i, k);
  return std::size_t(n);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SEAM_RELAXATION_H
