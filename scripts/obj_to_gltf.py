#!/usr/bin/env python3
"""Writes a glTF 2.0 copy of an OBJ + MTL scene, with the buffer embedded as base64 (one file).

    scripts/obj_to_gltf.py assets/cornell_box.obj assets/cornell_box.gltf

Python's standard library only. Reads what the scenes in assets/ use: `v`, `f` (polygons, fanned into
triangles, which keeps planar convex polygons exact), `o`/`g`, `usemtl`, `mtllib`, and from the MTL `newmtl`,
`Kd` and `Ke`. Each object becomes a mesh on a node of its own, one primitive per material; `Kd` becomes
baseColorFactor (both are linear); `Ke` becomes emissiveFactor, scaled into [0, 1] as glTF requires, with the
scale in KHR_materials_emissive_strength. OBJ has no camera, so neither has the copy.
"""
import base64
import json
import os
import struct
import sys


def read_mtl(path):
    materials = {}
    current = None
    with open(path) as f:
        for line in f:
            words = line.split('#', 1)[0].split()
            if not words:
                continue
            if words[0] == 'newmtl':
                current = materials.setdefault(' '.join(words[1:]), {'Kd': [0.5] * 3, 'Ke': [0.0] * 3})
            elif words[0] in ('Kd', 'Ke') and current is not None:
                current[words[0]] = [float(w) for w in words[1:4]]
    return materials


def read_obj(path):
    positions, objects, libraries = [], [], []
    current, material = None, None
    with open(path) as f:
        for line in f:
            words = line.split('#', 1)[0].split()
            if not words:
                continue
            key = words[0]
            if key == 'v':
                positions.append([float(w) for w in words[1:4]])
            elif key in ('o', 'g'):
                current = {'name': ' '.join(words[1:]), 'faces': []}
                objects.append(current)
            elif key == 'usemtl':
                material = ' '.join(words[1:])
            elif key == 'mtllib':
                libraries.append(' '.join(words[1:]))
            elif key == 'f':
                if current is None:
                    current = {'name': 'object', 'faces': []}
                    objects.append(current)
                corners = []
                for w in words[1:]:
                    i = int(w.split('/')[0])
                    corners.append(i - 1 if i > 0 else len(positions) + i)
                current['faces'].append((material, corners))
    return positions, objects, libraries


def gltf_material(name, m):
    out = {'name': name, 'pbrMetallicRoughness': {'baseColorFactor': m['Kd'] + [1.0], 'metallicFactor': 0.0,
                                                  'roughnessFactor': 1.0}}
    strength = max(m['Ke'])
    if strength > 0:
        out['emissiveFactor'] = [c / max(strength, 1.0) for c in m['Ke']]
        if strength > 1:
            out['extensions'] = {'KHR_materials_emissive_strength': {'emissiveStrength': strength}}
    return out


def convert(obj_path, gltf_path):
    positions, objects, libraries = read_obj(obj_path)
    materials = {}
    for lib in libraries:
        materials.update(read_mtl(os.path.join(os.path.dirname(obj_path), lib)))
    names = list(materials)
    blob = bytearray()
    views, accessors, meshes = [], [], []

    def add_view(data, target):
        while len(blob) % 4:
            blob.append(0)
        views.append({'buffer': 0, 'byteOffset': len(blob), 'byteLength': len(data), 'target': target})
        blob.extend(data)
        return len(views) - 1

    for obj in objects:
        primitives = []
        for material in dict.fromkeys(m for m, _ in obj['faces']):
            used, index = {}, []
            for m, corners in obj['faces']:
                if m != material:
                    continue
                for k in range(1, len(corners) - 1):
                    for c in (corners[0], corners[k], corners[k + 1]):
                        index.append(used.setdefault(c, len(used)))
            points = [positions[c] for c in used]
            view = add_view(b''.join(struct.pack('<3f', *p) for p in points), 34962)
            accessors.append({'bufferView': view, 'componentType': 5126, 'count': len(points), 'type': 'VEC3',
                              'min': [min(p[i] for p in points) for i in range(3)],
                              'max': [max(p[i] for p in points) for i in range(3)]})
            view = add_view(struct.pack('<%dI' % len(index), *index), 34963)
            accessors.append({'bufferView': view, 'componentType': 5125, 'count': len(index), 'type': 'SCALAR'})
            primitive = {'attributes': {'POSITION': len(accessors) - 2}, 'indices': len(accessors) - 1}
            if material in materials:
                primitive['material'] = names.index(material)
            primitives.append(primitive)
        meshes.append({'name': obj['name'], 'primitives': primitives})

    gltf = {
        'asset': {'version': '2.0', 'generator': 'scripts/obj_to_gltf.py from ' + os.path.basename(obj_path)},
        'scene': 0,
        'scenes': [{'nodes': list(range(len(meshes)))}],
        'nodes': [{'name': m['name'], 'mesh': i} for i, m in enumerate(meshes)],
        'meshes': meshes,
        'materials': [gltf_material(n, materials[n]) for n in names],
        'accessors': accessors,
        'bufferViews': views,
        'buffers': [{'byteLength': len(blob),
                     'uri': 'data:application/octet-stream;base64,' + base64.b64encode(bytes(blob)).decode()}],
    }
    if any('extensions' in m for m in gltf['materials']):
        gltf['extensionsUsed'] = ['KHR_materials_emissive_strength']
    with open(gltf_path, 'w') as f:
        json.dump(gltf, f, indent=1)
        f.write('\n')


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit('usage: obj_to_gltf.py SCENE.obj OUT.gltf')
    convert(sys.argv[1], sys.argv[2])
