"""Building an atlas: in blocks, in one process or on a Dask cluster, stoppable and resumable.

A build draws samples in blocks of `block` linkages; block ``i`` of a build with `seed`
uses its own seed, `block_seed` ``(seed, i)``, so every block is a pure function of
``(seed, i)`` and the settings. That is what lets the blocks run anywhere: in this process,
or as tasks of a Dask ``distributed.Client`` (a local cluster or many machines), and still
give the same atlas, bit for bit. The blocks are then taken in order until `n` usable
linkages are kept; the last block is cut short.

With a folder, each block's kept rows are written as a Parquet part as soon as the block is
taken (its index in the part's metadata), so a build that is stopped can be resumed: the
blocks already on disk are skipped. Dask and tqdm are imported only when asked for.
"""

import time

import numpy as np

from mech._validate import _show, bool_flag, integer, nonnegative_number
from mech.atlas._parts import _blocks, _done_parts, _folder, _take_blocks, block_seed
from mech.atlas._records import _MAX_SEED, _box
from mech.atlas._planar._sampling import COUPLER, LENGTHS, coupler_curves, sample_fourbars
from mech.atlas._planar._signature import HARMONICS, SAMPLES, _resample_rows, _samples, normal_form
from mech.atlas._planar._slider import OFFSETS, RODS, check_mechanism, sample_slider_cranks
from mech.atlas._planar._store import (
    ATLAS_VERSION, Atlas, _check_settings, _read_settings, columns_of, write_part,
)

__all__ = ["build_atlas"]

def signatures_of(linkages, harmonics, samples):
    """Signatures (n, 4K) of the closed coupler curves of `linkages` (and their normal forms)."""
    curves = coupler_curves(linkages.columns(), samples)
    form = normal_form(_resample_rows(curves, samples, True), harmonics)
    return form.signature, form


def build_block(seed, index, block, harmonics, samples, lengths, coupler, min_transmission, mechanism="four-bar",
                offsets=OFFSETS):
    """Block `index` of a build: its usable linkages (as a dict of columns) and their signatures.

    A pure function of its arguments (the unit of work of a Dask build).
    """
    if mechanism == "slider-crank":
        drawn = sample_slider_cranks(block, seed=block_seed(seed, index), rods=lengths, offsets=offsets,
                                     coupler=coupler, min_transmission=min_transmission)
    else:
        drawn = sample_fourbars(block, seed=block_seed(seed, index), lengths=lengths, coupler=coupler,
                                min_transmission=min_transmission)
    good = drawn.take(drawn.usable)
    # a curve that did not assemble, or shrank to a point (a link 1e-200 of the others),
    # has no signature: its NaN row is dropped below, quietly
    with np.errstate(invalid="ignore", divide="ignore"):
        sig, _ = signatures_of(good, harmonics, samples)
    finite = np.all(np.isfinite(sig), axis=1)          # a pose that did not assemble
    return good.take(finite).columns(), sig[finite]


def build_atlas(n, *, seed=0, harmonics=HARMONICS, samples=SAMPLES, lengths=None, coupler=COUPLER,
                min_transmission=0.0, block=4096, progress=False, client=None, path=None, resume=False,
                mechanism="four-bar", offsets=OFFSETS):
    """Build an atlas of `n` usable four-bars (or slider-cranks) with the signatures of their coupler curves.

    Samples are drawn by `sample_fourbars` in blocks of `block`, block ``i`` with a seed
    derived from ``(seed, i)``; those that cannot move or whose minimum transmission angle is
    below `min_transmission` are left out, and blocks are taken in order until `n` are kept.
    The blocks can run on a Dask cluster (`client`) and be written to a folder as they come
    (`path`), so that a stopped build can be resumed.

    Parameters
    ----------
    n : int
        Number of linkages, in [1, 10**7].
    seed : int, optional
        Master seed of the build, in [0, 2**63 - 1] (atlases keep it in a 64-bit column).
    harmonics, samples : int, optional
        Signature settings (see `curve_signature`); `samples` is also the number of input
        steps along each coupler curve.
    lengths, coupler : tuple, optional
        The design space (see `sample_fourbars`); for slider-cranks `lengths` is the range
        of the rod over the crank (`sample_slider_cranks`'s `rods`). By default
        ``(0.2, 5.0)`` for four-bars, ``(0.3, 5.0)`` for slider-cranks.
    min_transmission : float, optional
        Keep only linkages whose `gamma_min` is at least this, radians in [0, pi/2]; any
        value above 0 keeps only linkages whose crank turns fully.
    block : int, optional
        Samples drawn per block, in [16, 10**6].
    progress : bool, optional
        Show a tqdm progress bar.
    client : distributed.Client, optional
        Compute the blocks as tasks on this Dask cluster (its workers need `mech`); the
        result is identical to a build in this process.
    path : str or os.PathLike, optional
        Write each block as a Parquet part of the atlas folder `path` as soon as it is taken.
    resume : bool, optional
        With `path`: continue a stopped build of the same settings, skipping the blocks on
        disk. Without it the folder must not hold an atlas yet.
    mechanism : {"four-bar", "slider-crank"}, optional
        The linkages of the atlas: four-bars (`sample_fourbars`) or slider-cranks with a
        coupler point on the rod (`sample_slider_cranks`); `query` searches either.
    offsets : (float, float), optional
        For slider-cranks: the range of the guide's offset over the crank.

    Returns
    -------
    Atlas
        Read back from `path` when one is given.

    Raises
    ------
    ValueError
        For bad settings (named), a folder that already holds an atlas (without `resume`)
        or parts of another build (with it).

    Notes
    -----
    Every block is a pure function of ``(seed, index)`` and the settings, so a build is
    reproduced exactly by its seed and block size, whether its blocks ran here, on a cluster
    or in several sessions. Builds with different seeds draw different blocks.

    Examples
    --------
    >>> from mech.atlas import build_atlas
    >>> atlas = build_atlas(200, seed=5)
    >>> len(atlas), atlas.signatures.shape, atlas.settings["version"]
    (200, (200, 32), 1)
    >>> bool(atlas.linkages.usable.all())
    True
    >>> sliders = build_atlas(100, seed=5, mechanism="slider-crank", min_transmission=0.3)
    >>> sliders.settings["mechanism"], bool(sliders.linkages.full_turn.all())
    ('slider-crank', True)
    """
    n = integer("n", n, minimum=1, maximum=10**7)
    seed = integer("seed", seed, minimum=0, maximum=_MAX_SEED)
    harmonics = integer("harmonics", harmonics, minimum=1, maximum=1 << 14)
    samples = _samples(samples, harmonics=harmonics)
    block = integer("block", block, minimum=16, maximum=10**6)
    progress = bool_flag("progress", progress)
    resume = bool_flag("resume", resume)
    min_transmission = nonnegative_number("min_transmission", min_transmission)
    mechanism = check_mechanism(mechanism)
    slider = mechanism == "slider-crank"
    if lengths is None:
        lengths = RODS if slider else LENGTHS
    if slider:
        if not _box("lengths", lengths, 2)[0] > 0.0:
            raise ValueError(f"Expected `lengths` > 0, got {_show(lengths)}")
        sample_slider_cranks(0, rods=lengths, offsets=offsets, coupler=coupler,
                             min_transmission=min_transmission)  # checks
    else:
        sample_fourbars(0, lengths=lengths, coupler=coupler, min_transmission=min_transmission)  # checks
    if client is not None and not (callable(getattr(client, "submit", None))
                                   and callable(getattr(client, "nthreads", None))):
        raise TypeError(f"Expected `client` to be a dask.distributed Client, got {_show(client)}")
    if resume and path is None:
        raise ValueError("Expected a `path` to resume a build in, got None")
    lengths, coupler = list(map(float, lengths)), list(map(float, coupler))
    settings = {"version": ATLAS_VERSION, "harmonics": harmonics, "samples": samples, "lengths": lengths,
                "coupler": coupler, "min_transmission": min_transmission, "block": block}
    offsets = list(map(float, offsets)) if slider else None
    if slider:
        settings.update(mechanism=mechanism, offsets=offsets)
    names, record = columns_of(mechanism)
    build = {"seed": seed, "n": n, "block": block}
    folder = None if path is None else _folder(path)
    done, total = (_done_blocks(folder, settings, build, resume) if folder is not None else (-1, 0))

    def work(index):
        return seed, index, block, harmonics, samples, lengths, coupler, min_transmission, mechanism, offsets

    started = time.perf_counter()
    kept, sigs, total = _take_blocks(
        _blocks(done + 1, work, client, build_block), n, total, seed, build, settings, folder, record, write_part, progress,
        lambda index: (f"Expected `lengths`, `coupler` and `min_transmission` of a design space with "
                       f"movable linkages, got lengths={lengths!r}, coupler={coupler!r}, "
                       f"min_transmission={min_transmission!r}: none in {index} blocks"))
    if folder is not None:
        return Atlas.from_parquet(folder)
    cols = {k: np.concatenate([getattr(s, k) for s in kept]) for k in names}
    settings["build_seconds"] = round(time.perf_counter() - started, 3)
    return Atlas(record(**cols), np.concatenate(sigs), np.full(total, seed, dtype=np.int64), settings)


def _done_blocks(folder, settings, build, resume):
    """The last block index on disk and the rows there, checking that they belong to `build`."""
    return _done_parts(folder, settings, build, resume, _read_settings, _check_settings)


