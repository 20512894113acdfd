"""The spherical atlas: sampled spherical four-bars with their signatures, stored as Parquet.

The layout mirrors the planar atlas (`mech.atlas.Atlas`): a folder of parts
``part-00000.parquet``, ... written by pyarrow, each holding the columns of `SphereSamples`,
the seed of the build that made it and the signature as a fixed-size list column; the schema
metadata (key ``mech.atlas.sphere``) records the format version and the build settings, so a
planar atlas folder is not read as a spherical one, nor the other way round. Appending
checks the settings; loading concatenates the parts. pyarrow is imported only to read or write.
"""

import json
import os
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from mech._validate import integer
from mech.atlas._parts import _CHUNK_KEY, _done_parts, _next_part, _read_parts, _table_columns
from mech.atlas._sphere._sampling import SphereSamples, sphere_curves

__all__ = ["SPHERE_ATLAS_VERSION", "SphereAtlas"]

#: Format version of a stored spherical atlas; another version is refused on loading.
SPHERE_ATLAS_VERSION = 1
_META_KEY = b"mech.atlas.sphere"
_COLUMNS = ("a", "b", "c", "d", "r", "gamma", "branch", "kind", "full_turn", "theta_lo", "theta_hi",
            "gamma_min", "movable", "usable")
#: Settings that must agree between the parts of one atlas.
_SETTINGS = ("version", "harmonics", "samples", "arcs", "coupler_arc", "min_transmission")


@dataclass(frozen=True)
class SphereAtlas:
    """Spherical four-bars with the signatures of their closed coupler curves.

    Built by `build_sphere_atlas`, read by `SphereAtlas.from_parquet`, searched by
    `query_sphere`.

    Attributes
    ----------
    linkages : SphereSamples
        The linkages, one row each (full-turn cranks and rocking inputs).
    signatures : ndarray, shape (n, 3 (K + 1))
        `sphere_signature` of each closed coupler curve.
    seeds : ndarray of int, shape (n,)
        The seed of the build that produced each row.
    settings : dict
        ``version``, ``harmonics``, ``samples``, ``arcs``, ``coupler_arc``,
        ``min_transmission`` and ``block`` of the build.

    Examples
    --------
    >>> import tempfile
    >>> from mech.atlas import SphereAtlas, build_sphere_atlas
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     _ = build_sphere_atlas(60, seed=1).to_parquet(folder)
    ...     _ = build_sphere_atlas(40, seed=2).to_parquet(folder, append=True)
    ...     atlas = SphereAtlas.from_parquet(folder)
    >>> len(atlas), sorted(set(atlas.seeds.tolist())), atlas.settings["version"]
    (100, [1, 2], 1)
    """

    linkages: SphereSamples
    signatures: np.ndarray
    seeds: np.ndarray
    settings: dict

    def __len__(self):
        return len(self.linkages)

    @property
    def kind(self):
        """Type of each row (`SphereSamples.kind`)."""
        return self.linkages.kind

    @property
    def harmonics(self):
        """Harmonics K of the signatures."""
        return int(self.settings["harmonics"])

    @property
    def samples(self):
        """Equal steps of length per curve used for the signatures."""
        return int(self.settings["samples"])

    @cached_property
    def _spectra(self):
        """Rotation spectra of the curves, ``|C_k|`` over the three coordinates (n, K + 1).

        Any orthonormal frame keeps ``sum_i |c_k,i|^2``, so this part of the signature does
        not depend on the principal frame at all, even where two moments are nearly equal.
        """
        return spectra(self.signatures)

    @cached_property
    def _arc_cache(self):
        """Sub-arc signatures by (span, starts), for open targets (filled by `query_sphere`)."""
        return {}

    def fourbar(self, i):
        """Row `i` as a `mech.spherical.SphericalFourBar` in its standard frame."""
        return self.linkages.fourbar(i)

    def curves(self, index, samples=None):
        """Closed coupler curves of rows `index`, shape (rows, samples, 3), at the curve
        parameter ``u = 2 pi (j + 1/2) / samples`` (the crank angle for a full turn; see
        `SphereSamples.curves`)."""
        samples = self.samples if samples is None else integer("samples", samples, minimum=4, maximum=1 << 16)
        return sphere_curves(self.linkages.take(index).columns(), samples)

    def to_parquet(self, path, *, append=False):
        """Write the atlas to the folder `path` as one new Parquet part; returns its path.

        With ``append=True`` the part is added to an existing atlas of the same settings;
        without it the folder must not hold an atlas yet.
        """
        target = _next_part(path, append, self.settings, read_settings, check_settings)
        write_part(target, self.linkages, self.signatures, self.seeds, self.settings)
        return target

    @classmethod
    def from_parquet(cls, path):
        """Read a spherical atlas written by `to_parquet` or a build with a `path`.

        Raises
        ------
        ValueError
            If `path` holds no spherical atlas, or parts of another version or settings.
        """
        settings, tables = _read_parts(path, "a spherical atlas", SPHERE_ATLAS_VERSION, read_settings,
                                       check_settings)
        cols, sig, seeds = _table_columns(tables, _COLUMNS)
        width = 3 * (int(settings["harmonics"]) + 1)
        return cls(SphereSamples(**cols), sig.reshape(-1, width), seeds, settings)


def spectra(signatures):
    """``sqrt(sum_i |c_k,i|^2)`` from signatures laid out as three blocks of K + 1 moduli."""
    sig = np.asarray(signatures)
    return np.sqrt(np.sum(sig.reshape(*sig.shape[:-1], 3, -1) ** 2, axis=-2))


def write_part(target, linkages, signatures, seeds, settings, chunk=None):
    """Write one Parquet part atomically; `chunk` (a block record) goes into its metadata."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    cols = linkages.columns()
    arrays = [pa.array(cols[name]) for name in _COLUMNS]
    arrays.append(pa.array(np.asarray(seeds).astype(np.int64)))
    flat = pa.array(np.ascontiguousarray(signatures, dtype=np.float64).reshape(-1))
    arrays.append(pa.FixedSizeListArray.from_arrays(flat, signatures.shape[1]))
    table = pa.Table.from_arrays(arrays, names=[*_COLUMNS, "seed", "signature"])
    meta = {_META_KEY: json.dumps(settings).encode()}
    if chunk is not None:
        meta[_CHUNK_KEY] = json.dumps(chunk).encode()
    target = Path(target)
    scratch = target.with_name(target.name + ".partial")
    pq.write_table(table.replace_schema_metadata(meta), scratch)
    os.replace(scratch, target)


def read_settings(part):
    """The settings recorded in a part, refusing a part that is not of a spherical atlas."""
    import pyarrow.parquet as pq

    meta = pq.read_schema(part).metadata or {}
    if _META_KEY not in meta:
        raise ValueError(f"Expected `path` to hold spherical atlas parts, got {str(part)!r} without "
                         f"spherical atlas metadata")
    return json.loads(meta[_META_KEY])


def check_settings(have, new, where):
    diff = [k for k in _SETTINGS if have.get(k) != new.get(k)]
    if diff:
        shown = ", ".join(f"{k}: {have.get(k)!r} vs {new.get(k)!r}" for k in diff)
        raise ValueError(f"Expected atlas parts with the same settings in `path`, got {shown} in {where!r}")


def done_blocks(folder, settings, build, resume):
    """The last block index on disk and its rows, checking they belong to `build` (resume)."""
    return _done_parts(folder, settings, build, resume, read_settings, check_settings)
