"""What the gearkit fuzzer checks on the files a run leaves (tests/fuzz/fuzz.py): no temporary
file left behind, nothing written by a run that failed, no output cut short (docs/cli.md: "no
half-written output file"); and whether an error message says where (docs/cli.md: file:line:column
or the option)."""
import json
import os
import re

OWN = {".stdout", ".stderr"}


def listing(scratch):
    """{path relative to scratch: (size, mtime_ns)} of every regular file under scratch."""
    found = {}
    for folder, _, files in os.walk(scratch):
        for name in files:
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, scratch)
            if rel in OWN:
                continue
            try:
                st = os.lstat(path)
            except OSError:
                continue
            found[rel] = (st.st_size, st.st_mtime_ns)
    return found


def cut_short(path):
    """Why the file at `path` is incomplete, or None. Judged by its first bytes: SVG/XML ends with
    its root's end tag, DXF with EOF, JSON parses."""
    try:
        with open(path, "rb") as f:
            head = f.read(64)
            f.seek(max(os.path.getsize(path) - 256, 0))
            tail = f.read().rstrip()
    except OSError:
        return None
    text = head.lstrip()
    if text.startswith(b"<?xml") or text.startswith(b"<svg"):
        return None if tail.endswith(b"</svg>") else "SVG without its end tag"
    if text.startswith(b"0\n") or text.startswith(b"0\r\n") or head.startswith(b"  0"):
        return None if tail.endswith(b"EOF") else "DXF without EOF"
    if text.startswith(b"<!DOCTYPE html") or text.startswith(b"<html"):
        return None if tail.endswith(b"</html>") else "HTML without its end tag"
    if text.startswith(b"{") and os.path.getsize(path) < 8 << 20:
        try:
            with open(path, encoding="utf-8") as f:
                json.load(f)
        except (ValueError, UnicodeDecodeError):
            return "JSON that does not parse"
    return None


def problem(scratch, before, status):
    """A description of a half-written output, or None. After a signal (status < 0 or 128 + N) only
    what an atomic write excludes counts: a temporary left, a file cut short."""
    after = listing(scratch)
    temporaries = sorted(p for p in after if "gearkit-tmp" in p)
    if temporaries:
        return f"temporary file left: {temporaries[0]}"
    changed = sorted(p for p in after if before.get(p) != after[p])
    if status in (2, 1) or status is not None and status > 3 and status < 128:
        if changed:
            return f"exit {status} {'changed' if changed[0] in before else 'wrote'} {changed[0]}"
        return None
    for rel in changed:
        why = cut_short(os.path.join(scratch, rel))
        if why:
            return f"{rel}: {why}"
    return None


# An error that says where: file:line:column, a named option or argument, the command word.
LOCATED = re.compile(r":\d+:\d+: |option '|argument '|the [A-Z]+ argument|command '|found '|standard (output|input|error)|"
                     r"environment variable|plugin '|\.(yaml|yml|so)'?: ")


def located(line):
    return bool(LOCATED.search(line))
