"""Benchmark: five-pose rigid-body guidance (Burmester dyads and the four-bars they make).

Times, in a fresh process, for example 2-15 and for random five-pose tasks taken from
crank-rocker coupler motions:

- ``burmester(theta, d)``: every real Burmester dyad (linear system, two conics, a quartic,
  Newton polishing);
- ``guidance_fourbars(theta, d)``: the same plus the 12 candidate four-bars, each analysed
  with ``FourBar`` (poses reproduced, branch, order, transmission angle);
- for comparison, the textbook's route (damped least squares, ``scipy.optimize.least_squares``
  on the half-form (2-40)) from random starts: the time per start, and how many starts it
  took to find all the dyads that ``burmester`` finds.

The first call (imports and caches cold) is reported apart; the other times are medians of
the repeats. The goal for ``guidance_fourbars`` is under 50 ms per task. Results go to
``benchmarks/results/burmester.json``.

    python benchmarks/bench_burmester.py            # full run
    python benchmarks/bench_burmester.py --quick    # fewer repeats, nothing written
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
sys.path.insert(0, str(HERE))

START = time.perf_counter()
import numpy as np  # noqa: E402

from mech.planar import FourBar, grashof  # noqa: E402
from mech.planar.synthesis import burmester, guidance_fourbars  # noqa: E402

IMPORT_TIME = time.perf_counter() - START

EX_P = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j])
EX_THETA = np.radians([0.0, 8.88, 22.1, 63.68, -3.0])
OUTPUT = HERE / "results" / "burmester.json"


def coupler_task(seed):
    """Five coupler poses of a random crank-rocker (as in tests/planar/synthesis/test_synthesis_guidance.py)."""
    rng = np.random.default_rng(seed)
    while True:
        a, b, c, d = rng.uniform(0.2, 1.0), *rng.uniform(1.0, 3.0, 3)
        if 2 * max(a, b, c, d) < a + b + c + d and grashof(a, b, c, d).kind == "crank-rocker":
            break
    p, q = rng.uniform(-1.5, 1.5, 2)
    linkage = FourBar(a, b, c, d, coupler=(p, q))
    start = rng.uniform(-np.pi, np.pi)
    theta_in = np.concatenate([[start], start + np.sort(rng.uniform(0.3, 2 * np.pi - 0.3, 4))])
    pose = linkage.solve(theta_in)
    return np.angle(pose.C - pose.B), pose.P


def timed(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), float(np.min(times))


def least_squares_route(theta, d, found, max_starts, seed):
    """Random starts of damped least squares until every dyad of `found` is hit."""
    from scipy.optimize import least_squares

    rng = np.random.default_rng(seed)
    size = np.max(np.abs(d - d.mean()))
    w = np.exp(1j * (theta - theta[0]))

    def res(v):
        B1, A = (v[0] + 1j * v[1]) * size, (v[2] + 1j * v[3]) * size
        Bj = w[1:] * (B1 - d[0]) + d[1:]
        return 0.5 * (np.abs(Bj - A) ** 2 - np.abs(B1 - A) ** 2) / size**2

    missing = {k for k in range(len(found.dyads))}
    t0 = time.perf_counter()
    starts = 0
    while missing and starts < max_starts:
        starts += 1
        c = d.mean() / size
        x0 = np.array([c.real, c.imag, c.real, c.imag]) + np.exp(rng.uniform(np.log(0.1), np.log(60))) * rng.normal(size=4) / 2
        sol = least_squares(res, x0, xtol=1e-15, ftol=1e-15, gtol=1e-15, method="lm")
        A = (sol.x[2] + 1j * sol.x[3]) * size
        for k in list(missing):
            if abs(found.dyads[k].centre_point - A) < 1e-6 * max(size, abs(A)):
                missing.discard(k)
    elapsed = time.perf_counter() - t0
    return {"starts": starts, "found_all": not missing, "seconds": elapsed, "seconds_per_start": elapsed / starts}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", type=Path, default=None)
    args = parser.parse_args(argv)
    repeats = 5 if args.quick else 31
    tasks = 3 if args.quick else 20

    t0 = time.perf_counter()
    first = guidance_fourbars(EX_THETA, EX_P)
    cold = time.perf_counter() - t0

    results = {"example_2_15": {}, "random_tasks": [], "first_call_seconds": cold, "import_seconds": IMPORT_TIME}
    ex = results["example_2_15"]
    ex["burmester"] = timed(lambda: burmester(EX_THETA, EX_P), repeats)
    ex["guidance_fourbars"] = timed(lambda: guidance_fourbars(EX_THETA, EX_P), repeats)
    ex["real_dyads"] = len(first.dyads)
    ex["passing"] = len(first.passing)
    ex["least_squares"] = least_squares_route(EX_THETA, EX_P, burmester(EX_THETA, EX_P), 2000, 1)

    for seed in range(tasks):
        theta, d = coupler_task(seed)
        found = burmester(theta, d)
        results["random_tasks"].append({
            "seed": seed, "real_dyads": len(found.dyads),
            "burmester": timed(lambda: burmester(theta, d), repeats)[0],
            "guidance_fourbars": timed(lambda: guidance_fourbars(theta, d), repeats)[0],
            "least_squares": least_squares_route(theta, d, found, 2000, seed),
        })
    rt = results["random_tasks"]
    results["summary"] = {
        "burmester_median_ms": 1e3 * float(np.median([r["burmester"] for r in rt])),
        "guidance_fourbars_median_ms": 1e3 * float(np.median([r["guidance_fourbars"] for r in rt])),
        "guidance_fourbars_max_ms": 1e3 * float(np.max([r["guidance_fourbars"] for r in rt])),
        "least_squares_starts_median": float(np.median([r["least_squares"]["starts"] for r in rt])),
        "least_squares_ms_per_start": 1e3 * float(np.median([r["least_squares"]["seconds_per_start"] for r in rt])),
        "goal_ms": 50.0,
    }
    from bench_coupler_curve import machine, versions

    results["machine"], results["versions"] = machine(), versions()
    results["date"] = _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds")
    s = results["summary"]
    print(f"example 2-15: burmester {1e3 * ex['burmester'][0]:.2f} ms, guidance_fourbars "
          f"{1e3 * ex['guidance_fourbars'][0]:.2f} ms (first call {1e3 * cold:.1f} ms); "
          f"least squares needed {ex['least_squares']['starts']} starts, {1e3 * ex['least_squares']['seconds']:.0f} ms")
    print(f"{tasks} random tasks: burmester {s['burmester_median_ms']:.2f} ms, guidance_fourbars "
          f"{s['guidance_fourbars_median_ms']:.2f} ms median (max {s['guidance_fourbars_max_ms']:.2f}); "
          f"least squares: {s['least_squares_starts_median']:.0f} starts median at "
          f"{s['least_squares_ms_per_start']:.2f} ms each")
    output = args.output or (None if args.quick else OUTPUT)
    if output is not None:
        output.write_text(json.dumps(results, indent=1) + "\n")
        print(f"wrote {output}")


if __name__ == "__main__":
    main()
