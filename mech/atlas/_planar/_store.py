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
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from mech._validate import integer
from mech.atlas._parts import _CHUNK_KEY, _fingerprint, _next_part, _read_parts, _table_columns
from mech.atlas._planar._sampling import FourBarSamples, coupler_curves

__all__ = ["ATLAS_VERSION", "Atlas"]

#: Format version of a stored atlas; a different version is refused on loading.
ATLAS_VERSION = 1
_META_KEY = b"mech.atlas"
_COLUMNS = ("a", "b", "c", "d", "p", "q", "branch", "kind", "full_turn", "theta_lo", "theta_hi",
            "gamma_min", "movable", "usable")
_SLIDER_COLUMNS = ("a", "b", "e", "p", "q", "branch", "kind", "full_turn", "theta_lo", "theta_hi",
                   "gamma_min", "movable", "usable")


def mechanism_of(settings):
    """The mechanism of an atlas's settings: "four-bar" (also when not recorded) or "slider-crank"."""
    return settings.get("mechanism", "four-bar")


def columns_of(mechanism):
    """The linkage columns and their record class for a mechanism."""
    if mechanism == "slider-crank":
        from mech.atlas._planar._slider import SliderCrankSamples

        return _SLIDER_COLUMNS, SliderCrankSamples
    return _COLUMNS, FourBarSamples


@dataclass(frozen=True)
class Atlas:
    """Four-bars with the shape signatures of their coupler curves.

    Built by `build_atlas`, read by `Atlas.from_parquet`, searched by `query`.

    Attributes
    ----------
    linkages : FourBarSamples or SliderCrankSamples
        The linkages, one row each (normalised: ground d = 1 for four-bars, crank a = 1
        for slider-cranks).
    signatures : ndarray, shape (n, 4 * harmonics)
        The signature of each closed coupler curve (`curve_signature`).
    seeds : ndarray of int, shape (n,)
        The seed of the build that produced each row.
    settings : dict
        ``version``, ``harmonics``, ``samples`` (arc-length points per curve), ``lengths``,
        ``coupler`` and ``min_transmission`` of the builds; an atlas of slider-cranks also
        records ``mechanism`` ("slider-crank") and ``offsets``, and keeps the rod range in
        ``lengths`` (an atlas without ``mechanism`` holds four-bars).

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
    #: The folder the atlas was read from (`from_parquet`), where the open-arc index is kept.
    path: object = field(default=None, compare=False, repr=False)

    def __len__(self):
        return len(self.linkages)

    @cached_property
    def _norms(self):
        """Squared norms of the signatures (the search's brute force reuses them)."""
        return np.einsum("ij,ij->i", self.signatures, self.signatures)

    @cached_property
    def _signatures32(self):
        """The signatures in float32 (C order) and their squared norms, for the brute force."""
        sig = np.ascontiguousarray(self.signatures, dtype=np.float32)
        return sig, np.einsum("ij,ij->i", sig, sig)

    @cached_property
    def _ann(self):
        """The approximate nearest-neighbour index stored with the atlas, or None (loaded on
        first use; `query` then searches the signatures through it)."""
        from mech.atlas._planar._ann import load_index

        return load_index(self)

    @cached_property
    def _driven_cache(self):
        """The rows that satisfy a set of constraints, as a smaller atlas, by constraints (filled by `find_linkages`)."""
        return {}

    @cached_property
    def _arc_cache(self):
        """Sub-arc signatures of the curves, by (span, starts), for open targets (filled by `query`)."""
        return {}

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
        target = _next_part(path, append, self.settings, _read_settings, _check_settings)
        write_part(target, self.linkages, self.signatures, self.seeds, self.settings)
        return target

    @classmethod
    def from_parquet(cls, path):
        """Read an atlas written by `to_parquet` (every part of the folder `path`).

        Raises
        ------
        ValueError
            If `path` holds no atlas, or parts of another format version or other settings.
        """
        settings, tables = _read_parts(path, "an atlas", ATLAS_VERSION, _read_settings, _check_settings)
        names, record = columns_of(mechanism_of(settings))
        cols, sig, seeds = _table_columns(tables, names)
        width = 4 * int(settings["harmonics"])
        return cls(record(**cols), sig.reshape(-1, width), seeds, settings, Path(path))


def write_part(target, linkages, signatures, seeds, settings, chunk=None):
    """Write one Parquet part atomically (a temporary file renamed into place).

    `chunk` (the block index of a chunked build) is recorded in the part's metadata, so a
    resumed build knows which blocks are done.
    """
    import pyarrow as pa
    import pyarrow.parquet as pq

    cols = linkages.columns()
    names = tuple(cols)
    arrays = [pa.array(cols[name]) for name in names]
    arrays.append(pa.array(np.asarray(seeds).astype(np.int64)))
    width = signatures.shape[1]
    flat = pa.array(np.ascontiguousarray(signatures, dtype=np.float64).reshape(-1))
    arrays.append(pa.FixedSizeListArray.from_arrays(flat, width))
    table = pa.Table.from_arrays(arrays, names=[*names, "seed", "signature"])
    meta = {_META_KEY: json.dumps(settings).encode()}
    if chunk is not None:
        meta[_CHUNK_KEY] = json.dumps(chunk).encode()
    table = table.replace_schema_metadata(meta)
    target = Path(target)
    scratch = target.with_name(target.name + ".partial")
    pq.write_table(table, scratch)
    os.replace(scratch, target)


def _read_settings(part):
    import pyarrow.parquet as pq

    meta = pq.read_schema(part).metadata or {}
    if _META_KEY not in meta:
        raise ValueError(f"Expected `path` to hold atlas parts, got {str(part)!r} without atlas metadata")
    return json.loads(meta[_META_KEY])


def _check_settings(have, new, where):
    keys = ("version", "harmonics", "samples", "lengths", "coupler", "min_transmission", "mechanism", "offsets")
    diff = [k for k in keys if have.get(k) != new.get(k)]
    if diff:
        shown = ", ".join(f"{k}: {have.get(k)!r} vs {new.get(k)!r}" for k in diff)
        raise ValueError(f"Expected atlas parts with the same settings in `path`, got {shown} in {where!r}")


#: Folder, inside an atlas folder, of the stored open-arc indexes (window signatures).
ARC_FOLDER = "arcs"


def _arc_file(atlas, key):
    return Path(atlas.path) / ARC_FOLDER / ("arcs-" + "-".join(f"{k:g}" for k in key) + ".npz")


def load_arc_index(atlas, key):
    """The stored open-arc index `key` of an atlas read from a folder, or None (none stored,
    or stored for other rows)."""
    if atlas.path is None:
        return None
    name = _arc_file(atlas, key)
    if not name.is_file():
        return None
    try:
        with np.load(name, allow_pickle=False) as data:
            if str(data["fingerprint"]) != _fingerprint(atlas):
                return None
            return data["sigs"], data["norms"], data["gaps"]
    except (OSError, ValueError, KeyError):
        return None                   # unreadable or half-written: built again


def save_arc_index(atlas, key, arrays):
    """Store an open-arc index beside the Parquet parts (atomically; skipped where the folder
    cannot be written, the index then being built again by the next process)."""
    if atlas.path is None:
        return None
    name = _arc_file(atlas, key)
    scratch = name.with_name(name.name + ".partial")
    try:
        name.parent.mkdir(exist_ok=True)
        sigs, norms, gaps = arrays
        with open(scratch, "wb") as out:
            np.savez(out, sigs=sigs, norms=norms, gaps=gaps, fingerprint=np.array(_fingerprint(atlas)))
        os.replace(scratch, name)
    except OSError:
        return None
    return name
