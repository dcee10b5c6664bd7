// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ROTATION_MINIMAX_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ROTATION_MINIMAX_H

// The lowest largest rotation of a trivial connection. Two connections with the same holonomy
// around every dual cycle differ by the coboundary of a potential p on the faces: the
// adjustment angle of the edge between faces a and b changes by p[a] - p[b]. Keeping every
// |x0_e + p[a] - p[b]| <= T is a system of difference constraints, solvable (Bellman-Ford) unless
// some dual cycle turns by more than T times its number of edges; so the lowest largest
// rotation over all connections with the holonomies of x0 is the largest mean rotation of a
// dual cycle, and a cycle with a mean above T proves that no such connection stays within T.

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The dual graph of the unknowns: arc k runs from tail[k] to head[k] and bounds p[head] -
// p[tail] by T - sign[k] x0[column[k]] (two arcs per column, one per direction).
struct Rotation_constraint_graph
{
  int nodes = 0;
  std::vector<int> first, tail, head, column;   // arcs in compressed rows by tail
  std::vector<double> sign;
  std::vector<std::array<int, 2>> ends;   // ends[c] = (a, b): the unknown of column c changes by p[a] - p[b]

  // arc relaxations allowed to one Bellman-Ford run: 1000 passes over the arcs
  std::size_t budget() const { return 1000 * tail.size() + 1000000; }

  Rotation_constraint_graph(int n, const std::vector<std::array<int, 2>>& column_ends)
      : nodes(n), first(std::size_t(n) + 1, 0), ends(column_ends)
  {
    for(const auto& e : ends) { ++first[std::size_t(e[0]) + 1]; ++first[std::size_t(e[1]) + 1]; }
    for(int v = 0; v < n; ++v) first[std::size_t(v) + 1] += first[std::size_t(v)];
    const std::size_t arcs = 2 * ends.size();
    tail.resize(arcs); head.resize(arcs); column.resize(arcs); sign.resize(arcs);
    std::vector<int> fill(first.begin(), first.end() - 1);
    for(std::size_t c = 0; c < ends.size(); ++c) {
      const int a = ends[c][0], b = ends[c][1];
      // p[a] - p[b] <= T - x0_c: arc b -> a; p[b] - p[a] <= T + x0_c: arc a -> b
      const int k1 = fill[std::size_t(b)]++, k2 = fill[std::size_t(a)]++;
      tail[std::size_t(k1)] = b; head[std::size_t(k1)] = a; column[std::size_t(k1)] = int(c); sign[std::size_t(k1)] = 1;
      tail[std::size_t(k2)] = a; head[std::size_t(k2)] = b; column[std::size_t(k2)] = int(c); sign[std::size_t(k2)] = -1;
    }
  }
};

enum class Rotation_bound_outcome { WITHIN, CYCLE, UNDECIDED };

// Whether the potentials exist for bound T (Bellman-Ford from all nodes at 0, first-in first-out,
// at most `budget` arc relaxations). WITHIN: `p` holds them; CYCLE: a dual cycle of
// `cycle_length` edges turns by `cycle_mean` per edge on average, more than T (its arcs in
// `cycle_arcs` if given: the cycle turns by the sum of sign[k] x0[column[k]] over them).
inline Rotation_bound_outcome rotations_within(const Rotation_constraint_graph& g, const Eigen::VectorXd& x0, double T,
                                               std::vector<double>& p, double& cycle_mean, int& cycle_length, std::size_t budget,
                                               std::vector<int>* cycle_arcs = nullptr)
{
  const int n = g.nodes;
  p.assign(std::size_t(n), 0.);
  std::vector<int> pred(std::size_t(n), -1), queue(std::size_t(n) + 1), color(std::size_t(n), 0);
  std::vector<char> queued(std::size_t(n), 1);
  std::size_t front = 0, back = 0;
  for(int v = 0; v < n; ++v) queue[back++] = v;
  const std::size_t ring = queue.size();
  std::size_t work = 0, waiting = std::size_t(n), improvements = 0;
  auto weight = [&](int k) { return T - g.sign[std::size_t(k)] * x0[g.column[std::size_t(k)]]; };
  // A cycle of the predecessor arcs has negative weight: looked for after every n improvements
  // (walks to the roots, each node once), which finds a negative cycle long before a path of n
  // arcs would.
  auto negative_cycle = [&]() {
    std::fill(color.begin(), color.end(), 0);
    for(int s = 0; s < n; ++s) {
      int x = s;
      while(x >= 0 && color[std::size_t(x)] == 0) { color[std::size_t(x)] = s + 1; x = pred[std::size_t(x)] >= 0 ? g.tail[std::size_t(pred[std::size_t(x)])] : -1; }
      if(x < 0 || color[std::size_t(x)] != s + 1) continue;
      double turn = 0, total = 0;
      int length = 0;
      const int w = x;
      if(cycle_arcs) cycle_arcs->clear();
      do {
        const int a = pred[std::size_t(x)];
        if(cycle_arcs) cycle_arcs->push_back(a);
        turn += g.sign[std::size_t(a)] * x0[g.column[std::size_t(a)]];
        total += weight(a);
        ++length;
        x = g.tail[std::size_t(a)];
      } while(x != w);
      if(total < 0) { cycle_mean = turn / length; cycle_length = length; return true; }
    }
    return false;
  };
  while(waiting > 0) {
    const int u = queue[front];
    front = (front + 1) % ring;
    --waiting;
    queued[std::size_t(u)] = 0;
    for(int k = g.first[std::size_t(u)]; k < g.first[std::size_t(u) + 1]; ++k) {
      if(++work > budget) return Rotation_bound_outcome::UNDECIDED;
      const int v = g.head[std::size_t(k)];
      const double dv = p[std::size_t(u)] + weight(k);
      if(!(dv < p[std::size_t(v)] - 1e-13 * (1 + std::abs(p[std::size_t(v)])))) continue;
      p[std::size_t(v)] = dv;
      pred[std::size_t(v)] = k;
      if(++improvements % std::size_t(n) == 0 && negative_cycle()) return Rotation_bound_outcome::CYCLE;
      if(!queued[std::size_t(v)]) { queued[std::size_t(v)] = 1; queue[back] = v; back = (back + 1) % ring; ++waiting; }
    }
  }
  return Rotation_bound_outcome::WITHIN;
}

// Bisection for the lowest largest rotation over the connections x0 + coboundary: on return
// [lo, hi] brackets it (lo proven by a cycle, 0 if none was found; hi = max |x0| at worst), `p`
// holds potentials that keep every rotation within hi. Stops after `steps` decisions, at a
// relative width of 1e-3, or at the first undecided bound.
inline void lowest_largest_rotation(const Rotation_constraint_graph& g, const Eigen::VectorXd& x0, int steps, std::size_t budget,
                                    double& lo, double& hi, std::vector<double>& p)
{
  lo = 0;
  hi = x0.size() ? x0.cwiseAbs().maxCoeff() : 0.;
  p.assign(std::size_t(g.nodes), 0.);
  std::vector<double> q;
  for(int s = 0; s < steps && hi - lo > 1e-3 * hi; ++s) {
    const double T = 0.5 * (lo + hi);
    double mean = 0;
    int length = 0;
    const Rotation_bound_outcome r = rotations_within(g, x0, T, q, mean, length, budget);
    if(r == Rotation_bound_outcome::UNDECIDED) break;
    if(r == Rotation_bound_outcome::WITHIN) { hi = T; p.swap(q); }
    else lo = (std::min)(hi, (std::max)(T, mean));
  }
}

// A dual cycle met by the search over turning numbers (Trivial_connection with smoothest turning
// numbers): with the turning numbers moved by d (in steps of 1/N from where the search began) it
// turns by turn + (2 pi / N) sum over (g, m) in winding of m d[g], over `length` edges; the
// winding numbers m are its coefficients on the generators' rows (its homology class).
struct Turning_cycle
{
  double turn = 0;
  int length = 1;
  std::vector<std::pair<int, long>> winding;
};

inline double cycle_turn(const Turning_cycle& c, const std::vector<long>& d, int N)
{
  double t = c.turn;
  for(const auto& gm : c.winding) t += (2 * M_PI / N) * double(gm.second) * double(d[std::size_t(gm.first)]);
  return t;
}

// Moves d so that every cycle turns by at most `goal` per edge on average: greedily, by the single
// move (one generator, a whole number of steps) that most lowers the total excess
// sum max(0, |turn| / length - goal), the fewer steps the better among equal ones. Returns whether
// every cycle ends within the goal (false: no single move helps any more).
inline bool fit_turning_steps(const std::vector<Turning_cycle>& cycles, int N, double goal, std::vector<long>& d)
{
  auto excess = [&]() {
    double e = 0;
    for(const Turning_cycle& c : cycles) e += (std::max)(0., std::abs(cycle_turn(c, d, N)) / c.length - goal);
    return e;
  };
  double current = excess();
  for(int move = 0; move < 100000 && current > 0; ++move) {
    int best_g = -1;
    long best_step = 0;
    double best = current;
    for(const Turning_cycle& c : cycles) {
      const double turn = cycle_turn(c, d, N);
      if(std::abs(turn) / c.length <= goal) continue;
      for(const auto& gm : c.winding) {
        const double ideal = -turn / ((2 * M_PI / N) * double(gm.second));   // the steps that bring this cycle's turn to 0
        const long candidates[3] = {long(std::floor(ideal)), long(std::ceil(ideal)), ideal > 0 ? 1L : -1L};
        for(long step : candidates) {
          if(step == 0) continue;
          long& dg = d[std::size_t(gm.first)];
          dg += step;
          const double e = excess();
          dg -= step;
          if(e < best - 1e-12 * (1 + best) || (best_g >= 0 && e <= best && std::labs(step) < std::labs(best_step))) {
            best = e;
            best_g = gm.first;
            best_step = step;
          }
        }
      }
    }
    if(best_g < 0) return false;
    d[std::size_t(best_g)] += best_step;
    current = best;
  }
  return current <= 0;
}

// When every cycle winds around one generator g only: the least, over all turning numbers, of the
// largest mean rotation |turn| / length of these cycles (a convex function of d[g]: walked down
// from d[g] by single steps); every connection turns some edge by at least this. -1 when the
// cycles wind around several generators.
inline double one_generator_bound(const std::vector<Turning_cycle>& cycles, int N, std::vector<long> d)
{
  int g = -1;
  for(const Turning_cycle& c : cycles)
    for(const auto& gm : c.winding) {
      if(g >= 0 && gm.first != g) return -1;
      g = gm.first;
    }
  if(g < 0) return -1;
  auto largest = [&]() {
    double m = 0;
    for(const Turning_cycle& c : cycles) m = (std::max)(m, std::abs(cycle_turn(c, d, N)) / c.length);
    return m;
  };
  double best = largest();
  for(long step : {1L, -1L}) {
    for(;;) {
      d[std::size_t(g)] += step;
      const double m = largest();
      if(!(m < best)) { d[std::size_t(g)] -= step; break; }
      best = m;
    }
  }
  return best;
}

// The dual cycle of `arcs` (found by rotations_within()) as a Turning_cycle: its turn under x, its
// length, and its winding numbers, the generator entries of mu in A W A^T mu = A W s_C (`chol`
// factors A W A^T; the generator rows start at `first_generator_row`). Its signed indicator s_C
// must then be A^T mu, a combination of the rows: false when it is not, or when a winding
// number does not come out an integer.
template <typename SparseMatrix, typename Chol>
bool turning_cycle(const Rotation_constraint_graph& g, const std::vector<int>& arcs, const Eigen::VectorXd& x, const SparseMatrix& A,
                   const Eigen::VectorXd& W, const Chol& chol, Eigen::Index first_generator_row, std::size_t generators,
                   Turning_cycle& cycle)
{
  Eigen::VectorXd sC = Eigen::VectorXd::Zero(x.size());
  cycle = Turning_cycle();
  for(int a : arcs) {
    sC[g.column[std::size_t(a)]] += g.sign[std::size_t(a)];
    cycle.turn += g.sign[std::size_t(a)] * x[g.column[std::size_t(a)]];
  }
  cycle.length = int(arcs.size());
  const Eigen::VectorXd mu = chol.solve(Eigen::VectorXd(A * (W.asDiagonal() * sC)));
  if(!((Eigen::VectorXd(A.transpose() * mu) - sC).cwiseAbs().maxCoeff() < 1e-6)) return false;
  for(std::size_t k = 0; k < generators; ++k) {
    const double m = mu[first_generator_row + Eigen::Index(k)];
    const long mr = std::lround(m);
    if(!(std::abs(m - double(mr)) <= 1e-6)) return false;
    if(mr != 0) cycle.winding.emplace_back(int(k), mr);
  }
  return true;
}

// The smallest weight lambda that brings every |(1 - lambda) a + lambda b| within `goal`, for
// a = x, b = x_inf with |b| <= goal (1 at most).
inline double blend_weight(const Eigen::VectorXd& x, const Eigen::VectorXd& x_inf, double goal)
{
  double lambda = 0;
  for(Eigen::Index c = 0; c < x.size(); ++c) {
    const double a = x[c], v = x_inf[c];
    if(a > goal) lambda = (std::max)(lambda, (a - goal) / (a - v));
    else if(a < -goal) lambda = (std::max)(lambda, (-goal - a) / (v - a));
  }
  return (std::min)(1., lambda * (1 + 1e-9));
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ROTATION_MINIMAX_H
