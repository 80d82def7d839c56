#!/usr/bin/env python3
"""Time to accuracy (issue 22): the peak force of an impact against its converged value, and the time
of the whole process, for meshes × time steps, on two cases of the mesh-objective contact's reference
(docs/notes/contact-reference.md, tests/io/run/test_mesh_objective_impact.cpp), both run with the program's
defaults (Hertz pressure, MITC9), which converge:

  heavy  the §3.6 impact, examples/thesis-3.6-v268.toml without its thesis choices (point force, q9,
         15 × 11): 6.14 kg at 2.68 m/s, a 4.3 ms contact; reference (i), 12 878.0 N;
  light  the §4.2 plate [0_2/90_4/0_2] of the same material struck by an 8.4 g steel ball (R = 6.35 mm,
         k = "auto") at 3 m/s, a 135 µs contact, run to 400 µs; reference (iii), 447.94 N.

  light-auto  the light case run to the end-of-event rule (end = "auto", the default): a 135 µs contact
         and a free vibration of about 1 ms after it, where nothing changes the contact force.

Each cell runs `plyimpact impact DECK -o DIR -q` (set-up, time loop, outputs, plots) REPEATS times and
reports the median wall time and the peak force's error. Then each case runs on its default graded mesh
with error-controlled steps ([time] adaptive = true) at a range of tolerances, from the largest fixed step
of its table down to the smallest.

Usage: bench/time_to_accuracy.py [REPEATS]   (needs build/release/plyimpact; bench/README.md)
"""
import json
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PROGRAM = ROOT / "build/release/plyimpact"
MESHES = ["graded", (5, 3), (7, 5), (9, 7), (15, 11)]  # "graded": no nx/ny, the default mesh


def heavy(mesh, dt_us):
    """The §3.6 deck with the program's defaults, on `mesh` at Δt = dt_us."""
    text = (ROOT / "examples/thesis-3.6-v268.toml").read_text()
    text = re.sub(r"\[mesh\].*?\n\n", "", text, flags=re.S)  # thesis mesh, q9, lumped: all removed
    text = re.sub(r'load = "point".*\n', "", text)  # default: the Hertz pressure
    text = text.replace("dt = 1.0e-6", f"dt = {dt_us}e-6")
    return text + mesh_table(mesh)


def light(mesh, dt_us):
    """Case (iii): the §4.2 plate struck by an 8.4 g ball, on `mesh` at Δt = dt_us."""
    text = heavy("graded", dt_us)
    text = text.replace('layup = "[45/90/-45/0]3s"', 'layup = "[0_2/90_4/0_2]"')
    text = re.sub(r"ply_thickness = .*\n", "ply_thickness = 0.58125e-3\n", text)
    text = re.sub(r"\[impactor\].*?\n\n", "[impactor]\ndensity = 7850.0\nradius = 6.35e-3\nE = 207e9\n"
                  "nu = 0.3\nvelocity = 3.0\n\n", text, flags=re.S)
    text = text.replace("k = 0.6e9", 'k = "auto"').replace('end = "auto"', "end = 400e-6")
    return text + mesh_table(mesh)


def light_auto(mesh, dt_us):
    """The light case run to the end-of-event rule."""
    return light(mesh, dt_us).replace("end = 400e-6", 'end = "auto"')


def mesh_table(mesh):
    return "" if mesh == "graded" else f"\n[mesh]\nnx = {mesh[0]}\nny = {mesh[1]}\n"


# name: deck builder, reference peak force [N] (docs/notes/contact-reference.md), time steps [µs], meshes,
# the largest adaptive step [µs] and the levels that take it below the smallest fixed step
CASES = {
    "heavy": (heavy, 12878.0, [1, 2, 5, 10, 20, 50, 100, 200], MESHES, 200, 12),
    "light": (light, 447.94, [0.1, 0.2, 0.5, 1, 2, 5], MESHES, 5, 8),
    "light-auto": (light_auto, 447.94, [0.1, 0.2, 0.5, 1, 2, 5], ["graded"], 40, 11),
}
TOLERANCES = ["1e-2", "3e-3", "1e-3", "3e-4", "1e-4", "3e-5"]


def run(path, out, repeats):
    """Median wall time of the whole process [s] and the summary of the last run."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        subprocess.run([str(PROGRAM), "impact", str(path), "-o", str(out), "--overwrite", "-q"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        times.append(time.perf_counter() - start)
    return statistics.median(times), json.loads((out / "summary.json").read_text())


def table(case, repeats, work):
    """The markdown table of one case and the two cheapest cells within 1 %."""
    deck, reference, steps_us, meshes, _, _ = CASES[case]
    cells = {}
    for mesh in meshes:
        for dt in steps_us:
            path = work / "case.toml"
            path.write_text(deck(mesh, dt))
            wall, summary = run(path, work / "out", repeats)
            error = summary["peak_force"] / reference - 1.0
            cells[(str(mesh), dt)] = (error, wall, summary["steps"], summary["wall_time"])
            print(f"{case} {mesh} dt {dt} us: F {summary['peak_force']:.2f} N, error {100 * error:+.3f} %, "
                  f"{summary['steps']} steps, loop {summary['wall_time']:.3f} s, process {wall:.3f} s",
                  file=sys.stderr, flush=True)
    name = {str(m): ("graded (default)" if m == "graded" else f"{m[0]}×{m[1]}") for m in meshes}
    print(f"\n{case}: peak force error against {reference} N, and the whole process's median time\n")
    print("| mesh | " + " | ".join(f"Δt = {dt} µs" for dt in steps_us) + " |")
    print("|---|" + "---:|" * len(steps_us))
    for mesh in meshes:
        row = [f"{100 * cells[(str(mesh), dt)][0]:+.2f} %, {cells[(str(mesh), dt)][1]:.3f} s" for dt in steps_us]
        print(f"| {name[str(mesh)]} | " + " | ".join(row) + " |")
    # The cheapest cell within 1 %, and the cheapest whose mesh alone (at the case's smallest step) and step
    # alone (on the graded mesh, the finest of the table) are each within 1 %, so that it is not two errors
    # cancelling.
    finest, smallest = str(meshes[0]), steps_us[0]
    within = [(c[1], key) for key, c in cells.items() if abs(c[0]) < 0.01]
    honest = [(c[1], key) for key, c in cells.items() if abs(c[0]) < 0.01
              and abs(cells[(key[0], smallest)][0]) < 0.01 and abs(cells[(finest, key[1])][0]) < 0.01]
    for label, found in (("cheapest within 1 %", within), ("cheapest within 1 % without cancellation", honest)):
        if found:
            wall, key = min(found)
            print(f"\n{label}: {name[key[0]]}, Δt = {key[1]} µs: {100 * cells[key][0]:+.2f} %, {wall:.3f} s "
                  f"({cells[key][2]} steps)")


def adaptive_table(case, repeats, work):
    """Error-controlled steps on the default graded mesh: the peak force's error, the time and the steps at
    each tolerance."""
    deck, reference, steps_us, _, largest_us, levels = CASES[case]
    print(f"\n{case}, graded mesh, adaptive steps from {largest_us} µs down to "
          f"{largest_us / 2 ** (levels - 1):.3g} µs ({levels} levels)\n")
    print("| tolerance | error | whole process | time loop | steps (redone) | smallest step | factorizations |")
    print("|---:|---:|---:|---:|---:|---:|---:|")
    for tol in TOLERANCES:
        text = deck("graded", 1).replace(
            "dt = 1e-6", f"dt = {largest_us}e-6\nadaptive = true\nlevels = {levels}\ntolerance = {tol}")
        path = work / "case.toml"
        path.write_text(text)
        wall, summary = run(path, work / "out", repeats)
        steps = summary["time_steps"]
        error = summary["peak_force"] / reference - 1.0
        print(f"| {tol} | {100 * error:+.2f} % | {wall:.3f} s | {summary['wall_time']:.3f} s | {summary['steps']} "
              f"({steps['rejected_steps']}) | {steps['smallest_used_dt'] * 1e6:.3g} µs | {steps['factorizations']} |",
              flush=True)


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    with tempfile.TemporaryDirectory() as work:
        for case in CASES:
            table(case, repeats, Path(work))
            adaptive_table(case, repeats, Path(work))


if __name__ == "__main__":
    main()
