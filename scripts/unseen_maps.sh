#!/bin/sh
# The default camera against the thesis camera and the spring arm on walks of the Quake III
# maps no shipped walk uses (36 of the 40 maps in Debian's openarena-085-data and
# openarena-088-data; the shipped walks use the other four): 4 walks per map, made by
# `sightline level walk` (seed 300 + i for the i-th map), filmed by the suite this script
# writes, tabled by scripts/default_camera_table.py.
#
#   scripts/unseen_maps.sh OUT [SIGHTLINE]      (SIGHTLINE: default build/apps/sightline)
#
# Writes OUT/walks/*.yaml, OUT/unseen-maps.yaml, OUT/suite/ (results.csv, report.html) and
# prints the table and the default camera's runs that miss one of issue 24's marks. The maps
# are read from the installed packages, never copied. docs/EXPERIMENTS.md "The default
# camera on maps it was never tuned on" has the figures.
set -eu
out=${1:?usage: scripts/unseen_maps.sh OUT [SIGHTLINE]}
sightline=${2:-build/apps/sightline}
here=$(cd "$(dirname "$0")" && pwd)
baseoa=/usr/share/games/openarena/baseoa
maps="085:am_underworks 085:am_underworks2 085:blitzkrieg3 085:ctf_gate1 085:ctf_inyard
085:hydronex2 085:oa_koth2 085:oa_reptctf11 085:ps37ctf2 088:am_galmevish2 088:am_lavactf
088:am_mckinleyish2 088:am_spacecont 088:am_thornish 088:cbctf1 088:czest1dm 088:czest2ctf
088:czest3ctf 088:delta 088:mlca1 088:oasago1 088:oasago2 088:oa_bases3 088:oa_bases7
088:oa_ctf2 088:oa_ctf4ish 088:oa_koth1 088:oa_minia 088:oa_shouse 088:oa_spirit3 088:ps9ctf
088:pul1ctf 088:pul1duel-oa 088:pxlfan 088:sleekgrinder 088:slimefac"
mkdir -p "$out/walks"
i=0
for entry in $maps; do
  i=$((i + 1))
  pk3="$baseoa/pak6-patch${entry%%:*}.pk3"
  map=${entry#*:}
  "$sightline" level walk "$pk3" --map "$map" --walks 4 --seed $((300 + i)) \
    --out "$out/walks" > /dev/null
done
cat > "$out/unseen-maps.yaml" <<EOF
name: unseen-maps
description: the default camera, the thesis camera and the spring arm on 144 walks of 36 maps
camera:
  scenes:
    - $(cd "$out" && pwd)/walks/*.yaml
  solvers: [occlusion-octree, spring-arm]
  profiles: [default, thesis]
  seeds: [1]
EOF
"$sightline" run "$out/unseen-maps.yaml" --out "$out/suite" > /dev/null
python3 "$here/default_camera_table.py" "$out/suite/results.csv" --runs
