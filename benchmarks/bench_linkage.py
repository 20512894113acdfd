"""Benchmark: ready-made six-bars and Jansen's leg, solve time per pose against error.

For the Watt six-bar, the Stephenson six-bar and Jansen's linkage of
``mech.planar.special._library`` (default dimensions), N crank angles (N = 10^4) are solved

- by ``mech``: ``Linkage.solve(theta, order=0)`` (positions) and ``order=2`` (positions,
  velocities, accelerations, omega = 1, alpha = 0), vectorised over all poses;
- by a plain Python loop over the poses: the law of cosines with ``math`` per pose for the
  positions, and central differences along the crank angle (step 1e-4) for the rates,
  the way one would write it without an array library.

Errors of both against the 50-digit mpmath reference of ``tests/planar/linkage_reference.py``
are measured on a 200-pose sample, relative to the largest magnitude of each quantity. Times
are medians of several runs, interleaved so a change in the shared machine's load hits both
methods alike; only ratios are meaningful. Results go to ``benchmarks/results/linkage.json``.

    python benchmarks/bench_linkage.py            # full run
    python benchmarks/bench_linkage.py --quick    # small N, nothing written
"""

from __future__ import annotations

import argparse
import cmath
import datetime as _dt
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(ROOT / "tests" / "planar"))

import linkage_reference as ref  # noqa: E402
from bench_coupler_curve import machine, versions  # noqa: E402

from mech.planar.special import _library as lib  # noqa: E402

N = 10_000
SAMPLES = 200
REPEATS = 7
STEP = 1e-4
OUTPUT = HERE / "results" / "linkage.json"


# ----------------------------------------------------------------------------- Python loop
def _pin(P1, P2, r1, r2, side):
    g = P2 - P1
    d = abs(g)
    c = (r1 * r1 + d * d - r2 * r2) / (2.0 * r1 * d)
    return P1 + r1 * cmath.exp(1j * (math.atan2(g.imag, g.real) + side * math.acos(c)))


def _watt(t):
    B = 20.0 * cmath.exp(1j * t)
    C = _pin(B, 50.0 + 0j, 50.0, 45.0, 1)
    g = C - 50.0
    E = 50.0 + 44.0 * cmath.exp(1j * (math.atan2(g.imag, g.real) + math.radians(-150.0)))
    G = _pin(E, 68.0 - 9.0j, 24.0, 18.0, -1)
    return {"B": B, "C": C, "E": E, "G": G}


def _stephenson(t):
    B = 20.0 * cmath.exp(1j * t)
    C = _pin(B, 50.0 + 0j, 50.0, 45.0, 1)
    E = B + (55.0 + 15.0j) * (C - B) / 50.0
    G = _pin(E, 54.0 - 27.0j, 82.3, 8.0, 1)
    return {"B": B, "C": C, "E": E, "G": G}


def _jansen(t):
    n = lib.JANSEN_HOLY_NUMBERS
    Z = complex(-n["a"], -n["l"])
    A = n["m"] * cmath.exp(1j * t)
    B = _pin(A, Z, n["j"], n["b"], -1)
    C = _pin(Z, B, n["d"], n["e"], 1)
    D = _pin(A, Z, n["k"], n["c"], 1)
    E = _pin(C, D, n["f"], n["g"], -1)
    F = _pin(D, E, n["i"], n["h"], 1)
    return {"A": A, "B": B, "C": C, "D": D, "E": E, "F": F}


LINKAGES = {
    "watt": (lib.watt_six_bar, _watt),
    "stephenson": (lib.stephenson_six_bar, _stephenson),
    "jansen": (lib.jansen_linkage, _jansen),
}


def loop_run(pose, theta, order):
    """Per-pose Python loop; returns dicts name -> complex arrays (P, V, A)."""
    P, V, A = {}, {}, {}
    for k, t in enumerate(theta.tolist()):
        p0 = pose(t)
        if order >= 1:
            pm, pp = pose(t - STEP), pose(t + STEP)
        for name, z in p0.items():
            P.setdefault(name, []).append(z)
            if order >= 1:
                V.setdefault(name, []).append((pp[name] - pm[name]) / (2 * STEP))
                A.setdefault(name, []).append((pp[name] - 2 * z + pm[name]) / (STEP * STEP))
    conv = lambda d: {k: np.array(v) for k, v in d.items()}
    return conv(P), conv(V), conv(A)


def mech_run(linkage, theta, order):
    sol = linkage.solve(theta, order=order)
    return sol.points, sol.velocities, sol.accelerations


# ----------------------------------------------------------------------------- errors
def reference(name, theta):
    rows = [ref.rates(ref.REFERENCES[name], float(t)) for t in theta]
    names = rows[0][0].keys()
    return [{p: np.array([complex(r[k][p]) for r in rows]) for p in names} for k in range(3)]


def max_errors(got, want, order):
    out = []
    for k in range(order + 1):
        worst = 0.0
        for p, w in want[k].items():
            worst = max(worst, float(np.max(np.abs(got[k][p] - w)) / np.max(np.abs(w))))
        out.append(worst)
    return out


# ----------------------------------------------------------------------------- main
def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="N = 10^3, 3 repeats, write nothing")
    parser.add_argument("--output", type=Path, default=None)
    args = parser.parse_args(argv)
    n, repeats = (1_000, 3) if args.quick else (N, REPEATS)
    theta = 2.0 * np.pi * np.arange(n) / n
    idx = np.unique(np.linspace(0, n - 1, min(SAMPLES, n)).astype(np.int64))
    results = {}
    for name, (build, pose) in LINKAGES.items():
        linkage = build()
        want = reference(name, theta[idx])
        row = {}
        for order in (0, 2):
            times = {"mech": [], "loop": []}
            mech_run(linkage, theta, order)                   # warm-up
            for _ in range(repeats):
                for method, fn in (("mech", lambda: mech_run(linkage, theta, order)),
                                   ("loop", lambda: loop_run(pose, theta, order))):
                    start = time.perf_counter()
                    got = fn()
                    times[method].append(time.perf_counter() - start)
            for method in ("mech", "loop"):
                got = mech_run(linkage, theta[idx], order) if method == "mech" else loop_run(pose, theta[idx], order)
                errs = max_errors(got, want, order)
                row[f"{method}_order{order}"] = {
                    "seconds_per_pose_median": float(np.median(times[method]) / n),
                    "seconds_per_pose_min": float(np.min(times[method]) / n),
                    "max_rel_error": dict(zip(("position", "velocity", "acceleration"), errs)),
                }
            row[f"loop_over_mech_order{order}"] = (row[f"loop_order{order}"]["seconds_per_pose_median"]
                                                   / row[f"mech_order{order}"]["seconds_per_pose_median"])
        row["order2_over_order0_mech"] = (row["mech_order2"]["seconds_per_pose_median"]
                                          / row["mech_order0"]["seconds_per_pose_median"])
        results[name] = row
        print(f"{name:11s} loop/mech: order 0 {row['loop_over_mech_order0']:6.1f}x, order 2 "
              f"{row['loop_over_mech_order2']:6.1f}x; mech order2/order0 {row['order2_over_order0_mech']:.2f}; "
              f"mech errors {row['mech_order2']['max_rel_error']}, loop errors {row['loop_order2']['max_rel_error']}")
    out = {
        "benchmark": "bench_linkage",
        "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "poses": n, "repeats": repeats, "reference_samples": int(len(idx)), "reference_dps": ref.DPS,
        "loop_difference_step": STEP, "machine": machine(), "versions": versions(), "results": results,
    }
    path = args.output or (None if args.quick else OUTPUT)
    if path is not None:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(out, indent=2) + "\n")
        print(f"wrote {path}")
    return out


if __name__ == "__main__":
    main()
