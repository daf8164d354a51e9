#!/usr/bin/env python3
"""Lists the C++ functions longer than a limit (80 lines), from universal-ctags' start and end
lines, and with --check fails when one is not in the allowlist or an allowlisted one is gone.

    scripts/long_functions.py                 # every function over 80 lines, longest first
    scripts/long_functions.py --check         # CI: exit 1 on a new long function or a stale entry

A function's length runs from the line of its name to its closing brace, lambdas and local
classes included. The allowlist (scripts/long_functions.allow) names `path function` per line;
it lists the functions that were already too long when the check began and must end empty.
"""
import argparse
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Top-level folders that hold no project source: build trees (any name starting "build"),
# version control and documentation. Every other folder is scanned, so a new library
# (libfoo/) is checked from its first file.
SKIPPED_DIRS = (".git", ".ci", "cmake", "docs", "scripts")


def source_dirs(root):
    return sorted(d for d in os.listdir(root)
                  if os.path.isdir(os.path.join(root, d)) and d not in SKIPPED_DIRS and not d.startswith("build"))


def source_files(root):
    files = []
    for top in source_dirs(root):
        for folder, subfolders, names in os.walk(os.path.join(root, top)):
            subfolders[:] = [d for d in subfolders if not d.startswith("build")]
            files += [os.path.join(folder, n) for n in names if n.endswith((".cpp", ".hpp", ".h", ".cc"))]
    return sorted(files)


def long_functions(root, limit):
    ctags = shutil.which("ctags")
    if not ctags:
        sys.exit("long_functions: needs universal-ctags (Debian package universal-ctags; scripts/setup-deps.sh)")
    files = source_files(root)
    out = subprocess.run([ctags, "--languages=C++", "--kinds-C++=f", "--fields=+ne", "-o", "-", *files],
                         check=True, capture_output=True, text=True).stdout
    found = []
    for line in out.splitlines():
        fields = line.split("\t")
        extra = dict(f.split(":", 1) for f in fields[3:] if ":" in f)
        if "line" not in extra or "end" not in extra:
            continue
        length = int(extra["end"]) - int(extra["line"]) + 1
        if length > limit:
            found.append((length, os.path.relpath(fields[1], root), int(extra["line"]), fields[0]))
    return sorted(found, key=lambda f: (-f[0], f[1], f[2]))


def read_allowlist(path):
    entries = set()
    if not os.path.exists(path):
        return entries
    with open(path, encoding="utf-8") as f:
        for raw in f:
            line = raw.split("#", 1)[0].strip()
            if line:
                parts = line.split()
                entries.add((parts[0], parts[1]))
    return entries


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max", type=int, default=80, help="longest allowed function, in lines (80)")
    parser.add_argument("--check", action="store_true", help="fail on functions missing from the allowlist")
    parser.add_argument("--allowlist", default=os.path.join(ROOT, "scripts", "long_functions.allow"))
    parser.add_argument("--root", default=ROOT, help="source tree (default: this repository)")
    args = parser.parse_args()

    found = long_functions(args.root, args.max)
    if not args.check:
        for length, path, line, name in found:
            print(f"{length:5d} {path}:{line} {name}")
        return 0
    allowed = read_allowlist(args.allowlist)
    seen = {(path, name) for _, path, _, name in found}
    new = [f for f in found if (f[1], f[3]) not in allowed]
    stale = sorted(allowed - seen)
    for length, path, line, name in new:
        print(f"{path}:{line}: function '{name}' is {length} lines long; split it under {args.max + 1} lines")
    for path, name in stale:
        print(f"{os.path.relpath(args.allowlist, args.root)}: '{path} {name}' is no longer over {args.max} "
              "lines (or gone): remove it from the allowlist")
    if new or stale:
        return 1
    print(f"long_functions: no new function over {args.max} lines ({len(found)} allowlisted remain)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
