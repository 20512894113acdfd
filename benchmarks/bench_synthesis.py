"""Benchmark: path synthesis from the atlas on targets that anyone can rerun (issue 28, item 3).

The targets are files in ``benchmarks/targets/``, each with its source in its header:

- ``*.closed.csv``, ``*.open.csv``: the point lists of the literature targets (Yu et al.
  2007, McGarva 1994, Ullah & Kota 1997, Bulatovic et al. 2016, Hernandez et al. 2021) and
  the drawn arcs of the test folders of the four-bar-rs project, copied as data, and the
  curves of three linkages given there by their parameters (Wu et al. 2011, Hsieh 2017);
- ``letters/*.svg``: capital letters drawn as SVG paths (read by `mech.atlas.read_target`,
  closed or open as drawn);
- ``random/*.csv``: coupler curves of random four-bars (closed, or an arc of 40 % of the
  cycle), with and without Gaussian noise of 1 % of the curve's RMS radius; the generating
  linkage and seed are in each header (``--write-targets`` writes them again, identically).

For each target: `query` on a four-bar atlas (closed curves, or open arcs against parts of
curves), then, for a closed target, `find_linkages` (several refined starts) with its default
constraints (a crank that turns fully, a transmission angle of at least 30 degrees, links
within a ratio of 10) and again without any (``Constraints.none()``), and the ratio of the
two errors. Recorded: the
relative RMS error of the first match and of the refined best (`Match.relative_error`),
the wall time of each step, and the answer as a designer would build it
(`mech.planar.export.design_of`): its Grashof type, where the motor goes and whether that
link turns fully, its smallest transmission angle, and its longest-to-shortest link ratio.

    python benchmarks/bench_synthesis.py                 # a few minutes: 10^4 atlas, 2 starts,
                                                         # writes results/synthesis.json
    python benchmarks/bench_synthesis.py --full          # 10^5 atlas, every random target,
                                                         # find_linkages' default 8 starts
    python benchmarks/bench_synthesis.py --atlas DIR     # search a stored atlas instead (any size)
    python benchmarks/bench_synthesis.py --output /tmp/s.json --only yu1,O
    python benchmarks/bench_synthesis.py --refine-open   # refine the open targets' first match too

Times are on a shared machine (its load average is recorded).
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
TARGETS = HERE / "targets"
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent))

from bench_coupler_curve import machine, versions  # noqa: E402

from mech.atlas import Atlas, Constraints, build_atlas, find_linkages, query, read_target, refine, resample  # noqa: E402
from mech.planar import FourBar, grashof  # noqa: E402
from mech.planar.export import design_of  # noqa: E402

#: (name, seed, closed, noise): the random targets; the first of each kind runs by default
RANDOM = [(f"{'closed' if closed else 'open'}{'-noisy' if noise else ''}-{k}", 100 + 10 * k + 2 * closed + noise,
           closed, noise) for k in range(3) for closed in (True, False) for noise in (False, True)]


def _random_fourbar(rng):
    """A crank-rocker with a coupler point off the coupler line (lengths relative to the ground 1)."""
    while True:
        a, b, c = rng.uniform(0.15, 0.5), rng.uniform(0.5, 1.6), rng.uniform(0.5, 1.6)
        f = FourBar(a, b, c, 1.0, coupler=(rng.uniform(-0.5, 1.5) * b, rng.uniform(-1.0, 1.0) * b),
                    branch=int(rng.choice([-1, 1])))
        if f.solve(np.linspace(0, 2 * np.pi, 64)).valid.all():
            return f


def write_random_targets():
    """Write ``targets/random/*.csv`` (deterministic: numpy's PCG64 from each seed)."""
    folder = TARGETS / "random"
    folder.mkdir(exist_ok=True)
    for name, seed, closed, noise in RANDOM:
        rng = np.random.default_rng(seed)
        f = _random_fourbar(rng)
        start = rng.uniform(0, 2 * np.pi)
        span = 2 * np.pi if closed else 0.4 * 2 * np.pi
        theta = start + np.linspace(0, span, 120, endpoint=not closed)
        z = f.solve(theta).P
        z = 10.0 * np.exp(1j * rng.uniform(0, 2 * np.pi)) * z + complex(*rng.uniform(-5, 5, 2))
        if noise:
            rms = np.sqrt(np.mean(np.abs(z - z.mean()) ** 2))
            z = z + 0.01 * rms * (rng.standard_normal(z.size) + 1j * rng.standard_normal(z.size)) / np.sqrt(2)
        p, q = f.coupler
        head = [f"# Coupler curve of FourBar({float(f.a)!r}, {float(f.b)!r}, {float(f.c)!r}, {float(f.d)!r}, branch={f.branch}, "
                f"coupler=({float(p)!r}, {float(q)!r})), seed {seed} of benchmarks/bench_synthesis.py;",
                f"# {'the full cycle' if closed else 'an arc of 40 % of the cycle'}, moved, turned and scaled by 10"
                + (", with Gaussian noise of 1 % of the RMS radius." if noise else "."), "x,y"]
        rows = [f"{float(w.real)!r},{float(w.imag)!r}" for w in z]
        (folder / f"{name}.{'closed' if closed else 'open'}.csv").write_text("\n".join(head + rows) + "\n")


#: linkages given by their parameters in four-bar-rs's test folder (its older RON layout:
#: driver pivot p1, ground angle a, ground l1, driver l2, coupler l3, follower l4, coupler
#: point at l5 from the driver's pin at the angle g from the coupler line), with the source
LINKAGE_TARGETS = {
    "wu1": dict(p1=10 + 14j, a=0.1745, l1=11.0, l2=6.0, l3=8.0, l4=10.0, l5=7.0, g=0.6981, file="test-fb/wu1.closed.ron",
                cite="Wu, J., Ge, Q. J., Gao, F. and Guo, W. Z. (2011). On the extension of a Fourier descriptor "
                     "based method for planar four-bar linkage synthesis for generation of open and closed paths. "
                     "J. Mechanisms Robotics 3(3)."),
    "wu2": dict(p1=-2 - 3j, a=0.2, l1=3.0, l2=1.0, l3=2.0, l4=1.6, l5=0.5, g=0.3, file="test-fb/wu2.open.ron",
                cite="Wu, Ge, Gao and Guo (2011), J. Mechanisms Robotics 3(3)."),
    "c-shape": dict(p1=-2 - 3j, a=0.0, l1=6.0, l2=6.0, l3=8.0, l4=10.0, l5=2.0, g=1.0, file="test-fb/c-shape-1.open.ron",
                    cite="C.-Y. Hsieh (2017). Synthesis of four-bar linkage for path generation and motion generation "
                         "using Fourier descriptor. Master's thesis, National Taiwan University."),
}


def write_linkage_targets():
    """Write the curves of `LINKAGE_TARGETS`: the full cycle of a crank, else the input's range (branch +1)."""
    for name, t in LINKAGE_TARGETS.items():
        f = FourBar(t["l2"], t["l3"], t["l4"], t["l1"], coupler=(t["l5"] * math.cos(t["g"]), t["l5"] * math.sin(t["g"])))
        theta = np.linspace(-np.pi, np.pi, 7200, endpoint=False)
        ok = f.solve(theta).valid
        closed = bool(ok.all())
        if not closed:
            # the input rocks over one interval; start it at its first valid angle after a gap
            start = int(np.flatnonzero(ok & ~np.roll(ok, 1))[0])
            theta, ok = np.roll(theta, -start), np.roll(ok, -start)
            theta = np.unwrap(theta[: int(np.argmin(ok))])
        z = t["p1"] + np.exp(1j * t["a"]) * f.solve(theta).P
        z = z[:: max(1, len(z) // 120)]
        head = [f"# Coupler curve of the linkage in four-bar-rs (github.com/KmolYuan/four-bar-rs, licence "
                f"AGPL-3.0-or-later), file {t['file']} (commit 00e68872), read as FourBar({t['l2']}, {t['l3']}, "
                f"{t['l4']}, {t['l1']}, coupler=(l5 cos g, l5 sin g)) with l5 = {t['l5']}, g = {t['g']}, on branch +1,",
                f"# placed at the driver pivot {t['p1']} with the ground turned by {t['a']} rad; "
                + ("the full cycle." if closed else "the input's whole range, from one dead point to the other."),
                f"# Literature: {t['cite']}", "x,y"]
        rows = [f"{float(w.real)!r},{float(w.imag)!r}" for w in z]
        (TARGETS / f"{name}.{'closed' if closed else 'open'}.csv").write_text("\n".join(head + rows) + "\n")


#: the linkages the literature gives for its targets, as four-bar-rs stores them (files
#: syn-examples/refer/*.closed.ron at commits 1b3dba64 and d9a0de70): driver pivot, ground
#: angle a, ground l1, driver l2, coupler l3, follower l4, coupler point l5 at angle g
LITERATURE = {
    "yu1": dict(p0=-11.55 - 20.14j, a=2.981022362406315, l1=65.87, l2=17.43, l3=25.46, l4=64.57, l5=23.47,
                g=2.834414705238791),
    "yu2": dict(p0=-44.87 + 71.09j, a=5.187118536927147, l1=76.77, l2=27.31, l3=46.44, l4=72.55, l5=60.42,
                g=5.489060497522167),
    "mcgarva": dict(p0=54.6 - 35.5j, a=1.95, l1=47.5, l2=24.3, l3=48.1, l4=47.0, l5=85.6, g=0.9599310885968813),
    "ullah": dict(p0=-11.77 + 5.38j, a=4.9031534676276705, l1=9.33, l2=1.41, l3=7.39, l4=3.6, l5=13.57,
                  g=0.7452555906015788),
}


def shape_error(target, curve, samples=128, fine=8):
    """Relative RMS distance of a closed curve from a closed target, best aligned.

    Both are resampled at equal arc-length steps (the curve `fine` times more densely); every
    start of the curve (to 1/fine of a step) and both directions are tried, each with its
    best similarity (least squares); the RMS distance is divided by the target's RMS radius.
    The measure of `Match.relative_error`, written out here so that a linkage from elsewhere
    can be scored the same way.
    """
    t = resample(target, samples)
    t = t - t.mean()
    dense = resample(curve, samples * fine)
    best = np.inf
    for run in (dense, np.roll(dense[::-1], 1)):
        for shift in range(fine):
            rows = np.roll(run, -shift)[::fine]
            rows = np.array([np.roll(rows, -k) for k in range(samples)])
            a = rows - rows.mean(axis=1)[:, None]
            w = np.einsum("ij,j->i", a.conj(), t) / np.sum(np.abs(a) ** 2, axis=1)
            err = np.sqrt(np.mean(np.abs(t[None, :] - w[:, None] * a) ** 2, axis=1))
            best = min(best, float(err.min()))
    return best / float(np.sqrt(np.mean(np.abs(t) ** 2)))


def literature_errors(rows):
    """The literature linkage's own error on its target, read on either branch and either side."""
    for row in rows:
        ref = LITERATURE.get(row["name"])
        if ref is None:
            continue
        target, _ = read_target(HERE / row["source"])
        found = []
        for branch in (1, -1):
            for side in (1, -1):
                f = FourBar(ref["l2"], ref["l3"], ref["l4"], ref["l1"], branch=branch,
                            coupler=(ref["l5"] * math.cos(ref["g"]), side * ref["l5"] * math.sin(ref["g"])))
                sol = f.solve(np.linspace(0, 2 * np.pi, 4096, endpoint=False))
                if sol.valid.all():
                    found.append((shape_error(target, sol.P), branch, side))
        if found:
            err, branch, side = min(found)
            row["literature"] = {"error": err, "branch": branch, "coupler_side": side,
                                 "kind": grashof(ref["l2"], ref["l3"], ref["l4"], ref["l1"]).kind}


def targets(full, only):
    """``[(name, source file, closed, points)]``; by default one random target of each kind."""
    out = []
    files = sorted(TARGETS.glob("*.csv")) + sorted((TARGETS / "letters").glob("*.svg")) \
        + sorted((TARGETS / "random").glob("*.csv"))
    default_random = {r[0] for r in RANDOM[:4]}
    for path in files:
        name, kind = path.name.split(".")[:2]
        if path.parent.name == "random" and not full and name not in default_random:
            continue
        if only and name not in only:
            continue
        z, closed = read_target(path)
        out.append((name, str(path.relative_to(HERE)), kind == "closed" if closed is None else closed, z))
    return out


def _answer(match):
    """The match as built: type, motor, full turn, transmission angle, link ratio."""
    d = design_of(match)
    if d.type == "four-bar":
        links = [d.spec[k] for k in "abcd"]            # the measure: a, b, c, d
    else:
        # each link's length is its longest pin distance (the frame's too); a one-pin link has none
        links = [max(abs(d.joints[p] - d.joints[q]) for p in pins for q in pins)
                 for pins in d.links.values() if len(pins) >= 2]
    return {"type": d.type, "kind": d.kind, "motor": d.motor, "full_turn": d.full_turn,
            "gamma_min_deg": round(math.degrees(d.gamma_min), 2), "link_ratio": round(float(max(links) / min(links)), 2)}


def run_target(atlas, name, source, closed, z, starts, iterations, refine_open=False):
    row = {"name": name, "source": source, "closed": closed, "points": len(z)}
    t0 = time.perf_counter()
    first = query(atlas, z, k=1, closed=closed)[0]
    row["query_ms"] = round(1000 * (time.perf_counter() - t0), 1)
    row["query_error"] = float(first.relative_error)
    row["query_answer"] = _answer(first)
    if closed:
        t0 = time.perf_counter()
        best = find_linkages(atlas, z, starts=starts, iterations=iterations)[0]
        row["refine_s"] = round(time.perf_counter() - t0, 2)
        row["refined_error"] = float(best.relative_error)
        row["answer"] = _answer(best)
        # the same search without constraints (any four-bar, triple-rockers included): the
        # error a motor-driven answer is compared with
        t0 = time.perf_counter()
        free = find_linkages(atlas, z, starts=starts, iterations=iterations, constraints=Constraints.none())[0]
        row["free_s"] = round(time.perf_counter() - t0, 2)
        row["free_error"] = float(free.relative_error)
        row["free_kind"] = free.kind
        row["driven_over_free"] = round(row["refined_error"] / row["free_error"], 3)
    elif refine_open:
        t0 = time.perf_counter()
        best = refine(first, z)
        row["refine_s"] = round(time.perf_counter() - t0, 2)
        row["refined_error"] = float(best.relative_error)
        row["answer"] = _answer(best)
    else:
        row["answer"] = row["query_answer"]
    return row


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--full", action="store_true", help="10^5 atlas, every random target, 8 starts")
    parser.add_argument("--atlas", help="a stored atlas folder to search instead of building one")
    parser.add_argument("--only", help="comma-separated target names")
    parser.add_argument("--output", help="result file (default results/synthesis.json, or synthesis_full.json)")
    parser.add_argument("--refine-open", action="store_true", help="refine the first match of an open target too")
    parser.add_argument("--write-targets", action="store_true", help="write targets/random/*.csv again and stop")
    args = parser.parse_args(argv)
    if args.write_targets:
        write_random_targets()
        write_linkage_targets()
        return 0
    n, starts, iterations = (100_000, 8, 400) if args.full else (10_000, 2, 150)
    t0 = time.perf_counter()
    if args.atlas:
        atlas = Atlas.from_parquet(args.atlas)
        atlas_note = {"atlas": args.atlas, "size": len(atlas), "load_s": round(time.perf_counter() - t0, 2)}
    else:
        atlas = build_atlas(n, seed=0, progress=False)
        atlas_note = {"atlas": f"build_atlas({n}, seed=0)", "size": n, "build_s": round(time.perf_counter() - t0, 2)}
    print(f"atlas: {atlas_note}", flush=True)
    only = set(args.only.split(",")) if args.only else None
    rows = []
    for name, source, closed, z in targets(args.full, only):
        row = run_target(atlas, name, source, closed, z, starts, iterations, args.refine_open)
        a = row["answer"]
        print(f"{name:18s} {'closed' if closed else 'open  '} query {100 * row['query_error']:6.2f} % "
              f"{row['query_ms']:7.1f} ms" + (f"  refined {100 * row['refined_error']:6.2f} % {row['refine_s']:6.1f} s"
                                              if "refined_error" in row else " " * 28)
              + (f"  free {100 * row['free_error']:6.2f} % ({row['free_kind']})  x{row['driven_over_free']:.2f}"
                 if "free_error" in row else "")
              + f"  {a['kind']:14s} motor {a['motor']} {'turns' if a['full_turn'] else 'rocks'}  "
              f"gamma_min {a['gamma_min_deg']:5.1f} deg  ratio {a['link_ratio']}", flush=True)
        rows.append(row)
    literature_errors(rows)
    for r in rows:
        if "literature" in r:
            lit = r["literature"]
            print(f"{r['name']:18s} the literature's linkage ({lit['kind']}): {100 * lit['error']:.2f} %", flush=True)
    closed_rows = [r for r in rows if r["closed"]]
    summary = {
        "targets": len(rows),
        "closed": len(closed_rows),
        "closed_refined_error_median": float(np.median([r["refined_error"] for r in closed_rows])) if closed_rows else None,
        "closed_answers_that_turn": sum(r["answer"]["full_turn"] for r in closed_rows),
        "closed_answers_gamma_30_ratio_10": sum(r["answer"]["full_turn"] and r["answer"]["gamma_min_deg"] >= 30
                                                and r["answer"]["link_ratio"] <= 10 for r in closed_rows),
        "closed_driven_within_1_5_free": sum(r["driven_over_free"] <= 1.5 for r in closed_rows),
        "open_query_error_median": float(np.median([r["query_error"] for r in rows if not r["closed"]]))
        if len(rows) > len(closed_rows) else None,
    }
    print(json.dumps(summary, indent=1))
    out = {
        "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "machine": machine(),
        "versions": versions(),
        "load_average": list(os.getloadavg()),
        "settings": {"full": args.full, "starts": starts, "iterations": iterations, "only": args.only, **atlas_note},
        "error": "relative RMS distance at equal arc-length steps, best aligned, over the target's RMS radius "
                 "(Match.relative_error)",
        "summary": summary,
        "targets": rows,
    }
    path = Path(args.output) if args.output else HERE / "results" / ("synthesis_full.json" if args.full else "synthesis.json")
    path.write_text(json.dumps(out, indent=1) + "\n")
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
