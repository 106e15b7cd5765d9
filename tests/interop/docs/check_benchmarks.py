#!/usr/bin/env python3
"""Checks the results table of docs/benchmarks.md and the Rust version the README states.

Every row of the results table (the first table of docs/benchmarks.md) must have:

  - a status that starts with "met", "not met", "blocked" or "not measured";
  - unless its figure is "not measured" (then command and commit are "—"):
    - a figure linking to where it was measured: a file that exists and, when the link
      has an anchor, a heading of that file with that anchor;
    - a command in backticks that names something that exists: a `fleetlink bench X`
      subcommand X (from `$FLEETLINK_BIN bench --help`, else from the bench module's
      source), a `cargo bench -p PKG --bench NAME` target, or a script in the repository;
    - a commit: a hex hash that `git cat-file -e` resolves (skipped, with a note, outside
      a git checkout or in a shallow clone).

Every link into docs/benchmarks.md or docs/benchmarks/ from README.md and docs/ must
resolve to an existing file and heading. And README.md's "`cargo`, X or newer" must
equal `rust-version` in the root Cargo.toml.

Usage: check_benchmarks.py [--bin FLEETLINK_BIN]. Exits 1 naming each failure.
"""

import argparse
import re
import shlex
import subprocess
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
TABLE_DOC = ROOT / "docs" / "benchmarks.md"
STATUSES = ("met", "not met", "blocked", "not measured")
NONE = {"—", "-", ""}

failures = []


def fail(msg):
    failures.append(msg)


def plain(cell):
    """A cell's text without emphasis and surrounding space."""
    return re.sub(r"\*+", "", cell).strip()


def split_row(line):
    """Splits a table row on the pipes outside backtick spans."""
    cells, cur, in_code = [], [], False
    for ch in line.strip().strip("|"):
        if ch == "`":
            in_code = not in_code
        if ch == "|" and not in_code:
            cells.append("".join(cur).strip())
            cur = []
        else:
            cur.append(ch)
    cells.append("".join(cur).strip())
    return cells


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = heading.replace("`", "").strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    """The anchors of a Markdown file's headings (fenced blocks skipped, repeats numbered)."""
    seen, result, fence = {}, set(), False
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fence = not fence
            continue
        m = None if fence else re.match(r"#{1,6}\s+(.*)", line)
        if m:
            base = slug(m.group(1))
            n = seen.get(base, 0)
            seen[base] = n + 1
            result.add(base if n == 0 else f"{base}-{n}")
    return result


def check_link(where, doc, target):
    """A relative Markdown link from `doc` resolves to a file and, if given, a heading."""
    if re.match(r"[a-z]+:", target):
        return
    file_part, _, anchor = target.partition("#")
    path = (doc.parent / file_part).resolve() if file_part else doc
    shown = path.relative_to(ROOT) if path.is_relative_to(ROOT) else path
    if not path.is_file():
        fail(f"{where}: link to {target}: no file {shown}")
        return
    if anchor and path.suffix == ".md" and anchor not in anchors(path):
        fail(f"{where}: link to {target}: {shown} has no heading with anchor #{anchor}")


def bench_subcommands(binary):
    """`fleetlink bench` subcommands: from the binary's help, else from the source."""
    if binary:
        try:
            out = subprocess.run([binary, "bench", "--help"], capture_output=True, text=True,
                                 timeout=30, check=True).stdout
            section = out.split("Commands:", 1)[1].split("Options:", 1)[0]
            names = {m.group(1) for m in re.finditer(r"^\s{2}([a-z][a-z0-9-]*)\s", section, re.M)}
            names.discard("help")
            if names:
                return names, f"`{binary} bench --help`"
        except (OSError, subprocess.SubprocessError, IndexError) as e:
            print(f"note: `{binary} bench --help` failed ({e}); reading the source instead")
    src = (ROOT / "crates/bench/src/lib.rs").read_text(encoding="utf-8")
    body = src.split("enum Command {", 1)[1].split("\n}", 1)[0]
    names = {re.sub(r"(?<!^)([A-Z])", r"-\1", m.group(1)).lower()
             for m in re.finditer(r"^\s{4}([A-Z]\w*)\s*\(", body, re.M)}
    return names, "crates/bench/src/lib.rs"


def cargo_bench_exists(words):
    """`cargo bench -p PKG --bench NAME ...`: PKG is a workspace crate with benches/NAME.rs."""
    def opt(flag):
        if flag in words and words.index(flag) + 1 < len(words):
            return words[words.index(flag) + 1]
        return None
    pkg, bench = opt("-p") or opt("--package"), opt("--bench")
    if not pkg or not bench:
        return "a cargo command must be `cargo bench -p PKG --bench NAME`"
    for manifest in ROOT.glob("crates/*/Cargo.toml"):
        name = tomllib.loads(manifest.read_text(encoding="utf-8")).get("package", {}).get("name")
        if name == pkg:
            if (manifest.parent / "benches" / f"{bench}.rs").is_file():
                return None
            return f"package {pkg} has no benches/{bench}.rs"
    return f"no workspace package named {pkg}"


def check_command(where, command, subcommands, source):
    try:
        words = shlex.split(command)
    except ValueError as e:
        fail(f"{where}: command `{command}` does not parse: {e}")
        return
    while words and (words[0] == "sudo" or re.match(r"[A-Za-z_][A-Za-z0-9_]*=", words[0])):
        words.pop(0)
    if not words:
        fail(f"{where}: command `{command}` runs nothing")
        return
    program = words[0]
    if Path(program).name == "fleetlink":
        if len(words) < 3 or words[1] != "bench":
            fail(f"{where}: command `{command}` is not `fleetlink bench <subcommand> ...`")
        elif words[2] not in subcommands:
            fail(f"{where}: `fleetlink bench {words[2]}` is not a bench subcommand "
                 f"(per {source}: {', '.join(sorted(subcommands))})")
    elif program == "cargo":
        problem = cargo_bench_exists(words)
        if problem:
            fail(f"{where}: command `{command}`: {problem}")
    elif not (ROOT / program).is_file():
        fail(f"{where}: command `{command}` names {program}, which is not a file in the repository")


def git_can_check():
    """Whether commits can be resolved here: a git checkout with its history."""
    try:
        inside = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--is-inside-work-tree"],
                                capture_output=True, text=True).stdout.strip()
        if inside != "true":
            return False, "not a git checkout"
        shallow = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--is-shallow-repository"],
                                 capture_output=True, text=True).stdout.strip()
        if shallow == "true":
            return False, "a shallow clone"
        return True, ""
    except OSError:
        return False, "git not installed"


def results_table(text):
    """The header and rows of the first table in the text."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("|") and i + 1 < len(lines) and re.match(r"\|[\s:|-]+\|$", lines[i + 1]):
            rows = []
            for row in lines[i + 2:]:
                if not row.startswith("|"):
                    break
                rows.append(split_row(row))
            return [c.lower() for c in split_row(line)], rows
    return None, []


def check_table(binary):
    header, rows = results_table(TABLE_DOC.read_text(encoding="utf-8"))
    doc = "docs/benchmarks.md"
    if header is None:
        fail(f"{doc}: no results table")
        return 0
    cols = {}
    for key in ("target", "figure", "command", "commit", "status"):
        found = [i for i, h in enumerate(header) if key in h]
        if not found:
            fail(f"{doc}: the results table has no '{key}' column (header: {header})")
            return 0
        cols[key] = found[0]
    subcommands, source = bench_subcommands(binary)
    git_ok, git_why = git_can_check()
    if not git_ok:
        print(f"note: commits not resolved ({git_why}); checked only that each row names one")
    for n, cells in enumerate(rows, 1):
        if len(cells) != len(header):
            fail(f"{doc}: row {n} has {len(cells)} cells, the header {len(header)}")
            continue
        where = f"{doc}: row {n} ({plain(cells[cols['target']])[:70]})"
        figure, command = cells[cols["figure"]], cells[cols["command"]]
        commit, status = plain(cells[cols["commit"]]), plain(cells[cols["status"]]).lower()
        if not status.startswith(STATUSES):
            fail(f"{where}: status '{cells[cols['status']]}' is none of: {', '.join(STATUSES)}")
        if plain(figure).lower() == "not measured":
            if not status.startswith("not measured"):
                fail(f"{where}: figure 'not measured' but status '{status}'")
            if plain(command) not in NONE or commit not in NONE:
                fail(f"{where}: a row without a figure names a command or commit")
            continue
        if status.startswith("not measured"):
            fail(f"{where}: status 'not measured' but a figure is given")
        links = re.findall(r"\]\(([^)\s]+)\)", figure)
        if not links:
            fail(f"{where}: the figure links to no section where it was measured")
        for target in links:
            check_link(where, TABLE_DOC, target)
        commands = re.findall(r"`([^`]+)`", command)
        if not commands:
            fail(f"{where}: no command (in backticks)")
        for c in commands:
            check_command(where, c, subcommands, source)
        hashes = re.findall(r"\b[0-9a-f]{7,40}\b", commit)
        if not hashes:
            fail(f"{where}: no commit hash in '{cells[cols['commit']]}'")
        if git_ok:
            for h in hashes:
                r = subprocess.run(["git", "-C", str(ROOT), "cat-file", "-e", f"{h}^{{commit}}"],
                                   capture_output=True)
                if r.returncode != 0:
                    fail(f"{where}: commit {h} does not resolve (git cat-file -e)")
    return len(rows)


def check_links_into_benchmarks():
    """Links from README.md and docs/ into the benchmark pages resolve."""
    docs = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
    bench = (ROOT / "docs" / "benchmarks.md", ROOT / "docs" / "benchmarks")
    count = 0
    for doc in docs:
        fence = False
        for lineno, line in enumerate(doc.read_text(encoding="utf-8").splitlines(), 1):
            if line.startswith("```"):
                fence = not fence
            if fence:
                continue
            for target in re.findall(r"\]\(([^)\s]+)\)", line):
                if re.match(r"[a-z]+:", target):
                    continue
                file_part = target.partition("#")[0]
                path = (doc.parent / file_part).resolve() if file_part else doc
                if path == bench[0] or bench[1] in path.parents:
                    count += 1
                    check_link(f"{doc.relative_to(ROOT)}:{lineno}", doc, target)
    return count


def check_rust_version():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    m = re.search(r"`cargo`,\s*(\d+\.\d+(?:\.\d+)?) or newer", readme)
    if not m:
        fail("README.md states no Rust version (expected \"`cargo`, X.Y or newer\")")
        return
    manifest = tomllib.loads((ROOT / "Cargo.toml").read_text(encoding="utf-8"))
    declared = manifest.get("workspace", {}).get("package", {}).get("rust-version")
    if declared is None:
        fail("Cargo.toml: no [workspace.package] rust-version")
        return
    norm = lambda v: tuple(int(x) for x in v.split(".")) + (0,) * (3 - len(v.split(".")))
    if norm(m.group(1)) != norm(declared):
        fail(f"README.md says Rust {m.group(1)} or newer, Cargo.toml's rust-version is {declared}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", help="the fleetlink binary (for `bench --help`)")
    args = parser.parse_args()
    rows = check_table(args.bin)
    links = check_links_into_benchmarks()
    check_rust_version()
    if failures:
        for f in failures:
            print(f"FAIL: {f}", file=sys.stderr)
        return 1
    print(f"PASS: benchmarks table: {rows} rows with command, commit and status; "
          f"{links} links into the benchmark pages resolve; README's Rust version is Cargo.toml's")
    return 0


if __name__ == "__main__":
    sys.exit(main())
