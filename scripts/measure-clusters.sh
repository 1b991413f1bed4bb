#!/usr/bin/env bash
# The distances `grader class` clusters wrong pictures by (grader/src/class/clusters.rs), measured:
# a class of one student per catalogued mistake a picture's check catches (tests/mistakes), graded
# in f32 and again in f64 (the same wrong code drawn by other arithmetic), the two grades put in
# one class (STUDENT and STUDENT-f64), and its page written again (`class --report-only`). Prints,
# per picture's check, the largest distance inside a cluster (a mistake against itself in the
# other precision) and the smallest between two clusters (two mistakes), as class.html states
# them: the share of pixels whose FLIP error a viewer notices at a glance.
#
#   scripts/measure-clusters.sh [WORK]   (~15 minutes on 2 cores, the f64 build included;
#                                         WORK defaults to target/measure-clusters)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(realpath -m "${1:-target/measure-clusters}")
rm -rf "$work" && mkdir -p "$work/submissions"

python3 - "$work/submissions" <<'EOF'
import glob, os, shutil, sys, tomllib
out = sys.argv[1]
for f in sorted(glob.glob("tests/mistakes/*.toml")):
    for i, m in enumerate(tomllib.load(open(f, "rb"))["mistake"]):
        if "/image/" not in m["caught_by"] and "/geometry/" not in m["caught_by"]:
            continue
        student = os.path.join(out, f"{os.path.basename(f)[:3]}-{i}")
        for src in glob.glob("lectures/*/src"):
            shutil.copytree(src, os.path.join(student, src))
        path = os.path.join(student, m["file"])
        text = open(path).read()
        assert text.count(m["find"]) == 1, m["name"]
        open(path, "w").write(text.replace(m["find"], m["replace"]))
EOF

cargo build -q -p grader
target/debug/grader class "$work/submissions" -o "$work/f32" --workdir "$work/work32"
CARGO_TARGET_DIR="$work/target64" cargo build -q -p grader --features raylab/f64
CARGO_TARGET_DIR="$work/target64" "$work/target64/debug/grader" class "$work/submissions" \
  -o "$work/f64" --workdir "$work/work64"

# One class of both: the f64 grades renamed, their pictures beside the f32 ones.
python3 - "$work" <<'EOF'
import json, os, shutil, sys
work = sys.argv[1]
both = os.path.join(work, "both")
shutil.copytree(os.path.join(work, "f32"), both)
for student in os.listdir(os.path.join(work, "f64", "students")):
    src = os.path.join(work, "f64", "students", student)
    dst = os.path.join(both, "students", student + "-f64")
    shutil.copytree(src, dst)
    grade = json.load(open(os.path.join(dst, "grade.json")))
    grade["student"] = student + "-f64"
    for check in grade["checks"]:
        if check.get("picture"):
            check["picture"] = check["picture"].replace(f"students/{student}/", f"students/{student}-f64/")
    json.dump(grade, open(os.path.join(dst, "grade.json"), "w"))
EOF
target/debug/grader class --report-only -o "$work/both"

python3 - "$work/both/class.html" <<'EOF'
import re, sys
page = open(sys.argv[1]).read()
rows = re.findall(r'<tr class="clusters" data-check="([^"]+)">.*?\(pictures in a cluster at most ([0-9.]+) % of pixels apart(?:, the nearest two ([0-9.]+) % apart)?\)', page)
print(f"{'picture check':40} {'inside (%)':>10} {'between (%)':>11}")
for check, inside, between in rows:
    print(f"{check:40} {inside:>10} {between or '-':>11}")
print(f"largest inside: {max(float(r[1]) for r in rows):.2f} %; smallest between: "
      f"{min((float(r[2]) for r in rows if r[2]), default=float('nan')):.2f} %")
EOF
