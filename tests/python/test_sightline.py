"""The Python module against the C++ program: problems built in Python and solved by every
solver that takes them, the same optimum as `sightline solve`; a camera trace in numpy equal
to the CSV the program writes; a suite run from Python that resumes; bad input raising with
file and line."""
import csv
import os
import re
import subprocess

import numpy as np
import pytest

import sightline as sl

MEETINGS = """name: meetings
variables:
  - {name: m0, int: [0, 2]}
  - {name: m1, int: [0, 2]}
  - {name: m2, int: [0, 2]}
  - {name: m3, int: [0, 2]}
constraints:
  - {kind: not_equal, scope: [m0, m1], hard: true}
  - {kind: not_equal, scope: [m1, m2], hard: true}
  - {kind: not_equal, scope: [m2, m3]}
  - {kind: linear, scope: [m0, m3], coefficients: [1, 1], op: "<=", rhs: 1, weight: 2}
"""


def build_meetings():
    b = sl.ProblemBuilder("meetings")
    for name in ("m0", "m1", "m2", "m3"):
        b.integer(name, 0, 2)
    b.constrain("not_equal", ["m0", "m1"], hard=True)
    b.constrain("not_equal", ["m1", "m2"], hard=True)
    b.constrain("not_equal", ["m2", "m3"])
    b.constrain("linear", ["m0", "m3"], weight=2, coefficients=[1, 1], op="<=", rhs=1)
    return b.build()


def test_every_solver_that_takes_a_python_problem_reaches_the_programs_optimum(tmp_path, binary):
    path = tmp_path / "meetings.yaml"
    path.write_text(MEETINGS)
    out = subprocess.run([binary, "solve", str(path), "--solver", "bnb"], capture_output=True,
                         text=True, check=True).stdout
    program_cost = float(re.search(r"cost ([0-9.eE+-]+)", out).group(1))
    built = build_meetings()
    loaded = sl.load_problem(str(path))
    assert built.variables == loaded.variables == ["m0", "m1", "m2", "m3"]
    exact = sl.solve(built, "bnb")
    assert exact.stop == "proven optimal"
    assert exact.cost == pytest.approx(program_cost)
    assert sl.solve(loaded, "bnb").cost == pytest.approx(program_cost)
    tried = 0
    for info in sl.solvers():
        name = info["name"]
        try:
            r = sl.solve(built, name, time_limit=0.2, seed=1)
        except ValueError as e:  # a solver that does not take this problem says why
            assert "cannot solve" in str(e)
            continue
        tried += 1
        assert r.feasible, name
        assert r.cost >= exact.cost - 1e-9, name
        # The reported score is the problem's score of the reported assignment.
        assert built.score(r.values) == pytest.approx((r.hard, r.cost)), name
        assert set(r.assignment) == {"m0", "m1", "m2", "m3"}
    assert tried >= 4
    names = [name for name, _ in exact.breakdown]
    assert "not_equal(m2, m3)" in names  # constraints named by their variables' names


def test_values_come_back_as_their_labels(source_dir):
    problem = sl.load_problem(os.path.join(source_dir, "examples/problems/australia.yaml"))
    r = sl.solve(problem, "bnb")
    assert r.feasible
    assert set(r.assignment.values()) <= {"red", "green", "blue"}


def test_a_camera_trace_in_numpy_equals_the_programs_csv(tmp_path, binary, source_dir):
    scene = os.path.join(source_dir, "experiments/scenes/shots/walk-and-talk.yaml")
    csv_path = tmp_path / "walk.csv"
    subprocess.run([binary, "follow", scene, "--trace", str(csv_path)], check=True,
                   capture_output=True)
    run = sl.follow(scene)
    trace = run["trace"]
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(trace)
    for column in ("t", "char_x", "char_z", "cam_x", "cam_y", "cam_z", "target_x", "fov", "roll"):
        expected = np.array([float(r[column]) for r in rows])
        # The CSV keeps 4-6 decimals.
        assert np.allclose(trace[column], expected, atol=1e-3), column
    assert list(trace["cut"]) == [int(r["cut"]) for r in rows]
    assert "tracking shot" in run["summary"]


def test_a_solve_keeps_its_anytime_trajectory(source_dir):
    problem = sl.load_problem(os.path.join(source_dir, "examples/graphs/myciel5.col"), colours=5)
    r = sl.solve(problem, "tabu", max_evaluations=200000)
    assert r.trajectory, "an improvement at least"
    times = [t for t, _, _, _ in r.trajectory]
    costs = [c for _, _, c, h in r.trajectory if h == 0]
    assert times == sorted(times)
    assert costs == sorted(costs, reverse=True)
    assert r.trajectory[-1][2] == r.cost and r.trajectory[-1][3] == r.hard


def test_a_python_constraint_solves_like_the_kind_it_mimics():
    def model(python):
        b = sl.ProblemBuilder("colours")
        for v in "abcd":
            b.integer(v, 0, 2)
        for x, y in ("ab", "bc", "cd", "da", "ac"):
            if python:
                b.function([x, y], lambda p, q: 1.0 if p == q else 0.0, weight=2, label=f"{x} != {y}")
            else:
                b.constrain("not_equal", [x, y], weight=2)
        b.constrain("equals", ["a"], value=1)
        return b.build()
    for solver in ("bnb", "tabu", "sls"):
        kind = sl.solve(model(False), solver, max_evaluations=50000)
        python = sl.solve(model(True), solver, max_evaluations=50000)
        assert python.cost == kind.cost, solver
    assert sl.solve(model(True), "bnb").stop == "proven optimal"


def test_a_python_constraint_that_raises_or_returns_nonsense_fails_the_solve_clearly():
    def build(function):
        b = sl.ProblemBuilder("bad")
        b.integer("x", 0, 3)
        b.function(["x"], function, label="mine")
        return b.build()

    class Broken(Exception):
        pass

    def raises(x):
        raise Broken("no")
    with pytest.raises(Broken):
        sl.solve(build(raises), "sls", max_evaluations=100)
    with pytest.raises(TypeError, match="mine.*number"):
        sl.solve(build(lambda x: "high"), "sls", max_evaluations=100)
    with pytest.raises(ValueError, match="mine.*>= 0"):
        sl.solve(build(lambda x: -1.0), "bnb")
    b = sl.ProblemBuilder("scope")
    b.integer("x", 0, 1)
    with pytest.raises(ValueError, match="unknown variable 'y'"):
        b.function(["y"], lambda y: 0.0)


def test_a_conversation_is_edited_with_its_shots_and_the_judges_metrics(source_dir):
    scene = os.path.join(source_dir, "experiments/scenes/conversations/two-standing.yaml")
    film = sl.follow(scene)
    assert film["edit"]["edit_line_crossings"] == 0
    assert film["edit"]["edit_speaker_shown_pct"] >= 90
    starts = [t for t, _ in film["shots"]]
    assert starts == sorted(starts) and len(film["shots"]) >= 2
    assert sum(film["trace"]["cut"]) == len(film["shots"]) - 1
    greedy = sl.follow(scene, solver="greedy")
    assert "edited by 'greedy'" in greedy["summary"]


def test_a_suite_run_from_python_resumes(tmp_path, source_dir):
    suite = tmp_path / "suite.yaml"
    suite.write_text(
        "name: tiny\nproblems:\n  instances:\n    - {nqueens: [6, 8]}\n"
        "  solvers: [sls, bnb]\n  seeds: [1]\n  limits: {time_seconds: 1}\n")
    out = str(tmp_path / "out")
    first = sl.run_suite(str(suite), out)
    assert first["total"] == 4 and first["ran"] == 4 and first["failed"] == 0
    again = sl.run_suite(str(suite), out)
    assert again["reused"] == 4 and again["ran"] == 0
    rows = sl.load_results(out)
    assert len(rows) == 4
    assert {r["solver"] for r in rows} == {"sls", "bnb"}
    assert all(r["status"] == "ok" for r in rows)


def test_bad_input_raises_with_file_and_line(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("name: bad\nvariables:\n  - {name: x, int: [0, 2]}\nconstraints:\n"
                    "  - {kind: not_equal, scope: [x, y]}\n")
    with pytest.raises(sl.InputError) as caught:
        sl.load_problem(str(path))
    assert caught.value.file == str(path)
    assert caught.value.line == 5
    assert "y" in caught.value.detail
    with pytest.raises(sl.OptionError):
        sl.solve(build_meetings(), "no-such-solver")
    with pytest.raises(sl.OptionError):
        sl.solve(build_meetings(), "sls", options={"no_such_option": 1})
    with pytest.raises(TypeError):
        sl.solve(build_meetings(), 3)
    b = sl.ProblemBuilder("types")
    b.integer("x", 0, 1)
    with pytest.raises(TypeError):
        b.constrain("linear", ["x"], rhs=object())
    with pytest.raises(ValueError):
        b.constrain("not_equal", ["x", "nobody"])
    with pytest.raises(ValueError):
        sl.solve(build_meetings(), "sls", time_limit=-1)
