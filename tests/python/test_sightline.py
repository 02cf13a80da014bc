"""The Python module against the C++ program: problems built in Python and solved by every
solver that takes them (toulbar2 too, when installed), the same optimum as `sightline solve`;
a camera trace in numpy equal to the CSV the program writes, column for column; a suite run
from Python that resumes; Ctrl-C stopping a solve or a suite; bad input raising with file and
line, in Python's words; docs/PYTHON.md's examples running."""
import csv
import glob
import os
import re
import shutil
import signal
import subprocess
import threading
import time

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
        reader = csv.DictReader(f)
        rows = list(reader)
        columns = reader.fieldnames
    assert len(rows) == len(trace)
    # Every column of the CSV, in its order, is a column of the array.
    assert list(trace.dtype.names[:len(columns)]) == columns
    for column in columns:
        if trace.dtype[column].kind == "U":  # words: cut_reason (and shot in an edited run)
            assert list(trace[column]) == [r[column] for r in rows], column
            continue
        expected = np.array([float(r[column]) for r in rows])
        if column == "solve_us":  # timing: the two runs differ
            continue
        # The CSV keeps 3-6 decimals (cost 6 significant digits).
        assert np.allclose(trace[column], expected, atol=1e-3, rtol=1e-5), column
    assert "none" in set(trace["cut_reason"])
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
    assert {name for _, name in film["shots"]} <= set(film["trace"]["shot"])
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


def test_toulbar2_solves_from_python_and_in_its_suites(tmp_path, source_dir):
    if shutil.which("toulbar2") is None:
        pytest.skip("toulbar2 is not installed")
    assert "toulbar2" in [s["name"] for s in sl.solvers()]
    problem = sl.load_problem(os.path.join(source_dir, "examples/problems/seating.yaml"))
    r = sl.solve(problem, "toulbar2")
    assert r.stop == "proven optimal"
    assert r.cost == sl.solve(problem, "bnb").cost == 2
    # Fractional costs too (written scaled by 10^d, toulbar2's costs divided back).
    b = sl.ProblemBuilder("halves")
    for v in ("a", "b", "c"):
        b.integer(v, 0, 2)
    b.constrain("not_equal", ["a", "b"], weight=1.5)
    b.constrain("abs_deviation", ["c"], weight=0.5, target=2)
    b.constrain("linear", ["a", "b", "c"], weight=0.25, op="<=", rhs=1)
    halves = b.build()
    assert sl.solve(halves, "toulbar2").cost == sl.solve(halves, "bnb").cost
    suite = tmp_path / "suite.yaml"
    suite.write_text("name: t2\nproblems:\n  instances:\n    - {nqueens: [6]}\n"
                     "  solvers: [toulbar2, bnb]\n  seeds: [1]\n")
    out = str(tmp_path / "out")
    done = sl.run_suite(str(suite), out)
    assert done["ran"] == 2 and done["failed"] == 0
    assert {r["solver"]: r["status"] for r in sl.load_results(out)} == {"toulbar2": "ok", "bnb": "ok"}


def interrupt_after(seconds):
    """Ctrl-C to this process from a timer thread, as a terminal would send it."""
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def interrupt_once(ready, give_up_seconds=60):
    """Ctrl-C to this process from a thread, as soon as ready() holds (polled every 10 ms)."""
    def wait_then_interrupt():
        deadline = time.monotonic() + give_up_seconds
        while not ready() and time.monotonic() < deadline:
            time.sleep(0.01)
        os.kill(os.getpid(), signal.SIGINT)
    thread = threading.Thread(target=wait_then_interrupt)
    thread.start()
    return thread


def test_ctrl_c_interrupts_a_solve_without_a_time_limit(source_dir):
    # bnb cannot prove myciel5's 5-colouring optimum (1 conflict) in any reasonable time.
    problem = sl.load_problem(os.path.join(source_dir, "examples/graphs/myciel5.col"), colours=5)
    timer = interrupt_after(0.5)
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        sl.solve(problem, "bnb")
    timer.join()
    assert time.monotonic() - started < 10  # promptly, not at the end of the search
    # The module still works afterwards, and a solve nobody stops is not disturbed.
    assert sl.solve(build_meetings(), "bnb").stop == "proven optimal"


def test_ctrl_c_stops_a_suite_keeping_what_is_done_and_says_how_to_resume(tmp_path, source_dir):
    graph = os.path.join(source_dir, "examples/graphs/myciel5.col")
    suite = tmp_path / "suite.yaml"
    # 8 runs of 0.4 s each, one at a time: anytime solvers use their whole limit on a problem
    # whose optimum is above 0.
    suite.write_text(f"name: long\nproblems:\n  instances:\n    - {{graph: {graph}, colours: 5}}\n"
                     "  solvers: [sls, tabu]\n  seeds: [1, 2, 3, 4]\n  limits: {time_seconds: 0.4}\n")
    out = str(tmp_path / "out")
    # Once the first run is saved (not after a fixed time: on a loaded machine the first run
    # may not be done by then), while 7 runs of 0.4 s are still to come.
    timer = interrupt_once(lambda: bool(glob.glob(os.path.join(out, "runs", "*.result"))))
    with pytest.raises(KeyboardInterrupt) as caught:
        sl.run_suite(str(suite), out)
    timer.join()
    message = str(caught.value)
    assert "runs are done and saved" in message
    assert f"resume with: sightline.run_suite('{suite}', '{out}')" in message
    done = sl.load_results(out)
    assert 1 <= len(done) < 8
    again = sl.run_suite(str(suite), out)
    assert again["reused"] == len(done) and again["ran"] == 8 - len(done)


def test_messages_speak_pythons_words(tmp_path):
    graph = tmp_path / "g.col"
    graph.write_text("p edge 2 1\ne 1 2\n")
    with pytest.raises(sl.InputError) as caught:
        sl.load_problem(str(graph))
    assert "colours=K" in str(caught.value) and "--colours" not in str(caught.value)
    b = sl.ProblemBuilder("words")
    b.integer("x", 0, 2)
    with pytest.raises(ValueError, match=r"formula 'x \+ \+ ': cannot be parsed"):
        b.constrain("expression", ["x"], formula="x + + ")
    with pytest.raises(ValueError, match="got '5'"):
        b.constrain("linear", ["x"], op=5, rhs=1)


def test_the_examples_of_docs_python_md_run(tmp_path, source_dir, monkeypatch):
    with open(os.path.join(source_dir, "docs/PYTHON.md")) as f:
        blocks = re.findall(r"```python\n(.*?)```", f.read(), re.S)
    assert len(blocks) >= 2
    monkeypatch.chdir(source_dir)
    namespace = {}  # one session, as a reader runs the page's examples in order
    for block in blocks:
        # The suite example writes under out/: here into the test's folder, on a small suite.
        small = tmp_path / "small.yaml"
        small.write_text("name: small\nproblems:\n  instances:\n    - {nqueens: [6]}\n"
                         "  solvers: [sls]\n  seeds: [1]\n")
        block = block.replace('"experiments/suites/solvers.yaml"', repr(str(small)))
        block = block.replace('"out/solvers"', repr(str(tmp_path / "out")))
        exec(compile(block, "docs/PYTHON.md", "exec"), namespace)


def test_a_shot_composed_in_python_is_judged_alike_by_the_program(tmp_path, binary, source_dir):
    """compose() and evaluate_pose() against `sightline compose --evaluate`: the pose Python
    found, written as a pose file, gets the same verdict from the program; a dict and the
    file's path are judged alike; a pose that is no view and a scene without a shot raise."""
    import json
    scene = os.path.join(source_dir, "experiments/scenes/shots/walk-and-talk.yaml")
    shot = sl.compose(scene, time=1.0)
    assert shot["feasible"] and shot["solver"] == "shot-search" and shot["time"] == 1.0
    assert [p["kind"] for p in shot["properties"]]
    assert all(0 <= p["score"] <= 1 for p in shot["properties"])
    pose_path = tmp_path / "pose.json"
    pose_path.write_text(json.dumps({k: shot[k] for k in ("position", "look_at", "roll", "fov", "aspect")}))
    out = subprocess.run([binary, "compose", scene, "--time", "1", "--evaluate", str(pose_path),
                          "--format", "json"], check=True, capture_output=True, text=True)
    judged = json.loads(out.stdout)
    assert judged["satisfaction"] == pytest.approx(shot["satisfaction"], abs=1e-12)
    assert judged["feasible"] == shot["feasible"]
    by_path = sl.evaluate_pose(scene, str(pose_path), time=1.0)
    by_dict = sl.evaluate_pose(scene, shot, time=1.0)
    assert by_path["satisfaction"] == by_dict["satisfaction"] == pytest.approx(shot["satisfaction"])
    # Far outside the region: judged, infeasible, saying why.
    far = dict(shot, position=(500.0, 2.0, 500.0))
    verdict = sl.evaluate_pose(scene, far, time=1.0)
    assert not verdict["feasible"] and verdict["why_infeasible"]
    with pytest.raises(ValueError, match="not a view"):
        sl.evaluate_pose(scene, dict(shot, look_at=shot["position"]))
    bad = tmp_path / "bad.json"
    bad.write_text('{"position": [0, 1]}')
    with pytest.raises(sl.InputError) as e:
        sl.evaluate_pose(scene, str(bad))
    assert e.value.line == 1
    with pytest.raises(ValueError, match="no shot"):
        sl.compose(os.path.join(source_dir, "experiments/scenes/open-field.yaml"))


def test_a_trace_is_judged_frame_by_frame_as_each_pose_alone(source_dir):
    """evaluate_trace() against evaluate_pose() at each frame's time: the same satisfaction,
    feasibility and per-property scores on every tenth frame of a filmed tracking shot; a
    scene loaded once films and composes as its path does; a frame with no view is judged
    infeasible, not raised; a trace missing a column or with columns of different lengths,
    and a scene that is no Scene or path, raise."""
    path = os.path.join(source_dir, "experiments/scenes/shots/circling-dialogue.yaml")
    scene = sl.load_scene(path)
    assert scene.has_shot and scene.frames > 100 and len(scene.people) >= 2
    film = sl.follow(scene)
    assert np.array_equal(film["trace"]["cam_x"], sl.follow(path)["trace"]["cam_x"])
    trace = film["trace"]
    judged = sl.evaluate_trace(scene, trace)
    n = len(judged["properties"])
    assert judged["scores"].shape == judged["measures"].shape == (len(trace), n)
    assert [(p["kind"], p["targets"]) for p in judged["properties"]] == \
        [(p["kind"], p["targets"]) for p in sl.evaluate_pose(path, sl.compose(scene))["properties"]]
    for i in range(0, len(trace), 10):
        row = trace[i]
        pose = {"position": [float(row[k]) for k in ("cam_x", "cam_y", "cam_z")],
                "look_at": [float(row[k]) for k in ("target_x", "target_y", "target_z")],
                "fov": float(row["fov"]), "roll": float(row["roll"])}
        alone = sl.evaluate_pose(scene, pose, time=float(row["t"]))
        assert judged["satisfaction"][i] == pytest.approx(alone["satisfaction"], abs=1e-12)
        assert judged["feasible"][i] == alone["feasible"]
        assert judged["why_infeasible"][i] == alone["why_infeasible"]
        assert list(judged["scores"][i]) == pytest.approx([p["score"] for p in alone["properties"]], abs=1e-12)
    # A dict of lists is a trace too; a frame looking straight down has no view.
    columns = {k: [float(v) for v in trace[k]] for k in
               ("t", "cam_x", "cam_y", "cam_z", "target_x", "target_y", "target_z", "fov", "roll")}
    columns["target_x"][0], columns["target_z"][0] = columns["cam_x"][0], columns["cam_z"][0]
    columns["target_y"][0] = columns["cam_y"][0] - 1
    by_dict = sl.evaluate_trace(path, columns)
    assert not by_dict["feasible"][0] and "no view" in by_dict["why_infeasible"][0]
    assert np.array_equal(by_dict["satisfaction"][1:], judged["satisfaction"][1:])
    with pytest.raises(ValueError, match="no column 'fov'"):
        sl.evaluate_trace(scene, {k: v for k, v in columns.items() if k != "fov"})
    with pytest.raises(ValueError, match="'roll' has 1 values"):
        sl.evaluate_trace(scene, dict(columns, roll=[0.0]))
    with pytest.raises(ValueError, match="not a finite number"):
        sl.evaluate_trace(scene, dict(columns, t=[float("nan")] * len(columns["t"])))
    with pytest.raises(TypeError, match="sightline.Scene or a path"):
        sl.evaluate_trace(3, trace)
    with pytest.raises(ValueError, match="no shot"):
        sl.evaluate_trace(os.path.join(source_dir, "experiments/scenes/open-field.yaml"), trace)
