#!/usr/bin/python3
"""Independent check of a DXF file written by gearkit, with ezdxf (Debian's python3-ezdxf).

Usage: ezdxf_check.py FILE.dxf [--points CSV [--x-column NAME --y-column NAME] --layer NAME --tol MM]

Loads the file with ezdxf, runs its audit and prints one JSON object:
  {"dxfversion": "AC1015", "insunits": 4, "audit_errors": [...], "audit_fixes": [...],
   "entities": {"layer": {"LWPOLYLINE": 1, ...}}, "closed_polylines": {"layer": n},
   "max_deviation_mm": d, "max_gap_mm": g, "handles_unique": true}
With --points, every point of CSV (the named columns, else the first two; '#' comments and a header
allowed) must lie on the geometry of layer NAME (polylines with bulges, lines, arcs, circles as
ezdxf reads them back) within MM; max_deviation_mm is the largest distance found and max_gap_mm the largest distance
from the read-back geometry to the nearest given point (so a missing piece of profile is caught).
Exit status: 0 when the audit finds no errors and the deviations are within tolerance, 1 otherwise,
2 for a file ezdxf cannot read.
"""
import argparse
import json
import math
import sys

import ezdxf
from ezdxf.math import bulge_to_arc


def read_points(csv_path, x_column, y_column):
    """Points from two columns of a CSV (by header name), or from its first two columns."""
    points = []
    ix, iy = 0, 1
    with open(csv_path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            cells = line.split(",")
            if x_column and x_column in cells and y_column in cells:
                ix, iy = cells.index(x_column), cells.index(y_column)
                continue
            try:
                points.append((float(cells[ix]), float(cells[iy])))
            except (ValueError, IndexError):
                continue  # header row
    return points


def arc_primitive(cx, cy, r, start_rad, end_rad):
    """A counter-clockwise arc as (\"arc\", cx, cy, r, start, sweep) with 0 < sweep <= 2 pi."""
    sweep = (end_rad - start_rad) % (2 * math.pi)
    if sweep == 0:
        sweep = 2 * math.pi
    return ("arc", cx, cy, r, start_rad, sweep)


def layer_primitives(msp, layer):
    """Exact geometry of the layer as line segments and circular arcs (no Bezier approximation:
    ezdxf's paths approximate arcs by cubic curves, 2.7e-4 r off, too coarse for this check)."""
    prims = []
    for e in msp.query(f'*[layer=="{layer}"]'):
        kind = e.dxftype()
        if kind == "LINE":
            prims.append(("seg", e.dxf.start.x, e.dxf.start.y, e.dxf.end.x, e.dxf.end.y))
        elif kind == "CIRCLE":
            prims.append(arc_primitive(e.dxf.center.x, e.dxf.center.y, e.dxf.radius, 0.0, 2 * math.pi))
        elif kind == "ARC":
            prims.append(arc_primitive(e.dxf.center.x, e.dxf.center.y, e.dxf.radius,
                                       math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)))
        elif kind == "LWPOLYLINE":
            pts = list(e.get_points("xyb"))
            n = len(pts)
            last = n if e.closed else n - 1
            for i in range(last):
                x0, y0, b = pts[i]
                x1, y1, _ = pts[(i + 1) % n]
                if b == 0 or (x0 == x1 and y0 == y1):
                    prims.append(("seg", x0, y0, x1, y1))
                else:
                    center, start, end, radius = bulge_to_arc((x0, y0), (x1, y1), b)
                    prims.append(arc_primitive(center.x, center.y, radius, start, end))
    return prims


def arc_point(p, t):
    _, cx, cy, r, start, sweep = p
    return cx + r * math.cos(start + t * sweep), cy + r * math.sin(start + t * sweep)


def distance_to(p, px, py):
    if p[0] == "seg":
        _, ax, ay, bx, by = p
        dx, dy = bx - ax, by - ay
        length2 = dx * dx + dy * dy
        t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / length2))
        return math.hypot(px - (ax + t * dx), py - (ay + t * dy))
    _, cx, cy, r, start, sweep = p
    if (math.atan2(py - cy, px - cx) - start) % (2 * math.pi) <= sweep:
        return abs(math.hypot(px - cx, py - cy) - r)
    return min(math.hypot(px - x, py - y) for x, y in (arc_point(p, 0), arc_point(p, 1)))


def bounding_box(p):
    if p[0] == "seg":
        _, ax, ay, bx, by = p
        return min(ax, bx), min(ay, by), max(ax, bx), max(ay, by)
    _, cx, cy, r, start, sweep = p
    xs, ys = zip(*(arc_point(p, t) for t in (0.0, 1.0)))
    xs, ys = list(xs), list(ys)
    for q in range(8):  # quadrant points within the sweep (two turns cover a start near 2 pi)
        a = q * math.pi / 2
        if start <= a <= start + sweep:
            xs.append(cx + r * math.cos(a))
            ys.append(cy + r * math.sin(a))
    return min(xs), min(ys), max(xs), max(ys)


def sample(p, spacing):
    """Points along a primitive at most `spacing` apart."""
    if p[0] == "seg":
        _, ax, ay, bx, by = p
        n = max(1, int(math.ceil(math.hypot(bx - ax, by - ay) / spacing)))
        return [(ax + (bx - ax) * i / n, ay + (by - ay) * i / n) for i in range(n + 1)]
    n = max(1, int(math.ceil(p[3] * p[5] / spacing)))
    return [arc_point(p, i / n) for i in range(n + 1)]


class Grid:
    """Uniform grid over primitives so that nearest-primitive queries stay fast for dense curves."""

    def __init__(self, prims, cell):
        self.cell = cell
        self.cells = {}
        self.prims = prims
        for i, p in enumerate(prims):
            x0, y0, x1, y1 = bounding_box(p)
            for gx in range(int(math.floor(x0 / cell)), int(math.floor(x1 / cell)) + 1):
                for gy in range(int(math.floor(y0 / cell)), int(math.floor(y1 / cell)) + 1):
                    self.cells.setdefault((gx, gy), []).append(i)

    def nearest(self, px, py):
        gx, gy = int(math.floor(px / self.cell)), int(math.floor(py / self.cell))
        best = math.inf
        ring = 0
        while ring < 10000:
            for x in range(gx - ring, gx + ring + 1):
                for y in range(gy - ring, gy + ring + 1):
                    if max(abs(x - gx), abs(y - gy)) != ring:
                        continue
                    for i in self.cells.get((x, y), ()):
                        best = min(best, distance_to(self.prims[i], px, py))
            # Anything in a farther ring is at least ring * cell away.
            if best <= ring * self.cell:
                return best
            ring += 1
        return best


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("dxf")
    parser.add_argument("--points")
    parser.add_argument("--layer", default="profile")
    parser.add_argument("--tol", type=float, default=1e-3)
    parser.add_argument("--x-column")
    parser.add_argument("--y-column")
    args = parser.parse_args()

    try:
        doc = ezdxf.readfile(args.dxf)
    except (IOError, ezdxf.DXFStructureError) as error:
        print(json.dumps({"read_error": str(error)}))
        return 2

    auditor = doc.audit()
    msp = doc.modelspace()
    entities = {}
    closed = {}
    handles = []
    for e in msp:
        layer = e.dxf.layer
        entities.setdefault(layer, {})
        entities[layer][e.dxftype()] = entities[layer].get(e.dxftype(), 0) + 1
        handles.append(e.dxf.handle)
        if e.dxftype() == "LWPOLYLINE" and e.closed:
            closed[layer] = closed.get(layer, 0) + 1
    result = {
        "dxfversion": doc.dxfversion,
        "insunits": doc.header.get("$INSUNITS", 0),
        "audit_errors": [str(x.message) for x in auditor.errors],
        "audit_fixes": [str(x.message) for x in auditor.fixes],
        "entities": entities,
        "closed_polylines": closed,
        "handles_unique": len(handles) == len(set(handles)),
    }
    ok = not auditor.errors and result["handles_unique"]

    if args.points:
        points = read_points(args.points, args.x_column, args.y_column)
        prims = layer_primitives(msp, args.layer)
        if not points or not prims:
            result["max_deviation_mm"] = None
            ok = False
        else:
            span = max(max(abs(x), abs(y)) for x, y in points) or 1.0
            grid = Grid(prims, span / 50)
            result["max_deviation_mm"] = max(grid.nearest(x, y) for x, y in points)
            # The reverse direction: the read-back geometry stays near the given points (nothing
            # stray, no piece missing between them).
            spacing = max(math.hypot(points[i + 1][0] - points[i][0], points[i + 1][1] - points[i][1])
                          for i in range(len(points) - 1)) if len(points) > 1 else 0.0
            pgrid = Grid([("seg", x, y, x, y) for x, y in points], span / 50)
            gap = max(pgrid.nearest(x, y) for p in prims for x, y in sample(p, max(spacing, 1e-3)))
            result["max_gap_mm"] = gap
            result["point_spacing_mm"] = spacing
            ok = ok and result["max_deviation_mm"] <= args.tol and gap <= spacing + args.tol
    result["ok"] = ok
    print(json.dumps(result))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
