#!/usr/bin/env bash
# The finite-element runs of docs/notes/contact-reference.md: each deck of this folder on centre-node
# (odd nx, ny) and corner-node (even) meshes, q9 / mitc9, point / hertz-pressure, impact at the plate
# centre. Prints one CSV line per run: deck, nx, ny, element, load, peak force [N], time of peak [us],
# first contact duration [us]. `end` is cut shortly after the first contact to keep the runs short.
#   docs/notes/decks/fe-runs.sh build/release/plyimpact > fe-runs.csv
set -euo pipefail
exe=${1:-build/release/plyimpact}
dir=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "deck,nx,ny,element,load,peak_force_N,time_of_peak_us,contact_duration_us"
run() { # deck end nx ny element load
  sed -e "s/^nx = .*/nx = $3/" -e "s/^ny = .*/ny = $4/" -e "s/^element = .*/element = \"$5\"/" \
      -e "s/^load = .*/load = \"$6\"/" -e "s/^end = .*/end = $2/" "$dir/$1.toml" > "$work/deck.toml"
  "$exe" impact "$work/deck.toml" -o "$work/out" > /dev/null
  python3 -c "import json; d = json.load(open('$work/out/summary.json')); \
print('$1,$3,$4,$5,$6,%.2f,%.2f,%.2f' % (d['peak_force'], d['time_of_peak_force'] * 1e6, d['contact_duration'] * 1e6))"
}
for spec in "case-ii 1.6e-3" "case-iii 0.2e-3" "light-ball-t300 0.2e-3"; do
  read -r deck end <<< "$spec"
  for mesh in "15 9" "31 19" "61 37" "30 18" "60 36"; do
    for element in q9 mitc9; do
      for load in point hertz-pressure; do
        run "$deck" "$end" $mesh "$element" "$load"
      done
    done
  done
done
