"""Benchmark: the coupler-curve atlas on the sphere (issue 13), in one run.

- build: `build_sphere_atlas(n)` in one process (full-turn and rocking inputs), n = 10^4 and
  10^5, reported per 10^4 linkages;
- closed targets: atlas rows under a random rotation of the sphere, restart, reversal half of
  the time and Gaussian noise of 1e-3 of the target's RMS size; the rate at which the row
  comes first, the query time (median, max) and the worst relative error of the first match;
- open arcs: half a cycle of an atlas curve (half a turn of a crank that turns fully) from a
  random start, with the same rotation, reversal and noise, on a 2000-entry atlas; the rate
  at which the row comes first and the query time;
- refinement: closed curves of spherical four-bars drawn with another seed (not in the
  atlas): the relative RMS error of the first match, after `refine_sphere`, and after
  `find_sphere_linkages` from 4 starts;
- Dask: the 10^5 build again on a local cluster of 2 worker processes (one thread each),
  its throughput and whether it is identical to the single-process build.

Written to ``results/atlas_sphere.json`` (the planar atlas has ``results/atlas.json``).
Times are on a shared machine (its load average is recorded).

    python benchmarks/bench_atlas_sphere.py            # writes results/atlas_sphere.json
    python benchmarks/bench_atlas_sphere.py --quick    # smaller, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from bench_coupler_curve import machine, versions  # noqa: E402

from mech.atlas import (build_sphere_atlas, find_sphere_linkages, query_sphere, refine_sphere,  # noqa: E402
                        sample_sphere_fourbars)
from mech.atlas._sphere._sampling import sphere_points  # noqa: E402

OUTPUT = HERE / "results" / "atlas_sphere.json"
NOISE = 1e-3


def _rotation(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))


def _noisy(rng, c):
    radius = np.sqrt(np.mean(np.sum((c - c.mean(axis=0)) ** 2, axis=1)))
    x = c + NOISE * radius * rng.normal(size=c.shape)
    return x / np.linalg.norm(x, axis=1)[:, None]


def _closed(atlas, trials, rng):
    hits, times, worst, misses = 0, [], 0.0, []
    query_sphere(atlas, atlas.curves(0, 300)[0])                    # warm
    for _ in range(trials):
        i = int(rng.integers(len(atlas)))
        c = np.roll(atlas.curves(i, 300)[0], int(rng.integers(300)), axis=0)
        if rng.random() < 0.5:
            c = c[::-1]
        x = _noisy(rng, c @ _rotation(rng).T)
        t = time.perf_counter()
        matches = query_sphere(atlas, x, k=5)
        times.append(time.perf_counter() - t)
        if matches[0].index == i:
            hits += 1
            worst = max(worst, matches[0].relative_error)
        else:
            misses.append({"row": i, "kind": str(atlas.kind[i]), "first": matches[0].index,
                           "first_relative_error": matches[0].relative_error,
                           "row_rank": next((m.rank for m in matches if m.index == i), None)})
    return {"n": len(atlas), "trials": trials, "recovered": hits, "query_median_s": float(np.median(times)),
            "query_max_s": float(np.max(times)), "worst_relative_error_of_hits": worst, "misses": misses}


def _open(atlas, trials, rng):
    hits, times, worst, full = 0, [], 0.0, [0, 0]
    t = time.perf_counter()
    query_sphere(atlas, atlas.curves(0, 300)[0][:150], closed=False)  # fills the sub-arc cache
    cache = time.perf_counter() - t
    for _ in range(trials):
        i = int(rng.integers(len(atlas)))
        u = rng.uniform(0, 2 * np.pi) + np.linspace(0, np.pi, 200)
        c = sphere_points(atlas.linkages.take([i]).columns(), u[None])[0]
        if rng.random() < 0.5:
            c = c[::-1]
        x = _noisy(rng, c @ _rotation(rng).T)
        t = time.perf_counter()
        best = query_sphere(atlas, x, k=5, closed=False)[0]
        times.append(time.perf_counter() - t)
        hits += best.index == i
        worst = max(worst, best.relative_error)
        if atlas.linkages.full_turn[i]:
            full[0] += best.index == i
            full[1] += 1
    return {"n": len(atlas), "trials": trials, "recovered": hits, "full_turn_recovered": full[0],
            "full_turn_trials": full[1], "query_median_s": float(np.median(times)), "first_query_s": cache,
            "worst_relative_error_of_first": worst}


def _refinement(atlas, count, rng):
    drawn = sample_sphere_fourbars(400, seed=2027)
    rows = np.flatnonzero(drawn.usable)[:count]
    out = []
    for i in rows:
        target = drawn.take([i]).curves(400)[0] @ _rotation(rng).T
        first = query_sphere(atlas, target, k=1)[0]
        t = time.perf_counter()
        better = refine_sphere(first, target)
        one = time.perf_counter() - t
        t = time.perf_counter()
        multi = find_sphere_linkages(atlas, target, starts=4)[0]
        out.append({"kind": str(drawn.kind[i]), "first_relative_error": first.relative_error,
                    "refined_relative_error": better.relative_error, "refine_s": one,
                    "multistart4_relative_error": multi.relative_error, "multistart4_s": time.perf_counter() - t})
        print(f"    refine ({drawn.kind[i]}): {first.relative_error:.2e} -> {better.relative_error:.2e} "
              f"in {one:.1f} s; from 4 starts {multi.relative_error:.2e} in {out[-1]['multistart4_s']:.1f} s")
    return out


def _dask_build(n, single):
    import logging

    from distributed import Client, LocalCluster

    logging.getLogger("distributed").setLevel(logging.ERROR)
    env = {"PYTHONPATH": os.environ.get("PYTHONPATH", "")}
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0",
                      env=env) as cluster, Client(cluster) as client:
        build_sphere_atlas(4000, seed=1, client=client)                # warm the workers
        t = time.perf_counter()
        atlas = build_sphere_atlas(n, seed=0, client=client)
        build = time.perf_counter() - t
    same = bool(np.array_equal(atlas.signatures, single.signatures)
                and all(np.array_equal(v, getattr(single.linkages, k)) for k, v in atlas.linkages.columns().items()))
    one = single.settings["build_seconds"]
    print(f"Dask, 2 workers: n = {n}: {n / build:,.0f} linkages/s (one process {n / one:,.0f}), identical: {same}")
    return {"n": n, "workers": 2, "build_s": build, "linkages_per_s": n / build, "single_process_build_s": one,
            "single_process_linkages_per_s": n / one, "identical": same}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", type=Path, default=None)
    args = parser.parse_args(argv)
    sizes = (10_000,) if args.quick else (10_000, 100_000)
    rng = np.random.default_rng(2026)
    closed = {}
    for n in sizes:
        t = time.perf_counter()
        atlas = build_sphere_atlas(n, seed=0)
        build = time.perf_counter() - t
        closed[str(n)] = {"build_s": build, "build_s_per_1e4": build / n * 1e4,
                          "rocking_fraction": float(np.mean(~atlas.linkages.full_turn)),
                          **_closed(atlas, 20 if args.quick else 100, rng)}
        r = closed[str(n)]
        print(f"n = {n:>7}: build {build:6.2f} s ({r['build_s_per_1e4']:.2f} s per 10^4), closed recovered "
              f"{r['recovered']}/{r['trials']}, query median {1e3 * r['query_median_s']:.0f} ms "
              f"(max {1e3 * r['query_max_s']:.0f}), worst first-match error {r['worst_relative_error_of_hits']:.1e}")
    dask_report = _dask_build(sizes[-1], atlas)
    small = build_sphere_atlas(2000, seed=0)
    arcs = _open(small, 10 if args.quick else 30, rng)
    print(f"open half-cycle arcs, n = 2000: recovered {arcs['recovered']}/{arcs['trials']} (full turn "
          f"{arcs['full_turn_recovered']}/{arcs['full_turn_trials']}), query median "
          f"{1e3 * arcs['query_median_s']:.0f} ms, first query (sub-arc signatures) {arcs['first_query_s']:.1f} s")
    ten = build_sphere_atlas(10_000, seed=0)
    refined = _refinement(ten, 2 if args.quick else 5, rng)
    report = {"date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"), "noise": NOISE,
              "machine": machine(), "versions": versions(), "closed": closed, "dask": dask_report,
              "open_arcs": arcs, "refinement": refined}
    output = args.output or (None if args.quick else OUTPUT)
    if output is not None:
        output.write_text(json.dumps(report, indent=2) + "\n")
        print(f"written {output}")
    ok = dask_report["identical"] and all(r["recovered"] == r["trials"] for r in closed.values())
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
