"""Releasing the GIL (issue 21): 8 impact cases on 1 and on 2 Python threads.

Eight velocities of the thesis §3.6 deck (examples/thesis-3.6-v268.toml, 15 x 11, 8 626 steps at 2.68
m/s), run with concurrent.futures.ThreadPoolExecutor; median of REPEAT repetitions of each. Run from
the repository root after the build:

    PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_python_threads.py [REPEAT]
"""
import statistics
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import plyimpact

repeat = int(sys.argv[1]) if len(sys.argv) > 1 else 3
base = plyimpact.load("examples/thesis-3.6-v268.toml")
decks = [base.replace({"impactor.velocity": 1.0 + 0.25 * i}) for i in range(8)]


def run_all(threads: int) -> list[float]:
    with ThreadPoolExecutor(max_workers=threads) as pool:
        return [r.summary["peak_force"] for r in pool.map(lambda d: plyimpact.impact(d, history=False), decks)]


medians = {}
reference = None
for threads in (1, 2):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        peaks = run_all(threads)
        times.append(time.perf_counter() - t0)
        reference = reference or peaks
        assert peaks == reference, "threads changed a result"
    medians[threads] = statistics.median(times)
    print(f"{threads} thread{'s' if threads > 1 else ''}: median {medians[threads]:.3f} s of {repeat} "
          f"(runs: {', '.join(f'{t:.3f}' for t in times)})")
print(f"2 threads / 1 thread: {medians[2] / medians[1]:.3f} (issue 21 target: <= 0.6)")
