#!/usr/bin/python3
"""Plot the series `pellicle validate` writes: every DIR/*.csv whose first line is
`# <title>` and second line a header becomes DIR/<same name>.png, the other columns plotted
against the first."""

import argparse
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def plot(path: pathlib.Path) -> pathlib.Path:
    with path.open() as f:
        title = f.readline().lstrip("#").strip()
        rows = list(csv.reader(f))
    header, data = rows[0], [[float(x) for x in r] for r in rows[1:] if r]
    if not data:
        raise ValueError("no data rows")
    columns = list(zip(*data))
    if any(name.startswith("exact ") for name in header):
        fig = plot_panels(title, header, columns)
    elif header[:2] == ["x", "y"]:
        fig = plot_points(title, header, columns)
    else:
        fig, ax = plt.subplots(figsize=(8, 4.5))
        for name, values in zip(header[1:], columns[1:]):
            style = "--" if name in ("exact", "modal solution") else "-"
            ax.plot(columns[0], values, style, label=name, linewidth=1.2)
        ax.set_xlabel(header[0])
        ax.set_title(title)
        ax.grid(alpha=0.3)
        ax.legend()
    out = path.with_suffix(".png")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


def plot_panels(title, header, columns):
    """One panel per quantity q that has an `exact q` column: computed values as dots, the
    exact solution as a line."""
    quantities = [h for h in header[1:] if f"exact {h}" in header]
    rows = (len(quantities) + 1) // 2
    fig, axes = plt.subplots(rows, 2, figsize=(10, 3.2 * rows), squeeze=False)
    for ax, q in zip(axes.flat, quantities):
        ax.plot(columns[0], columns[header.index(q)], ".", markersize=3, label="MPM")
        ax.plot(columns[0], columns[header.index(f"exact {q}")], "k-", linewidth=1, label="exact")
        ax.set_xlabel(header[0])
        ax.set_ylabel(q)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    for ax in list(axes.flat)[len(quantities):]:
        ax.set_visible(False)
    fig.suptitle(title)
    return fig


def plot_points(title, header, columns):
    """Point positions (x, y), one panel per further column, coloured by its value."""
    count = len(header) - 2
    fig, axes = plt.subplots(1, count, figsize=(5.2 * count, 4.6), squeeze=False)
    for ax, name, values in zip(axes.flat, header[2:], columns[2:]):
        shown = ax.scatter(columns[0], columns[1], c=values, s=4, cmap="viridis")
        fig.colorbar(shown, ax=ax, label=name)
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_title(name)
    fig.suptitle(title)
    return fig


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("directory", type=pathlib.Path)
    args = parser.parse_args()
    if not args.directory.is_dir():
        print(f"plot_validation.py: error: {args.directory}: not a directory", file=sys.stderr)
        return 2
    for path in sorted(args.directory.glob("*.csv")):
        try:
            print(plot(path))
        except (ValueError, IndexError) as e:
            print(f"plot_validation.py: error: {path}: {e}", file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
