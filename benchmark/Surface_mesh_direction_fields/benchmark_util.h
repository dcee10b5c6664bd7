// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Shared helpers of the Surface_mesh_direction_fields benchmarks (Google Benchmark 1.7).
//
//  * Meshes of a given size, built once per process and cached:
//      const smdf_bench::Bench_mesh* m = smdf_bench::setup(state);   // mesh for state.range(0)
//    The base mesh is $SMDF_BENCH_MESH if set, else ../shared/data/meshes/feline_vhacd.off
//    (genus 2, 99,732 faces), else a generated torus. It is refined with Loop subdivision until it
//    has at least ~the target number of faces, then decimated (Lindstrom-Turk edge collapse)
//    down to the target when it overshoots by more than 10% (so 10k is a decimated feline,
//    100k the feline itself, 400k one Loop step, 1M two Loop steps decimated to 1M).
//    The actual face count, genus etc. are reported as counters and the recipe as the label.
//  * Memory: Memory_probe reads VmRSS / VmHWM from /proc/self/status around the timed loop
//    and reports peak_rss_MB, peak_extra_MB, rss_delta_MB and page_faults (see
//    benchmark/README.md); $SMDF_BENCH_WARM=1 keeps freed memory in the allocator
//    (warm_allocator()) to separate computation from first-touch page faults.
//  * Registration: BENCHMARK(BM_x)->Apply(smdf_bench::standard_options) registers the sizes
//    (10k, 100k, 400k and 1M faces, or the comma-separated list in $SMDF_BENCH_SIZES; alone:
//    ->Apply(smdf_bench::mesh_sizes)), milliseconds, wall-clock time, 5 repetitions, aggregates.
//  * SMDF_BENCHMARK_MAIN(): main() that adds the mesh source to the context and returns 1 if
//    any benchmark failed to set up (so the CTest smoke run catches it).
#ifndef SMDF_BENCHMARK_UTIL_H
#define SMDF_BENCHMARK_UTIL_H

#include <benchmark/benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include "huge_page_new.h"

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef SMDF_SHARED_DATA_DIR
#define SMDF_SHARED_DATA_DIR "../shared/data"
#endif

namespace smdf_bench {

namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;

// ------------------------------------------------------------------------------------------
// Memory
// ------------------------------------------------------------------------------------------

struct Memory_usage
{
  double rss_MB = 0;   // VmRSS: resident now
  double hwm_MB = 0;   // VmHWM: peak resident since start (or since the last reset_peak_rss())
};

// Reads VmRSS and VmHWM from /proc/self/status (zeros where unavailable).
inline Memory_usage read_memory_usage()
{
  Memory_usage u;
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line)) {
    double* dst = nullptr;
    if(line.compare(0, 6, "VmRSS:") == 0) dst = &u.rss_MB;
    else if(line.compare(0, 6, "VmHWM:") == 0) dst = &u.hwm_MB;
    if(!dst) continue;
    std::istringstream is(line.substr(6));
    double kb = 0;
    is >> kb;
    *dst = kb / 1024.;
  }
  return u;
}

// Resets VmHWM to the current RSS (Linux >= 4.0: write "5" to /proc/self/clear_refs).
// Returns false where that is not possible; VmHWM is then the peak since process start.
inline bool reset_peak_rss()
{
  std::ofstream out("/proc/self/clear_refs");
  if(!out) return false;
  out << "5" << std::flush;
  return bool(out);
}

// Whether reset_peak_rss() works here (checked once).
inline bool peak_rss_resettable()
{
  static const bool ok = reset_peak_rss();
  return ok;
}

// Page faults of the process so far (minor + major).
inline double page_faults()
{
  rusage u;
  if(getrusage(RUSAGE_SELF, &u) != 0) return 0;
  return double(u.ru_minflt) + double(u.ru_majflt);
}

// Allocator mode, from $SMDF_BENCH_WARM (read once):
//  cold (default): every benchmark run starts by giving freed memory back to the system
//    (malloc_trim), so the measured code pays for first-touching its memory as in a fresh
//    process, and peak_extra_MB sees its whole working memory.
//  warm (SMDF_BENCH_WARM=1): glibc keeps freed memory (no trimming, no mmap below 32 MiB), so
//    from the second iteration or repetition on, the time is computation only.
inline bool warm_allocator()
{
  static const bool warm = [] {
    const char* env = std::getenv("SMDF_BENCH_WARM");
    if(!env || !*env || std::string(env) == "0") return false;
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);   // glibc's maximum
    mallopt(M_TRIM_THRESHOLD, 2147483647);
#endif
    return true;
  }();
  return warm;
}

// Cold mode: gives memory freed by earlier runs back to the system (glibc only).
inline void release_free_memory()
{
#if defined(__GLIBC__)
  if(!warm_allocator()) malloc_trim(0);
#endif
}

// Measures the memory of a benchmark's timed loop:
//   smdf_bench::Memory_probe mem;           // right before `for(auto _ : state)`
//   for(auto _ : state) { ... }
//   mem.report(state);
// Counters (MB, 1 MB = 2^20 bytes):
//   peak_rss_MB   VmHWM after the loop: peak resident memory of the process during the loop if
//                 the peak could be reset (context "smdf_peak_rss_reset"), else since start.
//                 Includes every mesh cached by the process so far.
//   peak_extra_MB peak_rss_MB - VmRSS before the loop: the working memory the measured code
//                 needed on top of what was already resident (the cached meshes).
//   rss_delta_MB  VmRSS after - VmRSS before the loop: memory still held afterwards (should be
//                 ~0; the allocator may keep some freed memory).
//   page_faults   page faults per iteration: first touches of memory the allocator got from
//                 the system. Each costs ~0.2 us on bare metal but ~10 us in some VMs, where
//                 they can dominate (benchmark/README.md).
class Memory_probe
{
public:
  Memory_probe()
  {
    release_free_memory();
    if(peak_rss_resettable()) reset_peak_rss();
    before_ = read_memory_usage();
    faults_ = page_faults();
  }
  void report(benchmark::State& state) const
  {
    const double faults = page_faults() - faults_;
    const Memory_usage after = read_memory_usage();
    state.counters["peak_rss_MB"] = after.hwm_MB;
    state.counters["peak_extra_MB"] = (std::max)(0., after.hwm_MB - before_.rss_MB);
    state.counters["rss_delta_MB"] = after.rss_MB - before_.rss_MB;
    state.counters["page_faults"] = benchmark::Counter(faults, benchmark::Counter::kAvgIterations);
  }

private:
  Memory_usage before_;
  double faults_ = 0;
};

// ------------------------------------------------------------------------------------------
// Meshes
// ------------------------------------------------------------------------------------------

struct Bench_mesh
{
  Mesh mesh;
  std::string source;          // recipe, e.g. "feline_vhacd.off Loop^2 decimated" (the label)
  std::size_t target_faces = 0;
  std::size_t faces = 0, vertices = 0, edges = 0;
  std::size_t components = 0, boundary_loops = 0;
  long genus = 0;              // sum over components
  long euler_characteristic = 0;   // V - E + F, isolated vertices excluded
  long betti_1 = 0;            // number of homology generators
  double build_seconds = 0;    // time to make this mesh from the base mesh
};

inline bool file_exists(const std::string& path) { return bool(std::ifstream(path)); }

// The base mesh file: $SMDF_BENCH_MESH if set (must exist), else the shared feline if present,
// else "" (a torus is generated instead).
inline std::string base_mesh_path()
{
  if(const char* env = std::getenv("SMDF_BENCH_MESH"))
    if(*env) return env;
  const std::string feline = std::string(SMDF_SHARED_DATA_DIR) + "/meshes/feline_vhacd.off";
  return file_exists(feline) ? feline : std::string();
}

inline std::string base_name(const std::string& path)
{
  const std::size_t s = path.find_last_of('/');
  return s == std::string::npos ? path : path.substr(s + 1);
}

// Human-readable description of the base mesh (for the benchmark context).
inline std::string base_mesh_description()
{
  const std::string p = base_mesh_path();
  return p.empty() ? std::string("generated torus (") + SMDF_SHARED_DATA_DIR +
                         "/meshes/feline_vhacd.off not found)"
                   : p;
}

// Wavy torus (genus 1) with about `target_faces` faces: an n x m grid, n ~ 3m.
inline void make_torus(std::size_t target_faces, Mesh& mesh)
{
  const std::size_t m = (std::max)(std::size_t(3), std::size_t(std::ceil(std::sqrt(target_faces / 6.))));
  const std::size_t n = (std::max)(std::size_t(3), (target_faces + 2 * m - 1) / (2 * m));
  const double R = 3, r = 1;
  std::vector<Point_3> pts;
  pts.reserve(n * m);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j) {
      const double u = 2 * CGAL_PI * double(i) / double(n), v = 2 * CGAL_PI * double(j) / double(m);
      const double rr = r * (1 + 0.15 * std::sin(3 * u));
      pts.emplace_back((R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u),
                       rr * std::sin(v));
    }
  auto id = [&](std::size_t i, std::size_t j) { return (i % n) * m + (j % m); };
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(2 * n * m);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j) {
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  mesh.clear();
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, faces, mesh);
}

// Fills the counters of a Bench_mesh from its mesh.
inline void describe(Bench_mesh& b)
{
  b.faces = num_faces(b.mesh);
  b.vertices = num_vertices(b.mesh);
  b.edges = num_edges(b.mesh);
  const SMDF::Mesh_topology<Mesh> topo = SMDF::mesh_topology(b.mesh);
  b.components = topo.components.size();
  b.boundary_loops = topo.boundary_loops.size();
  b.genus = 0;
  for(const auto& c : topo.components) b.genus += c.genus;
  b.betti_1 = topo.betti_1();
  b.euler_characteristic = topo.euler_characteristic();
}

// The base mesh, loaded once; nullptr when a torus is to be generated. Throws
// std::runtime_error (every time) if the base mesh file cannot be read.
inline const Mesh* base_mesh()
{
  static std::unique_ptr<Mesh> base;
  static std::string error;
  static bool tried = false;
  if(!tried) {
    tried = true;
    const std::string path = base_mesh_path();
    if(!path.empty()) {
      std::unique_ptr<Mesh> m(new Mesh);
      try {
        SMDF::read_triangle_mesh(path, *m);
        base = std::move(m);
      } catch(const std::exception& e) {
        error = "cannot use benchmark mesh '" + path + "': " + e.what();
      }
    }
  }
  if(!error.empty()) throw std::runtime_error(error);
  return base.get();
}

// Decimates `mesh` to about `target_faces` faces (Lindstrom-Turk edge collapse, which keeps the
// topology) and compacts it, so indices are contiguous again.
inline void decimate(Mesh& mesh, std::size_t target_faces)
{
  // E ~ 3F/2 on a closed triangle mesh; the predicate stops when fewer edges than this remain
  const std::size_t edge_target = (3 * target_faces + 1) / 2;
  CGAL::Surface_mesh_simplification::Count_stop_predicate<Mesh> stop(edge_target);
  CGAL::Surface_mesh_simplification::edge_collapse(mesh, stop);
  mesh.collect_garbage();
}

// Loop subdivision until `mesh` has at least 97% of `target_faces` (3% slack, so that feline,
// 99,732 faces, counts as 100k and one Loop step, 398,928, as 400k), then Lindstrom-Turk
// decimation down to the target if it overshoots by more than 10%; appends what was done to
// `src` (" Loop^2 decimated").
inline void refine_to_size(Mesh& mesh, std::size_t target_faces, std::ostream& src)
{
  int steps = 0;
  while(double(num_faces(mesh)) < 0.97 * double(target_faces)) {
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
    ++steps;
  }
  if(steps > 0) src << " Loop^" << steps;
  if(double(num_faces(mesh)) > 1.10 * double(target_faces)) {
    decimate(mesh, target_faces);
    src << " decimated";
  }
}

// The registration settings shared by the drivers: milliseconds, wall-clock time, medians of
// 5 repetitions (3 from 400k faces on).
inline benchmark::internal::Benchmark* sized(benchmark::internal::Benchmark* b, std::int64_t size)
{
  return b->Arg(size)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Repetitions(size >= 400000 ? 3 : 5)
      ->ReportAggregatesOnly(true);
}

// Builds a mesh with about `target_faces` faces from the base mesh (see the top of this file).
inline std::unique_ptr<Bench_mesh> build_mesh(std::size_t target_faces)
{
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<Bench_mesh> b(new Bench_mesh);
  b->target_faces = target_faces;
  const Mesh* base = base_mesh();
  std::ostringstream src;
  if(!base) {
    make_torus(target_faces, b->mesh);
    src << "generated torus";
  } else {
    b->mesh = *base;
    src << base_name(base_mesh_path());
    refine_to_size(b->mesh, target_faces, src);
  }
  describe(*b);
  b->build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  b->source = src.str();
  return b;
}

// Cached mesh for a target face count (built on first use; every size once per process).
inline const Bench_mesh& mesh_of_size(std::size_t target_faces)
{
  static std::map<std::size_t, std::unique_ptr<Bench_mesh>> cache;
  auto it = cache.find(target_faces);
  if(it == cache.end()) it = cache.emplace(target_faces, build_mesh(target_faces)).first;
  return *it->second;
}

// ------------------------------------------------------------------------------------------
// Benchmark plumbing
// ------------------------------------------------------------------------------------------

inline bool& had_errors()
{
  static bool e = false;
  return e;
}

// Sets the mesh counters (faces, genus, generators = first Betti number, faces_per_s) and the
// label (mesh recipe) of a benchmark run.
inline void set_mesh_counters(benchmark::State& state, const Bench_mesh& b)
{
  state.counters["faces"] = double(b.faces);
  state.counters["genus"] = double(b.genus);
  state.counters["generators"] = double(b.betti_1);
  // throughput: faces per second
  state.counters["faces_per_s"] =
      benchmark::Counter(double(b.faces), benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(b.source);
}

// Returns the mesh for state.range(0) faces with its counters set, or nullptr after
// SkipWithError (the benchmark must then return without entering its loop).
inline const Bench_mesh* setup(benchmark::State& state)
{
  try {
    const Bench_mesh& b = mesh_of_size(std::size_t(state.range(0)));
    set_mesh_counters(state, b);
    return &b;
  } catch(const std::exception& e) {
    had_errors() = true;
    state.SkipWithError(e.what());
    return nullptr;
  }
}

// Target face counts: 10k, 100k, 400k, 1M, or $SMDF_BENCH_SIZES (e.g. "10000,50000").
inline std::vector<std::int64_t> target_sizes()
{
  std::vector<std::int64_t> sizes;
  if(const char* env = std::getenv("SMDF_BENCH_SIZES")) {
    std::stringstream ss(env);
    std::string tok;
    while(std::getline(ss, tok, ','))
      if(!tok.empty()) sizes.push_back(std::stoll(tok));
  }
  if(sizes.empty()) sizes = {10000, 100000, 400000, 1000000};
  return sizes;
}

// For ->Apply(): one run per target size; names are BM_x/<size>/..., so
// --benchmark_filter=/10000/ selects one size.
inline void mesh_sizes(benchmark::internal::Benchmark* b)
{
  for(std::int64_t s : target_sizes()) b->Arg(s);
}

// Standard options of a per-size benchmark, for BENCHMARK(BM_x)->Apply(standard_options):
// sizes, milliseconds, wall-clock time, 5 repetitions reported as mean / median / stddev / cv.
inline void standard_options(benchmark::internal::Benchmark* b)
{
  mesh_sizes(b);
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
}

// SMDF_BENCH_HUGEPAGES=1: large blocks (operator new and CHOLMOD's) on transparent huge pages,
// as in the smdf tool (tools/smdf/huge_page_new.cpp).
inline bool cholmod_huge_pages()
{
  const char* env = std::getenv("SMDF_BENCH_HUGEPAGES");
  return env && std::string(env) == "1";
}

inline void add_context()
{
  benchmark::AddCustomContext("smdf_cholmod_huge_pages", cholmod_huge_pages() ? "yes (SMDF_BENCH_HUGEPAGES=1)" : "no");
  benchmark::AddCustomContext("smdf_base_mesh", base_mesh_description());
  benchmark::AddCustomContext("smdf_peak_rss_reset", peak_rss_resettable() ? "yes" : "no");
  benchmark::AddCustomContext("smdf_allocator", warm_allocator()
      ? "warm (SMDF_BENCH_WARM: freed memory kept, repetitions after the first exclude page faults)"
      : "cold (freed memory returned before each run: includes first-touch page faults)");
#ifdef NDEBUG
  benchmark::AddCustomContext("smdf_build", "NDEBUG (release)");
#else
  benchmark::AddCustomContext("smdf_build", "assertions on (NOT a release build)");
#endif
}

} // namespace smdf_bench

// main() of a benchmark driver.
#define SMDF_BENCHMARK_MAIN()                                               \
  int main(int argc, char** argv)                                           \
  {                                                                         \
    ::benchmark::Initialize(&argc, argv);                                   \
    if(::benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;      \
    if(::smdf_bench::cholmod_huge_pages())                                  \
      ::smdf_memory::enable_huge_pages();                                   \
    ::smdf_bench::add_context();                                            \
    ::benchmark::RunSpecifiedBenchmarks();                                  \
    ::benchmark::Shutdown();                                                \
    return ::smdf_bench::had_errors() ? 1 : 0;                              \
  }                                                                         \
  int main(int, char**)

#endif // SMDF_BENCHMARK_UTIL_H
