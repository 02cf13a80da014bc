#!/usr/bin/env bash
# The installed package as a user meets it: installs BUILD_DIR into a temporary prefix, checks
# the runtime component's link interface and its shared library's dependencies, builds and
# runs a researcher's program on the static components and the installed program, then
# imports the installed Python module (where its interpreter looks under the prefix), then
# configures, builds and runs examples/embedding/ (C and C++) against the prefix, each from
# its own folder, and judges the C example's trace with `sightline view` (the independent
# visibility check and the unflagged-jump count). Run by ctest (test install_and_embed).
# Usage: check-install.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: check-install.sh BUILD_DIR}" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

# Installed in one place and used from another: the package must be relocatable.
cmake --install "$build" --prefix "$work/staging" >/dev/null
mv "$work/staging" "$prefix"
echo "installed, then moved to $prefix"

cmake -S "$root/tests/install/link_interface" -B "$work/link" -DCMAKE_PREFIX_PATH="$prefix" \
  | grep "link interface"
needed="$(readelf -d "$prefix"/lib*/libsightline.so | grep NEEDED || true)"
if grep -Eiq "assimp|libzip|mpi|boost_iostreams" <<<"$needed"; then
  echo "libsightline.so needs a file reader, importer or MPI:"; echo "$needed"; exit 1
fi

# Research code: the static components (csp, files, camera, suites) and their headers.
cmake -S "$root/tests/install/research" -B "$work/research" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/research" -j2 >/dev/null
echo "--- tests/install/research"
"$work/research/research_check" "$root/experiments/scenes/crammed-doorway.yaml"
"$prefix/bin/sightline" solvers >/dev/null

# The Python module (when built): installed where its interpreter looks under the configured
# prefix (python/CMakeLists.txt), and importable from there with what it needs.
location="$build/python/install-location.txt"
if [ -f "$location" ]; then
  { read -r python; read -r site; read -r configured; } < "$location"
  case "$site" in
    /*) echo "--- Python module installed to the absolute $site: not checked here" ;;
    *)
      echo "--- Python module in $site"
      PYTHONPATH="$prefix/$site" "$python" -c '
import sys
import sightline
assert sightline.__file__.startswith(sys.argv[1]), sightline.__file__
p = sightline.ProblemBuilder("x"); p.integer("a", 0, 1); r = sightline.solve(p.build(), "bnb")
print("imported", sightline.__file__, "-", r.stop)' "$prefix/$site"
      # Under the configured prefix, the interpreter itself searches that directory, when it
      # searches anything there (Debian's /usr/local and /usr).
      "$python" - "$configured" "$site" <<'PY'
import os, sys
prefix, site = sys.argv[1], sys.argv[2]
under = [p for p in sys.path if p.startswith(prefix.rstrip("/") + "/")]
if under and os.path.join(prefix, site) not in sys.path:
    sys.exit(f"{os.path.join(prefix, site)} is not on {sys.executable}'s path {under}")
print("on the interpreter's path under", prefix, ":", bool(under))
PY
      ;;
  esac
fi

map="/usr/share/games/openarena/baseoa/pak6-patch088.pk3"
for lang in c cpp; do
  cmake -S "$root/examples/embedding/$lang" -B "$work/$lang" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$work/$lang" -j2 >/dev/null
  echo "--- examples/embedding/$lang"
  (cd "$work/$lang" && "./sightline_${lang}_example")
  if [ ! -f "$map" ]; then continue; fi
  view="$("$build/apps/sightline" view "$root/experiments/scenes/levels/oa_thor-walk1.yaml" \
          --trace "$work/$lang/trace.csv" --out "$work/$lang/view.html")"
  echo "$view" | tail -n 1
  grep -q "hidden in 0 (independent check)" <<<"$view" \
    || { echo "the $lang example's trace hides the look-at point"; exit 1; }
  grep -q " 0 unflagged jumps" <<<"$view" \
    || { echo "the $lang example's trace has unflagged jumps"; exit 1; }
done
echo "install and embedding: ok"
