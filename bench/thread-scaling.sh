#!/usr/bin/env bash
# Threads inside a run on the coupon (issue 50): bench/decks/coupon-threads.toml with --threads N for each
# N in THREADS, REPEAT rounds, the thread counts interleaved within a round; prints each run's time loop
# (summary.json wall_time) and whole process, then the medians, the speed-up over one thread, and whether
# every run's summary.json (less wall_time and program) and history.csv are the same bytes as the first's.
#   bench/thread-scaling.sh [REPEAT] [THREADS] [EXE] [KEEP]   (from the repository root)
#   defaults: 3, "1 2", build/release/plyimpact; KEEP, when given, is a folder that receives the table
set -euo pipefail
repeat=${1:-3}
threads=${2:-"1 2"}
exe=${3:-build/release/plyimpact}
keep=${4:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
deck=bench/decks/coupon-threads.toml
nproc
for i in $(seq "$repeat"); do
  for n in $threads; do
    out="$work/r$i-t$n"
    start=$(date +%s.%N)
    "$exe" impact "$deck" -o "$out" --overwrite -q --threads "$n" >/dev/null 2>>"$work/stderr"
    end=$(date +%s.%N)
    loop=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['wall_time'])" "$out/summary.json")
    python3 - "$out" >"$work/r$i-t$n.key" <<'PY'
import hashlib, json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
s.pop("wall_time", None)
s.pop("program", None)
h = hashlib.sha256(json.dumps(s, sort_keys=True).encode())
h.update(open(sys.argv[1] + "/history.csv", "rb").read())
print(h.hexdigest())
PY
    echo "$n $i $loop $(python3 -c "print($end - $start)") $(cut -c1-12 "$work/r$i-t$n.key")" | tee -a "$work/times"
    [ -n "$keep" ] && cp "$work/times" "$keep/thread-times.txt"
    rm -rf "$out"
  done
done
python3 - "$work/times" <<'PY' | tee "$work/table"
import statistics, sys
runs, keys = {}, set()
for line in open(sys.argv[1]):
    n, _, loop, whole, key = line.split()
    runs.setdefault(int(n), []).append((float(loop), float(whole)))
    keys.add(key)
one = statistics.median(l for l, _ in runs[min(runs)])
print("| threads | time loop (median; range) | whole process (median) | speed-up of the loop |")
print("|---:|---:|---:|---:|")
for n, v in sorted(runs.items()):
    loops = [l for l, _ in v]
    l, w = statistics.median(loops), statistics.median(x for _, x in v)
    print(f"| {n} | {l:.2f} s ({min(loops):.2f}-{max(loops):.2f}) | {w:.2f} s | {one / l:.2f}x |")
print("same bytes for every run:", "yes" if len(keys) == 1 else f"NO ({len(keys)} different results)")
PY
[ -n "$keep" ] && cp "$work/table" "$keep/thread-table.md"
exit 0
