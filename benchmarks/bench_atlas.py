"""Benchmark: the coupler-curve atlas (issue 13): build, query and recovery, in one run.

- build: `build_atlas(n)` in one process, for n = 10^4 and 10^5, reported per 10^4 linkages;
- query: `query(atlas, target, k=5)` on each atlas, median and max over the trials (goal for
  10^5 entries: under 50 ms);
- recovery: targets taken from random atlas rows, restarted between samples, reversed half
  of the time, moved, turned and scaled at random, with Gaussian noise of 1e-3 of their RMS
  radius; a trial succeeds when the first match is that row or one of its cognates (a miss
  is listed with the row's own rank and error among the first five);
- open arcs: targets that are half a cycle of an atlas curve (from a random start, so half a
  turn of the crank when it turns fully), with the same random similarity, reversal and
  1e-3 noise; the recovery rate of the first match (the row or a cognate), overall and for
  full-turn inputs, on the 10^4 atlas (and 50 trials on the 10^5 atlas), the misses whose
  first match fits within 1.5 times the noise (each miss with |c1|/S of the target, its
  first harmonic over its RMS radius: below about 0.1 the normalisation is ill-conditioned),
  the time to build the window signatures and their memory;
- refinement from several starts (`find_linkages`, 8 starts): the coupler curve of example
  2-1's linkage with a coupler point (20, 15), and curves of random linkages drawn with
  another seed (not in the atlas): the relative RMS error of the first match and after;
- sphere: a spherical atlas of 2000 four-bars whose crank turns fully; targets from random
  rows under a random rotation of the sphere, restart, reversal and 1e-3 noise; the rate at
  which the row comes first, and the query time;
- Dask: the same build of the largest atlas on a local Dask cluster of 2 worker processes
  (one thread each), its throughput beside the single-process build's, and whether its
  signatures are identical to the single-process build's (they must be: every block is a
  pure function of the seed and its index);
- slider-cranks (``--only slider``, run apart, written to ``results/atlas_slider.json``):
  build and query times of slider-crank atlases of 10^4 and 10^5 entries and the recovery
  of noisy targets from random rows, full-turn and rocking cranks counted apart;
- invariance: the largest signature change over random band-limited curves under random
  similarities, fractional restarts and reversals (exact resampling), as in the tests.

Times are on a shared machine (its load average is recorded).

    python benchmarks/bench_atlas.py            # writes results/atlas.json
    python benchmarks/bench_atlas.py --quick    # smaller, nothing written
    python benchmarks/bench_atlas.py --only slider   # the slider-crank atlas alone:
                                                     # writes results/atlas_slider.json
    python benchmarks/bench_atlas.py --open-arcs-only   # the open arcs on 10^4 only, same draws;
                                                        # updates that part of results/atlas.json
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

from mech.atlas import (build_atlas, build_sphere_atlas, curve_signature, find_linkages, query,  # noqa: E402
                        query_sphere, resample, sample_fourbars)
from mech.atlas._planar._sampling import coupler_curves, coupler_points  # noqa: E402
from mech.planar import FourBar, cognates  # noqa: E402

GOAL_QUERY_S = 0.050
#: An open-arc miss whose first match fits within this many times the noise counts as an equivalent fit.
NOISE_FIT = 1.5
OUTPUT = HERE / "results" / "atlas.json"
SLIDER_OUTPUT = HERE / "results" / "atlas_slider.json"


def _target(atlas, i, rng, points=300):
    curve = coupler_curves(atlas.linkages.take([i]).columns(), 4 * points)[0]
    curve = np.roll(curve, int(rng.integers(4 * points)))[::4]
    if rng.random() < 0.5:
        curve = curve[::-1]
    moved = complex(*rng.normal(scale=10, size=2)) + 10 ** rng.uniform(-2, 2) * np.exp(
        1j * rng.uniform(-np.pi, np.pi)) * curve
    size = np.sqrt(np.mean(np.abs(moved - moved.mean()) ** 2))
    return moved + 1e-3 * size * (rng.normal(size=points) + 1j * rng.normal(size=points)) / np.sqrt(2)


def _found(atlas, i, match):
    if match.index == i:
        return True
    L = atlas.linkages
    f = FourBar(L.a[i], L.b[i], L.c[i], L.d[i], branch=int(L.branch[i]), coupler=(L.p[i], L.q[i]))
    g = match.linkage.fourbar
    mine = np.array([g.a, g.b, g.c, g.d]) / g.d
    return any(np.allclose(np.array(c.lengths) / c.lengths[3], mine, rtol=1e-6) for c in cognates(f))


def _invariance(trials, rng):
    k = np.arange(-6, 7)
    worst = 0.0
    for _ in range(trials):
        c = rng.normal(size=13) + 1j * rng.normal(size=13)
        t = np.arange(64) / 64
        z = np.exp(2j * np.pi * np.outer(t, k)) @ c
        C = np.fft.fft(z) / 64
        if min(abs(C[1]), abs(C[-1])) < 0.05 * np.sqrt(np.sum(np.abs(C[1:]) ** 2)):
            continue
        tau, sign = rng.uniform(), rng.choice([-1, 1])
        w = np.exp(2j * np.pi * np.outer(sign * (t + tau), k)) @ c
        rho, beta = 10 ** rng.uniform(-3, 3), rng.uniform(-np.pi, np.pi)
        w = rho * complex(*rng.uniform(-50, 50, 2)) + rho * np.exp(1j * beta) * w
        worst = max(worst, float(np.max(np.abs(curve_signature(w, resampled=True)
                                               - curve_signature(z, resampled=True)))))
    return worst


def _arc_target(atlas, i, rng, points=200):
    u0 = rng.uniform(0, 2 * np.pi)
    arc = coupler_points(atlas.linkages.take([i]).columns(), (u0 + np.pi * np.linspace(0, 1, points))[None, :])[0]
    if rng.random() < 0.5:
        arc = arc[::-1]
    moved = complex(*rng.normal(scale=10, size=2)) + 10 ** rng.uniform(-2, 2) * np.exp(
        1j * rng.uniform(-np.pi, np.pi)) * arc
    size = np.sqrt(np.mean(np.abs(moved - moved.mean()) ** 2))
    return moved + 1e-3 * size * (rng.normal(size=points) + 1j * rng.normal(size=points)) / np.sqrt(2)


def _open_arcs(atlas, trials, rng):
    """Recovery of half-cycle arcs taken from atlas rows (first match is the row or a cognate).

    A miss is listed with the first match's relative error and the row's own (if among the
    first five); a miss whose first match fits the target within the noise (relative error
    at most `NOISE_FIT` times the 1e-3 noise) is counted apart, as an equivalent fit.
    """
    from mech.atlas._planar._arcs import arc_signatures

    t, c = time.perf_counter(), time.process_time()
    query(atlas, _arc_target(atlas, 0, rng), closed=False)            # the window signatures
    arc_signatures(atlas, 0.5, 64, base=2)                              # and those normalised on c_2
    cache_s, cache_cpu_s = time.perf_counter() - t, time.process_time() - c
    memory = sum(x.nbytes for pair in atlas._arc_cache.values() for x in pair)
    hits, full_hits, full, times, cpus, kinds, misses = 0, 0, 0, [], [], {}, []
    small_times, small_cpus, small_hits = [], [], 0
    for _ in range(trials):
        i = int(rng.integers(len(atlas)))
        target = _arc_target(atlas, i, rng)
        t, c = time.perf_counter(), time.process_time()
        matches = query(atlas, target, closed=False, k=5)
        times.append(time.perf_counter() - t)
        cpus.append(time.process_time() - c)
        ok = _found(atlas, i, matches[0])
        hits += ok
        if _first_harmonic(target) < 0.25:
            small_times.append(times[-1])
            small_cpus.append(cpus[-1])
            small_hits += ok
        kind = str(atlas.linkages.kind[i])
        kinds.setdefault(kind, [0, 0])
        kinds[kind][0] += ok
        kinds[kind][1] += 1
        if atlas.linkages.full_turn[i]:
            full += 1
            full_hits += ok
        if not ok:
            own = [m for m in matches if _found(atlas, i, m)]
            misses.append({"row": i, "kind": kind, "first_relative_error": matches[0].relative_error,
                           "first_kind": matches[0].kind,
                           # |c_1| over the RMS radius of the arc run forward and back: below
                           # about 0.1 the signature's normalisation is ill-conditioned
                           "first_harmonic": _first_harmonic(target),
                           "row_relative_error": own[0].relative_error if own else None,
                           "row_rank": own[0].rank if own else None})
    within = sum(m["first_relative_error"] <= NOISE_FIT * 1e-3 for m in misses)
    print(f"open arcs (half a cycle, 1e-3 noise), n = {len(atlas)}: recovered {hits}/{trials} "
          f"(+{within} misses fitted within the noise), full-turn inputs {full_hits}/{full}, query median "
          f"{1e3 * np.median(times):.0f} ms (CPU {1e3 * np.median(cpus):.0f} ms), window signatures "
          f"{memory / 1e6:.1f} MB (both sets) built in {cache_s:.1f} s; |c1|/S < 0.25: {small_hits}/"
          f"{len(small_times)}, query median {1e3 * np.median(small_times or [np.nan]):.0f} ms (CPU "
          f"{1e3 * np.median(small_cpus or [np.nan]):.0f} ms); by kind "
          + ", ".join(f"{k} {v[0]}/{v[1]}" for k, v in sorted(kinds.items())))
    for miss in misses:
        print(f"    miss: row {miss['row']} ({miss['kind']}) first match error {miss['first_relative_error']:.2e}, "
              f"the row itself at rank {miss['row_rank']} with error {miss['row_relative_error']}, "
              f"|c1|/S = {miss['first_harmonic']:.3f}")
    return {"n": len(atlas), "trials": trials, "recovered": hits, "misses_within_noise": within,
            "noise_fit": NOISE_FIT, "full_turn_trials": full, "full_turn_recovered": full_hits, "by_kind": kinds,
            "query_median_s": float(np.median(times)), "query_cpu_median_s": float(np.median(cpus)),
            "query_max_s": float(np.max(times)), "window_build_s": cache_s, "window_build_cpu_s": cache_cpu_s,
            "sub_arc_memory_mb": memory / 1e6, "small_first_harmonic": {
                "below": 0.25, "trials": len(small_times), "recovered": small_hits,
                "query_median_s": float(np.median(small_times)) if small_times else None,
                "query_cpu_median_s": float(np.median(small_cpus)) if small_cpus else None},
            "misses": misses}


def _first_harmonic(target):
    """|c_1| over the RMS radius of an arc run forward and back: below about 0.25 the window
    signatures normalised on c_1 are ill-conditioned, and the query also uses those on c_2."""
    coef = np.fft.fft(resample(np.concatenate([target, target[-2:0:-1]]), 256)) / 256
    return float(abs(coef[1]) / np.sqrt(np.sum(np.abs(coef[1:]) ** 2)))


def _replay_to_open_arcs(rng):
    """Advance `rng` past the draws the full run makes before its open arcs on 10^4 linkages
    (closed targets on 10^4 and 10^5, then arcs on 10^5; queries draw nothing), so
    ``--open-arcs-only`` repeats the same 200 arcs."""
    def skip(n, points, arc, warm):
        if not warm:
            rng.integers(n)
        rng.uniform(0, 2 * np.pi) if arc else rng.integers(4 * points)
        rng.random()
        rng.normal(scale=10, size=2)
        rng.uniform(-2, 2)
        rng.uniform(-np.pi, np.pi)
        rng.normal(size=points)
        rng.normal(size=points)

    for n in (10_000, 100_000):
        for trial in range(201):
            skip(n, 300, False, trial == 0)
    for trial in range(51):
        skip(100_000, 200, True, trial == 0)


def _refinement(atlas, targets, rng):
    """Multi-start refinement of targets not in the atlas: relative error before and after."""
    t = np.linspace(0, 2 * np.pi, 300, endpoint=False)
    cases = [("example 2-1, coupler (20, 15)", FourBar(10, 40, 30, 35, coupler=(20, 15)).solve(t).P)]
    others = sample_fourbars(400, seed=987654)
    others = others.take(others.usable & others.full_turn)
    for j in range(targets):
        cases.append((f"random crank-driven linkage {j}", others.fourbar(j).solve(t).P))
    rows = []
    for name, curve in cases:
        started = time.perf_counter()
        first = query(atlas, curve, k=1)[0]
        found = find_linkages(atlas, curve, starts=8)
        rows.append({"target": name, "first_relative_error": first.relative_error,
                     "refined_relative_error": found[0].relative_error,
                     "each_start": [m.relative_error for m in found], "seconds": time.perf_counter() - started})
        print(f"refine, 8 starts: {name}: first match {100 * first.relative_error:.3f} % -> "
              f"{100 * found[0].relative_error:.4f} % RMS of its size ({rows[-1]['seconds']:.1f} s)")
    return rows


def _sphere(trials, rng, n=2000):
    """Recovery on the sphere under a random rotation, restart, reversal and 1e-3 noise."""
    t = time.perf_counter()
    atlas = build_sphere_atlas(n, seed=4)
    build = time.perf_counter() - t
    hits, times = 0, []
    for _ in range(trials):
        i = int(rng.integers(n))
        c = np.roll(atlas.curves(i, 300)[0], int(rng.integers(300)), axis=0)
        if rng.random() < 0.5:
            c = c[::-1]
        q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        x = c @ (q * np.sign(np.linalg.det(q))).T + 1e-3 * rng.normal(size=c.shape)
        t = time.perf_counter()
        best = query_sphere(atlas, x / np.linalg.norm(x, axis=1)[:, None], k=1)[0]
        times.append(time.perf_counter() - t)
        hits += best.index == i
    print(f"sphere: n = {n}, build {build:.2f} s, recovered {hits}/{trials} under rotation + 1e-3 noise, "
          f"query median {1e3 * np.median(times):.0f} ms")
    return {"n": n, "build_s": build, "trials": trials, "recovered": hits, "query_median_s": float(np.median(times))}


def _dask_build(n, single):
    """Build the atlas of `single` again on a local cluster of 2 worker processes; compare."""
    import logging

    from distributed import Client, LocalCluster

    logging.getLogger("distributed").setLevel(logging.ERROR)
    t = time.perf_counter()
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            Client(cluster) as client:
        start_s = time.perf_counter() - t
        client.run(lambda: __import__("mech.atlas._planar._build"))     # warm the workers (imports)
        build_atlas(20_000, seed=1, client=client)
        t = time.perf_counter()
        atlas = build_atlas(n, seed=0, client=client)
        build = time.perf_counter() - t
    same = bool(np.array_equal(atlas.signatures, single.signatures)
                and all(np.array_equal(v, getattr(single.linkages, k)) for k, v in atlas.linkages.columns().items()))
    one = single.settings["build_seconds"]
    print(f"Dask, 2 workers: n = {n}: build {build:.2f} s ({n / build:,.0f} linkages/s; one process "
          f"{n / one:,.0f} linkages/s), cluster start {start_s:.2f} s, signatures identical: {same}")
    return {"n": n, "workers": 2, "build_s": build, "linkages_per_s": n / build,
            "single_process_build_s": one, "single_process_linkages_per_s": n / one,
            "cluster_start_s": start_s, "identical": same}


def _slider(sizes, trials, rng, quick):
    """The slider-crank atlas: build time, query time and recovery of noisy atlas curves.

    Targets are made like the four-bar ones (`_target`) from random rows, full-turn cranks
    and rocking ones counted apart; a trial succeeds when the first match is that row
    (slider-crank matches have no cognates).
    """
    results = {}
    for n in sizes:
        t = time.perf_counter()
        atlas = build_atlas(n, seed=0, mechanism="slider-crank")
        build = time.perf_counter() - t
        query(atlas, _target(atlas, 0, rng))                # warm
        times, hits, counts, misses = [], {"crank-slider": 0, "rocker-slider": 0}, {"crank-slider": 0,
                                                                                   "rocker-slider": 0}, []
        for _ in range(trials):
            i = int(rng.integers(n))
            kind = str(atlas.linkages.kind[i])
            target = _target(atlas, i, rng)
            t = time.perf_counter()
            matches = query(atlas, target, k=5)
            times.append(time.perf_counter() - t)
            counts[kind] += 1
            if matches[0].index == i:
                hits[kind] += 1
                continue
            own = [m for m in matches if m.index == i]
            misses.append({"row": i, "kind": kind, "first_relative_error": matches[0].relative_error,
                           "row_relative_error": own[0].relative_error if own else None,
                           "row_rank": own[0].rank if own else None})
        results[str(n)] = {"build_s": build, "build_s_per_1e4": build / n * 1e4,
                           "full_turn_fraction": float(np.mean(atlas.linkages.full_turn)),
                           "query_median_s": float(np.median(times)), "query_max_s": float(np.max(times)),
                           "recovered": hits, "trials": counts, "misses": misses}
        print(f"slider-crank n = {n:>7}: build {build:6.2f} s ({build / n * 1e4:.2f} s per 10^4), query median "
              f"{1e3 * np.median(times):6.1f} ms (max {1e3 * np.max(times):.1f}), recovered "
              + ", ".join(f"{hits[k]}/{counts[k]} {k}" for k in hits))
        for miss in misses:
            print(f"    miss: row {miss['row']} ({miss['kind']}) first match error {miss['first_relative_error']:.2e}, "
                  f"the row itself at rank {miss['row_rank']} with error {miss['row_relative_error']}")
    return {"date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"), "goal_query_s": GOAL_QUERY_S,
            "machine": machine(), "versions": versions(), "quick": quick, "results": results}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", type=Path, default=None)
    parser.add_argument("--only", choices=["slider"], default=None,
                        help="run one part alone: 'slider' writes results/atlas_slider.json")
    parser.add_argument("--open-arcs-only", action="store_true",
                        help="rerun only the open arcs on 10^4 linkages (the same draws) and update that "
                             "part of the results file")
    args = parser.parse_args(argv)
    if args.only == "slider":
        rng = np.random.default_rng(2027)
        report = _slider((10_000,) if args.quick else (10_000, 100_000), 20 if args.quick else 200, rng, args.quick)
        output = args.output or (None if args.quick else SLIDER_OUTPUT)
        if output is not None:
            output.write_text(json.dumps(report, indent=2) + "\n")
            print(f"written {output}")
        return 0
    if args.open_arcs_only:
        rng = np.random.default_rng(2026)
        _replay_to_open_arcs(rng)
        arcs = _open_arcs(build_atlas(10_000, seed=0), 200, rng)
        output = args.output or OUTPUT
        report = json.loads(output.read_text()) if output.exists() else {}
        report["open_arcs"] = arcs
        report["open_arcs_date"] = _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds")
        output.write_text(json.dumps(report, indent=2) + "\n")
        print(f"written the open arcs of {output}")
        return 0
    sizes = (10_000,) if args.quick else (10_000, 100_000)
    trials = 20 if args.quick else 200
    rng = np.random.default_rng(2026)
    results = {}
    for n in sizes:
        t = time.perf_counter()
        atlas = build_atlas(n, seed=0)
        build = time.perf_counter() - t
        query(atlas, _target(atlas, 0, rng))                # warm
        times, cpus, hits, ties = [], [], 0, []
        for _ in range(trials):
            i = int(rng.integers(n))
            target = _target(atlas, i, rng)
            t, c = time.perf_counter(), time.process_time()
            matches = query(atlas, target, k=5)
            times.append(time.perf_counter() - t)
            cpus.append(time.process_time() - c)
            if _found(atlas, i, matches[0]):
                hits += 1
                continue
            # a miss: is the row among the five, as good as the first within the noise?
            own = [m for m in matches if _found(atlas, i, m)]
            ties.append({"row": i, "kind": str(atlas.linkages.kind[i]),
                         "first_relative_error": matches[0].relative_error,
                         "row_relative_error": own[0].relative_error if own else None,
                         "row_rank": own[0].rank if own else None})
        results[str(n)] = {"build_s": build, "build_s_per_1e4": build / n * 1e4,
                           "query_median_s": float(np.median(times)), "query_max_s": float(np.max(times)),
                           "query_cpu_median_s": float(np.median(cpus)),
                           "recovered": hits, "trials": trials, "misses": ties}
        print(f"n = {n:>7}: build {build:6.2f} s ({build / n * 1e4:.2f} s per 10^4), query median "
              f"{1e3 * np.median(times):6.1f} ms (max {1e3 * np.max(times):.1f}, CPU median "
              f"{1e3 * np.median(cpus):.1f}), recovered {hits}/{trials}")
        for miss in ties:
            print(f"    miss: row {miss['row']} ({miss['kind']}) first match error {miss['first_relative_error']:.2e}, "
                  f"the row itself at rank {miss['row_rank']} with error {miss['row_relative_error']}")
    dask_report = _dask_build(sizes[-1], atlas)
    arcs_large = _open_arcs(atlas, 10 if args.quick else 50, rng) if len(sizes) > 1 else None
    del atlas
    small = build_atlas(sizes[0], seed=0)
    arcs = _open_arcs(small, 20 if args.quick else 200, rng)
    refined = _refinement(small, 2 if args.quick else 10, rng)
    sphere = _sphere(10 if args.quick else 100, rng)
    worst = _invariance(200 if args.quick else 5000, rng)
    print(f"largest signature change under similarity + restart + reversal: {worst:.2e}")
    report = {"date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
              "goal_query_s": GOAL_QUERY_S, "machine": machine(), "versions": versions(),
              "results": results, "dask": dask_report, "open_arcs": arcs, "open_arcs_large": arcs_large, "refinement": refined, "sphere": sphere,
              "invariance_max": worst}
    output = args.output or (None if args.quick else OUTPUT)
    if output is not None:
        output.write_text(json.dumps(report, indent=2) + "\n")
        print(f"written {output}")
    largest = results[str(sizes[-1])]
    # a miss is accepted only when the row itself is among the five, within 10 % of the first's error
    # (a nearly circular curve: several linkages trace it within the noise)
    ties_ok = all(m["row_rank"] is not None and m["row_relative_error"] <= 1.1 * m["first_relative_error"]
                  for r in results.values() for m in r["misses"])
    return 0 if largest["query_median_s"] < GOAL_QUERY_S and ties_ok and dask_report["identical"] else 1


if __name__ == "__main__":
    sys.exit(main())
