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

#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/compute_trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/flat_development.h>
#include <CGAL/Surface_mesh_direction_fields/grid_tessellation.h>
#include <CGAL/Surface_mesh_direction_fields/integer_grid_map.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/remeshing_cones.h>
#include <CGAL/Surface_mesh_direction_fields/tessellation_on_input.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

// The automatic quad remesh of `smdf remesh MESH --faces N` (issue #37), library calls only:
// place_remeshing_cones() (the cones 4 quad sides apart, smdf's first attempt), the flat cone metric of those cones on the input's edges
// (as smdf, the placement's own read-back when it needed no flip), the trivial connection's cross field, integer_grid_map() and tessellate_flat_metric(), with
// N = faces / 5 quads (100k faces -> 20k quads). The base mesh is $SMDF_REMESH_BENCH_MESH, else
// the shared bunny_bff.obj (closed, genus 0, 28,576 faces; the feline of the other benchmarks
// takes over 500 cones, past smdf's default maximum), decimated or Loop-subdivided to each size.
// A metric the input's edges cannot carry is computed on their conforming Delaunay refinement
// (counter `refined`, the fraction of runs), as smdf does with --uv-out (without it, smdf now
// takes the placement's intrinsic triangulation and its common subdivision instead); smdf's cone
// separation is not run (0.4 s of smdf's 58 s at 1M faces, where no cone is moved); its other fallbacks (intrinsic flips,
// further placements with the cones at other spacings, untangling) are not run: a size that needs
// them reports read_back_ok 0 and the stage it failed in.
// Counters: placement_s, cone_metric_s (with the refinement), cross_field_s,
// integer_grid_map_s, tessellation_s, cones, seams, output_quads, folded_triangles, refined,
// read_back_ok (the tessellation succeeded with no inverted face).
namespace {

std::string remesh_base_mesh_path()
{
  if(const char* env = std::getenv("SMDF_REMESH_BENCH_MESH"))
    if(*env) return env;
  return std::string(SMDF_SHARED_DATA_DIR) + "/meshes/bunny_bff.obj";
}

const smdf_bench::Bench_mesh& remesh_mesh_of_size(std::size_t faces)
{
  static std::unique_ptr<Mesh> base;
  static std::map<std::size_t, std::unique_ptr<smdf_bench::Bench_mesh>> cache;
  if(!base) {
    std::unique_ptr<Mesh> m(new Mesh);
    SMDF::read_triangle_mesh(remesh_base_mesh_path(), *m);
    const SMDF::Mesh_topology<Mesh> topo = SMDF::mesh_topology(*m);
    if(topo.components.size() != 1 || !topo.is_closed())
      throw std::runtime_error("benchmark mesh '" + remesh_base_mesh_path() + "' is not a closed surface of one component");
    base = std::move(m);
  }
  auto it = cache.find(faces);
  if(it == cache.end()) {
    std::unique_ptr<smdf_bench::Bench_mesh> b(new smdf_bench::Bench_mesh);
    b->mesh = *base;
    b->target_faces = faces;
    std::ostringstream src;
    src << smdf_bench::base_name(remesh_base_mesh_path());
    smdf_bench::refine_to_size(b->mesh, faces, src);
    smdf_bench::describe(*b);
    b->source = src.str();
    it = cache.emplace(faces, std::move(b)).first;
  }
  return *it->second;
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The base mesh Loop-subdivided `steps` times, no decimation (its noise raises the cone count).
const smdf_bench::Bench_mesh& remesh_mesh_subdivided(int steps)
{
  static std::map<int, std::unique_ptr<smdf_bench::Bench_mesh>> cache;
  auto it = cache.find(steps);
  if(it == cache.end()) {
    std::unique_ptr<smdf_bench::Bench_mesh> b(new smdf_bench::Bench_mesh);
    SMDF::read_triangle_mesh(remesh_base_mesh_path(), b->mesh);
    if(steps > 0) CGAL::Subdivision_method_3::Loop_subdivision(b->mesh, CGAL::parameters::number_of_iterations(steps));
    smdf_bench::describe(*b);
    b->target_faces = b->faces;
    b->source = smdf_bench::base_name(remesh_base_mesh_path()) + (steps > 0 ? " Loop^" + std::to_string(steps) : std::string());
    it = cache.emplace(steps, std::move(b)).first;
  }
  return *it->second;
}

void run_automatic_remesh(benchmark::State& state, const smdf_bench::Bench_mesh* b);

} // namespace

static void BM_remesh_automatic(benchmark::State& state)
{
  const smdf_bench::Bench_mesh* b = nullptr;
  try { b = &remesh_mesh_of_size(std::size_t(state.range(0))); } catch(const std::exception& e) {
    smdf_bench::had_errors() = true;
    state.SkipWithError(e.what());
    return;
  }
  run_automatic_remesh(state, b);
}

// The same on the base mesh Loop-subdivided 0, 1, 2 times (the bunny: 28,576, 114,304 and
// 457,216 faces), without the decimation of the standard sizes.
static void BM_remesh_automatic_loop(benchmark::State& state)
{
  const smdf_bench::Bench_mesh* b = nullptr;
  try { b = &remesh_mesh_subdivided(int(state.range(0))); } catch(const std::exception& e) {
    smdf_bench::had_errors() = true;
    state.SkipWithError(e.what());
    return;
  }
  run_automatic_remesh(state, b);
}

namespace {

void run_automatic_remesh(benchmark::State& state, const smdf_bench::Bench_mesh* b)
{
  smdf_bench::set_mesh_counters(state, *b);
  const double quads_wanted = double(num_faces(b->mesh)) / 5;
  double placement_s = 0, metric_s = 0, field_s = 0, map_s = 0, tessellation_s = 0;
  std::size_t cones = 0, seams = 0, quads = 0, folded = 0, refinements = 0;
  bool ok = true;
  std::string failure;
  smdf_bench::Memory_probe mem;
  for(auto _ : state) {
    Mesh work = b->mesh;
    typedef Mesh::Edge_index Edge;
    auto placed = work.add_property_map<Edge, double>("e:bench_placed", 0.).first;
    auto t0 = std::chrono::steady_clock::now();
    // as smdf's first attempt: the cones 4 quad sides apart (measured on the input)
    const double h_input = std::sqrt(CGAL::Polygon_mesh_processing::area(work) / quads_wanted);
    const auto ps = SMDF::place_remeshing_cones(work, placed, SMDF::parameters::symmetry_order(4)
                                                                  .minimum_cone_distance(4 * h_input)
                                                                  .minimum_boundary_distance(4 * h_input));
    placement_s += seconds_since(t0);
    cones = ps.cones.size();
    if(!ps.success) { ok = false; failure = "placement: " + ps.message; continue; }
    t0 = std::chrono::steady_clock::now();
    std::vector<std::pair<Mesh::Vertex_index, double>> indices;
    for(const auto& c : ps.cones) indices.emplace_back(c.first, c.second / (2 * CGAL_PI));
    // the metric on the input's edges, else (as smdf) on its conforming Delaunay refinement,
    // which keeps the input's vertex indices
    Mesh refined;
    Mesh* on = &work;
    auto metric_on = [&](Mesh& m, Mesh::Property_map<Edge, double>& lengths) {
      auto target = m.add_property_map<Mesh::Vertex_index, double>("v:bench_target", 0.).first;
      for(const auto& c : ps.cones) target[c.first] = c.second;
      lengths = m.add_property_map<Edge, double>("e:bench_lengths", 0.).first;
      return SMDF::compute_cone_metric(m, target, lengths, SMDF::parameters::intrinsic_edge_flips(false));
    };
    Mesh::Property_map<Edge, double> lengths;
    // as smdf: the placement's read-back is the metric; when it needed flips, on its intrinsic
    // triangulation (a copy as a mesh), the remesh brought back through the common subdivision
    SMDF::Cone_metric_status cm;
    Mesh intrinsic;
    const bool on_intrinsic = ps.metric.converged && ps.metric.triangulation_changed && ps.metric.intrinsic_triangulation.has_common_subdivision();
    if(ps.metric.converged && !ps.metric.triangulation_changed) {
      lengths = placed;
      cm.converged = true;
    } else if(on_intrinsic) {
      lengths = intrinsic.add_property_map<Edge, double>("e:bench_lengths", 0.).first;
      SMDF::copy_intrinsic_triangulation(ps.metric.intrinsic_triangulation, work, intrinsic, lengths);
      on = &intrinsic;
      cm.converged = true;
    } else if(!ps.metric.converged) {   // else the correspondence failed: on the input's edges, or its refinement
      cm = metric_on(work, lengths);
    }
    if(!cm.converged) {
      const SMDF::Delaunay_refinement_status rs = SMDF::conforming_delaunay_refinement(work, refined);
      if(rs.success) {
        on = &refined;
        cm = metric_on(refined, lengths);
        ++refinements;
      }
    }
    metric_s += seconds_since(t0);
    if(!cm.converged) { ok = false; failure = "flat cone metric on the input's edges and its refinement (smdf flips): " + cm.message; continue; }
    Mesh& m = *on;
    t0 = std::chrono::steady_clock::now();
    auto adjustment = m.add_property_map<Edge, double>("e:bench_adjustment", 0.).first;
    auto field = m.add_property_map<Mesh::Face_index, double>("f:bench_field", 0.).first;
    const SMDF::Trivial_connection_status ts = SMDF::compute_trivial_connection(
        m, indices, adjustment,
        SMDF::parameters::edge_length_map(lengths).symmetry_order(4).smoothest_generator_turning_numbers(true).face_angle_map(field));
    field_s += seconds_since(t0);
    if(!ts.success) { ok = false; failure = "cross field: " + ts.message; continue; }
    t0 = std::chrono::steady_clock::now();
    double area = 0;
    for(auto f : faces(m)) {
      const auto h = halfedge(f, m);
      area += SMDF::triangle_area(lengths[edge(h, m)], lengths[edge(next(h, m), m)], lengths[edge(prev(h, m), m)]);
    }
    auto uv = m.add_property_map<Mesh::Halfedge_index, std::array<double, 2>>("h:bench_uv").first;
    const SMDF::Integer_grid_map_status gs =
        SMDF::integer_grid_map(m, field, std::sqrt(area / quads_wanted), uv, SMDF::parameters::edge_length_map(lengths));
    map_s += seconds_since(t0);
    seams = gs.arcs;
    folded = gs.folded_triangles;
    if(!gs.success) { ok = false; failure = "integer-grid map (smdf places the cones again): " + gs.message; continue; }
    t0 = std::chrono::steady_clock::now();
    for(Edge e : edges(m)) {   // the map's lengths, in grid units
      const auto x = halfedge(e, m);
      const std::array<double, 2> p = uv[prev(x, m)], q = uv[x];
      lengths[e] = std::hypot(q[0] - p[0], q[1] - p[1]);
    }
    Mesh out;
    const auto dev = SMDF::develop_flat_metric(m, SMDF::parameters::edge_length_map(lengths));
    const SMDF::Grid_tessellation_status st = SMDF::tessellate_flat_metric(m, dev, SMDF::SQUARE_GRID, 1., out);
    if(on_intrinsic && num_faces(out) > 0) SMDF::place_tessellation_on_input(ps.metric.intrinsic_triangulation, work, st, out);
    tessellation_s += seconds_since(t0);
    quads = st.faces;
    if(!st.success || st.inverted_faces > 0) { ok = false; failure = "tessellation: " + st.message; }
  }
  mem.report(state);
  for(auto c : {std::make_pair("placement_s", placement_s), std::make_pair("cone_metric_s", metric_s), std::make_pair("cross_field_s", field_s),
                std::make_pair("integer_grid_map_s", map_s), std::make_pair("tessellation_s", tessellation_s)})
    state.counters[c.first] = benchmark::Counter(c.second, benchmark::Counter::kAvgIterations);
  state.counters["cones"] = double(cones);
  state.counters["seams"] = double(seams);
  state.counters["output_quads"] = double(quads);
  state.counters["folded_triangles"] = double(folded);
  state.counters["refined"] = benchmark::Counter(double(refinements), benchmark::Counter::kAvgIterations);
  state.counters["read_back_ok"] = ok ? 1 : 0;
  if(!ok) state.SetLabel(b->source + " FAILED: " + failure);
}

} // namespace

BENCHMARK(BM_remesh_automatic)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_remesh_automatic_loop)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_remesh_cube)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_delaunay_refinement)->Apply(smdf_bench::standard_options);
BENCHMARK(BM_develop_cube)->Apply(smdf_bench::standard_options);

SMDF_BENCHMARK_MAIN();
