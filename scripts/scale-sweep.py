#!/usr/bin/env python3
"""One answer at every scale, checked on real meshes (docs/numerics.md).

For every mesh geodex accepts at unit scale (Debian's libcgal-demo by default), distances from v:0
with `geodex distance`, then for the mesh scaled by 2^k: accepted and every distance equal to the
unscaled one x 2^k bit for bit; scaled by 10^k: accepted and within 1e-12 of the largest distance.
Only the coordinates change: they are scaled exactly (2^k) or correctly rounded (10^k, in decimal)
and written with 17 significant digits, which round-trips. A scaled copy at 2^0 must reproduce the
original file's distances bit for bit, or the copy itself is wrong (reported as such).

  scripts/scale-sweep.py [--quick] [--geodex BIN] [--meshes DIR] [--mesh FILE ...]
                         [--pow2=K,K,...] [--pow10=K,K,...] [--jobs N]   (with "=": K may be negative)

Prints a line per mesh and a summary; exit 0 when every mesh passes, 1 when one fails, 2 for bad
usage, 77 when there are no meshes (CTest's skip).
"""
import argparse
import concurrent.futures
import math
import os
import subprocess
import sys
import tempfile
from decimal import Decimal, getcontext

getcontext().prec = 60  # exact enough to round 10^k x coordinate once, and to compare at 1e-250

POW2 = [-900, -600, -300, -100, 100, 300, 600, 900]
POW10 = [-250, -150, -100, -80, 80, 100, 150, 250]
QUICK_MESHES = ["elephant.off", "fandisk.off", "mushroom.off", "cross.off"]  # closed, CAD, boundary, small
QUICK_POW2 = [-900, 900]
QUICK_POW10 = [-250, 250]
RELATIVE_TOLERANCE = 1e-12  # of the largest distance, for 10^k (the input's rounding)


def read_mesh(path):
    """(vertices as lists of coordinate strings, face lines) of an ASCII OFF or PLY file."""
    with open(path, encoding="latin-1") as f:
        lines = [l.split("#")[0].strip() for l in f]
    lines = [l for l in lines if l]
    if lines[0].startswith("ply"):
        header_end = lines.index("end_header")
        nv = nf = 0
        vertex_props, element = [], None
        for l in lines[1:header_end]:
            t = l.split()
            if t[0] == "format" and t[1] != "ascii":
                raise ValueError("binary PLY is not supported here")
            if t[0] == "element":
                element = t[1]
                if element == "vertex":
                    nv = int(t[2])
                elif element == "face":
                    nf = int(t[2])
            elif t[0] == "property" and element == "vertex":
                vertex_props.append(t[-1])
        xyz = [vertex_props.index(c) for c in "xyz"]
        body = lines[header_end + 1:]
        vertices = [[body[i].split()[j] for j in xyz] for i in range(nv)]
        return vertices, body[nv:nv + nf]
    header = lines[0].split()
    if not header[0].endswith("OFF"):
        raise ValueError("not an OFF or PLY file")
    counts, rest = (header[1:], lines[1:]) if len(header) > 1 else (lines[1].split(), lines[2:])
    nv, nf = int(counts[0]), int(counts[1])
    vertices = [rest[i].split()[:3] for i in range(nv)]
    return vertices, rest[nv:nv + nf]


def scaled(text, base, k):
    x = float(text)
    if base == 2:
        return math.ldexp(x, k)  # exact while the result is a normal number
    return float(Decimal(x) * (Decimal(10) ** k))  # one correct rounding


def write_scaled(mesh, path, base, k):
    """Writes the scaled copy; False when a scaled coordinate is not a normal number (or zero):
    then the copy is not the same mesh, and 2^k promises nothing."""
    vertices, faces = mesh
    normal = True
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        for v in vertices:
            xs = [scaled(c, base, k) for c in v]
            normal = normal and all(x == 0.0 or (math.isfinite(x) and abs(x) >= sys.float_info.min) for x in xs)
            f.write(" ".join(repr(x) for x in xs) + "\n")
        for face in faces:
            f.write(face + "\n")
    return normal


def distances(geodex, path):
    r = subprocess.run([geodex, "distance", path, "--source", "v:0", "--quiet"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return r.returncode, r.stderr.strip().splitlines()[-1:] or [""]
    return 0, [float(x) for x in r.stdout.split()]


def sweep_one(geodex, path, pow2, pow10, work):
    name = os.path.basename(path)
    rc, base = distances(geodex, path)
    if rc != 0:
        return name, "refused", "at unit scale: " + base[0][:90], 0.0
    try:
        mesh = read_mesh(path)
    except (ValueError, IndexError) as e:
        return name, "FAIL", "cannot scale it here: %s" % e, 0.0
    copy = os.path.join(work, name + ".off")
    largest = max([d for d in base if math.isfinite(d)] or [0.0])
    failures, notNormal, worst = [], [], 0.0
    for b, ks in ((2, [0] + pow2), (10, pow10)):
        for k in ks:
            what = "2^%d" % k if b == 2 else "10^%d" % k
            if not write_scaled(mesh, copy, b, k) and b == 2:
                notNormal.append(what)
                continue
            rc, got = distances(geodex, copy)
            if rc != 0:
                failures.append("%s: exit %d %s" % (what, rc, got[0][:80]))
                continue
            if len(got) != len(base):
                failures.append("%s: %d lines for %d vertices" % (what, len(got), len(base)))
                continue
            if b == 2:
                bad = [v for v, (x, y) in enumerate(zip(base, got)) if y != math.ldexp(x, k)]
                if bad:
                    v = bad[0]
                    failures.append("%s%s: %d vertices not bit for bit, first %d: %r vs %r x 2^%d" % (
                        what, " (the copy itself)" if k == 0 else "", len(bad), v, got[v], base[v], k))
                continue
            scale = Decimal(10) ** k
            err = 0.0
            for x, y in zip(base, got):
                if math.isinf(x) or math.isinf(y):
                    if x != y:
                        err = math.inf
                    continue
                err = max(err, float(abs(Decimal(y) / scale - Decimal(x))))
            rel = err / largest if largest > 0 else err
            worst = max(worst, rel)
            if not rel <= RELATIVE_TOLERANCE:
                failures.append("%s: off by %.3g of the largest distance" % (what, rel))
    os.remove(copy)
    if failures:
        return name, "FAIL", "; ".join(failures)[:300], worst
    return name, "pass", ("not checked, coordinates not normal there: " + ", ".join(notNormal)) if notNormal else "", worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--geodex", default="build/release/bin/geodex")
    ap.add_argument("--meshes", default="build/release/data/meshes")
    ap.add_argument("--mesh", action="append", default=[], help="a mesh file (repeatable)")
    ap.add_argument("--quick", action="store_true", help="4 meshes, 2^±900 and 10^±250")
    ap.add_argument("--pow2", help="exponents k of 2^k, comma-separated")
    ap.add_argument("--pow10", help="exponents k of 10^k, comma-separated")
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    parse = lambda s: [int(x) for x in s.split(",") if x.strip()]
    try:
        pow2 = parse(a.pow2) if a.pow2 is not None else (QUICK_POW2 if a.quick else POW2)
        pow10 = parse(a.pow10) if a.pow10 is not None else (QUICK_POW10 if a.quick else POW10)
    except ValueError:
        print("error: --pow2 and --pow10 take comma-separated integers", file=sys.stderr)
        return 2
    if not (os.path.isfile(a.geodex) and os.access(a.geodex, os.X_OK)):
        print("error: no geodex binary at %s (build the release preset)" % a.geodex, file=sys.stderr)
        return 2
    if a.mesh:
        meshes = [m if os.path.isabs(m) or os.path.exists(m) else os.path.join(a.meshes, m) for m in a.mesh]
    elif a.quick:
        meshes = [os.path.join(a.meshes, m) for m in QUICK_MESHES]
    else:
        meshes = sorted(os.path.join(a.meshes, m) for m in (os.listdir(a.meshes) if os.path.isdir(a.meshes) else [])
                        if m.endswith((".off", ".ply")))
    meshes = [m for m in meshes if os.path.isfile(m)]
    if not meshes:
        print("no meshes (install libcgal-demo and re-run cmake, or name them with --mesh)", file=sys.stderr)
        return 77
    print("%-34s %-8s %10s  %s" % ("mesh", "verdict", "worst 10^k", "detail"))
    counts = {"pass": 0, "refused": 0, "FAIL": 0}
    with tempfile.TemporaryDirectory(prefix="geodex-scale-") as work, \
            concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        for name, verdict, detail, worst in pool.map(lambda m: sweep_one(a.geodex, m, pow2, pow10, work), meshes):
            counts[verdict] += 1
            print("%-34s %-8s %10.2g  %s" % (name, verdict, worst, detail), flush=True)
    print("%d meshes, %d scales each (2^k: %s; 10^k: %s): %d pass, %d refused at unit scale, %d fail" % (
        len(meshes), len(pow2) + len(pow10), ",".join(map(str, pow2)), ",".join(map(str, pow10)),
        counts["pass"], counts["refused"], counts["FAIL"]))
    return 1 if counts["FAIL"] else 0


if __name__ == "__main__":
    sys.exit(main())
