#!/usr/bin/env python3
"""Reads any ncverify file (samples, grid, distances) with numpy: the snippet of FORMATS.md,
and regenerates a samples file's points from its mesh and lattice sizes, bit for bit.

Usage: python3 docs/read_ncverify.py FILE
"""
import json
import struct
import sys

import numpy as np


def read_ncverify(path):
    buf = open(path, "rb").read()
    magic, kind, version, meta_bytes, file_bytes = struct.unpack_from("<8s4sIQQ", buf, 0)
    assert magic == b"NCVERIFY" and file_bytes == len(buf), "not a complete ncverify file"
    meta = json.loads(buf[64:64 + meta_bytes])
    arrays = {
        s["name"]: np.frombuffer(buf, dtype=s["dtype"], count=int(np.prod(s["shape"])),
                                 offset=s["offset"]).reshape(s["shape"])
        for s in meta["sections"]
    }
    return kind.decode(), version, meta, arrays


def sample_points(arrays):
    """Every sample's position and owning triangle, in sample order (FORMATS.md, the lattice)."""
    # Vertices may be stored as <f4 (exact floats): the lattice is computed in double.
    vertices = arrays["mesh_vertices"].astype(np.float64)
    triangles = arrays["mesh_triangles"].astype(np.int64)
    sizes = arrays["lattice_sizes"].astype(np.int64)
    sampled = np.flatnonzero(sizes >= 2)
    # Vertex samples: the vertices of sampled triangles, in vertex order, each owned by its
    # lowest-index sampled triangle.
    owner_of_vertex = np.full(len(vertices), np.iinfo(np.int64).max)
    for corner in range(3):
        np.minimum.at(owner_of_vertex, triangles[sampled, corner], sampled)
    used = np.flatnonzero(owner_of_vertex != np.iinfo(np.int64).max)
    interior = np.where(sizes >= 3, sizes * (sizes + 1) // 2 - 3, 0)
    first = len(used) + np.concatenate(([0], np.cumsum(interior)[:-1]))
    total = len(used) + int(interior.sum())
    positions, owner = np.empty((total, 3)), np.empty(total, dtype=np.uint32)
    positions[:len(used)], owner[:len(used)] = vertices[used], owner_of_vertex[used]
    # Interior points: A + i (B - A)/(n - 1) + j (C - A)/(n - 1), row-major, corners skipped.
    for n in np.unique(sizes[sizes >= 3]):
        ij = [(i, j) for i in range(n) for j in range(n - i)
              if (i, j) not in ((0, 0), (n - 1, 0), (0, n - 1))]
        i, j = (np.array(c, dtype=np.float64)[None, :, None] for c in zip(*ij))
        ts = np.flatnonzero(sizes == n)
        a = vertices[triangles[ts, 0]][:, None, :]
        e1 = ((vertices[triangles[ts, 1]] - vertices[triangles[ts, 0]]) / (n - 1))[:, None, :]
        e2 = ((vertices[triangles[ts, 2]] - vertices[triangles[ts, 0]]) / (n - 1))[:, None, :]
        rows = first[ts][:, None] + np.arange(len(ij))[None, :]
        positions[rows] = a + i * e1 + j * e2
        owner[rows] = ts[:, None]
    return positions, owner


if __name__ == "__main__":
    kind, version, meta, arrays = read_ncverify(sys.argv[1])
    print(f"{kind} version {version}")
    for name, array in arrays.items():
        print(f"{name} {array.shape} {array.dtype}")
    if "lattice_sizes" in arrays:
        positions, owner = sample_points(arrays)
        print(f"positions {positions.shape} {positions.dtype} (regenerated)")
