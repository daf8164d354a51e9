#!/usr/bin/env python3
"""Fails on any dependency between gearkit's libraries, plugins and executable that the graph in
docs/design.md ("Layering") does not draw (issue 27, item 4).

    scripts/check_layering.py --targets build/layering/targets.txt [--root SRC] [--design FILE]

Three kinds of edge are read from the build and the sources:
  - link: a target's link line names another gearkit target (targets.txt, written at configure
    time by cmake/GearkitLayering.cmake from the targets' LINK_LIBRARIES and
    INTERFACE_LINK_LIBRARIES);
  - source: a target compiles a file of another node's folder;
  - include: a file includes `<gearkit/X/...>` or a quoted path that lands in another node's folder.
A link or source edge must be an arrow of the graph. An include edge may reach any node the
graph leads to from the file's node (a plugin that links libmechanism may include libkin's
headers, which libmechanism's public headers include anyway). Dotted arrows are debt: allowed,
but each must still be used, so that the list only shrinks. The graph must have no cycle, and
every gearkit target must be one of its nodes. Prints one line per problem; exit 1 if any.
"""
import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".cc")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
EDGE = re.compile(r'^\s*(\w+)\s*(-->|-\.->)\s*(\w+)\s*$')
NODE = re.compile(r'^\s*(\w+)\s*\[')


def read_graph(design):
    """The ```mermaid block under the "Layering" heading: nodes, arrows (-->) and debt (-.->)."""
    text = open(design, encoding="utf-8").read()
    m = re.search(r'^## Layering\b.*?^```mermaid\n(.*?)^```', text, re.S | re.M)
    if not m:
        raise SystemExit(f"{design}: no ```mermaid block under '## Layering'")
    nodes, edges, debt = set(), set(), set()
    for line in m.group(1).splitlines():
        e = EDGE.match(line)
        if e:
            a, kind, b = e.groups()
            (edges if kind == "-->" else debt).add((a, b))
            nodes.update((a, b))
            continue
        n = NODE.match(line)
        if n:
            nodes.add(n.group(1))
    return nodes, edges, debt


def node_of_target(target):
    """gearkit_kin -> kin, gearkit_plugin_cam -> plugin_cam, gearkit (the executable) -> cli."""
    return "cli" if target == "gearkit" else target[len("gearkit_"):]


def node_of_path(rel):
    """The node that owns a file (path relative to the source root), or None (tests, examples)."""
    parts = rel.split("/")
    if parts[0] == "libplugin":  # two targets share the folder: the header-only API and the host
        return "plugin" if parts[-1] == "plugin.hpp" else "plugin_host"
    if parts[0].startswith("lib") and len(parts) > 1:
        return parts[0][3:]
    if parts[0] == "plugins" and len(parts) > 2:
        return "plugin_" + parts[1]
    if parts[0] == "cli":
        return "kin_equations" if parts[-1] == "kin_equations.cpp" else "cli"
    return None


def node_of_include(path):
    """<gearkit/kin/model.hpp> -> kin (plugin_host.hpp is the host's, the rest of gearkit/plugin the API's)."""
    parts = path.split("/")
    if len(parts) < 3 or parts[0] != "gearkit":
        return None
    if parts[1] == "plugin":
        return "plugin_host" if parts[2] == "plugin_host.hpp" else "plugin"
    return parts[1]


def read_targets(path):
    targets = {}
    for line in open(path, encoding="utf-8"):
        if line.startswith("#") or not line.strip():
            continue
        name, kind, deps, sources = (line.rstrip("\n").split("\t") + ["", "", ""])[:4]
        targets[name] = (kind, deps.split(), sources.split())
    return targets


def source_files(root):
    for top in sorted(os.listdir(root)):
        if not (top.startswith("lib") or top in ("plugins", "cli")) or not os.path.isdir(os.path.join(root, top)):
            continue
        for folder, subfolders, names in os.walk(os.path.join(root, top)):
            subfolders.sort()
            for n in sorted(names):
                if n.endswith(SOURCE_SUFFIXES):
                    yield os.path.relpath(os.path.join(folder, n), root).replace(os.sep, "/")


def include_edges(root):
    """(from node, to node, where, what) for every include that crosses into another node."""
    for rel in source_files(root):
        here = node_of_path(rel)
        with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                bracket, path = m.groups()
                to = node_of_include(path) if bracket == "<" else None
                if bracket == '"':
                    target = os.path.normpath(os.path.join(os.path.dirname(rel), path)).replace(os.sep, "/")
                    if os.path.exists(os.path.join(root, target)):
                        to = node_of_path(target)
                if to and here and to != here:
                    shown = f"<{path}>" if bracket == "<" else f'"{path}"'
                    yield here, to, f"{rel}:{number}", f"includes {shown}"


def reachable(edges, start):
    seen, todo = set(), [start]
    while todo:
        a = todo.pop()
        for x, b in edges:
            if x == a and b not in seen:
                seen.add(b)
                todo.append(b)
    return seen


def check(targets_file, root, design):
    nodes, edges, debt = read_graph(design)
    allowed = edges | debt
    problems, used_debt = [], set()
    for n in sorted(nodes):
        if n in reachable(allowed, n):
            problems.append(f"{design}: the graph has a cycle through {n}")
    for target, (kind, deps, sources) in sorted(read_targets(targets_file).items()):
        if kind == "UTILITY":
            continue  # an aggregate (gearkit_runtime: what `make demo` builds) compiles and links nothing
        a = node_of_target(target)
        if a not in nodes:
            problems.append(f"{design}: target {target} ({kind}) is no node of the graph: draw it and its arrows")
            continue
        for dep in deps:
            b = node_of_target(dep)
            if (a, b) not in allowed:
                problems.append(f"{target} links {dep}: the edge {a} -> {b} is not in the graph of {design}")
            used_debt.add((a, b))
        for src in sources:
            b = node_of_path(src)
            if b and b != a:
                if (a, b) not in allowed:
                    problems.append(f"{target} compiles {src}: the edge {a} -> {b} is not in the graph of {design}")
                used_debt.add((a, b))
    for a, b, where, what in include_edges(root):
        used_debt.add((a, b))
        if b not in reachable(allowed, a):
            problems.append(f"{where}: {a} {what}: the edge {a} -> {b} is not in the graph of {design}")
    for a, b in sorted(debt - used_debt):
        problems.append(f"{design}: the debt {a} -.-> {b} is paid (no link, source or include uses it): remove it")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--targets", required=True, help="layering/targets.txt of a configured build tree")
    ap.add_argument("--root", default=ROOT, help="source root (default: this checkout)")
    ap.add_argument("--design", help="the design page with the graph (default: ROOT/docs/design.md)")
    args = ap.parse_args()
    design = args.design or os.path.join(args.root, "docs", "design.md")
    problems = check(args.targets, args.root, design)
    for p in problems:
        print(p)
    if not problems:
        print("layering: every link, source and include edge is in the graph of", design)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
