#!/usr/bin/env bash
# Issue 16: peak force against the number of equations for point load / Hertz pressure x q9 / MITC9 x
# impact on an element-centre node (odd nx, ny: 15x9, 31x19, 61x37) / on a corner node shared by four
# elements (even: 16x10, 30x18, 60x36), uniform meshes, cases (ii) and (iii) of docs/validation.md §19;
# plus the default deck (graded MITC9, Hertz pressure). Prints one CSV row per run:
# case, series, nx, ny, equations, peak force [N]. docs/images/peak-force-vs-dofs.gp plots it.
#   docs/notes/decks/peak-force-vs-dofs.sh [plyimpact executable] > docs/notes/decks/peak-force-vs-dofs.csv
set -euo pipefail
cd "$(dirname "$0")/../../.."
exe=$(realpath "${1:-build/release/plyimpact}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
one() { # case end nx ny element load  (nx = default: the default deck)
  local tag="$1-$3-$4-$5-$6"
  if [ "$3" = default ]; then
    sed -e '/^\[mesh\]/,/^$/d' -e '/^dt = /d' -e '/^load = /d' -e "s/^end = .*/end = $2/" \
      "docs/notes/decks/case-$1.toml" > "$work/$tag.toml"
  else
    sed -e "s/^nx = .*/nx = $3/" -e "s/^ny = .*/ny = $4/" -e "s/^element = .*/element = \"$5\"/" \
      -e "s/^load = .*/load = \"$6\"/" -e "s/^end = .*/end = $2/" "docs/notes/decks/case-$1.toml" \
      > "$work/$tag.toml"
  fi
  "$exe" impact "$work/$tag.toml" -o "$work/$tag" > /dev/null 2>&1
  local node=centre
  [ "$3" != default ] && [ $(($3 % 2)) -eq 0 ] && node=corner
  [ "$3" = default ] && node=graded
  echo "$1,$5 $6 $node,$3,$4,$(jq '.equations' "$work/$tag/summary.json"),$(jq '.peak_force' "$work/$tag/summary.json")"
}
export -f one
export exe work
{
  for spec in "ii 1.6e-3" "iii 0.2e-3"; do
    read -r c end <<< "$spec"
    echo "$c $end default default mitc9 hertz-pressure"
    for mesh in "15 9" "31 19" "61 37" "16 10" "30 18" "60 36"; do
      for element in q9 mitc9; do
        for load in point hertz-pressure; do
          echo "$c $end $mesh $element $load"
        done
      done
    done
  done
} | xargs -P "$(nproc)" -L 1 bash -c 'one "$@"' _ > "$work/rows.csv"
echo "case,series,nx,ny,equations,peak_force_N"
sort -t, -k1,1 -k2,2 -k5,5n "$work/rows.csv"
