#!/usr/bin/env python3
"""docs/validation.md's table of the figures CI measures, from what the validation tests record.

The validation tests write their figures to build/validation/<Suite.Test>.json (tests/support/
validation_figures.hpp): name, value, unit, tolerance, reference and the digits to show. This script

  --write   replaces the table between the markers in docs/validation.md with the recorded figures;
  --check   compares the committed table with the recorded figures at the table's digits, and exits 1
            naming each figure that moved (a figure whose test did not run is reported, not failed).

Usage: python3 scripts/validation_table.py --write [--figures build/validation] [--doc docs/validation.md]
       python3 scripts/validation_table.py --check [...]
"""
import argparse
import glob
import json
import math
import os
import sys

BEGIN = "<!-- ci-figures:begin (scripts/validation_table.py --write) -->"
END = "<!-- ci-figures:end -->"
HEADER = ["Test", "Figure", "grit", "Tolerance", "Reference"]


def formatted(value, digits):
    """The value at `digits` significant digits, signed (errors carry their sign)."""
    if value == 0 or not math.isfinite(value):
        return f"{value:+g}"
    return f"{value:+.{digits}g}"


def recorded(folder):
    """{(test, figure name): figure dict} from every <test>.json in `folder`."""
    out = {}
    for path in sorted(glob.glob(os.path.join(folder, "*.json"))):
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        for fig in data["figures"]:
            out[(data["test"], fig["name"])] = fig
    return out


def row(test, fig):
    value = formatted(fig["value"], fig.get("digits", 3)) + (" " + fig["unit"] if fig["unit"] not in ("", "-") else "")
    cells = [f"`{test}`", fig["name"], value, fig["tolerance"], fig["reference"]]
    return "| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |"


def table(figures):
    lines = ["| " + " | ".join(HEADER) + " |", "|" + "---|" * len(HEADER)]
    for (test, _), fig in sorted(figures.items(), key=lambda kv: kv[0]):
        lines.append(row(test, fig))
    return lines


def split_doc(text, doc):
    if BEGIN not in text or END not in text:
        sys.exit(f"{doc}: the markers {BEGIN!r} and {END!r} are missing")
    head, rest = text.split(BEGIN, 1)
    body, tail = rest.split(END, 1)
    return head, body, tail


def committed_rows(body):
    """{(test, figure name): the row's text} of the committed table."""
    rows = {}
    for line in body.strip().splitlines()[2:]:
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if len(cells) != len(HEADER):
            continue
        rows[(cells[0].strip("`"), cells[1])] = line.strip()
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--write", action="store_true")
    mode.add_argument("--check", action="store_true")
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--figures", default=os.path.join(root, "build", "validation"))
    parser.add_argument("--doc", default=os.path.join(root, "docs", "validation.md"))
    args = parser.parse_args()

    figures = recorded(args.figures)
    with open(args.doc, encoding="utf-8") as f:
        text = f.read()
    head, body, tail = split_doc(text, args.doc)

    if args.write:
        if not figures:
            sys.exit(f"{args.figures}: no recorded figures (run the validation tests first: make test)")
        with open(args.doc, "w", encoding="utf-8") as f:
            f.write(head + BEGIN + "\n" + "\n".join(table(figures)) + "\n" + END + tail)
        print(f"{args.doc}: {len(figures)} figures written")
        return 0

    rows = committed_rows(body)
    moved, missing, unrun = [], [], []
    for key, line in rows.items():
        fig = figures.get(key)
        if fig is None:
            unrun.append(key)
        elif row(key[0], fig) != line:
            moved.append(f"{key[0]}: {key[1]}: the table says {line.split(' | ')[2]}, the test measured "
                         f"{row(key[0], fig).split(' | ')[2]}")
    for key in figures:
        if key not in rows:
            missing.append(f"{key[0]}: {key[1]} is recorded but not in the table")
    for key in unrun:
        print(f"not run here: {key[0]}: {key[1]}")
    for problem in moved + missing:
        print(f"FAIL: {problem}")
    checked = len(rows) - len(unrun)
    print(f"{checked} figures checked, {len(moved) + len(missing)} differ, {len(unrun)} not run "
          f"(update the table with: python3 scripts/validation_table.py --write)")
    return 1 if moved or missing else 0


if __name__ == "__main__":
    sys.exit(main())
