#!/usr/bin/env bash
# Memory of a sweep (bench/README.md, "Per-case memory"): the heap that the sweep of
# bench/sweep-bench.sh (the thesis §4.2 plate, 15 x 11, swept over 12 velocities) holds while its cases
# run, at --jobs 1 and --jobs 2, through the contact-point response and with every case solved in full.
# The workers share the plate, so what a second job adds is the memory of one case in flight.
# Measured with heaptrack (Debian package heaptrack): its massif export gives the heap over time; the
# cases run after the set-up's peak (the assembly), so the median of the snapshots after that peak is
# the heap while the cases run.
# Usage: bench/sweep-memory.sh   (needs a configured and built build/release, and heaptrack)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=$PWD/build/release/plyimpact
command -v heaptrack > /dev/null || { echo "sweep-memory.sh: needs heaptrack (apt install heaptrack)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
deck=$PWD/examples/thesis-4.2-velocity-2.92.toml
{ cat "$deck"; printf '\n[sweep]\nplate_response = "full"\n'; } > "$work/full.toml"

measure() { # label, deck, jobs: prints the peak heap (the set-up's) and the heap while the cases run
  local label=$1 deck=$2 jobs=$3
  rm -rf "$work/out"
  heaptrack -o "$work/ht" "$exe" sweep --jobs "$jobs" "$deck" -o "$work/out" \
    --set impactor.velocity=0.5:3.25:12 -q > /dev/null 2>&1
  local peak
  peak=$(heaptrack_print -M "$work/massif" "$work/ht.zst" 2> /dev/null | grep 'peak heap memory consumption' | cut -d: -f2)
  rm -f "$work/ht.zst"
  grep -E '^mem_heap_B=' "$work/massif" | cut -d= -f2 > "$work/heap"
  local peak_line plateau
  peak_line=$(awk '$1 > peak { peak = $1; at = NR } END { print at, peak }' "$work/heap")
  # The median of the snapshots after the peak: the plateau while the cases run (the few snapshots of
  # the set-up's tail and of the exit do not move it).
  plateau=$(tail -n +"$((${peak_line% *} + 1))" "$work/heap" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)], NR }')
  awk -v label="$label" -v peak="$peak" -v plateau="${plateau% *}" -v n="${plateau#* }" 'BEGIN {
    printf "%-20s peak heap%s (set-up), while the cases run %6.3f MiB (median of %d snapshots)\n",
      label, peak, plateau / 2^20, n }'
}

measure "response, --jobs 1" "$deck" 1
measure "response, --jobs 2" "$deck" 2
measure "full, --jobs 1" "$work/full.toml" 1
measure "full, --jobs 2" "$work/full.toml" 2
