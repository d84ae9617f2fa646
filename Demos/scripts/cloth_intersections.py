#!/usr/bin/env python3
"""Self-intersections of written cloth frames: for every frame of a cloth's
series, the edges that pass through a triangle they share no vertex with.

A sheet that ends a frame through itself is tangled: the contact passes
keep each vertex on the side of a triangle it started the sub-step on
(Eq. 21's side test), so a tangle, once made, is held. Counting them
frame by frame shows when and where a run tangles (Doc/design.md, "Where
fig9's worst strain comes from").

usage: python3 Demos/scripts/cloth_intersections.py RUN_DIR [CLOTH] [--frames A:B]
  RUN_DIR  an output folder of `soak run` (its CLOTH/ folder of .vtp frames;
           CLOTH defaults to the first cloth_*.pvd there)
prints one line per frame: frame, intersecting edge-triangle pairs, vertices
of those edges and triangles, and the pairs' spread over the mesh (the
number of mesh hops between edge and triangle: 'near' under 8, 'far' the rest).

Needs numpy and VTK's Python modules (python3-paraview on Debian: run it with
the system's python3).
"""
import argparse
import glob
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def read_frame(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    polys = vtk_to_numpy(data.GetPolys().GetData())
    if polys.size % 4:
        sys.exit(f"{path}: the cloth is not all triangles")
    return points, polys.reshape(-1, 4)[:, 1:].astype(np.int64)


def unique_edges(triangles):
    e = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    e.sort(axis=1)
    return np.unique(e, axis=0)


def candidate_pairs(points, edges, triangles, cell):
    """Edge-triangle pairs whose midpoint and centroid lie in neighbouring
    cells of size `cell` (at least the longest edge: every intersecting pair
    is among them)."""
    mid = points[edges].mean(axis=1)
    cen = points[triangles].mean(axis=1)
    lo = np.minimum(mid.min(axis=0), cen.min(axis=0))
    key_e = np.floor((mid - lo) / cell).astype(np.int64)
    key_t = np.floor((cen - lo) / cell).astype(np.int64)
    span = max(int(key_e.max()), int(key_t.max())) + 3

    def flat(k):
        return ((k[:, 0] + 1) * span + (k[:, 1] + 1)) * span + (k[:, 2] + 1)

    tri_keys = flat(key_t)
    order = np.argsort(tri_keys, kind="stable")
    sorted_keys = tri_keys[order]
    pairs_e, pairs_t = [], []
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            for dz in (-1, 0, 1):
                want = flat(key_e + np.array([dx, dy, dz]))
                first = np.searchsorted(sorted_keys, want, side="left")
                last = np.searchsorted(sorted_keys, want, side="right")
                count = last - first
                if count.sum() == 0:
                    continue
                e_idx = np.repeat(np.arange(len(edges)), count)
                offsets = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
                pairs_e.append(e_idx)
                pairs_t.append(order[np.repeat(first, count) + offsets])
    return np.concatenate(pairs_e), np.concatenate(pairs_t)


def intersections(points, edges, triangles):
    longest = np.linalg.norm(points[edges[:, 0]] - points[edges[:, 1]], axis=1).max()
    ei, ti = candidate_pairs(points, edges, triangles, max(longest, 1e-6))
    e, t = edges[ei], triangles[ti]
    shares = (t == e[:, :1]).any(axis=1) | (t == e[:, 1:]).any(axis=1)
    ei, ti, e, t = ei[~shares], ti[~shares], e[~shares], t[~shares]
    p0, p1 = points[e[:, 0]], points[e[:, 1]]
    a, b, c = points[t[:, 0]], points[t[:, 1]], points[t[:, 2]]
    n = np.cross(b - a, c - a)
    s0 = np.einsum("ij,ij->i", p0 - a, n)
    s1 = np.einsum("ij,ij->i", p1 - a, n)
    crosses = s0 * s1 < 0.0
    q = p0 + (p1 - p0) * (s0 / np.where(crosses, s0 - s1, 1.0))[:, None]
    inside = np.ones(len(q), dtype=bool)
    for u, v in ((a, b), (b, c), (c, a)):
        inside &= np.einsum("ij,ij->i", np.cross(v - u, q - u), n) >= 0.0
    hit = crosses & inside
    return ei[hit], ti[hit]


def mesh_hops(edges, triangles, n_vertices, ei, ti, limit=8):
    """Hops over the mesh from each hit edge's first vertex to the nearest
    vertex of its triangle, up to `limit` (limit: `limit` or more)."""
    neighbours = [[] for _ in range(n_vertices)]
    for a, b in edges:
        neighbours[a].append(b)
        neighbours[b].append(a)
    hops = []
    for k in range(len(ei)):
        targets = set(triangles[ti[k]].tolist())
        frontier, seen, h = {int(edges[ei[k], 0])}, set(), 0
        while h < limit and not (frontier & targets):
            seen |= frontier
            frontier = {m for v in frontier for m in neighbours[v]} - seen
            h += 1
        hops.append(h)
    return np.array(hops)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("cloth", nargs="?")
    parser.add_argument("--frames", help="A:B, the frames numbered A to B-1")
    args = parser.parse_args()
    cloth = args.cloth
    if cloth is None:
        pvds = sorted(glob.glob(os.path.join(args.run_dir, "cloth_*.pvd")))
        if not pvds:
            sys.exit(f"{args.run_dir}: no cloth_*.pvd")
        cloth = os.path.splitext(os.path.basename(pvds[0]))[0]
    files = sorted(glob.glob(os.path.join(args.run_dir, cloth, "*.vtp")))
    if not files:
        sys.exit(f"{args.run_dir}/{cloth}: no frames")
    def number(path):
        digits = "".join(ch for ch in os.path.basename(path) if ch.isdigit())
        return int(digits) if digits else -1

    first, last = 0, None
    if args.frames:
        a, b = args.frames.split(":")
        first, last = int(a or 0), int(b) if b else None
    print("frame,pairs,vertices,near,far")
    for path in files:
        f = number(path)
        if f < first or (last is not None and f >= last):
            continue
        points, triangles = read_frame(path)
        edges = unique_edges(triangles)
        ei, ti = intersections(points, edges, triangles)
        vertices = np.unique(np.concatenate([edges[ei].ravel(), triangles[ti].ravel()])) if len(ei) else []
        hops = mesh_hops(edges, triangles, len(points), ei, ti) if len(ei) else np.array([])
        print(f"{f},{len(ei)},{len(vertices)},{int((hops < 8).sum())},{int((hops >= 8).sum())}", flush=True)


if __name__ == "__main__":
    main()
