#!/usr/bin/env python3
"""Per-stage parallel fraction from `fluidsim bench` JSON lines (stdin; several runs may be
concatenated): the best (smallest) ms per (size, solver, stage, threads) over the runs, the
speed-up S at the second thread count t, the parallel fraction p from Amdahl's law
S = 1 / ((1 - p) + p / t), and the predicted speed-ups at 4 and 16 threads. For machines
with few cores (docs/fluidsim.md §7): on a loaded machine take several runs.

    for r in 1 2 3; do build/bin/fluidsim bench --sizes 64 --threads 1,2 --steps 3 \\
        --poisson fdm,fft --nu 1e-4; done | tests/bench/fluidsim_amdahl.py
"""
import json
import sys


def amdahl(p, t):
    return 1.0 / ((1.0 - p) + p / t)


best = {}
for line in sys.stdin:
    line = line.strip()
    if not line.startswith("{"):
        continue
    d = json.loads(line)
    if d.get("bench") != "fluidsim":
        continue
    key = (d["size"], d["solver"], d["stage"])
    slot = best.setdefault(key, {})
    t = d["threads"]
    slot[t] = min(slot.get(t, float("inf")), d["ms"])

print("| size | solver | stage | ms at 1 thread | speed-up at t | p | Amdahl 4 | Amdahl 16 |")
print("| --- | --- | --- | --- | --- | --- | --- | --- |")
for (size, solver, stage), slot in sorted(best.items()):
    threads = sorted(slot)
    if len(threads) < 2 or threads[0] != 1:
        continue
    t = threads[1]
    s = slot[1] / slot[t]
    # S = 1/((1-p) + p/t)  =>  p = (1 - 1/S) / (1 - 1/t), clamped to [0, 1].
    p = min(1.0, max(0.0, (1.0 - 1.0 / s) / (1.0 - 1.0 / t)))
    print(f"| {size}^3 | {solver} | {stage} | {slot[1]:.1f} | {s:.2f} (t={t}) | {p:.2f} | "
          f"{amdahl(p, 4):.2f} | {amdahl(p, 16):.2f} |")
