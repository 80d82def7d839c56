#!/usr/bin/env python3
"""Selective mass scaling of a stack against the unscaled run: wall time, median of interleaved repetitions.

    python3 bench/mass_scaling.py [--program build/release/plyimpact] [--repeat 3] [--threads 1] [--whole-event]

Pairs (each: the deck as shipped, then with `[time] mass_scaling = "selective"`; docs/mass_scaling.md):
- examples/impact-delamination-damage.toml to its end, 0.15 ms (ply damage and delamination, the run at
  half the stable step as `dt = "auto"` takes it with cracking plies);
- with --whole-event also examples/impact-delamination-explicit.toml and its selective twin, whole event
  (about 7 minutes a repetition on the 2-core machine).
The runs of a pair alternate repetition by repetition (interleaved), so a change in the machine's load hits
both. Prints, per run, the median, the smallest and largest wall time of the whole process, its steps, the
stable step, peak force and energy-balance error (bench/README.md, "Selective mass scaling of a stack").
"""
import argparse
import json
import pathlib
import re
import statistics
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]


def selective(text: str) -> str:
    text, n = re.subn(r"(?m)^(dt = \"auto\".*)$", r'\1\nmass_scaling = "selective"', text)
    if n != 1:
        raise SystemExit('deck changed: no `dt = "auto"` line to put mass_scaling after')
    return text


def pairs(whole_event: bool):
    damage = (ROOT / "examples/impact-delamination-damage.toml").read_text()
    yield ("impact-delamination-damage.toml to 0.15 ms", damage, selective(damage))
    if whole_event:
        yield ("impact-delamination-explicit.toml, whole event",
               (ROOT / "examples/impact-delamination-explicit.toml").read_text(),
               (ROOT / "examples/impact-delamination-explicit-selective.toml").read_text())


def run(program: str, deck: pathlib.Path, out: pathlib.Path, threads: int):
    start = time.monotonic()
    subprocess.run([program, "impact", str(deck), "-o", str(out), "--overwrite", "-q", "--threads", str(threads)],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    seconds = time.monotonic() - start
    return seconds, json.loads((out / "summary.json").read_text())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", default=str(ROOT / "build/release/plyimpact"))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--whole-event", action="store_true")
    args = parser.parse_args()
    print("| run | scaling | Δt | steps | peak force | balance error | wall time, median (min–max) |")
    print("|---|---|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        for name, unscaled, scaled in pairs(args.whole_event):
            decks = {"none": unscaled, "selective": scaled}
            times = {k: [] for k in decks}
            summaries = {}
            for k, text in decks.items():
                (work / f"{k}.toml").write_text(text)
            for _ in range(args.repeat):
                for k in decks:  # interleaved: none, selective, none, selective, ...
                    seconds, summaries[k] = run(args.program, work / f"{k}.toml", work / k, args.threads)
                    times[k].append(seconds)
            for k in decks:
                s = summaries[k]
                print(f"| {name} | {k} | {s['dt'] * 1e9:.2f} ns | {s['steps']} | {s['peak_force']:.2f} N | "
                      f"{s['energy_balance_error']:.1e} | {statistics.median(times[k]):.2f} s "
                      f"({min(times[k]):.2f}–{max(times[k]):.2f}) |")


if __name__ == "__main__":
    main()
