#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Regenerates the remeshing pictures of the manual (section "Pictures of Remeshing") with the smdf
# tool: ./make_remeshing_figures.sh [path/to/smdf]. Spot ships in data/.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
smdf=${1:-$root/build/tools/smdf/smdf}
spot=$root/data/spot.off
view=(--view 60,20,y --width 500)
run() { echo "smdf $*"; "$smdf" "$@" > /dev/null || echo "  (exit $?: see the caption)"; }
# quads through the box polycube: eight cones of valence 3
run remesh "$spot" --polycube box --faces 2000 --out /tmp/smdf_spot_quads.obj --svg "$here/spot_remesh_box.svg" "${view[@]}"
# the same box with Lai et al.'s segments by Ricci flow (conformal: the legs and head shrink)
run remesh "$spot" --polycube box --segments ricci --faces 2000 --out /tmp/smdf_spot_quads_ricci.obj --svg "$here/spot_remesh_box_ricci.svg" "${view[@]}"
# triangles through the octahedron: six cones of valence 4 (the grid's 5 inverted triangles are
# unfolded along the surface)
run remesh "$spot" --polycube octahedron --faces 1200 --out /tmp/smdf_spot_triangles.obj --svg "$here/spot_remesh_octahedron.svg" "${view[@]}"
# quads and triangles through the obelisk of Lai et al. Fig. 1c (the grid's one inverted face, next
# to the apex on a horn's tip, is unfolded by letting the apex slide)
run remesh "$spot" --polycube obelisk --grid mixed --faces 1500 --out /tmp/smdf_spot_obelisk.obj --svg "$here/spot_remesh_obelisk.svg" "${view[@]}"
# a woven Celtic knot along the box remesh's medial graph (Lai et al. Fig. 13)
run remesh "$spot" --polycube box --faces 700 --out /tmp/smdf_spot_knot.obj --knot-svg "$here/spot_celtic_knot.svg" "${view[@]}"
# automatic quad remeshes (placed cones, integer-grid map) of genus 0, 1 and 3, each beside
# QuadriFlow's at the same target, both drawn by compare_quadriflow.py's one renderer (needs the
# shared meshes beside the project and Debian's blender; skipped without them)
shared=$root/../shared/data/meshes
if [ -d "$shared" ]; then
  # automatic remeshes of open meshes: the boundary along grid lines
  run remesh "$shared/holes_cgal.off" --faces 4000 --out /tmp/smdf_holes.obj --svg "$here/holes_auto_4000.svg" --view 30,35,z --width 500
  for spec in spot_c3d.obj:60,20,y rocker-arm_c3d.obj:30,25,z genus3_vhacd.off:30,35,z punctured-torus_bff.obj:30,35,z annulus_igltest.obj:30,35,z; do
    mesh=${spec%%:*}
    python3 "$root/benchmark/compare_quadriflow.py" "$smdf" "$shared" --faces 4000 --meshes "$mesh" --svg-dir "$here" --view "${spec#*:}" > /dev/null ||
      echo "  (compare_quadriflow.py failed on $mesh)"
  done
fi
