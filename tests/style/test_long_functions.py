#!/usr/bin/env python3
"""scripts/long_functions.py finds a long function in any source folder, including a library
added after the script was written (issue 12: libelements, libsym, libsynth were not scanned),
and skips build trees. Exit 0 when it does."""
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                      "scripts", "long_functions.py")


def function(name, lines):
    return f"int {name}() {{\n" + "".join(f"  int v{i} = {i};\n" for i in range(lines - 3)) + "  return 0;\n}\n"


def main():
    with tempfile.TemporaryDirectory() as root:
        for folder, name in (("libnew/src", "new_library_function"), ("plugins/p", "plugin_function"),
                             ("build-x/gen", "generated_function")):
            os.makedirs(os.path.join(root, folder))
            with open(os.path.join(root, folder, "a.cpp"), "w") as f:
                f.write(function(name, 90) + function("short_" + name, 10))
        allow = os.path.join(root, "empty.allow")
        open(allow, "w").close()
        r = subprocess.run([sys.executable, SCRIPT, "--check", "--root", root, "--allowlist", allow],
                           capture_output=True, text=True)
        problems = []
        if r.returncode != 1:
            problems.append(f"--check exited {r.returncode}, expected 1")
        for expected in ("libnew/src/a.cpp:1: function 'new_library_function' is 90 lines long",
                         "plugins/p/a.cpp:1: function 'plugin_function' is 90 lines long"):
            if expected not in r.stdout:
                problems.append(f"missing: {expected}")
        for unexpected in ("generated_function", "short_"):
            if unexpected in r.stdout:
                problems.append(f"reported {unexpected} (a build tree or a short function)")
        for p in problems:
            print("test_long_functions:", p, "\n", r.stdout, r.stderr)
        return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
