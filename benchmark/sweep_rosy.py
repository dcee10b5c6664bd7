#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Randomised "user sweep" of `smdf rosy` over every valid mesh of a directory (stdlib only).

usage: sweep_rosy.py SMDF_BINARY MESH_DIR --seed S [--max-faces 120000] [--jobs 1]
                     [--out FILE] [--only NAME[,NAME...]] [--timeout 300]

Every *.off / *.obj of MESH_DIR is first checked with `smdf info`: meshes it rejects (non-manifold,
non-orientable, not triangles, ...), meshes with several components, meshes with zero-area faces
(info accepts them but rosy rejects them) and meshes with more than --max-faces faces (read from
the file, before info runs) are skipped, with the reason printed.

Runs, per mesh (the random choices come from random.Random("SEED:MESH"), so a mesh gets the same
runs whatever --only and --jobs are):
  closed meshes   two N drawn from {1, 2, 3, 4, 6}; for each, random cones given as
                  --cone-indices 'v:k/N,...' with --N N and the default method: mostly +-1/N,
                  summing exactly to chi, always one pair of adjacent cones +1/N and -1/N (for
                  N = 1 the +1 is itself a punched hole), 0-2 more +-1/N pairs, for N >= 3 sometimes a cone of +-2/N, and on genus-0 meshes
                  sometimes one cone of index 1 or 2 (a punched hole, no cone next to it);
                  then one `--cones auto --N N` run with N drawn from {1, 2, 3, 4, 6}.
  open meshes     --boundary free, parallel and orthogonal, each with its own N from
                  {1, 2, 3, 4, 6} and a few interior cones (--cone-indices, --N N):
                  - parallel / orthogonal with N = 1 or 2: the boundary vertices' turning angles
                    are rounded to multiples of pi strictly inside (-pi, pi), i.e. to 0, so the
                    interior indices must sum to chi: they are built like the closed-mesh sets;
                  - otherwise (free boundary, or N >= 3): 0 to 3 random cones of +-1/N (half of
                    the time plus an adjacent +-1/N pair); the tool's boundary turning absorbs
                    the rest of Gauss-Bonnet.
                  Interior cones are off the boundary; cones of index >= 1 (punched holes) sit
                  two rings away from it and not next to another cone.
                  Then one run with cones touching the boundary (interior vertices next to a
                  boundary vertex), --boundary parallel or orthogonal, N from {1, 2, 3, 4, 6};
                  for N = 1 one of them of index 1 (its hole touches the boundary).
Every run writes --face-field-out, --matching-out and --field-out, then the face field is read
back with `smdf singularities MESH --field FACE --N N --matching MATCHING`. A run is OK when rosy
exits 0 with "success": true and the read-back "singularities" list equals the prescribed cones
exactly (the list [{"vertex": v, "index": k / N}] sorted by vertex, compared with == as
test_smdf.py does; for --cones auto: rosy's own "prescribed" list). A run that exceeds --timeout
seconds (each of the two smdf calls) fails.

Prints one line per run (as runs finish) and a summary: ok/total, per mesh and per mode, and the
failures grouped by message (file names and numbers replaced by placeholders), one reproducing
command per group. --out FILE gets the run lines (in run order) and the summary.
Exit code 0 when every run is OK, 1 when some failed (or no mesh was left to run), 2 on usage
errors. OMP_NUM_THREADS and OPENBLAS_NUM_THREADS default to 1 in the children (as in the tests).
"""

import argparse
import concurrent.futures
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time

NS = (1, 2, 3, 4, 6)


# ---- meshes -------------------------------------------------------------------------------------

def header_face_count(path):
    """The number of faces of an OFF (header) or OBJ (f lines) file, or None if unreadable."""
    try:
        if path.lower().endswith(".off"):
            with open(path) as f:
                tokens = []
                for line in f:
                    line = line.split("#", 1)[0]
                    tokens += line.split()
                    if len(tokens) >= 4:
                        break
            if tokens and tokens[0].endswith("OFF"):
                tokens = tokens[1:]
            return int(tokens[1])
        with open(path, errors="replace") as f:
            return sum(1 for line in f if line.startswith("f ") or line.startswith("f\t"))
    except (OSError, ValueError, IndexError):
        return None


def read_faces(path):
    """(number of vertices in the file, faces as tuples of 0-based vertex indices in file order)."""
    faces = []
    if path.lower().endswith(".off"):
        with open(path) as f:
            lines = (l.split("#", 1)[0].split() for l in f)
            lines = [t for t in lines if t]
        head = lines[0]
        if head[0].endswith("OFF") and len(head) == 1:
            counts, pos = lines[1], 2
        else:
            counts, pos = head[1:] if head[0].endswith("OFF") else head, 1
        nv, nf = int(counts[0]), int(counts[1])
        pos += nv
        for t in lines[pos:pos + nf]:
            n = int(t[0])
            faces.append(tuple(int(x) for x in t[1:1 + n]))
        return nv, faces
    nv = 0
    with open(path, errors="replace") as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                nv += 1
            elif t[0] == "f":
                idx = [int(x.split("/")[0]) for x in t[1:]]
                faces.append(tuple(i - 1 if i > 0 else nv + i for i in idx))
    return nv, faces


class Mesh:
    """Connectivity of a valid mesh: neighbours, boundary vertices, the interior vertices and
    those two rings away from the boundary."""

    def __init__(self, path, info):
        self.path = path
        self.name = os.path.basename(path)
        self.info = info
        self.genus = info["genus"][0]
        self.loops = info["boundary_loops"]
        self.chi = info["euler_characteristic"]
        self.faces_count = info["faces"]
        nv, faces = read_faces(path)
        self.nv = nv
        self.adjacent = {}
        edge_count = {}
        for f in faces:
            for k in range(len(f)):
                a, b = f[k], f[(k + 1) % len(f)]
                self.adjacent.setdefault(a, set()).add(b)
                self.adjacent.setdefault(b, set()).add(a)
                e = (min(a, b), max(a, b))
                edge_count[e] = edge_count.get(e, 0) + 1
        self.on_border = {v for e, n in edge_count.items() if n == 1 for v in e}
        self.interior = sorted(v for v in self.adjacent if v not in self.on_border)
        self.interior_set = inner = set(self.interior)
        self.near_interior = sorted(v for v in self.interior if self.adjacent[v] <= inner)
        near = set(self.near_interior)
        self.far = sorted(v for v in self.near_interior if self.adjacent[v] <= near)
        # where a cone of index >= 1 (a punched hole) goes: two rings from the boundary if possible
        self.hole_candidates = self.far or self.near_interior or self.interior
        self.referenced = len(self.adjacent)


def smdf_info(smdf, path, timeout):
    """(info dict, None) or (None, reason)."""
    try:
        p = subprocess.run([smdf, "info", path], stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "smdf info timed out"
    if p.returncode != 0:
        err = p.stderr.decode("utf-8", "replace").strip().splitlines()
        return None, "invalid: " + strip_error(err[0] if err else "smdf info exit %d" % p.returncode)
    try:
        return json.loads(p.stdout.decode("utf-8")), None
    except ValueError as e:
        return None, "smdf info printed no JSON (%s)" % e


# ---- random prescriptions ------------------------------------------------------------------------

class ConeSet:
    """Cones as {vertex: k} (index k / N). Cones of index >= 1 (punched holes) get no other
    cone next to them, except the +1 of an adjacent pair when N = 1."""

    def __init__(self, rng, mesh, N):
        self.rng, self.mesh, self.N = rng, mesh, N
        self.cones = {}
        self.holes = set()

    def free(self, v):
        return v not in self.cones and not any(w in self.holes for w in self.mesh.adjacent[v])

    def isolated(self, v):
        return v not in self.cones and not any(w in self.cones for w in self.mesh.adjacent[v])

    def pick(self, candidates, ok):
        for _ in range(2000):
            v = self.rng.choice(candidates)
            if ok(v):
                return v
        for v in self.rng.sample(candidates, len(candidates)):
            if ok(v):
                return v
        raise ValueError("no vertex left for a cone")

    def add(self, k):
        """A cone of index k / N at a random free vertex (index >= 1: a punched hole, two rings
        from the boundary and with no cone next to it)."""
        if k >= self.N:
            v = self.pick(self.mesh.hole_candidates, self.isolated)
            self.holes.add(v)
        else:
            v = self.pick(self.mesh.interior, self.free)
        self.cones[v] = k
        return v

    def adjacent_pair(self):
        """+1/N and -1/N at two adjacent interior vertices (for N = 1 the +1 is a punched hole:
        then none of its other neighbours is a cone)."""
        cands = self.mesh.hole_candidates if self.N == 1 else self.mesh.interior
        inner = self.mesh.interior_set

        def ok(a):
            return self.isolated(a) and any(b in inner and self.free(b) for b in self.mesh.adjacent[a])
        a = self.pick(cands, ok)
        b = self.rng.choice(sorted(w for w in self.mesh.adjacent[a] if w in inner and self.free(w)))
        self.cones[a], self.cones[b] = 1, -1
        if self.N == 1:
            self.holes.add(a)

    def total(self):
        return sum(self.cones.values())

    def fill_to(self, units):
        """More cones, mostly +-1/N, until the indices sum to units / N."""
        rest = units - self.total()
        sign = 1 if rest > 0 else -1
        while rest != 0:
            if self.N >= 3 and abs(rest) >= 2 and self.rng.random() < 0.15:
                self.add(2 * sign)
                rest -= 2 * sign
            else:
                self.add(sign)
                rest -= sign

    def spec(self):
        return ",".join("%d:%d/%d" % (v, k, self.N) for v, k in sorted(self.cones.items()))

    def want(self):
        return [{"vertex": v, "index": k / self.N} for v, k in sorted(self.cones.items())]


def closed_like_set(rng, mesh, N, allow_big):
    """Cones summing exactly to chi: an adjacent +-1/N pair, 0-2 more +-1/N pairs, sometimes
    (allow_big) one cone of index 1 or 2, the rest +-1/N (sometimes +-2/N for N >= 3)."""
    c = ConeSet(rng, mesh, N)
    c.adjacent_pair()
    if allow_big and rng.random() < 0.4:
        c.add(rng.choice((1, 2)) * N)
    for _ in range(rng.randint(0, 2)):
        c.add(1)
        c.add(-1)
    c.fill_to(mesh.chi * N)
    return c


def plan_runs(mesh, seed):
    """The runs of one mesh: dicts with mode, N, args, want (None: rosy's 'prescribed')."""
    rng = random.Random("%s:%s" % (seed, mesh.name))
    runs = []
    if mesh.loops == 0:
        for N in rng.sample(NS, 2):
            c = closed_like_set(rng, mesh, N, allow_big=mesh.genus == 0)
            runs.append(dict(mode="cones", N=N, args=["--cone-indices", c.spec(), "--N", str(N)], want=c.want(),
                             ncones=len(c.cones)))
        N = rng.choice(NS)
        runs.append(dict(mode="auto", N=N, args=["--cones", "auto", "--N", str(N)], want=None, ncones=None))
    else:
        for mode in ("free", "parallel", "orthogonal"):
            N = rng.choice(NS)
            if mode != "free" and N in (1, 2):
                # every boundary vertex turns by 0 (multiples of pi strictly inside (-pi, pi)):
                # the interior indices sum to chi
                c = closed_like_set(rng, mesh, N, allow_big=mesh.chi > 0)
            else:
                c = ConeSet(rng, mesh, N)
                if rng.random() < 0.5:
                    c.adjacent_pair()
                for _ in range(rng.randint(0, 3)):
                    c.add(rng.choice((1, -1)))
            args = (["--cone-indices", c.spec()] if c.cones else []) + ["--N", str(N), "--boundary", mode]
            runs.append(dict(mode=mode, N=N, args=args, want=c.want(), ncones=len(c.cones)))
        # cones touching the boundary (the flat metric may need a vertex on the border edge a
        # cone faces; for N = 1 one of index 1, whose hole needs room first)
        touching = sorted(set(mesh.interior) - set(mesh.near_interior))
        mode, N = rng.choice(("parallel", "orthogonal")), rng.choice(NS)
        if len(touching) >= 12:
            c = ConeSet(rng, mesh, N)
            if N == 1:
                c.cones[rng.choice(touching)] = 1
            units = mesh.chi * N if N in (1, 2) else c.total() + rng.choice((-2, -1, 1, 2))
            for _ in range(10000):
                if c.total() == units:
                    break
                v = rng.choice(touching)
                if v not in c.cones:
                    c.cones[v] = 1 if units > c.total() else -1
            if c.total() == units:
                # (no cone at all when the boundary alone carries the total: the annulus at N = 2)
                args = (["--cone-indices", c.spec()] if c.cones else []) + ["--N", str(N), "--boundary", mode]
                runs.append(dict(mode="touch-" + mode[:4], N=N, args=args, want=c.want(), ncones=len(c.cones)))
    return runs


# ---- running ---------------------------------------------------------------------------------------

def strip_error(line):
    return line[len("smdf: error: "):] if line.startswith("smdf: error: ") else line


def first_line(data):
    for line in data.decode("utf-8", "replace").splitlines():
        if line.strip():
            return line.strip()
    return ""


def normalise(msg, paths):
    """A message with file names, numbers and per-mesh details replaced by placeholders."""
    for p in paths:
        msg = msg.replace(p, "MESH")
    msg = re.sub(r"/\S+\.(off|obj|txt)", "FILE", msg)
    msg = re.sub(r"\([^()]*\d[^()]*\)", "(...)", msg)   # lists of vertices, values in parentheses
    msg = re.sub(r"-?\d+(\.\d+)?(e[-+]?\d+)?", "#", msg)
    return msg


def child_env():
    env = dict(os.environ)
    env.setdefault("OMP_NUM_THREADS", "1")   # single-threaded BLAS/OpenMP, as in the tests
    env.setdefault("OPENBLAS_NUM_THREADS", "1")
    return env


def call(cmd, timeout, env):
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout, env=env)
        return p.returncode, p.stdout, p.stderr, time.monotonic() - t0
    except subprocess.TimeoutExpired:
        return None, b"", b"", time.monotonic() - t0


def diff_text(got, want):
    g = {(x.get("vertex"), x.get("index")) for x in got if isinstance(x, dict)}
    w = {(x["vertex"], x["index"]) for x in want}
    extra, missing = sorted(g - w), sorted(w - g)
    return "%d extra (%s), %d missing (%s)" % (len(extra), ", ".join("%s:%g" % e for e in extra[:3]),
                                               len(missing), ", ".join("%s:%g" % m for m in missing[:3]))


def execute(smdf, mesh, run, tmp, timeout, env):
    """Runs rosy and the read-back; fills run['ok'], ['method'], ['time'], ['message']."""
    files = {k: os.path.join(tmp, "%s_%d_%s.txt" % (mesh.name, run["id"], k)) for k in ("face", "matching", "vertex")}
    cmd = [smdf, "rosy", mesh.path] + run["args"] + ["--face-field-out", files["face"], "--matching-out", files["matching"],
                                                     "--field-out", files["vertex"]]
    # the command as printed for reproduction: output files in the current directory
    shown = {files[k]: k + ".txt" for k in files}
    run["cmd"] = [shown.get(a, a) for a in cmd]
    run["ok"], run["method"], run["message"] = False, None, ""
    rc, out, err, dt = call(cmd, timeout, env)
    run["time"] = dt
    try:
        if rc is None:
            run["message"] = "timeout after %d s" % timeout
            return
        doc = None
        try:
            doc = json.loads(out.decode("utf-8"), parse_constant=lambda s: float("nan")) if out.strip() else None
        except ValueError:
            doc = None
        if isinstance(doc, dict):
            run["method"] = doc.get("method")
            if run["mode"] == "auto":
                run["ncones"] = len(doc.get("prescribed", []) or [])
        if rc != 0 or not isinstance(doc, dict) or doc.get("success") is not True:
            msg = strip_error(first_line(err))
            if not msg and isinstance(doc, dict):
                msg = str(doc.get("message") or doc.get("failure") or "")
            if not msg:
                msg = "no JSON on stdout" if doc is None else "success is %r" % doc.get("success")
            run["message"] = "rosy exit %s: %s" % (rc, msg) if rc != 0 else "rosy: " + msg
            return
        want = run["want"] if run["want"] is not None else doc.get("prescribed")
        if want is None:
            run["message"] = "rosy --cones auto printed no 'prescribed' list"
            return
        for k in ("face", "matching", "vertex"):
            if not os.path.isfile(files[k]):
                run["message"] = "rosy wrote no --%s file" % {"face": "face-field-out", "matching": "matching-out",
                                                              "vertex": "field-out"}[k]
                return
        back_cmd = [smdf, "singularities", mesh.path, "--field", files["face"], "--N", str(run["N"]), "--matching", files["matching"]]
        brc, bout, berr, _ = call(back_cmd, timeout, env)
        if brc is None:
            run["message"] = "read-back: smdf singularities timeout after %d s" % timeout
            return
        if brc != 0:
            run["message"] = "read-back: smdf singularities exit %s: %s" % (brc, strip_error(first_line(berr)))
            return
        try:
            back = json.loads(bout.decode("utf-8"), parse_constant=lambda s: float("nan"))
        except ValueError:
            run["message"] = "read-back: smdf singularities printed no JSON"
            return
        got = back.get("singularities") if isinstance(back, dict) else None
        if got != want:
            run["message"] = "read-back differs from the prescribed cones: " + (diff_text(got, want) if isinstance(got, list)
                                                                                else "no singularities list")
            return
        run["ok"] = True
    finally:
        for f in files.values():
            try:
                os.remove(f)
            except OSError:
                pass


def run_line(mesh, run, width):
    return "[%*d/%d] %-6s %-28s g=%-3s b=%-2s N=%d %-10s cones=%-5s method=%-45s %8.2fs%s" % (
        width, run["seq"], run["total"], "OK" if run["ok"] else "FAILED", mesh.name, mesh.genus, mesh.loops, run["N"],
        run["mode"], "-" if run["ncones"] is None else run["ncones"], run["method"] or "-", run["time"],
        "" if run["ok"] else "  " + run["message"])


# ---- summary -----------------------------------------------------------------------------------------

def table(headers, rows):
    widths = [max(len(str(x)) for x in col) for col in zip(headers, *rows)]
    fmt = "  ".join("%%-%ds" % w for w in widths)
    lines = [fmt % tuple(headers), fmt % tuple("-" * w for w in widths)]
    lines += [fmt % tuple(str(x) for x in r) for r in rows]
    return [l.rstrip() for l in lines]


def summary(all_runs, meshes, skipped, args):
    out = []
    ok = sum(1 for m, r in all_runs if r["ok"])
    out.append("")
    out.append("== smdf rosy sweep: seed %s, %d meshes run, %d skipped: %d of %d runs OK, %d failed"
               % (args.seed, len(meshes), len(skipped), ok, len(all_runs), len(all_runs) - ok))
    if skipped:
        out.append("")
        out.append("skipped meshes:")
        out += ["  " + l for l in table(["mesh", "reason"], sorted(skipped))]
    out.append("")
    out.append("per mesh:")
    rows = []
    for mesh in meshes:
        rs = [r for m, r in all_runs if m is mesh]
        if not rs:
            continue
        rows.append([mesh.name, mesh.genus, mesh.loops, mesh.faces_count, "%d/%d" % (sum(r["ok"] for r in rs), len(rs)),
                     "%.2f" % sum(r["time"] for r in rs), "%.2f" % max(r["time"] for r in rs)])
    out += ["  " + l for l in table(["mesh", "genus", "loops", "faces", "ok/total", "time_s", "max_s"], rows)]
    out.append("")
    out.append("per mode:")
    rows = []
    for mode in ("cones", "auto", "free", "parallel", "orthogonal", "touch-para", "touch-orth"):
        rs = [r for m, r in all_runs if r["mode"] == mode]
        if rs:
            rows.append([mode, "%d/%d" % (sum(r["ok"] for r in rs), len(rs))])
    out += ["  " + l for l in table(["mode", "ok/total"], rows)]
    failed = [(m, r) for m, r in all_runs if not r["ok"]]
    if failed:
        groups = {}
        for m, r in failed:
            groups.setdefault(normalise(r["message"], [m.path]), []).append((m, r))
        out.append("")
        out.append("failures by message (%d groups):" % len(groups))
        for key, items in sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0])):
            out.append("  %3d x  %s" % (len(items), key))
            out.append("         runs: " + ", ".join("%s N=%d %s" % (m.name, r["N"], r["mode"]) for m, r in items))
            m, r = items[0]
            out.append("         e.g.: " + r["message"])
            out.append("         reproduce: " + " ".join(quote(a) for a in r["cmd"]))
    return out


def quote(a):
    return a if re.fullmatch(r"[A-Za-z0-9_./:,=+-]+", a) else "'" + a.replace("'", "'\\''") + "'"


# ---- main ----------------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n", 2)[2])
    ap.add_argument("smdf", help="the smdf executable")
    ap.add_argument("mesh_dir", help="directory of OFF/OBJ meshes")
    ap.add_argument("--seed", required=True, help="random seed (any string; each mesh derives its own generator from it)")
    ap.add_argument("--max-faces", type=int, default=120000, help="skip meshes with more faces (default 120000)")
    ap.add_argument("--jobs", type=int, default=1, help="runs in parallel (default 1)")
    ap.add_argument("--out", help="also write the run lines and the summary to this file")
    ap.add_argument("--only", help="comma-separated mesh file names (or name stems) to sweep, e.g. rotor_cgal.off,mushroom_cgal")
    ap.add_argument("--timeout", type=float, default=300, help="seconds per smdf call before the run counts as failed (default 300)")
    args = ap.parse_args()

    smdf = os.path.abspath(args.smdf)
    if not os.access(smdf, os.X_OK):
        ap.error("%s is not an executable" % args.smdf)
    if not os.path.isdir(args.mesh_dir):
        ap.error("%s is not a directory" % args.mesh_dir)
    if args.jobs < 1:
        ap.error("--jobs must be at least 1")
    names = sorted(n for n in os.listdir(args.mesh_dir) if n.lower().endswith((".off", ".obj")))
    if args.only:
        wanted = {w.strip() for w in args.only.split(",") if w.strip()}
        unknown = [w for w in wanted if not any(n == w or os.path.splitext(n)[0] == w for n in names)]
        if unknown:
            ap.error("--only: no mesh named %s in %s" % (", ".join(sorted(unknown)), args.mesh_dir))
        names = [n for n in names if n in wanted or os.path.splitext(n)[0] in wanted]

    env = child_env()
    meshes, skipped = [], []
    for name in names:
        path = os.path.abspath(os.path.join(args.mesh_dir, name))
        nf = header_face_count(path)
        if nf is not None and nf > args.max_faces:
            skipped.append([name, "%d faces > --max-faces %d" % (nf, args.max_faces)])
            continue
        info, why = smdf_info(smdf, path, args.timeout)
        if info is None:
            skipped.append([name, why.replace(path + ": ", "")])
        elif info.get("components") != 1:
            skipped.append([name, "%s components" % info.get("components")])
        elif info.get("faces", 0) > args.max_faces:
            skipped.append([name, "%d faces > --max-faces %d" % (info["faces"], args.max_faces)])
        elif info.get("degenerate_faces", 0) > 0:
            skipped.append([name, "%d zero-area faces (rejected by the geometric commands)" % info["degenerate_faces"]])
        else:
            try:
                mesh = Mesh(path, info)
            except (OSError, ValueError, IndexError) as e:
                skipped.append([name, "unreadable here: %s" % e])
                continue
            if mesh.nv != info["vertices"] or mesh.referenced != info["vertices"] - info.get("isolated_vertices", 0):
                skipped.append([name, "vertex counts differ from smdf info (%d/%d here)" % (mesh.referenced, mesh.nv)])
                continue
            meshes.append(mesh)
    for name, why in skipped:
        print("skip %s: %s" % (name, why), flush=True)

    all_runs = []
    for mesh in meshes:
        try:
            plan = plan_runs(mesh, args.seed)
        except ValueError as e:
            skipped.append([mesh.name, "no prescription: %s" % e])
            print("skip %s: no prescription: %s" % (mesh.name, e), flush=True)
            continue
        for run in plan:
            all_runs.append((mesh, run))
    meshes = [m for m in meshes if any(mm is m for mm, _ in all_runs)]
    width = len(str(len(all_runs)))
    for i, (mesh, run) in enumerate(all_runs):
        run["id"], run["seq"], run["total"] = i, i + 1, len(all_runs)
    print("%d runs on %d meshes (seed %s, %d job(s), timeout %g s)" % (len(all_runs), len(meshes), args.seed, args.jobs, args.timeout),
          flush=True)

    tmp = tempfile.mkdtemp(prefix="sweep_rosy_")
    lock = threading.Lock()

    def work(item):
        mesh, run = item
        execute(smdf, mesh, run, tmp, args.timeout, env)
        with lock:
            print(run_line(mesh, run, width), flush=True)

    try:
        if args.jobs == 1:
            for item in all_runs:
                work(item)
        else:
            with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
                for f in [pool.submit(work, item) for item in all_runs]:
                    f.result()
    finally:
        shutil.rmtree(tmp, ignore_errors=True)

    lines = summary(all_runs, meshes, skipped, args)
    print("\n".join(lines), flush=True)
    if args.out:
        with open(args.out, "w") as f:
            for name, why in skipped:
                f.write("skip %s: %s\n" % (name, why))
            for mesh, run in all_runs:
                f.write(run_line(mesh, run, width) + "\n")
            f.write("\n".join(lines) + "\n")
    if not all_runs:
        print("no runs: every mesh was skipped", flush=True)
        return 1
    return 0 if all(r["ok"] for _, r in all_runs) else 1


if __name__ == "__main__":
    sys.exit(main())
