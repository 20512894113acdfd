"""Benchmark: five-orientation spherical rigid-body guidance (Burmester theory on the sphere).

Times, in a fresh process:

- ``burmester(R)``: every real Burmester dyad of five orientations (the resultant (9) sampled
  at 16 great circles, the sextic (10), its roots, Newton polishing);
- ``guidance_fourbars(R)``: the same plus every candidate four-bar analysed with
  ``SphericalFourBar`` (orientations reproduced, branch, order, transmission angle);
- for comparison, the planar ``mech.planar.burmester`` on example 2-15;

for example 2-15 carried onto a sphere of radius 1000 (``planar_orientations(..., 1e-3)``)
and for 50 random sets of five orientations. Medians of the repeats; the first call is
reported apart. Goal: ``burmester`` under 100 ms. Results go to
``benchmarks/results/spherical_guidance.json``.

    python benchmarks/bench_spherical_guidance.py            # full run
    python benchmarks/bench_spherical_guidance.py --quick    # fewer repeats, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

START = time.perf_counter()
import numpy as np  # noqa: E402

from mech.planar.synthesis import burmester as planar_burmester  # noqa: E402
from mech.spherical import burmester, guidance_fourbars, planar_orientations, rotation_matrix  # noqa: E402

IMPORT_TIME = time.perf_counter() - START
EX_P = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j])
EX_THETA = np.radians([0.0, 8.88, 22.1, 63.68, -3.0])
OUTPUT = HERE / "results" / "spherical_guidance.json"


def random_set(seed):
    rng = np.random.default_rng(seed)
    return np.stack([rotation_matrix(rng.normal(size=3), rng.uniform(0.1, 1.2)) for _ in range(5)])


def timed(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), float(np.min(times))


def main(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    repeats = 5 if args.quick else 30
    R_ex = planar_orientations(EX_THETA, EX_P, 1e-3)
    t0 = time.perf_counter()
    burmester(R_ex)
    first = time.perf_counter() - t0
    out = {
        "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "import_s": IMPORT_TIME,
        "first_call_s": first,
        "example_2_15_on_sphere": {
            "burmester_ms": [1e3 * t for t in timed(lambda: burmester(R_ex), repeats)],
            "guidance_fourbars_ms": [1e3 * t for t in timed(lambda: guidance_fourbars(R_ex), repeats)],
            "planar_burmester_ms": [1e3 * t for t in timed(lambda: planar_burmester(EX_THETA, EX_P), repeats)],
            "real_dyads": len(burmester(R_ex).dyads),
            "passing_fourbars": len(guidance_fourbars(R_ex).passing),
        },
    }
    sets = [random_set(s) for s in range(10 if args.quick else 50)]
    b_times, b_best, g_times, reals, residuals = [], [], [], [], []
    for R in sets:
        median, best = timed(lambda: burmester(R), 5)
        b_times.append(median)
        b_best.append(best)
        g_times.append(timed(lambda: guidance_fourbars(R), 3)[0])
        found = burmester(R)
        reals.append(len(found.dyads))
        residuals.append(found.residual)
    out["random_sets"] = {
        "count": len(sets),
        "burmester_ms_median": 1e3 * float(np.median(b_times)),
        "burmester_ms_max": 1e3 * float(np.max(b_times)),
        "burmester_best_of_5_ms_median": 1e3 * float(np.median(b_best)),
        "burmester_best_of_5_ms_max": 1e3 * float(np.max(b_best)),
        "guidance_fourbars_ms_median": 1e3 * float(np.median(g_times)),
        "guidance_fourbars_ms_max": 1e3 * float(np.max(g_times)),
        "real_dyads_histogram": {str(k): int(np.sum(np.array(reals) == k)) for k in (0, 2, 4, 6)},
        "max_residual": float(np.max(residuals)),
    }
    out["goal_burmester_ms"] = 100.0
    # the machine is shared: judge the goal on the median task and the best-of-5 worst task
    out["meets_goal"] = bool(out["random_sets"]["burmester_ms_median"] < 100.0
                             and out["random_sets"]["burmester_best_of_5_ms_max"] < 100.0)
    out["load_average"] = list(__import__("os").getloadavg())
    print(json.dumps(out, indent=2))
    if not args.quick:
        OUTPUT.write_text(json.dumps(out, indent=2) + "\n")
    return out


if __name__ == "__main__":
    main()
