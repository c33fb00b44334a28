#!/usr/bin/python3
"""Scatter plot of Pellicle material points coloured by a point field.

Reads a results directory (through its points.pvd) or a single .vtu file,
plots the x-y positions of the points coloured by one field, and prints the
path of the PNG written. 3D data is shown as its x-y projection.

Without --field, a run with fluid points (the `fluid` flag of the snapshots)
shows the pressure of its fluid points and draws the other points (membranes,
solids) in dark grey; a run without fluid shows von_mises on every point.
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

# Field shown when the run has no fluid points.
DEFAULT_FIELD = "von_mises"
# Colour of the points a fluid-pressure picture leaves out of the colour scale.
OTHER_POINTS = "0.25"

# Component names accepted by --component, by number of components.
COMPONENT_NAMES = {
    3: ["x", "y", "z"],
    6: ["xx", "yy", "zz", "xy", "yz", "xz"],
}


def pressure_from_stress(stress):
    """p = -tr(sigma)/3 from the 6-component stress (xx, yy, zz, ...).

    Pellicle keeps the out-of-plane zz in 2D too, so the trace has three terms
    in both dimensions (this is how the writer's own `pressure` is defined).
    """
    return -(stress[:, 0] + stress[:, 1] + stress[:, 2]) / 3.0


def field_values(fields, name, component, path):
    """Return (values, label) of a field reduced to one scalar per point.

    Vectors default to their magnitude, tensors to their first component.
    `pressure` is derived from `stress` in files that lack it.
    """
    if name == "pressure" and name not in fields and "stress" in fields:
        fields = dict(fields, pressure=pressure_from_stress(np.asarray(fields["stress"])))
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


def fluid_points(fields):
    """Boolean mask of the fluid points, or None when the file flags none."""
    flag = fields.get("fluid")
    if flag is None or not np.any(flag):
        return None
    return np.asarray(flag) != 0


def default_field(fields):
    """The field shown without --field: fluid pressure if there is fluid."""
    has_pressure = "pressure" in fields or "stress" in fields
    return "pressure" if has_pressure and fluid_points(fields) is not None else DEFAULT_FIELD


def load(snapshots, field, component):
    """Read the snapshots [(time, vtu_path)] for plotting.

    Returns (frames, label, field): one (time, points, values, coloured) per
    snapshot, `coloured` marking the points that take colours. With field None
    the default_field of the first snapshot is used; when that is the fluid
    pressure, only the fluid points take colours.
    """
    fluid_only = False
    frames = []
    for time, vtu in snapshots:
        points, fields = read_vtu(vtu)
        if field is None:
            field = default_field(fields)
            fluid_only = field == "pressure"
        values, label = field_values(fields, field, component, vtu)
        coloured = fluid_points(fields) if fluid_only else None
        if coloured is None:
            coloured = np.ones(len(values), dtype=bool)
        frames.append((time, points, values, coloured))
    return frames, ("fluid " if fluid_only else "") + label, field


def plot(frames, label, out, strip=False):
    """Draw the frames from load() sharing one colour scale: up to 3 panels per
    row, or with `strip` all in one row. Points left out of the colour scale
    are drawn in grey.
    """
    is_3d = any(np.any(p[:, 2] != 0) for _, p, _, _ in frames if p.shape[1] > 2)
    shown = np.concatenate([v[c] for _, _, v, c in frames])
    finite = shown[np.isfinite(shown)]
    vmin, vmax = (finite.min(), finite.max()) if finite.size else (0.0, 1.0)
    xlim, ylim = limits([p for _, p, _, _ in frames])

    ncols = len(frames) if strip else min(3, len(frames))
    nrows = -(-len(frames) // ncols)
    aspect = np.clip(np.ptp(ylim) / np.ptp(xlim), 0.3, 2.0)
    panel = 3.5 if strip else 5
    fig, axes = plt.subplots(nrows, ncols, squeeze=False,
                             layout="compressed" if strip else None,
                             figsize=(panel * ncols + 1.2, (panel * aspect + 1) * nrows))
    scatters = []
    for ax, (time, points, values, coloured) in zip(axes.flat, frames):
        others = ax.scatter(points[~coloured, 0], points[~coloured, 1], c=OTHER_POINTS,
                            linewidths=0)
        scatters.append((others, ax.scatter(points[coloured, 0], points[coloured, 1],
                                            c=values[coloured], cmap="viridis",
                                            vmin=vmin, vmax=vmax, linewidths=0)))
        ax.set_xlim(xlim)
        ax.set_ylim(ylim)
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_title(f"t = {time:g}" if math.isfinite(time) else "")
    for ax in axes.flat[len(frames):]:
        ax.set_visible(False)
    fig.colorbar(scatters[0][1], ax=axes.ravel().tolist(), label=label, shrink=0.9)
    for (others, scatter), (_, points, _, coloured) in zip(scatters, frames):
        sizes = marker_sizes(scatter.axes, points[:, 0], points[:, 1])
        others.set_sizes(sizes[~coloured])
        scatter.set_sizes(sizes[coloured])

    title = label + (" (x-y projection of 3D data)" if is_3d else "")
    if len(frames) == 1:
        time = frames[0][0]
        axes[0, 0].set_title(title + (f", t = {time:g}" if math.isfinite(time) else ""))
    else:
        fig.suptitle(title)
    fig.savefig(out, dpi=120, bbox_inches="tight")
    plt.close(fig)


def evenly_in_time(entries, count, path):
    """`count` entries of a collection nearest to evenly spaced times, first to last."""
    if not entries:
        raise InputError(path, "the collection lists no snapshots")
    times = np.array([t for t, _ in entries])
    targets = np.linspace(times[0], times[-1], min(count, len(entries)))
    picks = np.unique([int(np.argmin(np.abs(times - t))) for t in targets])
    return [entries[i] for i in picks]


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
               "stress, strain, pressure, von_mises, body and fluid.")
    parser.add_argument("input", metavar="RESULTS_DIR_OR_VTU",
                        help="results directory holding points.pvd, a .pvd file, "
                             "or a single .vtu file")
    parser.add_argument("--field",
                        help="point field to colour every point by (default: the pressure "
                             "of the fluid points, other points in grey, when the run has "
                             "fluid; von_mises otherwise)")
    parser.add_argument("--component", metavar="K",
                        help="component of a vector or tensor field: an index from 0, "
                             "a name (x, y, z; xx, yy, zz, xy, yz, xz) or 'mag' "
                             "(default: magnitude of vectors, first component of tensors)")
    parser.add_argument("--snapshot", metavar="INDEX|last|all",
                        help="position in points.pvd (0 = first, negative counts from "
                             "the end), 'last' (default) or 'all' (up to "
                             f"{MAX_PANELS} evenly spaced snapshots)")
    parser.add_argument("--strip", metavar="N", type=int,
                        help="one row of N snapshots evenly spaced in time, first to last, "
                             "sharing one colour bar (instead of --snapshot)")
    parser.add_argument("--out", metavar="PNG",
                        help="output file (default: <results dir>/points_<field>.png, "
                             "points_<field>_strip.png with --strip)")
    args = parser.parse_args()

    path = args.input
    if os.path.isdir(path):
        path = os.path.join(path, "points.pvd")
    if args.strip is not None and args.snapshot is not None:
        parser.error("give either --strip or --snapshot")
    if args.strip is not None and args.strip < 1:
        parser.error("--strip needs N >= 1")
    try:
        if path.endswith(".vtu"):
            if not os.path.isfile(path):
                raise InputError(path, "no such file")
            if args.strip is not None:
                raise InputError(path, "--strip needs a results directory or a .pvd file")
            snapshots = [(time_from_pvd(path), path)]
        elif args.strip is not None:
            snapshots = evenly_in_time(read_pvd(path), args.strip, path)
        else:
            snapshots = select_snapshots(read_pvd(path), args.snapshot or "last", path)
        frames, label, field = load(snapshots, args.field, args.component)
        strip = "_strip" if args.strip is not None else ""
        out = args.out or os.path.join(os.path.dirname(path), f"points_{field}{strip}.png")
        plot(frames, label, out, strip=bool(strip))
    except InputError as err:
        parser.exit(2, f"{parser.prog}: error: {err.path}: {err.problem}\n")
    except OSError as err:
        parser.exit(2, f"{parser.prog}: error: {err.filename}: {err.strerror}\n")
    print(out)


if __name__ == "__main__":
    main()
