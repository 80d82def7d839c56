#!/usr/bin/env bash
# Sweep throughput (bench/README.md, "Sweeps"): cases per second for the thesis §4.2 plate
# (15 x 11, [45/90/-45/0]3s, dt = 1 us) swept over 12 impact velocities, at --jobs 1, --jobs 2,
# with 2 MPI ranks, at --jobs 1 without sharing the factorization of K-bar between cases, and at --jobs 1
# and 2 with every case solved in full ([sweep] plate_response = "full": no contact-point response).
# Usage: bench/sweep-bench.sh [ROUNDS]   (needs a configured and built build/release)
# On a shared machine give the measurement its own scheduling group for the minute it takes:
#   setsid bash -c 'echo -20 > /proc/self/autogroup && exec nice -n -20 bench/sweep-bench.sh 4' 
set -euo pipefail
cd "$(dirname "$0")/.."
exe=build/release/plyimpact
repeats=${1:-3} # rounds
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
deck=examples/thesis-4.2-velocity-2.92.toml
full_deck="$work/full.toml" # the same deck, every case solved in full
{ cat "$deck"; printf '\n[sweep]\nplate_response = "full"\n'; } > "$full_deck"
sets=(--set impactor.velocity=0.5:3.25:12)

run() { # label, command...: one timed sweep, its sweep.csv kept as $work/<label>.csv
  local label=$1 deck=$deck
  shift
  if [[ $label == full* ]]; then deck=$full_deck; fi
  rm -rf "$work/out"
  local load line cpu
  load=$(cut -d' ' -f1 /proc/loadavg)
  local TIMEFORMAT='%R s wall, %U s user + %S s sys'
  cpu=$( { time "$@" "$deck" -o "$work/out" "${sets[@]}" > "$work/stdout"; } 2>&1 )
  line=$(grep 'cases run in' "$work/stdout")
  echo "$label (load $load): $line [$cpu]"
  cp "$work/out/sweep.csv" "$work/$label.csv"
}

# Interleaved, so that a change in the machine's other load hits every variant alike.
for round in $(seq 1 "$repeats"); do
  echo "round $round"
  run jobs1 "$exe" sweep --jobs 1
  run jobs2 "$exe" sweep --jobs 2
  run mpi2 mpirun --allow-run-as-root --oversubscribe -n 2 "$exe" sweep --jobs 1
  run jobs1-no-sharing "$exe" sweep --jobs 1 --no-sharing
  run full-jobs1 "$exe" sweep --jobs 1
  run full-jobs2 "$exe" sweep --jobs 2
done
for t in jobs2 mpi2 jobs1-no-sharing; do
  cmp -s "$work/jobs1.csv" "$work/$t.csv" && echo "$t: sweep.csv identical to jobs1" || echo "$t: sweep.csv DIFFERS"
done
cmp -s "$work/full-jobs1.csv" "$work/full-jobs2.csv" && echo "full-jobs2: sweep.csv identical to full-jobs1" ||
  echo "full-jobs2: sweep.csv DIFFERS"
