#!/usr/bin/python3
"""Pictures of a Pellicle surface run: its points in 3D coloured by a point field.

Reads a results directory (through its surface.pvd) or a single .vtp file and
draws one panel per snapshot (up to six evenly spaced with --snapshot all), the
points seen from one direction and coloured by the field; prints the PNG path.
"""

import argparse
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtk_reader import MAX_PANELS, InputError, read_pvd, read_vtp, select_snapshots  # noqa: E402

def scalar(fields, name, path):
    """One value per point: the field, or the magnitude of a vector field."""
    if name not in fields:
        raise InputError(path, f"unknown field '{name}' (available: {', '.join(sorted(fields))})")
    data = np.asarray(fields[name], dtype=float)
    return data if data.ndim == 1 else np.linalg.norm(data, axis=1)


def far_half(points, elevation, azimuth):
    """The points on the far side of the plane through the cloud's centre facing the viewer
    (as the paper shows its joining spheres): a cut through the surface."""
    e, a = np.radians(elevation), np.radians(azimuth)
    toward_viewer = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    return (points - centre) @ toward_viewer < 0.0


# Display axes (left-right, front-back, up) for each choice of the upward coordinate: a cyclic
# permutation, so the picture is not mirrored.
AXES_FOR_UP = {"z": (0, 1, 2), "y": (2, 0, 1), "x": (1, 2, 0)}


def plot(snapshots, field, elevation, azimuth, per_panel, out, half=False, up="z"):
    """Draw the panels with one colour scale for all of them, or one each (per_panel); with
    half, only the far half of each cloud; `up` is the coordinate drawn upward."""
    order = AXES_FOR_UP[up]
    frames = []
    for time, path in snapshots:
        points, fields = read_vtp(path)
        points = points[:, order]
        values = scalar(fields, field, path)
        if half:
            keep = far_half(points, elevation, azimuth)
            points, values = points[keep], values[keep]
        frames.append((time, points, values))
    low = min(np.nanmin(v) for _, _, v in frames)
    high = max(np.nanmax(v) for _, _, v in frames)
    columns = min(3, len(frames))
    rows = -(-len(frames) // columns)
    fig = plt.figure(figsize=(4.5 * columns, 4.2 * rows))
    every = np.concatenate([p for _, p, _ in frames])
    centre = 0.5 * (every.min(axis=0) + every.max(axis=0))
    half = 0.5 * (every.max(axis=0) - every.min(axis=0)).max()
    for k, (time, points, values) in enumerate(frames):
        ax = fig.add_subplot(rows, columns, k + 1, projection="3d")
        scale = (np.nanmin(values), np.nanmax(values)) if per_panel else (low, high)
        drawn = ax.scatter(points[:, 0], points[:, 1], points[:, 2], c=values, s=2,
                           cmap="viridis", vmin=scale[0], vmax=scale[1], depthshade=False)
        if per_panel:
            fig.colorbar(drawn, ax=ax, shrink=0.6, pad=0.12, label=field)
        for axis, set_limits in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
            set_limits(centre[axis] - half, centre[axis] + half)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=elevation, azim=azimuth)
        ax.set_title(f"t = {time:g}, {len(points)} points", fontsize=10)
        ax.set_xlabel("xyz"[order[0]])
        ax.set_ylabel("xyz"[order[1]])
        ax.set_zlabel("xyz"[order[2]])
    if not per_panel:
        fig.colorbar(drawn, ax=fig.axes, shrink=0.6, label=field)
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(
        description="3D pictures of a surface run's points coloured by a point field.",
        epilog="Fields written by Pellicle's surface runs include phi, curvature, velocity, "
               "normal, smoothing_length, boundary, chamber and, with an exact solution, exact "
               "and error.")
    parser.add_argument("input", metavar="RESULTS_DIR_OR_VTP",
                        help="results directory holding surface.pvd, a .pvd file or a .vtp file")
    parser.add_argument("--field", default="curvature", help="field to colour by (default: curvature)")
    parser.add_argument("--snapshot", metavar="INDEX|last|all", default="last",
                        help=f"position in surface.pvd, 'last' (default) or 'all' (up to {MAX_PANELS})")
    parser.add_argument("--elevation", type=float, default=25.0, help="view elevation, degrees")
    parser.add_argument("--azimuth", type=float, default=-60.0, help="view azimuth, degrees")
    parser.add_argument("--up", choices=("x", "y", "z"), default="z",
                        help="coordinate drawn upward (default: z)")
    parser.add_argument("--scale", choices=("shared", "panel"), default="shared",
                        help="one colour scale for all panels (default) or one per panel")
    parser.add_argument("--half", action="store_true",
                        help="only the half of the points away from the viewer (a cut, to see "
                             "inside: contact between surfaces)")
    parser.add_argument("--out", metavar="PNG", help="output (default: <dir>/surface_<field>.png)")
    args = parser.parse_args()
    path = os.path.join(args.input, "surface.pvd") if os.path.isdir(args.input) else args.input
    try:
        if path.endswith(".vtp"):
            if not os.path.isfile(path):
                raise InputError(path, "no such file")
            snapshots = [(float("nan"), path)]
        else:
            snapshots = select_snapshots(read_pvd(path), args.snapshot, path)
        out = args.out or os.path.join(os.path.dirname(path), f"surface_{args.field}.png")
        plot(snapshots, args.field, args.elevation, args.azimuth, args.scale == "panel", out,
             args.half, args.up)
    except InputError as err:
        parser.exit(2, f"{parser.prog}: error: {err.path}: {err.problem}\n")
    except OSError as err:
        parser.exit(2, f"{parser.prog}: error: {err.filename}: {err.strerror}\n")
    print(out)


if __name__ == "__main__":
    main()
