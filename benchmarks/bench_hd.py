"""Benchmark: a stack of H-D matrices (2-67) in one vectorised call against a Python loop.

- ``hd``: ``mech.spatial._transforms.hd(phi, lam, s, h)`` on N = 10^6 random parameter sets,
  one call returning an array of shape (N, 4, 4);
- ``loop``: a plain Python loop building one 4x4 ``numpy`` array per parameter set from
  ``math.cos``/``math.sin`` (the way one writes (2-67) without thinking of stacks). The loop
  is timed on the first 10^4 sets and scaled to N (the scaling is linear; the results say so);
- ``chain``: the pose of N = 10^6 random 6-joint RRPRRR-style chains (``OpenChain.solve``,
  order 0) against a loop of per-pose 4x4 products (``hd`` rows built in the loop as above),
  the loop again timed on 10^4 poses and scaled.

Accuracy: the vectorised stack and the loop are compared entry by entry on the timed slice
(they should agree to a few ulps). Times are medians of interleaved repeats on a shared
machine; only the ratios are meaningful. Results go to ``benchmarks/results/hd.json``.

    python benchmarks/bench_hd.py            # full run
    python benchmarks/bench_hd.py --quick    # N = 10^5, loop on 10^3, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from bench_coupler_curve import machine, versions  # noqa: E402

from mech.spatial._chain import Joint, OpenChain  # noqa: E402
from mech.spatial._transforms import hd  # noqa: E402

N = 1_000_000
LOOP_N = 10_000
REPEATS = 5
OUTPUT = HERE / "results" / "hd.json"


def loop_hd(phi, lam, s, h):
    """One 4x4 numpy array per parameter set, (2-67) typed per matrix."""
    out = []
    for p, l_, s_, h_ in zip(phi.tolist(), lam.tolist(), s.tolist(), h.tolist()):
        cp, sp, cl, sl = math.cos(p), math.sin(p), math.cos(l_), math.sin(l_)
        out.append(np.array([[cp, -cl * sp, sl * sp, h_ * cp],
                             [sp, cl * cp, -sl * cp, h_ * sp],
                             [0.0, sl, cl, s_],
                             [0.0, 0.0, 0.0, 1.0]]))
    return out


def loop_chain(chain, q):
    """Per pose: build each joint's matrix with the loop above and multiply with numpy."""
    ends = []
    for row in q:
        T = np.eye(4)
        for joint, x in zip(chain.joints, row.tolist()):
            phi = joint.phi + (x if joint.kind == "R" else 0.0)
            s = joint.s + (x if joint.kind == "P" else 0.0)
            T = T @ loop_hd(np.array([phi]), np.array([joint.lam]), np.array([s]), np.array([joint.h]))[0]
        ends.append(T)
    return ends


def _timed(fn, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return times


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="N = 10^5, loop on 10^3, write nothing")
    parser.add_argument("--output", type=Path, default=None)
    args = parser.parse_args(argv)
    n, loop_n, repeats = (100_000, 1_000, 3) if args.quick else (N, LOOP_N, REPEATS)
    rng = np.random.default_rng(2025)
    params = (rng.uniform(-np.pi, np.pi, n), rng.uniform(-np.pi, np.pi, n),
              rng.uniform(-1, 1, n), rng.uniform(-1, 1, n))
    small = tuple(p[:loop_n] for p in params)

    hd(*small)                                                   # warm-up
    t_vec, t_loop = [], []
    for _ in range(repeats):                                     # interleaved
        t_vec += _timed(lambda: hd(*params), 1)
        t_loop += _timed(lambda: loop_hd(*small), 1)
    stack, loop = hd(*small), np.array(loop_hd(*small))
    err_hd = float(np.abs(stack - loop).max())
    row_hd = {
        "n": n, "loop_n_timed": loop_n,
        "hd_seconds_median": float(np.median(t_vec)), "hd_seconds_min": float(np.min(t_vec)),
        "loop_seconds_median_scaled_to_n": float(np.median(t_loop) * n / loop_n),
        "loop_seconds_min_scaled_to_n": float(np.min(t_loop) * n / loop_n),
        "max_abs_difference_on_timed_slice": err_hd,
    }
    row_hd["loop_over_hd"] = row_hd["loop_seconds_median_scaled_to_n"] / row_hd["hd_seconds_median"]
    print(f"hd stack of {n:.0e}: {row_hd['hd_seconds_median']:.3f} s; loop (timed on {loop_n:.0e}, scaled) "
          f"{row_hd['loop_seconds_median_scaled_to_n']:.1f} s; ratio {row_hd['loop_over_hd']:.0f}x; "
          f"max difference {err_hd:.1e}")

    quarter = np.pi / 2
    chain = OpenChain([Joint("R", lam=quarter, s=0.4), Joint("R", h=0.5), Joint("P", lam=-quarter),
                       Joint("R", lam=quarter, h=0.1), Joint("R", lam=-quarter), Joint("R", s=0.2)])
    q = rng.uniform(-np.pi, np.pi, (n, chain.dof))
    q_small = q[:loop_n]
    chain.solve(q_small)
    c_vec, c_loop = [], []
    for _ in range(repeats):
        c_vec += _timed(lambda: chain.solve(q), 1)
        c_loop += _timed(lambda: loop_chain(chain, q_small), 1)
    err_chain = float(np.abs(chain.solve(q_small).M - np.array(loop_chain(chain, q_small))).max())
    row_chain = {
        "n": n, "joints": len(chain.joints), "chain": repr(chain), "loop_n_timed": loop_n,
        "solve_seconds_median": float(np.median(c_vec)), "solve_seconds_min": float(np.min(c_vec)),
        "loop_seconds_median_scaled_to_n": float(np.median(c_loop) * n / loop_n),
        "max_abs_difference_on_timed_slice": err_chain,
    }
    row_chain["loop_over_solve"] = row_chain["loop_seconds_median_scaled_to_n"] / row_chain["solve_seconds_median"]
    print(f"chain of {len(chain.joints)} joints at {n:.0e} poses: {row_chain['solve_seconds_median']:.3f} s; loop "
          f"(scaled) {row_chain['loop_seconds_median_scaled_to_n']:.1f} s; ratio {row_chain['loop_over_solve']:.0f}x; "
          f"max difference {err_chain:.1e}")

    out = {
        "benchmark": "bench_hd",
        "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "repeats": repeats,
        "note": "loop times measured on the first loop_n_timed sets and scaled linearly to n",
        "machine": machine(), "versions": versions(),
        "results": {"hd_stack": row_hd, "chain_pose": row_chain},
    }
    path = args.output or (None if args.quick else OUTPUT)
    if path is not None:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(out, indent=2) + "\n")
        print(f"wrote {path}")
    return out


if __name__ == "__main__":
    main()
