#!/usr/bin/env bash
# The browser check of the 3D replay (docs/REPLAY.md): headless Chromium with software WebGL
# (SwiftShader) opens a thesis report and a level report at #run=..&t=..&panel=.. fragments,
# takes screenshots and asserts no JavaScript errors, a 3D view that is not blank, and the
# character's magenta in the main-camera panel exactly where the independent check says the
# look-at point is visible (present) and hidden (absent: Bourne & Sattar's camera as published
# above the roof of the thesis' enclosed room). Bash and python3's standard library only.
#
#   scripts/check-replay.sh [--build DIR] [--out DIR] [THESIS_REPORT_DIR LEVEL_REPORT_DIR]
#
# Without report folders it makes its own from experiments/suites/replay-check.yaml (the
# enclosed room and one short level walk, a few seconds) with DIR/apps/sightline (--build,
# default ./build), plus a `sightline view` page of the room's two traces (its three.js and
# data beside it, in view-assets/), and checks all three. Given report folders (from
# `sightline run experiments/suites/thesis.yaml` and `.../levels.yaml`) it checks those: the
# scene inside-room in the first, the first scene of the second. Screenshots and the
# browser's logs go to OUT/shots (default BUILD/replay-check).
#
# Exit status: 0 passed; 1 a check failed; 2 bad usage or a broken setup; 77 chromium is not
# installed (ctest reports the test as skipped).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build"
out=""
reports=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$(realpath -m "$2")"; shift 2 ;;
    --out) out="$(realpath -m "$2")"; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "check-replay: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) reports+=("$(realpath -m "$1")"); shift ;;
  esac
done
if [ ${#reports[@]} -ne 0 ] && [ ${#reports[@]} -ne 2 ]; then
  echo "check-replay: give two report folders (thesis, level) or none" >&2
  exit 2
fi
out="${out:-$build/replay-check}"

browser="$(command -v chromium || command -v chromium-browser || true)"
if [ -z "$browser" ]; then
  echo "check-replay: SKIPPED: chromium is not installed (scripts/install-deps.sh installs it)"
  exit 77
fi
command -v python3 >/dev/null || { echo "check-replay: python3 is needed" >&2; exit 2; }

mkdir -p "$out/shots"
rm -f "$out"/shots/*.png
check=(python3 "$root/scripts/check_replay.py" --browser "$browser" --out "$out/shots")
status=0
started=$SECONDS

if [ ${#reports[@]} -eq 0 ]; then
  sightline="$build/apps/sightline"
  [ -x "$sightline" ] || { echo "check-replay: no $sightline (build first)" >&2; exit 2; }
  # Fresh runs: a suite keeps finished runs, which may come from an older build.
  rm -rf "$out/suite"
  "$sightline" run "$root/experiments/suites/replay-check.yaml" --out "$out/suite" >/dev/null
  room=("$out"/suite/runs/inside-room__bourne-published__*.trace.csv
        "$out"/suite/runs/inside-room__occlusion-octree__*.trace.csv)
  # With its three.js and data beside the page (the report has them inline): both ways load.
  rm -rf "$out/view-assets"
  "$sightline" view "$root/experiments/scenes/inside-room.yaml" --trace "${room[0]}" \
    --trace "${room[1]}" --out "$out/view.html" --assets beside >/dev/null
  thesis="$out/suite/report.html"
  level="$out/suite/report.html"
  level_scene=(--scene aggressor-walk4)
else
  thesis="${reports[0]}/report.html"
  level="${reports[1]}/report.html"
  level_scene=()
fi
for page in "$thesis" "$level"; do
  [ -f "$page" ] || { echo "check-replay: no $page" >&2; exit 2; }
done

run_check() {
  local code=0
  "${check[@]}" "$@" || code=$?
  if [ "$code" -eq 2 ]; then exit 2; fi
  if [ "$code" -ne 0 ]; then status=1; fi
}

# (a) The thesis' enclosed room: magenta where the look-at point is visible (both cameras),
# none at bourne-published's hidden frame (above the roof).
run_check "$thesis" --name thesis --scene inside-room --run bourne-published \
  --run occlusion-octree --hidden-run bourne-published
# (b) A level walk: the occlusion-aware camera keeps the character in view through the map.
run_check "$level" --name level "${level_scene[@]}" --run occlusion-octree --visible-frames 3
# (c) `sightline view`'s page of the room's traces, when made here.
if [ ${#reports[@]} -eq 0 ]; then
  run_check "$out/view.html" --name view --scene inside-room --run bourne-published \
    --hidden-run bourne-published --visible-frames 1
fi

echo "check-replay: $([ $status -eq 0 ] && echo passed || echo FAILED) in $((SECONDS - started)) s;" \
  "screenshots in $out/shots"
exit $status
