#!/usr/bin/env bash
# A student's loop, measured: edit → verdict per lecture. For each lecture 01–10, three rounds
# alternating the lectures: a one-line change in an exercise (a statement, `std::hint::black_box(i);`,
# put first in the body of the lecture's first exercise, in file order: code the compiler must
# compile again), then `cargo run -q -p grader -- NN` (total); then the same command again with
# nothing to rebuild (rerun: cargo's no-op and the checks' run). Prints per lecture the medians of
# total and rerun, and their difference (rebuild: the lecture, the checks crate and the link).
#
#   scripts/measure-edit-verdict.sh             the table (~2 minutes on 2 cores)
#   ROUNDS=5 scripts/measure-edit-verdict.sh    medians of 5 rounds (the machine's noise is ±0.1 s)
#   LECTURES="09 10" scripts/measure-edit-verdict.sh   those lectures only (each graded once, untimed,
#                                               before its edit)
#   EDIT=comment scripts/measure-edit-verdict.sh   the edit a comment appended to lib.rs instead
#                                               (the table before session 25: cheaper to rebuild)
#   scripts/measure-edit-verdict.sh --debuginfo the relink after an edit and a cold build of the
#                                               checks, with the workspace's debug info against
#                                               full debug info everywhere (~3 minutes)
#   scripts/measure-edit-verdict.sh --mistakes  edit → verdict when the edit is a mistake: each of
#                                               tests/mistakes/*.toml's planted alone, the lecture
#                                               graded (its checks failing: the causes, the
#                                               pictures' diagnoses, the report's images and 3D
#                                               views), put back; per lecture the median and the
#                                               slowest (~3 minutes; LECTURES as above).
#                                               `--student --mistakes` in a student's tree
#   scripts/measure-edit-verdict.sh --student   the same table in a student's tree: the handout
#                                               (`grader handout`, in STUDENT_DIR or a temporary
#                                               folder) with the reference's solutions put back,
#                                               the instructors' parts left out as the handout
#                                               leaves them, and where a solution calls those
#                                               (lecture 09's traversal calls fast.rs) the accepted
#                                               answer of tests/mistakes/ that does without
#
# The lectures' files are put back as they were (their contents; their times set in the past).
set -euo pipefail
cd "$(dirname "$0")/.."

# The mistakes' catalogue, from this repository (a student's tree has none).
MISTAKES_DIR=${MISTAKES_DIR:-$PWD/tests/mistakes}
export MISTAKES_DIR

if [ "${1:-}" = "--student" ]; then
  shift
  dir=${STUDENT_DIR:-$(mktemp -d)/student}
  cargo run -q -p grader -- handout "$dir"
  python3 - "$dir" <<'PY'
import glob, os, sys, tomllib
dir = sys.argv[1]
def without_instructor(text):
    # The handout's rule (grader/src/handout.rs): comment lines ending in INSTRUCTOR BEGIN / END
    # and what lies between them go.
    kept, inside = [], False
    for line in text.split("\n"):
        t = line.strip()
        marker = t.startswith("//") or t.startswith("#")
        if marker and t.endswith("INSTRUCTOR BEGIN"):
            inside = True
        elif marker and t.endswith("INSTRUCTOR END"):
            inside = False
        elif not inside:
            kept.append(line)
    return "\n".join(kept)
for path in glob.glob("lectures/*/src/**/*.rs", recursive=True):
    if os.path.exists(os.path.join(dir, path)):
        with open(os.path.join(dir, path), "w") as f:
            f.write(without_instructor(open(path).read()))
for catalogue in sorted(glob.glob("tests/mistakes/*.toml")):
    for answer in tomllib.load(open(catalogue, "rb")).get("accepted", []):
        if "crate::fast" in answer["find"]:
            path = os.path.join(dir, answer["file"])
            text = open(path).read()
            assert text.count(answer["find"]) == 1, answer["name"]
            open(path, "w").write(text.replace(answer["find"], answer["replace"]))
PY
  mkdir -p "$dir/scripts"
  cp "$0" "$dir/scripts/"
  if ! (cd "$dir" && cargo run -q -p grader -- --strict > /dev/null); then
    echo "the student's tree does not pass its checks: cd $dir && cargo run -p grader" >&2
    exit 1
  fi
  echo "a student's tree, every check passing: $dir"
  exec bash "$dir/scripts/$(basename "$0")" "$@"
fi

if [ "${1:-}" = "--mistakes" ]; then
  cargo run -q -p grader > /dev/null 2>&1 || true
  python3 - <<'PY'
import glob, json, os, statistics, subprocess, time, tomllib
def grade(n):
    return subprocess.run(["cargo", "run", "-q", "-p", "grader", "--", n, "--format", "json"],
                          capture_output=True, text=True)
times = {}
for catalogue in sorted(glob.glob(os.path.join(os.environ["MISTAKES_DIR"], "l[0-9][0-9].toml"))):
    n = os.path.basename(catalogue)[1:3]
    if n not in os.environ.get("LECTURES", n).split():
        continue
    grade(n)  # the lecture built before its first mistake, untimed
    for mistake in tomllib.load(open(catalogue, "rb")).get("mistake", []):
        path = mistake["file"]
        text = open(path).read()
        if text.count(mistake["find"]) != 1:
            print(f"{n} skipped: not in this tree's {path}: {mistake['name'][:60]}")
            continue
        open(path, "w").write(text.replace(mistake["find"], mistake["replace"]))
        try:
            start = time.time()
            ran = grade(n)
            seconds = time.time() - start
        finally:
            # Put back with the time of now: cargo must compile the lecture again (a time in the
            # past would leave the mistake compiled in).
            open(path, "w").write(text)
            os.utime(path, None)
        try:
            checks = json.loads(ran.stdout)["checks"]
            verdict = f"{sum(c['status'] != 'passed' for c in checks):2} of {len(checks)} checks not passed"
        except (ValueError, KeyError):
            verdict = f"no report (exit {ran.returncode}): {ran.stderr.strip()[-200:]}"
        times.setdefault(n, []).append(seconds)
        print(f"{n} {seconds:5.2f} s  {verdict}  {mistake['name'][:70]}", flush=True)
    grade(n)
print("lecture  mistakes  median  slowest   (seconds)")
for n, ts in sorted(times.items()):
    print(f"{n}       {len(ts):8}  {statistics.median(ts):6.2f}  {max(ts):7.2f}")
PY
  exit 0
fi

if [ "${1:-}" = "--debuginfo" ]; then
  lib=lectures/04-quadrics-transforms/src/lib.rs
  variant() {
    local name=$1; shift
    local target; target=$(mktemp -d)
    local s e
    s=$(date +%s.%N)
    CARGO_TARGET_DIR=$target cargo build -q "$@" -p raylab-checks --bin raylab-checks \
      --no-default-features --features l04
    e=$(date +%s.%N)
    echo "$name: cold build $(echo "$e - $s" | bc) s, binary $(stat -c %s "$target/debug/raylab-checks") bytes"
    cp "$lib" "$target/lib.rs"
    for i in 1 2 3; do
      echo "// edit $i" >> "$lib"
      s=$(date +%s.%N)
      CARGO_TARGET_DIR=$target cargo build -q "$@" -p raylab-checks --bin raylab-checks \
        --no-default-features --features l04
      e=$(date +%s.%N)
      cp "$target/lib.rs" "$lib"
      echo "$name: rebuild after an edit of lecture 04 $(echo "$e - $s" | bc) s"
    done
    touch -d '2026-01-01' "$lib"
    rm -rf "$target"
  }
  variant "full debug info" --config 'profile.dev.package."*".debug=true' \
    --config 'profile.dev.package.raylab-checks.debug=true'
  variant "the workspace's"
  exit 0
fi

raw=$(mktemp)
cargo run -q -p grader > /dev/null 2>&1 || true
for i in $(seq 1 "${ROUNDS:-3}"); do
  for d in lectures/[0-9][0-9]-*/; do
    n=$(basename "$d" | cut -c1-2)
    case " ${LECTURES:-$n} " in *" $n "*) ;; *) continue ;; esac
    # With some lectures only, an edit of an earlier one (01) leaves the lectures between it and
    # this one (02–09) stale in this one's build: they are rebuilt here, untimed, not in the
    # timed grade (which measured lecture 10 at 2.6 s after 01's edit, 1.5 s alone). With every
    # lecture, each grade has rebuilt them already.
    if [ -n "${LECTURES:-}" ]; then
      cargo run -q -p grader -- "$n" > /dev/null 2>&1 || true
    fi
    if [ "${EDIT:-code}" = comment ]; then
      f=$d/src/lib.rs
      cp "$f" "$raw.bak"
      echo "// edit $i" >> "$f"
    else
      f=$(grep -l '// SOLUTION BEGIN' "$d"src/*.rs | sort | head -1)
      cp "$f" "$raw.bak"
      # After the first `// SOLUTION BEGIN` only, with its indentation.
      awk -v i="$i" '!done && /\/\/ SOLUTION BEGIN/ { print; sub(/\/\/ SOLUTION BEGIN.*/, ""); print $0 "std::hint::black_box(" i ");"; done = 1; next } { print }' \
        "$raw.bak" > "$f"
    fi
    s=$(date +%s.%N)
    cargo run -q -p grader -- "$n" > /dev/null 2>&1 || true
    e=$(date +%s.%N)
    cargo run -q -p grader -- "$n" > /dev/null 2>&1 || true
    e2=$(date +%s.%N)
    cp "$raw.bak" "$f"
    touch -d '2026-01-01' "$f"
    echo "$n $(echo "$e - $s" | bc) $(echo "$e2 - $e" | bc)" >> "$raw"
  done
done
python3 - "$raw" <<'EOF'
import collections, statistics, sys
rows = collections.defaultdict(list)
for line in open(sys.argv[1]):
    n, total, rerun = line.split()
    rows[n].append((float(total), float(rerun)))
print(f"lecture  total  rerun  rebuild   (seconds, median of {len(next(iter(rows.values())))})")
for n in sorted(rows):
    total = statistics.median(t for t, _ in rows[n])
    rerun = statistics.median(r for _, r in rows[n])
    print(f"{n}       {total:5.2f}  {rerun:5.2f}  {total - rerun:5.2f}")
EOF
rm -f "$raw" "$raw.bak"
