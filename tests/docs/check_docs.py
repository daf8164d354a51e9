#!/usr/bin/env python3
"""docs/cli.md and docs/design.md stay true to the code (issue 11 item H):

- docs/cli.md has one "Limits" table (two overlapping ones had grown) and states every limit of
  libio/include/gearkit/io/limits.hpp in it; the Environment paragraph appears once;
- docs/design.md's "Error policy" names the mechanism files go through (io::OutputSet) and does
  not claim that nothing but the error reaches stderr (warning lines do).
Exit 0 when all hold; otherwise one line per problem."""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def read(relative):
    with open(os.path.join(ROOT, relative), encoding="utf-8") as f:
        return f.read()


def section(text, heading):
    """The body of '## heading' up to the next '## ' heading, or None."""
    m = re.search(rf"^## {re.escape(heading)}\n(.*?)(?=^## |\Z)", text, re.MULTILINE | re.DOTALL)
    return m.group(1) if m else None


def numbers(text):
    """Every number in `text`, thousands separators removed ("2,000" and "2 000" are 2000)."""
    found = set()
    for m in re.finditer(r"\d[\d, ]*(?:\.\d+)?(?:e[+-]?\d+)?", text):
        token = re.sub(r"[, ](?=\d{3}\b)", "", m.group(0)).strip(" ,")
        try:
            found.add(float(token))
        except ValueError:
            pass
    return found


def main():
    problems = []
    cli, design = read("docs/cli.md"), read("docs/design.md")
    headings = re.findall(r"^## (.*)$", cli, re.MULTILINE)
    for name in ("Limits", "Environment"):
        if headings.count(name) != 1:
            problems.append(f"docs/cli.md: expected one '## {name}' section, found {headings.count(name)}")
    if any("Limits" in h and h != "Limits" for h in headings):
        problems.append("docs/cli.md: a second limits section: " + ", ".join(h for h in headings if "Limits" in h))
    if cli.count("`GEARKIT_PLUGIN_PATH` (folders or plugin files") != 1:
        problems.append("docs/cli.md: the GEARKIT_PLUGIN_PATH paragraph appears more than once")
    limits = section(cli, "Limits") or ""
    stated = numbers(limits)
    for name, value in re.findall(r"inline constexpr \w+(?:::\w+)? (k\w+) = ([\d'.e]+);",
                                  read("libio/include/gearkit/io/limits.hpp")):
        if float(value.replace("'", "")) not in stated:
            problems.append(f"docs/cli.md Limits: no row states {name} = {value} (libio/include/gearkit/io/limits.hpp)")
    policy = section(design, "Error policy") or ""
    if "OutputSet" not in policy:
        problems.append("docs/design.md Error policy: does not say that files go through io::OutputSet")
    if "Nothing else reaches stderr" in policy:
        problems.append("docs/design.md Error policy: 'Nothing else reaches stderr' is false (warning lines)")
    for p in problems:
        print("check_docs:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
