#!/bin/bash
# Evidence for a surviving mutant: the release CLI of a commit with the mutant planted against the
# same CLI without it, byte for byte, on
#   - every fuzz_solver input of corpus/ (seed, regress) and of the fuzzing work corpus
#     (build/fuzz-work/fuzz_solver/corpus) that `geodex repro` describes as an OFF mesh and
#     sources: the distances, and the path to the last vertex;
#   - the meshes of build/release/data/meshes (libcgal-demo) and tests/data/regression: distances
#     from v:0 and from the centroid of face 0, paths from v:0 to the last vertex, the middle
#     vertex and the centroid of the middle face.
# Prints each output that differs and a count. Runs in its own worktree (default
# /tmp/geodex-compare, created at REV) and never touches the checkout.
#   scripts/mutation-evidence/compare_cli.sh REV MUTANT_HASH [WORKTREE]
set -euo pipefail
REV=$1 HASH=$2 W=${3:-/tmp/geodex-compare}
MAIN=$(cd "$(dirname "$0")/../.." && pwd)
OUT=$W/compare-$(git -C "$MAIN" rev-parse --short "$REV")
[ -d "$W" ] || git -C "$MAIN" worktree add --detach "$W" "$REV" -q
cd "$W"
git checkout -q --detach "$REV" && git checkout -q -- .
[ -d build/release ] || cmake --preset release > /dev/null
cmake --build --preset release --target geodex_cli -j2 > /dev/null
mkdir -p "$OUT/cases" && cp build/release/bin/geodex "$OUT/geodex-base"
BASE=$OUT/geodex-base

# The corpus inputs as OFF files and source arguments.
python3 - "$BASE" "$MAIN" "$OUT/cases" <<'PY'
import hashlib, os, subprocess, sys
geodex, main, out = sys.argv[1:]
dirs = [f"{main}/corpus/fuzz_solver/seed", f"{main}/corpus/fuzz_solver/regress",
        f"{main}/build/fuzz-work/fuzz_solver/corpus"]
for d in filter(os.path.isdir, dirs):
    for f in sorted(os.listdir(d)):
        if f.startswith("open-"):
            continue  # known open bugs: their checks fail, not the CLI
        r = subprocess.run([geodex, "repro", os.path.join(d, f), "--target", "fuzz_solver"],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
        lines = r.stdout.split("\n")
        if "OFF" not in lines:
            continue
        i = lines.index("OFF")
        nv, nf = map(int, lines[i + 1].split()[:2])
        sources = [l.split()[1] for l in lines[i + 2 + nv + nf:] if l.startswith("source ")]
        if not sources:
            continue
        name = hashlib.sha1(os.path.join(d, f).encode()).hexdigest()[:12]
        open(f"{out}/{name}.off", "w").write("\n".join(lines[i:i + 2 + nv + nf]) + "\n")
        open(f"{out}/{name}.args", "w").write(" ".join("-s " + s for s in sources) + "\n")
PY

# run GEODEX DIR: every output of one CLI build into DIR.
run() {
  local g=$1 d=$2 m b info nv nf s t
  mkdir -p "$d"
  for a in "$OUT"/cases/*.args; do
    m=${a%.args} b=$(basename "${a%.args}")
    nv=$(sed -n 2p "$m.off" | awk '{print $1}')
    # shellcheck disable=SC2046  # the source arguments, split on purpose
    { timeout 60 "$g" distance "$m.off" $(cat "$a") -q; echo "rc $?"; } > "$d/$b.d" 2>&1 || true
    # shellcheck disable=SC2046
    { timeout 60 "$g" path "$m.off" $(cat "$a") -t "v:$((nv - 1))"; echo "rc $?"; } > "$d/$b.p" 2>&1 || true
  done
  for m in "$MAIN"/build/release/data/meshes/* "$MAIN"/tests/data/regression/*.off; do
    b=$(basename "$m")
    info=$("$BASE" info "$m" 2> /dev/null) || continue
    nv=$(echo "$info" | awk '/^vertices:/{print $2}') nf=$(echo "$info" | awk '/^faces:/{print $2}')
    for s in v:0 f:0,0.3333333333333333,0.3333333333333333,0.3333333333333334; do
      { timeout 300 "$g" distance "$m" -s "$s" -q; echo "rc $?"; } > "$d/$b-${s%%,*}.d" 2>&1 || true
    done
    for t in "v:$((nv - 1))" "v:$((nv / 2))" "f:$((nf / 2)),0.3333333333333333,0.3333333333333333,0.3333333333333334"; do
      { timeout 300 "$g" path "$m" -s v:0 -t "$t"; echo "rc $?"; } > "$d/$b-${t%%,*}.p" 2>&1 || true
    done
  done
}
[ -d "$OUT/base" ] || run "$BASE" "$OUT/base"

python3 - "$MAIN" "$REV" "$HASH" <<'PY'
import subprocess, sys
sys.path.insert(0, sys.argv[1] + "/scripts")
import mutate
rev = subprocess.run(["git", "rev-parse", sys.argv[2]], stdout=subprocess.PIPE, text=True).stdout.strip()
ms = [m for m in mutate.catalogue(1, rev) if m["id"].endswith(sys.argv[3])]
assert len(ms) == 1, "no single mutant %s in the catalogue of %s" % (sys.argv[3], rev)
assert mutate.plant(".", ms[0]), "the source line of %s has changed" % ms[0]["id"]
print("planted", ms[0]["id"])
PY
cmake --build --preset release --target geodex_cli -j2 > /dev/null
rm -rf "${OUT:?}/$HASH" && run build/release/bin/geodex "$OUT/$HASH"
git checkout -q -- .
n=0 differ=0
for f in "$OUT"/base/*; do
  n=$((n + 1))
  cmp -s "$f" "$OUT/$HASH/$(basename "$f")" || { differ=$((differ + 1)); echo "differs: $(basename "$f")"; }
done
echo "$HASH at $REV: $n outputs ($(find "$OUT/cases" -name "*.args" | wc -l) corpus cases), $differ differ"
