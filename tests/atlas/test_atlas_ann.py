"""The stored approximate nearest-neighbour index (issue 28, item 1): built once, loaded (not
rebuilt) by a new load of the atlas folder, refused for other rows, and finding the exact
nearest signature among its first 10 answers; without it the search is exact."""

import numpy as np
import pytest

from mech.atlas import Atlas, build_atlas, query, sample_fourbars

faiss = pytest.importorskip("faiss")

from mech.atlas._planar import _ann  # noqa: E402
from mech.atlas._planar._sampling import coupler_curves  # noqa: E402
from mech.atlas._planar._search import _nearest  # noqa: E402
from mech.atlas._planar._signature import _resample_rows, normal_form  # noqa: E402


@pytest.fixture(scope="module")
def stored(tmp_path_factory):
    folder = tmp_path_factory.mktemp("ann") / "atlas"
    atlas = build_atlas(1200, seed=4, path=folder, block=1024)
    _ann.build_index(atlas)
    return folder


def _forms(atlas, count):
    """Normal forms of curves of linkages drawn apart from the atlas (another seed)."""
    s = sample_fourbars(4 * count, seed=77)
    s = s.take(s.usable)
    curves = coupler_curves(s.columns(), atlas.samples)
    curves = curves[np.all(np.isfinite(curves), axis=1)][:count]
    return normal_form(_resample_rows(curves, atlas.samples, True), atlas.harmonics).candidates


def test_index_is_stored_and_loaded_not_rebuilt(stored, monkeypatch):
    assert (stored / "ann" / "hnsw.faiss").is_file()
    atlas = Atlas.from_parquet(stored)
    monkeypatch.setattr(_ann, "build_index", None)        # a rebuild would fail here
    index = atlas._ann
    assert index is not None and len(index) == len(atlas)


def test_index_of_other_rows_is_refused(stored, tmp_path):
    atlas = Atlas.from_parquet(stored)
    other = build_atlas(300, seed=5, path=tmp_path / "other")
    (tmp_path / "other" / "ann").mkdir()
    for name in ("hnsw.faiss", "hnsw.faiss.json"):
        (tmp_path / "other" / "ann" / name).write_bytes((stored / "ann" / name).read_bytes())
    assert Atlas.from_parquet(tmp_path / "other")._ann is None and other._ann is None
    assert atlas._ann is not None


def test_recall_of_the_exact_nearest_within_ten(stored):
    """The exact nearest row (by a plain float64 distance to the nearest normal form, not the
    search's float32 scores) is among the index's first 10 answers for >= 99 % of targets."""
    atlas = Atlas.from_parquet(stored)
    forms = _forms(atlas, 100)
    sig = atlas.signatures
    hits = 0
    for c in forms:
        d2 = np.min([np.sum((sig - row) ** 2, axis=1) for row in c], axis=0)
        hits += int(np.argmin(d2)) in set(atlas._ann.search(c, 10).tolist())
    assert hits >= 0.99 * len(forms)


def test_query_through_the_index_matches_the_exact_one(stored):
    atlas = Atlas.from_parquet(stored)
    fresh = Atlas.from_parquet(stored)
    fresh.__dict__["_ann"] = None                          # the exact search
    for i in (3, 500, 1100):
        target = 2 - 1j + 4 * np.exp(0.7j) * atlas.curves(i)[0]
        got, want = query(atlas, target, k=3, shortlist=16), query(fresh, target, k=3, shortlist=16)
        assert got[0].index == want[0].index == i
        assert [m.index for m in got] == [m.index for m in want]


def test_exact_flag_and_short_list(stored):
    atlas = Atlas.from_parquet(stored)
    c = _forms(atlas, 1)[0]
    exact = set(_nearest(atlas, c, 32, exact=True).tolist())
    approx = set(_nearest(atlas, c, 32, exact=False).tolist())
    assert len(approx) == 32 and len(exact & approx) >= 28
