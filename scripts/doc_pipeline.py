#!/usr/bin/env python3
"""The pipeline table of docs/architecture.md, as `grit check --pipeline cases/demo.toml` prints it.

    python3 scripts/doc_pipeline.py --write build/grit   rewrites the block between the markers
    python3 scripts/doc_pipeline.py --check build/grit   exits 1 when the block differs from the output

so that the documented order of a step's stages cannot drift from the code's.
"""
import argparse
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "architecture.md"
CASE = ROOT / "cases" / "demo.toml"
BEGIN = "<!-- pipeline:begin (scripts/doc_pipeline.py --write) -->"
END = "<!-- pipeline:end -->"


def pipeline_text(grit):
    out = subprocess.run([grit, "check", str(CASE), "--pipeline"], check=True, capture_output=True, text=True).stdout
    lines = out.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("pipeline ("))
    body = "\n".join(lines[start:])
    return f"$ grit check cases/demo.toml --pipeline\n...\n{body}\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--write", metavar="GRIT")
    mode.add_argument("--check", metavar="GRIT")
    args = parser.parse_args()
    text = DOC.read_text()
    if BEGIN not in text or END not in text:
        sys.exit(f"{DOC}: the markers {BEGIN} and {END} are missing")
    head, rest = text.split(BEGIN, 1)
    committed, tail = rest.split(END, 1)
    block = "\n```\n" + pipeline_text(args.write or args.check) + "```\n"
    if args.write:
        DOC.write_text(head + BEGIN + block + END + tail)
        return 0
    if committed != block:
        print(f"{DOC}: the pipeline table differs from `grit check --pipeline {CASE.name}`; run "
              f"python3 scripts/doc_pipeline.py --write build/grit", file=sys.stderr)
        print("committed:\n" + committed + "\nnow:\n" + block, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
