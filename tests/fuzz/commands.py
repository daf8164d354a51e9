"""The commands the gearkit fuzzer (tests/fuzz/fuzz.py) runs and their options."""
import os
import re

import yaml

from mutate import random_number, random_quantity, scalar_paths

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
    except (yaml.YAMLError, RecursionError, ValueError, TypeError):
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
