#!/usr/bin/env python3
"""Usage: furnished_room.py SEED TARGET_FACES OUT.obj [FURNITURE_DIR]

A closed room (floor, four walls, ceiling; one emissive panel under the ceiling) furnished with Sweet Home 3D
models, written as OUT.obj + OUT.mtl. FURNITURE_DIR holds the *.sh3f zips of Debian's sweethome3d-furniture
(`dpkg -x sweethome3d-furniture_*.deb DIR`; default DIR/usr/share/sweethome3d/furniture with DIR = /tmp/sh3d/x).
Models are picked at random (SEED) among those that stand on the floor, scaled to their catalogue's width,
depth and height (cm), and set on a grid of rows with 0.3 m between them, until their faces, counted as the
program's loader counts them (non-planar or concave polygons split into triangles), are within 2 % of
TARGET_FACES.
Only Kd is kept from the models' materials (clamped to [0.02, 0.9]; textures, Ke and transparency are dropped).
"""
import random
import re
import sys
import zipfile
from pathlib import Path

ROOMS = {"Living room", "Kitchen", "Bedroom", "Bathroom", "Office", "Miscellaneous"}
GAP = 0.3            # metres between models and from the walls
MAX_SHARE = 0.25     # no single model above this share of the target faces
LIGHT_LE = 4.0       # emitted radiance of the ceiling panel (E = pi Le)


def catalogue(zf):
    """The catalogue's floor-standing models: (zip, model path, width, depth, height in metres)."""
    props = {}
    for line in zf.read("PluginFurnitureCatalog.properties").decode("latin-1").splitlines():
        m = re.match(r"(\w+)#(\d+)=(.*)", line)
        if m:
            props.setdefault(int(m.group(2)), {})[m.group(1)] = m.group(3).strip()
    for p in props.values():
        if (p.get("category") in ROOMS and p.get("doorOrWindow") == "false" and "elevation" not in p
                and "modelRotation" not in p and "lightSourceX" not in p):
            w, d, h = (float(p[k]) / 100 for k in ("width", "depth", "height"))
            if min(w, d) >= 0.15 and h >= 0.3:
                yield zf, p["model"].lstrip("/"), w, d, h


def load_model(zf, path):
    """Vertices, faces as [(material, [vertex index])], materials {name: Kd} of one OBJ in the zip."""
    folder = path.rsplit("/", 1)[0]
    verts, faces, kd, mat = [], [], {}, None
    for line in zf.read(path).decode("latin-1").splitlines():
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            verts.append(tuple(float(x) for x in w[1:4]))
        elif w[0] == "f":
            idx = [int(c.split("/")[0]) for c in w[1:]]
            idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
            if len(set(idx)) >= 3:
                faces.append((mat, idx))
        elif w[0] == "usemtl":
            mat = " ".join(w[1:])
        elif w[0] == "mtllib":
            lib = folder + "/" + " ".join(w[1:])
            if lib in zf.namelist():
                for ml in zf.read(lib).decode("latin-1").splitlines():
                    m = ml.split()
                    if m and m[0] == "newmtl":
                        name = " ".join(m[1:])
                        kd[name] = (0.5, 0.5, 0.5)
                    elif m and m[0] == "Kd" and len(m) >= 4:
                        kd[name] = tuple(min(max(float(x), 0.02), 0.9) for x in m[1:4])
    return verts, faces, kd


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def loader_faces(verts, idx):
    """The faces the program's loader makes of one polygon: one if planar (within 1e-6 of its size) and
    convex, else n - 2 triangles."""
    p = [verts[i] for i in idx]
    if len(p) == 3:
        return 1
    normal = [0.0, 0.0, 0.0]
    for a, b in zip(p, p[1:] + p[:1]):  # Newell's normal
        normal = [normal[0] + (a[1] - b[1]) * (a[2] + b[2]), normal[1] + (a[2] - b[2]) * (a[0] + b[0]),
                  normal[2] + (a[0] - b[0]) * (a[1] + b[1])]
    size = max(max(abs(c) for c in sub(a, b)) for a in p for b in p)
    length = sum(c * c for c in normal) ** 0.5
    if length == 0 or size == 0:
        return len(p) - 2
    n = [c / length for c in normal]
    flat = all(abs(sum(n[k] * (q[k] - p[0][k]) for k in range(3))) <= 1e-6 * size for q in p)
    turns = [sum(n[k] * c for k, c in enumerate(cross(sub(b, a), sub(c2, b))))
             for a, b, c2 in zip(p, p[1:] + p[:1], p[2:] + p[:2])]
    return 1 if flat and all(t > 0 for t in turns) else len(p) - 2


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    seed, target, out = int(sys.argv[1]), int(sys.argv[2]), Path(sys.argv[3])
    fdir = Path(sys.argv[4] if len(sys.argv) == 5 else "/tmp/sh3d/x/usr/share/sweethome3d/furniture")
    pool = [e for f in sorted(fdir.glob("*.sh3f")) for e in catalogue(zipfile.ZipFile(f))]
    rng = random.Random(seed)
    rng.shuffle(pool)

    # Pick models until the faces reach the target.
    picked, faces_total = [], 7
    for zf, path, w, d, h in pool:
        if faces_total >= 0.98 * target:
            break
        verts, faces, kd = load_model(zf, path)
        n = sum(loader_faces(verts, idx) for _, idx in faces)
        if not faces or n > MAX_SHARE * target or faces_total + n > 1.02 * target:
            continue
        picked.append((path, w, d, h, verts, faces, kd))
        faces_total += n

    # Rows along x in a room about twice as wide as deep.
    area = sum((w + GAP) * (d + GAP) for _, w, d, *_ in picked)
    width = max(4.0, (2 * area) ** 0.5 * 1.2)
    placed, x, z, row_depth = [], GAP, GAP, 0.0
    for item in picked:
        _, w, d, *_ = item
        if x + w + GAP > width:
            x, z, row_depth = GAP, z + row_depth + GAP, 0.0
        placed.append((x, z, item))
        x, row_depth = x + w + GAP, max(row_depth, d)
    depth = max(3.0, z + row_depth + GAP)
    height = max(2.6, max(h for _, _, _, h, *_ in picked) + 0.4)

    obj, mtl = [f"mtllib {out.with_suffix('.mtl').name}"], []
    mtl += ["newmtl room_wall", "Kd 0.7 0.7 0.7", "newmtl room_floor", "Kd 0.45 0.35 0.25",
            "newmtl room_light", "Kd 0.1 0.1 0.1", f"Ke {LIGHT_LE} {LIGHT_LE} {LIGHT_LE}"]
    nv = 0

    def quad(name, material, o, u, v):
        """A quad o, o+u, o+u+v, o+v; its front (counter-clockwise side) faces u x v."""
        nonlocal nv
        obj.extend([f"o {name}", f"usemtl {material}"])
        for p in (o, [o[i] + u[i] for i in range(3)], [o[i] + u[i] + v[i] for i in range(3)],
                  [o[i] + v[i] for i in range(3)]):
            obj.append("v %.5f %.5f %.5f" % tuple(p))
        obj.append(f"f {nv + 1} {nv + 2} {nv + 3} {nv + 4}")
        nv += 4

    W, D, H = width, depth, height  # y up, the room spans [0, W] x [0, H] x [0, D]; every side faces inward
    quad("floor", "room_floor", [0, 0, 0], [0, 0, D], [W, 0, 0])
    quad("ceiling", "room_wall", [0, H, 0], [W, 0, 0], [0, 0, D])
    quad("wall_back", "room_wall", [0, 0, 0], [W, 0, 0], [0, H, 0])
    quad("wall_front", "room_wall", [0, 0, D], [0, H, 0], [W, 0, 0])
    quad("wall_left", "room_wall", [0, 0, 0], [0, H, 0], [0, 0, D])
    quad("wall_right", "room_wall", [W, 0, 0], [0, 0, D], [0, H, 0])
    s = min(1.2, W / 3, D / 3)
    quad("light", "room_light", [W / 2 - s / 2, H - 0.01, D / 2 - s / 2], [s, 0, 0], [0, 0, s])

    for k, (x0, z0, (path, w, d, h, verts, faces, kd)) in enumerate(placed):
        lo = [min(p[i] for p in verts) for i in range(3)]
        hi = [max(p[i] for p in verts) for i in range(3)]
        scale = [size / max(hi[i] - lo[i], 1e-9) for i, size in enumerate((w, h, d))]
        at = (x0, 0.0, z0)
        obj.append(f"o m{k}_{Path(path).stem}")
        for p in verts:
            obj.append("v %.10g %.10g %.10g" % tuple(at[i] + (p[i] - lo[i]) * scale[i] for i in range(3)))
        names = {}
        for name in sorted({m for m, _ in faces}, key=str):
            names[name] = f"m{k}_{len(names)}"
            mtl += [f"newmtl {names[name]}", "Kd %.4f %.4f %.4f" % kd.get(name, (0.5, 0.5, 0.5))]
        current = None
        for m, idx in faces:
            if m != current:
                obj.append(f"usemtl {names[m]}")
                current = m
            obj.append("f " + " ".join(str(nv + 1 + i) for i in idx))
        nv += len(verts)

    out.write_text("\n".join(obj) + "\n")
    out.with_suffix(".mtl").write_text("\n".join(mtl) + "\n")
    print(f"{out}: {len(placed)} models, {faces_total} faces (as the loader counts them), room {W:.2f} x {D:.2f} x {H:.2f} m", file=sys.stderr)


if __name__ == "__main__":
    main()
