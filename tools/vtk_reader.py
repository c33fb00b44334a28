"""Minimal readers for the VTK XML files Pellicle writes.

Supported: UnstructuredGrid (.vtu) and PolyData (.vtp) files with inline
DataArrays in "binary" (base64, uncompressed) or "ascii" format, and ParaView
collections (.pvd).

    points, fields = read_vtu("results/points_000010.vtu")
    points, fields = read_vtp("results/surface_000010.vtp")
    for time, path in read_pvd("results/points.pvd"): ...
"""

import base64
import binascii
import os
import xml.etree.ElementTree as ET

import numpy as np

__all__ = ["InputError", "read_vtu", "read_vtp", "read_pvd", "select_snapshots", "MAX_PANELS"]

# Most snapshots a picture series shows.
MAX_PANELS = 6

_TYPES = {
    "Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2",
    "Int32": "i4", "UInt32": "u4", "Int64": "i8", "UInt64": "u8",
    "Float32": "f4", "Float64": "f8",
}


class InputError(Exception):
    """A problem with an input file; `path` is the file, `problem` the reason."""

    def __init__(self, path, problem):
        super().__init__(f"{path}: {problem}")
        self.path = str(path)
        self.problem = problem


def _parse(path, expected_type):
    """Parse an XML file and check that it is a VTKFile of the expected type."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as err:
        raise InputError(path, f"not valid XML ({err})") from None
    if root.tag != "VTKFile" or root.get("type") != expected_type:
        raise InputError(path, f"not a VTK {expected_type} file")
    return root


def _decode_binary(text, dtype, header_dtype, path, name):
    """Decode VTK's uncompressed inline binary: base64([byte count][data]).

    The header and the data are normally one base64 block; blocks encoded
    separately (as some writers do) are accepted too.
    """
    text = "".join(text.split())
    size = header_dtype.itemsize
    split = 4 * -(-size // 3)  # base64 length of the header on its own
    try:
        raw = base64.b64decode(text, validate=True)
    except (binascii.Error, ValueError):
        raw = b""
    nbytes = None
    if len(raw) >= size:
        nbytes = int(np.frombuffer(raw[:size], header_dtype)[0])
        data = raw[size:]
    if nbytes is None or len(data) < nbytes:
        try:  # header and data as two separate base64 blocks
            header = base64.b64decode(text[:split], validate=True)[:size]
            data = base64.b64decode(text[split:], validate=True)
            nbytes = int(np.frombuffer(header, header_dtype)[0])
        except (binascii.Error, ValueError):
            nbytes = None
    if nbytes is None or len(data) < nbytes or nbytes % dtype.itemsize:
        raise InputError(path, f"DataArray '{name}': invalid or truncated binary data")
    return np.frombuffer(data[:nbytes], dtype)


def _read_array(element, count, byte_order, header_dtype, path):
    """Return a DataArray element's values as an array of shape (count,) or (count, k)."""
    name = element.get("Name", "Points")
    type_name = element.get("type")
    if type_name not in _TYPES:
        raise InputError(path, f"DataArray '{name}': unsupported type {type_name!r}")
    dtype = np.dtype(byte_order + _TYPES[type_name])
    components = int(element.get("NumberOfComponents", "1"))
    fmt = element.get("format", "ascii")
    text = element.text or ""
    if fmt == "binary":
        values = _decode_binary(text, dtype, header_dtype, path, name)
    elif fmt == "ascii":
        values = np.array(text.split(), dtype=dtype)
    else:
        raise InputError(path, f"DataArray '{name}': unsupported format {fmt!r}")
    if values.size != count * components:
        raise InputError(path, f"DataArray '{name}': expected {count * components} "
                               f"values, found {values.size}")
    values = values.astype(dtype.newbyteorder("="))
    return values if components == 1 else values.reshape(count, components)


def read_vtu(path):
    """Read a .vtu file.

    Returns (points, fields): points is an (N, 3) float array, fields maps
    each PointData array name to an (N,) array (one component) or an (N, k)
    array (k components).
    """
    return _read_points(path, "UnstructuredGrid")


def read_vtp(path):
    """Read a .vtp file (a surface snapshot); returns (points, fields) as read_vtu."""
    return _read_points(path, "PolyData")


def _read_points(path, kind):
    """Points and point fields of the first piece of a `kind` file."""
    root = _parse(path, kind)
    if root.get("compressor"):
        raise InputError(path, "compressed data is not supported")
    byte_order = "<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">"
    header_type = root.get("header_type", "UInt32")
    if header_type not in ("UInt32", "UInt64"):
        raise InputError(path, f"unsupported header_type {header_type!r}")
    header_dtype = np.dtype(byte_order + _TYPES[header_type])

    piece = root.find(f"{kind}/Piece")
    if piece is None:
        raise InputError(path, "no <Piece> element")
    count = int(piece.get("NumberOfPoints", "0"))

    array = piece.find("Points/DataArray")
    if array is None:
        if count:
            raise InputError(path, "no <Points> data")
        points = np.zeros((0, 3))
    else:
        points = _read_array(array, count, byte_order, header_dtype, path)
        points = np.asarray(points, dtype=float).reshape(count, -1)

    fields = {}
    for array in piece.findall("PointData/DataArray"):
        fields[array.get("Name")] = _read_array(array, count, byte_order, header_dtype, path)
    return points, fields


def read_pvd(path):
    """Read a .pvd collection.

    Returns a list of (time, vtu_path) in file order; relative file names are
    resolved against the folder holding the .pvd.
    """
    root = _parse(path, "Collection")
    folder = os.path.dirname(path)
    entries = []
    for dataset in root.iter("DataSet"):
        name = dataset.get("file")
        if not name:
            raise InputError(path, "<DataSet> without a file attribute")
        try:
            time = float(dataset.get("timestep", "nan"))
        except ValueError:
            raise InputError(path, f"bad timestep for {name}") from None
        entries.append((time, os.path.join(folder, name)))
    return entries


def select_snapshots(entries, choice, path):
    """Pick (time, vtu) entries from a collection: an index, 'last' or 'all'."""
    if not entries:
        raise InputError(path, "the collection lists no snapshots")
    if choice == "last":
        return [entries[-1]]
    if choice == "all":
        count = min(MAX_PANELS, len(entries))
        picks = np.unique(np.round(np.linspace(0, len(entries) - 1, count)).astype(int))
        return [entries[i] for i in picks]
    try:
        return [entries[int(choice)]]
    except (ValueError, IndexError):
        raise InputError(path, f"no snapshot {choice!r} (the collection has "
                               f"{len(entries)}: use 0..{len(entries) - 1}, "
                               "-1, 'last' or 'all')") from None
