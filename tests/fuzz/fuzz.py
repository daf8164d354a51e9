#!/usr/bin/env python3
"""Mutation fuzzer for the gearkit executable (issue 11, item 12).

Each case takes a shipped example (examples/) or no file, mutates it (YAML structure and raw
text: huge, tiny, non-finite and negative numbers, wrong units, missing and unknown keys,
repeated items, odd strings) and adds random options of the command (numbers, members, ranges,
output destinations including the input itself, missing folders, devices, '-' and ''). It runs
the case with a time and memory limit and classifies the outcome:

  ok0 ok2 ok3   exit 0, 2 (bad input), 3 (warnings under --strict): fine
  exit1         an internal error: a bug (or out of memory: see memory)
  crash         killed by a signal (segfault, abort)
  sanitizer     AddressSanitizer / UndefinedBehaviorSanitizer / LeakSanitizer report
  timeout       longer than --timeout seconds
  memory        out of memory, or a peak RSS above --max-rss-mb
  stderr        the stderr rule of docs/cli.md broken: a line not starting "gearkit:", more than
                one error line, an error not last, non-warning lines on success
  json          --format json output that strict JSON (no NaN/Infinity) rejects
  nonfinite     nan/inf in a text report, or JSON null, with no warning in the report
  input         an input file changed by the run
  slow          informative only: longer than --slow seconds

Usage: fuzz.py --exe build/bin/gearkit [--cases N] [--seed S] [--jobs J] [--corpus DIR]
               [--save DIR] [--sanitizer] [--timeout SEC]
Exit status 0 when no case falls in a failing class (every class but ok*, slow).
"""
import argparse
import collections
import concurrent.futures
import copy
import json
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
EXAMPLES = os.path.join(SOURCE, "examples")
FAILING = ["exit1", "crash", "sanitizer", "timeout", "memory", "stderr", "json", "nonfinite", "input"]
COLUMNS = ["cases", "ok0", "ok2", "ok3"] + FAILING + ["slow", "max s", "max MB"]
SANITIZER_STATUS = {86: "asan", 87: "ubsan", 23: "lsan"}

# ---------------------------------------------------------------------------------------------
# Values

NUMBERS = ["0", "-0", "1", "-1", "0.5", "2", "3", "7", "-7", "12", "20", "90", "180", "360", "1e-300", "1e-12",
           "1e-6", "1e6", "1e9", "1e20", "1e300", "-1e300", "1e309", "-1e309", "nan", "inf", "-inf", ".nan",
           ".inf", "-.inf", "100000", "100001", "2147483648", "9223372036854775808", "99999999999999999999999",
           "0x10", "1/3", "1,5", "4.9e-324", "2.5e-308"]
UNITS = ["", " mm", " m", " deg", " rad", " rpm", " rad/s", " N*m", " kW", " W", " kg", " s", " MPa", " %",
         " kg*m^2", " mm/s", " 1/s", " furlong"]
STRINGS = ["", " ", "~", "null", "x" * 70, "ring", "sun", "carrier", "a=b", "=", "é", "\u202e", "\t", "- x",
           "{", "[", "*anchor", "&a", "!!binary AA==", "1 mm mm", "0 deg deg", "line1\nline2"]


def random_number(rng):
    if rng.random() < 0.7:
        return rng.choice(NUMBERS)
    return repr(rng.uniform(-1e3, 1e3)) if rng.random() < 0.5 else str(rng.randint(-10, 400))


def random_quantity(rng):
    return random_number(rng) + rng.choice(UNITS)


# ---------------------------------------------------------------------------------------------
# Model-file mutations

def scalar_paths(node, path=()):
    """Every (path, value) to a scalar in a YAML tree (a self-referencing alias is cut short)."""
    if len(path) > 40:
        return
    if isinstance(node, dict):
        for k, v in node.items():
            yield from scalar_paths(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from scalar_paths(v, path + (i,))
    else:
        yield path, node


def container_paths(node, path=()):
    if isinstance(node, (dict, list)) and len(path) <= 40:
        yield path, node
        items = node.items() if isinstance(node, dict) else enumerate(node)
        for k, v in items:
            yield from container_paths(v, path + (k,))


def get_at(tree, path):
    for p in path:
        tree = tree[p]
    return tree


def mutate_scalar(rng, old):
    """A new value for a scalar, often keeping its unit so that the value goes deep."""
    text = str(old)
    unit = re.sub(r"^[-+0-9.eE]+", "", text) if re.match(r"^[-+0-9.]", text) else ""
    roll = rng.random()
    if roll < 0.55:
        return random_number(rng) + unit
    if roll < 0.7:
        return random_quantity(rng)
    if roll < 0.8:
        return rng.choice(STRINGS)
    if roll < 0.85:
        return None
    if roll < 0.9:
        return [random_number(rng) for _ in range(rng.randint(0, 3))]
    return {"x": random_number(rng)}


def mutate_tree(rng, tree):
    scalars = [p for p, _ in scalar_paths(tree) if p]
    containers = [(p, c) for p, c in container_paths(tree)]
    roll = rng.random()
    if scalars and roll < 0.75:
        path = rng.choice(scalars)
        parent = get_at(tree, path[:-1])
        parent[path[-1]] = mutate_scalar(rng, parent[path[-1]])
        return
    path, node = rng.choice(containers)
    if isinstance(node, list) and node:
        i = rng.randrange(len(node))
        action = rng.choice(["dup", "del", "many", "swap"])
        if action == "dup":
            node.insert(i, copy.deepcopy(node[i]))
        elif action == "del":
            del node[i]
        elif action == "many":
            node.extend(copy.deepcopy(node[i]) for _ in range(rng.choice([10, 100, 1000])))
        else:
            j = rng.randrange(len(node))
            node[i], node[j] = node[j], node[i]
    elif isinstance(node, dict) and node:
        key = rng.choice(list(node))
        action = rng.choice(["del", "del", "unknown", "null", "list", "copy", "copy"])
        if action == "del":
            del node[key]
        elif action == "unknown":
            node[key + "_x"] = node[key]
        elif action == "null":
            node[key] = None
        elif action == "list":
            node[key] = [node[key], node[key]]
        else:
            other = rng.choice(list(node))
            node[key] = copy.deepcopy(node[other])


def mutate_text(rng, text):
    """Byte-level damage that a YAML dump would never produce."""
    lines = text.split("\n")
    action = rng.choice(["truncate", "dupline", "delline", "indent", "document", "bytes", "anchor", "tab"])
    i = rng.randrange(len(lines)) if lines else 0
    if action == "truncate":
        return text[: rng.randrange(len(text) + 1)]
    if action == "dupline" and lines:
        lines.insert(i, lines[i])
    elif action == "delline" and lines:
        del lines[i]
    elif action == "indent" and lines:
        lines[i] = " " * rng.choice([1, 2, 3]) + lines[i]
    elif action == "document":
        lines.insert(i, "---")
    elif action == "bytes":
        pos = rng.randrange(len(text) + 1)
        return text[:pos] + rng.choice(["\x00", "\xff", "\u00e9", ": :", "{{", "]]", "\r", "&x *x"]) + text[pos:]
    elif action == "anchor":
        lines.insert(i, "a: &a [*a]")
    elif action == "tab" and lines:
        lines[i] = "\t" + lines[i]
    return "\n".join(lines)


def mutate_file(rng, text):
    try:
        tree = yaml.safe_load(text)
    except yaml.YAMLError:
        tree = None
    if isinstance(tree, (dict, list)) and rng.random() < 0.8:
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            mutate_tree(rng, tree)
        try:
            text = yaml.safe_dump(tree, sort_keys=False, allow_unicode=True, width=10**6)
        except (yaml.YAMLError, RecursionError):
            text = mutate_text(rng, text)
    else:
        text = mutate_text(rng, text)
    if rng.random() < 0.1:
        text = mutate_text(rng, text)
    return text


# ---------------------------------------------------------------------------------------------
# Commands and their options. Kinds: num (number + unit), int, member, member=num, A=B, path,
# flag, range (START:END:STEP), or a list of choices.

TRAIN_MEMBERS = ["sun", "ring", "carrier", "planet", "ring1", "ring2", "s", "c", "r", "x", "sun1", "sun2", "arm"]
MATERIALS = ["18CrNiMo7-6", "16MnCr5", "42CrMo4", "C45", "42CrMo4-induction", "31CrMoV9-nitrided", "S355",
             "GJL-250", "GJS-700", "case_carburized:MQ:700", "steel", "x:y:z"]
FACTORS = ["K_v", "K_Hbeta", "K_Halpha", "K_Fbeta", "Z_NT1", "Y_NT1", "Y_F", "J1", "K_A", "Z_E", "x"]

# The rating options that `gear` (with a pair) and `gear size` share (docs/rating.md).
RATING = {
    "--torque1": "num:N*m", "--power": "num:kW", "--speed1": "num:rpm", "--material1": MATERIALS,
    "--material2": MATERIALS, "--method": ["iso6336", "agma", "lewis-hertz", "x"], "--application-factor": "num:",
    "--life": "num:h", "--oil-viscosity": "num:", "--flank-roughness": "num:", "--flank-rz": "num:",
    "--root-roughness": "num:", "--protuberance": "num:", "--f-pb": "num:", "--f-falpha": "num:",
    "--F-betax": "num:", "--f-ma": "num:", "--f-sh": "num:", "--tip-relief": "num:", "--rim1": "num:mm",
    "--rim2": "num:mm", "--min-safety-pitting": "num:", "--min-safety-bending": "num:", "--limited-pitting": "flag",
    "--optimum-long-life": "flag", "--root-shift": ["generating", "nominal", "x"], "--agma-quality": "int",
    "--reliability": "num:", "--mounting": ["open", "commercial", "precision", "extra-precision", "x"],
    "--crowned": "flag", "--lewis-profile": ["cast", "cut", "hobbed", "ground", "x"], "--factor": "factor"}
# Accuracy, inspection and backlash options of `gear` (docs/gear.md).
TOLERANCES = {
    "--quality": "grades", "--iso1328-edition": ["2013", "1995", "2020", "x"], "--thickness-allowances1": "pair",
    "--thickness-allowances2": "pair", "--din3967": ["27cd", "26cd,27cd", "25f", "29x", "x"],
    "--min-backlash": "num:mm", "--centre-distance-tolerance": ["js7", "js9", "js0", "js20", "x"],
    "--centre-distance-allowances": "pair", "--temperature": "pair", "--expansion": "triple"}
GEAR = {
    "--z1": "int", "--z2": "int", "--module": "num:mm", "--pressure-angle": "num:deg", "--helix-angle": "num:deg",
    "--x1": "num:", "--x2": "num:", "--centre-distance": "num:mm", "--center-distance": "num:mm",
    "--split": ["balanced", "proportional", "user"], "--internal": "flag", "--transverse": "flag",
    "--no-tip-shortening": "flag", "--addendum": "num:", "--dedendum": "num:", "--root-radius": "num:",
    "--face-width": "num:mm", "--backlash": "num:mm", "--allowance1": "num:mm", "--allowance2": "num:mm",
    "--centre-distance-deviation": "num:mm", "--pin-diameter": "num:mm", "--pin-diameter1": "num:mm",
    "--pin-diameter2": "num:mm", "--svg": "path", "--dxf": "path", "--draw": ["pair", "gear1", "gear2", "x"],
    "--tolerance": "num:um", "--cutter-teeth": "int", "--cutter-tip-radius": "num:mm"}
SIZE = {
    "--ratio": "num:", "--ratio-tolerance": "num:", "--modules": "list", "--z1-min": "int", "--z1-max": "int",
    "--shifts": "list", "--helix-angle": "num:deg", "--pressure-angle": "num:deg", "--width-ratio-max": "num:",
    "--width-module-min": "num:", "--count": "int", "--quality": "grades"}
SYNTH_TASKS = {"crank_rocker": "crank-rocker", "dwell": "dwell", "five_positions": "motion",
               "four_positions": "motion", "three_positions": "motion", "two_positions": "motion",
               "function_log10": "function", "function_slider": "function", "path_ellipse": "path"}

# Each command: "files" (an examples/ folder for the FILE argument, or None), "base" (words always
# given), "task" (words before the file: a subcommand chosen from the file's name) and "options".
COMMANDS = {
    "gear": {"files": None, "base": ["--z1", "12", "--z2", "24", "--module", "3"],
             "options": dict(GEAR, **TOLERANCES, **RATING)},
    "gear file": {"files": "gears", "base": [], "options": dict(TOLERANCES, **RATING, **{
        k: GEAR[k] for k in ("--svg", "--dxf", "--draw", "--tolerance", "--cutter-teeth", "--cutter-tip-radius")})},
    "gear size": {"files": None, "base": ["--ratio", "3.5", "--torque1", "500N*m", "--speed1", "1450rpm", "--material1",
                                          "18CrNiMo7-6", "--material2", "18CrNiMo7-6"],
                  "options": dict(RATING, **SIZE)},
    "train": {"files": "trains", "base": [], "options": {
        "--fix": "member", "--couple": "A=B", "--input": "member=num:rpm", "--output-member": "member",
        "--torque": "member=num:N*m", "--power": "member=num:kW", "--mesh-efficiency": "plain", "--modes": "flag",
        "--centre-tolerance": "num:mm", "--rate": "flag", "--willis": "names"}},
    "train synth": {"files": None, "base": ["reducer", "--m1", "2", "--m2", "2", "--ratio", "1/12"], "options": {
        "--ratio": "num:", "--tolerance": "plain", "--z-min": "int", "--z-max": "int", "--max-results": "int",
        "--m1": "num:mm", "--m2": "num:mm", "--z1": "int", "--equal-stages": "flag"}},
    "train synth planetary": {"files": None, "base": ["planetary", "--ratio", "1/5"], "options": {
        "--ratio": "num:", "--tolerance": "plain", "--z-min": "int", "--z-max": "int", "--max-results": "int",
        "--planets": "int", "--fixed": ["sun", "carrier", "ring", "x"], "--input": ["sun", "carrier", "ring"],
        "--output-member": ["sun", "carrier", "ring"], "--z-ring-max": "int"}},
    "cam": {"files": "cams", "base": [], "options": {
        "--dxf": "path", "--dxf-lines-arcs": "flag", "--svg": "path", "--follower-at": "num:deg", "--plot": "path",
        "--csv": "path", "--cutter-radius": "num:mm", "--dynamics-plot": "path", "--dyn": "path", "--gcode": "path",
        "--gcode-form": ["xy", "polar", "x"], "--feed": "num:mm/min"}},
    "kin": {"files": "mechanisms", "base": [], "options": {
        "--at": "num:deg", "--sweep": "range", "--driver": ["crank", "input", "x", "theta2"], "--outputs": ["x", "a,b"],
        "--plot": "path", "--animate": "path", "--equations": "flag", "--branch": ["continue", "switch", "other", ""]}},
    "kin example": {"files": None, "base": ["--example"], "options": {"--equations": "flag", "--at": "num:deg"}},
    "dyn": {"files": "dynamics", "base": [], "options": {"--plot": "path", "--speed-plot": "path"}},
    "synth": {"files": "synthesis", "base": [], "task": SYNTH_TASKS, "options": {
        "--mechanism": "path", "-m": "path", "--drawing": "path", "--plot": "path", "--seed": "int",
        "--evaluations": "int", "--restarts": "int"}},
    "demo": {"files": None, "base": [], "options": {"--output": "dir", "-o": "dir"}, "common": False},
    "plugins": {"files": None, "base": [], "options": {}},
    # The global options before the command word: --plugin FILE, --version, --help, help COMMAND.
    "global": {"files": None, "base": [], "options": {}, "common": False},
}
WEIGHTS = {"gear": 2.5, "gear file": 1, "gear size": 1, "train": 3.5, "train synth": 1, "train synth planetary": 1,
           "cam": 3, "kin": 2.5, "kin example": 0.5, "dyn": 3, "synth": 1.5, "demo": 0.15, "plugins": 0.2,
           "global": 0.2}
COMMON = {"--format": ["text", "json", "json", "csv", "md", "xml"], "--strict": "flag", "--output": "path"}


def typed_number(rng, unit):
    """A number for an option whose default unit is `unit`: mostly its own unit or none."""
    roll = rng.random()
    if roll < 0.45:
        return random_number(rng)
    if roll < 0.85 and unit:
        return random_number(rng) + " " + unit
    return random_quantity(rng)


def option_value(rng, kind, scratch, input_path):
    if isinstance(kind, list):
        return rng.choice(kind) if rng.random() < 0.95 else "x"
    if kind == "int":
        return rng.choice(["1", "2", "3", "5", "8", "12", "17", "20", "24", "60", "150", "200", "401", "1000",
                           "100000", "100001", "0", "-3", "1e3", "2147483648", "x"])
    if kind == "plain":
        return random_number(rng)
    if kind in ("pair", "triple", "list"):
        count = {"pair": 2, "triple": 3}.get(kind, rng.randint(1, 6))
        count += rng.choice([0, 0, 0, -1, 1])
        return ",".join(random_number(rng) for _ in range(max(count, 0)))
    if kind == "grades":
        return ",".join(rng.choice(["1", "5", "6", "7", "11", "12", "0", "-1", "x", "7.5"])
                        for _ in range(rng.choice([1, 1, 2, 3])))
    if kind == "factor":
        return f"{rng.choice(FACTORS)}={random_number(rng)}"
    if kind == "chain":
        return "chain:" + rng.choice(["0", "1", "2", "10", "100", "10000", "10001", "x", "-1", "1e3", ""])
    if kind == "names":
        return ",".join(rng.choice(TRAIN_MEMBERS) for _ in range(rng.randint(1, 4)))
    if kind == "dir":
        return rng.choice([os.path.join(scratch, "demo"), os.path.join(scratch, "existing.txt"),
                           os.path.join(scratch, "nodir", "x", "y"), os.path.join(scratch, "link-to-input"),
                           scratch, "-", "/dev/null", os.path.join(scratch, "demo-with-folder")]
                          + ([""] if rng.random() < 0.2 else []))
    if kind.startswith("num:"):
        return typed_number(rng, kind[4:])
    if kind == "member":
        return rng.choice(TRAIN_MEMBERS)
    if kind.startswith("member=num:"):
        return f"{rng.choice(TRAIN_MEMBERS)}={typed_number(rng, kind[11:])}"
    if kind == "A=B":
        return f"{rng.choice(TRAIN_MEMBERS)}={rng.choice(TRAIN_MEMBERS)}"
    if kind == "range":
        return ":".join(random_quantity(rng).replace(" ", "") if rng.random() < 0.2 else random_number(rng)
                        for _ in range(rng.choice([3, 3, 3, 3, 2, 4])))
    if kind == "path":
        return rng.choice([os.path.join(scratch, "out.txt"), os.path.join(scratch, "existing.txt"),
                           os.path.join(scratch, "nodir", "x.svg"), os.path.join(scratch, "link-to-input"),
                           input_path or os.path.join(scratch, "out2.txt"), scratch, "-", "/dev/null",
                           "/dev/full", os.path.join(scratch, "out.txt"), os.path.join(scratch, "out.svg"),
                           os.path.join(scratch, "out.dxf"), os.path.join(scratch, "out.csv")]
                          + ([""] if rng.random() < 0.2 else []))
    raise ValueError(kind)


REPEATABLE = {"--fix", "--couple", "--input", "--torque", "--power", "--factor"}


def names_in(text):
    """The names a model defines (members, gears, drivers, outputs), for options that take one."""
    try:
        tree = yaml.safe_load(text) if text else None
    except yaml.YAMLError:
        return []
    names = []
    for path, value in scalar_paths(tree) if isinstance(tree, (dict, list)) else []:
        if isinstance(value, str) and path and (path[-1] == "name" or (len(path) == 2 and path[0] == "members")):
            names.append(value)
    return names


def random_options(rng, spec, scratch, input_path, names, given):
    options = dict(spec["options"], **(COMMON if spec.get("common", True) else {}))
    args, used = [], set(given)
    for _ in range(rng.choice([0, 1, 1, 2, 2, 3, 4]) if options else 0):
        name = rng.choice(list(options))
        if name in used and name not in REPEATABLE:
            continue
        used.add(name)
        kind = options[name]
        args.append(name)
        if kind == "flag":
            continue
        value = option_value(rng, kind, scratch, input_path)
        if names and isinstance(kind, str) and (kind in ("member", "A=B") or kind.startswith("member=")) \
                and rng.random() < 0.8:
            value = re.sub(r"^[^=]*", rng.choice(names), value)
            if kind == "A=B":
                value = value.split("=")[0] + "=" + rng.choice(names)
        elif names and name in ("--driver", "--outputs") and rng.random() < 0.8:
            value = rng.choice(names)
        elif names and kind == "names" and rng.random() < 0.8:
            value = ",".join(rng.choice(names) for _ in range(rng.randint(1, 4)))
        args.append(value)
    if "--format" not in used and rng.random() < 0.5:
        args += ["--format", "json"]
    return args


# ---------------------------------------------------------------------------------------------
# One case

class Case:
    """A command line (with {input} and {scratch} placeholders) and an optional input file."""

    def __init__(self, command, args, input_text=None, note="", stdout_to=None, folder=None):
        self.command, self.args, self.input_text, self.note = command, args, input_text, note
        self.stdout_to, self.folder = stdout_to, folder

    def to_json(self):
        return {"command": self.command, "args": self.args, "input": self.input_text, "note": self.note,
                "stdout_to": self.stdout_to, "folder": self.folder}

    @staticmethod
    def from_json(d):
        return Case(d["command"], d["args"], d.get("input"), d.get("note", ""), d.get("stdout_to"), d.get("folder"))


def example_files(folder):
    root = os.path.join(EXAMPLES, folder)
    return sorted(os.path.join(root, f) for f in os.listdir(root) if f.endswith(".yaml"))


def generate_case(rng):
    command = rng.choices(list(WEIGHTS), weights=list(WEIGHTS.values()))[0]
    spec = COMMANDS[command]
    input_text = None
    args = list(spec["base"])
    if command == "kin example":
        args.append(option_value(rng, "chain", "{scratch}", None))
    if command == "global":
        for _ in range(rng.choice([0, 1, 1, 2])):
            args += ["--plugin", rng.choice(["{scratch}/existing.txt", "/dev/null", "{scratch}/nodir/x.so", "{scratch}",
                                             "libc.so.6", "gearkit-gear.so", "{scratch}/fifo.so", ""])]
        args += rng.choice([["plugins"], ["gear", "--z1", "12", "--z2", "24", "--module", "3"], ["--version"],
                            ["--help"], ["help"], ["help", "train"], ["help", "x"], ["frobnicate"], [], ["--x"]])
    if spec["files"]:
        path = rng.choice(example_files(spec["files"]))
        with open(path, encoding="utf-8") as f:
            input_text = f.read()
        if rng.random() < 0.7:
            input_text = mutate_file(rng, input_text)
        task = []
        if "task" in spec:  # the subcommand the file is for, now and then another one
            stem = os.path.splitext(os.path.basename(path))[0]
            tasks = sorted(set(spec["task"].values())) + ["x"]
            task = [spec["task"][stem] if rng.random() < 0.9 else rng.choice(tasks)]
        args = task + ["{input}"] + args
    elif len(args) > 2 and rng.random() < 0.1:
        i = rng.randrange(len(args) // 2) * 2 + len(args) % 2  # an option and its value
        del args[i:i + 2]
    placeholder_scratch, placeholder_input = "{scratch}", ("{input}" if input_text is not None else None)
    args += random_options(rng, spec, placeholder_scratch, placeholder_input, names_in(input_text), set(args))
    return Case(command, args, input_text, folder=spec["files"])


# The words on the command line of a fuzzer command that is not named as typed.
COMMAND_WORDS = {"gear file": "gear", "kin example": "kin", "train synth planetary": "train synth", "global": ""}


def prepare(case, scratch):
    """Writes the case's files into `scratch`; returns (argv, input path or None)."""
    input_path = None
    if case.folder:  # models that name other files (a dyn model its mechanism) find them
        for path in example_files(case.folder):
            shutil.copy(path, scratch)
    if case.input_text is not None:
        input_path = os.path.join(scratch, "model.yaml")
        with open(input_path, "w", encoding="utf-8", errors="surrogatepass") as f:
            f.write(case.input_text)
        os.symlink("model.yaml", os.path.join(scratch, "link-to-input"))
    with open(os.path.join(scratch, "existing.txt"), "w") as f:
        f.write("existing\n")
    os.makedirs(os.path.join(scratch, "demo-with-folder", "cam.svg"), exist_ok=True)  # demo: a folder in the way
    os.mkfifo(os.path.join(scratch, "fifo.so"))  # --plugin: must be refused without blocking
    argv = COMMAND_WORDS.get(case.command, case.command).split() + [
        a.replace("{input}", input_path or "").replace("{scratch}", scratch) for a in case.args]
    return argv, input_path


def limits(memory_mb):
    def apply():
        os.setsid()
        if memory_mb:
            resource.setrlimit(resource.RLIMIT_AS, (memory_mb << 20, memory_mb << 20))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    return apply


STDOUT_CHECKED = 4 << 20  # bytes of a report parsed (a parsed JSON takes ten times its size here)


def execute(exe, argv, scratch, stdout_to, timeout, memory_mb, env):
    """(status or -signal or None on timeout, stdout, stderr, seconds, peak RSS in MB)."""
    out_path = stdout_to or os.path.join(scratch, ".stdout")
    err_path = os.path.join(scratch, ".stderr")
    start = time.monotonic()
    with open(out_path, "wb") as out, open(err_path, "wb") as err:
        proc = subprocess.Popen([exe] + argv, stdin=subprocess.DEVNULL, stdout=out, stderr=err, cwd=scratch,
                                env=env, preexec_fn=limits(memory_mb))
        status, rss = None, 0
        while True:
            pid, raw, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                status = os.waitstatus_to_exitcode(raw)
                rss = usage.ru_maxrss / 1024
                proc.returncode = status
                break
            if time.monotonic() - start > timeout:
                os.killpg(proc.pid, signal.SIGKILL)
                os.wait4(proc.pid, 0)
                proc.returncode = -9
                break
            time.sleep(0.003)
    seconds = time.monotonic() - start
    # A report of millions of rows (kin --sweep allows 1e7 positions) is not read whole: the
    # fuzzer's own size would count in the next child's peak RSS (a fork copies it before exec).
    stdout = b""
    if not stdout_to:
        with open(out_path, "rb") as f:
            stdout = f.read(STDOUT_CHECKED + 1)
    return status, stdout, open(err_path, "rb").read(), seconds, rss


NONFINITE_TEXT = re.compile(r"(?<![\w.])[-+]?(nan|inf)(?![\w])", re.IGNORECASE)


def strict_json(text):
    def refuse(name):
        raise ValueError(f"non-standard JSON constant {name}")
    return json.loads(text, parse_constant=refuse)


# JSON nulls with a documented meaning (docs/cli.md): "none", "at infinity", "not applicable".
DOCUMENTED_NULLS = [re.compile(p) for p in (
    r"\.rho_concave_min_mm$",            # docs/cam.md: no concave part
    r"\.(outer_wall|conjugate_cam)\.rho_min_mm$",  # docs/cam.md: the other surface has no convex part
    r"\.instant_centres\.[^.]+$",         # docs/kin.md: a link in pure translation
    r"\.modes\[\d+\]\.(exact|value)$",   # docs/train.md: the mode has no ratio (message says why)
)]


def null_path(node, path=""):
    """The path of the first JSON null without a documented meaning, or None."""
    if node is None:
        return None if any(p.search(path) for p in DOCUMENTED_NULLS) else (path or "(document)")
    items = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else []
    for k, v in items:
        # docs/rating.md: a life is null with life_unlimited: true (the stress below the knee).
        if v is None and isinstance(node, dict) and k in ("life_h", "life_H_h", "life_F_h") and node.get("life_unlimited") is True:
            continue
        # docs/kin.md: on a change point the Lagrange effort is null (Phi_q singular, multipliers
        # indeterminate) and the position says so.
        if v is None and isinstance(node, dict) and k == "driving_torque_lagrange_Nm" and node.get("on_change_point") is True:
            continue
        found = null_path(v, f"{path}.{k}" if isinstance(node, dict) else f"{path}[{k}]")
        if found:
            return found
    return None


def stderr_problem(status, lines):
    """A description of a broken stderr rule, or None."""
    for line in lines:
        if not line.startswith("gearkit: "):
            return f"line without 'gearkit: ': {line[:80]!r}"
        if len(line) > 600:
            return f"line of {len(line)} characters"
    errors = [l for l in lines if not l.startswith("gearkit: warning: ")]
    if status in (0, 3) and errors:
        return f"non-warning line on success: {errors[0][:80]!r}"
    if status == 2:
        if not lines or lines[-1].startswith("gearkit: warning: "):
            return "status 2 without a reason as the last line"
        if len(errors) > 1 and not all("plugin" in e for e in errors):
            return f"{len(errors)} error lines"
    return None


def report_problem(argv, stdout, model=None):
    """'json' or 'nonfinite' with a detail, or (None, None) for a sound report on stdout. `model`:
    the input file's bytes, whose own names ("name: -inf") the report may echo."""
    if len(stdout) > STDOUT_CHECKED:
        return None, None  # too long to parse here; the format tests check long reports
    text = stdout.decode("utf-8", "replace")
    fmt = argv[argv.index("--format") + 1] if "--format" in argv[:-1] else "text"
    to_stdout = all(a not in ("-", "/dev/stdout") for a in argv)
    for flag in ("--output", "-o"):
        if flag in argv[:-1] and argv[argv.index(flag) + 1] != "-":
            to_stdout = False
    if not to_stdout:
        return None, None
    if "help" in argv[:1] or "--help" in argv or "-h" in argv:  # help is text, whatever --format says
        return None, None
    if "--example" in argv:  # kin --example writes a mechanism file, whatever --format says
        try:
            yaml.safe_load(text)
        except yaml.YAMLError as e:
            return "json", f"--example wrote invalid YAML: {str(e)[:100]}"
        return None, None
    if fmt == "json":
        try:
            doc = strict_json(text)
        except ValueError as e:
            return "json", str(e)[:120]
        warnings = doc.get("warnings") if isinstance(doc, dict) else None
        where = null_path(doc)
        if where and not warnings:
            return "nonfinite", f"JSON null with no warning at {where}"
        return None, None
    echoed = NONFINITE_TEXT.findall(model.decode("utf-8", "replace")) if model else []
    found = [m.group(0) for m in NONFINITE_TEXT.finditer(text) if m.group(1) not in echoed]
    if fmt in ("text", "md", "csv") and found:
        if re.search(r"^Warnings: none$", text, re.MULTILINE) or "Warnings" not in text:
            return "nonfinite", found[0]
    return None, None


def classify(case, result, input_before, input_after, options):
    status, stdout, stderr, seconds, rss = result
    lines = stderr.decode("utf-8", "replace").splitlines()
    argv = case.args
    if status is None or status == -9 and seconds >= options.timeout:
        return "timeout", f"{seconds:.1f} s"
    if status in SANITIZER_STATUS or any("Sanitizer" in l or "runtime error:" in l for l in lines):
        return "sanitizer", next((l for l in lines if "Sanitizer" in l or "runtime error" in l), "")[:160]
    if status < 0:
        return "crash", f"signal {-status}"
    if status == 1 and any("out of memory" in l for l in lines) or rss > options.max_rss_mb:
        return "memory", f"peak RSS {rss:.0f} MB"
    if status not in (0, 2, 3):
        return "exit1", (lines[-1] if lines else f"status {status}")[:160]
    problem = stderr_problem(status, lines)
    if problem:
        return "stderr", problem
    if input_before is not None and input_before != input_after:
        return "input", "the model file changed"
    if status in (0, 3):
        kind, detail = report_problem(argv, stdout, input_before)
        if kind:
            return kind, detail
    if seconds > options.slow:
        return "slow", f"{seconds:.1f} s"
    return f"ok{status}", (lines[-1] if lines else "")


def run_case(case, options):
    scratch = tempfile.mkdtemp(prefix="case-", dir=options.work)
    try:
        argv, input_path = prepare(case, scratch)
        before = open(input_path, "rb").read() if input_path else None
        stdout_to = case.stdout_to
        result = execute(options.exe, argv, scratch, stdout_to, options.timeout, options.memory_mb, options.env)
        after = open(input_path, "rb").read() if input_path and os.path.exists(input_path) else None
        outcome, detail = classify(case, result, before, after, options)
        return case, outcome, detail, result[3], result[4], argv
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


# ---------------------------------------------------------------------------------------------
# Campaign

def load_corpus(folder):
    cases = []
    for name in sorted(os.listdir(folder)) if folder and os.path.isdir(folder) else []:
        if name.endswith(".json"):
            with open(os.path.join(folder, name), encoding="utf-8") as f:
                cases.append(Case.from_json(json.load(f)))
    return cases


def print_table(table, out):
    width = max(len(c) for c in table) + 2
    out.write("command".ljust(width) + " ".join(c.rjust(9) for c in COLUMNS) + "\n")
    for command in sorted(table, key=lambda c: (c == "total", c)):
        out.write(command.ljust(width) + " ".join(str(table[command].get(c, 0)).rjust(9) for c in COLUMNS) + "\n")


def save_failure(folder, index, case, outcome, detail):
    os.makedirs(folder, exist_ok=True)
    d = case.to_json()
    d["note"] = f"{outcome}: {detail}"
    with open(os.path.join(folder, f"{outcome}-{index:06d}.json"), "w", encoding="utf-8") as f:
        json.dump(d, f, indent=1, ensure_ascii=False)


def parse_arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--exe", required=True)
    p.add_argument("--cases", type=int, default=300)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--corpus", default=os.path.join(HERE, "corpus"))
    p.add_argument("--save", default=None, help="folder for the failing cases (corpus format)")
    p.add_argument("--timeout", type=float, default=10.0)
    p.add_argument("--slow", type=float, default=3.0)
    p.add_argument("--sanitizer", action="store_true", help="the executable is built with ASan/UBSan")
    p.add_argument("--work", default=None, help="scratch folder (default: a temporary one)")
    p.add_argument("--show", type=int, default=20, help="failing cases listed")
    p.add_argument("--reasons", type=int, default=0, help="list the N commonest reasons for status 2")
    p.add_argument("--replay", default=None, help="prepare one saved case in a kept folder and run it")
    o = p.parse_args()
    o.exe = os.path.abspath(o.exe)
    o.env = dict(os.environ, LC_ALL="C")
    if o.sanitizer:
        # Shadow memory makes RLIMIT_AS useless; ASan's own limits stand in for it.
        o.memory_mb, o.max_rss_mb = 0, 3000
        o.env["ASAN_OPTIONS"] = "exitcode=86:hard_rss_limit_mb=3000:allocator_may_return_null=1:detect_leaks=1"
        o.env["UBSAN_OPTIONS"] = "exitcode=87:halt_on_error=1:print_stacktrace=1"
        o.env["LSAN_OPTIONS"] = "exitcode=23"
    else:
        # docs/cli.md: every run stays under "a few hundred MB"; the largest documented limits
        # (a kin sweep of 500,000 coordinate-positions, 4,000 drawn teeth) need about 250 MB.
        o.memory_mb, o.max_rss_mb = 4096, 512
    return o


def replay(o):
    with open(o.replay, encoding="utf-8") as f:
        case = Case.from_json(json.load(f))
    scratch = tempfile.mkdtemp(prefix="gearkit-replay-")
    argv, _ = prepare(case, scratch)
    print(f"cd {scratch} && {o.exe} " + " ".join(repr(a) for a in argv))
    status, out, err, seconds, rss = execute(o.exe, argv, scratch, case.stdout_to, o.timeout, o.memory_mb, o.env)
    print(f"status {status}, {seconds:.2f} s, {rss:.0f} MB\n{err.decode('utf-8', 'replace')[-2000:]}")
    return 0


def main():
    o = parse_arguments()
    if o.replay:
        return replay(o)
    rng = random.Random(o.seed)
    cases = load_corpus(o.corpus) + [generate_case(rng) for _ in range(o.cases)]
    own_work = o.work is None
    o.work = o.work or tempfile.mkdtemp(prefix="gearkit-fuzz-")
    os.makedirs(o.work, exist_ok=True)
    table, failures, reasons = {}, [], collections.Counter()
    started = time.monotonic()
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=o.jobs) as pool:
            for index, (case, outcome, detail, seconds, rss, argv) in enumerate(pool.map(lambda c: run_case(c, o), cases)):
                for row in (case.command, "total"):
                    entry = table.setdefault(row, {"cases": 0, "max s": 0.0, "max MB": 0.0})
                    entry["cases"] += 1
                    entry[outcome] = entry.get(outcome, 0) + 1
                    entry["max s"] = max(entry["max s"], round(seconds, 2))
                    entry["max MB"] = max(entry["max MB"], round(rss))
                if outcome == "ok2":
                    reasons[(case.command, re.sub(r"'[^']*'|\d+|/\S+", "_", detail)[:90])] += 1
                if outcome in FAILING:
                    failures.append((index, case, outcome, detail, argv))
                if o.save and (outcome in FAILING or outcome == "slow"):
                    save_failure(o.save, index, case, outcome, detail)  # slow ones too, to look at
    finally:
        if own_work:
            shutil.rmtree(o.work, ignore_errors=True)
    print(f"gearkit fuzz: {len(cases)} cases ({len(cases) - o.cases} from the corpus), seed {o.seed}, "
          f"{time.monotonic() - started:.0f} s, {o.exe}")
    print_table(table, sys.stdout)
    for index, case, outcome, detail, argv in failures[: o.show]:
        print(f"case {index}: {outcome}: {detail}\n  gearkit {' '.join(map(repr, argv))}")
    for (command, reason), n in reasons.most_common(o.reasons):
        print(f"{n:6d}  {command}: {reason}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
