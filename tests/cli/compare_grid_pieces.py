"""Compare a distributed run's grid snapshot pieces (.vti) with one process's .vti.

Usage: compare_grid_pieces.py WHOLE.vti PIECE.vti... ; prints the largest difference of any
node array relative to that array's largest value in WHOLE, and exits 1 above 1e-12.
2D images only (the CLI test's case)."""
import base64
import re
import struct
import sys

import numpy as np


def read_vti(path):
    text = open(path).read()
    extent = [int(v) for v in re.search(r'<Piece Extent="([^"]*)"', text).group(1).split()]
    arrays = {}
    pattern = r'<DataArray type="Float64" Name="([^"]*)" NumberOfComponents="(\d+)" ' \
              r'format="binary">\s*([^<]*)<'
    for name, components, data in re.findall(pattern, text):
        raw = base64.b64decode(data.strip())
        size = struct.unpack("<Q", raw[:8])[0]  # header_type UInt64: bytes that follow
        values = np.frombuffer(raw[8:8 + size], dtype="<f8")
        nx, ny = extent[1] - extent[0] + 1, extent[3] - extent[2] + 1
        arrays[name] = values.reshape(ny, nx, int(components))
    return extent, arrays


def main():
    whole_extent, whole = read_vti(sys.argv[1])
    worst = 0.0
    for path in sys.argv[2:]:
        extent, arrays = read_vti(path)
        if set(arrays) != set(whole):
            print(f"{path}: arrays {sorted(arrays)}, expected {sorted(whole)}")
            return 1
        for name, values in arrays.items():
            x0, y0 = extent[0] - whole_extent[0], extent[2] - whole_extent[2]
            same_nodes = whole[name][y0:y0 + values.shape[0], x0:x0 + values.shape[1]]
            scale = np.abs(whole[name]).max() or 1.0
            worst = max(worst, np.abs(same_nodes - values).max() / scale)
    print(f"largest difference of the pieces from one process, relative: {worst:.2g}")
    return 0 if worst <= 1e-12 else 1


if __name__ == "__main__":
    sys.exit(main())
