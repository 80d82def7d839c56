"""Energy sweep: peak contact force and absorbed energy against the impact energy, plotted.

The thesis §4.2 plate (examples/thesis-4.2-velocity-2.92.toml) struck with impact energies from 0.1 to
2 J, run through the sweep engine on two threads; the plot goes to energy_sweep.png (or the folder
given as the first argument). Run from the repository root:

    PYTHONPATH=build/release/python python3 examples/python/energy_sweep.py [OUT_DIR]
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no window
import matplotlib.pyplot as plt

import plyimpact

out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(".")
tree = plyimpact.load("examples/thesis-4.2-velocity-2.92.toml").to_dict()
del tree["impactor"]["velocity"]  # the impact is given by its energy instead, as drop-weight tests are
tree["impactor"]["energy"] = 1.0
deck = plyimpact.deck(tree, source="thesis-4.2 by energy")

table = plyimpact.sweep(deck, {"impactor.energy": "0.1:2.0:8"}, jobs=2)
energy = table["impactor.energy"]
print(f"{'energy [J]':>10} {'peak force [N]':>15} {'absorbed [J]':>13}")
for e, f, a in zip(energy, table["peak_force_N"], table["absorbed_energy_J"]):
    print(f"{e:10.3f} {f:15.1f} {a:13.4f}")

fig, force_axis = plt.subplots(figsize=(6.4, 4.0), dpi=120)
force_axis.plot(energy, table["peak_force_N"], "o-", color="tab:blue")
force_axis.set_xlabel("impact energy [J]")
force_axis.set_ylabel("peak contact force [N]", color="tab:blue")
absorbed_axis = force_axis.twinx()
absorbed_axis.plot(energy, table["absorbed_energy_J"], "s--", color="tab:red")
absorbed_axis.set_ylabel("absorbed energy [J]", color="tab:red")
force_axis.set_title("Thesis §4.2 plate, 0.314 kg impactor: energy sweep", fontsize=11)
force_axis.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(out / "energy_sweep.png")
print(f"plot: {out / 'energy_sweep.png'}")
