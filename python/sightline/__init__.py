"""sightline: weighted constraint satisfaction with pluggable solvers, and camera control.

Build a problem (ProblemBuilder, or load_problem for .yaml, .wcsp, .cfn and .col files), solve
it with any registered solver (solvers() lists them), read a scene once (load_scene), film it
(follow), compose a shot of several people at one instant, judge a pose or every frame of a
trace on it (compose, evaluate_pose, evaluate_trace) and run suites (run_suite, load_results). Bad input raises InputError (a ValueError with file, line, column
and detail); unknown solvers and options raise OptionError.
"""
import csv as _csv

from ._sightline import (InputError, OptionError, Problem, ProblemBuilder, Result, Scene, compose,
                         evaluate_pose, evaluate_trace, follow, kinds, load_problem, load_scene,
                         run_suite, solve, solvers)

__all__ = ["InputError", "OptionError", "Problem", "ProblemBuilder", "Result", "Scene", "compose",
           "evaluate_pose", "evaluate_trace", "follow", "kinds", "load_problem", "load_scene",
           "run_suite", "solve", "solvers", "load_results", "to_dataframe"]


def to_dataframe(records):
    """A pandas DataFrame of a trace array or a list of result rows (pandas must be installed)."""
    import pandas  # optional: only this helper needs it
    return pandas.DataFrame(records)


def load_results(out_dir):
    """The rows of a suite's results.csv (OUT/results.csv) as a list of dicts, numbers as floats
    where the cell is a number; a DataFrame with to_dataframe(load_results(out))."""
    rows = []
    with open(f"{out_dir}/results.csv", newline="") as f:
        for row in _csv.DictReader(f):
            for key, value in row.items():
                try:
                    row[key] = float(value) if value not in ("", None) else None
                except ValueError:
                    pass
            rows.append(row)
    return rows
