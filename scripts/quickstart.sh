#!/usr/bin/env bash
# The main job: installs what is missing, builds (Release), and runs the main comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
bash scripts/main-job.sh
