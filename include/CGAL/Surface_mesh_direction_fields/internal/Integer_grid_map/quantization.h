// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_QUANTIZATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_QUANTIZATION_H

// The rounding of integer_grid_map() (integer_grid_map.h): the seams' small unknowns y = B t,
// continuous minimisers of t^T G t - 2 g^T t, are made integers one at a time (Bommes, Zimmer and
// Kobbelt 2009's greedy rounding), each to an integer the seams' lattice admits
// (seam_lattice.h), while the arcs of the seamless map's T-mesh (motorcycle_graph.h) keep
// nonnegative lengths (Campen, Bommes and Kobbelt 2015's condition for a quantization that a
// valid map can follow), and those at least half a unit long in the seamless map at least 1:
// among the admitted integers nearest to a value, the first that keeps every arc at its least
// length once t is re-solved is taken; an arc that still falls short is held at its least length
// (0: its ends aligned), a further condition on the lattice and on t. The T-mesh's spans (a
// boundary run between corners, a separatrix from a cone or corner to the boundary or to another
// cone) keep a length of at least 1 in both roundings: a map that keeps the T-mesh has them so.

#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/motorcycle_graph.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/seam_lattice.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Quantization_counts
{
  std::size_t rounded = 0;         // values rounded
  std::size_t implied = 0;         // values the rounded ones and the held arcs determined
  std::size_t moved = 0;           // values rounded to an integer other than the nearest admitted one, to keep the arcs nonnegative
  std::size_t held_arcs = 0;       // arcs and spans held at their least length
};

// Rounds y = B t (B given by its rows Brow; Ginv = G^-1, updated in place with t) in two phases:
// values from index `first_point` on (singularity and corner positions) first, then the others;
// the nearest to an integer first, keeping the lengths of `arcs` and `spans` (either may be empty).
// False with a message if the lattice admits no integer near a value.
inline bool quantize(Seam_lattice& lattice, const Eigen::SparseMatrix<double, Eigen::RowMajor>& Brow, Eigen::MatrixXd& Ginv,
                     Eigen::VectorXd& t, int first_point, const std::vector<Linear_form>& arcs, const std::vector<Linear_form>& spans,
                     Quantization_counts& counts, std::string& message)
{
  const int ns = int(Brow.rows());
  const Eigen::Index nt = Brow.cols();
  std::vector<const Linear_form*> kept;   // the arcs, then the spans
  for(const Linear_form& a : arcs) kept.push_back(&a);
  for(const Linear_form& a : spans) kept.push_back(&a);
  // the kept lengths in t: Q = R B, their current values q = Q t
  Eigen::SparseMatrix<double, Eigen::RowMajor> Q;
  {
    std::vector<Eigen::Triplet<double>> tr;
    for(std::size_t j = 0; j < kept.size(); ++j)
      for(const auto& e : kept[j]->terms) tr.emplace_back(int(j), e.first, e.second);
    Eigen::SparseMatrix<double, Eigen::RowMajor> R(Eigen::Index(kept.size()), ns);
    R.setFromTriplets(tr.begin(), tr.end());
    Q = (R * Eigen::SparseMatrix<double>(Brow)).pruned();
  }
  Eigen::VectorXd q = Q * t;
  std::vector<char> held(kept.size(), 0);
  const double g_scale = nt > 0 ? (std::max)(Ginv.diagonal().cwiseAbs().maxCoeff(), 1e-300) : 1.;
  const double tol = 1e-7;
  // an arc at least half a unit long in the seamless map keeps a length of at least 1; a shorter
  // one may collapse to 0 (its ends aligned). Measured on test_remeshing's maps (greedy rounding
  // alone / collapses allowed everywhere / no collapse at all / this): casting 14 / 12 / 0 / 0
  // folded triangles, cheburashka 71 / 65 / 172 / 36, homer 46 / 57 / 456 / 48.
  Eigen::VectorXd min_arc(q.size());
  for(Eigen::Index j = 0; j < q.size(); ++j) min_arc[j] = std::size_t(j) >= arcs.size() || q[j] >= 0.5 ? 1. : 0.;
  // a @ t moved by d * step within the conditions so far (c = G^-1 a, d = a @ c, qc = Q c if
  // known), a rank-one update of G^-1
  auto update = [&](const Eigen::VectorXd& c, double d, double step, const Eigen::VectorXd& qc) {
    t.noalias() += c * step;
    if(qc.size() > 0) q.noalias() += qc * step; else q.noalias() += Q * (c * step);
    Ginv.noalias() -= (c / d) * c.transpose();
  };
  // a @ t = target (a not yet fixed: else round-off on a value nearly determined)
  auto impose = [&](const Eigen::VectorXd& a, double target) {
    const Eigen::VectorXd c = Ginv * a;
    const double d = a.dot(c);
    if(d > 1e-14 * g_scale) update(c, d, (target - a.dot(t)) / d, Eigen::VectorXd());
  };
  // the arcs fallen short of their least length held there (or at the next length with an
  // integer solution), the shortest first
  auto hold_short_arcs = [&]() -> bool {
    for(;;) {
      Eigen::Index worst = -1;
      for(Eigen::Index j = 0; j < q.size(); ++j)
        if(!held[std::size_t(j)] && q[j] < min_arc[j] - tol && (worst < 0 || q[j] - min_arc[j] < q[worst] - min_arc[worst])) worst = j;
      if(worst < 0) return true;
      held[std::size_t(worst)] = 1;
      Seam_lattice::Sparse row;
      for(const auto& e : kept[std::size_t(worst)]->terms) row[e.first] = Seam_lattice::Int(std::lround(e.second));
      std::string why;
      const Seam_lattice::Int shortest = Seam_lattice::Int(min_arc[worst]);
      Seam_lattice::Int length = shortest;
      while(length < 4 + shortest && !lattice.add(row, why, length)) {
        if(why.find("2^30") != std::string::npos) { message = why; return false; }
        ++length;   // a parity: the next length with an integer solution
      }
      if(length == 4 + shortest) continue;   // no short length is admitted: left negative, counted at the end
      ++counts.held_arcs;
      impose(Eigen::VectorXd(Q.row(worst).transpose()), double(length));
    }
  };
  auto current = [&](int k) { return Brow.row(k).dot(t); };
  for(int phase = 0; phase < 2; ++phase) {
    std::vector<int> todo;
    for(int k = 0; k < ns; ++k) if((k >= first_point) == (phase == 0)) todo.push_back(k);
    while(!todo.empty()) {
      std::size_t best = 0;
      double best_gap = 2;
      for(std::size_t i = 0; i < todo.size(); ++i) {
        const int k = todo[i];
        if(lattice.determined(k)) { best = i; best_gap = -1; break; }   // implied: taken off first
        const double v = current(k), gap = std::abs(v - std::round(v));
        if(gap < best_gap) { best = i; best_gap = gap; }
      }
      const int k = todo[best];
      todo.erase(todo.begin() + std::ptrdiff_t(best));
      if(best_gap < 0) { ++counts.implied; continue; }
      const double yk = current(k);
      const Eigen::VectorXd ak = Brow.row(k).transpose();
      const Eigen::VectorXd c = Ginv * ak;
      const double d = ak.dot(c);
      const Eigen::VectorXd qc = kept.empty() ? Eigen::VectorXd() : Eigen::VectorXd(Q * c);
      // the admitted integers r0, r0 + dir, r0 - dir, r0 + 2 dir, ...: the first that keeps every
      // arc at its least length once t is re-solved, else the one that falls least short
      const double r0 = std::round(yk), dir = yk >= r0 ? 1 : -1;
      double chosen = 0, chosen_min = -std::numeric_limits<double>::infinity(), nearest = 0;
      int admitted = 0;
      for(int step = 0; step <= 64 && admitted < 5; ++step) {
        const double v = step == 0 ? r0 : r0 + dir * ((step + 1) / 2) * (step % 2 == 1 ? 1 : -1);
        if(!lattice.admits(k, Seam_lattice::Int(v))) continue;
        ++admitted;
        double lowest = std::numeric_limits<double>::infinity();
        if(d > 1e-14 * g_scale && !kept.empty()) {
          const double s = (v - yk) / d;
          for(Eigen::Index j = 0; j < q.size(); ++j) if(!held[std::size_t(j)]) lowest = (std::min)(lowest, q[j] + qc[j] * s - min_arc[j]);
        }
        if(admitted == 1) nearest = v;
        if(admitted == 1 || lowest > chosen_min + tol) {
          chosen = v;
          chosen_min = lowest;
        }
        if(!(chosen_min < -tol)) break;
      }
      if(admitted == 0) { message = "no integer near " + std::to_string(yk) + " is admitted by the seams' conditions"; return false; }
      counts.moved += chosen != nearest;
      Seam_lattice::Sparse fix;
      fix[k] = 1;
      if(!lattice.add(fix, message, Seam_lattice::Int(chosen))) return false;
      if(d > 1e-14 * g_scale) update(c, d, (chosen - yk) / d, qc);
      ++counts.rounded;
      if(!kept.empty() && !hold_short_arcs()) return false;
    }
  }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_QUANTIZATION_H
