// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTEGER_GRID_MAP_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTEGER_GRID_MAP_H

// An integer-grid map of a mesh of any genus and any number of boundary loops from a cross field
// and a scale (mixed-integer quadrangulation, Bommes, Zimmer and Kobbelt 2009): a seamless
// parametrisation whose gradients follow the field, scaled by the flat cone metric's conformal
// factor, then the seam translations, the singularities and the boundary's grid lines rounded to
// integers. Its edge lengths are a flat cone metric that tessellate_flat_metric() grids exactly.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cotan_weights.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/local_resolve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/map_factor.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/motorcycle_graph.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/quantization.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/t_mesh_faces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/seam_layout.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/seam_lattice.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/winding.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of integer_grid_map().
struct Integer_grid_map_status
{
  bool success = false;   ///< the map was computed, with no triangle folded or degenerate
  std::string message;    ///< why not
  /// vertices where the field's rotation around them is not the identity (its singularities),
  /// in vertex order (indices of `vertices(tm)`), with the quarter turns of that rotation
  std::vector<std::pair<std::size_t, int>> singularities;
  std::size_t cut_edges = 0;   ///< edges of the cut graph (seams)
  std::size_t arcs = 0;        ///< seams between the cut graph's nodes, one translation each
  std::size_t rounded = 0;     ///< integer values fixed (singularity and translation coordinates)
  std::size_t implied = 0;     ///< integer values that the seams' conditions fix given the rounded ones
  /// triangles whose image is folded (clockwise) or degenerate; success requires none
  std::size_t folded_triangles = 0;
  std::size_t seamless_folded_triangles = 0;   ///< the same count for the seamless map, before rounding
  /// vertices the map winds around otherwise than the field asks, no triangle folded (a branch
  /// point, the boundary folding back along its grid line); success requires none
  std::size_t winding_faults = 0;
  /// the T-mesh of the seamless map (Campen, Bommes and Kobbelt 2015: the separatrices traced
  /// from the singularities and corners until each meets a line traced before it): its arcs,
  /// whose lengths the rounding keeps nonnegative, and at least 1 where they measure half a grid
  /// unit or more in the seamless map
  std::size_t t_mesh_arcs = 0;
  std::string t_mesh_failure;      ///< why the T-mesh could not be traced (the rounding then keeps no arc), else empty
  std::size_t rounded_apart = 0;   ///< values rounded to an admitted integer other than the nearest, to keep the arcs' lengths
  /// arcs held at their least length where rounding would shorten them further: 0 (their ends
  /// aligned) for an arc shorter than half a grid unit in the seamless map, else 1
  std::size_t held_arcs = 0;
  std::size_t collapsed_arcs = 0;  ///< arcs of length 0 in the integer map
  std::size_t negative_arcs = 0;   ///< arcs of negative length in the integer map (it must then route a separatrix otherwise, or fold)
  /// the T-mesh's spans (boundary runs between corners; separatrices from a singularity or concave
  /// corner that end on the boundary or at a singularity), which both roundings keep at least 1
  /// long: those of them shorter in the integer map
  std::size_t t_mesh_spans = 0;
  std::size_t short_spans = 0;   ///< see `t_mesh_spans`
  /// the T-mesh's faces that are rectangles of the seamless map (all of them on a closed genus-0
  /// map: faces around a handle or along a boundary loop without corners need not be). A face of
  /// width or height 0 in the integer map (`collapsed_faces`) cannot keep its piece of the surface:
  /// the map must route a separatrix elsewhere than the seamless map does, or fold there
  std::size_t t_mesh_faces = 0;
  std::size_t t_mesh_nodes = 0;      ///< the T-mesh's nodes: singularities, corners and the separatrices' ends
  std::size_t collapsed_faces = 0;   ///< rectangles of width or height 0 in the integer map
  bool arcs_kept = false;          ///< the map kept is the second rounding's, which kept the arcs' lengths
  int stiffening_rounds = 0;   ///< re-solves with the faces around folded ones weighted more
  /// boundary vertices where the boundary turns (by a multiple of \f$\pi/2\f$ under the metric):
  /// integer points of the map, in vertex order, with the quarter turns there
  std::vector<std::pair<std::size_t, int>> boundary_corners;
  /// straight runs of the boundary between corners and seams: each lies on one grid line, one
  /// integer value each
  std::size_t boundary_lines = 0;
  /// the smallest ratio, over the triangles, of the image's signed area to the area the target
  /// scale asks for (1 where the map is exactly the target, negative for a folded triangle)
  double min_area_ratio = 0;
  /// \f$\sum_f A_f |\nabla P - s_f e^{-i\theta_f}|^2 / \sum_f A_f s_f^2\f$ of the continuous
  /// (seamless) and of the integer map: how far each is from the target, relative
  double seamless_energy = 0, integer_energy = 0;
};


/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Computes an integer-grid map of a triangle mesh (mixed-integer quadrangulation, Bommes, Zimmer
/// and Kobbelt 2009), closed or open: per corner, coordinates \f$P = U + iV\f$ such that
/// - across every edge the two faces' images differ by a symmetry of the square grid: a rotation
///   by a multiple of \f$\pi/2\f$ (the field's matching) and an integer translation;
/// - every singularity of the field is an integer point;
/// - on an open mesh, every boundary edge lies on a grid line (\f$U\f$ or \f$V\f$ an integer
///   along it) and every boundary corner is an integer point: the boundary runs along the grid;
/// - in each face the map is as close as possible (least squares, cotan weights) to the face's
///   shape under the metric, rotated so that the field's direction becomes the \f$U\f$ axis and
///   scaled so that one grid unit measures \f$h\f$. Under a flat cone metric whose cones are the
///   field's singularities (curvatures multiples of \f$\pi/2\f$), with the field parallel, that
///   target is exactly a seamless map on genus 0; on higher genus the field's rotation around the
///   handles differs from the metric's and the least squares spreads the difference.
///
/// <b>Method.</b> The field is combed along a breadth-first tree of the faces; the other edges,
/// pruned of branches that end at regular vertices, form the cut graph, whose arcs (chains
/// between nodes and singularities) each carry one rotation and one translation. Every corner is
/// an affine function of one unknown per vertex and of the arcs' translations and the
/// singularities' positions (the small unknowns), through the motions crossed around its vertex;
/// closing each vertex's fan gives the linear conditions on the small unknowns (at a singularity
/// of rotation \f$i^k\f$: \f$(1 - i^k) Z = T\f$; at a node: \f$T = 0\f$). One sparse Cholesky
/// factorisation of the whole system with the small unknowns ordered last (its trailing block is
/// their Schur complement; the vertex block split in two domains factored on two threads) and a
/// dense system for the small unknowns give the seamless map. Its T-mesh (Campen, Bommes and
/// Kobbelt 2015) is traced: the separatrices of the singularities and corners, straight lines
/// through the triangles and across the seams, each stopping where it meets a line traced before
/// (the motorcycle graph); each arc between two nodes has a length linear in the small unknowns.
/// Then the singularity coordinates, then the translations, are rounded one at a time, nearest to
/// an integer first, each re-solving only the dense system (restricted to the conditions'
/// solutions). The conditions have integer coefficients; unimodular changes of variables (a column
/// Hermite reduction) keep their integer solutions exactly, so each value is rounded to the
/// nearest integer that still leaves one (a cone of \f$-\pi\f$, whose closing has a
/// coefficient 2, constrains parities); values the others determine are not rounded again. No
/// rounding can leave a later value without an admissible integer. Both roundings keep the
/// T-mesh's spans at least 1 long, as a map that keeps the seamless map's T-mesh has them: the
/// boundary runs between corners, and the separatrices that run from a singularity or concave
/// corner to the boundary or to another singularity (else a cone falls on the boundary, or two
/// corners or cones on one point). If that map folds, the
/// rounding is done again, each value to the nearest admitted integer that keeps every arc of the
/// T-mesh nonnegative, and at least 1 where it measures half a grid unit or more in the seamless
/// map (an arc that still falls short is held there); the map with fewer folded triangles is
/// kept (`arcs_kept`). The T-mesh is not traced where the seamless map folds around a singularity
/// or along the boundary (`t_mesh_failure` says where). The read-back counts folded triangles:
/// rounding can fold the map where singularities are closer than about one grid unit; the status
/// then fails.
///
/// <b>Boundary.</b> On an open mesh the cut graph's seams end on the boundary, and the boundary
/// splits into straight runs at its corners (vertices where it turns under the metric) and where
/// seams end. A run lies on one grid line: each of its vertices keeps one unknown (its position
/// along the line) and the run one small unknown (the line), rounded with the translations; each
/// corner is a small unknown like a singularity. The field must follow the boundary (e.g.
/// boundary_aligned_field_of_metric() on a flat cone metric whose boundary is straight between
/// corners that turn by multiples of \f$\pi/2\f$); the status fails with a message otherwise.
///
/// \param tm a triangle mesh of one component, closed or with boundary
/// \param face_angles the cross field (\f$N = 4\f$): per face, the angle of one of its four
///   directions, counterclockwise from `halfedge(f)` in the face's frame under the metric of `np`
///   (as the package's field functions compute it with that `edge_length_map`)
/// \param h the grid's edge length under the metric
/// \param uv_map receives, for every halfedge `g` with a face, the image of `target(g)` in
///   `face(g)` as `std::array<double, 2>` (grid units: the lattice is \f$\mathbb{Z}^2\f$)
/// \param np `edge_length_map` (the metric, e.g. a flat cone metric on `tm`'s edges) or
///   `vertex_point_map`, index maps
///
/// Throws `Input_error` for several components, or \f$h \le 0\f$.
template <typename TriangleMesh, typename FaceAngleMap, typename HalfedgeUVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Integer_grid_map_status integer_grid_map(const TriangleMesh& tm, const FaceAngleMap& face_angles, double h, HalfedgeUVMap uv_map,
                                         const NamedParameters& np = parameters::default_values())
{
  using internal::Cplx;
  using internal::unit_power;
  typedef internal::Corner_expression Expr;
  Integer_grid_map_status st;
  if(!(h > 0) || !std::isfinite(h)) throw Input_error(Input_error::INVALID_ARGUMENT, "integer_grid_map(): the edge length must be positive");
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "integer_grid_map() needs a mesh of one component; this one has " +
                                                     std::to_string(topo.components.size()));
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();

  // 1.-4. the field combed, its matching and singularities, the cut graph, its arcs and the
  // boundary's corners and straight runs (internal/Integer_grid_map/seam_layout.h)
  internal::Seam_layout seams;
  {
    std::vector<double> theta0(nf);
    for(std::size_t f = 0; f < nf; ++f) theta0[f] = get(face_angles, m.faces[f]);
    if(!internal::lay_out_seams(m, topo, std::move(theta0), seams, st.message)) return st;
  }
  const std::vector<double>& theta = seams.theta;
  const std::vector<int>& turns = seams.turns;
  const std::vector<char>& singular = seams.singular;
  const int narcs = seams.narcs, nlines = seams.nlines;
  const std::vector<char>& bcorner = seams.boundary_corner;
  const std::vector<int>& turn_quarters = seams.turn_quarters;
  st.cut_edges = seams.cut_edges;
  st.arcs = std::size_t(narcs);
  st.boundary_lines = std::size_t(nlines);
  // 5. corner expressions in the unknowns, the closings around the vertices and the boundary's
  // line conditions (internal/Integer_grid_map/seam_layout.h)
  internal::Corner_layout layout;
  if(!internal::write_corner_expressions(m, topo, seams, layout, st.message)) return st;
  const std::vector<int>& big = layout.big;
  const std::vector<Cplx>& big_dir = layout.big_dir;
  const int nsmall = layout.nsmall, nbig = layout.nbig;
  const std::vector<Expr>& corner = layout.corner;
  for(std::size_t v = 0; v < nv; ++v) {
    if(singular[v]) {
      int k = ((turns[v] % 4) + 4) % 4;
      st.singularities.emplace_back(v, k > 2 ? k - 4 : k);
    }
    if(bcorner[v]) st.boundary_corners.emplace_back(v, turn_quarters[v]);
  }
  // 6. the energy: per face and side x (corner a = source(x), b = target(x)), the cotan weight of
  // the opposite corner times |P_b - P_a - s_f e^{-i theta_f} (z_b - z_a)|^2, in real unknowns:
  // big 2 per vertex inside and 1 on the boundary, small 2 per small unknown. The translation of
  // the whole map: with a singularity or a corner, the first one is at the origin (a condition
  // below); else on the boundary the first line is at 0 and one of its vertices holds the
  // position along it; else one vertex holds it.
  const int first_point = narcs + nlines < nsmall ? narcs + nlines : -1;
  const int pinned = first_point >= 0 ? -1 : nlines > 0 ? big[std::size_t(m.source(topo.loops[0][0] ^ 1))] : 0;
  std::vector<int> big_col(std::size_t(nbig), -1);
  int nb = 0;
  for(int b = 0; b < nbig; ++b) {
    if(b == pinned) continue;
    big_col[std::size_t(b)] = nb;
    nb += big_dir[std::size_t(b)] == Cplx(0, 0) ? 2 : 1;
  }
  const int ns = 2 * nsmall;
  std::vector<Eigen::Triplet<double>> tall, tbs;   // the whole matrix's lower triangle; Hbs
  Eigen::MatrixXd Hss;
  Eigen::VectorXd gb, gs;
  double target_norm = 0;
  struct Term { std::vector<std::pair<int, double>> b, s; double rhs; };   // one real residual row
  auto scale = [&](int) { return 1 / h; };
  std::vector<double> area(nf);
  // a face's vertex block, summed over its six rows before it joins the triplets (a third of
  // the triplets row by row: their sort was a quarter of the map's time at 114k faces)
  struct Face_block { int n = 0; int col[6]; double h[6][6]; } fb;
  auto local = [&](int col) {
    for(int i = 0; i < fb.n; ++i) if(fb.col[i] == col) return i;
    fb.col[fb.n] = col;
    for(int i = 0; i <= fb.n; ++i) fb.h[fb.n][i] = fb.h[i][fb.n] = 0;
    return fb.n++;
  };
  auto add_row = [&](const Term& t, double w) {
    int li[4];
    for(std::size_t a = 0; a < t.b.size(); ++a) li[a] = local(t.b[a].first);
    for(std::size_t a = 0; a < t.b.size(); ++a) {
      const auto& p = t.b[a];
      for(std::size_t c = 0; c < t.b.size(); ++c) fb.h[li[a]][li[c]] += w * p.second * t.b[c].second;
      for(const auto& q : t.s) tbs.emplace_back(p.first, q.first, w * p.second * q.second);
      gb[p.first] += w * p.second * t.rhs;
    }
    for(const auto& p : t.s) {
      for(const auto& q : t.s) Hss(p.first, q.first) += w * p.second * q.second;
      gs[p.first] += w * p.second * t.rhs;
    }
  };
  // the real rows of (expression difference) - target, for a complex coefficient c on the
  // complex unknown (X, Y): Re = c_r X - c_i Y, Im = c_i X + c_r Y
  auto rows_of = [&](const Expr& pa, const Expr& pb, Cplx target, Term& re, Term& imr) {
    re.b.clear(); re.s.clear(); imr.b.clear(); imr.s.clear();   // kept allocated from row to row
    auto put_big = [&](int v, Cplx c) {
      if(v < 0) return;
      const int col = big_col[std::size_t(v)];
      if(col < 0) return;
      const Cplx d = big_dir[std::size_t(v)];
      if(d != Cplx(0, 0)) {   // a real unknown s along d: c d s
        re.b.emplace_back(col, (c * d).real());
        imr.b.emplace_back(col, (c * d).imag());
        return;
      }
      re.b.emplace_back(col, c.real()); re.b.emplace_back(col + 1, -c.imag());
      imr.b.emplace_back(col, c.imag()); imr.b.emplace_back(col + 1, c.real());
    };
    auto put_small = [&](int k, Cplx c) {
      re.s.emplace_back(2 * k, c.real()); re.s.emplace_back(2 * k + 1, -c.imag());
      imr.s.emplace_back(2 * k, c.imag()); imr.s.emplace_back(2 * k + 1, c.real());
    };
    if(pa.vertex == pb.vertex && pa.vertex >= 0) put_big(pa.vertex, pb.a - pa.a);
    else { put_big(pb.vertex, pb.a); put_big(pa.vertex, -pa.a); }
    Expr d = pb;
    for(const auto& s : pa.small) d.add(s.first, -s.second);
    for(const auto& s : d.small) if(std::abs(s.second) > 0) put_small(s.first, s.second);
    re.rhs = target.real();
    imr.rhs = target.imag();
  };
  // the seams' conditions on the small unknowns (the closings, the lines, the gauge): homogeneous,
  // with integer coefficients (internal/Integer_grid_map/seam_lattice.h)
  typedef internal::Seam_lattice::Sparse Int_row;
  std::vector<Int_row> condition_rows;
  if(!internal::seam_condition_rows(layout, narcs, nlines, first_point, condition_rows)) {
    st.message = "the seams' conditions have coefficients that are not integers (a matching that is no quarter turn)";
    return st;
  }
  // the translations eliminated first, the positions of singularities and corners (ordered last)
  // only where no other variable can be
  internal::Seam_lattice lattice(ns, 2 * (narcs + nlines));
  for(const Int_row& row : condition_rows)
    if(!lattice.add(row, st.message)) return st;
  const std::vector<int> free_variables = lattice.free_variables();
  const Eigen::Index nt = Eigen::Index(free_variables.size());
  Eigen::SparseMatrix<double> B(ns, nt);   // y = B t
  {
    std::vector<Eigen::Triplet<double>> tb;
    for(Eigen::Index j = 0; j < nt; ++j)
      for(const auto& e : lattice.column(free_variables[std::size_t(j)])) tb.emplace_back(e.first, int(j), double(e.second));
    B.setFromTriplets(tb.begin(), tb.end());
  }
  // R^T R of the conditions: the penalty that makes the whole matrix positive definite
  Eigen::MatrixXd penalty = Eigen::MatrixXd::Zero(ns, ns);
  for(const Int_row& row : condition_rows)
    for(const auto& p : row)
      for(const auto& q : row) penalty(p.first, q.first) += double(p.second) * double(q.second);
  // the normal equations with a stiffness per face (1, raised where the map folds: Bommes et
  // al.'s local stiffening), factored with the small unknowns last (map_factor.h): their Schur
  // complement S y = rs on the small unknowns, S = Hss - Hbs^T Hbb^-1 Hbs
  Eigen::MatrixXd S;
  Eigen::VectorXd xg, rs; // xg = Hbb^-1 gb
  internal::Map_factor chol;
  Eigen::SparseMatrix<double> Hbs;
  std::vector<double> stiffness(nf, 1.);
  internal::Map_factor::Matrix A;
  double w = 1;   // the penalty's weight
  // face f's rows, weighted by k times their cotan weights: its vertex block summed in fb, its
  // products with the small unknowns in tbs, Hss, gb and gs
  auto face_terms = [&](std::size_t f, double k, Term& re, Term& imr) {
    const int x0 = m.face_halfedge[f];
    const Cplx rot = std::polar(scale(int(f)), -theta[f]);
    for(int x = x0, i = 0; i < 3; ++i, x = m.next[std::size_t(x)]) {
      // cot of the corner opposite side x: at source(prev(x))
      const int o = m.prev(x);
      const double lo = m.edge_length(x), la = m.edge_length(m.next[std::size_t(x)]), lb = m.edge_length(o);
      // the per-face sum over sides with these (possibly negative) weights is A_f |grad(P - target)|^2 >= 0
      const double wpos = 0.5 * (la * la + lb * lb - lo * lo) / (4 * area[f]);
      const Cplx edge = std::polar(lo, internal::halfedge_direction(m, x));
      rows_of(corner[std::size_t(x)], corner[std::size_t(m.next[std::size_t(x)])], rot * edge, re, imr);
      add_row(re, wpos * k);
      add_row(imr, wpos * k);
    }
  };
  auto assemble = [&]() -> bool {
    tall.clear(); tbs.clear();
    Term re, imr;
    Hss = Eigen::MatrixXd::Zero(ns, ns);
    gb = Eigen::VectorXd::Zero(nb); gs = Eigen::VectorXd::Zero(ns);
    target_norm = 0;
    for(std::size_t f = 0; f < nf; ++f) {
      const int x0 = m.face_halfedge[f];
      area[f] = triangle_area(m.edge_length(x0), m.edge_length(m.next[std::size_t(x0)]), m.edge_length(m.prev(x0)));
      target_norm += area[f] * scale(int(f)) * scale(int(f));
      face_terms(f, stiffness[f], re, imr);
      for(int i = 0; i < fb.n; ++i)
        for(int j = 0; j < fb.n; ++j) if(fb.col[j] <= fb.col[i]) tall.emplace_back(fb.col[i], fb.col[j], fb.h[i][j]);
      fb.n = 0;
    }
    // the whole matrix, small unknowns last; the conditions' penalty makes it positive definite
    w = 0;
    for(int k = 0; k < ns; ++k) w += Hss(k, k);
    w = ns > 0 && w > 0 ? w / ns : 1.;
    tall.reserve(tall.size() + tbs.size() + std::size_t(ns) * std::size_t(ns + 1) / 2);
    for(const auto& t : tbs) tall.emplace_back(nb + t.col(), t.row(), t.value());
    for(int c = 0; c < ns; ++c)
      for(int r = c; r < ns; ++r) tall.emplace_back(nb + r, nb + c, Hss(r, c) + w * penalty(r, c));   // zeros too: one pattern for every round
    A = internal::Map_factor::Matrix(nb + ns, nb + ns);
    A.setFromTriplets(tall.begin(), tall.end());
    A.makeCompressed();
    std::vector<Eigen::Triplet<double>>().swap(tall);
    std::string msg;
    if(!chol.factor(A, nb, msg)) { st.message = "the map's system could not be factored: " + msg; return false; }
    Hbs = Eigen::SparseMatrix<double>(nb, ns);
    Hbs.setFromTriplets(tbs.begin(), tbs.end());
    S = chol.schur() - w * penalty;
    xg = chol.solve_vertices(gb);
    rs = gs;
    if(nb > 0) rs.noalias() -= Hbs.transpose() * xg;
    return true;
  };
  // the faces stiffened (from `before` to stiffness[f]) once the small unknowns are rounded: only
  // their difference is added, into the matrix's entries in place (same pattern; at 457k faces a
  // full assembly was half of a stiffening round's 3.3 s), gb and Hbs
  auto restiffen = [&](const std::vector<std::size_t>& stiffened, const std::vector<double>& before) {
    tbs.clear();
    Term re, imr;
    const Eigen::MatrixXd hss0 = Hss;
    for(std::size_t i = 0; i < stiffened.size(); ++i) {
      const std::size_t f = stiffened[i];
      face_terms(f, stiffness[f] - before[i], re, imr);
      for(int a = 0; a < fb.n; ++a)
        for(int b = 0; b < fb.n; ++b) if(fb.col[b] <= fb.col[a]) A.coeffRef(fb.col[a], fb.col[b]) += fb.h[a][b];
      fb.n = 0;
    }
    for(const auto& t : tbs) {
      A.coeffRef(nb + t.col(), t.row()) += t.value();
      Hbs.coeffRef(t.row(), t.col()) += t.value();
    }
    for(int c = 0; c < ns; ++c)
      for(int r = c; r < ns; ++r) if(Hss(r, c) != hss0(r, c)) A.coeffRef(nb + r, nb + c) += Hss(r, c) - hss0(r, c);
  };
  if(!assemble()) return st;
  auto big_of = [&](const Eigen::VectorXd& small) {   // the vertex unknowns given the small ones
    return chol.solve_vertices(Eigen::VectorXd(gb - Hbs * small));
  };
  Eigen::VectorXd y, z;
  auto value = [&](const Expr& e) {
    Cplx p(0, 0);
    if(e.vertex >= 0) {
      const int col = big_col[std::size_t(e.vertex)];
      const Cplx d = big_dir[std::size_t(e.vertex)];
      if(col >= 0) p += d != Cplx(0, 0) ? e.a * d * z[col] : e.a * Cplx(z[col], z[col + 1]);
    }
    for(const auto& s : e.small) p += s.second * Cplx(y[2 * s.first], y[2 * s.first + 1]);
    return p;
  };
  auto image = [&](int x) { return value(corner[std::size_t(x)]); };   // of the corner at source(x)
  auto folded = [&](std::size_t f) {
    const int x0 = m.face_halfedge[f];
    const Cplx p0 = image(x0), p1 = image(m.next[std::size_t(x0)]), p2 = image(m.prev(x0));
    return !((p1 - p0).real() * (p2 - p0).imag() - (p1 - p0).imag() * (p2 - p0).real() > 0);
  };
  // local stiffening of the integer map (its small unknowns fixed, only the vertices move): the
  // faces around a folded one weigh three times more, re-solved, until no triangle folds or two
  // rounds in a row fold as many, in two phases of up to eight rounds. First each round re-solves
  // only the vertices within 8 grid units (and 2 rings) of the triangles folded so far, the others
  // held (local_resolve.h): the stiffening's effect is mostly local, and a factorisation of the
  // whole system per round was most of the map's time at 457k faces (4 rounds, 1.5-2 s each).
  // If triangles still fold, the whole system is factored again each round (measured in the
  // manual). The seamless map is not stiffened: each round there needed a new Schur complement
  // and the shared meshes remeshed no better with it.
  const std::vector<double> expected_angle = internal::map_angle_sums_expected(m, seams);
  std::vector<char> free_vertex(nv, 0), free_col(std::size_t(nb), 0);
  std::vector<double> reach(nv, std::numeric_limits<double>::infinity());
  std::vector<int> hops(nv, 0);
  auto free_near = [&](const std::vector<std::size_t>& folded_faces) {
    internal::mark_vertices_near_faces(m, folded_faces, 8 * h, 2, reach, hops, free_vertex);
    for(std::size_t v = 0; v < nv; ++v) {
      if(!free_vertex[v] || big[v] < 0) continue;
      const int col = big_col[std::size_t(big[v])];
      if(col < 0) continue;
      free_col[std::size_t(col)] = 1;
      if(big_dir[std::size_t(big[v])] == Cplx(0, 0)) free_col[std::size_t(col) + 1] = 1;
    }
  };
  auto unfold = [&]() -> bool {
    z = big_of(y);   // the unstiffened system, as factored
    for(int phase = 0; phase < 2; ++phase) {
      std::size_t best = std::size_t(-1);
      int stalled = 0;
      for(int round = 0; round < 8; ++round) {
        std::vector<char> stiffen(nf, 0);
        std::vector<std::size_t> folded_faces;
        for(std::size_t f = 0; f < nf; ++f) if(folded(f)) folded_faces.push_back(f);
        if(folded_faces.empty())   // counterclockwise everywhere: the faces around a misfolded vertex
          folded_faces = internal::faces_around(m, internal::winding_faults(m, expected_angle, image));
        const std::size_t count = folded_faces.size();
        if(count == 0) return true;
        stalled = count < best ? 0 : stalled + 1;
        best = (std::min)(best, count);
        if(stalled >= 2) break;
        for(std::size_t f : folded_faces) {
          int x = m.face_halfedge[f];
          for(int i = 0; i < 3; ++i, x = m.next[std::size_t(x)]) {   // the faces around its corners
            int g = m.vertex_out[std::size_t(m.source(x))], g0 = g;
            do { if(m.face[std::size_t(g)] >= 0) stiffen[std::size_t(m.face[std::size_t(g)])] = 1; g = m.ccw_out(g); } while(g != g0);
          }
        }
        std::vector<std::size_t> stiffened;
        std::vector<double> before;
        for(std::size_t f = 0; f < nf; ++f)
          if(stiffen[f]) { stiffened.push_back(f); before.push_back(stiffness[f]); stiffness[f] *= 3; }
        ++st.stiffening_rounds;
        restiffen(stiffened, before);
        std::string msg;
        if(phase == 0) {
          free_near(folded_faces);
          if(!internal::resolve_on_region(A, nb, Eigen::VectorXd(gb - Hbs * y), free_col, z, msg)) { st.message = msg; return false; }
        } else {
          if(!A.isCompressed()) A.makeCompressed();
          if(!chol.factor(A, nb, msg)) { st.message = "the map's system could not be factored: " + msg; return false; }
          z = big_of(y);
        }
      }
    }
    return true;
  };
  // the seamless map on the lattice's span: t minimises t^T G t - 2 g^T t, G = B^T S B, g = B^T rs
  const Eigen::MatrixXd SB = S * B;
  Eigen::MatrixXd Ginv;
  Eigen::VectorXd t;
  {
    const Eigen::MatrixXd G = B.transpose() * SB;
    const Eigen::LLT<Eigen::MatrixXd> llt(G);
    if(llt.info() != Eigen::Success) { st.message = "the map's system on the seams' conditions is singular"; return st; }
    Ginv = llt.solve(Eigen::MatrixXd::Identity(nt, nt));
    t = Ginv * (B.transpose() * rs);
  }
  y = B * t;
  // 8. the seamless map read back, and its T-mesh (motorcycle_graph.h)
  auto folds = [&]() {
    std::size_t n = 0;
    for(std::size_t f = 0; f < nf; ++f) n += folded(f);
    return n;
  };
  auto map_energy = [&]() {
    double energy = 0;
    for(std::size_t f = 0; f < nf; ++f) {
      const int x0 = m.face_halfedge[f];
      const Cplx rot = std::polar(scale(int(f)), -theta[f]);
      for(int x = x0, i = 0; i < 3; ++i, x = m.next[std::size_t(x)]) {
        const double lo = m.edge_length(x), la = m.edge_length(m.next[std::size_t(x)]), lb = m.edge_length(m.prev(x));
        const double w = 0.5 * (la * la + lb * lb - lo * lo) / (4 * area[f]);
        const Cplx diff = value(corner[std::size_t(m.next[std::size_t(x)])]) - value(corner[std::size_t(x)]) -
                          rot * std::polar(lo, internal::halfedge_direction(m, x));
        energy += w * std::norm(diff);
      }
    }
    return energy / target_norm;
  };
  z = big_of(y);
  st.seamless_energy = map_energy();
  st.seamless_folded_triangles = folds();
  internal::Separatrix_arcs arcs;
  if(!internal::trace_separatrix_arcs(m, topo, seams, layout, expected_angle, image, y, arcs, st.t_mesh_failure)) arcs = internal::Separatrix_arcs();
  st.t_mesh_arcs = arcs.forms.size();
  st.t_mesh_spans = arcs.spans.size();
  std::vector<internal::Linear_form> face_sides;
  st.t_mesh_faces = internal::t_mesh_face_sides(arcs, y, face_sides);
  st.t_mesh_nodes = internal::t_mesh_nodes(arcs);
  // the faces' sides are read back, not kept by the rounding: kept at least 1 by the second
  // rounding, the casting at 1,000 quads remeshed (it failed) but the holes at 1,000 failed, and
  // 41 of 58 remeshes at 1,000 and 2,500 quads had min scaled Jacobian > 0 against 38 (greedy
  // rounding with conditions is order-dependent: faces want an exact integer program)
  // 9. the rounding (quantization.h), the vertex unknowns and local stiffening: first Bommes et
  // al.'s greedy rounding alone; if the map folds, again keeping the T-mesh's arcs (the better
  // map kept). Measured on test_remeshing's maps, the arcs' conditions alone: the casting unfolds
  // and the cheburashka folds 36 triangles instead of 71, but at 1,000 quads the feline, whose
  // thin limbs leave no room for arcs of length 1, folds 2,451 of its 99,732 triangles (it was valid).
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Brow = B;
  const internal::Seam_lattice lattice0 = lattice;
  const Eigen::MatrixXd Ginv0 = Ginv;
  const Eigen::VectorXd t0 = t;
  auto round_and_unfold = [&](const std::vector<internal::Linear_form>& kept, const std::vector<internal::Linear_form>& spans) -> bool {
    internal::Quantization_counts qc;
    if(!internal::quantize(lattice, Brow, Ginv, t, 2 * (narcs + nlines), kept, spans, qc, st.message)) return false;
    st.rounded = qc.rounded;
    st.implied = qc.implied;
    st.rounded_apart = qc.moved;
    st.held_arcs = qc.held_arcs;
    // every small unknown is now determined by the lattice: the exact integers, free of round-off
    for(int k = 0; k < ns; ++k) {
      if(!lattice.determined(k)) { st.message = "a seam value was left undetermined by the rounding"; return false; }
      y[k] = double(lattice.offset(k));
    }
    const internal::T_mesh_lengths tl = internal::t_mesh_lengths(arcs, face_sides, y);
    st.negative_arcs = tl.negative_arcs;
    st.collapsed_arcs = tl.collapsed_arcs;
    st.short_spans = tl.short_spans;
    st.collapsed_faces = tl.collapsed_faces;
    if(!unfold()) { if(st.message.empty()) st.message = "the stiffened system could not be solved"; return false; }
    return true;
  };
  if(!round_and_unfold({}, arcs.spans)) return st;
  std::size_t faults = folds();
  if(faults == 0) faults = internal::winding_faults(m, expected_angle, image).size();
  if(faults > 0 && !arcs.forms.empty()) {
    const Integer_grid_map_status first = st;
    const Eigen::VectorXd y1 = y, z1 = z;
    {   // the stiffness back to 1, the system factored again
      std::vector<std::size_t> stiffened;
      std::vector<double> before;
      for(std::size_t f = 0; f < nf; ++f)
        if(stiffness[f] != 1.) { stiffened.push_back(f); before.push_back(stiffness[f]); stiffness[f] = 1.; }
      restiffen(stiffened, before);
      std::string msg;
      if(!A.isCompressed()) A.makeCompressed();
      if(!stiffened.empty() && !chol.factor(A, nb, msg)) { st.message = "the map's system could not be factored: " + msg; return st; }
    }
    lattice = lattice0; Ginv = Ginv0; t = t0;
    const bool done = round_and_unfold(arcs.forms, arcs.spans);
    std::size_t faults2 = done ? folds() : faults + 1;
    if(done && faults2 == 0) faults2 = internal::winding_faults(m, expected_angle, image).size();
    st.arcs_kept = faults2 < faults;
    if(!st.arcs_kept) {   // the first map stays
      const int rounds = st.stiffening_rounds;
      (st = first).stiffening_rounds = rounds;
      y = y1; z = z1;
    }
    st.message.clear();
  }
  st.integer_energy = map_energy();
  st.min_area_ratio = std::numeric_limits<double>::infinity();
  for(std::size_t f = 0; f < nf; ++f) {
    const int x0 = m.face_halfedge[f], x1 = m.next[std::size_t(x0)], x2 = m.next[std::size_t(x1)];
    const Cplx p0 = value(corner[std::size_t(x0)]), p1 = value(corner[std::size_t(x1)]), p2 = value(corner[std::size_t(x2)]);
    for(int x : {x0, x1, x2}) {
      const Cplx p = value(corner[std::size_t(m.next[std::size_t(x)])]);   // target(x) = source(next(x))
      put(uv_map, m.halfedge_descriptor_of(x, tm), std::array<double, 2>{{p.real(), p.imag()}});
    }
    const double a = 0.5 * ((p1 - p0).real() * (p2 - p0).imag() - (p1 - p0).imag() * (p2 - p0).real());
    st.min_area_ratio = (std::min)(st.min_area_ratio, a / (area[f] * scale(int(f)) * scale(int(f))));
    if(!(a > 0)) ++st.folded_triangles;
  }
  st.winding_faults = st.folded_triangles == 0 ? internal::winding_faults(m, expected_angle, image).size() : 0;
  if((st.success = st.folded_triangles == 0 && st.winding_faults == 0)) return st;
  if(st.folded_triangles > 0)
    st.message = std::to_string(st.folded_triangles) + " triangles are folded by the integer-grid map (singularities or seams "
                 "closer than about one grid unit: try a smaller edge length)";
  else
    st.message = "the integer-grid map winds around " + std::to_string(st.winding_faults) + " vertices otherwise than the field asks "
                 "(the boundary folds back along a grid line, or a branch point), with no triangle folded: try a smaller edge length";
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTEGER_GRID_MAP_H
