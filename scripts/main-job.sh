#!/usr/bin/env bash
# The main job, on an already built tree.
set -euo pipefail
cd "$(dirname "$0")/.."
./build/apps/sightline compare
