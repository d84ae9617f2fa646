#!/usr/bin/env python3
"""Writes a skirt as an OBJ with UVs: a frustum of a cone (waist radius,
hem radius, length) of `around` x `down` quads, each split along alternating
diagonals, as a modeller exports a garment (vertices shared along the seam,
where the faces name their own vt, u = 1 on one side and 0 on the other).
Its waist is the top ring (the first `around` vertices), at height `top`.
u runs round the skirt, v down it, both in metres of the unrolled pattern's
arc and slant lengths at the waist, so the fabric's warp is vertical.

    python3 Demos/scripts/make_garment.py Scenes/meshes/skirt.obj
    python3 Demos/scripts/make_garment.py out.obj --around 32 --down 12

Standard library only."""
import argparse
import math


def skirt(around, down, waist, hem, length, top):
    verts, uvs, faces = [], [], []
    slant = math.hypot(length, hem - waist)
    for j in range(down + 1):
        t = j / down
        r = waist + (hem - waist) * t
        y = top - length * t
        for i in range(around):
            a = 2 * math.pi * i / around
            verts.append((r * math.cos(a), y, r * math.sin(a)))
    # vt: around + 1 per ring (the seam's column twice: u = 0 and u = 1).
    for j in range(down + 1):
        for i in range(around + 1):
            uvs.append((2 * math.pi * waist * i / around, slant * j / down))

    def v(i, j):
        return j * around + i % around + 1

    def vt(i, j):
        return j * (around + 1) + i + 1

    for j in range(down):
        for i in range(around):
            a, b, c, d = (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)
            tris = [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]
            for tri in tris:
                faces.append([(v(*p), vt(*p)) for p in tri])
    return verts, uvs, faces


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("out")
    p.add_argument("--around", type=int, default=48, help="quads round the skirt")
    p.add_argument("--down", type=int, default=16, help="quads from waist to hem")
    p.add_argument("--waist", type=float, default=0.16, help="waist radius, m")
    p.add_argument("--hem", type=float, default=0.32, help="hem radius, m")
    p.add_argument("--length", type=float, default=0.45, help="waist to hem, m")
    p.add_argument("--top", type=float, default=1.2, help="height of the waist, m")
    a = p.parse_args()
    verts, uvs, faces = skirt(a.around, a.down, a.waist, a.hem, a.length, a.top)
    with open(a.out, "w") as f:
        f.write("# skirt: Demos/scripts/make_garment.py --around %d --down %d --waist %g --hem %g --length %g "
                "--top %g\n" % (a.around, a.down, a.waist, a.hem, a.length, a.top))
        for x in verts:
            f.write("v %.6f %.6f %.6f\n" % x)
        for t in uvs:
            f.write("vt %.6f %.6f\n" % t)
        for face in faces:
            f.write("f " + " ".join("%d/%d" % c for c in face) + "\n")


if __name__ == "__main__":
    main()
