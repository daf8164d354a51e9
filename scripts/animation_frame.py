#!/usr/bin/env python3
"""A still frame of a `gearkit kin --animate` SVG, to render with rsvg-convert (which ignores
SMIL): every <animate> sets its attribute to its K-th value, every <animateTransform> pair
(translate, then rotate additive="sum") sets the transform, and the animation elements go.

usage: animation_frame.py IN.svg K OUT.svg   (K: the frame index, 0-based; -1 the last)
"""
import sys
import xml.etree.ElementTree as ET

NS = "http://www.w3.org/2000/svg"
ET.register_namespace("", NS)


def frame(path, k, out):
    tree = ET.parse(path)
    for parent in tree.iter():
        transforms = []
        for child in list(parent):
            tag = child.tag.split("}")[-1]
            if tag not in ("animate", "animateTransform"):
                continue
            values = child.get("values").split(";")
            value = values[k]
            if tag == "animate":
                parent.set(child.get("attributeName"), value)
            else:
                transforms.append(f"{child.get('type')}({value})")
            parent.remove(child)
        if transforms:
            parent.set("transform", " ".join(transforms))
    tree.write(out, xml_declaration=True, encoding="UTF-8")


if __name__ == "__main__":
    frame(sys.argv[1], int(sys.argv[2]), sys.argv[3])
