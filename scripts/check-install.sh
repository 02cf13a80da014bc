#!/usr/bin/env bash
# The installed package as a user meets it: installs BUILD_DIR into a temporary prefix, checks
# the runtime component's link interface and its shared library's dependencies, builds and
# runs a researcher's program on the static components and the installed program, then
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
