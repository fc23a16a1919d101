#!/usr/bin/env python3
"""Checks one finding directory of `geodex crosscheck` from outside: every file is there, the
picture is a PNG, the mesh is small, expected.txt is what `geodex distance` gives on mesh.off,
and the program, run again on mesh.off, still disagrees with it by more than the tolerance.

    check_finding.py GEODEX FINDING_DIR MAX_FACES TOLERANCE 'CMD'    (exit 0: all good)

CMD is the crosscheck command template; the program is rerun with {mesh}, {source} and {out}
pointing into a temporary directory.
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile


def fail(message):
    print(f"check_finding: {sys.argv[2]}: {message}", file=sys.stderr)
    sys.exit(1)


def values(path):
    out = []
    for line in open(path):
        x = float(line)
        out.append(math.inf if math.isnan(x) or x < 0 or x >= 1e99 else x)
    return out


def main():
    geodex, finding, max_faces, tolerance, template = sys.argv[1:6]
    for name in ("mesh.off", "original.off", "source.txt", "expected.txt", "got.txt", "report.txt", "picture.png"):
        if not os.path.isfile(os.path.join(finding, name)):
            fail(f"no {name}")
    with open(os.path.join(finding, "picture.png"), "rb") as f:
        if f.read(8) != b"\x89PNG\r\n\x1a\n":
            fail("picture.png is not a PNG")
    words = open(os.path.join(finding, "mesh.off")).read().split()
    faces = int(words[2])
    if faces > int(max_faces):
        fail(f"{faces} faces, more than {max_faces}")
    source = int(open(os.path.join(finding, "source.txt")).read())

    work = tempfile.mkdtemp()
    try:
        mesh = os.path.join(work, "mesh.off")
        shutil.copy(os.path.join(finding, "mesh.off"), mesh)
        truth = os.path.join(work, "geodex.txt")
        subprocess.run([geodex, "distance", mesh, "--source", f"v:{source}", "--out", truth, "--quiet"], check=True)
        expected = values(truth)
        if values(os.path.join(finding, "expected.txt")) != expected:
            fail("expected.txt is not what `geodex distance` gives on mesh.off")
        again = os.path.join(work, "again.txt")
        command = template.replace("{mesh}", mesh).replace("{source}", str(source)).replace("{out}", again)
        subprocess.run(command, shell=True, check=True)
        got = values(again)
    finally:
        shutil.rmtree(work)
    largest = max(x for x in expected if math.isfinite(x))
    worst = max(abs(g - e) if math.isfinite(g) and math.isfinite(e) else (0 if g == e else math.inf)
                for g, e in zip(got, expected))
    if len(got) == len(expected) and not worst > float(tolerance) * largest:
        fail(f"the program agrees with geodex on mesh.off (worst {worst}): not a reproducer")
    print(f"{finding}: {faces} faces, off by {worst} (largest distance {largest})")


main()
