#!/usr/bin/python3
"""Renders gearkit's pages and drawings the way readers see them (ctest render.html_and_pdf):

- `--format html` pages of `train` and `cam` (with their SVG pictures) loaded by headless Chromium
  through scripts/html-check.sh: no console message (script error, failed resource), the DOM holds
  the report's tables by id, one inline <svg> per picture written, the warnings section and the
  version; a screenshot is written next to each page;
- the gear and cam DXF drawings printed to PDF by LibreCAD's dxf2pdf through scripts/dxf-to-pdf.sh:
  one page each, rendered to PNG.
The PNGs stay in --work for a person to look at. Exit status 0 when every check holds, else 1.
"""
import argparse
import os
import re
import subprocess
import sys


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300, **kw)


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
        ("train", [a.exe, "train", ex("trains/simple_planetary.yaml"), "--torque", "sun=10", "--svg", w("train.svg"),
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
