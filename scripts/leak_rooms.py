#!/usr/bin/env python3
"""Usage: leak_rooms.py OUT_DIR

Writes the leak suite (assets/hard/leak_*.obj + .mtl): closed rooms built the ways modelling tools and IFC
exporters build them, each a 1 x 1 x 1 interior (0 < x, y, z < 1) that no light may enter. They are lit from
outside by --sky (or --sun), or, where named, by a lamp in a neighbouring room; every element whose front looks
into the closed interior must stay at 0. Solid parts are closed boxes of six outward faces (grey, Kd 0.5) of
thickness T = 0.1. A ground (Kd 0.5, 4 x 4, facing up) lies under every room, 0.05 below its lowest face, so
that light from outside has something to bounce from.

  leak_inward_box      one box of six inward faces (zero thickness), as a room modelled from inside
  leak_slabs_touching  six slabs touching face to face (the walls stand on the floor slab, the ceiling slab on
                       the walls, the side walls between the end walls)
  leak_slabs_overlap   six slabs that run through each other at every corner and edge
  leak_slabs_edges     six slabs, each one face of the interior extruded outwards: they meet only along the
                       interior's edges, and the outside corners are open notches
  leak_floor_under     one floor quad (zero thickness, facing up) that runs under the wall slabs and 1 m out
                       into the open on every side; the walls stand on it, the ceiling slab on the walls
  leak_two_rooms       two interiors side by side (x 0..1 and x 1.1..2.1) sharing a wall slab 0.1 thick that
                       the floor and ceiling slabs run over; a lamp (Ke 1/pi, 0.3 x 0.3) under the first
                       room's ceiling and no other light: the second room stays dark
  leak_leg_through     leak_slabs_touching, with a table in the room whose four legs (0.04 x 0.04) pass through
                       the floor slab and 0.05 out below it, and a beam (0.1 x 0.1) through the wall x = 1 into
                       the open, 0.5 out: the parts outside are lit, nothing carries it in
"""
import sys
from pathlib import Path

T = 0.1


class Obj:
    def __init__(self, name):
        self.name = name
        self.lines = [f"# {name}: see scripts/leak_rooms.py", f"mtllib {name}.mtl"]
        self.count = 0

    def quad(self, group, material, corners):
        """A quad whose corners run counter-clockwise seen from its front."""
        base = self.count + 1
        self.count += 4
        for c in corners:
            self.lines.append("v {:.6g} {:.6g} {:.6g}".format(*c))
        self.lines.append(f"g {group}\nusemtl {material}\nf {base} {base + 1} {base + 2} {base + 3}")

    def box(self, group, lo, hi, material="grey"):
        """A closed box of six outward faces."""
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        self.quad(group, material, [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)])  # -y
        self.quad(group, material, [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)])  # +y
        self.quad(group, material, [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)])  # -x
        self.quad(group, material, [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)])  # +x
        self.quad(group, material, [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)])  # -z
        self.quad(group, material, [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)])  # +z

    def ground(self, y, lo=-1.5, hi=2.5):
        self.quad("ground", "grey", [(lo, y, lo), (lo, y, hi), (hi, y, hi), (hi, y, lo)])

    def write(self, folder, lamp=False):
        (folder / f"{self.name}.obj").write_text("\n".join(self.lines) + "\n")
        mtl = "newmtl grey\nKd 0.5 0.5 0.5\n"
        if lamp:
            mtl += "newmtl lamp\nKd 0 0 0\nKe 0.3183098861837907 0.3183098861837907 0.3183098861837907\n"
        (folder / f"{self.name}.mtl").write_text(mtl)


def touching(o, x0=0.0, x1=1.0):
    """Slabs touching face to face around the interior x0..x1, 0..1, 0..1."""
    o.box("floor", (x0 - T, -T, -T), (x1 + T, 0, 1 + T))
    o.box("ceiling", (x0 - T, 1, -T), (x1 + T, 1 + T, 1 + T))
    o.box("wall_x0", (x0 - T, 0, -T), (x0, 1, 1 + T))
    o.box("wall_x1", (x1, 0, -T), (x1 + T, 1, 1 + T))
    o.box("wall_z0", (x0, 0, -T), (x1, 1, 0))
    o.box("wall_z1", (x0, 0, 1), (x1, 1, 1 + T))


def main():
    folder = Path(sys.argv[1])
    folder.mkdir(parents=True, exist_ok=True)

    o = Obj("leak_inward_box")
    o.quad("floor", "grey", [(0, 0, 0), (0, 0, 1), (1, 0, 1), (1, 0, 0)])
    o.quad("ceiling", "grey", [(0, 1, 0), (1, 1, 0), (1, 1, 1), (0, 1, 1)])
    o.quad("wall_x0", "grey", [(0, 0, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1)])
    o.quad("wall_x1", "grey", [(1, 0, 0), (1, 0, 1), (1, 1, 1), (1, 1, 0)])
    o.quad("wall_z0", "grey", [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)])
    o.quad("wall_z1", "grey", [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)])
    o.ground(-0.05)
    o.write(folder)

    o = Obj("leak_slabs_touching")
    touching(o)
    o.ground(-T - 0.05)
    o.write(folder)

    o = Obj("leak_slabs_overlap")
    o.box("floor", (-T, -T, -T), (1 + T, 0, 1 + T))
    o.box("ceiling", (-T, 1, -T), (1 + T, 1 + T, 1 + T))
    o.box("wall_x0", (-T, -T, -T), (0, 1 + T, 1 + T))
    o.box("wall_x1", (1, -T, -T), (1 + T, 1 + T, 1 + T))
    o.box("wall_z0", (-T, -T, -T), (1 + T, 1 + T, 0))
    o.box("wall_z1", (-T, -T, 1), (1 + T, 1 + T, 1 + T))
    o.ground(-T - 0.05)
    o.write(folder)

    o = Obj("leak_slabs_edges")
    o.box("floor", (0, -T, 0), (1, 0, 1))
    o.box("ceiling", (0, 1, 0), (1, 1 + T, 1))
    o.box("wall_x0", (-T, 0, 0), (0, 1, 1))
    o.box("wall_x1", (1, 0, 0), (1 + T, 1, 1))
    o.box("wall_z0", (0, 0, -T), (1, 1, 0))
    o.box("wall_z1", (0, 0, 1), (1, 1, 1 + T))
    o.ground(-T - 0.05)
    o.write(folder)

    o = Obj("leak_floor_under")
    o.quad("floor", "grey", [(-1, 0, -1), (-1, 0, 2), (2, 0, 2), (2, 0, -1)])
    o.box("ceiling", (-T, 1, -T), (1 + T, 1 + T, 1 + T))
    o.box("wall_x0", (-T, 0, -T), (0, 1, 1 + T))
    o.box("wall_x1", (1, 0, -T), (1 + T, 1, 1 + T))
    o.box("wall_z0", (0, 0, -T), (1, 1, 0))
    o.box("wall_z1", (0, 0, 1), (1, 1, 1 + T))
    o.ground(-0.05)
    o.write(folder)

    o = Obj("leak_two_rooms")
    x2 = 1.0 + T
    o.box("floor", (-T, -T, -T), (x2 + 1 + T, 0, 1 + T))
    o.box("ceiling", (-T, 1, -T), (x2 + 1 + T, 1 + T, 1 + T))
    o.box("wall_x0", (-T, 0, -T), (0, 1, 1 + T))
    o.box("wall_between", (1, 0, -T), (x2, 1, 1 + T))
    o.box("wall_x1", (x2 + 1, 0, -T), (x2 + 1 + T, 1, 1 + T))
    o.box("wall_z0", (0, 0, -T), (1, 1, 0))
    o.box("wall_z1", (0, 0, 1), (1, 1, 1 + T))
    o.box("wall_z0_dark", (x2, 0, -T), (x2 + 1, 1, 0))
    o.box("wall_z1_dark", (x2, 0, 1), (x2 + 1, 1, 1 + T))
    o.quad("lamp", "lamp", [(0.35, 0.99, 0.35), (0.65, 0.99, 0.35), (0.65, 0.99, 0.65), (0.35, 0.99, 0.65)])
    o.write(folder, lamp=True)

    o = Obj("leak_leg_through")
    touching(o)
    o.box("table_top", (0.3, 0.45, 0.3), (0.7, 0.5, 0.7))
    for i, (x, z) in enumerate([(0.32, 0.32), (0.64, 0.32), (0.32, 0.64), (0.64, 0.64)]):
        o.box(f"leg_{i}", (x, -T - 0.05, z), (x + 0.04, 0.45, z + 0.04))
    o.box("beam", (0.6, 0.7, 0.45), (1 + T + 0.5, 0.8, 0.55))
    o.ground(-T - 0.1)
    o.write(folder)


main()
