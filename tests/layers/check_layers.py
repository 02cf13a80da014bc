#!/usr/bin/env python3
"""The tree's one-way rules (docs/ARCHITECTURE.md), checked on every #include: a folder may
include only the folders below it. Exit 1 naming each include that goes the wrong way.

usage: check_layers.py SOURCE_DIR
"""
import pathlib
import re
import sys

# What each folder may include besides itself (prefixes of "sightline/<path>"). A file obeys
# the most specific folder listed that holds it.
ALLOWED = {
    "csp": ["csp/constraint.h", "csp/domain.h", "csp/parameters.h", "csp/problem.h",
            "csp/incremental_evaluator.h", "csp/input_error.h", "csp/spec.h", "csp/score.h",
            "csp/json_text.h"],
    "csp/kinds": ["csp/constraint.h", "csp/domain.h", "csp/parameters.h", "csp/problem.h",
                  "csp/incremental_evaluator.h", "csp/input_error.h", "csp/spec.h",
                  "csp/score.h", "csp/kinds"],
    "csp/files": ["csp"],
    "solvers": ["csp", "solvers"],
    "domains": ["csp", "solvers", "domains", "world.h", "vec3.h"],
    # The camera domain: what a game's camera needs sits below its controller and baselines.
    "domains/camera": ["csp", "solvers", "domains/camera", "world.h", "vec3.h"],
    "domains/camera/control": ["csp", "solvers", "domains/camera", "world.h", "vec3.h"],
    "domains/camera/baselines": ["csp", "domains/camera", "world.h", "vec3.h"],
    "domains/camera/composition": ["csp", "solvers", "domains/camera", "world.h", "vec3.h"],
    "domains/camera/editing": ["csp", "solvers", "domains/camera", "world.h", "vec3.h"],
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
# Exceptions to ALLOWED: what a folder may not include although a prefix above allows it.
# The camera a game runs (domains/camera and its controller) knows nothing of the baselines,
# and the baselines nothing of the constraint camera's controller.
DENIED = {
    "domains/camera": ["domains/camera/control", "domains/camera/baselines",
                       "domains/camera/composition", "domains/camera/editing"],
    "domains/camera/control": ["domains/camera/baselines", "domains/camera/composition",
                               "domains/camera/editing"],
    "domains/camera/baselines": ["domains/camera/control", "domains/camera/composition",
                                 "domains/camera/editing"],
    "domains/camera/composition": ["domains/camera/control", "domains/camera/baselines",
                                   "domains/camera/editing"],
    "domains/camera/editing": ["domains/camera/control", "domains/camera/baselines"],
    "api": ["domains/camera/baselines"],
}
# Files of a folder built into a target above it: the scene file reader (camera_files) reads
# the shot: block, so it may include the composition's shot reader.
EXCEPTIONS = {
    "domains/camera/scene_file.cc": ["domains/camera/composition/shot.h"],
}
INCLUDE = re.compile(r'#include "sightline/([^"]+)"')


def owner(relative: str) -> str:
    """The most specific folder of ALLOWED holding `relative`, or ''."""
    best = ""
    for folder in ALLOWED:
        if relative.startswith(folder + "/") and len(folder) > len(best):
            best = folder
    return best


def main(root: pathlib.Path) -> int:
    wrong = []
    for top in sorted({f.split("/")[0] for f in ALLOWED}):
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in (".h", ".cc"):
                continue
            folder = owner(str(path.relative_to(root)))
            if not folder:
                continue
            allowed = ALLOWED[folder]
            for number, line in enumerate(path.read_text().splitlines(), 1):
                match = INCLUDE.search(line)
                denied = DENIED.get(folder, [])
                excepted = EXCEPTIONS.get(str(path.relative_to(root)), [])
                if match and match.group(1) not in excepted and (
                        not any(match.group(1).startswith(a) for a in allowed) or
                        any(match.group(1).startswith(d) for d in denied)):
                    wrong.append(f"{path.relative_to(root)}:{number}: {folder}/ may not include "
                                 f"sightline/{match.group(1)}")
    for w in wrong:
        print(w)
    print(f"{len(wrong)} includes against the layering" if wrong else "layering: ok")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))
