#!/usr/bin/python3
"""Renders gearkit's pages and drawings the way readers see them (ctest render.html_and_pdf):

- `--format html` pages of `train` and `cam` (with their SVG pictures) loaded by headless Chromium
  through scripts/html-check.sh: no console message (script error, failed resource), the DOM holds
  the report's tables by id, one inline <svg> per picture written, the warnings section and the
  version; a screenshot is written next to each page;
- the gear and cam DXF drawings printed to PDF by LibreCAD's dxf2pdf through scripts/dxf-to-pdf.sh:
  one page each, rendered to PNG. LibreCAD strokes text as lines (the PDF holds no text for
  pdftotext), so what it will draw is checked on the DXF as LibreCAD reads it: each TEXT's style
  names a LibreCAD font (LibreCAD picks the font by style name) holding a glyph for every
  character written (the Greek alpha_n, beta, rho_fP* of the gear data block drew as a lozenge in
  the "standard" font), and the data block's diameters equal the JSON report's.
The PNGs stay in --work for a person to look at. Exit status 0 when every check holds, else 1.
"""
import argparse
import json
import os
import re
import subprocess
import sys


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300, **kw)


LIBRECAD_FONTS = "/usr/share/librecad/fonts"


def dxf_texts(path):
    """(layer, style, text) of every TEXT entity, \\U+XXXX escapes decoded."""
    with open(path, encoding="cp1252") as f:
        lines = [l.rstrip("\r\n") for l in f]
    out, i = [], 0
    while i + 1 < len(lines):
        if lines[i].strip() == "0" and lines[i + 1] == "TEXT":
            tags, i = {}, i + 2
            while i + 1 < len(lines) and lines[i].strip() != "0":
                tags.setdefault(lines[i].strip(), lines[i + 1])
                i += 2
            text = re.sub(r"\\U\+([0-9A-Fa-f]{4})", lambda m: chr(int(m.group(1), 16)), tags.get("1", ""))
            out.append((tags.get("8", ""), tags.get("7", "Standard"), text))
        else:
            i += 2
    return out


def lff_glyphs(style):
    """Code points of the LibreCAD font LibreCAD takes for a text style, or None without one."""
    path = os.path.join(LIBRECAD_FONTS, style.lower() + ".lff")
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8", errors="replace") as f:
        return {int(m.group(1), 16) for m in re.finditer(r"^\[([0-9A-Fa-f]{4,6})\]", f.read(), re.M)}


def check_dxf_text(check, name, path):
    texts = dxf_texts(path)
    check(len(texts) > 10, f"{name}.dxf: {len(texts)} TEXT entities")
    for style in sorted({s for _, s, _ in texts}):
        glyphs = lff_glyphs(style)
        check(glyphs is not None, f"{name}.dxf: text style '{style}' is a LibreCAD font")
        missing = sorted({c for _, s, t in texts if s == style for c in t if c != " " and ord(c) not in (glyphs or set())})
        check(not missing, f"{name}.dxf: LibreCAD font '{style}' draws every character (missing: {''.join(missing)})")
    return texts


def check_gear_block(check, texts, report):
    """The data block (layer data_block) shows the report's diameters of both gears, to 3 decimals."""
    block = {t for layer, _, t in texts if layer == "data_block"}
    symbols = {"z", "m_n", "α_n", "β", "x", "d", "d_a", "d_b", "d_f", "W_k", "M_d", "a"}
    check(symbols <= block, f"gear.dxf data block has the symbols (missing: {sorted(symbols - block)})")
    for g in report["gears"]:
        for key in ("d_mm", "d_a_mm", "d_b_mm", "d_f_mm"):
            value = f"{g[key]:.3f}"
            check(value in block, f"gear.dxf data block shows {key} = {value} as the report")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    ex = lambda p: os.path.join(a.source, "examples", p)
    w = lambda p: os.path.join(a.work, p)
    scripts = os.path.join(a.source, "scripts")
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    pages = [
        ("train", [a.exe, "train", ex("trains/simple_planetary.yaml"), "--torque", "sun=10N*m", "--svg", w("train.svg"),
                   "--format", "html", "-o", w("train.html")], ["speeds", "torques", "assembly_conditions"], 1, "857.1429"),
        ("cam", [a.exe, "cam", ex("cams/translating_roller_cycloidal.yaml"), "--svg", w("cam.svg"), "--plot", w("plot.svg"),
                 "--format", "html", "-o", w("cam.html")], ["motion_program", "checks"], 2, "cycloidal"),
    ]
    for name, cmd, ids, pictures, number in pages:
        r = run(cmd)
        check(r.returncode == 0, f"gearkit {name} --format html: exit {r.returncode} {r.stderr.strip()}")
        r = run([os.path.join(scripts, "html-check.sh"), w(name + ".html"), w(name + "-page.png")])
        check(r.returncode == 0, f"{name}.html loads in Chromium without console messages {r.stderr.strip()[-300:]}")
        dom = r.stdout
        for i in ids:
            check(f'id="{i}' in dom, f"{name}.html: table '{i}' (key or key prefix) in the DOM")
        check(len(re.findall(r"<svg\b", dom)) == pictures, f"{name}.html: {pictures} inline SVG picture(s)")
        check('id="warnings"' in dom and "gearkit 0." in dom, f"{name}.html: warnings section and version")
        check(number in dom, f"{name}.html: '{number}' shown")
        check(os.path.getsize(w(name + "-page.png")) > 10000, f"{name}-page.png written")

    r1 = run([a.exe, "gear", "--z1", "20", "--z2", "40", "--module", "3", "--x1", "0.2", "--x2", "0.1", "--quality", "7",
              "--dxf", w("gear.dxf")])
    r2 = run([a.exe, "cam", ex("cams/translating_roller_cycloidal.yaml"), "--dxf", w("cam.dxf")])
    check(r1.returncode == 0 and r2.returncode == 0, "gear and cam DXF written")
    gear_texts = check_dxf_text(check, "gear", w("gear.dxf"))
    check_dxf_text(check, "cam", w("cam.dxf"))
    r = run([a.exe, "gear", "--z1", "20", "--z2", "40", "--module", "3", "--x1", "0.2", "--x2", "0.1", "--quality", "7",
             "--format", "json"])
    check_gear_block(check, gear_texts, json.loads(r.stdout))
    r = run([os.path.join(scripts, "dxf-to-pdf.sh"), w("pdf"), w("gear.dxf"), w("cam.dxf")])
    check(r.returncode == 0, f"LibreCAD dxf2pdf {r.stderr.strip()}")
    for name in ("gear", "cam"):
        pdf = w(os.path.join("pdf", name + ".pdf"))
        info = run(["pdfinfo", pdf]).stdout if os.path.exists(pdf) else ""
        check(re.search(r"^Pages:\s+1$", info, re.M) is not None, f"{name}.pdf has one page")
        png = w(os.path.join("pdf", name + ".png"))
        check(os.path.exists(png) and os.path.getsize(png) > 10000, f"{name}.png rendered from the PDF")
    print(f"pictures to look at: {a.work}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
