"""Benchmark: error reached against time on Example 2-24 (a coupler point through ten points).

The model is `path_synthesis_model` of the textbook's ten points (gamma_min = 30 degrees,
ten variables). Methods, each at several budgets, in the same run:

- ``mech-penalty``: `penalty_method` (interior penalty, Nelder-Mead stages) from the rough
  start of the book page, with ``stages`` as the budget;
- ``scipy-de``: `scipy.optimize.differential_evolution` on the same objective, box and
  constraints (``NonlinearConstraint`` on g <= 0), no polishing, with ``maxiter`` as the
  budget and seeds 0, 1, 2 for the repeats;
- ``scipy-slsqp``: `scipy_minimize` (SLSQP) from the same start, for reference.

Every measurement runs in a fresh Python process (imports done before the clock starts);
times and errors are medians over the repeats. The error of a result is measured by
analysis: the designed `FourBar` is solved at the ten crank steps (`CouplerPathDesign.prove`)
and the distances to the targets are summed; the largest constraint value is recorded too.

    python benchmarks/bench_path_synthesis.py            # writes results/path_synthesis.json
    python benchmarks/bench_path_synthesis.py --quick    # one repeat, small budgets, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
OUTPUT = HERE / "results" / "path_synthesis.json"
POINTS = [9.50 + 8.26j, 9 + 8.87j, 7.96 + 9.51j, 5.65 + 9.94j, 4.36 + 9.7j, 3.24 + 9j, 3.26 + 8.36j,
          4.79 + 8.11j, 6.58 + 8j, 9.12 + 7.89j]
START = [1.7, 5.8, 5.4, 7.0, 8.0, 2.0, 2.2, np.radians(80), np.radians(-70), np.radians(90)]
BUDGETS = {"mech-penalty": [1, 2, 4, 8, 12], "scipy-de": [25, 50, 100, 200, 400], "scipy-slsqp": [500]}
QUICK = {"mech-penalty": [1, 2], "scipy-de": [10, 20], "scipy-slsqp": [500]}
REPEATS = 3


def child(method, budget, seed):
    """One measurement, in this process: returns a dict (time, evaluations, error)."""
    import time

    import scipy.optimize as so

    from mech.planar.synthesis import CouplerPathDesign, path_synthesis_model, penalty_method, scipy_minimize

    model = path_synthesis_model(np.array(POINTS), gamma_min=np.radians(30.0))
    t = time.perf_counter()
    if method == "mech-penalty":
        res = penalty_method(model, START, stages=budget)
        x, nfev = res.x, res.evaluations
    elif method == "scipy-slsqp":
        res = scipy_minimize(model, START, options={"maxiter": budget})
        x, nfev = res.x, res.evaluations
    else:
        res = so.differential_evolution(lambda v: float(model.f(v)), model.bounds, maxiter=budget, seed=seed,
                                        polish=False, constraints=so.NonlinearConstraint(model.g, -np.inf, 0.0))
        x, nfev = res.x, int(res.nfev)
    elapsed = time.perf_counter() - t
    try:
        proof = CouplerPathDesign(x, POINTS).prove()
        error, valid = proof.objective, proof.valid
    except ValueError:                      # a design that is not a four-bar at all
        error, valid = float("inf"), False
    return {"time_s": elapsed, "evaluations": nfev, "error": error, "valid": valid,
            "max_g": float(np.max(model.g(x))), "x": [float(v) for v in x]}


def measure(method, budget, seed):
    cmd = [sys.executable, str(Path(__file__).resolve()), "--child", method, str(budget), str(seed)]
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    out = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", type=Path, default=None)
    parser.add_argument("--child", nargs=3, metavar=("METHOD", "BUDGET", "SEED"))
    args = parser.parse_args(argv)
    if args.child:
        method, budget, seed = args.child
        print(json.dumps(child(method, int(budget), int(seed))))
        return 0
    budgets = QUICK if args.quick else BUDGETS
    repeats = 1 if args.quick else REPEATS
    rows = []
    for method, levels in budgets.items():
        for budget in levels:
            runs = [measure(method, budget, seed) for seed in range(repeats)]
            row = {"method": method, "budget": budget, "repeats": repeats,
                   "median_time_s": float(np.median([r["time_s"] for r in runs])),
                   "median_error": float(np.median([r["error"] for r in runs])),
                   "best_error": float(np.min([r["error"] for r in runs])),
                   "median_evaluations": float(np.median([r["evaluations"] for r in runs])),
                   "all_feasible": bool(all(r["max_g"] <= 0 and r["valid"] for r in runs)),
                   "runs": runs}
            rows.append(row)
            print(f"{method:>13} budget {budget:4d}: {row['median_time_s']:7.3f} s, "
                  f"{row['median_evaluations']:8.0f} evaluations, sum of distances {row['median_error']:.4f} "
                  f"(best {row['best_error']:.4f}), feasible {row['all_feasible']}", flush=True)
    if args.quick and args.output is None:
        return 0
    sys.path.insert(0, str(HERE))
    from bench_coupler_curve import machine, versions

    report = {"date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
              "task": "Example 2-24, ten points, gamma_min 30 deg, 10 variables", "start": START,
              "error": "sum of distances from the ten targets, measured by FourBar.solve",
              "machine": machine(), "versions": versions(), "rows": rows}
    path = args.output or OUTPUT
    path.write_text(json.dumps(report, indent=1) + "\n")
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
