#!/usr/bin/env python3
"""Writes the ```yaml examples of the project's docs as seeds for the YAML fuzz targets.

The shipped files (scenes, problems, profiles) are the main seeds and are read where they
are; this adds the examples the docs give of what those files do not use, at run time, into
a folder that is never committed. Each block becomes OUT_DIR/<doc>-<n>.yaml as written. With
--problem, a block that is only a list of constraints (PROBLEM_FORMAT.md shows them so) is
made a whole problem: every name in its scopes is declared `int: [0, 9]`, so that the
reader gets as far as the constraint kinds.

usage: make_yaml_seeds.py [--problem] OUT_DIR DOC.md...
"""
import pathlib
import re
import sys

BLOCK = re.compile(r"^```yaml\n(.*?)^```", re.S | re.M)
SCOPE = re.compile(r"\bscopes?: *\[(.*?)\]\s*[,}\n]", re.S)
NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def as_problem(block):
    """A block of `- {kind: ...}` items as a whole problem file; other blocks as they are."""
    if not block.lstrip().startswith("- {kind:") and not block.lstrip().startswith("- kind:"):
        return block
    names = []
    for scope in SCOPE.findall(block):
        for name in NAME.findall(scope):
            if name not in names:
                names.append(name)
    variables = "".join(f"  - {{name: {n}, int: [0, 9]}}\n" for n in names)
    constraints = "".join("  " + line + "\n" for line in block.splitlines())
    return f"variables:\n{variables}constraints:\n{constraints}"


def main(args):
    problem = "--problem" in args
    args = [a for a in args if a != "--problem"]
    if len(args) < 2:
        sys.exit(__doc__)
    out = pathlib.Path(args[0])
    out.mkdir(parents=True, exist_ok=True)
    written = 0
    for doc in map(pathlib.Path, args[1:]):
        for n, block in enumerate(BLOCK.findall(doc.read_text()), 1):
            text = as_problem(block) if problem else block
            (out / f"{doc.stem.lower()}-{n}.yaml").write_text(text)
            written += 1
    print(f"{written} seeds in {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
