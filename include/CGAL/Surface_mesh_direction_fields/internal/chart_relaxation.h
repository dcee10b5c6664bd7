// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHART_RELAXATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHART_RELAXATION_H

// The charts of a polyhedron's faces, made close to the input's own triangles while bijective:
// stretch-minimising Tutte embeddings of each piece (stretch_minimizing_tutte()), then
// as-rigid-as-possible relaxation of all of them (the local / global iteration of Liu et al.
// 2008, relax_polyhedron_charts()), with the cut paths free
// to slide along P's edges: every path vertex has one unknown, its distance t from the edge's
// first corner, shared by the two faces beside the path, so both sides always agree on where
// it lies and the resulting lengths stay one metric. Each step is accepted only as far as it
// keeps every triangle on the side of the start and every path monotone (at most halving any
// triangle's area or path gap per step), so the charts remain bijective onto P's convex faces.

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_threads.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// A triangle of side lengths a = |p0 p1|, b = |p1 p2|, c = |p2 p0| in the plane: p0 at the origin,
// p1 on the positive x axis, p2 above it (sign +1) or below (-1).
inline std::array<Point_2, 3> reference_triangle(double a, double b, double c, double sign)
{
  const double x = (a * a + c * c - b * b) / (2 * a);
  return {{Point_2(0, 0), Point_2(a, 0), Point_2(x, sign * std::sqrt((std::max)(c * c - x * x, 0.)))}};
}
// Cotangent weights (halved) of the edges k = (corner k, corner k + 1) of the triangle of side
// lengths l[0..2] (l[k] from corner k to k + 1) and twice its area, clamped to [5e-3, 50] so that
// the energy stays convex and needles do not dominate.
inline std::array<double, 3> clamped_cotan_weights(const double l[3], double area2)
{
  std::array<double, 3> w;
  for(int k = 0; k < 3; ++k) {   // cot of the angle opposite edge k: (sum of the other squares - its square) / (4 area)
    const double o1 = l[(k + 1) % 3], o2 = l[(k + 2) % 3];
    const double cot = area2 > 0 ? (o1 * o1 + o2 * o2 - l[k] * l[k]) / (2 * area2) : 1.;
    w[std::size_t(k)] = 0.5 * (std::min)(1e2, (std::max)(1e-2, cot));
  }
  return w;
}

// The rotation (cos, sin) closest to the map from triangle `ref` to triangle `x` in the weighted
// sense of as-rigid-as-possible energies: the local step of Liu et al. 2008.
inline std::array<double, 2> closest_rotation(const Point_2 x[3], const std::array<Point_2, 3>& ref, const std::array<double, 3>& w)
{
  double A[2][2] = {{0, 0}, {0, 0}};   // sum of w (x_a - x_b)(p_a - p_b)^T
  for(int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3;
    const double ex[2] = {x[k].x() - x[k1].x(), x[k].y() - x[k1].y()};
    const double ep[2] = {ref[std::size_t(k)].x() - ref[std::size_t(k1)].x(), ref[std::size_t(k)].y() - ref[std::size_t(k1)].y()};
    for(int r = 0; r < 2; ++r) for(int q = 0; q < 2; ++q) A[r][q] += w[std::size_t(k)] * ex[r] * ep[q];
  }
  // the rotation's angle is arg(A00 + A11 + i (A10 - A01)): normalised, without trigonometry
  const double ra = A[0][0] + A[1][1], rb = A[1][0] - A[0][1], rn = std::sqrt(ra * ra + rb * rb);
  return rn > 0 ? std::array<double, 2>{{ra / rn, rb / rn}} : std::array<double, 2>{{1., 0.}};
}

// Twice the area of triangle p, signed by `sign`.
inline double signed_doubled_area(const Point_2 p[3], double sign)
{
  return sign * ((p[1].x() - p[0].x()) * (p[2].y() - p[0].y()) - (p[2].x() - p[0].x()) * (p[1].y() - p[0].y()));
}

// The largest fraction a of the move of triangle p by v that keeps its doubled area, signed by
// `sign`, above `floor` (which it is above at a = 0): the first positive root of a quadratic in
// a (infinity when the area never gets that low).
inline double area_floor_step(const Point_2 p[3], const Point_2 v[3], double sign, double floor)
{
  const double ax = p[1].x() - p[0].x(), ay = p[1].y() - p[0].y(), bx = p[2].x() - p[0].x(), by = p[2].y() - p[0].y();
  const double dax = v[1].x() - v[0].x(), day = v[1].y() - v[0].y(), dbx = v[2].x() - v[0].x(), dby = v[2].y() - v[0].y();
  const double c0 = signed_doubled_area(p, sign) - floor, c1 = sign * (ax * dby + dax * by - bx * day - dbx * ay), c2 = sign * (dax * dby - dbx * day);
  const double inf = std::numeric_limits<double>::infinity();
  if(!(c0 > 0)) return 0;
  if(std::abs(c2) < 1e-300) return c1 < 0 ? -c0 / c1 : inf;
  const double disc = c1 * c1 - 4 * c2 * c0;
  if(disc < 0) return inf;
  const double q = -0.5 * (c1 + (c1 >= 0 ? 1 : -1) * std::sqrt(disc));
  double best = inf;
  for(double r : {q / c2, q != 0 ? c0 / q : inf}) if(r > 0) best = (std::min)(best, r);
  return best;
}

// The largest fraction of the move that keeps at least half of the triangle's area (after Smith
// and Schaefer 2015's line search).
inline double half_area_step(const Point_2 p[3], const Point_2 v[3], double sign)
{
  return area_floor_step(p, v, sign, 0.5 * signed_doubled_area(p, sign));
}

// The Tutte embedding of one piece of the cut (`piece`: its mesh faces; `unknowns`: its inner
// vertices, `column` their rows; `fixed`: the positions of its boundary vertices), first with
// symmetrised mean value weights of the metric (the mean of Floater's weights at the edge's two
// ends), then up to `extra_rounds` more times with every weight divided once more by the L2
// stretch over `reference` at its far end (Yoshizawa, Belyaev and Seidel 2004), while that
// stretch falls: positive weights keep every embedding bijective. Writes the inner vertices'
// positions to `solved`; false (and `message`) when the piece is not a disk bounded by the fixed
// vertices or its system cannot be factored.
template <typename TM>
bool stretch_minimizing_tutte(const Mesh_arrays<TM>& m, const std::vector<int>& piece, const std::vector<int>& column,
                              const std::vector<int>& unknowns, const std::map<int, Point_2>& fixed, const std::vector<double>* reference,
                              int extra_rounds, std::vector<Point_2>& solved, std::string& message)
{
  const std::size_t nv = m.number_of_vertices();
  solved.assign(unknowns.size(), Point_2(0, 0));
  auto place = [&](int v) { return column[std::size_t(v)] >= 0 ? solved[std::size_t(column[std::size_t(v)])] : fixed.at(v); };
  std::vector<double> sigma(nv, 0.), divisor(nv, 1.);   // per vertex: its stretch, the product of its stretches so far
  std::vector<Point_2> best;
  double best_stretch = std::numeric_limits<double>::infinity();
  const int rounds = reference && extra_rounds > 0 ? 1 + extra_rounds : 1;
  // per unknown: its neighbours and their symmetrised mean value weights (the weight at v is
  // (tan(a/2) + tan(b/2)) / |vq|, a and b the metric's angles at v beside vq; at q likewise)
  const int n = int(unknowns.size());
  std::vector<int> first(std::size_t(n) + 1, 0), neighbour;
  std::vector<double> base;
  for(int i = 0; i < n; ++i) {
    const int h0 = m.vertex_out[std::size_t(unknowns[std::size_t(i)])];
    int h = h0;
    do {
      const int q = m.target[std::size_t(h)];
      if(column[std::size_t(q)] < 0 && fixed.find(q) == fixed.end()) { message = "a piece of the cut is not a disk bounded by its paths"; return false; }
      const double at_v = std::tan(0.5 * m.angle[std::size_t(h)]) + std::tan(0.5 * m.angle[std::size_t(m.next[std::size_t(h ^ 1)])]);
      const double at_q = std::tan(0.5 * m.angle[std::size_t(h ^ 1)]) + std::tan(0.5 * m.angle[std::size_t(m.next[std::size_t(h)])]);
      neighbour.push_back(q);
      base.push_back(0.5 * (at_v + at_q) / (std::max)(m.edge_length(h), 1e-300));
      h = m.ccw_out(h);
    } while(h != h0);
    first[std::size_t(i) + 1] = int(neighbour.size());
  }
  // Weight w_vq / (d_v d_q) with w symmetric is row v of Yoshizawa's w_vq / d_q scaled by 1 / d_v:
  // the same embedding from a symmetric positive definite system, so CHOLMOD instead of sparse LU.
  Cholmod_cholesky solver;
  for(int round = 0; round < rounds && n > 0; ++round) {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(neighbour.size() / 2 + std::size_t(n));
    Eigen::VectorXd bx = Eigen::VectorXd::Zero(n), by = Eigen::VectorXd::Zero(n);
    for(int i = 0; i < n; ++i) {
      const int v = unknowns[std::size_t(i)];
      double sum = 0;
      for(int k = first[std::size_t(i)]; k < first[std::size_t(i) + 1]; ++k) {
        const int q = neighbour[std::size_t(k)];
        const double wgt = base[std::size_t(k)] / (divisor[std::size_t(v)] * divisor[std::size_t(q)]);
        sum += wgt;
        const int c = column[std::size_t(q)];
        if(c >= 0) { if(c < i) t.emplace_back(i, c, -wgt); }
        else {
          const Point_2& p = fixed.at(q);
          bx(i) += wgt * p.x();
          by(i) += wgt * p.y();
        }
      }
      t.emplace_back(i, i, sum);
    }
    Cholmod_cholesky::Matrix A(n, n);   // lower triangle
    A.setFromTriplets(t.begin(), t.end());
    std::string why;
    if(!(round == 0 ? solver.factor(A, why) : solver.refactor(A, why))) {   // the pattern stays: one analysis for all rounds
      message = "the Tutte embedding of a face could not be factored: " + why;
      return false;
    }
    const Eigen::VectorXd x = solver.solve(bx), y = solver.solve(by);
    for(int i = 0; i < n; ++i) solved[std::size_t(i)] = Point_2(x(i), y(i));
    if(rounds == 1) break;
    // the L2 stretch of the map from the chart to the reference triangles, per face and per vertex
    std::fill(sigma.begin(), sigma.end(), 0.);   // sums of area times squared stretch
    std::vector<double> vertex_area(nv, 0.);
    double total = 0, total_area = 0;
    for(int f : piece) {
      const int h0 = m.face_halfedge[std::size_t(f)], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
      const int vs[3] = {m.source(h0), m.source(h1), m.source(h2)};
      const double la = (*reference)[std::size_t(h0 >> 1)], lb = (*reference)[std::size_t(h1 >> 1)], lc = (*reference)[std::size_t(h2 >> 1)];
      const std::array<Point_2, 3> q = reference_triangle(la, lb, lc, 1.);
      const double qx = q[2].x(), qy = q[2].y();
      const Point_2 c0 = place(vs[0]), c1 = place(vs[1]), c2 = place(vs[2]);
      const double ux = c1.x() - c0.x(), uy = c1.y() - c0.y(), wx = c2.x() - c0.x(), wy = c2.y() - c0.y();
      const double det = ux * wy - wx * uy;
      // J = Q C^-1, Q = [(la, 0), (qx, qy)] as columns, C = [(ux, uy), (wx, wy)]; |J|_F^2 / 2
      const double i00 = wy / det, i01 = -wx / det, i10 = -uy / det, i11 = ux / det;
      const double j00 = la * i00 + qx * i10, j01 = la * i01 + qx * i11, j10 = qy * i10, j11 = qy * i11;
      const double s2 = 0.5 * (j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11);
      const double area = 0.5 * la * qy;
      for(int v : vs) { sigma[std::size_t(v)] += area * s2; vertex_area[std::size_t(v)] += area; }
      total += area * s2;
      total_area += area;
    }
    const double stretch = std::sqrt(total / (std::max)(total_area, 1e-300));
    if(!(stretch < best_stretch)) break;   // the stretch rises again: keep the best
    best_stretch = stretch;
    best = solved;
    for(std::size_t v = 0; v < nv; ++v) if(vertex_area[v] > 0) divisor[v] *= std::sqrt(sigma[v] / vertex_area[v]);
  }
  if(!best.empty()) solved = best;
  return true;
}

// What the relaxation needs of the cut: per mesh vertex its corner of P (or -1) and its path
// (or -1, for vertices inside the pieces), per mesh face its face of P; P's faces, their
// polygons, P's edges and the vertex sequences of their paths.
struct Polyhedron_cut_view
{
  const std::vector<int>* corner_of;
  const std::vector<int>* path_of_vertex;
  const std::vector<int>* pface;
  const std::vector<std::vector<int>>* pfaces;
  const std::vector<std::vector<Point_2>>* shape;
  const std::vector<std::array<int, 2>>* pedges;
  const std::vector<std::vector<int>>* paths;
};

// Relaxes `chart` (per mesh face its corners, all turning the way of `sign` = +1 or -1) towards
// the triangles of `reference` (one length per mesh edge, e.g. the input's Euclidean lengths)
// for at most `iterations` steps; returns the number of steps taken (with a nonzero step
// length). `message` says why it stopped early when the system could not be factored.
template <typename TM>
int relax_polyhedron_charts(const Mesh_arrays<TM>& m, const Polyhedron_cut_view& cut, const std::vector<double>& reference,
                            int iterations, double sign, std::vector<std::array<Point_2, 3>>& chart, std::string& message)
{
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces();
  const std::vector<int>& corner_of = *cut.corner_of;
  const std::vector<int>& path_of = *cut.path_of_vertex;
  const std::vector<int>& pface = *cut.pface;
  // unknowns: (u, v) per inner vertex, t per path vertex
  std::vector<int> column(nv, -1);
  int n = 0;
  for(std::size_t v = 0; v < nv; ++v) {
    if(corner_of[v] >= 0 || m.is_isolated(int(v))) continue;
    column[v] = n;
    n += path_of[v] >= 0 ? 1 : 2;
  }
  if(n == 0 || iterations <= 0) return 0;
  std::vector<double> target(cut.pedges->size(), 0.);   // each P edge's length in its polygons
  // one corner slot of one mesh face in its chart: position = base + sum of dir[i] * z[col[i]]
  struct Slot { Point_2 base; int col[2]; double dir[2][2]; int count; };
  std::vector<std::array<Slot, 3>> slot(nf);
  auto corner_position = [&](int j, int c, Point_2& p) {
    const std::vector<int>& f = (*cut.pfaces)[std::size_t(j)];
    for(std::size_t i = 0; i < f.size(); ++i) if(f[i] == c) { p = (*cut.shape)[std::size_t(j)][i]; return true; }
    return false;
  };
  for(std::size_t f = 0; f < nf; ++f) {
    int h = m.face_halfedge[f];
    for(int k = 0; k < 3; ++k, h = m.next[std::size_t(h)]) {
      const int v = m.source(h);
      Slot& s = slot[f][std::size_t(k)];
      s.count = 0;
      s.base = Point_2(0, 0);
      if(corner_of[std::size_t(v)] >= 0) {
        if(!corner_position(pface[f], corner_of[std::size_t(v)], s.base)) { message = "a corner is not on its piece's polygon"; return 0; }
      } else if(path_of[std::size_t(v)] >= 0) {
        const std::array<int, 2>& e = (*cut.pedges)[std::size_t(path_of[std::size_t(v)])];
        Point_2 a, b;
        if(!corner_position(pface[f], e[0], a) || !corner_position(pface[f], e[1], b)) { message = "a path is not on its piece's polygon"; return 0; }
        const double L = std::sqrt((b.x() - a.x()) * (b.x() - a.x()) + (b.y() - a.y()) * (b.y() - a.y()));
        target[std::size_t(path_of[std::size_t(v)])] = L;
        s.base = a;
        s.col[0] = column[std::size_t(v)];
        s.dir[0][0] = (b.x() - a.x()) / L;
        s.dir[0][1] = (b.y() - a.y()) / L;
        s.count = 1;
      } else {
        s.col[0] = column[std::size_t(v)];
        s.col[1] = column[std::size_t(v)] + 1;
        s.dir[0][0] = 1; s.dir[0][1] = 0;
        s.dir[1][0] = 0; s.dir[1][1] = 1;
        s.count = 2;
      }
    }
  }
  // the start: the unknowns read from the charts
  Eigen::VectorXd z(n);
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k) {
      const Slot& s = slot[f][std::size_t(k)];
      const Point_2& p = chart[f][std::size_t(k)];
      if(s.count == 1) z[s.col[0]] = (p.x() - s.base.x()) * s.dir[0][0] + (p.y() - s.base.y()) * s.dir[0][1];
      else if(s.count == 2) { z[s.col[0]] = p.x(); z[s.col[1]] = p.y(); }
    }
  auto position = [&](const Eigen::VectorXd& x, std::size_t f, int k) {
    const Slot& s = slot[f][std::size_t(k)];
    double px = s.base.x(), py = s.base.y();
    for(int i = 0; i < s.count; ++i) { px += s.dir[i][0] * x[s.col[i]]; py += s.dir[i][1] * x[s.col[i]]; }
    return Point_2(px, py);
  };
  // the reference triangles (turning like the charts) and their cotangent weights, clamped
  // positive so that the energy is convex and the matrix definite
  std::vector<std::array<Point_2, 3>> ref(nf);
  std::vector<std::array<double, 3>> weight(nf);   // of edge k = (slot k, slot k + 1)
  for(std::size_t f = 0; f < nf; ++f) {
    const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
    const double a = reference[std::size_t(h0 >> 1)], b = reference[std::size_t(h1 >> 1)], c = reference[std::size_t(h2 >> 1)];
    ref[f] = reference_triangle(a, b, c, sign);
    const double l[3] = {a, b, c};
    weight[f] = clamped_cotan_weights(l, std::abs(ref[f][2].y()) * a);
  }
  // The global step's energy: sum over the edges of every triangle of w |x_a - x_b - R (p_a - p_b)|^2.
  // Its Hessian has three blocks: inner vertices (x and y decoupled: the same matrix L for both),
  // path parameters (B), and the coupling C between them. Each global step is one block
  // Gauss-Seidel sweep (inner vertices with the paths fixed, then the paths): L is a scalar
  // Laplacian, a quarter of the coupled system's factorisation (433k faces: 0.5 s instead of 2.5 s).
  std::vector<int> block_index(std::size_t(n), -1);   // per column: its row in L (x and y columns) or in B
  std::vector<char> in_path(std::size_t(n), 0), axis(std::size_t(n), 0);   // axis: 1 for an inner vertex's y
  int n_inner = 0, n_path = 0;
  for(std::size_t v = 0; v < nv; ++v) {
    if(column[v] < 0) continue;
    if(path_of[v] >= 0) { in_path[std::size_t(column[v])] = 1; block_index[std::size_t(column[v])] = n_path++; }
    else { block_index[std::size_t(column[v])] = n_inner; block_index[std::size_t(column[v] + 1)] = n_inner++; axis[std::size_t(column[v] + 1)] = 1; }
  }
  // Assembled on two threads, each from half of the faces into its own matrices, then summed.
  const bool concurrent = nf >= 20000;
  const std::size_t half = nf / 2;
  Cholmod_cholesky::Matrix L_part[2], B_part[2];
  Eigen::SparseMatrix<double> C_part[2];
  run_on_two_threads([&](int part) {
    std::vector<Eigen::Triplet<double, int>> tl, tb, tc;   // L and B (lower triangles), C (inner columns x path parameters)
    const std::size_t f0 = part == 0 ? 0 : half, f1 = part == 0 ? half : nf;
    tl.reserve((f1 - f0) * 6);
    for(std::size_t f = f0; f < f1; ++f)
      for(int k = 0; k < 3; ++k) {
        const Slot* s[2] = {&slot[f][std::size_t(k)], &slot[f][std::size_t((k + 1) % 3)]};
        const double w = weight[f][std::size_t(k)];
        for(int x = 0; x < 2; ++x)
          for(int i = 0; i < s[x]->count; ++i)
            for(int y = 0; y < 2; ++y)
              for(int j = 0; j < s[y]->count; ++j) {
                const double coef = (x == y ? w : -w) * (s[x]->dir[i][0] * s[y]->dir[j][0] + s[x]->dir[i][1] * s[y]->dir[j][1]);
                const int r = s[x]->col[i], c = s[y]->col[j];
                if(coef == 0) continue;
                const bool pr = in_path[std::size_t(r)], pc = in_path[std::size_t(c)];
                const int br = block_index[std::size_t(r)], bc = block_index[std::size_t(c)];
                if(!pr && !pc) { if(i == 0 && j == 0 && br >= bc) tl.emplace_back(br, bc, coef); }   // x with x (y with y: the same)
                else if(pr && pc) { if(br >= bc) tb.emplace_back(br, bc, coef); }
                else if(!pr) tc.emplace_back(r, bc, coef);
              }
      }
    L_part[part].resize(n_inner, n_inner);
    B_part[part].resize(n_path, n_path);
    C_part[part].resize(n, n_path);   // rows: all columns (path rows stay empty)
    L_part[part].setFromTriplets(tl.begin(), tl.end());
    B_part[part].setFromTriplets(tb.begin(), tb.end());
    C_part[part].setFromTriplets(tc.begin(), tc.end());
  }, concurrent);
  const Cholmod_cholesky::Matrix L = L_part[0] + L_part[1], B = B_part[0] + B_part[1];
  const Eigen::SparseMatrix<double> C = C_part[0] + C_part[1];
  for(int part = 0; part < 2; ++part) { L_part[part] = Cholmod_cholesky::Matrix(); B_part[part] = Cholmod_cholesky::Matrix(); C_part[part] = Eigen::SparseMatrix<double>(); }
  Cholmod_cholesky inner_solver, path_solver;
  if((n_inner > 0 && !inner_solver.factor(L, message)) || (n_path > 0 && !path_solver.factor(B, message))) {
    message = "the relaxation's system could not be factored: " + message;
    return 0;
  }
  // the minimiser for fixed rotations (right-hand side `rhs`), one sweep from z
  auto global_step = [&](const Eigen::VectorXd& rhs) {
    Eigen::VectorXd zb(n_path);
    for(int c = 0; c < n; ++c) if(in_path[std::size_t(c)]) zb[block_index[std::size_t(c)]] = z[c];
    Eigen::VectorXd ra = rhs - C * zb;
    Eigen::VectorXd bx(n_inner), by(n_inner);
    for(int c = 0; c < n; ++c)
      if(!in_path[std::size_t(c)]) (axis[std::size_t(c)] == 0 ? bx : by)[block_index[std::size_t(c)]] = ra[c];
    const Eigen::VectorXd x = n_inner > 0 ? inner_solver.solve(bx) : bx, y = n_inner > 0 ? inner_solver.solve(by) : by;
    Eigen::VectorXd out(n);
    for(int c = 0; c < n; ++c)
      if(!in_path[std::size_t(c)]) out[c] = (axis[std::size_t(c)] == 0 ? x : y)[block_index[std::size_t(c)]];
    if(n_path > 0) {
      Eigen::VectorXd za = out;
      for(int c = 0; c < n; ++c) if(in_path[std::size_t(c)]) za[c] = 0;
      Eigen::VectorXd rb(n_path);
      for(int c = 0; c < n; ++c) if(in_path[std::size_t(c)]) rb[block_index[std::size_t(c)]] = rhs[c];
      rb -= C.transpose() * za;
      const Eigen::VectorXd t = path_solver.solve(rb);
      for(int c = 0; c < n; ++c) if(in_path[std::size_t(c)]) out[c] = t[block_index[std::size_t(c)]];
    }
    return out;
  };
  double scale = 0;
  for(const auto& sh : *cut.shape) for(const Point_2& p : sh) scale = (std::max)(scale, std::abs(p.x()) + std::abs(p.y()));
  // the largest fraction of the step from x by d that keeps at least half of every triangle's
  // area (signed as at the start) and of every gap along a path (after Smith and Schaefer 2015's
  // line search): the first root for each triangle, quadratic in the fraction, and each gap, linear
  auto largest_step = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& d) {
    double part_alpha[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    run_on_two_threads([&](int part) {
     double& alpha = part_alpha[part];
     for(std::size_t f = part == 0 ? 0 : half; f < (part == 0 ? half : nf); ++f) {
      Point_2 p[3], v[3];
      for(int k = 0; k < 3; ++k) {
        p[k] = position(x, f, k);
        const Slot& s = slot[f][std::size_t(k)];
        double dx = 0, dy = 0;
        for(int i = 0; i < s.count; ++i) { dx += s.dir[i][0] * d[s.col[i]]; dy += s.dir[i][1] * d[s.col[i]]; }
        v[k] = Point_2(dx, dy);
      }
      alpha = (std::min)(alpha, half_area_step(p, v, sign));   // area at least halved: far from folding
     }
    }, concurrent);
    double alpha = (std::min)(part_alpha[0], part_alpha[1]);
    for(std::size_t k = 0; k < cut.paths->size(); ++k) {
      const std::vector<int>& p = (*cut.paths)[k];
      if(p.size() <= 2) continue;
      for(std::size_t i = 1; i < p.size(); ++i) {   // gap from the previous vertex (0 at the first corner, target at the last)
        const bool first = i == 1, last = i + 1 == p.size();
        const double t1 = last ? target[k] : x[column[std::size_t(p[i])]], t0 = first ? 0. : x[column[std::size_t(p[i - 1])]];
        const double d1 = last ? 0. : d[column[std::size_t(p[i])]], d0 = first ? 0. : d[column[std::size_t(p[i - 1])]];
        if(d1 - d0 < 0) alpha = (std::min)(alpha, 0.5 * (t1 - t0) / (d0 - d1));
      }
    }
    return alpha;
  };
  int steps = 0;
  Eigen::VectorXd rhs(n), rhs_part(n);
  for(int it = 0; it < iterations; ++it) {
    run_on_two_threads([&](int part) {   // the local steps of the two halves of the faces, each into its own right-hand side
     Eigen::VectorXd& rhs_t = part == 0 ? rhs : rhs_part;
     rhs_t.setZero();
     for(std::size_t f = part == 0 ? 0 : half; f < (part == 0 ? half : nf); ++f) {
      // local step: the rotation closest to the map from the reference triangle to the chart's
      const Point_2 x[3] = {position(z, f, 0), position(z, f, 1), position(z, f, 2)};
      const std::array<double, 2> rot = closest_rotation(x, ref[f], weight[f]);
      const double c = rot[0], s = rot[1];
      // global step's right-hand side: w J^T (R (p_a - p_b) - (base_a - base_b))
      for(int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const Slot &sa = slot[f][std::size_t(k)], &sb = slot[f][std::size_t(k1)];
        const double ep[2] = {ref[f][std::size_t(k)].x() - ref[f][std::size_t(k1)].x(), ref[f][std::size_t(k)].y() - ref[f][std::size_t(k1)].y()};
        const double goal[2] = {c * ep[0] - s * ep[1] - (sa.base.x() - sb.base.x()), s * ep[0] + c * ep[1] - (sa.base.y() - sb.base.y())};
        const double w = weight[f][std::size_t(k)];
        for(int i = 0; i < sa.count; ++i) rhs_t[sa.col[i]] += w * (sa.dir[i][0] * goal[0] + sa.dir[i][1] * goal[1]);
        for(int i = 0; i < sb.count; ++i) rhs_t[sb.col[i]] -= w * (sb.dir[i][0] * goal[0] + sb.dir[i][1] * goal[1]);
      }
     }
    }, concurrent);
    rhs += rhs_part;
    const Eigen::VectorXd d = global_step(rhs) - z;
    const double alpha = (std::min)(1., largest_step(z, d));
    if(!(alpha > 1e-6)) break;   // blocked by a triangle about to fold: stay where the charts are bijective
    z += alpha * d;
    ++steps;
    // A triangle close to the half-area limit roughly halves alpha at every further step, so
    // the steps left would move z by about alpha in all (Spot 433k: 7 steps instead of 10, the
    // same quads); stop there.
    if(alpha < 0.01) break;
  }
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k) chart[f][std::size_t(k)] = position(z, f, k);
  return steps;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHART_RELAXATION_H
