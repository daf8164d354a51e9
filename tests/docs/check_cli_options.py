#!/usr/bin/env python3
"""Every command's --help against docs/cli.md, "Quantity options" (issue 25, section 1):

- every option that takes a value shows what the value looks like, never Boost's bare `arg`;
- every quantity option's help description ends with its bare-number rule, `(bare number: UNIT)`
  or `(unit required, e.g. EXAMPLE)`, and an option that looks like a quantity (its value is
  LEN, ANGLE, SPEED, POWER, ...) without that ending is a problem;
- the table lists exactly those options, per command, with the same rule and unit;
- one option name means one quantity and one bare-number rule in every command of the table.

usage: check_cli_options.py --exe build/bin/gearkit. Exit 0 when all hold; otherwise one line per
problem. The commands are those `gearkit --help` lists, plus their subcommands (gear size, train
synth, synth path, gear rack|worm|crossed)."""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SUBCOMMANDS = ["gear size", "gear bevel", "gear rack", "gear worm", "gear crossed", "train synth", "synth path"]
# An option whose value name (or NAME=VALUE part) is one of these takes a physical quantity.
QUANTITY_VALUES = {"LEN", "ANGLE", "SPEED", "POWER", "TORQUE", "TIME", "RATE", "MODULE", "START:END:STEP"}
RULE = re.compile(r"\((?:bare number: (?P<unit>[^()]+)|unit required, e\.g\. (?P<example>[^()]+))\)$")
OPTION_LINE = re.compile(r"^  (?:-\w \[ --(?P<long1>[\w-]+) \]|--(?P<long2>[\w-]+))(?P<value>(?: \S+)*?)(?: {2,}(?P<desc>.*))?$")


def run(exe, words):
    r = subprocess.run([exe] + words, capture_output=True, text=True, timeout=60)
    return r.returncode, r.stdout, r.stderr


def commands(exe):
    status, out, err = run(exe, ["--help"])
    if status != 0:
        sys.exit(f"gearkit --help: exit {status}: {err.strip()}")
    body = out.split("\nCommands:\n", 1)[1]
    names = []
    for line in body.splitlines():
        m = re.match(r"^  (\S+)\s", line)
        if not m:
            break
        if m.group(1) != "help":  # `gearkit help CMD` is `gearkit CMD --help`
            names.append(m.group(1))
    return names + SUBCOMMANDS


def help_options(text):
    """{option: (value part, description)} from a Boost.Program_options help text."""
    entries = []
    for line in text.splitlines():
        m = OPTION_LINE.match(line)
        if m:
            entries.append([m.group("long1") or m.group("long2"), m.group("value").strip(), (m.group("desc") or "").strip()])
        elif entries and entries[-1] and line.startswith("   ") and line.strip():
            entries[-1][2] = (entries[-1][2] + " " + line.strip()).strip()
        elif not line.strip() or not line.startswith(" "):
            entries.append(None)  # a blank line or heading ends an entry
    return {e[0]: (e[1], e[2]) for e in entries if e}


def looks_like_quantity(value):
    word = value.split(" ")[0] if value else ""
    word = word.split("=")[-1].strip("[]")
    return word in QUANTITY_VALUES


def parse_table(path):
    """{(command, option): rule} from the table, rule = ("unit", "mm") or ("required", "")."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    m = re.search(r"^## Quantity options\n(.*?)(?=^## |\Z)", text, re.MULTILINE | re.DOTALL)
    if not m:
        sys.exit("docs/cli.md: no section 'Quantity options'")
    table, quantities = {}, {}
    for line in m.group(1).splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 4 or not cells[1].startswith("`--"):
            continue
        cmds = [c.strip().strip("`") for c in cells[0].split(",")]
        options = [o.strip().strip("`").lstrip("-") for o in cells[1].split(",")]
        rule = ("required", "") if cells[3].startswith("unit required") else ("unit", cells[3].replace("`", "").strip())
        for c in cmds:
            for o in options:
                table[(c, o)] = rule
                quantities.setdefault(o, set()).add((cells[2], rule))
    return table, quantities


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    args = parser.parse_args()
    problems = []
    table, quantities = parse_table(os.path.join(ROOT, "docs", "cli.md"))
    status, out, _ = run(args.exe, ["--help"])
    seen = {"": help_options(out)}
    for cmd in commands(args.exe):
        status, out, err = run(args.exe, cmd.split() + ["--help"])
        if status != 0:
            problems.append(f"gearkit {cmd} --help: exit {status}: {err.strip()}")
            continue
        seen[cmd] = help_options(out)
        if not seen[cmd]:
            problems.append(f"gearkit {cmd} --help: no option lines found")
    for cmd, options in seen.items():
        where = f"gearkit {cmd} --help".replace("  ", " ")
        for name, (value, desc) in options.items():
            if re.search(r"(^| )arg( |$)", value):
                problems.append(f"{where}: --{name} shows 'arg' instead of what its value looks like")
            rule = RULE.search(desc)
            stated = None
            if rule:
                stated = ("unit", rule.group("unit").strip()) if rule.group("unit") else ("required", "")
            elif looks_like_quantity(value):
                problems.append(f"{where}: --{name} {value} takes a quantity but its help does not end with "
                                "'(bare number: UNIT)' or '(unit required, e.g. ...)'")
            if stated and (cmd, name) not in table:
                problems.append(f"docs/cli.md: the quantity table lacks `{cmd}` `--{name}` ({where} says {desc[rule.start():]})")
            elif stated and table[(cmd, name)] != stated:
                problems.append(f"docs/cli.md: `{cmd}` `--{name}` is {table[(cmd, name)]} in the table, but {where} says "
                                f"{desc[rule.start():]}")
    for (cmd, name), rule in sorted(table.items()):
        if cmd not in seen:
            problems.append(f"docs/cli.md: the quantity table names a command `{cmd}` that gearkit does not list")
        elif name not in seen[cmd]:
            problems.append(f"docs/cli.md: `{cmd}` has no option `--{name}` (gearkit {cmd} --help)")
        elif not RULE.search(seen[cmd][name][1]):
            problems.append(f"docs/cli.md: `{cmd}` `--{name}` is in the quantity table, but its help states no bare-number rule")
    for name, kinds in sorted(quantities.items()):
        if len(kinds) > 1:
            problems.append(f"docs/cli.md: `--{name}` means different quantities or units in different commands: {sorted(kinds)}")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
