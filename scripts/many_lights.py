#!/usr/bin/env python3
"""Usage: many_lights.py OUT.obj [LAMPS_PER_SIDE]

A closed 4 x 3 x 4 m room (grey walls, Kd 0.5) lit by LAMPS_PER_SIDE^2 (default 20 x 20 = 400) small square
lamps, 4 cm on a side, 2 cm under the ceiling and facing down, their total emitted power that of one 1 x 1 m
panel of Le 1. Written as OUT.obj + OUT.mtl: the hard case of many small emitter patches.
"""
import sys
from pathlib import Path

out = Path(sys.argv[1])
n = int(sys.argv[2]) if len(sys.argv) > 2 else 20
W, H, D = 4.0, 3.0, 4.0
side = 0.04
le = 1.0 / (n * n * side * side)

lines = [f"# {n} x {n} lamps of {side} m, Le {le:g}, under the ceiling of a closed {W} x {H} x {D} room",
         f"mtllib {out.stem}.mtl"]
vertices = []


def quad(name, material, corners):
    base = len(vertices) + 1
    vertices.extend(corners)
    lines.append(f"o {name}\nusemtl {material}\nf {base} {base + 1} {base + 2} {base + 3}")


# Room faces, counter-clockwise seen from inside.
quad("floor", "grey", [(0, 0, 0), (0, 0, D), (W, 0, D), (W, 0, 0)])
quad("ceiling", "grey", [(0, H, 0), (W, H, 0), (W, H, D), (0, H, D)])
quad("back", "grey", [(0, 0, 0), (W, 0, 0), (W, H, 0), (0, H, 0)])
quad("front", "grey", [(0, 0, D), (0, H, D), (W, H, D), (W, 0, D)])
quad("left", "grey", [(0, 0, 0), (0, H, 0), (0, H, D), (0, 0, D)])
quad("right", "grey", [(W, 0, 0), (W, 0, D), (W, H, D), (W, H, 0)])
y = H - 0.02
for i in range(n):
    for k in range(n):
        x = (i + 0.5) * W / n - side / 2
        z = (k + 0.5) * D / n - side / 2
        # Facing down: counter-clockwise seen from below.
        quad(f"lamp_{i}_{k}", "lamp", [(x, y, z), (x + side, y, z), (x + side, y, z + side), (x, y, z + side)])

text = "\n".join(lines[:2] + [f"v {a:g} {b:g} {c:g}" for a, b, c in vertices] + lines[2:]) + "\n"
out.write_text(text)
out.with_suffix(".mtl").write_text(f"newmtl grey\nKd 0.5 0.5 0.5\n\nnewmtl lamp\nKd 0 0 0\nKe {le:g} {le:g} {le:g}\n")
