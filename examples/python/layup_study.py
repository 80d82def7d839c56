"""Layup study: how the stacking sequence changes the plate's bending stiffness and the impact.

The thesis §3.6 plate (127 x 76.2 mm, 24 plies, simply supported, 6.14 kg at 2.68 m/s) with three
layups of the same plies. Run from the repository root:

    PYTHONPATH=build/release/python python3 examples/python/layup_study.py
"""
import plyimpact

base = plyimpact.load("examples/thesis-3.6-v268.toml")
material = base.to_dict()["materials"]["thesis_3_6"]
t = base["laminate.ply_thickness"]

print(f"{'layup':<18} {'D11 [N m]':>10} {'D22 [N m]':>10} {'peak force [N]':>15} {'at [us]':>8} {'w at contact [mm]':>17}")
for layup in ["[0/90]6s", "[45/-45]6s", "[45/90/-45/0]3s"]:
    lam = plyimpact.Laminate(layup, material, ply_thickness=t)
    run = plyimpact.impact(base.replace({"laminate.layup": layup}), history=False)
    s = run.summary
    print(f"{layup:<18} {lam.D[0, 0]:10.1f} {lam.D[1, 1]:10.1f} {s['peak_force']:15.1f} "
          f"{s['time_of_peak_force'] * 1e6:8.0f} {s['peak_contact_deflection'] * 1e3:17.3f}")
