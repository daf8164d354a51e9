#!/usr/bin/python3
"""Reads a DXF file with ezdxf (an independent reader) and prints JSON for the drawing tests:
{"audit_errors": n, "texts": {layer: [text, ...]}, "circles": {layer: [[cx, cy, r], ...]},
 "polylines": {layer: n}, "lines": {layer: [[x1, y1, x2, y2], ...]},
 "text_at": {layer: [[text, x, y], ...]}, "polyline_shapes": {layer: [{"closed": bool, "points": [[x, y], ...],
 "bulges": [b, ...]}]}, "text_height": {layer: [h, ...]} (as text_at), "arcs": {layer: [[cx, cy, r, start_deg, end_deg]]}}.
Exit status 2 if ezdxf cannot read it."""
import json
import re
import sys

import ezdxf

try:
    doc = ezdxf.readfile(sys.argv[1])
except Exception as e:  # noqa: BLE001 - any reader failure is a failed check
    print(json.dumps({"error": str(e)}))
    sys.exit(2)
auditor = doc.audit()
out = {"audit_errors": len(auditor.errors), "texts": {}, "circles": {}, "polylines": {}, "lines": {}, "text_at": {},
       "polyline_shapes": {}, "text_height": {}, "arcs": {}}
for e in doc.modelspace():
    layer = e.dxf.layer
    if e.dxftype() == "TEXT":
        # R2000 files carry non-ASCII characters as \U+XXXX escapes (the DXF reference, TEXT group 1).
        text = re.sub(r"\\U\+([0-9A-Fa-f]{4})", lambda m: chr(int(m.group(1), 16)), e.dxf.text)
        out["texts"].setdefault(layer, []).append(text)
        out["text_at"].setdefault(layer, []).append([text, e.dxf.insert.x, e.dxf.insert.y])
        out["text_height"].setdefault(layer, []).append(e.dxf.height)
    elif e.dxftype() == "CIRCLE":
        out["circles"].setdefault(layer, []).append([e.dxf.center.x, e.dxf.center.y, e.dxf.radius])
    elif e.dxftype() == "LWPOLYLINE":
        out["polylines"][layer] = out["polylines"].get(layer, 0) + 1
        out["polyline_shapes"].setdefault(layer, []).append(
            {"closed": bool(e.closed), "points": [[p[0], p[1]] for p in e.get_points("xy")],
             "bulges": [p[2] for p in e.get_points("xyb")]})
    elif e.dxftype() == "ARC":
        out["arcs"].setdefault(layer, []).append([e.dxf.center.x, e.dxf.center.y, e.dxf.radius, e.dxf.start_angle,
                                                  e.dxf.end_angle])
    elif e.dxftype() == "LINE":
        out["lines"].setdefault(layer, []).append([e.dxf.start.x, e.dxf.start.y, e.dxf.end.x, e.dxf.end.y])
print(json.dumps(out))
