"""Benchmark: a 100-point least-squares function generator (goal: under 20 ms).

The task is the textbook's Ex. 2-16, y = log10(x) on [1, 10], input range 100 degrees, output
range 60 degrees turning clockwise, start angles 40 and 245 degrees, ground 100 mm, with
N = 100 equally spaced pairs. Timed, each the median of interleaved repeats (SciPy imported
before timing):

- ``equation``: `least_squares(..., kind="equation")`, one linear solve plus the check of the
  design by `FourBar` over the range;
- ``structural``: `least_squares(...)`, the nonlinear fit of the structural error, from the
  linear fit, plus the same check;
- ``fit_start``: the structural fit with the start angles free.

For each the largest structural error over the range, in units of y, is recorded from the
`FourBar` simulation. Times are on a shared machine; the goal is the one named above.

    python benchmarks/bench_function_generation.py            # writes results/function_generation.json
    python benchmarks/bench_function_generation.py --quick    # fewer repeats, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from bench_coupler_curve import machine, versions  # noqa: E402

from mech.planar.synthesis import FunctionMap, least_squares  # noqa: E402

N = 100
REPEATS = 21
GOAL_S = 0.020
OUTPUT = HERE / "results" / "function_generation.json"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", type=Path, default=None)
    args = parser.parse_args(argv)
    repeats = 5 if args.quick else REPEATS
    import scipy.optimize  # noqa: F401  (import cost is not the fit's)

    task = FunctionMap(np.log10, (1.0, 10.0), np.radians(100.0), -np.radians(60.0))
    X, Y = task.rotations(np.linspace(1.0, 10.0, N))
    start = dict(theta0=np.radians(40.0), psi0=np.radians(245.0), d=100.0, target=task)
    methods = {
        "equation": lambda: least_squares(X, Y, kind="equation", **start),
        "structural": lambda: least_squares(X, Y, **start),
        "fit_start": lambda: least_squares(X, Y, fit_start=True, **start),
    }
    times = {name: [] for name in methods}
    designs = {}
    for _ in range(repeats):
        for name, run in methods.items():
            t = time.perf_counter()
            designs[name] = run()
            times[name].append(time.perf_counter() - t)
    results = {}
    for name, g in designs.items():
        results[name] = {
            "median_s": float(np.median(times[name])),
            "min_s": float(np.min(times[name])),
            "max_error_y": g.errors(2001)[0] / abs(task.output_scale),
            "covers_range": g.covers_range,
            "lengths": list(g.lengths),
        }
        print(f"{name:>10}: {1e3 * results[name]['median_s']:7.2f} ms (min {1e3 * results[name]['min_s']:.2f}),"
              f" max error in y {results[name]['max_error_y']:.2e}, covers range {g.covers_range}")
    report = {"date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"), "N": N,
              "repeats": repeats, "goal_s": GOAL_S, "machine": machine(), "versions": versions(),
              "results": results}
    output = args.output or (None if args.quick else OUTPUT)
    if output is not None:
        output.write_text(json.dumps(report, indent=2) + "\n")
        print(f"written {output}")
    return 0 if results["structural"]["median_s"] < GOAL_S else 1


if __name__ == "__main__":
    sys.exit(main())
