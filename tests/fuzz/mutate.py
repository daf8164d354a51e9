"""Model-file mutations of the gearkit fuzzer (tests/fuzz/fuzz.py): values, YAML tree edits and
raw-text damage; tests/fuzz/strategies.py adds in-place, graph and encoding mutations."""
import copy
import random
import re

import yaml

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
    except (yaml.YAMLError, RecursionError, ValueError, TypeError):  # a key "!!int members"
        tree = None
    if isinstance(tree, (dict, list)) and rng.random() < 0.8:
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            mutate_tree(rng, tree)
        try:
            text = yaml.safe_dump(tree, sort_keys=False, allow_unicode=True, width=10**6)
        except (yaml.YAMLError, RecursionError, ValueError, TypeError):
            text = mutate_text(rng, text)
    else:
        text = mutate_text(rng, text)
    if rng.random() < 0.1:
        text = mutate_text(rng, text)
    return text
