// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Benchmarks of regular remeshing (Lai et al. 2010, section 5). The remesh on the surface of a cube cut into
// k x k squares of two triangles per side (12 k^2 faces: 10k to 1M for the standard sizes),
// whose own metric is flat with eight cones of pi/2: develop_flat_metric() and
// tessellate_flat_metric() into quads of edge length 1/k' with 6 k'^2 about half the input's
// faces. Counters: output quads, and whether the read-back succeeded (valences, inversions).
// The input meshes are made here, not by benchmark_util.h: the remesher needs a metric whose
// holonomy fits the grid.
#include "benchmark_util.h"

#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/flat_development.h>
#include <CGAL/Surface_mesh_direction_fields/grid_tessellation.h>

#include <cmath>
#include <map>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
using smdf_bench::Mesh;

namespace {

// The unit cube's surface, k x k squares of two triangles per side.
Mesh cube(int k)
{
  Mesh m;
  std::map<std::array<int, 3>, Mesh::Vertex_index> index;
  auto vertex = [&](std::array<int, 3> g) {
    auto it = index.find(g);
    if(it != index.end()) return it->second;
    const Mesh::Vertex_index v = m.add_vertex(Mesh::Point(double(g[0]) / k, double(g[1]) / k, double(g[2]) / k));
    index[g] = v;
    return v;
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for(int i = 0; i < k; ++i)
        for(int j = 0; j < k; ++j) {
          Mesh::Vertex_index q[4];
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for(int c = 0; c < 4; ++c) {
            std::array<int, 3> g;
            g[std::size_t(axis)] = side * k;
            g[std::size_t(u)] = i + di[c];
            g[std::size_t(w)] = j + dj[c];
            q[c] = vertex(g);
          }
          if(side == 1) { m.add_face(q[0], q[1], q[2]); m.add_face(q[0], q[2], q[3]); }
          else { m.add_face(q[0], q[2], q[1]); m.add_face(q[0], q[3], q[2]); }
        }
    }
  return m;
}

const Mesh& cube_of_size(std::size_t faces)
{
  static std::map<std::size_t, Mesh> cache;
  auto it = cache.find(faces);
  if(it == cache.end()) it = cache.emplace(faces, cube(int(std::max(1., std::round(std::sqrt(double(faces) / 12)))))).first;
  return it->second;
}

} // namespace

// develop_flat_metric() + tessellate_flat_metric(): the whole remesh of a flat cone metric.
static void BM_remesh_cube(benchmark::State& state)
{
  const Mesh& mesh = cube_of_size(std::size_t(state.range(0)));
  const int kq = int(std::max(1., std::round(std::sqrt(double(num_faces(mesh)) / 12))));   // quads: 6 kq^2
  smdf_bench::Memory_probe mem;
  SMDF::Grid_tessellation_status st;
  for(auto _ : state) {
    Mesh out;
    const auto dev = SMDF::develop_flat_metric(mesh);
    st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, 1. / kq, out);
    benchmark::DoNotOptimize(num_faces(out));
  }
  mem.report(state);
  state.counters["faces"] = double(num_faces(mesh));
  state.counters["output_quads"] = double(st.faces);
  state.counters["read_back_ok"] = st.success ? 1 : 0;
  if(!st.success) {
    smdf_bench::had_errors() = true;
    state.SkipWithError(st.message.c_str());
  }
}

// develop_flat_metric() alone: layout, motions and cut graph.
static void BM_develop_cube(benchmark::State& state)
{
  const Mesh& mesh = cube_of_size(std::size_t(state.range(0)));
  smdf_bench::Memory_probe mem;
  std::size_t cut = 0;
  for(auto _ : state) {
    const auto dev = SMDF::develop_flat_metric(mesh);
    cut = dev.number_of_cut_edges();
    benchmark::DoNotOptimize(cut);
  }
  mem.report(state);
  state.counters["faces"] = double(num_faces(mesh));
  state.counters["cut_edges"] = double(cut);
}

// conforming_delaunay_refinement() of the standard benchmark meshes (the base mesh decimated or
// subdivided, see benchmark_util.h): what a metric that the input triangulation cannot carry
// costs before its flow. Counters: output faces over input faces, read-back (all Delaunay).
static void BM_delaunay_refinement(benchmark::State& state)
{
  const smdf_bench::Bench_mesh* b = smdf_bench::setup(state);
  if(!b) return;
  smdf_bench::Memory_probe mem;
  SMDF::Delaunay_refinement_status st;
  for(auto _ : state) {
    Mesh out;
    st = SMDF::conforming_delaunay_refinement(b->mesh, out);
    benchmark::DoNotOptimize(num_faces(out));
  }
  mem.report(state);
  state.counters["output_faces"] = double(st.faces);
  state.counters["growth"] = double(st.faces) / double(num_faces(b->mesh));
  state.counters["read_back_ok"] = st.success ? 1 : 0;
  if(!st.success) {
    smdf_bench::had_errors() = true;
    state.SkipWithError(st.message.c_str());
  }
}

BENCHMARK(BM_remesh_cube)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_delaunay_refinement)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_develop_cube)->Apply(smdf_bench::standard_options);

SMDF_BENCHMARK_MAIN();
