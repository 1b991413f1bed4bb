#!/usr/bin/env python3
"""How scattered the grader's concepts are (issue 33's figures), from the sources as text.

    python3 scripts/measure-concepts.py

Prints, for grader/src, grader/checks/src and grader/checks/core/src, code outside tests (a file's tests start at its
first `#[cfg(test)]` at the start of a line; files named `*tests.rs` are all tests):
  - lecture-number literals ("01" … "99" as a whole string literal), outside the lectures' own
    check crates (grader/checks/lectures/lNN/), per file;
  - files under grader/ over 700 lines;
  - import circles among the checks' core's top-level modules (grader/checks/core/src): groups of modules that use each
    other, directly or through others (`crate::m` or `super::m` paths, and `mod` children's uses
    counted as their parent's), tests included, since a circle through a test still ties the files.
"""
import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
LITERAL = re.compile(r'"(0[1-9]|[1-9][0-9])"')


def rust_files(folder):
    for base, dirs, files in os.walk(os.path.join(ROOT, folder)):
        dirs.sort()
        for name in sorted(files):
            if name.endswith(".rs"):
                yield os.path.join(base, name)


def code_of(path):
    text = open(path, encoding="utf-8").read()
    if os.path.basename(path).endswith("tests.rs"):
        return ""
    cut = re.search(r"^#\[cfg\((all\()?test", text, re.M)
    return text[: cut.start()] if cut else text


def relative(path):
    return os.path.relpath(path, ROOT)


def literals():
    total, per = 0, []
    for folder in ["grader/src", "grader/checks/src", "grader/checks/core/src"]:
        for path in rust_files(folder):
            rel = relative(path)
            n = len(LITERAL.findall(code_of(path)))
            if n:
                per.append((n, rel))
                total += n
    return total, sorted(per, reverse=True)


def long_files():
    found = []
    for path in rust_files("grader"):
        n = sum(1 for _ in open(path, encoding="utf-8"))
        if n > 700:
            found.append((n, relative(path)))
    return sorted(found, reverse=True)


def circles():
    src = os.path.join(ROOT, "grader/checks/core/src")
    modules = {}
    for path in rust_files("grader/checks/core/src"):
        rel = os.path.relpath(path, src)
        top = rel.split(os.sep)[0]
        top = top[:-3] if top.endswith(".rs") else top
        if top == "lib":
            continue
        uses = modules.setdefault(top, set())
        text = open(path, encoding="utf-8").read()
        for used in re.findall(r"\bcrate::([a-z_0-9]+)", text):
            if used != top:
                uses.add(used)
        # `super::m` from a top-level module's own file names a sibling.
        if os.sep not in rel:
            for used in re.findall(r"\bsuper::([a-z_0-9]+)", text):
                if used != top:
                    uses.add(used)
    names = [m for m in modules]
    uses = {m: {u for u in modules[m] if u in modules} for m in names}
    # Strongly connected components (Tarjan).
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(uses[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                out.append(sorted(group))

    sys.setrecursionlimit(10000)
    for v in sorted(names):
        if v not in index:
            visit(v)
    return out


def main():
    total, per = literals()
    print(f"lecture-number literals outside tests and the lectures' check folders: {total}")
    for n, rel in per:
        print(f"  {n:4}  {rel}")
    files = long_files()
    print(f"files under grader/ over 700 lines: {len(files)}")
    for n, rel in files:
        print(f"  {n:5}  {rel}")
    groups = circles()
    print(f"import circles among grader/checks/core/src's modules: {len(groups)}")
    for group in groups:
        print("  " + " ↔ ".join(group))


if __name__ == "__main__":
    main()
