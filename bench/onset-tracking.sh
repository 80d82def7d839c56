#!/usr/bin/env bash
# Onset tracking against the untracked run (issue 50): bench/decks/coupon-onset.toml with its [damage]
# criteria and without them, N interleaved pairs (default 5); prints each run's time loop (summary.json
# wall_time) and whole process, then the medians and their ratio.
#   bench/onset-tracking.sh [N]        (from the repository root, after cmake --build --preset release)
set -euo pipefail
n=${1:-5}
exe=build/release/plyimpact
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
deck=bench/decks/coupon-onset.toml
sed '/^\[damage\]/,$d' "$deck" >"$work/plain.toml"
cp "$deck" "$work/tracked.toml"
for i in $(seq "$n"); do
  for run in plain tracked; do
    start=$(date +%s.%N)
    "$exe" impact "$work/$run.toml" -o "$work/$run" --overwrite -q >/dev/null 2>>"$work/stderr"
    end=$(date +%s.%N)
    loop=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['wall_time'])" "$work/$run/summary.json")
    echo "$run $i $loop $(python3 -c "print($end - $start)")" | tee -a "$work/times"
  done
done
python3 - "$work/times" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, _, loop, whole = line.split()
    runs.setdefault(name, []).append((float(loop), float(whole)))
med = {k: (statistics.median(l for l, _ in v), statistics.median(w for _, w in v)) for k, v in runs.items()}
for k, (l, w) in med.items():
    print(f"{k}: time loop {l:.2f} s, whole process {w:.2f} s (medians of {len(runs[k])})")
print(f"tracked / plain time loop: {med['tracked'][0] / med['plain'][0]:.2f}x")
PY
