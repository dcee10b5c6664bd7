// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Benchmarks of Trivial_connection (Trivial_connection.h) on meshes of 10k, 100k, 400k and 1M
// faces (see benchmark_util.h for how the meshes are made and benchmark/README.md for the output).
//
// Targets (issue), `_median` rows:
//   400k faces: BM_tc_setup/400000 <= 1 s, BM_tc_edit/400000 <= 0.05 s;
//   1M faces:   BM_tc_setup/1000000 <= 3 s, BM_tc_edit/1000000 <= 0.15 s, peak memory <= 2 GB.
//
//   BM_tc_setup[_N4|_spqr]/<size>  constructor + first solve() (factorisation) + field_angles()
//   BM_tc_edit[_N4|_spqr]/<size>   move one singularity to another vertex + solve() + field_angles()
//                                  (object built and solved once outside the timed loop)
// Default: N = 1, CHOLMOD_NORMAL_EQUATIONS. _N4: N = 4 (cross fields). _spqr: SPQR_MINIMUM_NORM,
// the reference path (a full SuiteSparseQR minimum-norm solve at every solve()), registered only
// for sizes <= 100k faces because it is too slow and memory-hungry beyond that.
//
// Singularities: their indices must sum to the Euler characteristic chi (-2 for the feline):
// N|chi| vertices of index sign(chi)/N (two of -1 for N = 1, eight of -1/4 for N = 4), or a
// +1/N, -1/N pair when chi = 0 (generated torus), at random vertices (fixed seed).
#include "benchmark_util.h"

#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
using smdf_bench::Mesh;
typedef Mesh::Vertex_index Vertex;
typedef SMDF::Trivial_connection<Mesh> Connection;

namespace {

const double max_holonomy_error = 1e-8;
const std::int64_t spqr_max_faces = 100000;

// Writable face property map over a vector (field_angles() output, preallocated by the caller).
struct Face_angles
{
  std::vector<double>* angles;
  friend void put(const Face_angles& m, Mesh::Face_index f, double a) { (*m.angles)[f.idx()] = a; }
};

std::size_t face_index_bound(const Mesh& mesh)
{
  std::size_t n = 0;
  for(Mesh::Face_index f : faces(mesh)) n = (std::max)(n, std::size_t(f.idx()) + 1);
  return n;
}

// `count` distinct random vertices on which singularities may be placed (interior, not isolated).
std::vector<Vertex> random_interior_vertices(const Mesh& mesh, std::size_t count, unsigned seed)
{
  std::vector<Vertex> all;
  for(Vertex v : vertices(mesh))
    if(!CGAL::is_border(v, mesh) && halfedge(v, mesh) != Mesh::null_halfedge()) all.push_back(v);
  std::mt19937 rng(seed);
  std::shuffle(all.begin(), all.end(), rng);
  if(all.size() > count) all.resize(count);
  return all;
}

// The initial singularities for symmetry order N: indices summing to chi.
std::vector<std::pair<Vertex, double>> initial_singularities(const smdf_bench::Bench_mesh& b, int N)
{
  std::vector<double> idx;
  const long chi = b.euler_characteristic;
  if(chi == 0) idx = {1. / N, -1. / N};
  else idx.assign(std::size_t(N * std::labs(chi)), (chi > 0 ? 1. : -1.) / N);
  const std::vector<Vertex> vs = random_interior_vertices(b.mesh, idx.size(), 12345u);
  if(vs.size() < idx.size()) throw std::runtime_error("not enough interior vertices for the singularities");
  std::vector<std::pair<Vertex, double>> s;
  for(std::size_t i = 0; i < idx.size(); ++i) s.emplace_back(vs[i], idx[i]);
  return s;
}

// Factor and solve times (averaged per iteration) and the largest holonomy error of the solves.
struct Status_totals
{
  double factor_s = 0, solve_s = 0, hol_err = 0;
  void add(const SMDF::Trivial_connection_status& st)
  {
    factor_s += st.factor_seconds;
    solve_s += st.solve_seconds;
    hol_err = (std::max)(hol_err, st.max_holonomy_error);
  }
  void report(benchmark::State& state) const
  {
    state.counters["factor_s"] = benchmark::Counter(factor_s, benchmark::Counter::kAvgIterations);
    state.counters["solve_s"] = benchmark::Counter(solve_s, benchmark::Counter::kAvgIterations);
    state.counters["holonomy_error"] = hol_err;
  }
};

bool check_status(benchmark::State& state, const SMDF::Trivial_connection_status& st)
{
  std::string error;
  if(!st.success) error = "solve failed: " + st.message;
  else if(!(st.max_holonomy_error < max_holonomy_error))
    error = "max_holonomy_error " + std::to_string(st.max_holonomy_error) + " >= 1e-8";
  if(error.empty()) return true;
  smdf_bench::had_errors() = true;
  state.SkipWithError(error.c_str());
  return false;
}

// The timed loop: step() (a solve and its field, returning the solve's status) once per
// iteration, every status checked; then the memory probe and the status totals.
template <typename Step>
void timed_solves(benchmark::State& state, Step step, const std::vector<double>& angles)
{
  Status_totals totals;
  smdf_bench::Memory_probe mem;
  for(auto _ : state) {
    const SMDF::Trivial_connection_status st = step();
    benchmark::DoNotOptimize(angles.data());
    if(!check_status(state, st)) return;
    totals.add(st);
  }
  mem.report(state);
  totals.report(state);
}

void fail(benchmark::State& state, const std::exception& e)
{
  smdf_bench::had_errors() = true;
  state.SkipWithError(e.what());
}

// Constructor + singularities + first solve() (build and factor the system) + field_angles().
void tc_setup(benchmark::State& state, int N, SMDF::Connection_solver solver)
{
  const smdf_bench::Bench_mesh* b = smdf_bench::setup(state);
  if(!b) return;
  const Mesh& mesh = b->mesh;
  try {
    const auto sing = initial_singularities(*b, N);
    std::vector<double> angles(face_index_bound(mesh));
    timed_solves(state, [&] {
      Connection tc(mesh, SMDF::parameters::symmetry_order(N).solver(solver));
      for(const auto& s : sing) tc.set_singularity(s.first, s.second);
      const SMDF::Trivial_connection_status st = tc.solve();
      tc.field_angles(Face_angles{&angles});
      return st;
    }, angles);
  } catch(const std::exception& e) {
    fail(state, e);
  }
}

// One edit: move one singularity (round robin) to the next free vertex of a precomputed random
// list (old vertex index 0, new vertex the moved index), solve() (reuses the factorisation),
// field_angles(). The object is built and solved once outside the timed loop.
void tc_edit(benchmark::State& state, int N, SMDF::Connection_solver solver)
{
  const smdf_bench::Bench_mesh* b = smdf_bench::setup(state);
  if(!b) return;
  const Mesh& mesh = b->mesh;
  try {
    auto sing = initial_singularities(*b, N);
    const std::vector<Vertex> targets = random_interior_vertices(mesh, 4096, 67890u);
    std::vector<double> angles(face_index_bound(mesh));
    Connection tc(mesh, SMDF::parameters::symmetry_order(N).solver(solver));
    for(const auto& s : sing) tc.set_singularity(s.first, s.second);
    if(!check_status(state, tc.solve())) return;
    tc.field_angles(Face_angles{&angles});

    std::size_t next_target = 0, moved = 0;
    timed_solves(state, [&] {
      auto& s = sing[moved++ % sing.size()];
      Vertex to = targets[next_target++ % targets.size()];
      while(tc.singularity_index(to) != 0) to = targets[next_target++ % targets.size()];
      tc.set_singularity(s.first, 0);
      tc.set_singularity(to, s.second);
      s.first = to;
      const SMDF::Trivial_connection_status st = tc.solve();
      tc.field_angles(Face_angles{&angles});
      return st;
    }, angles);
  } catch(const std::exception& e) {
    fail(state, e);
  }
}

// Sizes up to max_faces (all by default); 5 repetitions, 3 from 400k faces on (long runs).
void register_sizes(const char* name, void (*fn)(benchmark::State&, int, SMDF::Connection_solver),
                    int N, SMDF::Connection_solver solver, std::int64_t max_faces = -1)
{
  for(std::int64_t size : smdf_bench::target_sizes()) {
    if(max_faces >= 0 && size > max_faces) continue;
    smdf_bench::sized(benchmark::RegisterBenchmark(name, fn, N, solver), size);
  }
}

const bool registered = [] {
  register_sizes("BM_tc_setup", tc_setup, 1, SMDF::CHOLMOD_NORMAL_EQUATIONS);
  register_sizes("BM_tc_edit", tc_edit, 1, SMDF::CHOLMOD_NORMAL_EQUATIONS);
  register_sizes("BM_tc_setup_N4", tc_setup, 4, SMDF::CHOLMOD_NORMAL_EQUATIONS);
  register_sizes("BM_tc_edit_N4", tc_edit, 4, SMDF::CHOLMOD_NORMAL_EQUATIONS);
  register_sizes("BM_tc_setup_spqr", tc_setup, 1, SMDF::SPQR_MINIMUM_NORM, spqr_max_faces);
  register_sizes("BM_tc_edit_spqr", tc_edit, 1, SMDF::SPQR_MINIMUM_NORM, spqr_max_faces);
  return true;
}();

} // namespace

SMDF_BENCHMARK_MAIN();
