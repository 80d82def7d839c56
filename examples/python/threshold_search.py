"""Threshold search: the smallest impact velocity (and energy) at which matrix cracking starts, for
cross-ply laminates with a thicker and thicker 90° core (thesis §4.3, Table 4.3).

Each search is the bisection of `plyimpact threshold`, on the Choi–Chang matrix-cracking criterion the
decks name. Run from the repository root:

    PYTHONPATH=build/release/python python3 examples/python/threshold_search.py
"""
import math

import plyimpact

print(f"{'layup':<22} {'threshold velocity [m/s]':>25} {'energy [J]':>11} {'trials':>7}")
for core in (2, 3, 4):
    deck = plyimpact.load(f"examples/thesis-4.3-threshold-0_2-90_{core}-0_2.toml")
    found = plyimpact.threshold(deck)
    v = found["threshold_velocity"]
    mass = deck["impactor.density"] * 4.0 / 3.0 * math.pi * deck["impactor.radius"] ** 3  # the decks give ρ
    energy = 0.5 * mass * v * v
    print(f"{deck['laminate.layup']:<22} {v:25.4f} {energy:11.4f} {len(found['trials']):7d}")
