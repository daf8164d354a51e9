#!/usr/bin/env python3
"""A test of the layering test (issue 27, item 4): scripts/check_layering.py passes on a copy of
the sources and the build's link lines, and fails, naming the edge, on each kind of bad edge
injected into the copy: an include, a link, a compiled source of another folder, a target not
drawn, a cycle in the graph and a paid debt. Drawing the included edge in the copy of
docs/design.md makes the include pass again: the allow-list is the page.

    test_check_layering.py BUILD/layering/targets.txt          (exit 0 when every case behaves)
"""
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "check_layering.py")


def copy_sources(dest):
    for top in os.listdir(ROOT):
        if (top.startswith("lib") or top in ("plugins", "cli")) and os.path.isdir(os.path.join(ROOT, top)):
            shutil.copytree(os.path.join(ROOT, top), os.path.join(dest, top),
                            ignore=shutil.ignore_patterns("build*", "*.yaml", "*.txt"))
    os.makedirs(os.path.join(dest, "docs"))
    shutil.copy(os.path.join(ROOT, "docs", "design.md"), os.path.join(dest, "docs", "design.md"))


def edit(path, change):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    with open(path, "w", encoding="utf-8") as f:
        f.write(change(text))
    return text


def run(root, targets):
    r = subprocess.run([sys.executable, SCRIPT, "--targets", targets, "--root", root], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def add_graph_line(line):
    return lambda text: text.replace("```mermaid\ngraph TD\n", f"```mermaid\ngraph TD\n  {line}\n", 1)


def add_link(target, dep):
    def change(text):
        lines = text.splitlines(keepends=True)
        for i, line in enumerate(lines):
            cols = line.rstrip("\n").split("\t")
            if cols[0] == target:
                cols[2] = (cols[2] + " " + dep).strip()
                lines[i] = "\t".join(cols) + "\n"
        return "".join(lines)
    return change


def add_source(target, source):
    def change(text):
        lines = text.splitlines(keepends=True)
        for i, line in enumerate(lines):
            cols = line.rstrip("\n").split("\t")
            if cols[0] == target:
                cols[3] = (cols[3] + " " + source).strip()
                lines[i] = "\t".join(cols) + "\n"
        return "".join(lines)
    return change


def main():
    problems = []
    with tempfile.TemporaryDirectory() as root:
        copy_sources(root)
        targets = os.path.join(root, "targets.txt")
        shutil.copy(sys.argv[1], targets)
        design = os.path.join(root, "docs", "design.md")
        solve = os.path.join(root, "libkin", "src", "solve.cpp")

        status, out = run(root, targets)
        if status != 0:
            problems.append(f"the unchanged copy fails (status {status}):\n{out}")

        # (file to change, change, text the failure must contain)
        cases = [
            (solve, lambda t: "#include <gearkit/gear/spur.hpp>\n" + t,
             "libkin/src/solve.cpp:1: kin includes <gearkit/gear/spur.hpp>: the edge kin -> gear is not in the graph"),
            (solve, lambda t: '#include "../../libio/include/gearkit/io/error.hpp"\n' + t,
             "the edge kin -> io is not in the graph"),
            (targets, add_link("gearkit_kin", "gearkit_io"),
             "gearkit_kin links gearkit_io: the edge kin -> io is not in the graph"),
            (targets, add_source("gearkit_plugin_cam", "plugins/gear/gear_report.cpp"),
             "gearkit_plugin_cam compiles plugins/gear/gear_report.cpp: the edge plugin_cam -> plugin_gear"),
            (targets, lambda t: t + "gearkit_shaft\tSHARED_LIBRARY\tgearkit_kin\t\n",
             "target gearkit_shaft (SHARED_LIBRARY) is no node of the graph"),
            (design, add_graph_line("io --> cli"), "the graph has a cycle through"),
            (design, add_graph_line("kin -.-> io"), "the debt kin -.-> io is paid"),
        ]
        for path, change, expected in cases:
            before = edit(path, change)
            status, out = run(root, targets)
            if status != 1 or expected not in out:
                problems.append(f"injected case expecting '{expected}': status {status}, output:\n{out}")
            edit(path, lambda _: before)

        # The allow-list is the page: drawing the edge lets the include through.
        before_solve = edit(solve, lambda t: "#include <gearkit/gear/spur.hpp>\n" + t)
        edit(design, add_graph_line("kin --> gear"))
        status, out = run(root, targets)
        if status != 0:
            problems.append(f"an include drawn in the graph still fails (status {status}):\n{out}")
        edit(solve, lambda _: before_solve)
    for p in problems:
        print("test_check_layering:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
