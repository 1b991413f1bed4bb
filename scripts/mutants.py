#!/usr/bin/env python3
"""Mutation score of a lecture's checks: does `grader NN` catch wrong exercise code?

    python3 scripts/mutants.py NN [--list] [--match REGEX] [--limit K] [--skip K] [--out FILE]

cargo-mutants (`cargo install cargo-mutants`) lists the mutants of lecture NN's crate
(`cargo mutants --list --json -p PACKAGE`); this keeps those inside a SOLUTION region (the
code a student writes; for a whole-body replacement, a function that holds one), applies
each alone to a scratch copy of the workspace (`target/mutants/work`, its own git worktree,
built in its own target folder), grades the lecture there (`cargo run -p grader -- NN
--format json`), and reverts it. A mutant is

- caught: a check of lecture NN does not pass (failed, crashed, timed out);
- missed: every check of lecture NN passes;
- unviable: the lecture does not compile with it.

Each result is appended to the JSON-lines file (default target/mutants/NN.jsonl) as it
comes, so a run can be stopped and resumed (--skip counts the mutants already done). The
score is caught / (caught + missed). One mutant at a time: the machine has 2 cores, and
the grader uses both.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = os.path.join(ROOT, "target", "mutants", "work")


def lecture_folder(number):
    for name in sorted(os.listdir(os.path.join(ROOT, "lectures"))):
        if name.startswith(number + "-"):
            return name
    sys.exit(f"no lecture {number} in lectures/")


def package_of(folder):
    with open(os.path.join(ROOT, "lectures", folder, "Cargo.toml")) as f:
        return re.search(r'^name\s*=\s*"([^"]+)"', f.read(), re.M).group(1)


def solution_regions(path):
    """The (first, last) line numbers (1-based) of each SOLUTION region of a file."""
    regions, start = [], None
    with open(os.path.join(ROOT, path)) as f:
        for n, line in enumerate(f, 1):
            if "SOLUTION BEGIN" in line:
                start = n
            elif "SOLUTION END" in line and start is not None:
                regions.append((start, n))
                start = None
    return regions


def in_solution(mutant, regions):
    line = mutant["span"]["start"]["line"]
    if any(a < line < b for a, b in regions[mutant["file"]]):
        return True
    # A whole body replaced (`-> Default::default()`): the function holds a region.
    if mutant["genre"] == "FnValue":
        f = mutant["function"]["span"]
        return any(f["start"]["line"] <= a and b <= f["end"]["line"] for a, b in regions[mutant["file"]])
    return False


def mutants_of(package):
    out = subprocess.run(
        ["cargo", "mutants", "--list", "--json", "-p", package],
        cwd=ROOT, capture_output=True, text=True, check=True,
    ).stdout
    every = json.loads(out)
    regions = {m["file"]: solution_regions(m["file"]) for m in every}
    return [m for m in every if in_solution(m, regions)]


def apply(text, mutant):
    """text with the mutant's span (1-based lines and columns, end exclusive) replaced."""
    lines = text.split("\n")
    s, e = mutant["span"]["start"], mutant["span"]["end"]
    offset = lambda lc: sum(len(l) + 1 for l in lines[: lc["line"] - 1]) + lc["column"] - 1
    return text[: offset(s)] + mutant["replacement"] + text[offset(e):]


def prepare():
    """The scratch worktree at HEAD (created once, reset to HEAD each run)."""
    if not os.path.isdir(WORK):
        os.makedirs(os.path.dirname(WORK), exist_ok=True)
        subprocess.run(["git", "worktree", "add", "--detach", WORK, "HEAD"], cwd=ROOT, check=True)
    subprocess.run(["git", "checkout", "--detach", "-q", subprocess.run(
        ["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()],
        cwd=WORK, check=True)
    subprocess.run(["git", "checkout", "-q", "--", "."], cwd=WORK, check=True)


def grade(number):
    """The statuses of lecture `number`'s checks in the scratch tree, or None if it did not compile."""
    out = os.path.join(WORK, "target", "mutant.json")
    if os.path.exists(out):
        os.remove(out)
    subprocess.run(
        ["cargo", "run", "-q", "-p", "grader", "--", number, "--format", "json", "-o", out],
        cwd=WORK, capture_output=True, text=True,
    )
    if not os.path.exists(out):
        return None
    with open(out) as f:
        graded = json.load(f)
    return {c["info"]["id"]: c["status"] for c in graded["checks"] if c["info"]["id"].startswith(number + "/")}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("lecture")
    ap.add_argument("--list", action="store_true", help="only list the mutants kept")
    ap.add_argument("--match", default=None, help="only the mutants whose name matches this regex")
    ap.add_argument("--limit", type=int, default=None)
    ap.add_argument("--skip", type=int, default=0)
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    folder = lecture_folder(args.lecture)
    mutants = mutants_of(package_of(folder))
    if args.match:
        mutants = [m for m in mutants if re.search(args.match, m["name"])]
    if args.list:
        for m in mutants:
            print(m["name"])
        print(f"{len(mutants)} mutants in SOLUTION regions", file=sys.stderr)
        return
    prepare()
    baseline = grade(args.lecture)
    if baseline is None or any(s != "passed" for s in baseline.values()):
        sys.exit(f"the reference does not pass lecture {args.lecture} in {WORK}: {baseline}")
    out = args.out or os.path.join(ROOT, "target", "mutants", f"{args.lecture}.jsonl")
    chosen = mutants[args.skip:][: args.limit]
    for n, m in enumerate(chosen, args.skip + 1):
        path = os.path.join(WORK, m["file"])
        with open(path) as f:
            original = f.read()
        with open(path, "w") as f:
            f.write(apply(original, m))
        start = time.time()
        try:
            statuses = grade(args.lecture)
        finally:
            with open(path, "w") as f:
                f.write(original)
        if statuses is None or any(s == "does_not_compile" for s in statuses.values()):
            verdict, by = "unviable", []
        else:
            by = sorted(i for i, s in statuses.items() if s != "passed")
            verdict = "caught" if by else "missed"
        record = {"mutant": m["name"], "verdict": verdict, "caught_by": by, "seconds": round(time.time() - start, 1)}
        with open(out, "a") as f:
            f.write(json.dumps(record, ensure_ascii=False) + "\n")
        print(f"[{n}/{len(mutants)}] {verdict:8} {m['name']}" + (f"  ({', '.join(by[:3])})" if by else ""), flush=True)


if __name__ == "__main__":
    main()
