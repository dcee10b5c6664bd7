#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
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
# Fig. 11: the cross field edited by hard direction constraints on two patches (the vertices
# within 0.12 of vertex 1500 on the back, and of 700 on the rump): on the first the field turned
# by 45 degrees about the vertex normals, on the second kept as it is; hatching, to compare with
# spot_hatching.svg
"$smdf" rosy "$spot" --cones "$cube" --field-out /tmp/smdf_spot_field.txt > /dev/null
python3 - "$spot" /tmp/smdf_spot_field.txt /tmp/smdf_spot_edit.txt 1500:45 700:0 <<'PY'
import math, sys
mesh, field, out, *chosen = sys.argv[1:]
tok = [t for line in open(mesh) for t in line.split("#")[0].split()]
nv, nf = int(tok[1]), int(tok[2])
P = [tuple(map(float, tok[4 + 3 * i:7 + 3 * i])) for i in range(nv)]
F = [tuple(map(int, tok[4 + 3 * nv + 4 * i + 1:4 + 3 * nv + 4 * i + 4])) for i in range(nf)]
V = [tuple(map(float, line.split())) for line in open(field)]
n = [[0.0, 0.0, 0.0] for _ in range(nv)]
for a, b, c in F:
    u = [P[b][k] - P[a][k] for k in range(3)]; w = [P[c][k] - P[a][k] for k in range(3)]
    x = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    for v in (a, b, c):
        for k in range(3): n[v][k] += x[k]
with open(out, "w") as f:
    f.write("# vertex x y z: the field at the vertex turned about its normal\n")
    patches = [(int(x.split(":")[0]), float(x.split(":")[1])) for x in chosen]
    near = lambda a, b: sum((P[a][k] - P[b][k]) ** 2 for k in range(3)) < 0.12 ** 2
    for v, degrees in [(v, d) for v in range(nv) for c, d in patches if near(v, c)]:
        l = math.sqrt(sum(x * x for x in n[v])); m = [x / l for x in n[v]]; d = V[v]
        t = (m[1] * d[2] - m[2] * d[1], m[2] * d[0] - m[0] * d[2], m[0] * d[1] - m[1] * d[0])
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        f.write("%d %.17g %.17g %.17g\n" % ((v,) + tuple(c * d[k] + s * t[k] for k in range(3))))
PY
run rosy "$spot" --cones "$cube" --edit /tmp/smdf_spot_edit.txt --hatching-svg "$here/spot_hatching_edited.svg" --view 60,20,y --width 600
# Figs. 14-15: pen-and-ink hatching along the cross field
run rosy "$spot" --cones "$cube" --hatching-svg "$here/spot_hatching.svg" --view 60,20,y --width 600
# a field parallel to the boundary of an open mesh (CGAL's mushroom: one boundary loop)
if [ -f "$meshes/mushroom_cgal.off" ]; then
  run rosy "$meshes/mushroom_cgal.off" --N 4 --boundary parallel --hatching-svg "$here/mushroom_boundary_parallel.svg" --width 500
fi
# the same on a surface with a handle (the punctured torus: rotation compensation with the
# boundary held)
if [ -f "$meshes/punctured-torus_bff.obj" ]; then
  run rosy "$meshes/punctured-torus_bff.obj" --N 4 --boundary parallel --hatching-svg "$here/punctured_torus_boundary_parallel.svg" --width 500
fi
# Fig. 8: one singularity of index +2 on a genus-0 surface; Fig. 2: one of index -2 on genus 2.
# The trivial connections of the embedding with those singularities, and Fig. 8 by the
# metric-driven method: a hole punched at the cone of 4 pi, the parallel field of the holed
# surface carried back and the hole filled (section "Cones of Index One or More"); a vector field
# parallel to a disk's boundary with one cone of index +1 inside, the same way.
run connection "$spot" --singularities 1855:2 --svg "$here/spot_index_2.svg" "${view[@]}"
run rosy "$spot" --cones 1855:4pi --N 1 --svg "$here/spot_index_2_punched.svg" "${view[@]}"
if [ -f "$meshes/mushroom_cgal.off" ]; then
  run rosy "$meshes/mushroom_cgal.off" --cones 16:2pi --N 1 --boundary parallel --svg "$here/mushroom_index_1_parallel.svg" --width 500
fi
if [ -f "$meshes/eight_directional.off" ]; then
  run connection "$meshes/eight_directional.off" --singularities 0:-2 --svg "$here/eight_index_minus_2.svg" \
      --view 30,40,z --width 500
fi
# Fig. 8 on a head by the metric-driven method where the hole's Ricci flow fails (Homer): the
# cone's curvature spread to its neighbours and the trivial connection; a field parallel to every
# boundary loop of a face with three holes (eyes and mouth); automatic singularities of a
# curvature-aligned field on a metric that needs flips (Cheburashka), hatched on the input
if [ -f "$meshes/homer_cgal.off" ]; then
  run rosy "$meshes/homer_cgal.off" --cone-indices 100:2 --N 1 --svg "$here/homer_index_2_punched.svg" --view 0,10,y --width 500
fi
if [ -f "$meshes/alex_ghm.off" ]; then
  run rosy "$meshes/alex_ghm.off" --N 4 --boundary parallel --hatching-svg "$here/alex_boundary_parallel.svg" --view 180,0,y --width 500
fi
if [ -f "$meshes/cheburashka_igltut.off" ]; then
  run rosy "$meshes/cheburashka_igltut.off" --cones auto --hatching-svg "$here/cheburashka_auto_hatching.svg" --view 0,10,y --width 500
fi
