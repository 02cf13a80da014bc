#!/usr/bin/env python3
"""Compare sightline's solvers on a few instances, cost against time budget, as a plot.

Each solver is given each time budget (10 ms to 1 s) on each instance, from the same start
and seed; the plot has one panel per instance, the best cost found within each budget per
solver (a solver's anytime curve sampled at those budgets), and the time it found it at.

    PYTHONPATH=build/python python3 examples/python/compare_solvers.py \
        [--out solvers.png] [INSTANCE ...]

Default instances: two of toulbar2's (../shared/data/wcsp) and a colouring graph.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

import sightline as sl  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
DEFAULT = [
    (os.path.join(ROOT, "..", "shared", "data", "wcsp", "example.wcsp"), 0),
    (os.path.join(ROOT, "..", "shared", "data", "wcsp", "celar7sub0.wcsp.gz"), 0),
    (os.path.join(ROOT, "examples", "graphs", "myciel5.col"), 5),
]
BUDGETS = [0.01, 0.03, 0.1, 0.3, 1.0]
SOLVERS = ["sls", "tabu", "lns", "bnb", "sls>bnb"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("instances", nargs="*", help="problem files (.yaml, .wcsp, .cfn)")
    parser.add_argument("--out", default="solvers.png", help="the PNG to write")
    parser.add_argument("--solvers", default=",".join(SOLVERS))
    args = parser.parse_args()
    instances = [(path, 0) for path in args.instances] or [d for d in DEFAULT if os.path.exists(d[0])]
    solvers = args.solvers.split(",")
    fig, axes = plt.subplots(1, len(instances), figsize=(5 * len(instances), 4), squeeze=False)
    for ax, (path, colours) in zip(axes[0], instances):
        problem = sl.load_problem(path, colours=colours)
        print(f"{os.path.basename(path)}: {len(problem.variables)} variables, "
              f"{problem.num_constraints} constraints")
        for name in solvers:
            costs = []
            for budget in BUDGETS:
                try:
                    r = sl.solve(problem, name, time_limit=budget, seed=1)
                except ValueError as e:  # the solver does not take this problem
                    print(f"  {name}: {e}")
                    break
                costs.append(r.cost if r.feasible else float("nan"))
                print(f"  {name:8s} {budget:6.2f} s: cost {r.cost:g}"
                      f"{'' if r.feasible else ' (infeasible)'}, best at {r.best_found_seconds:.3f} s, "
                      f"stop: {r.stop}")
            if costs:
                ax.plot(BUDGETS[:len(costs)], costs, marker="o", label=name)
        ax.set_xscale("log")
        ax.set_xlabel("time budget (s)")
        ax.set_ylabel("best cost (feasible)")
        ax.set_title(os.path.basename(path))
        ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
