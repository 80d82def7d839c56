#!/usr/bin/env python3
"""Ply damage and delamination over impact energy: the documented trends of docs/notes/impact-experiments.md §3.

Runs examples/impact-delamination-damage.toml (a [0/90]s T300/976 plate, 12 mm, 30 g impactor, both
mechanisms, explicit steps) at five velocities to the end of the event (`end = "auto"`), prints the table
of docs/notes/impact-experiments.md §3 and draws OUT/damage-trends.png with gnuplot (and, with --compare,
OUT/compare.png: the force histories of the cases that delaminate against the other study's).

    python3 docs/notes/decks/damage_trends.py [--program build/release/plyimpact] [--out /tmp/damage-trends]
        [--mass-scaling none|selective] [--compare OTHER_OUT]

By default the deck runs as shipped, unscaled (about 12 minutes on the 2-core machine). `--mass-scaling
selective` adds `[time] mass_scaling = "selective"` (docs/mass_scaling.md): 7 times fewer steps, the same
numbers up to the load drop, not after it (docs/validation.md §20, "Rerun ... with selective mass
scaling"). The cases run two at a time on one thread each, the most energetic
first (it takes the longest); the script prints each case's wall time and the whole study's. A case whose
summary.json is already in OUT/v<velocity> is read, not run again (delete OUT to start over). `--compare`
prints, case by case, this study's peak force, absorbed energy, delaminated and damaged area against
another OUT's (e.g. the unscaled reference), as relative differences.
"""
import argparse
import concurrent.futures
import csv
import json
import pathlib
import re
import subprocess
import time

ROOT = pathlib.Path(__file__).resolve().parents[3]
VELOCITIES = ["1.0", "1.5", "2.0", "2.5", "3.0"]


def deck_for(velocity: str, mass_scaling: str) -> str:
    text = (ROOT / "examples/impact-delamination-damage.toml").read_text()
    text, n_v = re.subn(r"(?m)^velocity = 3\.0\b", f"velocity = {velocity}", text)
    text, n_end = re.subn(r"(?m)^end = 1\.5e-4\b", 'end = "auto"', text)
    n_ms = 1
    if mass_scaling != "none":
        text, n_ms = re.subn(r"(?m)^(dt = \"auto\".*)$", rf'\1\nmass_scaling = "{mass_scaling}"', text)
    if n_v != 1 or n_end != 1 or n_ms != 1:
        raise SystemExit("examples/impact-delamination-damage.toml changed: velocity, end or dt not found")
    return text


def run_case(program: str, out: pathlib.Path, velocity: str, mass_scaling: str) -> tuple[pathlib.Path, float]:
    """The case's results folder and its wall time [s] (0 where it was read, not run)."""
    case = out / f"v{velocity}"
    if (case / "summary.json").exists():
        return case, 0.0
    case.mkdir(parents=True, exist_ok=True)
    deck = out / f"v{velocity}.toml"
    deck.write_text(deck_for(velocity, mass_scaling))
    start = time.monotonic()
    # One thread a case: two cases share the two cores (threads on top would oversubscribe them).
    subprocess.run([program, "impact", str(deck), "-o", str(case), "--overwrite", "-q", "--threads", "1"],
                   check=True)
    return case, time.monotonic() - start


def first_time(history, column):
    """Time [µs] and force [N] of the first row where `column` is positive, or None."""
    for row in history:
        if float(row[column]) > 0.0:
            return float(row["t_s"]) * 1e6, float(row["force_N"])
    return None


def first_fibre(damage):
    """Time [µs] and force [N] of the first fibre damage (either mode), or None."""
    firsts = [damage["first_damage_by_mode"][m] for m in ("fibre-tension", "fibre-compression")]
    firsts = [f for f in firsts if f is not None]
    if not firsts:
        return None
    f = min(firsts, key=lambda f: f["time"])
    return f["time"] * 1e6, f["contact_force"]


def row_of(case: pathlib.Path) -> dict:
    s = json.loads((case / "summary.json").read_text())
    with open(case / "history.csv", newline="") as f:
        history = list(csv.DictReader(f))
    by_mode = s["damage"]["dissipated_energy_by_mode"]
    first = s["damage"]["first_damage"]
    return {
        "energy_mJ": s["initial_energy"] * 1e3,
        "velocity": s["impact_velocity"],
        "peak_N": s["peak_force"],
        "absorbed_mJ": s["absorbed_energy"] * 1e3 if s["absorbed_energy"] is not None else float("nan"),
        "contact_mJ": s["contact_dissipation"] * 1e3,
        "matrix_mJ": (by_mode["matrix-tension"] + by_mode["matrix-compression"]) * 1e3,
        "fibre_mJ": (by_mode["fibre-tension"] + by_mode["fibre-compression"]) * 1e3,
        "interfaces_mJ": s["delamination"]["dissipated_energy_J"] * 1e3,
        "first_ply": f'{first["mode"]}, ply {first["ply"]}, {first["time"] * 1e6:.1f} µs, {first["contact_force"]:.0f} N'
        if first
        else "none",
        "first_fibre": first_fibre(s["damage"]),
        "first_interface": first_time(history, "delamination_dissipation_J"),
        "first_delaminated": first_time(history, "delamination_area_m2"),
        "delaminated_mm2": s["delamination"]["projected_delaminated_area_m2"] * 1e6,
        "damaged_mm2": s["damage"]["projected_damage_area"] * 1e6,
        "balance": s["energy_balance_error"],
        "steps": s["steps"],
        "history": history,
    }


def at(point):
    return "none" if point is None else f"{point[0]:.1f} µs, {point[1]:.0f} N"


def print_table(rows):
    print("| impact energy | peak force | absorbed | contact law | plies: matrix / fibre | interfaces | "
          "first ply damage | interfaces start to dissipate | first delaminated point | first fibre damage | "
          "delaminated | ply damage (d ≥ 0.5) | balance error |")
    print("|---:|---:|---:|---:|---:|---:|---|---|---|---|---:|---:|---:|")
    for r in rows:
        print(f'| {r["energy_mJ"]:.1f} mJ ({r["velocity"]:g} m/s) | {r["peak_N"]:.1f} N | {r["absorbed_mJ"]:.2f} mJ | '
              f'{r["contact_mJ"]:.2f} mJ | {r["matrix_mJ"]:.2f} / {r["fibre_mJ"]:.2f} mJ | {r["interfaces_mJ"]:.2f} mJ | '
              f'{r["first_ply"]} | {at(r["first_interface"])} | {at(r["first_delaminated"])} | {at(r["first_fibre"])} | '
              f'{r["delaminated_mm2"]:.2f} mm² | {r["damaged_mm2"]:.1f} mm² | {r["balance"]:.1e} |')


def write_force(path: pathlib.Path, history, every: int):
    """Time [µs] and contact force [N] of every `every`-th row of a history.csv, for gnuplot."""
    with open(path, "w") as f:
        for row in history[::every]:
            f.write(f'{float(row["t_s"]) * 1e6} {row["force_N"]}\n')


def print_comparison(rows, refs, reference_out: pathlib.Path):
    """Relative differences of this study against another OUT's, case by case (the mass-scaling check)."""
    print(f"\nagainst {reference_out}: relative difference (this / reference - 1)")
    print("| impact energy | peak force | absorbed | delaminated | ply damage (d ≥ 0.5) | steps |")
    print("|---:|---:|---:|---:|---:|---:|")
    for r, ref in zip(rows, refs):

        def rel(key):
            return "n/a" if ref[key] == 0.0 else f"{r[key] / ref[key] - 1.0:+.2%}"

        print(f'| {r["energy_mJ"]:.1f} mJ | {rel("peak_N")} | {rel("absorbed_mJ")} | {rel("delaminated_mm2")} | '
              f'{rel("damaged_mm2")} | {r["steps"]} / {ref["steps"]} |')


def scaling_of(out: pathlib.Path) -> str:
    """"unscaled" or "<kind> mass scaling", from a study's first summary.json."""
    s = json.loads((out / f"v{VELOCITIES[0]}" / "summary.json").read_text())
    kind = (s.get("mass_scaling") or {}).get("kind")
    return f"{kind} mass scaling" if kind else "unscaled"


def draw_comparison(rows, refs, label: str, reference_label: str, out: pathlib.Path, png: pathlib.Path):
    """The force histories of the cases that delaminate, this study's against the reference's, side by side."""
    cases = [(r, ref) for r, ref in zip(rows, refs) if r["delaminated_mm2"] > 0.0 or ref["delaminated_mm2"] > 0.0]
    if not cases:
        return
    plots = []
    for r, ref in cases:
        for tag, row in (("this", r), ("ref", ref)):
            write_force(out / f'compare-{tag}-{r["velocity"]:g}.dat', row["history"], every=10)
        plots.append(f"""set title '{r["energy_mJ"]:.1f} mJ: absorbed {r["absorbed_mJ"]:.1f} against {ref["absorbed_mJ"]:.1f} mJ'
plot '{out}/compare-ref-{r["velocity"]:g}.dat' using 1:2 with lines lw 2 lc rgb '#1f77b4' title '{reference_label}', \\
     '{out}/compare-this-{r["velocity"]:g}.dat' using 1:2 with lines lw 1 lc rgb '#d62728' title '{label}'""")
    script = f"""
set terminal pngcairo size {460 * len(cases)},480 font 'DejaVu Sans,11'
set output '{png}'
set multiplot layout 1,{len(cases)} title 'contact force: {label} against {reference_label}'
set xlabel 'time [µs]'
set ylabel 'contact force [N]'
set xrange [0:800]
set yrange [0:350]
set key top right
set grid
""" + "\n".join(plots) + "\nunset multiplot\n"
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def draw(rows, out: pathlib.Path, png: pathlib.Path):
    for r in rows:
        write_force(out / f'force-{r["velocity"]:g}.dat', r["history"], every=20)
    with open(out / "energies.dat", "w") as f:
        f.write("# E0 contact matrix fibre interfaces absorbed [mJ]\n")
        for r in rows:
            f.write(f'{r["energy_mJ"]} {r["contact_mJ"]} {r["matrix_mJ"]} {r["fibre_mJ"]} {r["interfaces_mJ"]} '
                    f'{r["absorbed_mJ"]}\n')
    curves = ", ".join(
        f"'{out}/force-{r['velocity']:g}.dat' using 1:2 with lines lw 2 title '{r['energy_mJ']:.0f} mJ'" for r in reversed(rows))
    script = f"""
set terminal pngcairo size 1400,560 font 'DejaVu Sans,12'
set output '{png}'
set multiplot layout 1,2 title '[0/90]s T300/976, 12 mm, 30 g: ply damage and delamination together (explicit steps)'
set title 'contact force, first 800 µs'
set xlabel 'time [µs]'
set xrange [0:800]
set ylabel 'contact force [N]'
set key top right
set grid
plot {curves}
set title 'where the impact energy goes (end of the event)'
set xlabel 'impact energy [mJ]'
set xrange [*:*]
set ylabel 'energy [mJ]'
set key top left
set style data histograms
set style histogram rowstacked
set style fill solid 0.85 border -1
set boxwidth 0.7
set yrange [0:*]
plot '{out}/energies.dat' using 2:xtic(sprintf('%.0f', $1)) title 'contact law (indentation)', \\
     '' using 3 title 'plies: matrix', '' using 4 title 'plies: fibre', '' using 5 title 'interfaces', \\
     '' using ($6) with linespoints lw 2 pt 7 lc rgb 'black' title 'absorbed = ½m(v₀² − v_r²)'
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", default=str(ROOT / "build/release/plyimpact"))
    parser.add_argument("--out", default="/tmp/damage-trends")
    parser.add_argument("--png", help="where to draw the picture (default OUT/damage-trends.png)")
    parser.add_argument("--mass-scaling", choices=["none", "selective"], default="none")
    parser.add_argument("--compare", help="another OUT to compare with, case by case")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:  # the longest case first
        runs = dict(pool.map(lambda v: (v, run_case(args.program, out, v, args.mass_scaling)),
                             reversed(VELOCITIES)))
    wall = time.monotonic() - start
    rows = [row_of(runs[v][0]) for v in VELOCITIES]
    print_table(rows)
    print("\nwall time per case: " + ", ".join(f"{v} m/s {runs[v][1]:.0f} s" for v in VELOCITIES) +
          f"; the study {wall:.0f} s (cases read from OUT count 0)")
    if args.compare:
        reference = pathlib.Path(args.compare)
        refs = [row_of(reference / f"v{v}") for v in VELOCITIES]
        print_comparison(rows, refs, reference)
        draw_comparison(rows, refs, scaling_of(out), scaling_of(reference), out, out / "compare.png")
    draw(rows, out, pathlib.Path(args.png) if args.png else out / "damage-trends.png")


if __name__ == "__main__":
    main()
