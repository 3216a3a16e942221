#!/usr/bin/env python3
"""Reads any ncverify file (samples, grid, distances) with numpy: the snippet of FORMATS.md.

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


if __name__ == "__main__":
    kind, version, meta, arrays = read_ncverify(sys.argv[1])
    print(f"{kind} version {version}")
    for name, array in arrays.items():
        print(f"{name} {array.shape} {array.dtype}")
