#!/usr/bin/env python3
"""The code's shape outside tests (issue 59): no file over 800 lines, no function over 150,
no import circle between the files of a crate. Prints what breaks a rule and exits 1, unless
it is one of the known exceptions below (each says why it is still there); an exception
that no longer applies is reported too, so the list only shrinks.

    python3 scripts/check-shape.py [CRATES_DIR]

What counts as a test: files named tests.rs or *_tests.rs, anything under tests/ or
benches/, and a `#[cfg(test)] mod ... {` block that ends a file. Lines are counted up to
that block. Functions are found by their `fn` line and their braces (strings and line
comments are blanked first). An import is a `crate::`, `super::` or `self::` path naming
another file's module (a path inside the same file does not count); a circle is a group
of files each reaching the others through such paths.
"""

import os
import re
import sys

FILE_LINES = 800
FN_LINES = 150

# What still breaks a rule, and why. Remove an entry when its cause is gone.
KNOWN = {
    # Bridge owns every part's state (node info, parameters, actions, services) and each
    # part is methods of Bridge.
    ("circle", "ros2", "bridge node_info offered_actions params services"),
}

FN_RE = re.compile(r"^\s*(pub(\([^)]*\))?\s+)?(const\s+)?(async\s+)?(unsafe\s+)?fn\s+(\w+)")
PATH_RE = re.compile(r"\b(crate|super|self)((?:::\w+)+)")
TEST_MOD_RE = re.compile(r"^#\[cfg\(test\)\]\s*$")


def is_test_file(path):
    parts = path.split(os.sep)
    name = parts[-1]
    return "tests" in parts or "benches" in parts or name == "tests.rs" or name.endswith("_tests.rs")


def blank(line):
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    line = re.sub(r"'(\\.|[^'\\])'", "''", line)
    i = line.find("//")
    return line if i < 0 else line[:i]


def code_lines(text):
    """The file's lines up to a trailing inline test module."""
    lines = text.split("\n")
    for i, line in enumerate(lines):
        if TEST_MOD_RE.match(line) and i + 1 < len(lines) and re.match(r"\s*(pub\s+)?mod \w+\s*\{", lines[i + 1]):
            return lines[:i]
    return lines


def long_functions(lines):
    i = 0
    while i < len(lines):
        m = FN_RE.match(lines[i])
        if m:
            depth, started, j = 0, False, i
            while j < len(lines):
                s = blank(lines[j])
                if not started and ";" in s and "{" not in s:
                    break
                for c in s:
                    if c == "{":
                        depth += 1
                        started = True
                    elif c == "}":
                        depth -= 1
                if started and depth <= 0:
                    break
                j += 1
            if started and j - i + 1 > FN_LINES:
                yield m.group(6), j - i + 1
        i += 1


def modules(src):
    """Each non-test source file of a crate by its module path (a tuple)."""
    files = {}
    for d, _, names in os.walk(src):
        for name in names:
            path = os.path.join(d, name)
            if not name.endswith(".rs") or is_test_file(path):
                continue
            parts = os.path.relpath(path, src)[:-3].split(os.sep)
            if parts[-1] in ("lib", "main", "mod"):
                parts = parts[:-1]
            files[tuple(parts)] = path
    return files


def circles(src):
    files = modules(src)
    edges = {m: set() for m in files}
    for mod, path in files.items():
        own = path.endswith(("lib.rs", "main.rs", "mod.rs"))
        text = "\n".join(blank(l) for l in code_lines(open(path, encoding="utf-8").read()))
        for m in PATH_RE.finditer(text):
            head, rest = m.group(1), m.group(2).split("::")[1:]
            if head == "crate":
                base = []
            elif head == "self":
                base = list(mod)
            else:
                base = list(mod) if own else list(mod[:-1])
                base = base[:-1] if own else base
                while rest and rest[0] == "super":
                    rest, base = rest[1:], base[:-1]
            want = base + rest
            for k in range(len(want), -1, -1):
                target = tuple(want[:k])
                if target in files:
                    if target != mod:
                        edges[mod].add(target)
                    break
    # Strongly connected components (Tarjan, iterative enough for these sizes).
    sys.setrecursionlimit(10000)
    index, low, stack, on, out, n = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = n[0]
        n[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(" ".join(sorted("::".join(c) or "lib" for c in comp)))

    for v in sorted(files):
        if v not in index:
            visit(v)
    return out


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "crates"
    found = set()
    report = []
    for crate in sorted(os.listdir(root)):
        src = os.path.join(root, crate, "src")
        if not os.path.isdir(src):
            continue
        for path in sorted(modules(src).values()):
            lines = code_lines(open(path, encoding="utf-8").read())
            if len(lines) > FILE_LINES:
                found.add(("file", path, ""))
                report.append((("file", path, ""), f"{path}: {len(lines)} lines (limit {FILE_LINES})"))
            for name, n in long_functions(lines):
                found.add(("fn", path, name))
                report.append((("fn", path, name), f"{path}: fn {name} is {n} lines (limit {FN_LINES})"))
        for comp in circles(src):
            key = ("circle", crate, comp)
            found.add(key)
            report.append((key, f"{crate}: these files import each other in a circle: {comp}"))
    advice = {
        "file": "split it along its seams",
        "fn": "split it into named steps",
        "circle": "move what they share into the file that owns it, or a leaf module",
    }
    bad = [f"{text}: {advice[key[0]]}" for key, text in report if key not in KNOWN]
    stale = [k for k in KNOWN if k not in found]
    for text in bad:
        print(f"shape: {text}", file=sys.stderr)
    for k in stale:
        print(f"shape: known exception {k} no longer applies: remove it from scripts/check-shape.py", file=sys.stderr)
    kept = len(found & KNOWN)
    if bad or stale:
        return 1
    print(f"shape: no file over {FILE_LINES} lines, no function over {FN_LINES}, no import circle ({kept} known exceptions)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
