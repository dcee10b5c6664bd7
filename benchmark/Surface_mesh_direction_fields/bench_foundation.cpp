// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Benchmarks of the package foundation on meshes of 10k, 100k, 400k and 1M faces
// (see benchmark_util.h for how the meshes are made and benchmark/README.md for the output).
//
// Target (issue): all homology generators plus the Levi-Civita and generalised holonomy of
// each of them in under 1 s on a 1M-face mesh: BM_generators_and_holonomy/1000000.
// The other benchmarks split that time into its parts.
#include "benchmark_util.h"

#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>

#include <cmath>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
using smdf_bench::Mesh;

// Everything the target asks for: generators, holonomy setup, both holonomies of each generator,
// with one pass over the mesh (Intrinsic_holonomy computes the generators from its own arrays).
static void BM_generators_and_holonomy(benchmark::State& state)
{
  const smdf_bench::Bench_mesh* b = smdf_bench::setup(state);
  if(!b) return;
  const Mesh& mesh = b->mesh;
  smdf_bench::Memory_probe mem;
  std::size_t cycle_length = 0;
  for(auto _ : state) {
    const SMDF::Intrinsic_holonomy<Mesh> hol(mesh);
    const auto gens = hol.tree_cotree_generators();
    double sum = 0;
    cycle_length = 0;
    for(const auto& g : gens) {
      sum += hol.levi_civita_holonomy(g.dual_cycle);
      const SMDF::Rigid_motion_2 m = hol.generalized_holonomy(g.dual_cycle);
      sum += m.rotation + m.translation.x();
      cycle_length += g.dual_cycle.size();
    }
    benchmark::DoNotOptimize(sum);
  }
  mem.report(state);
  state.counters["dual_cycle_faces"] = double(cycle_length);
}

// tree_cotree_generators() alone (it builds its own connectivity arrays, no metric).
static void BM_tree_cotree(benchmark::State& state)
{
  const smdf_bench::Bench_mesh* b = smdf_bench::setup(state);
  if(!b) return;
  const Mesh& mesh = b->mesh;
  smdf_bench::Memory_probe mem;
  std::size_t n = 0;
  for(auto _ : state) {
    const auto gens = SMDF::tree_cotree_generators(mesh);
    n = gens.size();
    benchmark::DoNotOptimize(gens.data());
  }
  mem.report(state);
  if(long(n) != b->betti_1) {
    smdf_bench::had_errors() = true;
    state.SkipWithError("number of generators differs from the first Betti number");
  }
}

// Intrinsic_holonomy construction alone: connectivity arrays + edge lengths + corner angles.
static void BM_holonomy_setup(benchmark::State& state)
{
  const smdf_bench::Bench_mesh* b = smdf_bench::setup(state);
  if(!b) return;
  const Mesh& mesh = b->mesh;
  smdf_bench::Memory_probe mem;
  for(auto _ : state) {
    const SMDF::Intrinsic_holonomy<Mesh> hol(mesh);
    benchmark::DoNotOptimize(&hol);
  }
  mem.report(state);
}

// The holonomies alone: both holonomies of every generator, generators and setup precomputed.
static void BM_holonomies(benchmark::State& state)
{
  const smdf_bench::Bench_mesh* b = smdf_bench::setup(state);
  if(!b) return;
  const Mesh& mesh = b->mesh;
  const auto gens = SMDF::tree_cotree_generators(mesh);
  const SMDF::Intrinsic_holonomy<Mesh> hol(mesh);
  smdf_bench::Memory_probe mem;
  for(auto _ : state) {
    double sum = 0;
    for(const auto& g : gens) {
      sum += hol.levi_civita_holonomy(g.dual_cycle);
      const SMDF::Rigid_motion_2 m = hol.generalized_holonomy(g.dual_cycle);
      sum += m.rotation + m.translation.x();
    }
    benchmark::DoNotOptimize(sum);
  }
  mem.report(state);
}

// total_angle_defect(): arrays + metric + angle sums (Gauss-Bonnet check costs this much).
static void BM_total_angle_defect(benchmark::State& state)
{
  const smdf_bench::Bench_mesh* b = smdf_bench::setup(state);
  if(!b) return;
  const Mesh& mesh = b->mesh;
  smdf_bench::Memory_probe mem;
  double total = 0;
  for(auto _ : state) {
    total = SMDF::total_angle_defect(mesh);
    benchmark::DoNotOptimize(total);
  }
  mem.report(state);
  // discrete Gauss-Bonnet (angle defects + geodesic curvatures): total = 2 pi chi
  state.counters["gauss_bonnet_error"] = std::abs(total - 2 * CGAL_PI * double(b->euler_characteristic));
}

BENCHMARK(BM_generators_and_holonomy)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_tree_cotree)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_holonomy_setup)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_holonomies)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_total_angle_defect)->Apply(smdf_bench::standard_options);

SMDF_BENCHMARK_MAIN();
