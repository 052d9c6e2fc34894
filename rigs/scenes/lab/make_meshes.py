#!/usr/bin/env python3
"""Writes the lab scene's meshes (run from anywhere; files land next to this script).

room.obj   6 x 4 m floor and four 2.5 m walls, faces wound to face into the room
table.off  1.2 x 0.8 x 0.75 m table: a 4 cm top on four 5 cm legs, centred on its origin
person.ply a 1.75 m hexagonal prism (0.3 m deep in x, 0.43 m wide in y) on its origin
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# Each quad lists its corners counter-clockwise seen from the side it faces.
BOX_QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (0, 4, 7, 3), (1, 2, 6, 5)]


def box(low, high):
    (x0, y0, z0), (x1, y1, z1) = low, high
    return [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
            (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]


def fmt(v):
    return " ".join(f"{c:g}" for c in v)


def write_room():
    hx, hy, h = 3.0, 2.0, 2.5
    corners = box((-hx, -hy, 0), (hx, hy, h))
    # Inside faces: the box's outward quads reversed, without the ceiling (index 1).
    quads = [tuple(reversed(q)) for i, q in enumerate(BOX_QUADS) if i != 1]
    with open(os.path.join(HERE, "room.obj"), "w") as f:
        f.write("# lab room: 6 x 4 m floor, 2.5 m walls, no ceiling; faces point inwards\n")
        f.write("o room\n")
        for c in corners:
            f.write(f"v {fmt(c)}\n")
        for q in quads:
            f.write("f " + " ".join(str(i + 1) for i in q) + "\n")


def write_table():
    length, width, height, top, leg = 1.2, 0.8, 0.75, 0.04, 0.05
    boxes = [box((-length / 2, -width / 2, height - top), (length / 2, width / 2, height))]
    for sx in (-1, 1):
        for sy in (-1, 1):
            x = sx * (length / 2 - leg / 2)
            y = sy * (width / 2 - leg / 2)
            boxes.append(box((x - leg / 2, y - leg / 2, 0), (x + leg / 2, y + leg / 2, height - top)))
    with open(os.path.join(HERE, "table.off"), "w") as f:
        f.write("OFF\n# lab table: 1.2 x 0.8 m top at 0.75 m on four legs\n")
        f.write(f"{8 * len(boxes)} {6 * len(boxes)} 0\n")
        for b in boxes:
            for c in b:
                f.write(fmt(c) + "\n")
        for n in range(len(boxes)):
            for q in BOX_QUADS:
                f.write("4 " + " ".join(str(8 * n + i) for i in q) + "\n")


def write_person():
    # A hexagon 0.5 m across in y (shoulders) and 0.3 m deep in x, extruded to 1.75 m.
    ring = [(0.15 * math.cos(a), 0.25 * math.sin(a)) for a in
            (math.radians(d) for d in range(0, 360, 60))]
    height = 1.75
    vertices = [(x, y, 0.0) for x, y in ring] + [(x, y, height) for x, y in ring]
    n = len(ring)
    faces = [tuple(reversed(range(n))), tuple(range(n, 2 * n))]
    faces += [(i, (i + 1) % n, n + (i + 1) % n, n + i) for i in range(n)]
    with open(os.path.join(HERE, "person.ply"), "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment lab person: hexagonal prism, 1.75 m tall\n")
        f.write(f"element vertex {len(vertices)}\nproperty float x\nproperty float y\n"
                "property float z\n")
        f.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        for v in vertices:
            f.write(fmt(round(c, 4) for c in v) + "\n")
        for face in faces:
            f.write(f"{len(face)} " + " ".join(str(i) for i in face) + "\n")


if __name__ == "__main__":
    write_room()
    write_table()
    write_person()
