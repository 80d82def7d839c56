#!/usr/bin/env bash
# `plyimpact preview` of every shipped example (issue 82: at most 5 s each), N runs each (default 3): the
# median wall time per deck, slowest last, and the largest median.
#   bench/preview-time.sh [N]        (from the repository root, after cmake --build --preset release)
set -euo pipefail
n=${1:-3}
exe=build/release/plyimpact
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for i in $(seq "$n"); do
  for deck in examples/*.toml; do
    name=$(basename "$deck" .toml)
    start=$(date +%s.%N)
    "$exe" preview "$deck" -o "$work/$name" >/dev/null 2>>"$work/stderr"
    end=$(date +%s.%N)
    echo "$name $(python3 -c "print($end - $start)")" >>"$work/times"
  done
done
python3 - "$work/times" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, t = line.split()
    runs.setdefault(name, []).append(float(t))
med = sorted((statistics.median(v), k) for k, v in runs.items())
for t, k in med[-10:]:
    print(f"{k:45s} {t:6.2f} s")
print(f"{len(med)} decks: median of the medians {statistics.median(t for t, _ in med):.2f} s, largest {med[-1][0]:.2f} s ({med[-1][1]})")
PY
