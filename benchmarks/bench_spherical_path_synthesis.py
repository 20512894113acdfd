"""Benchmark: spherical path synthesis (issue 14, item 5), distance against constant-arc.

Tasks (the worked examples of ``book/spherical/path-synthesis.md``):

- ``exact``: eight points of a known four-bar at prescribed input angles, no noise, from a
  start 0.05 rad off in every parameter;
- ``noisy``: the same points with Gaussian noise of 1e-3 per coordinate (example 1);
- ``circle``: nine points 40 degrees apart on a small circle of arc radius 0.25, input angles
  30 degrees apart, from the best start of the book's multi-start search (example 2);
- ``stephenson1``: seven points of a known Stephenson-1 six-bar, start 0.02 off (distance only);
- ``stephenson1-noisy``: twelve points of that six-bar with noise of 1e-3 per coordinate
  (example 3), start 0.02 off, without the assembly constraint (``min_transmission=None``:
  not in order) and with it (30 degrees);
- ``stephenson1-noisy-random``: the same points from ten random starts (example 3's search).

For each task and formulation: wall time (median of the repeats, imports done before the
clock starts), residual evaluations, and the largest and RMS arc error measured by analysis
(`path_verify`), with the in-order check. Times are on a shared machine (its load average
is recorded).

    python benchmarks/bench_spherical_path_synthesis.py          # writes results/spherical_path_synthesis.json
    python benchmarks/bench_spherical_path_synthesis.py --quick  # one repeat, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import statistics
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent))


def tasks():
    from mech.spherical import SphericalFourBar, ground_frame
    from mech.spherical.path._synthesis import _stephenson
    from tests.spherical.test_spherical_path_synthesis import (TH1, TH2, TH6, X1, X2, X6, example1_points,
                                                               example2_points, example3_points, random_starts)

    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    off = np.array([0.1, -0.1, 0.1, 0.05, -0.05, 0.05, -0.05, 0.1, -0.1])
    x6 = np.array([0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.2, 0.8, 0.3, -1.0, 0.8, 0.7, 0.4, 0.5])
    th6 = np.linspace(0.0, 1.6, 7)
    Q3 = example3_points()
    return {"exact": ("fourbar", m.solve(TH1).P, TH1, X1 + 0.05, 1e-6),
            "noisy": ("fourbar", example1_points(), TH1, X1 + off, 2e-3),
            "circle": ("fourbar", example2_points(), TH2, X2, 5e-3),
            "stephenson1": ("stephenson1", _stephenson(x6, (1, 1)).solve(th6).points["P"], th6, x6 + 0.02, 1e-6),
            "stephenson1-noisy": ("stephenson1", Q3, TH6, X6 + 0.02, 2e-3),
            "stephenson1-noisy-random": ("stephenson1", Q3, TH6, random_starts(Q3, 10, 7), 2e-3)}


def run(repeats):
    from mech.spherical import path_fourbar, path_stephenson1

    rows = []
    for name, (kind, Q, th, start, tol) in tasks().items():
        if kind == "fourbar":
            variants = [(form, {"formulation": form}) for form in ("distance", "constant-arc")]
        elif name == "stephenson1-noisy":
            variants = [("distance", {"min_transmission": None}), ("distance", {})]
        else:
            variants = [("distance", {})]
        for form, kwargs in variants:
            times, d = [], None
            for _ in range(repeats):
                if kind == "fourbar":
                    d = path_fourbar(Q, th, start, tol=tol, **kwargs)
                else:
                    d = path_stephenson1(Q, th, start, tol=tol, **kwargs)
                times.append(d.seconds)
            row = {"task": name, "linkage": kind, "formulation": form, "n_points": int(len(th)),
                   "seconds": statistics.median(times), "evaluations": int(d.evaluations),
                   "max_error": d.max_error, "rms_error": d.rms_error, "in_order": d.in_order,
                   "tol": tol, "passes": d.passes}
            if kind == "stephenson1":
                mu = kwargs.get("min_transmission", np.radians(30.0))
                row.update({"starts": int(np.atleast_2d(start).shape[0]),
                            "min_transmission": None if mu is None else float(mu)})
            rows.append(row)
            print(json.dumps(rows[-1]))
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args(argv)
    rows = run(1 if args.quick else 5)
    if args.quick:
        return
    import os
    import platform

    import scipy

    report = {"benchmark": "spherical_path_synthesis", "date": _dt.datetime.now(_dt.timezone.utc).isoformat(),
              "machine": {"platform": platform.platform(), "cpus": os.cpu_count(), "loadavg": os.getloadavg()},
              "versions": {"numpy": np.__version__, "scipy": scipy.__version__, "python": platform.python_version()},
              "rows": rows}
    out = HERE / "results" / "spherical_path_synthesis.json"
    out.write_text(json.dumps(report, indent=1) + "\n")


if __name__ == "__main__":
    main()
