"""The gearkit fuzzer's strategies beyond tree and text mutation (issue 26, Acceptance):

  help      options read from each command's own --help (names and value shapes), so that an
            option added later is fuzzed without an edit here
  inplace   a scalar's text changed where it stands in the file (comments, quoting and layout
            kept): digits, signs, exponents, units and look-alike characters
  graph     the YAML node graph edited: subtrees moved, duplicated (written as anchor + alias),
            deleted, merged with '<<', made to contain themselves
  encoding  the file in UTF-16/UTF-32 (with and without BOM), UTF-8 with BOM, Latin-1, with invalid
            UTF-8 sequences, NUL bytes, CR or CRLF line ends
  env       odd environments (TMPDIR, GEARKIT_PLUGIN_PATH, HOME, locale), standard streams
            (closed stdin/stdout/stderr, stdout on /dev/full or on a pipe nobody reads) and signals
            (SIGINT, SIGTERM, SIGHUP, SIGPIPE after a delay)
  cross     one command's model file fed to another command
"""
import copy
import re

import yaml

# ---------------------------------------------------------------------------------------------
# help: options read from --help

HELP_LINE = re.compile(r"^  (?:-\w \[ )?(--[a-z0-9][a-z0-9-]*)(?: \])?(?: ([^ ].*?))?(?:  |$)")


def parse_help(text):
    """{option: metavar or ''} of one command's --help text (global --help/--version left out)."""
    found = {}
    for line in text.splitlines():
        m = HELP_LINE.match(line)
        if m and m.group(1) not in ("--help", "--version"):
            found[m.group(1)] = (m.group(2) or "").split(" (=")[0]
    return found


HELP_NUMBERS = ["0", "1", "-1", "2.5", "20", "1e9", "1e-9", "nan", "inf", "1e400", "x", "", "3,5", "1/0"]
HELP_UNITS = ["", "mm", "deg", "rpm", "N*m", "kW", "s", "um", "µm", "μm", "rad^0", "N*m*rad^0", "1/s", "%", "in"]


def help_value(rng, metavar, scratch, input_path, names):
    """A value shaped like the help's metavar (FILE, N, A=B, x|y|z, START:END:STEP, ...), or not."""
    if rng.random() < 0.08:
        return rng.choice(["", "-", "--", "--help", "=", "x" * 300, "\u00a0", "\x7f", "-1", "--format"])
    if "|" in metavar:
        return rng.choice(metavar.split("|") + ["x", metavar])
    if "FILE" in metavar or "OUT" in metavar or metavar == "DIR":
        ext = metavar.rsplit(".", 1)[1] if "." in metavar else "txt"
        return rng.choice([f"{scratch}/out.{ext}", f"{scratch}/existing.txt", f"{scratch}/nodir/x.{ext}",
                           input_path or f"{scratch}/out2.txt", scratch, "-", "/dev/null", "/dev/full",
                           f"{scratch}/link-to-input", "", "/proc/self/fd/1"])  # no FIFO: one is written
    # as docs/cli.md says, so it waits for a reader as `cat > FIFO` does
    number = rng.choice(HELP_NUMBERS) + (rng.choice(HELP_UNITS) if rng.random() < 0.6 else "")
    if ":" in metavar:
        return ":".join(rng.choice(HELP_NUMBERS) for _ in range(metavar.count(":") + rng.choice([0, 0, 1, -1])))
    if "=" in metavar:
        left = rng.choice(names or ["sun", "x"]) if rng.random() < 0.8 else "x"
        return f"{left}={number if rng.random() < 0.7 else rng.choice(names or ['ring'])}"
    if "," in metavar:
        pool = names if names and "M" in metavar else HELP_NUMBERS
        return ",".join(rng.choice(pool) for _ in range(rng.randint(0, 4)))
    if metavar in ("N", "Z", "SEED") or metavar.endswith("N"):
        return rng.choice(["0", "1", "3", "12", "150", "1000000", "-2", "2147483648", "1.5", "x"])
    if metavar in ("MEMBER", "NAME", "M", "TASK", "KIND"):
        return rng.choice((names or []) + ["x", "", "sun"])
    return number


def help_options(rng, help_table, command_words, scratch, input_path, names):
    """1 to 4 options of the command's --help with values, some repeated, some unknown."""
    table = help_table.get(command_words) or {}
    if not table:
        return []
    args = []
    for _ in range(rng.choice([1, 1, 2, 3, 4])):
        name = rng.choice(sorted(table))
        if rng.random() < 0.04:
            name = name[:-1] if len(name) > 3 else name + "x"  # a near miss: named in the error?
        metavar = table.get(name, "X")
        if not metavar:
            args.append(name)
        elif rng.random() < 0.15:
            args.append(f"{name}={help_value(rng, metavar, scratch, input_path, names)}")
        else:
            args += [name, help_value(rng, metavar, scratch, input_path, names)]
    return args


# ---------------------------------------------------------------------------------------------
# inplace: scalars edited where they stand

LOOKALIKES = ["\u03bcm", "\u00b5m", "\u00a0", "\u2212", "\u2009", "\uff11", "\u0660", "\u200b", "\u00b0", "\u2032",
              "\u00d7", "\u00b7", "\u2044", "\ufeff", "\u0301", "\U0001f600"]


def scalar_spans(text, keys=False):
    """(start, end) character offsets of every scalar value (and key) in the first document."""
    try:
        node = yaml.compose(text, Loader=yaml.SafeLoader)
    except (yaml.YAMLError, RecursionError, ValueError, TypeError):
        return []
    spans, stack, seen = [], [node] if node is not None else [], set()
    while stack:
        n = stack.pop()
        if id(n) in seen:
            continue
        seen.add(id(n))
        if isinstance(n, yaml.ScalarNode):
            if n.end_mark.index > n.start_mark.index:
                spans.append((n.start_mark.index, n.end_mark.index))
        elif isinstance(n, yaml.SequenceNode):
            stack.extend(n.value)
        elif isinstance(n, yaml.MappingNode):
            for k, v in n.value:
                stack += [k, v] if keys else [v]
    return sorted(spans)


def edit_scalar(rng, s):
    """One small edit of a scalar's text."""
    digits = [i for i, c in enumerate(s) if c.isdigit()]
    roll = rng.randrange(14)
    if roll in (0, 12, 13) and digits:  # the commonest: one digit changed, the rest still valid
        i = rng.choice(digits)
        return s[:i] + rng.choice("0123456789") + s[i + 1:]
    if roll == 1 and digits:
        i = rng.choice(digits)
        return s[:i] + s[i] * rng.choice([2, 5, 40, 400]) + s[i + 1:]
    if roll == 2:
        return ("-" + s) if not s.startswith("-") else s[1:]
    if roll == 3 and digits:
        i = digits[-1] + 1
        return s[:i] + rng.choice(["e308", "e-308", "e99999", "e", ".", "..5", "e+", "_000"]) + s[i:]
    if roll == 4:
        return re.sub(r"[A-Za-z%*/^]+.*$", lambda m: rng.choice(["mm", "m", "um", "\u03bcm", "\u00b5m", "deg", "rad",
                                                                 "rpm", "N*m*rad^0", "N*m^0", "kN", "mm^2",
                                                                 "1/min", "", "mm mm", "xx"]), s, count=1)
    if roll == 5:
        i = rng.randrange(len(s) + 1)
        return s[:i] + rng.choice(LOOKALIKES) + s[i:]
    if roll == 6:
        i = rng.randrange(len(s) + 1)
        return s[:i] + s[i:][1:]
    if roll == 7:
        return s + rng.choice([" # comment", "  ", ",", "]", "}", ": x", " &a", " !!str", "'"])
    if roll == 8:
        return rng.choice(["'" + s + "'", '"' + s + '"', "!!float " + s, "!!int " + s, "!!str " + s, "? " + s])
    if roll == 9:
        return s.upper() if rng.random() < 0.5 else s.replace(" ", "")
    if roll == 10:
        return rng.choice(["0x1F", "0o17", "1_000", "+.5", "1.", ".Inf", "-.NaN", "1:30", "2026-01-01", "~", "y", "No"])
    return s * 2


def mutate_inplace(rng, text):
    spans = scalar_spans(text, keys=rng.random() < 0.1)
    for _ in range(rng.choice([1, 1, 2, 3]) if spans else 0):
        start, end = rng.choice(spans)
        replacement = edit_scalar(rng, text[start:end])
        text = text[:start] + replacement + text[end:]
        spans = [(a, b) for a, b in spans if b <= start] + \
                [(a + len(replacement) - (end - start), b + len(replacement) - (end - start)) for a, b in spans if a >= end]
    return text


# ---------------------------------------------------------------------------------------------
# graph: the node graph edited, written back with anchors and aliases

def containers(node, out, depth=0):
    if depth > 40 or any(node is n for n in out):
        return out
    if isinstance(node, (yaml.MappingNode, yaml.SequenceNode)):
        out.append(node)
        for child in (v for _, v in node.value) if isinstance(node, yaml.MappingNode) else node.value:
            containers(child, out, depth + 1)
    return out


def children(node):
    return [v for _, v in node.value] if isinstance(node, yaml.MappingNode) else list(node.value)


def graph_edit(rng, root):
    """One edit of the node graph; a node placed twice is written as an anchor and an alias."""
    nodes = containers(root, [])
    target = rng.choice(nodes)
    donor = rng.choice(nodes)
    items = children(donor)
    piece = rng.choice(items) if items else donor
    action = rng.choice(["alias", "alias", "move", "delete", "copy", "cycle", "merge", "wrap"])
    if action in ("alias", "copy", "move", "cycle"):
        placed = {"alias": piece, "copy": copy.deepcopy(piece), "move": piece, "cycle": target}[action]
        if action == "move" and isinstance(donor, yaml.MappingNode) and donor.value:
            donor.value = [kv for kv in donor.value if kv[1] is not piece]
        elif action == "move" and donor.value:
            donor.value = [v for v in donor.value if v is not piece]
        if isinstance(target, yaml.MappingNode):
            if target.value and rng.random() < 0.6:  # replace a value
                i = rng.randrange(len(target.value))
                target.value[i] = (target.value[i][0], placed)
            else:
                target.value.append((yaml.ScalarNode("tag:yaml.org,2002:str", rng.choice(["x", "name", "extra"])),
                                     placed))
        else:
            target.value.insert(rng.randint(0, len(target.value)), placed)
    elif action == "delete" and target.value:
        del target.value[rng.randrange(len(target.value))]
    elif action == "merge" and isinstance(target, yaml.MappingNode):
        source = rng.choice([n for n in nodes if isinstance(n, yaml.MappingNode)])
        target.value.insert(0, (yaml.ScalarNode("tag:yaml.org,2002:merge", "<<"), source))
    elif action == "wrap" and target.value:
        i = rng.randrange(len(target.value))
        if isinstance(target, yaml.MappingNode):
            k, v = target.value[i]
            target.value[i] = (k, yaml.SequenceNode("tag:yaml.org,2002:seq", [v]))
        else:
            target.value[i] = yaml.MappingNode("tag:yaml.org,2002:map", [
                (yaml.ScalarNode("tag:yaml.org,2002:str", "value"), target.value[i])])


def share_equal_scalars(rng, nodes):
    """Equal scalar values become one node (written once with an anchor, then as aliases): the same
    document to a reader that follows aliases, so the case should pass where the original does."""
    groups = {}
    for node in nodes:
        pairs = node.value if isinstance(node, yaml.MappingNode) else [(None, v) for v in node.value]
        for _, v in pairs:
            if isinstance(v, yaml.ScalarNode) and v.value:
                groups.setdefault((v.tag, v.value, v.style), []).append(v)
    shared = [g for g in groups.values() if len(g) > 1]
    if not shared:
        return
    first = rng.choice(shared)[0]
    key = (first.tag, first.value, first.style)
    for node in nodes:
        if isinstance(node, yaml.MappingNode):
            node.value = [(k, first if isinstance(v, yaml.ScalarNode) and (v.tag, v.value, v.style) == key else v)
                          for k, v in node.value]
        else:
            node.value = [first if isinstance(v, yaml.ScalarNode) and (v.tag, v.value, v.style) == key else v
                          for v in node.value]


def mutate_graph(rng, text):
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except (yaml.YAMLError, RecursionError, ValueError, TypeError):
        return text
    if not isinstance(root, (yaml.MappingNode, yaml.SequenceNode)):
        return text
    try:
        if rng.random() < 0.35:
            share_equal_scalars(rng, containers(root, []))
        else:
            for _ in range(rng.choice([1, 1, 2, 3])):
                graph_edit(rng, root)
        text = yaml.serialize(root, allow_unicode=True, width=10**6)
    except (yaml.YAMLError, RecursionError, ValueError, TypeError):
        return text
    if rng.random() < 0.05:  # nesting deeper than any model: the reader's recursion
        depth = rng.choice([100, 1000, 10000, 100000])
        text += rng.choice(["deep: ", "- "]) + "[" * depth + "]" * depth + "\n"
    return text


# ---------------------------------------------------------------------------------------------
# encoding: the bytes of the file

ENCODINGS = ["utf-16", "utf-16-le", "utf-16-be", "utf-32", "utf-8-sig", "latin-1", "cp1252", "raw"]
INVALID_UTF8 = ["\udcff", "\udcc0\udcaf", "\udce0\udc80\udc80", "\udced\udca0\udc80", "\udcf4\udc90\udc80\udc80",
                "\udcc3", "\udcfe\udcff", "\udc80"]


def mutate_encoding(rng, text):
    """(text, encoding): the case's file written in `encoding` ('raw': utf-8 with surrogateescape,
    so that the lone surrogates U+DC80..U+DCFF inserted here become invalid UTF-8 bytes)."""
    roll = rng.random()
    if roll < 0.3:
        pos = rng.randrange(len(text) + 1)
        return text[:pos] + rng.choice(INVALID_UTF8) + text[pos:], "raw"
    if roll < 0.45:
        pos = rng.randrange(len(text) + 1)
        return text[:pos] + "\x00" * rng.choice([1, 1, 4]) + text[pos:], None
    if roll < 0.6:
        return text.replace("\n", rng.choice(["\r\n", "\r", "\n\r", "\u2028", "\x85"])), None
    if roll < 0.7:
        return "\ufeff" + text.replace("\n", "\n\ufeff", rng.choice([0, 1])), None
    encoding = rng.choice(ENCODINGS[:-1])
    if encoding in ("latin-1", "cp1252"):
        text = text.replace("#", "# é µ ±", 1) if "#" in text else "# é µ ±\n" + text
    return text, encoding


def encode_input(text, encoding):
    if encoding == "raw":
        return text.encode("utf-8", "surrogateescape")
    if encoding:
        return text.encode(encoding, "replace")
    return text.encode("utf-8", "surrogatepass")


# ---------------------------------------------------------------------------------------------
# env: environment and standard streams

ENV_CHOICES = {
    "TMPDIR": ["", "relative/tmp", "{scratch}/existing.txt", "{scratch}/nodir", "/proc", "/dev/null", "{scratch}/fifo.so",
               "{scratch}/" + "d" * 250, "/", "{scratch}/with space", None],
    "GEARKIT_PLUGIN_PATH": ["", ":", "::", ".", "relative", "{scratch}", "{scratch}/existing.txt", "/dev/null",
                            "{scratch}/nodir", "{scratch}/fifo.so", "{scratch}/writable", "{scratch}/writable:.",
                            "/proc/self", "{scratch}/" + "p" * 300, "{plugins}", "{plugins}:{plugins}"],
    "HOME": [None, "", "/nonexistent", "{scratch}/existing.txt"],
    "LC_ALL": ["C.UTF-8", "POSIX", "tr_TR.UTF-8", "de_DE.UTF-8", "xx_XX", ""],
    "LANG": [None, "C.UTF-8", "de_DE.UTF-8"],
    "COLUMNS": ["0", "-1", "1", "99999999999", "x"],
    "PATH": [None, "", "{scratch}"],
}
STREAMS = {"stdin": ["closed", "closed", "tty-less pipe", "directory"],
           "stdout": ["closed", "closed", "closed", "full", "broken pipe", "null"],
           "stderr": ["closed", "full"],
           # a signal to the process group after a delay (fuzz.execute): no temporary may stay
           "signal": ["INT:0.02", "TERM:0.05", "HUP:0.1", "TERM:0.2", "PIPE:0.05", "INT:0.005"]}


def random_environment(rng):
    """({name: value or None to unset}, {stream: how}) for an env case."""
    env, streams = {}, {}
    for _ in range(rng.choice([0, 1, 1, 2])):
        name = rng.choice(sorted(ENV_CHOICES))
        env[name] = rng.choice(ENV_CHOICES[name])
    for _ in range(rng.choice([0, 1, 1, 1, 2])):
        name = rng.choice(["stdin", "stdout", "stdout", "stdout", "stderr", "signal", "signal"])
        streams[name] = rng.choice(STREAMS[name])
    if not env and not streams:
        streams["stdout"] = "closed"
    return env, streams
