#!/usr/bin/python3
"""Scatter plot of Pellicle material points coloured by a point field.

Reads a results directory (through its points.pvd) or a single .vtu file,
plots the x-y positions of the points coloured by one field, and prints the
path of the PNG written. 3D data is shown as its x-y projection.
"""

import argparse
import math
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtk_reader import MAX_PANELS, InputError, read_pvd, read_vtu, select_snapshots  # noqa: E402

# Component names accepted by --component, by number of components.
COMPONENT_NAMES = {
    3: ["x", "y", "z"],
    6: ["xx", "yy", "zz", "xy", "yz", "xz"],
}


def field_values(fields, name, component, path):
    """Return (values, label) of a field reduced to one scalar per point.

    Vectors default to their magnitude, tensors to their first component.
    """
    if name not in fields:
        raise InputError(path, f"unknown field '{name}' (available: "
                               f"{', '.join(sorted(fields))})")
    data = np.asarray(fields[name], dtype=float)
    if data.ndim == 1:
        if component not in (None, "0"):
            raise InputError(path, f"field '{name}' has only one component")
        return data, name
    k = data.shape[1]
    names = COMPONENT_NAMES.get(k, [])
    if component is None:
        component = "mag" if k == 3 else "0"
    if component == "mag" and k != 6:
        return np.linalg.norm(data, axis=1), f"|{name}|"
    if component in names:
        index = names.index(component)
    elif component.isdigit() and int(component) < k:
        index = int(component)
    else:
        raise InputError(path, f"field '{name}' has {k} components: use 0..{k - 1}"
                               f"{''.join(', ' + n for n in names)}{'' if k == 6 else ' or mag'}")
    suffix = names[index] if names else str(index)
    return data[:, index], f"{name}_{suffix}"


def marker_sizes(ax, x, y):
    """Marker areas (points^2), one per point, making the cloud look solid.

    The area each point covers comes from a coarse histogram (about nine
    points per filled cell); taking the fullest of the neighbouring cells
    keeps markers on the edges of a body as small as those inside it.
    """
    if len(x) == 0:
        return np.ones(0)
    ax.apply_aspect()
    points_per_unit = (ax.get_window_extent().width * 72 / ax.figure.dpi
                       / np.ptp(ax.get_xlim()))
    width, height = max(np.ptp(x), 1e-12), max(np.ptp(y), 1e-12)
    cells = max(1.0, len(x) / 9)
    nx = max(1, int(round(math.sqrt(cells * width / height))))
    ny = max(1, int(round(cells / nx)))
    box = [[x.min(), x.min() + width], [y.min(), y.min() + height]]
    counts, xedges, yedges = np.histogram2d(x, y, bins=(nx, ny), range=box)
    padded = np.pad(counts, 1)
    fullest = np.max([padded[i:i + nx, j:j + ny] for i in range(3) for j in range(3)], axis=0)
    ix = np.clip(np.searchsorted(xedges, x, side="right") - 1, 0, nx - 1)
    iy = np.clip(np.searchsorted(yedges, y, side="right") - 1, 0, ny - 1)
    area = (width / nx) * (height / ny) / fullest[ix, iy] * points_per_unit ** 2
    return np.clip(3.0 * area, 0.3, 400.0)


def limits(clouds):
    """Common (xlim, ylim) around all clouds, with a small margin."""
    x = np.concatenate([c[:, 0] for c in clouds])
    y = np.concatenate([c[:, 1] for c in clouds])
    if x.size == 0:
        return (0, 1), (0, 1)
    margin = 0.03 * max(np.ptp(x), np.ptp(y), 1e-12)
    return (x.min() - margin, x.max() + margin), (y.min() - margin, y.max() + margin)


def plot(snapshots, field, component, out):
    """Plot the snapshots [(time, vtu_path)] in a grid sharing the colour scale."""
    frames = []
    for time, vtu in snapshots:
        points, fields = read_vtu(vtu)
        values, label = field_values(fields, field, component, vtu)
        frames.append((time, points, values))
    is_3d = any(np.any(p[:, 2] != 0) for _, p, _ in frames if p.shape[1] > 2)
    finite = np.concatenate([v[np.isfinite(v)] for _, _, v in frames])
    vmin, vmax = (finite.min(), finite.max()) if finite.size else (0.0, 1.0)
    xlim, ylim = limits([p for _, p, _ in frames])

    ncols = min(3, len(frames))
    nrows = -(-len(frames) // ncols)
    aspect = np.clip(np.ptp(ylim) / np.ptp(xlim), 0.3, 2.0)
    fig, axes = plt.subplots(nrows, ncols, squeeze=False,
                             figsize=(5 * ncols + 1.2, (5 * aspect + 1) * nrows))
    scatters = []
    for ax, (time, points, values) in zip(axes.flat, frames):
        scatters.append(ax.scatter(points[:, 0], points[:, 1], c=values, cmap="viridis",
                                   vmin=vmin, vmax=vmax, linewidths=0))
        ax.set_xlim(xlim)
        ax.set_ylim(ylim)
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_title(f"t = {time:g}" if math.isfinite(time) else "")
    for ax in axes.flat[len(frames):]:
        ax.set_visible(False)
    fig.colorbar(scatters[0], ax=axes.ravel().tolist(), label=label, shrink=0.9)
    for scatter, (_, points, _) in zip(scatters, frames):
        scatter.set_sizes(marker_sizes(scatter.axes, points[:, 0], points[:, 1]))

    title = label + (" (x-y projection of 3D data)" if is_3d else "")
    if len(frames) == 1:
        time = frames[0][0]
        axes[0, 0].set_title(title + (f", t = {time:g}" if math.isfinite(time) else ""))
    else:
        fig.suptitle(title)
    fig.savefig(out, dpi=120, bbox_inches="tight")
    plt.close(fig)


def time_from_pvd(vtu):
    """Time of a .vtu as listed in a points.pvd beside it, or NaN."""
    pvd = os.path.join(os.path.dirname(vtu), "points.pvd")
    try:
        for time, listed in read_pvd(pvd):
            if os.path.samefile(listed, vtu):
                return time
    except (InputError, OSError):
        pass
    return math.nan


def main():
    parser = argparse.ArgumentParser(
        description="Scatter plot of material points (x-y) coloured by a point field.",
        epilog="Fields written by Pellicle include velocity, mass, volume, density, "
               "stress, strain, pressure, von_mises and body.")
    parser.add_argument("input", metavar="RESULTS_DIR_OR_VTU",
                        help="results directory holding points.pvd, a .pvd file, "
                             "or a single .vtu file")
    parser.add_argument("--field", default="von_mises",
                        help="point field to colour by (default: von_mises)")
    parser.add_argument("--component", metavar="K",
                        help="component of a vector or tensor field: an index from 0, "
                             "a name (x, y, z; xx, yy, zz, xy, yz, xz) or 'mag' "
                             "(default: magnitude of vectors, first component of tensors)")
    parser.add_argument("--snapshot", metavar="INDEX|last|all", default="last",
                        help="position in points.pvd (0 = first, negative counts from "
                             "the end), 'last' (default) or 'all' (up to "
                             f"{MAX_PANELS} evenly spaced snapshots)")
    parser.add_argument("--out", metavar="PNG",
                        help="output file (default: <results dir>/points_<field>.png)")
    args = parser.parse_args()

    path = args.input
    if os.path.isdir(path):
        path = os.path.join(path, "points.pvd")
    try:
        if path.endswith(".vtu"):
            if not os.path.isfile(path):
                raise InputError(path, "no such file")
            snapshots = [(time_from_pvd(path), path)]
        else:
            snapshots = select_snapshots(read_pvd(path), args.snapshot, path)
        out = args.out or os.path.join(os.path.dirname(path), f"points_{args.field}.png")
        plot(snapshots, args.field, args.component, out)
    except InputError as err:
        parser.exit(2, f"{parser.prog}: error: {err.path}: {err.problem}\n")
    except OSError as err:
        parser.exit(2, f"{parser.prog}: error: {err.filename}: {err.strerror}\n")
    print(out)


if __name__ == "__main__":
    main()
