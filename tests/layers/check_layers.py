#!/usr/bin/env python3
"""The tree's one-way rules (docs/ARCHITECTURE.md), checked on every #include: a folder may
include only the folders below it. Exit 1 naming each include that goes the wrong way.

usage: check_layers.py SOURCE_DIR
"""
import pathlib
import re
import sys

# What each folder may include besides itself (prefixes of "sightline/<path>").
ALLOWED = {
    "csp": ["csp"],
    "solvers": ["csp", "solvers"],
    "domains": ["csp", "solvers", "domains", "world.h", "vec3.h"],
    "experiments/runs": ["csp", "solvers", "domains", "experiments/runs", "world.h", "vec3.h"],
    "experiments/sources": ["csp", "solvers", "domains", "experiments/runs", "experiments/sources"],
    "experiments/replay": ["csp", "solvers", "domains", "experiments/runs", "experiments/replay"],
    "experiments/suite": ["csp", "solvers", "domains", "experiments/runs", "experiments/sources",
                          "experiments/suite"],
    "experiments/reports": ["csp", "solvers", "domains", "experiments/runs", "experiments/replay",
                            "experiments/sources", "experiments/suite", "experiments/reports"],
    "experiments/execution": ["csp", "solvers", "domains", "experiments"],
    "api": ["csp", "solvers", "domains", "camera.h", "world.h", "vec3.h", "sightline.h",
            "level.h", "version.h"],
}
INCLUDE = re.compile(r'#include "sightline/([^"]+)"')


def main(root: pathlib.Path) -> int:
    wrong = []
    for folder, allowed in ALLOWED.items():
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".h", ".cc"):
                continue
            for number, line in enumerate(path.read_text().splitlines(), 1):
                match = INCLUDE.search(line)
                if match and not any(match.group(1).startswith(a) for a in allowed):
                    wrong.append(f"{path.relative_to(root)}:{number}: {folder}/ may not include "
                                 f"sightline/{match.group(1)}")
    for w in wrong:
        print(w)
    print(f"{len(wrong)} includes against the layering" if wrong else "layering: ok")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))
