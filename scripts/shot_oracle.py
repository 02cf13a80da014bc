#!/usr/bin/env python3
"""How much of a tracking shot could be held at all: the frames where no pose holds everyone.

A tracking shot cannot keep everyone it names framed and visible when, at some instants, no
camera pose in the shot's region does (three people crossing in a line, two walking one
behind the other). This script films each scene with the default tracking camera (the
Python module's `follow`) and judges every frame by the shot's own `framed` and `visible`
properties (FORMATS.md "Shots"; `evaluate_trace`): everyone is *held* when each of those
properties scores 1.
For each frame the camera does not hold everyone, it solves the shot at that instant
offline with shot-search and with particle-swarm (BUDGET ms each); when neither finds a pose
that holds everyone, the frame is one no pose holds. It prints, per scene and in total, the
frames held, those no pose holds, and the share held of the rest.

The offline solves bound the frames no pose holds from above (a solver can miss a pose).
"Held" is stricter than the suites' `shot_shown_min_pct`, which counts each person on their
own, in the image (not the property's `rect`) and seen by the independent check's sight
lines. docs/COMPOSITION.md "Tracking shots" has the figures.

  PYTHONPATH=build/python scripts/shot_oracle.py SCENE.yaml [SCENE.yaml ...] [--budget-ms 30]

A generated tracking shot is written by `sightline scene tracking-shot SEED --out FILE`.
"""
import argparse
import sys

import sightline


def held(kinds, scores):
    """Everyone held: each framed and visible property scores 1."""
    return all(score >= 0.999 for kind, score in zip(kinds, scores) if kind in ("framed", "visible"))


def judge(path, budget_ms):
    scene = sightline.load_scene(path)  # read once: each frame's solves reuse it
    trace = sightline.follow(scene)["trace"]
    judged = sightline.evaluate_trace(scene, trace)
    kinds = [p["kind"] for p in judged["properties"]]
    held_frames = no_pose = 0
    for t, scores in zip(judged["t"], judged["scores"]):
        if held(kinds, scores):
            held_frames += 1
            continue
        kept = any(held(kinds, [p["score"] for p in sightline.compose(
                       scene, solver=name, time=float(t), budget_ms=budget_ms)["properties"]])
                   for name in ("shot-search", "particle-swarm"))
        no_pose += 0 if kept else 1
    return len(trace), held_frames, no_pose


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scenes", nargs="+", help="scene files with a shot: block and actors")
    parser.add_argument("--budget-ms", type=float, default=30, help="each offline solve's budget")
    args = parser.parse_args()
    print("| scene | frames | everyone held (%) | frames no pose holds everyone | "
          "held of the others (%) |")
    print("|---|---:|---:|---:|---:|")
    totals = [0, 0, 0]
    for scene in args.scenes:
        try:
            frames, held, no_pose = judge(scene, args.budget_ms)
        except (ValueError, RuntimeError) as e:
            print(f"{scene}: {e}", file=sys.stderr)
            return 1
        totals = [a + b for a, b in zip(totals, (frames, held, no_pose))]
        possible = max(1, frames - no_pose)
        print(f"| {scene} | {frames} | {held} ({100 * held / frames:.1f}) | {no_pose} | "
              f"{100 * held / possible:.1f} |")
    frames, held, no_pose = totals
    if len(args.scenes) > 1:
        print(f"| all | {frames} | {held} ({100 * held / max(1, frames):.1f}) | {no_pose} | "
              f"{100 * held / max(1, frames - no_pose):.1f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
