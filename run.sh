#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The README's two entry points (CONVENTIONS section 9):
#   ./run.sh example   install missing Debian packages, build smdf (Release), run it on data/spot.off
#   ./run.sh test      install missing Debian packages, build everything but the benchmark drivers,
#                      run ctest (without the "sweep" and "benchmark" labels)
#   ./run.sh sweep     the sweeps over every shared mesh (ctest -L sweep: field design, and automatic
#                      quad remeshing), then the benchmark drivers built and run once each on their
#                      smallest size
#   ./run.sh sanitize  the library's tests built with AddressSanitizer + UBSan (build-sanitize/;
#                      three of the seven unless SMDF_SANITIZE_TESTS=all;
#                      the smdf tool, examples, benchmarks and the downstream test are left out:
#                      the tool runs under ASan + UBSan in ./run.sh fuzz)
#   ./run.sh fuzz      the libFuzzer targets (clang, build-fuzz/), each run for SMDF_FUZZ_SECONDS
#                      (default 60) on its seed corpus
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
# libopenblas0-pthread: CHOLMOD's supernodal factorisation runs its dense blocks through BLAS;
# Debian's reference BLAS is several times slower.
# clang, libclang-rt-14-dev: the libFuzzer targets (./run.sh fuzz).
PACKAGES=(cmake g++ libcgal-dev libeigen3-dev libsuitesparse-dev libboost-dev libbenchmark-dev ccache doxygen python3 libopenblas0-pthread clang libclang-rt-14-dev)

usage() {
  echo "usage: $0 example|test|sweep|sanitize|fuzz" >&2
  echo "  example  build the smdf tool and run it on data/spot.off (cross field, cone metric, SVGs)" >&2
  echo "  test     build the library's tests, tool and examples and run the test suite (ctest, without the sweep)" >&2
  echo "  sweep    run the sweeps of field design and automatic remeshing over every shared mesh (ctest -L sweep), and build" >&2
  echo "           the benchmark drivers and run each once on its smallest size (ctest -L benchmark)" >&2
  echo "  sanitize build the library's tests with ASan + UBSan and run them" >&2
  echo "  fuzz     build the libFuzzer targets with clang and run each for a bounded time" >&2
  exit 2
}

install_dependencies() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "run.sh: dpkg-query not found (not Debian?); assuming ${PACKAGES[*]} are installed" >&2
    return
  fi
  local missing=() p
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return
  fi
  echo "run.sh: installing missing packages: ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then sudo=(sudo); fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
}

configure() {
  # Single-threaded BLAS/OpenMP: threaded OpenBLAS made SPQR far slower on a loaded machine.
  export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
}

# Prints a command's output, pretty-printed when it is JSON and python3 is available.
show() {
  echo "== smdf $*"
  local out
  out=$("$BUILD_DIR/tools/smdf/smdf" "$@")
  if command -v python3 >/dev/null 2>&1 && printf '%s\n' "$out" | python3 -m json.tool 2>/dev/null; then
    :
  else
    printf '%s\n' "$out"
  fi
  echo
}

# The package's job on a real mesh (data/spot.off, CC0, see data/README.md): a cross field with
# eight singularities of index 1/4 at the vertices extreme in the eight diagonal directions
# (they sum to chi = 2), then a flat cone metric with cones of pi/2 at the same vertices, and
# the cross field of that metric, which is parallel (Lai et al.: no rotation at all).
run_example() {
  local mesh=data/spot.off out=$BUILD_DIR/example
  local corners=(2202 1077 2587 1488 2221 1090 533 248)
  local sing="" cones="" v
  for v in "${corners[@]}"; do sing+="${sing:+,}$v:1/4"; cones+="${cones:+,}$v:pi/2"; done
  cmake --build "$BUILD_DIR" -j "$JOBS" --target smdf
  mkdir -p "$out"
  show info "$mesh"
  show connection "$mesh" --N 4 --singularities "$sing" --svg "$out/spot_cross_field.svg"
  show cone-metric "$mesh" --cones "$cones" --no-flips --lengths-out "$out/spot_cone_metric.txt"
  show connection "$mesh" --lengths "$out/spot_cone_metric.txt" --N 4 --singularities "$sing" \
    --svg "$out/spot_parallel_cross_field.svg"
  show rosy "$mesh" --cones "$cones" --hatching-svg "$out/spot_hatching.svg" --view 60,20,y
  show remesh "$mesh" --polycube box --faces 2000 --out "$out/spot_quads.obj" --svg "$out/spot_quads.svg"
  echo "Ran smdf on $mesh: a cross field with 8 singularities of index 1/4, a flat cone metric with"
  echo "8 cones of pi/2, the parallel cross field of that metric (max_rotation 0), the same field by"
  echo "Lai et al.'s pipeline (rosy: read back with its matching, found == prescribed), and a quad remesh"
  echo "through the box polycube metric ($out/spot_quads.obj: 8 vertices of valence 3, all others 4)."
  echo "Pictures: $out/spot_cross_field.svg, $out/spot_parallel_cross_field.svg, $out/spot_hatching.svg"
  echo "(pen-and-ink hatching along the field) and $out/spot_quads.svg (the remesh)"
  echo "(build: $BUILD_DIR, Release)."
}

run_tests() {
  cmake --build "$BUILD_DIR" -j "$JOBS"
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" -LE "sweep|benchmark"
}

# The sweep over every shared mesh (CTest label "sweep"), and the benchmark drivers, built here
# and run once each on their smallest size (label "benchmark"); CI runs this after the tests.
run_sweep() {
  cmake --build "$BUILD_DIR" -j "$JOBS" --target smdf smdf_benchmarks
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" -L "sweep|benchmark"
}

run_sanitized_tests() {
  local dir=${SANITIZE_BUILD_DIR:-build-sanitize}
  export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
  # CHOLMOD and OpenBLAS are not instrumented; leaks of their one-time allocations are not ours
  export ASAN_OPTIONS=detect_leaks=0:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # a reduced mesh set: instrumented code is slower (10k faces: test_remeshing 52 s instead of 175 s)
  export SMDF_TEST_MAX_FACES=${SMDF_TEST_MAX_FACES:-10000}
  # -O1: instrumented CGAL translation units took 6 min each at -O2 -g on 2 cores.
  # No smdf (CI time: its 11 instrumented units and test_smdf took 10 of 41 minutes); the fuzz
  # targets run the whole tool, main included, under ASan + UBSan.
  # The tests of the code changing most (intrinsic correspondence, remeshing) and the foundation;
  # SMDF_SANITIZE_TESTS=all adds those of field design, the trivial connection and the cone
  # metric, clean under both sanitizers in every CI run through 2026-12 (CI time: their
  # instrumented build and run took about 6 of its minutes; measured here, the four-test build
  # alone took 13.7 min of one core).
  local tests=(test_foundation test_intrinsic_correspondence test_remeshing)
  if [ "${SMDF_SANITIZE_TESTS:-}" = all ]; then tests+=(test_field_design test_trivial_connection test_random_verification test_cone_metric); fi
  local programs
  programs=$(IFS=';'; echo "${tests[*]}")
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1" -DSMDF_SANITIZE=ON \
        -DSMDF_BUILD_EXAMPLES=OFF -DSMDF_BUILD_BENCHMARKS=OFF -DSMDF_BUILD_TOOLS=OFF -DSMDF_TEST_PROGRAMS="$programs"
  cmake --build "$dir" -j "$JOBS"
  local pattern
  pattern="^($(IFS='|'; echo "${tests[*]}"))(_[a-z]+)?\$"
  ctest --test-dir "$dir" --output-on-failure -j "$JOBS" -R "$pattern"
}

run_fuzzers() {
  local dir=${FUZZ_BUILD_DIR:-build-fuzz} seconds=${SMDF_FUZZ_SECONDS:-60}
  local corpus=test/Surface_mesh_direction_fields/fuzz/corpus
  export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 ASAN_OPTIONS=detect_leaks=0
  CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1" -DSMDF_BUILD_FUZZERS=ON \
        -DSMDF_BUILD_TESTS=OFF -DSMDF_BUILD_EXAMPLES=OFF -DSMDF_BUILD_BENCHMARKS=OFF -DSMDF_BUILD_TOOLS=OFF
  local targets=(fuzz_mesh_reading fuzz_cli_lists fuzz_cli_files) t scratch
  # runs per target at most (with the fixed seed: the inputs of a clean local run of 45 s each;
  # CI gives each 30 s, which usually ends a run first)
  local -A runs=([fuzz_mesh_reading]=70000 [fuzz_cli_lists]=1500000 [fuzz_cli_files]=2800)
  cmake --build "$dir" -j "$JOBS" --target "${targets[@]}"
  for t in "${targets[@]}"; do
    scratch=$(mktemp -d)   # new inputs go there, the seed corpus in the repository stays as it is
    echo "run.sh: $t for ${seconds} s"
    # a fixed seed: CI explores the same inputs every time (new findings come from local runs)
    "$dir/test/Surface_mesh_direction_fields/fuzz/$t" -seed="${SMDF_FUZZ_SEED:-1}" -max_total_time="$seconds" -runs="${SMDF_FUZZ_RUNS:-${runs[$t]}}" -timeout=20 \
      -rss_limit_mb=4096 -print_final_stats=1 "$scratch" "$corpus/$t"
    rm -rf "$scratch"
  done
}

[ $# -eq 1 ] || usage
case "$1" in
  example) install_dependencies; configure; run_example ;;
  test)    install_dependencies; configure; run_tests ;;
  sweep)   install_dependencies; configure; run_sweep ;;
  sanitize) install_dependencies; run_sanitized_tests ;;
  fuzz)    install_dependencies; run_fuzzers ;;
  *)       usage ;;
esac
