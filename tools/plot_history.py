#!/usr/bin/python3
"""Plot the histories in a Pellicle history.csv.

MPM runs: writes <prefix>energy.png (energies against time, with the relative
drift of the total energy in the title) and <prefix>bodies.png (centre-of-mass
position and velocity of every body against time). Surface runs (no energies):
writes <prefix>surface.png, every column of the history against time. Then
prints the paths.
"""

import argparse
import csv
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtk_reader import InputError  # noqa: E402

ENERGIES = ["kinetic", "strain", "internal", "gravitational"]


def read_history(path):
    """Read history.csv into a dict column name -> 1-D float array.

    A trailing incomplete row (a run still writing) is ignored.
    """
    with open(path, newline="") as stream:
        rows = [row for row in csv.reader(stream) if row]
    if not rows:
        raise InputError(path, "empty file")
    header = [name.strip() for name in rows[0]]
    body = rows[1:]
    if body and len(body[-1]) != len(header):
        body = body[:-1]
    if not body:
        raise InputError(path, "no data rows")
    try:
        table = np.array([[float(value) for value in row] for row in body])
    except ValueError:
        raise InputError(path, "not a history file (non-numeric data rows)") from None
    if table.shape[1:] != (len(header),):
        raise InputError(path, "rows have different numbers of columns")
    return dict(zip(header, table.T))


def column(history, name, path):
    """Return a required column or raise InputError."""
    if name not in history:
        raise InputError(path, f"missing column '{name}'")
    return history[name]


def energy_drift(history, path):
    """max |E - E0| / max(|E0|, max(kinetic + strain)); 0 when the scale is 0."""
    total = column(history, "total", path)
    zeros = np.zeros_like(total)
    scale = max(abs(total[0]),
                np.max(history.get("kinetic", zeros) + history.get("strain", zeros)))
    return np.max(np.abs(total - total[0])) / scale if scale > 0 else 0.0


def plot_energy(history, path, out):
    """Energies that are not identically zero, and the total, against time."""
    time = column(history, "time", path)
    total = column(history, "total", path)
    fig, ax = plt.subplots(figsize=(8, 5))
    for name in ENERGIES:
        if name in history and np.any(history[name] != 0):
            ax.plot(time, history[name], label=name)
    ax.plot(time, total, "k", linewidth=2, label="total")
    ax.set_xlabel("time")
    ax.set_ylabel("energy")
    ax.set_title(f"Energy (relative drift of total: {energy_drift(history, path):.3e})")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def body_names(history):
    """Body names in column order, from the '<body>.com_x' columns."""
    return [m.group(1) for name in history
            if (m := re.fullmatch(r"(.+)\.com_x", name))]


def plot_bodies(history, path, out):
    """Centre-of-mass position and velocity of each body (x solid, y dashed)."""
    time = column(history, "time", path)
    names = body_names(history)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 7))
    handles = []
    for i, body in enumerate(names):
        colour = f"C{i % 10}"
        for ax, quantity in ((top, "com"), (bottom, "vel")):
            ax.plot(time, column(history, f"{body}.{quantity}_x", path), color=colour)
            if f"{body}.{quantity}_y" in history:
                ax.plot(time, history[f"{body}.{quantity}_y"], "--", color=colour)
        handles.append(Line2D([], [], color=colour, label=body))
    handles += [Line2D([], [], color="grey", label="x"),
                Line2D([], [], color="grey", linestyle="--", label="y")]
    top.set_ylabel("centre of mass")
    bottom.set_ylabel("velocity")
    bottom.set_xlabel("time")
    top.set_title("Bodies" if names else "Bodies (none found in history)")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    top.legend(handles=handles, ncol=max(1, len(handles) // 8), fontsize="small")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def plot_columns(history, path, names, out):
    """Each named column against time, one panel each."""
    time = column(history, "time", path)
    fig, axes = plt.subplots(len(names), 1, sharex=True, figsize=(8, 2.6 * len(names)),
                             squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        ax.plot(time, column(history, name, path))
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(
        description="Plot energies and body centre-of-mass histories from history.csv.")
    parser.add_argument("input", metavar="RESULTS_DIR_OR_HISTORY_CSV",
                        help="results directory holding history.csv, or the CSV file itself")
    parser.add_argument("--out", metavar="PNG_PREFIX",
                        help="prefix of the output files: writes PREFIXenergy.png and "
                             "PREFIXbodies.png (default: the CSV's directory + '/')")
    parser.add_argument("--columns", metavar="NAME[,NAME...]",
                        help="also write PREFIXcolumns.png: these history columns against "
                             "time, one panel each (e.g. probe positions, gas.pressure)")
    args = parser.parse_args()

    path = args.input
    if os.path.isdir(path):
        path = os.path.join(path, "history.csv")
    prefix = args.out if args.out is not None else os.path.join(os.path.dirname(path), "")
    try:
        history = read_history(path)
        if "total" in history:
            outputs = (prefix + "energy.png", prefix + "bodies.png")
            plot_energy(history, path, outputs[0])
            plot_bodies(history, path, outputs[1])
        else:  # a surface run: point counts, management, area, the PDE's totals and errors
            outputs = (prefix + "surface.png",)
            plot_columns(history, path, [n for n in history if n not in ("time", "step")],
                         outputs[0])
        if args.columns:
            outputs += (prefix + "columns.png",)
            plot_columns(history, path, args.columns.split(","), outputs[-1])
    except InputError as err:
        parser.exit(2, f"{parser.prog}: error: {err.path}: {err.problem}\n")
    except OSError as err:
        parser.exit(2, f"{parser.prog}: error: {err.filename}: {err.strerror}\n")
    print("\n".join(outputs))


if __name__ == "__main__":
    main()
