"""Command line of the coupler-curve atlas.

    python -m mech.atlas build ATLAS_DIR -n 10000 [--seed 0] [--min-transmission DEG]
                                          [--resume | --append] [--dask local:2 | --dask tcp://host:8786]
                                          [--mechanism four-bar | --mechanism slider-crank]
    python -m mech.atlas index ATLAS_DIR
    python -m mech.atlas query ATLAS_DIR points.csv [-k 5] [--open] [--plot out.png]
    python -m mech.atlas query ATLAS_DIR --target drawing.svg|points.csv [--json d.json] [--svg d.svg]
                                          [--dxf d.dxf] [--units mm] [--link-width W] [--hole H]

``build`` samples four-bars in blocks and computes their signatures with a progress bar,
writing each block as a Parquet part (``--resume`` continues a stopped build; ``--append``
adds one part built with another seed to an atlas); ``--dask`` computes the blocks on a
Dask cluster, with the same result; ``--mechanism slider-crank`` samples slider-cranks with
a coupler point on the rod instead. ``query`` reads a target curve (closed, or an open arc
with ``--open``) from a CSV file of ``x, y`` rows, or from the one path of an SVG drawing
(``--target``; closed or open as drawn), and prints the best linkages, placed on the target,
with their cognates, the motor's place and the smallest transmission angle; ``--plot``
draws them over the target (Matplotlib); ``--json``, ``--svg`` and ``--dxf`` write the best
one as files a maker uses (`mech.planar.export`). The first open query of an atlas
stores its index of windows in ``ATLAS_DIR/arcs/``; later queries load it. ``index``
builds the approximate nearest-neighbour index of the signatures (faiss's HNSW graph) and
stores it in ``ATLAS_DIR/ann/``: every later query of that atlas loads it and searches
through it (worth it from about 10^6 linkages; without it, or without faiss, the search is
exact).
"""

import argparse
import contextlib
import math
import os
import sys
import time

import numpy as np


def _build(args):
    from mech.atlas import Atlas, build_atlas

    if args.append and args.resume:
        raise ValueError("Expected one of `--append` and `--resume`, got both")
    # an unwritable folder is refused before minutes of sampling, not after
    try:
        os.makedirs(args.atlas, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"Expected `atlas` to be a folder that can be written, got {args.atlas!r} "
                         f"({exc.strerror})") from None
    started = time.perf_counter()
    options = dict(seed=args.seed, harmonics=args.harmonics, samples=args.samples, block=args.block,
                   min_transmission=math.radians(args.min_transmission), progress=not args.quiet,
                   mechanism=args.mechanism)
    with _client(args.dask) as client:
        if args.append:
            atlas = build_atlas(args.n, client=client, **options)
            part = atlas.to_parquet(args.atlas, append=True)
            where = f"to {part}"
        else:
            atlas = build_atlas(args.n, client=client, path=args.atlas, resume=args.resume, **options)
            where = f"to {args.atlas}"
    total = len(Atlas.from_parquet(args.atlas))
    print(f"wrote {len(atlas)} linkages {where} in {time.perf_counter() - started:.2f} s (atlas now {total})")


def _index(args):
    from mech.atlas import Atlas
    from mech.atlas._planar._ann import build_index

    started = time.perf_counter()
    atlas = Atlas.from_parquet(args.atlas)
    build_index(atlas)
    print(f"indexed {len(atlas)} signatures in {time.perf_counter() - started:.2f} s (stored in {args.atlas}/ann)")


@contextlib.contextmanager
def _client(spec):
    """No client for None; a local cluster of N worker processes for "local:N"; else a scheduler address."""
    if spec is None:
        yield None
        return
    import logging

    from distributed import Client, LocalCluster

    logging.getLogger("distributed").setLevel(logging.ERROR)
    if spec.startswith("local"):
        _, _, count = spec.partition(":")
        if not (count or "2").isdigit() or int(count or "2") < 1:
            raise ValueError(f"Expected --dask local:N with N >= 1 workers, got {spec!r}")
        with LocalCluster(n_workers=int(count or "2"), threads_per_worker=1, dashboard_address=":0") as cluster, \
                Client(cluster) as client:
            yield client
    else:
        with Client(spec) as client:
            yield client


def _describe(m):
    if hasattr(m.linkage, "slider"):
        sc, (p, q) = m.linkage.slider, m.linkage.coupler
        (A,), (G, u) = m.linkage.pivots, m.linkage.guide
        return "\n".join([
            f"#{m.rank}  row {m.index}  {m.kind}  error {m.error:.4g} ({100 * m.relative_error:.3g} %)  "
            f"gamma_min {math.degrees(m.gamma_min):.1f} deg  "
            f"{'full turn' if m.full_turn else 'rocking %.1f..%.1f deg' % tuple(map(math.degrees, m.theta_range))}",
            f"    slider-crank  a={sc.a:.5g} b={sc.b:.5g} e={sc.e:.5g} p={p:.5g} q={q:.5g} branch={sc.branch:+d}  "
            f"A=({A.real:.5g}, {A.imag:.5g})  guide through ({G.real:.5g}, {G.imag:.5g}) "
            f"along ({u.real:.5g}, {u.imag:.5g})"]
            + [f"    cognate  a={c.slider.a:.5g} b={c.slider.b:.5g} e={c.slider.e:.5g} p={c.coupler[0]:.5g} "
               f"q={c.coupler[1]:.5g}  guide through ({c.guide[0].real:.5g}, {c.guide[0].imag:.5g}) "
               f"along ({c.guide[1].real:.5g}, {c.guide[1].imag:.5g})" for c in m.cognates])
    f = m.linkage.fourbar
    A, D = m.linkage.pivots
    lines = [f"#{m.rank}  row {m.index}  {m.kind}  error {m.error:.4g} ({100 * m.relative_error:.3g} %)  "
             f"gamma_min {math.degrees(m.gamma_min):.1f} deg  "
             f"{'full turn' if m.full_turn else 'rocking %.1f..%.1f deg' % tuple(map(math.degrees, m.theta_range))}",
             f"    ABCD  a={f.a:.5g} b={f.b:.5g} c={f.c:.5g} d={f.d:.5g} p={f.coupler[0]:.5g} q={f.coupler[1]:.5g} "
             f"branch={f.branch:+d}  A=({A.real:.5g}, {A.imag:.5g}) D=({D.real:.5g}, {D.imag:.5g})"]
    if m.arc is not None:
        lines.append(f"    the part of its curve with curve parameter u from {math.degrees(m.arc[0]):.1f} "
                     f"to {math.degrees(m.arc[1]):.1f} deg")
    for c in m.cognates:
        g = c.fourbar
        P, Q = c.pivots
        lines.append(f"    {c.name}  a={g.a:.5g} b={g.b:.5g} c={g.c:.5g} d={g.d:.5g} p={g.coupler[0]:.5g} "
                     f"q={g.coupler[1]:.5g}  pivots ({P.real:.5g}, {P.imag:.5g}) ({Q.real:.5g}, {Q.imag:.5g})")
    return "\n".join(lines)


def _query(args):
    from mech.atlas import Atlas, query, read_target

    source = args.target or args.points
    if source is None or (args.target and args.points):
        raise ValueError(f"Expected one target file (`points` or `--target` FILE.csv|FILE.svg), got {[args.points, args.target]}")
    atlas = Atlas.from_parquet(args.atlas)
    target, closed = read_target(source)
    # a CSV does not say whether the curve closes: --open does; an SVG path says it itself
    closed = (not args.open) if closed is None or args.open else closed
    started = time.perf_counter()
    matches = query(atlas, target, k=args.k, closed=closed)
    print(f"{len(atlas)} linkages searched in {1000 * (time.perf_counter() - started):.1f} ms "
          f"({'closed curve' if closed else 'open arc'} of {len(target)} points from {source})")
    for m in matches:
        print(_describe(m))
        print("    " + _design_line(m, args.units))
    if args.plot:
        _plot(target, matches, args.plot)
    if matches and (args.json or args.svg or args.dxf):
        _export(matches[0], args)


def _design_line(m, units):
    """Type, where the motor goes and the smallest transmission angle of a match, as built."""
    from mech.planar.export import design_of

    d = design_of(m, units=units)
    where = d.joints[d.motor]
    turns = "turns fully" if d.full_turn else "only rocks (no motor can drive it round)"
    return (f"{d.type} ({d.kind}): motor at {d.motor} ({where.real:.5g}, {where.imag:.5g}) on the {d.driven} "
            f"{''.join(d.links[d.driven])}, which {turns}; minimum transmission angle "
            f"{math.degrees(d.gamma_min):.1f} deg")


def _export(m, args):
    from mech.planar.export import design_of, write_dxf, write_json, write_svg

    d = design_of(m, units=args.units)
    cutting = dict(link_width=args.link_width, hole_diameter=args.hole)
    for path, write in ((args.json, write_json), (args.svg, write_svg), (args.dxf, write_dxf)):
        if path:
            write(d, path, **cutting)
            print(f"wrote the best linkage to {path}")


def _plot(target, matches, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 5))
    ax.plot(target.real, target.imag, "k.", ms=3, label="target")
    for m in matches:
        curve = m.curve if m.arc is not None else np.append(m.curve, m.curve[0])
        pivots = np.asarray(m.linkage.pivots)
        line, = ax.plot(curve.real, curve.imag, lw=1, label=f"#{m.rank} ({m.kind})")
        ax.plot(pivots.real, pivots.imag, "^", color=line.get_color())
    ax.set_aspect("equal")
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=120)
    print(f"drew {path}")


class _Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line on stderr (status 2), not a usage block."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def main(argv=None):
    parser = _Parser(prog="python -m mech.atlas", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    b = sub.add_parser("build", help="sample four-bars and store their signatures")
    b.add_argument("atlas", help="atlas folder (Parquet parts)")
    b.add_argument("-n", type=int, default=10_000, help="linkages to add (default 10000)")
    b.add_argument("--seed", type=int, default=0)
    b.add_argument("--harmonics", type=int, default=8)
    b.add_argument("--samples", type=int, default=128)
    b.add_argument("--min-transmission", type=float, default=0.0, help="degrees")
    b.add_argument("--block", type=int, default=4096, help="linkages drawn per block (default 4096)")
    b.add_argument("--mechanism", choices=["four-bar", "slider-crank"], default="four-bar",
                   help="linkages of the atlas (default four-bar)")
    b.add_argument("--append", action="store_true", help="add a part to an existing atlas")
    b.add_argument("--resume", action="store_true", help="continue a stopped build (same settings)")
    b.add_argument("--dask", metavar="CLUSTER",
                   help="compute the blocks on Dask: local:N for a local cluster of N workers, "
                        "or a scheduler address such as tcp://host:8786")
    b.add_argument("--quiet", action="store_true", help="no progress bar")
    x = sub.add_parser("index", help="build and store the approximate nearest-neighbour index of an atlas (faiss)")
    x.add_argument("atlas")
    q = sub.add_parser("query", help="find linkages for a curve (closed, or open with --open) given as a CSV of x, y rows")
    q.add_argument("atlas")
    q.add_argument("points", nargs="?", help="the target: a CSV of x, y rows (or give --target)")
    q.add_argument("--target", help="the target: a CSV of x, y rows or an SVG with one path (closed or open read from it)")
    q.add_argument("--json", help="write the best linkage as JSON to this file")
    q.add_argument("--svg", help="draw the best linkage into this SVG file")
    q.add_argument("--dxf", help="write the best linkage's links and pin holes as a DXF for a laser cutter")
    q.add_argument("--units", default="", help="the unit of the target's lengths, written into the files (e.g. mm)")
    q.add_argument("--link-width", type=float, help="link width in the DXF and SVG (default 8 %% of the linkage's size)")
    q.add_argument("--hole", type=float, help="pin hole diameter (default half the link width)")
    q.add_argument("-k", type=int, default=5)
    q.add_argument("--open", action="store_true", help="the points are an open arc (matched against parts of curves)")
    q.add_argument("--plot", help="draw the matches over the target into this image file")
    args = parser.parse_args(argv)
    try:
        {"build": _build, "index": _index, "query": _query}[args.command](args)
    except (ValueError, TypeError, OSError, ImportError) as exc:
        # a bad value, an unreadable or unwritable path, a missing optional package: one line
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
