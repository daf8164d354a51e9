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
  output        a half-written output: a temporary file left behind, a file written (or an
                existing one changed) by a run that failed, an SVG/DXF/JSON file cut short
  where         exit 2 whose message names no file:line:column, option or argument
  slow          informative only: longer than --slow seconds

Strategies (a case's "strategy"): "tree" and "text" mutations of the model (mutate.py), and the
options of tests/fuzz/commands.py; issue 26 added options read from --help, in-place scalar
edits, YAML graph edits (anchors, aliases, merges, cycles), encodings, environment and stream
variations and cross-fed model files (strategies.py).

Usage: fuzz.py --exe build/bin/gearkit [--cases N] [--seed S] [--jobs J] [--corpus DIR]
               [--save DIR] [--sanitizer] [--timeout SEC]
Exit status 0 when no case falls in a failing class (every class but ok*, slow).
"""
import argparse
import collections
import concurrent.futures
import contextlib
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

from commands import COMMANDS, WEIGHTS, names_in, option_value, random_options
from mutate import mutate_file
import outputs
import strategies

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
EXAMPLES = os.path.join(SOURCE, "examples")
FAILING = ["exit1", "crash", "sanitizer", "timeout", "memory", "stderr", "json", "nonfinite", "input", "output",
           "where"]
COLUMNS = ["cases", "ok0", "ok2", "ok3"] + FAILING + ["slow", "max s", "max MB"]
SANITIZER_STATUS = {86: "asan", 87: "ubsan", 23: "lsan"}

# ---------------------------------------------------------------------------------------------
# One case

class Case:
    """A command line (with {input} and {scratch} placeholders), an optional input file (written in
    `encoding`, see strategies.encode_input), environment changes (a value None unsets) and
    standard streams (strategies.STREAMS), and the strategy that made it."""

    def __init__(self, command, args, input_text=None, note="", stdout_to=None, folder=None, encoding=None,
                 env=None, streams=None, strategy="tree"):
        self.command, self.args, self.input_text, self.note = command, args, input_text, note
        self.stdout_to, self.folder, self.encoding = stdout_to, folder, encoding
        self.env, self.streams, self.strategy = env or {}, streams or {}, strategy

    def to_json(self):
        d = {"command": self.command, "args": self.args, "input": self.input_text, "note": self.note,
             "stdout_to": self.stdout_to, "folder": self.folder, "strategy": self.strategy}
        for key in ("encoding", "env", "streams"):
            if getattr(self, key):
                d[key] = getattr(self, key)
        return d

    @staticmethod
    def from_json(d):
        return Case(d["command"], d["args"], d.get("input"), d.get("note", ""), d.get("stdout_to"), d.get("folder"),
                    d.get("encoding"), d.get("env"), d.get("streams"), d.get("strategy", "corpus"))


def example_files(folder):
    root = os.path.join(EXAMPLES, folder)
    return sorted(os.path.join(root, f) for f in os.listdir(root) if f.endswith(".yaml"))


# Strategies and their shares of a campaign: "tree" and "text" are the mutations of issue 11
# (mutate.py), the others those of issue 26 (strategies.py).
STRATEGIES = {"tree": 3, "help": 2, "inplace": 2, "graph": 1.5, "encoding": 1, "env": 1.5, "cross": 1}


def pick_model(rng, command, spec, strategy):
    """(text, path) of the example the case starts from: the command's own, or for "cross" one
    written for another command."""
    folders = sorted({c["files"] for c in COMMANDS.values() if c["files"]})
    folder = rng.choice([f for f in folders if f != spec["files"]]) if strategy == "cross" else spec["files"]
    path = rng.choice(example_files(folder))
    with open(path, encoding="utf-8") as f:
        return f.read(), path


def mutate_model(rng, text, strategy):
    """The model text under `strategy`, and the encoding it is written in."""
    if strategy == "inplace":
        return strategies.mutate_inplace(rng, text), None
    if strategy == "graph":
        return strategies.mutate_graph(rng, text), None
    if strategy == "encoding":
        return strategies.mutate_encoding(rng, mutate_file(rng, text) if rng.random() < 0.3 else text)
    if strategy in ("tree", "help") and rng.random() < 0.7 or strategy in ("env", "cross") and rng.random() < 0.3:
        return mutate_file(rng, text), None
    return text, None


def generate_case(rng, help_table=None):
    strategy = rng.choices(list(STRATEGIES), weights=list(STRATEGIES.values()))[0]
    if strategy == "help" and not help_table:
        strategy = "tree"
    command = rng.choices(list(WEIGHTS), weights=list(WEIGHTS.values()))[0]
    spec = COMMANDS[command]
    while strategy in ("inplace", "graph", "encoding", "cross") and not spec["files"]:
        command = rng.choices(list(WEIGHTS), weights=list(WEIGHTS.values()))[0]
        spec = COMMANDS[command]
    input_text, encoding = None, None
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
        input_text, path = pick_model(rng, command, spec, strategy)
        input_text, encoding = mutate_model(rng, input_text, strategy)
        task = []
        if "task" in spec:  # the subcommand the file is for, now and then another one
            stem = os.path.splitext(os.path.basename(path))[0]
            tasks = sorted(set(spec["task"].values())) + ["x"]
            task = [spec["task"].get(stem, "path") if rng.random() < 0.9 else rng.choice(tasks)]
        args = task + ["{input}"] + args
    elif len(args) > 2 and rng.random() < 0.1:
        i = rng.randrange(len(args) // 2) * 2 + len(args) % 2  # an option and its value
        del args[i:i + 2]
    placeholder_scratch, placeholder_input = "{scratch}", ("{input}" if input_text is not None else None)
    names = names_in(input_text)
    if strategy == "help":
        words = " ".join(COMMAND_WORDS.get(command, command).split()[:2])
        args += strategies.help_options(rng, help_table, words, placeholder_scratch, placeholder_input, names)
    elif strategy in ("tree", "env") or rng.random() < 0.4:  # a file strategy's case mostly tests the file alone
        args += random_options(rng, spec, placeholder_scratch, placeholder_input, names, set(args))
    env, streams = strategies.random_environment(rng) if strategy == "env" else ({}, {})
    return Case(command, args, input_text, folder=spec["files"], encoding=encoding, env=env, streams=streams,
                strategy=strategy)


def read_help(exe, env):
    """{command words: {option: metavar}} from `gearkit [COMMAND [SUB]] --help`."""
    table = {}
    for words in sorted({" ".join(COMMAND_WORDS.get(c, c).split()[:2]) for c in COMMANDS}):
        try:
            out = subprocess.run([exe] + words.split() + ["--help"], capture_output=True, env=env, timeout=30,
                                 stdin=subprocess.DEVNULL).stdout.decode("utf-8", "replace")
        except (OSError, subprocess.TimeoutExpired):
            continue
        table[words] = strategies.parse_help(out)
    return table


# The words on the command line of a fuzzer command that is not named as typed.
COMMAND_WORDS = {"gear file": "gear", "kin example": "kin", "train synth planetary": "train synth", "global": ""}


def prepare(case, scratch, exe):
    """Writes the case's files into `scratch`; returns (argv, input path or None, environment)."""
    input_path = None
    if case.folder:  # models that name other files (a dyn model its mechanism) find them
        for path in example_files(case.folder):
            shutil.copy(path, scratch)
    if case.input_text is not None:
        input_path = os.path.join(scratch, "model.yaml")
        with open(input_path, "wb") as f:
            f.write(strategies.encode_input(case.input_text, case.encoding))
        os.symlink("model.yaml", os.path.join(scratch, "link-to-input"))
    with open(os.path.join(scratch, "existing.txt"), "w") as f:
        f.write("existing\n")
    os.makedirs(os.path.join(scratch, "demo-with-folder", "cam.svg"), exist_ok=True)  # demo: a folder in the way
    os.mkfifo(os.path.join(scratch, "fifo.so"))  # --plugin: must be refused without blocking
    plugins = os.path.join(os.path.dirname(os.path.dirname(exe)), "lib", "gearkit", "plugins")

    def place(a):
        return a.replace("{input}", input_path or "").replace("{scratch}", scratch).replace("{plugins}", plugins)
    env = {}
    for name, value in case.env.items():
        env[name] = None if value is None else place(value)
        if "/writable" in (value or ""):  # a plugin folder and file anyone may write (issue 26, section 2)
            writable = os.path.join(scratch, "writable")
            os.makedirs(writable, exist_ok=True)
            shutil.copy(os.path.join(plugins, "gearkit-gear.so"), os.path.join(writable, "gearkit-extra.so"))
            os.chmod(writable, 0o777)
            os.chmod(os.path.join(writable, "gearkit-extra.so"), 0o666)
    argv = COMMAND_WORDS.get(case.command, case.command).split() + [place(a) for a in case.args]
    return argv, input_path, env


def limits(memory_mb, close=()):
    def apply():
        os.setsid()
        if memory_mb:
            resource.setrlimit(resource.RLIMIT_AS, (memory_mb << 20, memory_mb << 20))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        for fd in close:  # a closed standard stream (strategies.STREAMS)
            os.close(fd)
    return apply


STDOUT_CHECKED = 4 << 20  # bytes of a report parsed (a parsed JSON takes ten times its size here)


def stream_files(streams, scratch, out, err, stack):
    """(stdin, stdout, stderr, fds to close in the child) for the case's streams."""
    close, files = [], {}
    for fd, name, default in ((0, "stdin", subprocess.DEVNULL), (1, "stdout", out), (2, "stderr", err)):
        how = streams.get(name)
        if how == "closed":
            close.append(fd)
            files[name] = default
        elif how == "full":
            files[name] = stack.enter_context(open("/dev/full", "wb"))
        elif how == "null":
            files[name] = subprocess.DEVNULL
        elif how == "directory":
            files[name] = os.open(scratch, os.O_RDONLY)
            stack.callback(os.close, files[name])
        elif how in ("tty-less pipe", "broken pipe"):  # stdin at end of file; stdout that nobody reads
            r, w = os.pipe()
            keep, drop = (r, w) if fd == 0 else (w, r)
            os.close(drop)
            files[name] = keep
            stack.callback(os.close, keep)
        else:
            files[name] = default
    return files["stdin"], files["stdout"], files["stderr"], close


def execute(exe, argv, scratch, stdout_to, timeout, memory_mb, env, streams=None):
    """(status or -signal or None on timeout, stdout, stderr, seconds, peak RSS in MB)."""
    out_path = stdout_to or os.path.join(scratch, ".stdout")
    err_path = os.path.join(scratch, ".stderr")
    start = time.monotonic()
    with open(out_path, "wb") as out, open(err_path, "wb") as err, contextlib.ExitStack() as stack:
        stdin, stdout, stderr, close = stream_files(streams or {}, scratch, out, err, stack)
        proc = subprocess.Popen([exe] + argv, stdin=stdin, stdout=stdout, stderr=stderr, cwd=scratch,
                                env=env, preexec_fn=limits(memory_mb, close))
        status, rss = None, 0
        name, _, delay = (streams or {}).get("signal", "::").partition(":")
        while True:
            if name and time.monotonic() - start > float(delay):
                os.killpg(proc.pid, getattr(signal, "SIG" + name))
                name = ""
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


def case_environment(base, changes):
    env = dict(base)
    for name, value in changes.items():
        if value is None:
            env.pop(name, None)
        else:
            env[name] = value
    return env


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


def classify(case, result, input_before, input_after, options, output=None):
    """The outcome class and a detail. `output`: outputs.problem's finding on the files."""
    status, stdout, stderr, seconds, rss = result
    streams = case.streams
    lines = [] if "stderr" in streams else stderr.decode("utf-8", "replace").splitlines()
    argv = case.args
    if status is None or status == -9 and seconds >= options.timeout:
        return "timeout", f"{seconds:.1f} s"
    if status in SANITIZER_STATUS or any("Sanitizer" in l or "runtime error:" in l for l in lines):
        return "sanitizer", next((l for l in lines if "Sanitizer" in l or "runtime error" in l), "")[:160]
    sent = streams.get("signal", ":").split(":")[0]
    if status == -signal.SIGPIPE and streams.get("stdout") == "broken pipe" or sent and status in (
            -getattr(signal, "SIG" + sent), 128 + getattr(signal, "SIG" + sent)):  # a reader gone, a signal sent
        return ("output", output) if output else ("ok0", f"signal {-status}")
    if status < 0:
        return "crash", f"signal {-status}"
    if status == 1 and any("out of memory" in l for l in lines) or rss > options.max_rss_mb:
        return "memory", f"peak RSS {rss:.0f} MB"
    if status not in (0, 2, 3):
        return "exit1", (lines[-1] if lines else f"status {status}")[:160]
    problem = stderr_problem(status, lines) if "stderr" not in streams else None
    if problem:
        return "stderr", problem
    if input_before is not None and input_before != input_after:
        return "input", "the model file changed"
    if output:
        return "output", output
    if status == 2 and lines and not outputs.located(lines[-1]):
        return "where", lines[-1][:160]
    if status in (0, 3) and "stdout" not in streams:
        kind, detail = report_problem(argv, stdout, input_before)
        if kind:
            return kind, detail
    if seconds > options.slow:
        return "slow", f"{seconds:.1f} s"
    return f"ok{status}", (lines[-1] if lines else "")


def run_case(case, options):
    scratch = tempfile.mkdtemp(prefix="case-", dir=options.work)
    try:
        argv, input_path, env = prepare(case, scratch, options.exe)
        before = open(input_path, "rb").read() if input_path else None
        files_before = outputs.listing(scratch)
        stdout_to = case.stdout_to
        result = execute(options.exe, argv, scratch, stdout_to, options.timeout, options.memory_mb,
                         case_environment(options.env, env), case.streams)
        after = open(input_path, "rb").read() if input_path and os.path.exists(input_path) else None
        output = outputs.problem(scratch, files_before, result[0])
        outcome, detail = classify(case, result, before, after, options, output)
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
    for command in sorted(table, key=lambda c: (c == "total", c.startswith("strategy "), c)):
        out.write(command.ljust(width) + " ".join(str(table[command].get(c, 0)).rjust(9) for c in COLUMNS) + "\n")


def save_failure(folder, index, case, outcome, detail):
    os.makedirs(folder, exist_ok=True)
    d = case.to_json()
    d["note"] = f"{outcome}: {detail}"
    text = json.dumps(d, indent=1, ensure_ascii=False)
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:  # the lone surrogates of an invalid-UTF-8 case: written as \udcXX
        text = json.dumps(d, indent=1)
    with open(os.path.join(folder, f"{outcome}-{index:06d}.json"), "w", encoding="utf-8") as f:
        f.write(text)


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
    p.add_argument("--strategies", default=None, help="only these strategies (comma-separated): " + ",".join(STRATEGIES))
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
    argv, _, env = prepare(case, scratch, o.exe)
    print(f"cd {scratch} && {' '.join(f'{k}={v!r}' for k, v in env.items())} {o.exe} "
          + " ".join(repr(a) for a in argv) + (f"  # streams {case.streams}" if case.streams else ""))
    files = outputs.listing(scratch)
    status, out, err, seconds, rss = execute(o.exe, argv, scratch, case.stdout_to, o.timeout, o.memory_mb,
                                             case_environment(o.env, env), case.streams)
    print(f"status {status}, {seconds:.2f} s, {rss:.0f} MB, files: {outputs.problem(scratch, files, status)}\n"
          f"{err.decode('utf-8', 'replace')[-2000:]}")
    return 0


def main():
    o = parse_arguments()
    if o.replay:
        return replay(o)
    rng = random.Random(o.seed)
    for name in list(STRATEGIES) if o.strategies else []:
        if name not in o.strategies.split(","):
            del STRATEGIES[name]
    help_table = read_help(o.exe, o.env)
    cases = load_corpus(o.corpus) + [generate_case(rng, help_table) for _ in range(o.cases)]
    own_work = o.work is None
    o.work = o.work or tempfile.mkdtemp(prefix="gearkit-fuzz-")
    os.makedirs(o.work, exist_ok=True)
    table, failures, reasons = {}, [], collections.Counter()
    started = time.monotonic()
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=o.jobs) as pool:
            for index, (case, outcome, detail, seconds, rss, argv) in enumerate(pool.map(lambda c: run_case(c, o), cases)):
                for row in (case.command, f"strategy {case.strategy}", "total"):
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
