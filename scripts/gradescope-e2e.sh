#!/usr/bin/env bash
# Gradescope's autograder run for real on this machine, in the paths Gradescope uses: the bundle
# (`grader gradescope`) zipped and unzipped into /autograder/source, its setup.sh run once as root,
# then /autograder/run_autograder for each submission put in /autograder/submission, each
# /autograder/results/results.json checked against Gradescope's documented fields and against the
# score it should have:
#   reference        the instructors' lectures: full marks
#   handout          the student workspace as handed out: 0
#   redteam          the reference with attacks that read what only the judge may (a snapshot as
#                    its geometry image, the hidden checks' source at run time), kill the grader
#                    and leave a process behind: 0 for each check attacked, nothing else changed
#   redteam-compile  the reference with the hidden checks' source taken in at compile time
#                    (include_str! of its absolute path): lecture 10 does not compile, 0 for it
#   redteam-runtime  the reference with attacks as the grading user: its own binary rewritten, a
#                    process out of the check's group and session that waits to rewrite the
#                    results, /proc read for a judge's token, a fork bomb, the disk filled: 0 for
#                    each check attacked, nothing else changed, nothing of the user's left
#   before-main      the handout with a constructor in lecture 01 that forges the list and the
#                    verdicts (it scored 207/213 when the list came from the student's build): 0
# and the wall time of each run_autograder (the bundle warm: setup.sh built everything once).
#
# Usage, as root on Linux (it replaces /autograder, and refuses one it did not make):
#   scripts/gradescope-e2e.sh
# The results, logs and a summary go to target/gradescope-e2e/.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
OUT="$ROOT/target/gradescope-e2e"
MARK=/autograder/.made-by-raylab-e2e
[ "$(id -u)" = 0 ] || { echo "run as root: the grading user and /autograder need it" >&2; exit 2; }
if [ -e /autograder ] && [ ! -e "$MARK" ]; then
  echo "/autograder exists and this script did not make it: not touching it" >&2
  exit 2
fi
rm -rf /autograder "$OUT"
mkdir -p "$OUT" /autograder
touch "$MARK"

seconds() { date +%s.%N; }
elapsed() { python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.1f}')" "$1" "$2"; }

# The bundle, as an instructor uploads it and Gradescope unpacks it.
(cd "$ROOT" && cargo build -q -p grader)
"$ROOT/target/debug/grader" gradescope "$OUT/bundle" > /dev/null
(cd "$OUT/bundle" && zip -qr "$OUT/autograder.zip" .)
mkdir -p /autograder/source
unzip -q "$OUT/autograder.zip" -d /autograder/source
cp /autograder/source/run_autograder /autograder/run_autograder
echo "bundle: $(du -sh "$OUT/autograder.zip" | cut -f1) zipped"

start=$(seconds)
bash /autograder/source/setup.sh > "$OUT/setup.log" 2>&1 || { tail -30 "$OUT/setup.log"; exit 1; }
echo "setup.sh: $(elapsed "$start" "$(seconds)") s (log: $OUT/setup.log)"

# The submissions.
mkdir -p "$OUT/submissions"
cp -a "$ROOT/lectures" "$OUT/submissions/reference"
mkdir -p "$OUT/submissions/reference-tree"
mv "$OUT/submissions/reference" "$OUT/submissions/reference-tree/lectures"
"$ROOT/target/debug/grader" handout "$OUT/submissions/handout" > /dev/null
cp -a "$OUT/submissions/reference-tree" "$OUT/submissions/redteam"
cp -a "$OUT/submissions/reference-tree" "$OUT/submissions/redteam-compile"
cp -a "$OUT/submissions/reference-tree" "$OUT/submissions/redteam-runtime"
cp -a "$OUT/submissions/handout" "$OUT/submissions/before-main"
python3 - "$OUT/submissions" "$ROOT" << 'PATCH'
import sys, pathlib
subs, root = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])

def fragment(name):
    """An attack of the red team's (tests/redteam/), as tests/tests/redteam.rs inserts it."""
    return (root / "tests/redteam" / f"{name}.rs").read_text()

def attack(tree, file, function, code):
    path = subs / tree / file
    text = path.read_text()
    at = text.index(f"pub fn {function}(")
    begin = text.index("// SOLUTION BEGIN\n", at) + len("// SOLUTION BEGIN\n")
    path.write_text(text[:begin] + code + text[begin:])

# (c) the snapshot of that size, read where the judge keeps it, as the object-id image.
attack("redteam", "lectures/02-ray-casting/src/images.rs", "object_id_image", r'''
    let dir = std::path::Path::new("/autograder/source/lectures/02-ray-casting/snapshots");
    let mut found: Vec<std::path::PathBuf> = std::fs::read_dir(dir)
        .map(|entries| entries.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    found.sort();
    for path in found.into_iter().filter(|p| p.to_string_lossy().ends_with(".id.png")) {
        if let Ok(image) = Image::load_png(&path) {
            if (image.width, image.height) == (width, height) {
                return image;
            }
        }
    }
    return Image::new(width, height);
''')
# (d) the hidden checks' source, read at run time and shown in a panic; else a wrong answer.
attack("redteam", "lectures/05-shading/src/lambert.rs", "lambert", r'''
    if let Ok(text) = std::fs::read_to_string("/autograder/source/grader/checks/src/lectures/hidden.rs") {
        panic!("the hidden checks: {text}");
    }
    return 0.5;
''')
# (e) kills the grader (its parent) and leaves a process behind, once per check, then answers
# wrongly.
attack("redteam", "lectures/02-ray-casting/src/plane.rs", "hit_plane", fragment("kill-the-grader"))
# (g)–(l): the red team's attacks from outside the function bodies.
attack("redteam-runtime", "lectures/02-ray-casting/src/sphere.rs", "hit_sphere_geometric", fragment("rewrite-the-binary"))
attack("redteam-runtime", "lectures/02-ray-casting/src/sphere.rs", "hit_sphere_algebraic", fragment("escape-and-wait"))
attack("redteam-runtime", "lectures/03-polygons-triangles/src/triangle.rs", "hit_triangle_cramer", fragment("read-proc"))
attack("redteam-runtime", "lectures/03-polygons-triangles/src/polygon.rs", "winding_number", fragment("fork-bomb"))
attack("redteam-runtime", "lectures/03-polygons-triangles/src/triangle.rs", "hit_triangle_moller_trumbore", fragment("fill-the-disk"))
lib = subs / "before-main/lectures/01-transforms/src/lib.rs"
lib.write_text(lib.read_text() + "\n" + fragment("before-main"))
# (d) at compile time: the build runs as the grading user, who cannot read the source.
attack("redteam-compile", "lectures/10-textures-sampling/src/checker.rs", "checker", r'''
    let _hidden: &str = include_str!("/autograder/source/grader/checks/src/lectures/hidden.rs");
''')
PATCH

declare -A WALL
for name in reference handout redteam redteam-compile redteam-runtime before-main reference; do
  rm -rf /autograder/submission /autograder/results
  mkdir -p /autograder/submission
  if [ "$name" = reference ]; then from=reference-tree; else from=$name; fi
  cp -a "$OUT/submissions/$from/." /autograder/submission/
  start=$(seconds)
  /autograder/run_autograder > "$OUT/$name.log" 2>&1
  took=$(elapsed "$start" "$(seconds)")
  WALL[$name]="${WALL[$name]:-}${WALL[$name]:+, }$took"
  cp /autograder/results/results.json "$OUT/$name.json"
  # Nothing of the grading users' outlives a grade: no process (a zombie is gone), no file in /tmp.
  for user in $(getent passwd | cut -d: -f1 | grep '^raylab-student'); do
    left=$(ps -u "$user" -o stat=,pid=,comm= | grep -v '^ *Z' || true)
    [ -z "$left" ] || { echo "$name: processes of $user left: $left" >&2; exit 1; }
    files=$(find /tmp /var/tmp /dev/shm -maxdepth 1 -user "$user" 2> /dev/null || true)
    [ -z "$files" ] || { echo "$name: files of $user left: $files" >&2; exit 1; }
  done
  files=$(find /autograder/work -name fill 2> /dev/null || true)
  [ -z "$files" ] || { echo "$name: the work folder was written: $files" >&2; exit 1; }
  cp /tmp/grader.err "$OUT/$name.err" 2> /dev/null || true
  echo "run_autograder $name: $took s"
done

# Each results.json against Gradescope's fields, and the scores each submission should have.
python3 - "$OUT" << 'CHECK'
import json, sys, pathlib
out = pathlib.Path(sys.argv[1])
VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}
FORMATS = {"text", "html", "simple_format", "md", "ansi"}

def valid(name):
    r = json.loads((out / f"{name}.json").read_text())
    assert isinstance(r.get("score"), (int, float)), f"{name}: score"
    assert isinstance(r.get("tests"), list) and r["tests"], f"{name}: tests"
    for key, allowed in (("output_format", FORMATS), ("stdout_visibility", VISIBILITY), ("visibility", VISIBILITY)):
        assert key not in r or r[key] in allowed, f"{name}: {key} = {r[key]!r}"
    for t in r["tests"]:
        assert isinstance(t.get("name"), str) and t["name"], f"{name}: a test without a name"
        for key in ("score", "max_score"):
            assert isinstance(t.get(key), (int, float)), f"{name}: {t['name']}: {key}"
        assert t["status"] in ("passed", "failed"), f"{name}: {t['name']}: status {t.get('status')!r}"
        assert isinstance(t.get("output"), str), f"{name}: {t['name']}: output"
        assert t.get("visibility", "visible") in VISIBILITY, f"{name}: {t['name']}: visibility"
        assert t.get("output_format", "text") in FORMATS, f"{name}: {t['name']}: output_format"
        assert 0 <= t["score"] <= t["max_score"], f"{name}: {t['name']}: score out of range"
    assert abs(sum(t["score"] for t in r["tests"]) - r["score"]) < 1e-9, f"{name}: score is not the tests' sum"
    return r, {t["name"]: t for t in r["tests"]}

ref, ref_tests = valid("reference")
top = sum(t["max_score"] for t in ref["tests"])
assert ref["score"] == top, f"reference: {ref['score']} of {top}"
hand, _ = valid("handout")
assert hand["score"] == 0, f"handout: {hand['score']}"
red, red_tests = valid("redteam")
secret = "cos θ = 0.8; the light mirrored behind the surface"
assert secret not in json.dumps(red, ensure_ascii=False), "a result quotes the hidden checks' source"
attacked = [n for n in red_tests if n.startswith("02 geometry/") or n.startswith("05 lambert/") or n == "02 hit_plane/unit"]
assert any(n == "05 lambert/hidden-3-4-5" for n in attacked), "the hidden lambert check is missing"
for n in attacked:
    assert red_tests[n]["score"] == 0 and red_tests[n]["status"] == "failed", f"redteam: {n} scored"
for n, t in red_tests.items():
    # Lectures 01 and 07's unit checks call nothing attacked (their pictures draw with hit_plane).
    if n.startswith(("01 ", "07 ")) and not any(k in n for k in ("image/", "final/", "geometry/")):
        assert t["status"] == "passed", f"redteam: {n} changed: {t['output']}"
comp, comp_tests = valid("redteam-compile")
for n, t in comp_tests.items():
    expected = 0 if n.startswith("10 ") else t["max_score"]
    assert t["score"] == expected, f"redteam-compile: {n}: {t['score']} ({t['output'][:200]})"
run, run_tests = valid("redteam-runtime")
hit = ("02 hit_sphere_geometric/", "02 hit_sphere_algebraic/", "03 hit_triangle_cramer/", "03 winding_number/",
       "03 hit_triangle_moller_trumbore/")
runtime_attacked = [n for n in run_tests if n.startswith(hit)]
assert len(runtime_attacked) >= 5, runtime_attacked
for n, t in run_tests.items():
    assert "token found" not in t["output"], f"redteam-runtime: {n}: {t['output'][:300]}"
    if n in runtime_attacked:
        assert t["score"] == 0, f"redteam-runtime: {n} scored"
    elif not any(k in n for k in ("image/", "final/", "geometry/")):
        assert t["status"] == "passed", f"redteam-runtime: {n} changed: {t['output'][:300]}"
before, before_tests = valid("before-main")
assert before["score"] == 0, f"before-main: {before['score']}"
assert any("unsafe code is not allowed in a submission" in t["output"] for t in before_tests.values())
summary = [
    f"reference: {ref['score']}/{top}",
    f"handout: {hand['score']}/{top}",
    f"redteam: {red['score']}/{top}; {len(attacked)} attacked checks all 0",
    f"redteam-compile: {comp['score']}/{top}; lecture 10's checks 0",
    f"redteam-runtime: {run['score']}/{top}; {len(runtime_attacked)} attacked checks all 0, the rest as the reference's",
    f"before-main: {before['score']}/{top}; unsafe code refused",
    "every results.json has Gradescope's fields",
]
(out / "summary.txt").write_text("\n".join(summary) + "\n")
print("\n".join(summary))
CHECK
for name in "${!WALL[@]}"; do echo "wall $name: ${WALL[$name]} s"; done | sort | tee -a "$OUT/summary.txt"
