"""Benchmark: optimal spherical guidance beyond five orientations (§3.7) and minimax
function generation (§1.8).

For random crank-rocker tasks (n coupler orientations taken from a spherical crank-rocker,
placed by a random rotation, then perturbed by random rotations of a given size), times
`optimal_guidance` with the orientation-error objective and with the constant-length
objective (each including its default Burmester start) and records the orientation error
reached, checked by analysis, and whether the design is on one branch and in order. Also
times `minimax` against the structural `least_squares` on the log10 example of the book
page. Medians of the repeats; the first call (imports) is reported apart. Results go to
``benchmarks/results/spherical_optimal.json``.

    python benchmarks/bench_spherical_optimal.py            # full run
    python benchmarks/bench_spherical_optimal.py --quick    # fewer tasks, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import os
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

START = time.perf_counter()
import numpy as np  # noqa: E402

from mech.spherical import (SphericalFourBar, classify, least_squares, minimax, optimal_guidance,  # noqa: E402
                            rotation_matrix)

IMPORT_TIME = time.perf_counter() - START
OUTPUT = HERE / "results" / "spherical_optimal.json"


def _frame(p, q):
    t = q - np.sum(p * q, axis=-1, keepdims=True) * p
    t = t / np.linalg.norm(t, axis=-1, keepdims=True)
    return np.stack([p, t, np.cross(p, t)], axis=-1)


def crank_rocker_task(seed, n, noise):
    """n orientations of a random spherical crank-rocker's coupler, perturbed by `noise` rad."""
    rng = np.random.default_rng(seed)
    while True:
        arcs = rng.uniform(0.2, 1.2, 4)
        try:
            if classify(*arcs).kind == "crank-rocker":
                break
        except ValueError:                                 # cannot be assembled
            continue
    theta = np.linspace(0.0, rng.uniform(1.5, 3.0), n) + rng.uniform(-np.pi, np.pi)
    pose = SphericalFourBar(*arcs, branch=1).solve(theta)
    Q, G = rotation_matrix(rng.normal(size=3), rng.uniform(0, np.pi)), rotation_matrix(rng.normal(size=3), 1.0)
    zB, zC = Q @ [0.0, 0.0, 1.0], Q @ [np.sin(arcs[1]), 0.0, np.cos(arcs[1])]
    R = G @ _frame(pose.B, pose.C) @ _frame(zB, zC).T
    return np.stack([rotation_matrix(rng.normal(size=3), noise) @ r for r in R]) if noise else R


def timed(fn, repeats):
    times, result = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), result


def main(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    tasks = 4 if args.quick else 12
    t0 = time.perf_counter()
    optimal_guidance(crank_rocker_task(0, 9, 0.0), objective="constant_length")
    out = {"date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
           "import_s": IMPORT_TIME, "first_call_s": time.perf_counter() - t0, "guidance": {}}
    for n in (9, 15):
        for noise in (0.0, 0.005, 0.02):
            rows = {"orientation": [], "constant_length": []}
            for seed in range(tasks):
                R = crank_rocker_task(seed, n, noise)
                for objective in rows:
                    try:
                        seconds, fit = timed(lambda: optimal_guidance(R, objective=objective, rtol=4 * noise + 1e-9),
                                             2)
                    except ValueError as exc:          # no Burmester start found
                        rows[objective].append({"failed": str(exc)[:80]})
                        continue
                    rows[objective].append({"ms": 1e3 * seconds, "max_error": fit.design.pose_error,
                                            "rms_error": fit.rms_error, "in_order": fit.design.in_order,
                                            "passes": fit.design.passes, "nfev": fit.nfev})
            summary = {}
            for objective, found in rows.items():
                ok = [r for r in found if "ms" in r]
                summary[objective] = {
                    "tasks": len(found), "solved": len(ok),
                    "ms_median": float(np.median([r["ms"] for r in ok])) if ok else None,
                    "rms_error_median": float(np.median([r["rms_error"] for r in ok])) if ok else None,
                    "max_error_median": float(np.median([r["max_error"] for r in ok])) if ok else None,
                    "in_order": int(sum(r["in_order"] for r in ok)),
                    "passes": int(sum(r["passes"] for r in ok)),
                }
            pairs = [(a, b) for a, b in zip(rows["orientation"], rows["constant_length"]) if "ms" in a and "ms" in b]
            summary["orientation_rms_not_worse"] = int(sum(a["rms_error"] <= b["rms_error"] * 1.001 for a, b in pairs))
            summary["speedup_constant_length_median"] = (float(np.median([a["ms"] / b["ms"] for a, b in pairs]))
                                                         if pairs else None)
            out["guidance"][f"n={n}, noise={noise}"] = summary
    span_in, span_out = np.radians(90.0), np.radians(60.0)
    theta0, psi0 = np.radians(-120.0), np.radians(-70.0)
    u = np.linspace(1.0, 10.0, 401)
    x, y = span_in * (u - 1.0) / 9.0, span_out * np.log10(u)
    ls_s, fit = timed(lambda: least_squares(x, y, theta0, psi0), 3)
    mm_s, best = timed(lambda: minimax(x, y, theta0, psi0, start=fit), 3)
    out["minimax_log10"] = {"least_squares_ms": 1e3 * ls_s, "minimax_ms_after_start": 1e3 * mm_s,
                            "least_squares_max_error_deg": float(np.degrees(fit.max_error)),
                            "minimax_max_error_deg": float(np.degrees(best.max_error))}
    out["load_average"] = list(os.getloadavg())
    print(json.dumps(out, indent=2))
    if not args.quick:
        OUTPUT.write_text(json.dumps(out, indent=2) + "\n")
    return out


if __name__ == "__main__":
    main()
