#!/usr/bin/env python3
"""Mutation testing: plant one bug at a time in solver/ and verify/, rebuild, and see which test
catches it. Not part of ./test.sh; it runs in its own git worktree and never touches the checkout.

  scripts/mutate.sh [--list] [--only ID,...] [--max N] [--seed S] [--worktree DIR]
                    [--results FILE] [--report FILE] [--no-debug] [--commit REV]
                    [--tests-patch FILE]

The mutants are made by operators that look like real geometry bugs, at sites found in the
source (a fixed, seeded choice, so a run is reproducible and can be resumed):

  flip-comparison     < <-> <=, > <-> >=            (a tie or a boundary decided the other way)
  negate-condition    if (C) -> if (!(C))
  and-or              && <-> ||
  drop-statement      a statement that assigns, counts or calls, removed
  swap-mirrored       the two arms of a ternary whose arms are mirror images (b0/b1, v0/v2, G2/G3,
                      prev/next, front/back, ...) exchanged
  tolerance-x1000     a tolerance of tolerance.h made 1000x larger, and 1000x smaller
  swap-subtraction    a - b -> b - a
  end-to-edge-end     a computed end (b0 = ..., b1 = ...) replaced with the edge's end

Each mutant is built with the release preset and tested in order of cost, stopping at the first
failure: the unit tests, the properties (CI's seed), then the rest of the release ctest (the
corpus replay and every other test but those two, already run); each stage builds only what it
runs; a stage that only ran out of time runs once more (a test starved past its limit by other jobs
is no kill; a mutant that hangs runs out of time again). A mutant the release tests miss is built
and tested with the debug preset (checks on). A
mutant that does not compile is reported as such and left out of the score (a mutant the unit
tests kill is not built further: its other targets link the same solver library).

Results go to FILE (default build/mutation/results.jsonl, one JSON object per mutant, reused: a
mutant already there with the same source line is not run again), the report to
docs/mutation.md (every mutant, its verdict and the test that killed it). A survivor argued
equivalent (no input can tell it from the original) is listed in scripts/mutation-equivalents.json
by its hash with the evidence; the report shows it as equivalent and leaves it out of the score.
A survivor that was a better program than the original (it changed an output for the better, no
test could ask for the original's worse one, and the code was changed to do what it does) is
listed in scripts/mutation-adopted.json with the commit that adopted it; the report shows it as
adopted and leaves it out of the score too.
"""

import argparse
import hashlib
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLVER_FILES = ["solver/src/%s" % f for f in (
    "edge_intervals.cpp", "geodesic_solver.cpp", "propagate.cpp", "path.cpp", "surface_point.cpp",
    "mesh.cpp", "interval_pool.cpp")] + [
    "solver/include/geodex/edge_intervals.h", "solver/include/geodex/interval.h",
    "solver/include/geodex/predicates.h", "solver/include/geodex/bucket_queue.h"]
TOLERANCE_FILE = "solver/include/geodex/tolerance.h"
VERIFY_FILES = ["verify/src/%s" % f for f in ("invariant_checker.cpp", "oracles.cpp", "exact_predicates.cpp")]

MIRRORED_PAIRS = [("b0", "b1"), ("v0", "v2"), ("G2", "G3"), ("G4", "G5"), ("prev", "next"),
                  ("front", "back"), ("Left", "Right"), ("Start", "End"), ("edgeToV0", "edgeToV2"),
                  ("first", "last"), ("lo", "hi"), ("onE1", "onE2"), ("e1", "e2")]
DECLARATION = re.compile(r"^\s*(const |constexpr |static |auto |double |float |bool |int |std::|Index |"
                         r"Interval |Vec2 |Vec3 |return |using |template|typedef|case |default:)")


def code_part(line):
    """The line without its // comment (strings in this code base hold no //)."""
    return line.split("//", 1)[0]


def matching_paren(code, open_at):
    """The index of the ')' closing the '(' at open_at, or None when it is not on this line."""
    depth = 0
    for i in range(open_at, len(code)):
        depth += {"(": 1, ")": -1}.get(code[i], 0)
        if depth == 0:
            return i
    return None


def sites(path, text):
    """(line number, operator, original line, mutated line) for every candidate site in a file."""
    out = []
    in_block_comment = False
    for n, line in enumerate(text.split("\n"), start=1):
        stripped = line.strip()
        if in_block_comment:
            in_block_comment = "*/" not in stripped
            continue
        if stripped.startswith("/*"):
            in_block_comment = "*/" not in stripped
            continue
        if (not stripped or stripped.startswith(("//", "#", "///")) or "GEODEX_CHECK" in line
                or "GEODEX_REQUIRE" in line or "<<" in line or "static_assert" in line):
            continue
        code = code_part(line)
        rest = line[len(code):]
        for m in re.finditer(r"(?<=\s)(<=|>=|<|>)(?=\s)", code):
            op = m.group(1)
            flipped = {"<": "<=", "<=": "<", ">": ">=", ">=": ">"}[op]
            out.append((n, "flip-comparison", line, code[:m.start()] + flipped + code[m.end():] + rest))
        for m in re.finditer(r"(?<=\s)(&&|\|\|)(?=\s)", code):
            other = "||" if m.group(1) == "&&" else "&&"
            out.append((n, "and-or", line, code[:m.start()] + other + code[m.end():] + rest))
        m = re.match(r"^\s*(?:\} else )?if \(", code)
        if m and "constexpr" not in code:
            close = matching_paren(code, m.end() - 1)
            if close is not None:
                out.append((n, "negate-condition", line,
                            code[:m.end()] + "!(" + code[m.end():close] + ")" + code[close:] + rest))
        if (code.rstrip().endswith(";") and not DECLARATION.match(code) and code.count("(") == code.count(")")
                and re.match(r"^\s*(\+\+|--|[A-Za-z_][\w.\->\[\]]*\s*(=|\+=|-=|\*=|\(|\+\+|--))", code)
                and not re.match(r"^\s*\w+\s+\w+\s*=", code)):
            indent = re.match(r"^\s*", line).group(0)
            out.append((n, "drop-statement", line, indent + "; // (dropped)"))
        if "?" in code and ":" in code:
            for a, b in MIRRORED_PAIRS:
                pat = re.compile(r"\?\s*([^:?]*\b%s\b[^:?]*?)\s*:\s*([^;:?)]*\b%s\b[^;:?)]*)" % (a, b))
                mm = pat.search(code) or re.compile(
                    r"\?\s*([^:?]*\b%s\b[^:?]*?)\s*:\s*([^;:?)]*\b%s\b[^;:?)]*)" % (b, a)).search(code)
                if mm:
                    swapped = code[:mm.start()] + "? " + mm.group(2).strip() + " : " + mm.group(1).strip() + code[mm.end():]
                    out.append((n, "swap-mirrored", line, swapped + rest))
                    break
        for m in re.finditer(r"\b([A-Za-z_][\w.]*(?:\(\))?|\w+\[\w+\])\s-\s([A-Za-z_][\w.]*(?:\(\))?)(?=[\s;,)])", code):
            if m.group(1) == m.group(2):
                continue
            out.append((n, "swap-subtraction", line,
                        code[:m.start()] + m.group(2) + " - " + m.group(1) + code[m.end():] + rest))
        m = re.match(r"^(\s*[\w.\->]*\bb([01])\s*=\s*)([^;=]+);\s*$", code)
        if m and "edgeLength" in text and m.group(3).strip() not in ("0.0", "edgeLength"):
            end = "0.0" if m.group(2) == "0" else "edgeLength"
            out.append((n, "end-to-edge-end", line, m.group(1) + end + ";" + rest))
    return out


def tolerance_sites(text):
    out = []
    for n, line in enumerate(text.split("\n"), start=1):
        m = re.match(r"^(inline constexpr double k\w+ = )(.+);(.*)$", line)
        if not m:
            continue
        for factor in ("1e3", "1e-3"):
            out.append((n, "tolerance-x1000", line, "%s(%s) * %s;%s" % (m.group(1), m.group(2), factor, m.group(3))))
    return out


def source_at(rev, path):
    """A file's text at a commit. The mutants are planted in a worktree of HEAD, so the sites are
    found in HEAD's text too, never in the checkout's (which may hold someone's unfinished edits:
    other lines, another sample, and mutants whose line the worktree does not have)."""
    return subprocess.run(["git", "show", "%s:%s" % (rev, path)], cwd=ROOT, stdout=subprocess.PIPE, text=True,
                          check=True).stdout


def changed_lines(since, rev, path):
    """The line numbers of path at rev that are new or changed since the commit `since`."""
    diff = subprocess.run(["git", "diff", "-U0", since, rev, "--", path], cwd=ROOT, stdout=subprocess.PIPE,
                          text=True, check=True).stdout
    lines = set()
    for m in re.finditer(r"^@@ -\S+ \+(\d+)(?:,(\d+))? @@", diff, re.M):
        start, count = int(m.group(1)), int(m.group(2) or "1")
        lines.update(range(start, start + count))
    return lines


# A supplement (--changed-since) plants this share of the sites on changed lines of each file (at
# least one a file that has any), and every tolerance mutant of a changed tolerance line; the
# files include the interval pool's header, whose code moved there after the first run.
SUPPLEMENT_SHARE = 0.03
SUPPLEMENT_EXTRA_FILES = ["solver/include/geodex/interval_pool.h"]


def catalogue(seed, rev, since=None):
    """Every mutant of this run (sites in the commit rev): all tolerance mutants, a seeded sample
    of the other sites. With `since`, only sites on lines changed since that commit (a supplement
    to a run on it: the code written after it)."""
    rng = random.Random(seed)
    mutants = []

    def add(path, found, count):
        if since is not None:
            changed = changed_lines(since, rev, path)
            found = [s for s in found if s[0] in changed]
            if path != TOLERANCE_FILE:
                count = max(1, round(SUPPLEMENT_SHARE * len(found))) if found else 0
        by_operator = {}
        for s in found:
            by_operator.setdefault(s[1], []).append(s)
        chosen = []
        # Round-robin over the operators so that every kind of bug is planted in every file.
        pools = {k: rng.sample(v, len(v)) for k, v in sorted(by_operator.items())}
        while len(chosen) < count and any(pools.values()):
            for k in sorted(pools):
                if pools[k] and len(chosen) < count:
                    chosen.append(pools[k].pop())
        for n, op, before, after in sorted(chosen):
            digest = hashlib.sha1((path + before + after).encode()).hexdigest()[:8]
            mutants.append({"id": "%s:%d:%s:%s" % (os.path.basename(path), n, op, digest), "file": path,
                            "line": n, "operator": op, "before": before, "after": after})

    quota = {"solver/src/edge_intervals.cpp": 24, "solver/src/geodesic_solver.cpp": 14,
             "solver/src/propagate.cpp": 16, "solver/src/path.cpp": 5, "solver/src/surface_point.cpp": 3,
             "solver/src/mesh.cpp": 4, "solver/src/interval_pool.cpp": 2,
             "solver/include/geodex/edge_intervals.h": 6, "solver/include/geodex/interval.h": 3,
             "solver/include/geodex/predicates.h": 3, "solver/include/geodex/bucket_queue.h": 2,
             "verify/src/invariant_checker.cpp": 12, "verify/src/oracles.cpp": 6,
             "verify/src/exact_predicates.cpp": 4}
    for path in SOLVER_FILES + VERIFY_FILES + (SUPPLEMENT_EXTRA_FILES if since is not None else []):
        add(path, sites(path, source_at(rev, path)), quota.get(path, 2))
    tol = tolerance_sites(source_at(rev, TOLERANCE_FILE))
    add(TOLERANCE_FILE, tol, len(tol))
    return mutants


def run(cmd, cwd, timeout, log):
    """(exit code, output); 124 on a timeout."""
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                           text=True, errors="replace")
        out = p.stdout
        code = p.returncode
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        code = 124
    with open(log, "a") as f:
        f.write("$ %s\n%s\n" % (" ".join(cmd), out[-20000:]))
    return code, out


def first_failure(output):
    """The name of the first failing test in gtest or ctest output, or "?"."""
    m = re.search(r"^\[  FAILED  \] (\S+) \(", output, re.M)
    if m:
        return m.group(1)
    # CTest's summary: "  12 - name (Failed)", "(Subprocess aborted)", "(SEGFAULT)", "(Timeout)", ...
    # (the alternatives grouped: an ungrouped "(Failed|Timeout" made "Timeout" alone a match, with
    # no name in it).
    m = re.search(r"^\s*\d+ - (\S+) \((?:Failed|Timeout|Subprocess aborted|SEGFAULT|ILLEGAL|NUMERICAL|"
                  r"BUS_ERROR|INTERRUPT|OTHER_FAULT|CHILDKILLED|Not Run|Exception)[^)]*\)", output, re.M)
    if m:
        return m.group(1)
    m = re.search(r"^\[  FAILED  \] (\S+)", output, re.M)
    if m:
        return m.group(1)
    return "?"


def only_timeouts(output):
    """Whether every test CTest's summary lists as failed ran out of time (and some did)."""
    failed = re.findall(r"^\s*\d+ - \S+ \(([^)]*)\)", output, re.M)
    return bool(failed) and all(status.startswith("Timeout") for status in failed)


def unfinished_test(output):
    """The gtest test that started and never ended: a crash (a floating-point trap in the debug
    build, an abort) kills the binary before it prints [  FAILED  ]. Needs the output without
    --gtest_brief, where every test's [ RUN      ] line is printed and flushed before it runs."""
    started = re.findall(r"^\[ RUN      \] (\S+)", output, re.M)
    ended = set(re.findall(r"^\[ +(?:OK|FAILED|SKIPPED) +\] (\S+) \(", output, re.M))
    for name in reversed(started):
        if name not in ended:
            return name
    return None


def signal_name(code):
    """ "SIGFPE" for an exit code of -8 (subprocess's way of saying killed by a signal), else None."""
    if code >= 0:
        return None
    try:
        return signal.Signals(-code).name
    except ValueError:
        return "signal %d" % -code


def known_bugs(work):
    """The properties on tests/property/CMakeLists.txt's GEODEX_KNOWN_BUGS list: they fail on the
    unmutated source too, so the property stage leaves them out, as CTest's `property` test does
    (CTest runs each as known-bug.NAME, expected to fail: a mutant that makes one pass is seen
    there)."""
    with open(os.path.join(work, "tests", "property", "CMakeLists.txt")) as f:
        m = re.search(r"^set\(GEODEX_KNOWN_BUGS([^)]*)\)", f.read(), re.M)
    return re.findall(r'"([^"]+)"', m.group(1)) if m else []


def test_preset(work, preset, log):
    """(killed?, by what) for the current source in the worktree, built stage by stage; (None, "")
    when it does not compile."""
    bindir = os.path.join(work, "build", preset, "bin")
    known = known_bugs(work)
    # Each stage builds only what it runs (its test binary; everything for the last), so that a
    # mutant the unit tests kill costs one library and one test binary, not the CLI, the bench,
    # the Python module and the oracles: for a tolerance of tolerance.h, included by 41 files,
    # that is most of a full rebuild saved.
    stages = [
        ("unit", [os.path.join(bindir, "geodex_unit_tests"), "--gtest_brief=1"], 120),
        ("property", [os.path.join(bindir, "geodex_property_tests"), "--gtest_brief=1"] +
         (["--gtest_filter=-" + ":".join(known)] if known else []), 1200),
        # The rest of ctest (the corpus replay, CLI, scale, ...): not the unit tests and the
        # properties again, which the two stages above have just run (the same binaries, the
        # same seed, the coverage gate judging); the properties alone are 40 s in release and
        # 160 s in debug, the longest part of a survivor's run.
        ("ctest", ["ctest", "--preset", preset, "-j2", "--timeout", "600", "--stop-on-failure",
                   "-LE", "^unit$", "-E", "^property$"], 3600),
    ]
    env_rc = os.environ.get("RC_PARAMS")
    os.environ["RC_PARAMS"] = "seed=12345 max_success=200 noshrink=1"
    try:
        for name, cmd, timeout in stages:
            target = os.path.basename(cmd[0]) if name != "ctest" else None
            if not build(work, preset, log, target) and (target is None or not build(work, preset, log)):
                # (A target the preset does not define fails to build on its own; the whole
                # preset building then says the source compiles and the stage is skipped.)
                return None, ""
            if not os.path.exists(cmd[0]) and name != "ctest":
                continue
            # A stage that only ran out of time is run once more: on a machine shared with other
            # jobs a test can be starved past its limit (the crosscheck cases of edf2df04's debug
            # run, 300 s each beside three fuzzing campaigns, "killed" it). A mutant that hangs
            # runs out of time again.
            for attempt in (1, 2):
                code, out = run(cmd, work, timeout, log)
                if attempt == 1 and (code == 124 or (code != 0 and name == "ctest" and only_timeouts(out))):
                    with open(log, "a") as f:
                        f.write("[%s (%s) ran out of time: once more]\n" % (preset, name))
                    continue
                break
            if code == 124:
                return True, "%s (%s): timeout" % (preset, name)
            if code != 0:
                by = first_failure(out)
                if by == "?" and name != "ctest":
                    # The binary died without naming a test (with --gtest_brief only failures are
                    # printed, and a trap or abort leaves nothing): run it again unbriefed, where
                    # the last test started and never ended is the one that killed it.
                    code2, out2 = run([c for c in cmd if c != "--gtest_brief=1"], work, timeout, log)
                    crashed = unfinished_test(out2)
                    how = signal_name(code2) or signal_name(code)
                    if crashed:
                        by = "%s (%s)" % (crashed, how) if how else crashed
                    else:
                        by = first_failure(out2)
                # (A signal after a test already failed belongs to a later test: the failed one is
                # named, as the first failure.)
                return True, "%s: %s" % (preset, by)
        return False, ""
    finally:
        if env_rc is None:
            del os.environ["RC_PARAMS"]
        else:
            os.environ["RC_PARAMS"] = env_rc


def build(work, preset, log, target=None):
    code, _ = run(["cmake", "--build", "--preset", preset, "-j2"] + (["--target", target] if target else []),
                  work, 3600, log)
    return code == 0


def plant(work, m):
    """Writes mutant m into the checkout at work; False when its source line has changed."""
    path = os.path.join(work, m["file"])
    with open(path) as f:
        lines = f.read().split("\n")
    if lines[m["line"] - 1] != m["before"]:
        return False
    lines[m["line"] - 1] = m["after"]
    with open(path, "w") as f:
        f.write("\n".join(lines))
    return True


def mutate_one(work, m, presets, log):
    if not plant(work, m):
        return {"verdict": "stale", "by": "the source line changed"}
    try:
        for preset in presets:
            killed, by = test_preset(work, preset, log)
            if killed is None:
                return {"verdict": "did not compile", "by": ""}
            if killed:
                return {"verdict": "killed", "by": by}
        return {"verdict": "survived", "by": ""}
    finally:
        subprocess.run(["git", "checkout", "--", m["file"]], cwd=work, check=True)


def load_equivalents(path):
    """Mutant hash -> the evidence that it cannot change any output (scripts/mutation-equivalents.json),
    or, read from scripts/mutation-adopted.json, the commit that adopted it and why."""
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return json.load(f)


def report(mutants, results, path, seed, equivalents, adopted, commit, since=None):
    rows = []
    counts = {}
    for m in mutants:
        r = results.get(m["id"])
        verdict = r["verdict"] if r else "not run"
        evidence = equivalents.get(m["id"].rsplit(":", 1)[1])
        if verdict == "survived" and evidence:
            verdict = "equivalent"
            r = dict(r, by=evidence)
        adoption = adopted.get(m["id"].rsplit(":", 1)[1])
        if verdict == "survived" and adoption:
            verdict = "adopted"
            r = dict(r, by=adoption)
        counts[verdict] = counts.get(verdict, 0) + 1
        change = "`%s` → `%s`" % (code_part(m["before"]).strip()[:70], code_part(m["after"]).strip()[:70])
        by = (r or {}).get("by", "")
        if (r or {}).get("tests") == "patch" and verdict == "killed":
            by += " (a new test, in --tests-patch: not in %s)" % (r or {}).get("commit", "")[:7]
        rows.append("| %s | %s:%d | %s | %s | %s | %s |" % (
            m["id"].rsplit(":", 1)[1], m["file"], m["line"], m["operator"], change.replace("|", "\\|"),
            verdict, by.replace("|", "\\|")))
    scored = counts.get("killed", 0) + counts.get("survived", 0)
    with open(path, "w") as f:
        f.write("# Mutation testing\n\n")
        if since is None:
            made = "Made by `scripts/mutate.sh --seed %d --commit %s` (scripts/mutate.py says how): the mutants " \
                   "of commit %s." % (seed, commit[:7], commit[:7])
        else:
            made = "Made by `scripts/mutate.sh --seed %d --commit %s --changed-since %s` (scripts/mutate.py says " \
                   "how): a supplement to the run on %s, its mutants only on the lines of commit %s that are new " \
                   "or changed since %s." % (seed, commit[:7], since, since, commit[:7], since)
        f.write(made + " One planted bug at a time, "
                "in its own git worktree: built with the release preset and tested (unit tests, properties with "
                "CI's seed, then the rest of the release ctest with the corpus replay), and when those miss it, with the "
                "debug preset (checks on).\n\n")
        f.write("Killed %d of %d scored mutants (%.1f %%); %d argued equivalent "
                "(scripts/mutation-equivalents.json: the evidence is in the last column); %d adopted (a better "
                "program than the original, which was changed to do what it does: "
                "scripts/mutation-adopted.json); %d did not compile; %d not run yet.\n\n" % (
                    counts.get("killed", 0), scored, 100.0 * counts.get("killed", 0) / scored if scored else 0.0,
                    counts.get("equivalent", 0), counts.get("adopted", 0), counts.get("did not compile", 0),
                    counts.get("not run", 0)))
        f.write("| id | where | operator | change | verdict | killed by |\n|---|---|---|---|---|---|\n")
        f.write("\n".join(rows) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--list", action="store_true", help="print the catalogue and stop")
    ap.add_argument("--only", help="comma-separated mutant ids (the hash part is enough)")
    ap.add_argument("--max", type=int, help="run at most this many mutants not run before")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--worktree", default=os.path.join(os.environ.get("TMPDIR", "/tmp"), "geodex-mutate"))
    ap.add_argument("--results", default=os.path.join(ROOT, "build", "mutation", "results.jsonl"))
    ap.add_argument("--report", default=os.path.join(ROOT, "docs", "mutation.md"))
    ap.add_argument("--no-debug", action="store_true", help="release tests only")
    ap.add_argument("--tests-patch", metavar="FILE",
                    help="apply this patch to the commit's tests/ first (new tests not committed yet, "
                         "from `git diff HEAD -- tests`)")
    ap.add_argument("--commit", default="HEAD",
                    help="the commit whose source is mutated (default HEAD): a run resumed in several "
                         "invocations names the one it started on, so that commits made meanwhile do "
                         "not change its catalogue")
    ap.add_argument("--changed-since", metavar="REV",
                    help="a supplement to a run on REV: only sites on lines changed between REV and "
                         "the commit (SUPPLEMENT_SHARE of them a file, every changed tolerance)")
    a = ap.parse_args()
    # `kill -TERM` stops a run cleanly: the mutant being tested is put back in the worktree (the
    # finally of mutate_one) and left out of the results, to be run next time.
    signal.signal(signal.SIGTERM, lambda signum, frame: sys.exit("stopped by SIGTERM"))

    head = subprocess.run(["git", "rev-parse", a.commit], cwd=ROOT, stdout=subprocess.PIPE, text=True,
                          check=True).stdout.strip()
    mutants = catalogue(a.seed, head, a.changed_since)
    if a.list:
        for m in mutants:
            print("%s\n  - %s\n  + %s" % (m["id"], m["before"].strip(), m["after"].strip()))
        solver = sum(1 for m in mutants if m["file"].startswith("solver/"))
        print("%d mutants: %d over solver/, %d over verify/" % (len(mutants), solver, len(mutants) - solver))
        return 0
    if a.only:
        wanted = set(a.only.split(","))
        mutants = [m for m in mutants if m["id"] in wanted or m["id"].rsplit(":", 1)[1] in wanted]

    results = {}
    if os.path.exists(a.results):
        with open(a.results) as f:
            for line in f:
                r = json.loads(line)
                results[r["id"]] = r
    todo = [m for m in mutants if m["id"] not in results]
    if a.max is not None:
        todo = todo[:a.max]

    if todo:
        if not os.path.isdir(a.worktree):
            subprocess.run(["git", "worktree", "add", "--detach", a.worktree, head], cwd=ROOT, check=True)
        # A worktree a run with --tests-patch left has those tests changed: put them back first,
        # or the checkout of another commit refuses to overwrite them.
        subprocess.run(["git", "checkout", "--", "tests"], cwd=a.worktree, check=True)
        subprocess.run(["git", "clean", "-fdq", "--", "tests"], cwd=a.worktree, check=True)
        subprocess.run(["git", "checkout", "--detach", head], cwd=a.worktree, check=True)
        # The worktree's tests are the commit's, plus a patch when one is given (tests written for
        # survivors and not committed yet: `git diff HEAD -- tests`; the mutant is then re-run
        # against them). Not the checkout's tests/ as it is: tests committed after the commit may
        # test what the commit does not have yet, and would fail with or without the mutant.
        subprocess.run(["git", "checkout", head, "--", "tests"], cwd=a.worktree, check=True)
        subprocess.run(["git", "clean", "-fdq", "--", "tests"], cwd=a.worktree, check=True)
        if a.tests_patch:
            with open(a.tests_patch) as f:
                subprocess.run(["patch", "-p1", "-F3", "--no-backup-if-mismatch", "-s"], cwd=a.worktree,
                               stdin=f, check=True)
        shared = os.path.join(os.path.dirname(a.worktree), "shared")
        if not os.path.exists(shared) and os.path.isdir(os.path.join(os.path.dirname(ROOT), "shared")):
            os.symlink(os.path.join(os.path.dirname(ROOT), "shared"), shared)
        presets = ["release"] if a.no_debug else ["release", "debug"]
        for preset in presets:
            subprocess.run(["cmake", "--preset", preset], cwd=a.worktree, check=True, stdout=subprocess.DEVNULL)
            if not build(a.worktree, preset, os.devnull):
                sys.exit("the unmutated source does not build with the %s preset" % preset)
        os.makedirs(os.path.dirname(a.results), exist_ok=True)
        # The log stays in the build tree whatever the results file is (a results file kept under
        # docs/ to resume a run on another machine must not leave the build output beside it).
        log = os.path.join(ROOT, "build", "mutation", "log.txt")
        os.makedirs(os.path.dirname(log), exist_ok=True)
        for i, m in enumerate(todo, start=1):
            start = time.time()
            sys.stderr.write("[%d/%d] %s ... " % (i, len(todo), m["id"]))
            sys.stderr.flush()
            with open(log, "a") as f:
                f.write("\n=== %s\n- %s\n+ %s\n" % (m["id"], m["before"], m["after"]))
            r = mutate_one(a.worktree, m, presets, log)
            r.update({"id": m["id"], "seconds": round(time.time() - start, 1), "commit": head})
            if a.tests_patch:
                r["tests"] = "patch"
            results[m["id"]] = r
            with open(a.results, "a") as f:
                f.write(json.dumps(r) + "\n")
            sys.stderr.write("%s %s (%.0f s)\n" % (r["verdict"], r["by"], r["seconds"]))
    equivalents = load_equivalents(os.path.join(ROOT, "scripts", "mutation-equivalents.json"))
    adopted = load_equivalents(os.path.join(ROOT, "scripts", "mutation-adopted.json"))
    report(catalogue(a.seed, head, a.changed_since), results, a.report, a.seed, equivalents, adopted, head,
           a.changed_since)
    survived = [m["id"] for m in catalogue(a.seed, head, a.changed_since) if results.get(m["id"], {}).get("verdict") == "survived"
                and m["id"].rsplit(":", 1)[1] not in equivalents and m["id"].rsplit(":", 1)[1] not in adopted]
    print("report: %s; survivors: %s" % (a.report, ", ".join(survived) or "none"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
