#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the benchmark drivers and runs them at every size (benchmark/README.md).
#
#   benchmark/run_benchmarks.sh [driver] [extra Google Benchmark flags...]
#
# driver defaults to bench_foundation. Prints the console table and writes JSON to
# $BUILD_DIR/benchmark_results.json (per driver other than bench_foundation:
# $BUILD_DIR/benchmark_results_<driver>.json). Environment:
#   BUILD_DIR         build tree (default: build, configured if missing)
#   SMDF_BENCH_MESH   base mesh file (default: ../shared/data/meshes/feline_vhacd.off)
#   SMDF_BENCH_SIZES  comma-separated target face counts (default: 10000,100000,400000,1000000)
#   SMDF_BUILD_LOCK   lock file serialising builds and timed runs (default: /tmp/smdf_build.lock)
#   JOBS              parallel build jobs (default: 2)
#   SMDF_BENCH_HUGEPAGES  1: CHOLMOD's large blocks on transparent huge pages, as in the smdf tool
#                     (enable_cholmod_huge_pages(); see README.md)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR=${BUILD_DIR:-build}
LOCK=${SMDF_BUILD_LOCK:-/tmp/smdf_build.lock}
JOBS=${JOBS:-2}
DRIVER=bench_foundation
if [ $# -gt 0 ] && [[ "$1" != -* ]]; then DRIVER=$1; shift; fi

# Builds and timed runs hold the same lock, so a compile on a shared machine does not pollute timings.
locked() {
  if command -v flock >/dev/null 2>&1; then flock "$LOCK" "$@"; else "$@"; fi
}

# Single-threaded BLAS/OpenMP, as in the tests (CONVENTIONS section 7).
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1

if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  locked cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
fi
locked cmake --build "$BUILD_DIR" --target "$DRIVER" -j"$JOBS"

EXE="$BUILD_DIR/benchmark/Surface_mesh_direction_fields/$DRIVER"
if [ ! -x "$EXE" ]; then
  echo "run_benchmarks.sh: $EXE not built (is Google Benchmark, libbenchmark-dev, installed?)" >&2
  exit 1
fi

if [ "$DRIVER" = bench_foundation ]; then
  JSON="$BUILD_DIR/benchmark_results.json"
else
  JSON="$BUILD_DIR/benchmark_results_$DRIVER.json"
fi
locked "$EXE" --benchmark_format=console \
  --benchmark_out="$JSON" --benchmark_out_format=json "$@"
echo "run_benchmarks.sh: JSON results in $JSON"
