#!/usr/bin/env bash
# The README's two entry points (CONVENTIONS section 9):
#   ./run.sh example   install missing Debian packages, build smdf (Release), run it on data/torus.off
#   ./run.sh test      install missing Debian packages, build everything, run ctest
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
# libopenblas0-pthread: CHOLMOD's supernodal factorisation runs its dense blocks through BLAS;
# Debian's reference BLAS is several times slower.
PACKAGES=(cmake g++ libcgal-dev libeigen3-dev libsuitesparse-dev libboost-dev libbenchmark-dev ccache doxygen python3 libopenblas0-pthread)

usage() {
  echo "usage: $0 example|test" >&2
  echo "  example  build the smdf tool and run it on data/torus.off" >&2
  echo "  test     build everything and run the test suite (ctest)" >&2
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

run_example() {
  local mesh=data/torus.off
  cmake --build "$BUILD_DIR" -j "$JOBS" --target smdf
  show info "$mesh"
  show holonomy "$mesh"
  echo "Ran smdf info and smdf holonomy on $mesh (build: $BUILD_DIR, Release)."
}

run_tests() {
  cmake --build "$BUILD_DIR" -j "$JOBS"
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
}

[ $# -eq 1 ] || usage
case "$1" in
  example) install_dependencies; configure; run_example ;;
  test)    install_dependencies; configure; run_tests ;;
  *)       usage ;;
esac
