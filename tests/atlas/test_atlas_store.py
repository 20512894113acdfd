"""The atlas store: build, Parquet round trip, append, settings and version checks."""

import numpy as np
import pytest

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")

from mech.atlas import ATLAS_VERSION, Atlas, build_atlas, curve_signature  # noqa: E402


@pytest.fixture(scope="module")
def small():
    return build_atlas(300, seed=7, block=256)


def test_build_atlas_keeps_usable(small):
    assert len(small) == 300 and small.signatures.shape == (300, 32)
    assert np.all(small.linkages.usable) and np.all(np.isfinite(small.signatures))
    assert np.all(small.seeds == 7)
    assert small.settings["version"] == ATLAS_VERSION and small.settings["harmonics"] == 8


def test_build_atlas_reproducible(small):
    again = build_atlas(300, seed=7, block=256)
    assert np.array_equal(again.signatures, small.signatures)
    assert not np.array_equal(build_atlas(300, seed=8, block=256).linkages.a, small.linkages.a)


def test_build_atlas_signatures_are_curve_signatures(small):
    """The stored signature is `curve_signature` of the curve the atlas draws."""
    idx = [0, 5, 99]
    assert np.allclose(curve_signature(small.curves(idx)), small.signatures[idx], rtol=0, atol=1e-12)


def test_build_atlas_min_transmission():
    atlas = build_atlas(100, seed=1, min_transmission=np.radians(35))
    assert np.all(atlas.linkages.gamma_min >= np.radians(35)) and np.all(atlas.linkages.full_turn)


def test_to_parquet_roundtrip(small, tmp_path):
    part = small.to_parquet(tmp_path / "atlas")
    assert part.name == "part-00000.parquet"
    back = Atlas.from_parquet(tmp_path / "atlas")
    assert np.array_equal(back.signatures, small.signatures)
    assert np.array_equal(back.seeds, small.seeds)
    for name, col in small.linkages.columns().items():
        assert np.array_equal(getattr(back.linkages, name), col), name
        assert getattr(back.linkages, name).dtype.kind == col.dtype.kind, name
    assert back.settings == small.settings


def test_to_parquet_append(small, tmp_path):
    small.to_parquet(tmp_path / "a")
    other = build_atlas(120, seed=9, block=256)
    assert other.to_parquet(tmp_path / "a", append=True).name == "part-00001.parquet"
    back = Atlas.from_parquet(tmp_path / "a")
    assert len(back) == 420
    assert np.array_equal(back.seeds, np.r_[np.full(300, 7), np.full(120, 9)])
    assert np.array_equal(back.signatures[300:], other.signatures)


def test_to_parquet_refuses_overwrite_and_mismatch(small, tmp_path):
    small.to_parquet(tmp_path / "a")
    with pytest.raises(ValueError, match="Expected `path` without an atlas"):
        small.to_parquet(tmp_path / "a")
    with pytest.raises(ValueError, match="harmonics: 8 vs 4"):
        build_atlas(50, harmonics=4).to_parquet(tmp_path / "a", append=True)


def test_from_parquet_version_and_missing(small, tmp_path, bump_version):
    with pytest.raises(ValueError, match="Expected `path` to be a folder holding an atlas"):
        Atlas.from_parquet(tmp_path / "none")
    part = small.to_parquet(tmp_path / "v")
    bump_version(part, b"mech.atlas")
    with pytest.raises(ValueError, match="Expected an atlas of format version"):
        Atlas.from_parquet(tmp_path / "v")
    (tmp_path / "x").mkdir()
    pq.write_table(pa.table({"a": [1.0]}), tmp_path / "x" / "part-00000.parquet")
    with pytest.raises(ValueError, match="without atlas metadata"):
        Atlas.from_parquet(tmp_path / "x")


@pytest.mark.parametrize("kwargs, message", [
    ({"n": 0}, "Expected `n`"), ({"n": 10, "block": 8}, "Expected `block`"),
    ({"n": 10, "samples": 15}, "Expected `samples` > 2"), ({"n": 10, "progress": 1}, "Expected `progress`"),
    ({"n": 10, "lengths": (1.0, 1.0)}, "Expected `lengths`"), ({"n": 10, "min_transmission": -1.0},
                                                               "Expected `min_transmission`"),
])
def test_build_atlas_bad_inputs_named(kwargs, message):
    with pytest.raises(ValueError, match=message):
        build_atlas(**kwargs)


def test_build_atlas_progress_bar(capsys):
    build_atlas(40, seed=3, progress=True)
    assert "atlas" in capsys.readouterr().err
