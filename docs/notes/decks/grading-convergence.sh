#!/usr/bin/env bash
# Issue 16 convergence of the default grading: the default decks of cases (i)-(iii) (no mesh, no dt),
# then the same with size_at_impact and max_size halved twice (growth 1.25 kept). Prints one CSV row per
# run: case, refinement, elements, equations, peak force [N], change from the previous level [%].
#   docs/notes/decks/grading-convergence.sh [plyimpact executable]
set -euo pipefail
cd "$(dirname "$0")/../../.."
exe=${1:-build/release/plyimpact}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "case,refinement,elements,equations,peak_force_N,change_pct"
for c in i ii iii; do
  case $c in
    i) src=examples/thesis-3.6-v268.toml ;;
    *) src=docs/notes/decks/case-$c.toml ;;
  esac
  # The default deck: the [mesh] table, dt and the load model left out.
  sed -e '/^\[mesh\]/,/^$/d' -e '/^dt = /d' -e '/^load = /d' "$src" > "$tmp/$c.toml"
  [ "$c" = iii ] && sed -i 's/^end = "auto"/end = 400e-6/' "$tmp/$c.toml"
  "$exe" impact "$tmp/$c.toml" -o "$tmp/$c-0" > /dev/null 2>&1
  h0=$(jq '.mesh.smallest_element_m' "$tmp/$c-0/summary.json")
  hmax=$(jq '.mesh.largest_element_m' "$tmp/$c-0/summary.json")
  prev=""
  for level in 0 1 2; do
    if [ "$level" -gt 0 ]; then
      f=$((1 << level))
      { cat "$tmp/$c.toml"; printf '\n[mesh]\nsize_at_impact = %s\nmax_size = %s\n' \
          "$(awk -v h="$h0" -v f="$f" 'BEGIN { printf "%.9g", h / f }')" \
          "$(awk -v h="$hmax" -v f="$f" 'BEGIN { printf "%.9g", h / f }')"; } > "$tmp/$c-$level.toml"
      "$exe" impact "$tmp/$c-$level.toml" -o "$tmp/$c-$level" > /dev/null 2>&1
    fi
    s="$tmp/$c-$level/summary.json"
    F=$(jq '.peak_force' "$s")
    change=""
    [ -n "$prev" ] && change=$(awk -v a="$F" -v b="$prev" 'BEGIN { printf "%+.3f", 100 * (a / b - 1) }')
    echo "$c,$level,$(jq '.mesh.elements' "$s"),$(jq '.equations' "$s"),$F,$change"
    prev=$F
  done
done
