#!/usr/bin/env bash
# Regenerates the field-design pictures of the manual (section "Pictures of Field Design") with
# the smdf tool: ./make_field_design_figures.sh [path/to/smdf]. Spot ships in data/; the face,
# Spot's Keenan Crane original and the genus-2 model come from ../shared/data/meshes.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
smdf=${1:-$root/build/tools/smdf/smdf}
meshes=$root/../shared/data/meshes
spot=$root/data/spot.off
list() { local k=$1; shift; local out="" v; for v in "$@"; do out+="${out:+,}$v:$k"; done; echo "$out"; }
# the vertices of Spot extreme in the eight diagonal directions (a box) and along the axes
cube=$(list pi/2 2202 1077 2587 1488 2221 1090 533 248)
octahedron=$(list 2pi/3 1239 2369 1490 289 1855 1453)
view=(--view 60,20,y --width 500)
run() { echo "smdf $*"; "$smdf" "$@" > /dev/null; }

# Lai et al. Fig. 10: a 3-RoSy field (six cones of 2 pi/3) and a 4-RoSy field (eight of pi/2)
run rosy "$spot" --cones "$octahedron" --hatching-svg "$here/spot_3rosy_hatching.svg" "${view[@]}"
run rosy "$spot" --cones "$cube" --svg "$here/spot_4rosy.svg" "${view[@]}"
# Fig. 11: the cross field edited by two hard direction constraints
cat > /tmp/smdf_spot_edit.txt <<'EOF'
# vertex  x y z   (a direction at a vertex of the back and one of the neck)
1500 1 1 0
700 0 1 1
EOF
run rosy "$spot" --cones "$cube" --edit /tmp/smdf_spot_edit.txt --svg "$here/spot_4rosy_edited.svg" "${view[@]}"
# Figs. 14-15: pen-and-ink hatching along the cross field
run rosy "$spot" --cones "$cube" --hatching-svg "$here/spot_hatching.svg" --view 60,20,y --width 600
# a field parallel to the boundary of an open mesh (the face of boundary-first flattening)
if [ -f "$meshes/face_bff.obj" ]; then
  run rosy "$meshes/face_bff.obj" --N 4 --boundary parallel --hatching-svg "$here/face_boundary_parallel.svg" \
      --view 20,10,y --width 500
fi
# Fig. 8: one singularity of index +2 on a genus-0 surface; Fig. 2: one of index -2 on genus 2.
# A cone of index 1 or more has no flat cone metric (it would be a hole) and the single cone of
# -4 pi makes the Ricci flow flip edges (the field then lives on an intrinsic triangulation), so
# both are the trivial connections of the embedding with those singularities.
run connection "$spot" --singularities 1855:2 --svg "$here/spot_index_2.svg" "${view[@]}"
if [ -f "$meshes/eight_directional.off" ]; then
  run connection "$meshes/eight_directional.off" --singularities 0:-2 --svg "$here/eight_index_minus_2.svg" \
      --view 30,40,z --width 500
fi
