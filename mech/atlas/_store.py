"""The atlas: sampled four-bars with their shape signatures, stored as Parquet (issue 13, item 3).

An atlas on disk is a folder of Parquet files ``part-00000.parquet``, ``part-00001.parquet``,
... written by pyarrow. Each part holds the linkage columns of `FourBarSamples`, the seed of
the build that made it and the signature as a fixed-size list column; its schema metadata
records the atlas format version and the build settings (harmonics, samples, design space).
Appending writes a new part after checking that its settings match; loading concatenates
the parts. pyarrow is imported only here, inside the functions that read or write.
"""

import json
import os
import time
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from mech._validate import _show, bool_flag, integer, nonnegative_number
from mech.atlas._sampling import COUPLER, LENGTHS, FourBarSamples, coupler_curves, sample_fourbars
from mech.atlas._signature import HARMONICS, SAMPLES, _resample_rows, _samples, normal_form

__all__ = ["ATLAS_VERSION", "Atlas", "build_atlas"]

#: Format version of a stored atlas; a different version is refused on loading.
ATLAS_VERSION = 1
_META_KEY = b"mech.atlas"
_COLUMNS = ("a", "b", "c", "d", "p", "q", "branch", "kind", "full_turn", "theta_lo", "theta_hi",
            "gamma_min", "movable", "usable")


@dataclass(frozen=True)
class Atlas:
    """Four-bars with the shape signatures of their coupler curves.

    Built by `build_atlas`, read by `Atlas.from_parquet`, searched by `query`.

    Attributes
    ----------
    linkages : FourBarSamples
        The linkages, one row each (normalised: ground d = 1).
    signatures : ndarray, shape (n, 4 * harmonics)
        The signature of each closed coupler curve (`curve_signature`).
    seeds : ndarray of int, shape (n,)
        The seed of the build that produced each row.
    settings : dict
        ``version``, ``harmonics``, ``samples`` (arc-length points per curve), ``lengths``,
        ``coupler`` and ``min_transmission`` of the builds.

    Notes
    -----
    On disk an atlas is a folder of Parquet parts (pyarrow, imported only to read or write);
    `to_parquet` with ``append=True`` adds a part built with other seeds, and parts of
    another format version (`ATLAS_VERSION`) or other settings are refused. Signatures are
    derived in :ref:`deriv-shape-signature`.

    Examples
    --------
    >>> import tempfile
    >>> from mech.atlas import Atlas, build_atlas
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     _ = build_atlas(100, seed=1).to_parquet(folder)
    ...     _ = build_atlas(50, seed=2).to_parquet(folder, append=True)
    ...     atlas = Atlas.from_parquet(folder)
    >>> len(atlas), sorted(set(atlas.seeds.tolist()))
    (150, [1, 2])
    """

    linkages: FourBarSamples
    signatures: np.ndarray
    seeds: np.ndarray
    settings: dict

    def __len__(self):
        return len(self.linkages)

    @cached_property
    def _norms(self):
        """Squared norms of the signatures (the search's brute force reuses them)."""
        return np.einsum("ij,ij->i", self.signatures, self.signatures)

    @property
    def harmonics(self):
        """Harmonics per side of the signatures."""
        return int(self.settings["harmonics"])

    @property
    def samples(self):
        """Arc-length samples per curve used for the signatures."""
        return int(self.settings["samples"])

    def curves(self, index, samples=None):
        """Closed coupler curves of the rows `index`, shape (rows, samples), complex.

        `index` is a row number, row numbers or a boolean mask; `samples` defaults to the
        atlas's (see `FourBarSamples.curves` for how the input is stepped).
        """
        samples = self.samples if samples is None else integer("samples", samples, minimum=4, maximum=1 << 16)
        return coupler_curves(self.linkages.take(index).columns(), samples)

    def to_parquet(self, path, *, append=False):
        """Write the atlas to the folder `path` as one new Parquet part.

        Parameters
        ----------
        path : str or os.PathLike
            A folder; created if missing.
        append : bool, optional
            Add a part to an existing atlas (its settings must match); without it the folder
            must not hold an atlas yet.

        Returns
        -------
        pathlib.Path
            The part written.
        """
        import pyarrow as pa
        import pyarrow.parquet as pq

        append = bool_flag("append", append)
        folder = _folder(path)
        parts = sorted(folder.glob("part-*.parquet")) if folder.exists() else []
        if parts and not append:
            raise ValueError(f"Expected `path` without an atlas (or append=True), got {str(path)!r} "
                             f"holding {len(parts)} part(s)")
        if parts:
            _check_settings(_read_settings(parts[0]), self.settings, str(path))
        folder.mkdir(parents=True, exist_ok=True)
        cols = self.linkages.columns()
        arrays = [pa.array(cols[name]) for name in _COLUMNS]
        arrays.append(pa.array(self.seeds.astype(np.int64)))
        width = self.signatures.shape[1]
        flat = pa.array(np.ascontiguousarray(self.signatures, dtype=np.float64).reshape(-1))
        arrays.append(pa.FixedSizeListArray.from_arrays(flat, width))
        table = pa.Table.from_arrays(arrays, names=[*_COLUMNS, "seed", "signature"])
        table = table.replace_schema_metadata({_META_KEY: json.dumps(self.settings).encode()})
        target = folder / f"part-{len(parts):05d}.parquet"
        pq.write_table(table, target)
        return target

    @classmethod
    def from_parquet(cls, path):
        """Read an atlas written by `to_parquet` (every part of the folder `path`).

        Raises
        ------
        ValueError
            If `path` holds no atlas, or parts of another format version or other settings.
        """
        import pyarrow.parquet as pq

        folder = _folder(path)
        parts = sorted(folder.glob("part-*.parquet")) if folder.is_dir() else []
        if not parts:
            raise ValueError(f"Expected `path` to be a folder holding an atlas, got {str(path)!r}")
        settings = _read_settings(parts[0])
        if settings.get("version") != ATLAS_VERSION:
            raise ValueError(f"Expected an atlas of format version {ATLAS_VERSION}, got version "
                             f"{settings.get('version')!r} in {str(path)!r}")
        tables = []
        for part in parts:
            _check_settings(settings, _read_settings(part), str(part))
            tables.append(pq.read_table(part))
        cols = {name: np.concatenate([t.column(name).to_numpy() for t in tables]) for name in _COLUMNS}
        cols["kind"] = cols["kind"].astype(str)
        cols["branch"] = cols["branch"].astype(np.int8)
        width = 4 * int(settings["harmonics"])
        sig = np.concatenate([t.column("signature").combine_chunks().flatten().to_numpy() for t in tables])
        seeds = np.concatenate([t.column("seed").to_numpy() for t in tables])
        return cls(FourBarSamples(**cols), sig.reshape(-1, width), seeds, settings)


def _folder(path):
    if not isinstance(path, (str, os.PathLike)) or isinstance(path, bytes):
        raise TypeError(f"Expected `path` to be a folder name, got {_show(path)}")
    return Path(path)


def _read_settings(part):
    import pyarrow.parquet as pq

    meta = pq.read_schema(part).metadata or {}
    if _META_KEY not in meta:
        raise ValueError(f"Expected `path` to hold atlas parts, got {str(part)!r} without atlas metadata")
    return json.loads(meta[_META_KEY])


def _check_settings(have, new, where):
    keys = ("version", "harmonics", "samples", "lengths", "coupler", "min_transmission")
    diff = [k for k in keys if have.get(k) != new.get(k)]
    if diff:
        shown = ", ".join(f"{k}: {have.get(k)!r} vs {new.get(k)!r}" for k in diff)
        raise ValueError(f"Expected atlas parts with the same settings in `path`, got {shown} in {where!r}")


def signatures_of(linkages, harmonics, samples):
    """Signatures (n, 4K) of the closed coupler curves of `linkages` (and their normal forms)."""
    curves = coupler_curves(linkages.columns(), samples)
    form = normal_form(_resample_rows(curves, samples, True), harmonics)
    return form.signature, form


def block_seed(seed, index):
    """The seed of block `index` of a build with `seed` (NumPy's SeedSequence of the pair)."""
    return int(np.random.SeedSequence([seed, index]).generate_state(1, dtype=np.uint64)[0] >> 1)


def build_atlas(n, *, seed=0, harmonics=HARMONICS, samples=SAMPLES, lengths=LENGTHS, coupler=COUPLER,
                min_transmission=0.0, block=4096, progress=False):
    """Build an atlas of `n` usable four-bars with the signatures of their coupler curves.

    Samples are drawn by `sample_fourbars` in blocks of `block`, block ``i`` with the seed
    `block_seed` ``(seed, i)`` (so a build is reproduced exactly by its seed and block size,
    and builds with different seeds draw different blocks);
    those that cannot move or whose minimum transmission angle is below `min_transmission`
    are left out, until `n` are kept.

    Parameters
    ----------
    n : int
        Number of linkages, in [1, 10**7].
    seed : int, optional
        Seed of the first block.
    harmonics, samples : int, optional
        Signature settings (see `curve_signature`); `samples` is also the number of input
        steps along each coupler curve.
    lengths, coupler : tuple, optional
        The design space (see `sample_fourbars`).
    min_transmission : float, optional
        Keep only linkages whose `gamma_min` is at least this, radians in [0, pi/2]; any
        value above 0 keeps only linkages whose crank turns fully.
    block : int, optional
        Samples drawn per block, in [16, 10**6].
    progress : bool, optional
        Show a tqdm progress bar.

    Returns
    -------
    Atlas

    Examples
    --------
    >>> from mech.atlas import build_atlas
    >>> atlas = build_atlas(200, seed=5)
    >>> len(atlas), atlas.signatures.shape, atlas.settings["version"]
    (200, (200, 32), 1)
    >>> bool(atlas.linkages.usable.all())
    True
    """
    n = integer("n", n, minimum=1, maximum=10**7)
    seed = integer("seed", seed, minimum=0)
    harmonics = integer("harmonics", harmonics, minimum=1, maximum=1 << 14)
    samples = _samples(samples, harmonics=harmonics)
    block = integer("block", block, minimum=16, maximum=10**6)
    progress = bool_flag("progress", progress)
    min_transmission = nonnegative_number("min_transmission", min_transmission)
    sample_fourbars(0, lengths=lengths, coupler=coupler, min_transmission=min_transmission)  # checks
    kept, sigs, seeds, total = [], [], [], 0
    bar = _bar(progress, n)
    started = time.perf_counter()
    with bar:
        index = 0
        while total < n:
            drawn = sample_fourbars(block, seed=block_seed(seed, index), lengths=lengths, coupler=coupler,
                                    min_transmission=min_transmission)
            good = drawn.take(drawn.usable)
            sig, _ = signatures_of(good, harmonics, samples)
            finite = np.all(np.isfinite(sig), axis=1)          # a pose that did not assemble
            good, sig = good.take(finite), sig[finite]
            take = min(len(good), n - total)
            kept.append(good.take(np.arange(take)))
            sigs.append(sig[:take])
            seeds.append(np.full(take, seed, dtype=np.int64))
            total += take
            bar.update(take)
            index += 1
            if index > 1000 and total == 0:
                raise ValueError(f"Expected `lengths`, `coupler` and `min_transmission` of a design space with "
                                 f"movable linkages, got lengths={lengths!r}, coupler={coupler!r}, "
                                 f"min_transmission={min_transmission!r}: none in {index} blocks")
    cols = {k: np.concatenate([getattr(s, k) for s in kept]) for k in _COLUMNS}
    settings = {"version": ATLAS_VERSION, "harmonics": harmonics, "samples": samples,
                "lengths": list(map(float, lengths)), "coupler": list(map(float, coupler)),
                "min_transmission": min_transmission, "block": block,
                "build_seconds": round(time.perf_counter() - started, 3)}
    return Atlas(FourBarSamples(**cols), np.concatenate(sigs), np.concatenate(seeds), settings)


class _NoBar:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def update(self, n=1):
        pass


def _bar(progress, total):
    if not progress:
        return _NoBar()
    from tqdm.auto import tqdm

    return tqdm(total=total, desc="atlas", unit="linkage")
