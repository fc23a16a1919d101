#!/usr/bin/env python3
"""Checks .github/workflows: every file parses as YAML and is a workflow (a trigger and jobs with
steps); every ClusterFuzzLite step uses a mode and sanitizer the build supports; every fuzz target a
workflow names is one .clusterfuzzlite/build.sh builds, and build.sh builds every target
fuzz/CMakeLists.txt defines (a new target would otherwise never be fuzzed in CI); the test job runs
./test.sh. Prints one line per problem and exits 1 if there is any.

    check_workflows.py [REPO]      (default: the checkout this script is in)
"""
import pathlib
import re
import sys

import yaml

CFLITE = "google/clusterfuzzlite/actions/"
MODES = {"code-change", "batch", "prune", "coverage"}
# build.sh's CXXFLAGS hold ASan + UBSan: those two, and coverage for the report.
SANITIZERS = {"address", "undefined", "coverage"}


def targets_in(text, pattern):
    return set(re.findall(pattern, text, re.M))


def main():
    repo = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
    problems = []
    build_sh = (repo / ".clusterfuzzlite/build.sh").read_text()
    m = re.search(r"^TARGETS=\(([^)]*)\)", build_sh, re.M)
    built = set(m.group(1).split()) if m else set()
    if not built:
        problems.append(".clusterfuzzlite/build.sh: no TARGETS=(...) line")
    defined = targets_in((repo / "fuzz/CMakeLists.txt").read_text(), r"^add_fuzzer\((\w+)\)")
    for t in sorted(defined - built):
        problems.append(f".clusterfuzzlite/build.sh does not build {t} (fuzz/CMakeLists.txt defines it)")
    for t in sorted(built - defined):
        problems.append(f".clusterfuzzlite/build.sh builds {t}, which fuzz/CMakeLists.txt does not define")

    workflows = sorted((repo / ".github/workflows").glob("*.y*ml"))
    if not workflows:
        problems.append(".github/workflows: no workflow files")
    runs_test_sh = False
    uses_modes = set()
    for path in workflows:
        name = path.relative_to(repo)
        try:
            doc = yaml.safe_load(path.read_text())
        except yaml.YAMLError as e:
            problems.append(f"{name}: not YAML: {e}")
            continue
        # YAML 1.1 reads the key `on` as True.
        if not isinstance(doc, dict) or not (doc.get("on") or doc.get(True)):
            problems.append(f"{name}: no trigger ('on')")
            continue
        jobs = doc.get("jobs")
        if not isinstance(jobs, dict) or not jobs:
            problems.append(f"{name}: no jobs")
            continue
        for t in sorted(targets_in(path.read_text(), r"\bfuzz_[a-z_]+\b") - built):
            problems.append(f"{name}: names {t}, which .clusterfuzzlite/build.sh does not build")
        for job_name, job in jobs.items():
            steps = job.get("steps") if isinstance(job, dict) else None
            if not isinstance(steps, list) or not steps:
                problems.append(f"{name}: job {job_name} has no steps")
                continue
            matrix = ((job.get("strategy") or {}).get("matrix") or {}).get("sanitizer", [])
            for s in matrix:
                if s not in SANITIZERS:
                    problems.append(f"{name}: job {job_name}: sanitizer '{s}' is not one build.sh supports")
            for step in steps:
                if "./test.sh" in str(step.get("run", "")):
                    runs_test_sh = True
                uses = str(step.get("uses", ""))
                if not uses.startswith(CFLITE):
                    continue
                args = step.get("with") or {}
                sanitizer = str(args.get("sanitizer", "address"))
                if "${{" not in sanitizer and sanitizer not in SANITIZERS:
                    problems.append(f"{name}: job {job_name}: sanitizer '{sanitizer}' is not one build.sh supports")
                if uses.startswith(CFLITE + "build_fuzzers") and args.get("language") != "c++":
                    problems.append(f"{name}: job {job_name}: build_fuzzers without language: c++")
                if uses.startswith(CFLITE + "run_fuzzers"):
                    mode = args.get("mode")
                    if mode not in MODES:
                        problems.append(f"{name}: job {job_name}: mode '{mode}' is not one of {sorted(MODES)}")
                    uses_modes.add(mode)
    if workflows and not runs_test_sh:
        problems.append(".github/workflows: no job runs ./test.sh")
    for mode in ("code-change", "batch", "prune"):
        if workflows and mode not in uses_modes:
            problems.append(f".github/workflows: no ClusterFuzzLite job in '{mode}' mode")

    for p in problems:
        print(p)
    print(f"{len(workflows)} workflows, {len(built)} fuzz targets built: "
          f"{'ok' if not problems else str(len(problems)) + ' problem(s)'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
