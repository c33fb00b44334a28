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
