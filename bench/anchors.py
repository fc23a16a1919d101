#!/usr/bin/env python3
"""geodex beside the reference exact solvers, one run: Kirsanov's MMP (the Surazhsky et al. 2005
code) and VTP (Qin et al. 2016), built as command-line drivers by ../shared/anchors/build.sh.

  bench/anchors.py [--geodex BIN] [--anchors DIR] [--meshes DIR] [--big] [--reps N] [--only a,b]

Single vertex source v:0 on each mesh of the table in docs/benchmarks.md: propagation time (each
tool's own timer around the solve only; median of N runs, each in a fresh process) and the whole
process's peak memory (the largest over the runs, from wait4), and how far each reference is from
geodex (max |d - geodex| / the largest distance, over the vertices both reach). geodex runs
with two threads (`--threads 2`, the CLI's default on two cores; its distances are the same to
the bit with one), and once more with one for the column beside it; the references run on one
thread each, as they are written. Without
--anchors, or where a driver is missing or fails, its columns read "–" and nothing fails. Prints
a Markdown table; exit 2 only for bad usage or a geodex failure.
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

MESHES = ["fandisk.off", "armadillo.off", "bunny00.off", "refined_elephant.off", "icosphere-6"]
BIG = "dragon_vrip_welded.obj"  # ../shared/meshes; with --big


def icosphere(path, subdivisions):
    """An icosahedron with every face split in four `subdivisions` times, on the unit sphere."""
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
         (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    unit = lambda p: tuple(c / math.sqrt(sum(x * x for x in p)) for c in p)
    v = [unit(p) for p in v]
    for _ in range(subdivisions):
        mid = {}

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                mid[key] = len(v)
                v.append(unit(tuple((x + y) / 2 for x, y in zip(v[a], v[b]))))
            return mid[key]

        f = [g for a, b, c in f for g in ((a, m(a, b), m(c, a)), (b, m(b, c), m(a, b)),
                                           (c, m(c, a), m(b, c)), (m(a, b), m(b, c), m(c, a)))]
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(v), len(f)))
        out.writelines("%r %r %r\n" % p for p in v)
        out.writelines("3 %d %d %d\n" % t for t in f)


def run(cmd):
    """(exit code, stdout + stderr, peak RSS in MB) of one process."""
    with tempfile.TemporaryFile() as log:
        p = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(p.pid, 0)
        p.returncode = os.waitstatus_to_exitcode(status)
        log.seek(0)
        return p.returncode, log.read().decode(errors="replace"), usage.ru_maxrss / 1024.0


def distances(path):
    with open(path) as f:
        return [float(x) for x in f if x.strip()]


def geodex_run(binary, mesh, out, reps, threads):
    times, rss = [], 0.0
    for _ in range(reps):
        code, text, mb = run([binary, "distance", mesh, "--source", "v:0", "--stats", "--quiet", "--out", out,
                              "--threads", str(threads)])
        m = re.search(r"time:\s+[\d.]+ s load, ([\d.]+) s solve", text)
        if code != 0 or not m:
            sys.exit("geodex failed on %s: %s" % (mesh, text[-400:]))
        times.append(1000 * float(m.group(1)))
        rss = max(rss, mb)
    return statistics.median(times), rss


def reference_run(binary, mesh, out, reps):
    code, text, mb = run([binary, mesh, "v0", out, str(reps)])
    m = re.search(r"prop_ms=([\d.]+)", text)
    if code != 0 or not m:
        return None, mb, text.strip().splitlines()[-1:] or ["no output"]
    return float(m.group(1)), mb, None


def off_by(reference, ours):
    """Largest |reference - geodex| over the vertices both reach, over geodex's largest distance;
    and the vertices the two disagree on reaching (a reference that stops early leaves them at
    1e100, its 'unreachable': measured over the rest alone, its error would look small)."""
    reached = lambda y: 0 <= y < 1e99
    both = [(x, y) for x, y in zip(ours, reference) if math.isfinite(x) and reached(y)]
    largest = max((x for x, _ in both), default=0.0) or 1.0
    error = max((abs(x - y) for x, y in both), default=0.0) / largest
    disagree = sum(1 for x, y in zip(ours, reference) if math.isfinite(x) != reached(y))
    disagree += abs(len(ours) - len(reference))
    return "%.1e" % error + (", %d vertices reached by one only" % disagree if disagree else "")


def faces_of(mesh):
    with open(mesh, errors="replace") as f:
        if mesh.endswith(".obj"):
            return sum(1 for l in f if l.startswith("f "))
        lines = (l for l in f if l.strip() and not l.startswith("#"))
        head = next(lines).split()
        counts = head[1:] if len(head) > 1 else next(lines).split()
        return int(counts[1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--geodex", default="build/release/bin/geodex")
    ap.add_argument("--anchors", help="the folder ../shared/anchors/build.sh wrote (kirsanov, vtp)")
    ap.add_argument("--meshes", default="build/release/data/meshes")
    ap.add_argument("--shared-meshes", default="../shared/meshes")
    ap.add_argument("--big", action="store_true", help="also the 871K-face welded dragon")
    ap.add_argument("--only", help="comma-separated mesh names")
    ap.add_argument("--reps", type=int, default=3)
    a = ap.parse_args()
    if not os.access(a.geodex, os.X_OK):
        print("error: no geodex binary at %s" % a.geodex, file=sys.stderr)
        return 2
    refs = {}
    for name in ("kirsanov", "vtp"):
        path = os.path.join(a.anchors, name) if a.anchors else None
        refs[name] = path if path and os.access(path, os.X_OK) else None
        if a.anchors and not refs[name]:
            print("# no %s driver in %s: its columns stay empty" % (name, a.anchors), file=sys.stderr)
    names = MESHES + ([BIG] if a.big else [])
    if a.only:
        names = [n for n in names if n.split(".")[0] in a.only.split(",") or n in a.only.split(",")]
    work = tempfile.mkdtemp(prefix="geodex-anchors-")
    print("| mesh | faces | geodex ms | MB | 1 thread ms | Kirsanov ms | MB | VTP ms | MB | VTP / geodex "
          "| Kirsanov / geodex | geodex / VTP MB | Kirsanov off by | VTP off by |")
    print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    dash = "–"
    for name in names:
        if name == "icosphere-6":
            mesh = os.path.join(work, "icosphere-6.off")
            icosphere(mesh, 6)
        else:
            mesh = os.path.join(a.shared_meshes if name == BIG else a.meshes, name)
        if not os.path.isfile(mesh):
            print("# %s: not found, skipped" % mesh, file=sys.stderr)
            continue
        ours = os.path.join(work, "geodex.txt")
        g_ms, g_mb = geodex_run(a.geodex, mesh, ours, a.reps, 2)
        d = distances(ours)
        one_ms, _ = geodex_run(a.geodex, mesh, ours, a.reps, 1)
        if distances(ours) != d:
            sys.exit("geodex on one thread gave other distances than on two on %s" % mesh)
        cells = {}
        for ref, path in refs.items():
            if not path:
                cells[ref] = (None, None, dash)
                continue
            out = os.path.join(work, ref + ".txt")
            ms, mb, why = reference_run(path, mesh, out, a.reps)
            if ms is None:
                print("# %s failed on %s: %s" % (ref, name, why[0][:200]), file=sys.stderr)
                cells[ref] = (None, mb, "failed")
            else:
                cells[ref] = (ms, mb, off_by(distances(out), d))
        fmt = lambda x, p="%.0f": dash if x is None else p % x
        kms, kmb, koff = cells["kirsanov"]
        vms, vmb, voff = cells["vtp"]
        print("| %s | %d | %.0f | %.0f | %.0f | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name.rsplit(".", 1)[0], faces_of(mesh), g_ms, g_mb, one_ms, fmt(kms), fmt(kmb), fmt(vms), fmt(vmb),
            fmt(vms / g_ms if vms else None, "%.2f"), fmt(kms / g_ms if kms else None, "%.2f"),
            fmt(g_mb / vmb if vmb and vms else None, "%.2f"), koff, voff), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
