#!/usr/bin/env python3
"""Writes blocks.obj and blocks.mtl: the homework 4-5 object, "a 3D solid made of cubes".

Five unit cubes in a corner shape: three along x, one on top of the first, one behind it. Only
the outside faces are written (a face between two cubes is inside the solid), each with its
normal and texture coordinates; top faces use the material "paint", the others "wood", whose
diffuse map is ../textures/wood.png. The solid is centred on x and z and stands on y = 0, one
unit to a cube, 3 x 2 x 2 units overall.
"""
import os

CUBES = {(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (0, 0, 1)}
OFFSET = (-1.5, 0.0, -1.0)

# Each face: outward normal, and its four corners counter-clockwise seen from outside.
FACES = {
    (1, 0, 0): [(1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)],
    (-1, 0, 0): [(0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)],
    (0, 1, 0): [(0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)],
    (0, -1, 0): [(0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)],
    (0, 0, 1): [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
    (0, 0, -1): [(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)],
}
NORMALS = list(FACES)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    vertices, faces = [], {"wood": [], "paint": []}
    for cube in sorted(CUBES):
        for normal, corners in FACES.items():
            neighbour = tuple(c + n for c, n in zip(cube, normal))
            if neighbour in CUBES:
                continue
            indices = []
            for corner in corners:
                vertices.append(tuple(c + k + o for c, k, o in zip(cube, corner, OFFSET)))
                indices.append(len(vertices))
            material = "paint" if normal == (0, 1, 0) else "wood"
            faces[material].append((indices, NORMALS.index(normal) + 1))
    with open(os.path.join(here, "blocks.obj"), "w") as f:
        f.write("# The homework 4-5 object: five unit cubes (written by make_models.py)\n")
        f.write("mtllib blocks.mtl\n")
        for v in vertices:
            f.write("v %g %g %g\n" % v)
        for uv in ((0, 0), (1, 0), (1, 1), (0, 1)):
            f.write("vt %g %g\n" % uv)
        for n in NORMALS:
            f.write("vn %d %d %d\n" % n)
        for material in ("wood", "paint"):
            f.write("usemtl %s\n" % material)
            for indices, normal in faces[material]:
                f.write("f " + " ".join("%d/%d/%d" % (v, k + 1, normal) for k, v in enumerate(indices)) + "\n")
    with open(os.path.join(here, "blocks.mtl"), "w") as f:
        f.write("# Materials of blocks.obj (written by make_models.py)\n")
        f.write("newmtl wood\nKa 0.3 0.3 0.3\nKd 1 1 1\nKs 0.2 0.2 0.2\nNs 20\nmap_Kd ../textures/wood.png\n\n")
        f.write("newmtl paint\nKa 0.25 0.05 0.05\nKd 0.8 0.15 0.12\nKs 0.6 0.6 0.6\nNs 60\n")


if __name__ == "__main__":
    main()
