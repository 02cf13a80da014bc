#!/usr/bin/env python3
"""Compare sightline's solvers on a few instances: their anytime curves, as a plot.

Each solver runs once per instance with a time limit (1 s by default), from the same start
and seed, keeping its anytime trajectory (Result.trajectory: the best cost each time it
improved); the plot has one panel per instance and one step curve per solver, best feasible
cost against time (log scale). Where an instance's costs span orders of magnitude (a start
at 4e6, finals at 10310 and 10914), its cost axis is the cost above the lowest one reached,
on a symmetric log scale, so close finals stay apart.

    PYTHONPATH=build/python python3 examples/python/compare_solvers.py \
        [--out solvers.png] [--time-limit 1] [INSTANCE ...]

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
SOLVERS = ["sls", "tabu", "lns", "bnb", "sls>bnb"]


def plot_curves(ax, curves):
    """Step curves of (name, times, costs); relative to the lowest cost on a symlog axis when
    the costs above it span two orders of magnitude or more."""
    if not curves:
        return
    best = min(min(costs) for _, _, costs in curves)
    above = [c - best for _, _, costs in curves for c in costs if c > best]
    relative = bool(above) and max(above) >= 100 * min(above)
    for name, times, costs in curves:
        ax.step(times, [c - best for c in costs] if relative else costs, where="post", label=name)
    if relative:
        ax.set_yscale("symlog", linthresh=min(above))
        ax.set_ylabel(f"best cost - {best:g} (feasible; symlog)")
    else:
        ax.set_ylabel("best cost (feasible)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("instances", nargs="*", help="problem files (.yaml, .wcsp, .cfn)")
    parser.add_argument("--out", default="solvers.png", help="the PNG to write")
    parser.add_argument("--solvers", default=",".join(SOLVERS))
    parser.add_argument("--time-limit", type=float, default=1.0, help="seconds per solver")
    args = parser.parse_args()
    instances = [(path, 0) for path in args.instances] or [d for d in DEFAULT if os.path.exists(d[0])]
    solvers = args.solvers.split(",")
    fig, axes = plt.subplots(1, len(instances), figsize=(5 * len(instances), 4), squeeze=False)
    for ax, (path, colours) in zip(axes[0], instances):
        problem = sl.load_problem(path, colours=colours)
        print(f"{os.path.basename(path)}: {len(problem.variables)} variables, "
              f"{problem.num_constraints} constraints")
        curves = []
        for name in solvers:
            try:
                r = sl.solve(problem, name, time_limit=args.time_limit, seed=1)
            except ValueError as e:  # the solver does not take this problem
                print(f"  {name}: {e}")
                continue
            # (seconds, evaluations, cost, hard) at each improvement; feasible ones plotted.
            points = [(t, cost) for t, _, cost, hard in r.trajectory if hard <= 0]
            print(f"  {name:8s} cost {r.cost:g}{'' if r.feasible else ' (infeasible)'}, "
                  f"{len(r.trajectory)} improvements, best at {r.best_found_seconds:.4f} s, "
                  f"stop: {r.stop}")
            if points:
                times = [max(t, 1e-6) for t, _ in points] + [max(r.wall_seconds, points[-1][0])]
                costs = [c for _, c in points] + [points[-1][1]]
                curves.append((name, times, costs))
        plot_curves(ax, curves)
        ax.set_xscale("log")
        ax.set_xlabel("time (s)")
        ax.set_title(os.path.basename(path))
        ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
