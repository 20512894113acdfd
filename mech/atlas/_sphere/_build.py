"""Building a spherical atlas: in blocks, in one process or on a Dask cluster, stoppable and resumable.

The same scheme as the planar `build_atlas`: block ``i`` of a build with `seed` draws its
samples with the seed `block_seed` ``(seed, i)``, so every block is a pure function of
``(seed, i)`` and the settings, and the blocks may run here or as tasks of a Dask
``distributed.Client`` and give the same atlas bit for bit. With a folder each block is
written as a Parquet part as soon as it is taken, so a stopped build resumes where it stopped.
"""

import time
import uuid

import numpy as np

from mech._validate import _show, bool_flag, integer, nonnegative_number
from mech.atlas._parts import _blocks, _folder, _take_blocks, block_seed
from mech.atlas._records import _MAX_SEED
from mech.atlas._planar._signature import HARMONICS, SAMPLES
from mech.atlas._sphere._sampling import ARCS, COUPLER_ARC, SphereSamples, sample_sphere_fourbars, sphere_curves
from mech.atlas._sphere._signature import _resample_closed, _signature_rows
from mech.atlas._sphere._store import (
    _COLUMNS, SPHERE_ATLAS_VERSION, SphereAtlas, done_blocks, write_part,
)

__all__ = ["build_sphere_atlas"]

#: Curve points per signature sample computed before the arc-length resampling.
DENSE = 2


def sphere_signatures_of(linkages, harmonics, samples):
    """Signatures (n, 3 (K + 1)) of the closed coupler curves of `linkages` (SphereSamples)."""
    curves = sphere_curves(linkages.columns(), DENSE * samples)
    return _signature_rows(_resample_closed(curves, samples), harmonics)


def build_sphere_block(seed, index, block, harmonics, samples, arcs, coupler_arc, min_transmission):
    """Block `index` of a build: its usable linkages (dict of columns) and their signatures.

    A pure function of its arguments (the unit of work of a Dask build).
    """
    drawn = sample_sphere_fourbars(block, seed=block_seed(seed, index), arcs=arcs, coupler_arc=coupler_arc,
                                   min_transmission=min_transmission)
    good = drawn.take(drawn.usable)
    if len(good) == 0:      # a block with nothing usable (a strict min_transmission): no curves to draw
        return good.columns(), np.empty((0, 3 * (harmonics + 1)))
    sig = sphere_signatures_of(good, harmonics, samples)
    finite = np.all(np.isfinite(sig), axis=1)
    return good.take(finite).columns(), sig[finite]


def build_sphere_atlas(n, *, seed=0, harmonics=HARMONICS, samples=SAMPLES, arcs=ARCS, coupler_arc=COUPLER_ARC,
                       min_transmission=0.0, block=2048, progress=False, client=None, path=None, resume=False):
    """Build an atlas of `n` usable spherical four-bars with the signatures of their coupler curves.

    Samples are drawn by `sample_sphere_fourbars` in blocks of `block`, block ``i`` with a
    seed derived from ``(seed, i)``; those that cannot move, change-point linkages and those
    whose minimum transmission angle is below `min_transmission` are left out, and blocks
    are taken in order until `n` are kept. Cranks that turn fully and rocking inputs are
    both kept (a rocking input's closed curve runs over its range on one branch and back
    on the other).

    Parameters
    ----------
    n : int
        Number of linkages, in [1, 10**7].
    seed : int, optional
        Master seed of the build, in [0, 2**63 - 1] (atlases keep it in a 64-bit column).
    harmonics, samples : int, optional
        Signature settings (see `sphere_signature`).
    arcs, coupler_arc : (float, float), optional
        The design space (see `sample_sphere_fourbars`).
    min_transmission : float, optional
        Radians in [0, pi/2]; above 0 only cranks that turn fully are kept.
    block : int, optional
        Samples drawn per block, in [16, 10**6].
    progress : bool, optional
        Show a tqdm progress bar.
    client : distributed.Client, optional
        Compute the blocks as tasks on this Dask cluster; the result is identical.
    path : str or os.PathLike, optional
        Write each block as a Parquet part of the folder `path` as soon as it is taken.
    resume : bool, optional
        With `path`: continue a stopped build of the same settings.

    Returns
    -------
    SphereAtlas
        Read back from `path` when one is given.

    Examples
    --------
    >>> from mech.atlas import build_sphere_atlas
    >>> atlas = build_sphere_atlas(200, seed=1)
    >>> len(atlas), atlas.signatures.shape
    (200, (200, 27))
    >>> sorted(set(atlas.kind.tolist()))
    ['crank-rocker', 'double-crank', 'double-rocker', 'rocker-crank', 'triple-rocker']
    """
    n = integer("n", n, minimum=1, maximum=10**7)
    seed = integer("seed", seed, minimum=0, maximum=_MAX_SEED)
    harmonics = integer("harmonics", harmonics, minimum=1, maximum=1 << 12)
    samples = integer("samples", samples, minimum=4, maximum=1 << 16)
    if samples <= 2 * harmonics:
        raise ValueError(f"Expected `samples` > 2 * harmonics = {2 * harmonics}, got {samples}")
    block = integer("block", block, minimum=16, maximum=10**6)
    progress = bool_flag("progress", progress)
    resume = bool_flag("resume", resume)
    min_transmission = nonnegative_number("min_transmission", min_transmission)
    sample_sphere_fourbars(0, arcs=arcs, coupler_arc=coupler_arc, min_transmission=min_transmission)  # checks
    if client is not None and not (callable(getattr(client, "submit", None))
                                   and callable(getattr(client, "nthreads", None))):
        raise TypeError(f"Expected `client` to be a dask.distributed Client, got {_show(client)}")
    if resume and path is None:
        raise ValueError("Expected a `path` to resume a build in, got None")
    arcs, coupler_arc = [float(x) for x in arcs], [float(x) for x in coupler_arc]
    settings = {"version": SPHERE_ATLAS_VERSION, "harmonics": harmonics, "samples": samples, "arcs": arcs,
                "coupler_arc": coupler_arc, "min_transmission": min_transmission, "block": block}
    build = {"seed": seed, "n": n, "block": block}
    folder = None if path is None else _folder(path)
    done, total = done_blocks(folder, settings, build, resume) if folder is not None else (-1, 0)

    def work(index):
        return seed, index, block, harmonics, samples, arcs, coupler_arc, min_transmission

    tag = uuid.uuid4().hex[:8]
    started = time.perf_counter()
    kept, sigs, total = _take_blocks(
        _blocks(done + 1, work, client, build_sphere_block, lambda j: f"mech-sphere-atlas-{tag}-{j}"), n, total,
        seed, build, settings, folder, SphereSamples, write_part, progress,
        lambda index: (f"Expected `arcs`, `coupler_arc` and `min_transmission` of a design space with "
                       f"usable linkages, got arcs={arcs!r}, coupler_arc={coupler_arc!r}, "
                       f"min_transmission={min_transmission!r}: none in {index} blocks"))
    if folder is not None:
        return SphereAtlas.from_parquet(folder)
    cols = {k: np.concatenate([getattr(s, k) for s in kept]) for k in _COLUMNS}
    settings["build_seconds"] = round(time.perf_counter() - started, 3)
    return SphereAtlas(SphereSamples(**cols), np.concatenate(sigs), np.full(total, seed, dtype=np.int64), settings)
