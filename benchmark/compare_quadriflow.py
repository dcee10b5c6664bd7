#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Automatic quad remeshing, side by side: `smdf remesh MESH --faces N` (automatic cones and an
integer-grid map) against QuadriFlow as shipped in Debian's Blender (bpy.ops.object.quadriflow_remesh),
on the same meshes at the same target face counts, both outputs measured by one evaluator.

usage: compare_quadriflow.py SMDF MESH_DIR [--faces N ...] [--meshes a.off,b.obj] [--json FILE]
                             [--timeout S] [--blender PATH] [--svg-dir DIR] [--view A,E,UP]

With --svg-dir, one picture per run, DIR/<mesh>_<faces>.svg: the two remeshes side by side, drawn
by the same renderer from the same view (orthographic, azimuth A and elevation E in degrees
around the axis UP, x, y or z; default 30,20,z): faces shaded and painted back to front, back
faces culled, interior vertices of valence 3 marked red and of valence 5 or more blue.

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
import math
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


def read_polygons(path):
    """Vertices and faces (0-based) of an OBJ or OFF file."""
    vs, fs = [], []
    if path.endswith(".off"):
        words = []
        for line in open(path):
            words.extend(line.split("#")[0].split())
        nv, nf = int(words[1]), int(words[2])
        at = 4
        for _ in range(nv):
            vs.append(tuple(float(x) for x in words[at:at + 3]))
            at += 3
        for _ in range(nf):
            k = int(words[at])
            fs.append([int(x) for x in words[at + 1:at + 1 + k]])
            at += 1 + k
        return vs, fs
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            vs.append(tuple(float(x) for x in w[1:4]))
        elif w[0] == "f":
            fs.append([int(x.split("/")[0]) - 1 for x in w[1:]])
    return vs, fs


def svg_side_by_side(panels, view, width=1000):
    """One SVG of several meshes side by side, [(caption, vertices, faces)], one camera."""
    az, el = math.radians(view[0]), math.radians(view[1])
    up = "xyz".index(view[2])
    U = [0.0, 0.0, 0.0]
    U[up] = 1.0
    F0 = [0.0, 0.0, 0.0]
    F0[(up + 1) % 3] = 1.0
    R0 = [0.0, 0.0, 0.0]
    R0[(up + 2) % 3] = 1.0
    d = [math.cos(el) * (math.cos(az) * F0[i] + math.sin(az) * R0[i]) + math.sin(el) * U[i] for i in range(3)]
    dot = lambda a, b: a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    uu = [U[i] - dot(U, d) * d[i] for i in range(3)]
    n = math.sqrt(dot(uu, uu))
    uu = [x / n for x in uu]
    rr = cross(uu, d)
    light = [d[i] + 0.5 * uu[i] for i in range(3)]
    n = math.sqrt(dot(light, light))
    light = [x / n for x in light]
    pw, margin, caption_h = width / len(panels), 12.0, 22.0
    body, height = [], 0.0
    scales = []
    for _, vs, _ in panels:
        xs = [dot(v, rr) for v in vs]
        ys = [dot(v, uu) for v in vs]
        w, h = max(xs) - min(xs), max(ys) - min(ys)
        scales.append((min(xs), max(ys), min((pw - 2 * margin) / max(w, 1e-300), 1e300), h))
    scale = min(s[2] for s in scales)   # one scale for all panels: the same mesh at the same size
    for k, (caption, vs, fs) in enumerate(panels):
        x0, y1 = scales[k][0], scales[k][1]
        sx = lambda p: k * pw + margin + (dot(p, rr) - x0) * scale
        sy = lambda p: margin + (y1 - dot(p, uu)) * scale
        height = max(height, scales[k][3] * scale + 2 * margin + caption_h)
        valence, boundary = [0] * len(vs), set()
        edges = {}
        for f in fs:
            for i in range(len(f)):
                valence[f[i]] += 1
                a, b = f[i], f[(i + 1) % len(f)]
                edges[(a, b)] = edges.get((a, b), 0) + 1
        for (a, b) in edges:
            if (b, a) not in edges:
                boundary.update((a, b))
        items, nearest = [], {}
        for f in fs:
            nn = [0.0, 0.0, 0.0]
            for i in range(len(f)):
                c = cross(vs[f[i]], vs[f[(i + 1) % len(f)]])
                nn = [nn[j] + c[j] for j in range(3)]
            ln = math.sqrt(dot(nn, nn))
            if ln == 0 or dot(nn, d) <= 0:
                continue
            nn = [x / ln for x in nn]
            c = [sum(vs[v][j] for v in f) / len(f) for j in range(3)]
            depth = dot(c, d)
            items.append((depth, f, 0.35 + 0.65 * max(0.0, dot(nn, light))))
            for v in f:
                nearest[v] = max(nearest.get(v, -1e300), depth)
        marks = sorted((nearest[v], v) for v in nearest if v not in boundary and valence[v] != 4)
        items.sort(key=lambda t: t[0])
        m = 0
        for depth, f, shade in items:
            g = int(208 * shade)
            body.append('<polygon fill="#%02x%02x%02x" points="%s"/>' % (g, g, g, " ".join("%.1f,%.1f" % (sx(vs[v]), sy(vs[v])) for v in f)))
            while m < len(marks) and marks[m][0] <= depth:
                v = marks[m][1]
                body.append('<circle cx="%.1f" cy="%.1f" r="3.5" fill="%s"/>' % (sx(vs[v]), sy(vs[v]), "#d62020" if valence[v] < 4 else "#2050d6"))
                m += 1
        body.append('<text x="%.1f" y="%.1f">%s</text>' % (k * pw + margin, scales[k][3] * scale + 2 * margin + 14, caption))
    head = ('<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">\n'
            '<style>polygon{stroke:#303030;stroke-width:0.4;stroke-linejoin:round}circle{stroke:#000;stroke-width:0.5}'
            'text{font:13px sans-serif;fill:#404040}</style>\n' % (width, math.ceil(height), width, math.ceil(height)))
    return head + "\n".join(body) + "\n</svg>\n"


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
    ap.add_argument("--svg-dir", default=None)
    ap.add_argument("--view", default="30,20,z")
    a = ap.parse_args()
    view = a.view.split(",")
    if len(view) != 3 or view[2] not in ("x", "y", "z"):
        ap.error("--view A,E,UP: two angles in degrees and an axis x, y or z (got %r)" % a.view)
    view = (float(view[0]), float(view[1]), view[2])
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
                if a.svg_dir and outputs:
                    panels = []
                    for f, k, label in ((smdf_out, "smdf", "smdf"), (qf_out, "quadriflow", "QuadriFlow")):
                        x = row[k]
                        if f in outputs and "faces_by_size" in x:
                            vs, fs = read_polygons(f)
                            panels.append(("%s: %d quads, %d irregular vertices, %.2f s" % (label, x["faces_by_size"].get("4", 0),
                                                                                      x["irregular_vertices"], x["seconds"]), vs, fs))
                    if panels:
                        os.makedirs(a.svg_dir, exist_ok=True)
                        with open(os.path.join(a.svg_dir, "%s_%d.svg" % (os.path.splitext(name)[0], n)), "w") as fh:
                            fh.write(svg_side_by_side(panels, view))
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
