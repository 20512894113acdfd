"""Benchmark: the spherical four-bar's coupler curve against the planar one, and its error.

In one run, interleaved so that a change in the shared machine's load hits both alike:

- ``SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.5)).solve(theta)`` (order 0: B, C,
  P as unit vectors and psi) at N = 10^4 input angles;
- ``FourBar(1, 4, 3, 3.5, coupler=(2, 1)).solve(theta)`` (order 0) at the same angles.

Each is timed as the median of 7 repeats of a loop of calls; the ratio spherical / planar
must stay at or below 3 (issue 5). The error of order 0 (and of order 2) against the
50-digit small-circle construction of ``tests/spherical/spherical_reference.py`` is
measured on a sample of angles: the largest distance of B, C, P (unit vectors) and of psi.
Results go to ``benchmarks/results/spherical.json``.

    python benchmarks/bench_spherical.py            # full run, writes the json
    python benchmarks/bench_spherical.py --quick    # fewer repeats, nothing written
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
ROOT = HERE.parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(ROOT / "tests" / "spherical"))

import spherical_reference as ref  # noqa: E402
from bench_coupler_curve import machine, versions  # noqa: E402

from mech.planar import FourBar  # noqa: E402
from mech.spherical._fourbar import SphericalFourBar  # noqa: E402

N = 10_000
REPEATS = 7
LOOPS = 20
SAMPLES = 40
GOAL_RATIO = 3.0
SPHERICAL = dict(arcs=(0.3, 0.9, 0.7, 1.0), coupler=(0.4, 0.5))
PLANAR = dict(lengths=(1.0, 4.0, 3.0, 3.5), coupler=(2.0, 1.0))
OUTPUT = HERE / "results" / "spherical.json"


def _time(call, loops):
    start = time.perf_counter()
    for _ in range(loops):
        call()
    return (time.perf_counter() - start) / loops


def timings(repeats, loops, n=N):
    theta = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    sph = SphericalFourBar(*SPHERICAL["arcs"], coupler=SPHERICAL["coupler"])
    pla = FourBar(*PLANAR["lengths"], coupler=PLANAR["coupler"])
    calls = {"spherical": lambda: sph.solve(theta).P, "planar": lambda: pla.solve(theta).P}
    for call in calls.values():            # warm up
        call()
    samples = {name: [] for name in calls}
    for _ in range(repeats):
        for name, call in calls.items():
            samples[name].append(_time(call, loops))
    return {name: {"median_s": float(np.median(v)), "min_s": float(np.min(v))} for name, v in samples.items()}


def errors(samples=SAMPLES):
    """Largest error of order 0 and 2 against the 50-digit reference, both branches."""
    theta = np.linspace(-np.pi, np.pi, samples, endpoint=False) + 0.01
    worst = {"positions": 0.0, "psi": 0.0, "rates": 0.0}
    for branch in (1, -1):
        linkage = SphericalFourBar(*SPHERICAL["arcs"], branch=branch, coupler=SPHERICAL["coupler"])
        rl = ref.Linkage(*SPHERICAL["arcs"], branch=branch, coupler=SPHERICAL["coupler"])
        pose = linkage.solve(theta, order=2, omega=1.0, alpha=0.5)
        for i, th in enumerate(theta):
            exact = ref.pose(rl, th)
            for name in ("B", "C", "P"):
                want = np.array([float(x) for x in exact[name]])
                worst["positions"] = max(worst["positions"], float(np.max(np.abs(getattr(pose, name)[i] - want))))
            worst["psi"] = max(worst["psi"], abs(float(pose.psi[i]) - float(exact["psi"])))
            if i % 8 == 0:
                r = ref.rates(rl, th, 1.0, 0.5)
                for name in ("vP", "aP", "w_coupler", "dw_coupler"):
                    want = np.array([float(x) for x in r[name]])
                    worst["rates"] = max(worst["rates"], float(np.max(np.abs(getattr(pose, name)[i] - want))))
    return worst


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats; write nothing")
    args = parser.parse_args(argv)
    started = time.perf_counter()
    repeats, loops = (3, 5) if args.quick else (REPEATS, LOOPS)
    times = timings(repeats, loops)
    ratio = times["spherical"]["median_s"] / times["planar"]["median_s"]
    err = errors(8 if args.quick else SAMPLES)
    out = {
        "benchmark": "spherical",
        "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "duration_s": round(time.perf_counter() - started, 1),
        "machine": machine(),
        "versions": versions(),
        "n": N,
        "repeats": repeats,
        "loops_per_repeat": loops,
        "spherical": SPHERICAL,
        "planar": PLANAR,
        "times": times,
        "ratio_spherical_over_planar": ratio,
        "goal_ratio": GOAL_RATIO,
        "goal": "PASS" if ratio <= GOAL_RATIO else "FAIL",
        "errors_vs_mpmath_50_digits": err,
    }
    print(json.dumps({k: out[k] for k in ("times", "ratio_spherical_over_planar", "goal",
                                          "errors_vs_mpmath_50_digits")}, indent=1))
    if not args.quick:
        OUTPUT.write_text(json.dumps(out, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
