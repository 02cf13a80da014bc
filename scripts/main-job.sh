#!/usr/bin/env bash
# The main job, on an already built tree: the thesis comparison suite (Bourne & Sattar's
# chase camera as published against Ali's occlusion-aware octree, the generic solvers and the
# baselines, on the thesis scenes) into out/thesis, printing its Markdown summary; the report
# is out/thesis/report.html. Then the same on walks through real Quake III maps (the levels
# suite, out/levels). Then reactive against anticipating cameras on the thesis scenes, the
# switchbacks, colonnade and mover scenes (out/anticipation) and on the level walks
# (out/anticipation-levels). Then the default camera against the thesis camera and the spring
# arm on every shipped scene and seeded generated walks and agile characters
# (out/default-camera, with its table). Then the toy-domain solver comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
./build/apps/sightline run experiments/suites/thesis.yaml --out out/thesis
echo
./build/apps/sightline run experiments/suites/levels.yaml --out out/levels
echo
./build/apps/sightline run experiments/suites/anticipation.yaml --out out/anticipation
echo
./build/apps/sightline run experiments/suites/anticipation-levels.yaml --out out/anticipation-levels
echo
./build/apps/sightline run experiments/suites/default-camera.yaml --out out/default-camera
python3 scripts/default_camera_table.py out/default-camera/results.csv --runs
echo
./build/apps/sightline compare
