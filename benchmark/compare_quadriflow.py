#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Automatic quad remeshing, side by side: `smdf remesh MESH --faces N` (automatic cones and an
integer-grid map) against QuadriFlow as shipped in Debian's Blender (bpy.ops.object.quadriflow_remesh),
on the same meshes at the same target face counts, both outputs measured by one evaluator.

usage: compare_quadriflow.py SMDF MESH_DIR [--faces N ...] [--meshes a.off,b.obj] [--json FILE]
                             [--timeout S] [--blender PATH]

Exits 0 with a note when Blender is absent (Debian: apt-get install blender).

Per run, for each tool: exit status, quads and other faces, interior vertices of valence != 4
(irregular), min and mean over faces of the smallest corner's scaled Jacobian (the corner's
edge vectors' cross product along the input's normal at the input point nearest the face's
centroid, over their lengths' product), faces whose area vector opposes that normal (flipped),
longest over shortest edge, two-sided distance (remesh vertices to the input, input vertices to
the remesh) over the remesh's mean edge length, area ratio, and time: smdf's whole run (loading
included), QuadriFlow's operator alone (Blender's start-up and the file import excluded).
The evaluator runs inside Blender for its BVH (mathutils.bvhtree): closest points on triangles.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

DEFAULT_MESHES = ["spot_c3d.obj", "bunny_bff.obj", "torus_ddg.obj", "knot1_cgal.off", "bob_small_gc.off", "rocker-arm_c3d.obj",
                  "double-torus_jnd.off", "eight_directional.off", "genus3_vhacd.off", "triple_torus_ccg.off", "fertility_igltut.off"]

# Runs inside Blender: import an OBJ, remesh with QuadriFlow, export, print the operator's time.
QUADRIFLOW = r'''
import bpy, sys, time, json
a = sys.argv[sys.argv.index("--") + 1:]
src, dst, n = a[0], a[1], int(a[2])
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=src, forward_axis="Y", up_axis="Z")
ob = bpy.context.selected_objects[0]
bpy.context.view_layer.objects.active = ob
t = time.perf_counter()
r = bpy.ops.object.quadriflow_remesh(target_faces=n, use_mesh_symmetry=False, use_preserve_sharp=False, use_preserve_boundary=True,
                                      smooth_normals=False, mode="FACES")
dt = time.perf_counter() - t
bpy.ops.wm.obj_export(filepath=dst, export_selected_objects=True, export_materials=False, export_uv=False, export_normals=False,
                      apply_modifiers=False, forward_axis="Y", up_axis="Z")
print("QUADRIFLOW " + json.dumps({"result": list(r), "seconds": dt}))
'''

# Runs inside Blender (for mathutils): measures remeshes of one input, prints one JSON line.
EVALUATE = r'''
import sys, json, math
from mathutils import Vector
from mathutils.bvhtree import BVHTree
a = sys.argv[sys.argv.index("--") + 1:]

def read_obj(path):
    vs, fs = [], []
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            vs.append(Vector((float(w[1]), float(w[2]), float(w[3]))))
        elif w[0] == "f":
            fs.append([int(x.split("/")[0]) - 1 for x in w[1:]])
    return vs, fs

def triangles(fs):
    return [[f[0], f[i], f[i + 1]] for f in fs for i in range(1, len(f) - 1)]

def area(vs, f):
    s = Vector((0, 0, 0))
    for i in range(1, len(f) - 1):
        s += (vs[f[i]] - vs[f[0]]).cross(vs[f[i + 1]] - vs[f[0]])
    return s

iv, ifs = read_obj(a[0])
itree = BVHTree.FromPolygons(iv, triangles(ifs))
input_area = sum(area(iv, f).length for f in ifs) / 2
out = {}
for path in a[1:]:
    vs, fs = read_obj(path)
    if not fs:
        out[path] = None
        continue
    sizes = {}
    edges = {}
    for f in fs:
        sizes[len(f)] = sizes.get(len(f), 0) + 1
        for i in range(len(f)):
            e = (min(f[i], f[(i + 1) % len(f)]), max(f[i], f[(i + 1) % len(f)]))
            edges[e] = edges.get(e, 0) + 1
    boundary = set()
    valence = [0] * len(vs)
    for (p, q), c in edges.items():
        valence[p] += 1
        valence[q] += 1
        if c == 1:
            boundary.update((p, q))
    used = set(i for f in fs for i in f)
    irregular = sum(1 for v in used if v not in boundary and valence[v] != 4)
    lengths = [(vs[p] - vs[q]).length for (p, q) in edges]
    mean_edge = sum(lengths) / len(lengths)
    sj, flipped = [], 0
    for f in fs:
        c = sum((vs[i] for i in f), Vector((0, 0, 0))) / len(f)
        loc, normal, index, dist = itree.find_nearest(c)
        if area(vs, f).dot(normal) < 0:
            flipped += 1
        worst = 1.0
        for i in range(len(f)):
            e1 = vs[f[(i + 1) % len(f)]] - vs[f[i]]
            e2 = vs[f[i - 1]] - vs[f[i]]
            d = e1.length * e2.length
            worst = min(worst, e1.cross(e2).dot(normal) / d if d > 0 else -1.0)
        sj.append(worst)
    rtree = BVHTree.FromPolygons(vs, triangles(fs))
    to_input = max(itree.find_nearest(v)[3] for v in vs if v is not None)
    to_remesh = max(rtree.find_nearest(v)[3] for v in iv)
    out[path] = {"faces_by_size": {str(k): n for k, n in sorted(sizes.items())}, "irregular_vertices": irregular,
                 "min_scaled_jacobian": min(sj), "mean_scaled_jacobian": sum(sj) / len(sj), "flipped_faces": flipped,
                 "edge_length_ratio": max(lengths) / max(min(lengths), 1e-300),
                 "distance_over_edge_length": max(to_input, to_remesh) / mean_edge,
                 "area_ratio": sum(area(vs, f).length for f in fs) / 2 / input_area}
print("EVALUATION " + json.dumps(out))
'''


def off_to_obj(src, dst):
    """OFF (triangles) to OBJ, for Blender's importer; other formats are passed through."""
    words = []
    for line in open(src):
        line = line.split("#")[0]
        words.extend(line.split())
    if not words or not words[0].endswith("OFF"):
        raise ValueError("%s: not an OFF file" % src)
    nv, nf = int(words[1]), int(words[2])
    at = 4
    with open(dst, "w") as out:
        for _ in range(nv):
            out.write("v %s %s %s\n" % tuple(words[at:at + 3]))
            at += 3
        for _ in range(nf):
            k = int(words[at])
            out.write("f " + " ".join(str(int(x) + 1) for x in words[at + 1:at + 1 + k]) + "\n")
            at += 1 + k


def blender_run(blender, script, args, timeout):
    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as fh:
        fh.write(script)
        name = fh.name
    try:
        p = subprocess.run([blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python", name, "--"] + args,
                           capture_output=True, text=True, timeout=timeout)
    finally:
        os.remove(name)
    return p


def tagged(text, tag):
    for line in text.splitlines():
        if line.startswith(tag + " "):
            return json.loads(line[len(tag) + 1:])
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("smdf")
    ap.add_argument("mesh_dir")
    ap.add_argument("--faces", type=int, nargs="+", default=[4000, 20000])
    ap.add_argument("--meshes", default=",".join(DEFAULT_MESHES))
    ap.add_argument("--json", default=None)
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--blender", default=shutil.which("blender"))
    a = ap.parse_args()
    if not a.blender:
        print("compare_quadriflow: Blender not found (Debian: apt-get install blender); nothing compared")
        return 0
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in a.meshes.split(","):
            src = os.path.join(a.mesh_dir, name)
            if not os.path.exists(src):
                print("%s: not found, skipped" % src, file=sys.stderr)
                continue
            obj = os.path.join(tmp, os.path.splitext(name)[0] + ".obj")
            if name.endswith(".off"):
                off_to_obj(src, obj)
            else:
                shutil.copy(src, obj)
            for n in a.faces:
                row = {"mesh": name, "target_faces": n}
                smdf_out = os.path.join(tmp, "smdf_%d.obj" % n)
                t = time.perf_counter()
                try:
                    p = subprocess.run([a.smdf, "remesh", src, "--faces", str(n), "--out", smdf_out], capture_output=True, text=True,
                                       timeout=a.timeout)
                    row["smdf"] = {"exit": p.returncode, "seconds": time.perf_counter() - t, "message": p.stderr.strip()[:300]}
                    if p.returncode == 0:
                        row["smdf"]["cones"] = len(json.loads(p.stdout).get("placed_cones", []))
                except subprocess.TimeoutExpired:
                    row["smdf"] = {"exit": None, "seconds": a.timeout, "message": "timeout"}
                qf_out = os.path.join(tmp, "quadriflow_%d.obj" % n)
                t = time.perf_counter()
                try:
                    p = blender_run(a.blender, QUADRIFLOW, [obj, qf_out, str(n)], a.timeout)
                    r = tagged(p.stdout, "QUADRIFLOW")
                    row["quadriflow"] = {"exit": p.returncode, "seconds": r["seconds"] if r else None,
                                         "blender_seconds": time.perf_counter() - t,
                                         "message": "" if r and r["result"] == ["FINISHED"] else (p.stderr or p.stdout).strip()[-300:]}
                except subprocess.TimeoutExpired:
                    row["quadriflow"] = {"exit": None, "seconds": a.timeout, "message": "timeout"}
                outputs = [f for f, k in ((smdf_out, "smdf"), (qf_out, "quadriflow")) if row[k]["exit"] == 0 and os.path.exists(f)]
                if outputs:
                    p = blender_run(a.blender, EVALUATE, [obj] + outputs, a.timeout)
                    ev = tagged(p.stdout, "EVALUATION") or {}
                    for f, k in ((smdf_out, "smdf"), (qf_out, "quadriflow")):
                        if ev.get(f):
                            row[k].update(ev[f])
                for f in outputs:
                    os.remove(f)
                rows.append(row)
                print(json.dumps(row), flush=True)
    if a.json:
        with open(a.json, "w") as fh:
            json.dump(rows, fh, indent=1)
    # the table
    keys = ["irregular_vertices", "min_scaled_jacobian", "mean_scaled_jacobian", "flipped_faces", "edge_length_ratio",
            "distance_over_edge_length", "seconds"]
    print("\n| mesh | faces | tool | quads | " + " | ".join(keys) + " |")
    print("|---|---|---|---|" + "---|" * len(keys))
    for r in rows:
        for k in ("smdf", "quadriflow"):
            x = r[k]
            if x.get("exit") != 0 or "faces_by_size" not in x:
                print("| %s | %d | %s | failed: %s |" % (r["mesh"], r["target_faces"], k, (x.get("message") or "")[:80].replace("|", "/")))
                continue
            cells = ["%.3g" % x[c] if isinstance(x[c], float) else str(x[c]) for c in keys]
            print("| %s | %d | %s | %s | %s |" % (r["mesh"], r["target_faces"], k, x["faces_by_size"].get("4", 0), " | ".join(cells)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
