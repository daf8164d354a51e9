#!/usr/bin/env python3
"""Checks the library search path (DT_RUNPATH / DT_RPATH) of every ELF file in a build tree and
in a scratch install of it.

glibc reads an empty entry ("$ORIGIN/../lib:" or "::::") and a relative entry ("lib") as a folder
relative to the *working directory*: a library planted there would be loaded by anyone running
gearkit in it. Every entry must therefore be absolute or start with $ORIGIN.

Usage: check_runpath.py BUILD_DIR SCRATCH_DIR
  checks BUILD_DIR, then installs it with `cmake --install BUILD_DIR --prefix SCRATCH_DIR/prefix`
  and checks that prefix. Exit 0 when every entry is sound, 1 with one line per bad entry.
"""
import os
import shutil
import struct
import subprocess
import sys

PT_LOAD, PT_DYNAMIC = 1, 2
DT_NULL, DT_STRTAB, DT_RPATH, DT_RUNPATH = 0, 5, 15, 29
# Folders of the build tree that hold other projects or scratch copies (checked elsewhere or
# written while this test runs).
SKIP_DIRS = {"test-scratch", "oot", "runpath-scratch", ".git"}


def dynamic_search_paths(path):
    """[(tag name, string)] of DT_RPATH/DT_RUNPATH of an ELF file, [] for an ELF without them,
    None when the file is not ELF."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"\x7fELF":
        return None
    is64 = data[4] == 2
    end = "<" if data[5] == 1 else ">"
    if is64:
        phoff, = struct.unpack_from(end + "Q", data, 0x20)
        phentsize, phnum = struct.unpack_from(end + "HH", data, 0x36)
        ph_fmt, dyn_fmt = end + "IIQQQQQQ", end + "qQ"
    else:
        phoff, = struct.unpack_from(end + "I", data, 0x1C)
        phentsize, phnum = struct.unpack_from(end + "HH", data, 0x2A)
        ph_fmt, dyn_fmt = end + "IIIIIIII", end + "iI"
    loads, dynamic = [], None
    for i in range(phnum):
        fields = struct.unpack_from(ph_fmt, data, phoff + i * phentsize)
        if is64:
            p_type, _, p_offset, p_vaddr, _, p_filesz, _, _ = fields
        else:
            p_type, p_offset, p_vaddr, _, p_filesz, _, _, _ = fields
        if p_type == PT_LOAD:
            loads.append((p_vaddr, p_offset, p_filesz))
        elif p_type == PT_DYNAMIC:
            dynamic = (p_offset, p_filesz)
    if dynamic is None:
        return []
    entries, strtab = [], None
    size = struct.calcsize(dyn_fmt)
    for off in range(dynamic[0], dynamic[0] + dynamic[1], size):
        tag, val = struct.unpack_from(dyn_fmt, data, off)
        if tag == DT_NULL:
            break
        if tag == DT_STRTAB:
            strtab = val
        elif tag in (DT_RPATH, DT_RUNPATH):
            entries.append(("RUNPATH" if tag == DT_RUNPATH else "RPATH", val))
    if not entries:
        return []
    base = next(off + strtab - vaddr for vaddr, off, size in loads if vaddr <= strtab < vaddr + size)
    out = []
    for name, index in entries:
        start = base + index
        out.append((name, data[start:data.index(b"\0", start)].decode()))
    return out


def bad_entries(search_path):
    """The entries of a ':'-separated search path that depend on the working directory."""
    bad = []
    for entry in search_path.split(":"):
        if entry == "":
            bad.append("an empty entry (the working directory)")
        elif not (entry.startswith("/") or entry.startswith("$ORIGIN") or entry.startswith("${ORIGIN}")):
            bad.append(f"'{entry}' (relative to the working directory)")
    return bad


def check_tree(root):
    """(number of ELF files with a dynamic section read, list of problem lines)."""
    checked, problems = 0, []
    for folder, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS]
        for name in files:
            path = os.path.join(folder, name)
            if os.path.islink(path) or not os.path.isfile(path):
                continue
            paths = dynamic_search_paths(path)
            if paths is None:
                continue
            checked += 1
            for tag, value in paths:
                for bad in bad_entries(value):
                    problems.append(f"{path}: {tag} '{value}' has {bad}")
    return checked, problems


def readelf_runpath(path):
    """RUNPATH as binutils' readelf prints it, an independent reading of the same section."""
    if shutil.which("readelf") is None:
        return None
    text = subprocess.run(["readelf", "-d", path], capture_output=True, text=True, check=True).stdout
    for line in text.splitlines():
        if "(RUNPATH)" in line:
            return line.split("[", 1)[1].rsplit("]", 1)[0]
    return ""


def self_test():
    """The checker must reject what CMake produced before the fix."""
    assert bad_entries("$ORIGIN/../lib:"), "a trailing empty entry must be refused"
    assert bad_entries("::::::"), "padding colons must be refused"
    assert bad_entries("lib"), "a relative entry must be refused"
    assert not bad_entries("$ORIGIN/../lib"), "an $ORIGIN entry is sound"
    assert not bad_entries("/usr/lib/x"), "an absolute entry is sound"


def main():
    build, scratch = sys.argv[1], sys.argv[2]
    self_test()
    exe = os.path.join(build, "bin", "gearkit")
    parsed = dict(dynamic_search_paths(exe) or [])
    expected = readelf_runpath(exe)
    if expected is not None and parsed.get("RUNPATH", "") != expected:
        print(f"{exe}: parsed RUNPATH '{parsed.get('RUNPATH')}' but readelf says '{expected}'")
        return 1
    if not parsed.get("RUNPATH", "").startswith("$ORIGIN"):
        print(f"{exe}: expected a RUNPATH relative to $ORIGIN, found {parsed}")
        return 1

    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    prefix = os.path.join(scratch, "prefix")
    subprocess.run(["cmake", "--install", build, "--prefix", prefix], check=True, stdout=subprocess.DEVNULL)
    status = 0
    for root, minimum in ((build, 10), (prefix, 8)):
        checked, problems = check_tree(root)
        for p in problems:
            print(p)
        print(f"{root}: {checked} ELF files read, {len(problems)} bad search-path entries")
        if problems or checked < minimum:
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
