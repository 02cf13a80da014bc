#!/usr/bin/env bash
# Renders a suite report (DIR/report.html) in headless Chromium and saves a screenshot, to
# check that it opens offline in a real browser. Installs Debian's chromium if missing.
#
#   scripts/check-report.sh out/thesis [out/thesis/report.png] [WIDTHxHEIGHT]
#
# The browser gets no network use beyond what a local file needs (no QUIC, no background
# networking, no component updates) and a throwaway profile directory.
set -euo pipefail
dir="${1:?usage: check-report.sh DIR [SCREENSHOT.png] [WIDTHxHEIGHT]}"
shot="${2:-$dir/report.png}"
size="${3:-1400x2400}"
report="$(realpath "$dir/report.html")"
[ -f "$report" ] || { echo "check-report: no $dir/report.html" >&2; exit 2; }

browser="$(command -v chromium || command -v chromium-browser || true)"
if [ -z "$browser" ]; then
  echo "check-report: installing chromium (apt-get)" >&2
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get install -y chromium >/dev/null
  browser="$(command -v chromium)"
fi

# Self-contained: nothing fetched from elsewhere.
if grep -Eq "(src|href)=['\"]?(https?:)?//" "$report"; then
  echo "check-report: $report references external resources" >&2
  exit 1
fi

profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --hide-scrollbars --window-size="${size/x/,}" \
  --screenshot="$(realpath -m "$shot")" "file://$report" >/dev/null 2>&1
[ -s "$shot" ] || { echo "check-report: no screenshot produced" >&2; exit 1; }
echo "check-report: $report rendered to $shot"
