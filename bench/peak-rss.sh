#!/usr/bin/env bash
# Peak memory of an impact run against its length (bench/README.md, "Peak memory"): the thesis §3.6
# example (8 626 steps with end = "auto") and the same deck with `end` ten times its end time, each
# run's maximum resident set size from GNU time; also the deck with `end` fixed at its own end time (the
# same 8 626 steps without the fundamental-period eigenproblem that end = "auto" solves, which is what
# sets the peak of the shipped deck) (`/usr/bin/time -v`, apt-get install time).
# history.csv is streamed to disk while the run goes, so the ratio should stay near 1 (issue 17 asks
# for at most 1.2).
#   bench/peak-rss.sh [EXE]   (default build/release/plyimpact)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build/release/plyimpact}
deck=examples/thesis-3.6-v268.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

peak_kb() { # deck, folder: runs the impact, prints its peak RSS in kB
  /usr/bin/time -v "$exe" impact "$1" -o "$2" >"$work/stdout" 2>"$work/time.txt" || {
    cat "$work/stdout" "$work/time.txt" >&2
    exit 1
  }
  sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt"
}

normal=$(peak_kb "$deck" "$work/normal")
end=$(jq -r .end_time "$work/normal/summary.json")
long_end=$(awk -v e="$end" 'BEGIN { printf "%.9g", 10 * e }')
sed "s/^end = .*/end = $end/" "$deck" >"$work/fixed.toml"
fixed=$(peak_kb "$work/fixed.toml" "$work/fixed")
sed "s/^end = .*/end = $long_end/" "$deck" >"$work/long.toml"
long=$(peak_kb "$work/long.toml" "$work/long")
steps() { jq -r .steps "$1/summary.json"; }
rows() { echo $(($(wc -l <"$1/history.csv") - 1)); }
printf '%-28s %9s %11s %12s\n' run steps "history rows" "peak RSS kB"
printf '%-28s %9s %11s %12s\n' "end = auto ($end s)" "$(steps "$work/normal")" "$(rows "$work/normal")" "$normal"
printf '%-28s %9s %11s %12s\n' "end = $end s (fixed)" "$(steps "$work/fixed")" "$(rows "$work/fixed")" "$fixed"
printf '%-28s %9s %11s %12s\n' "end = $long_end s (x10)" "$(steps "$work/long")" "$(rows "$work/long")" "$long"
awk -v a="$normal" -v f="$fixed" -v b="$long" \
  'BEGIN { printf "ratio x10 / shipped deck: %.3f, x10 / same end fixed: %.3f\n", b / a, b / f }'
