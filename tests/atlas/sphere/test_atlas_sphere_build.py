"""The spherical atlas: Parquet store (version, seeds, append), builds in blocks, on Dask, resumed."""

import json

import numpy as np
import pytest

pa = pytest.importorskip("pyarrow")
import pyarrow.parquet as pq  # noqa: E402

import mech.atlas._sphere._build as build_module  # noqa: E402
from mech.atlas import SPHERE_ATLAS_VERSION, SphereAtlas, build_atlas, build_sphere_atlas, sphere_signature  # noqa: E402

SETTINGS = {"seed": 13, "block": 128, "harmonics": 6, "samples": 64}


@pytest.fixture(scope="module")
def reference():
    return build_sphere_atlas(500, **SETTINGS)


def test_build_keeps_usable_rocking_too(reference):
    s = reference.linkages
    assert len(reference) == 500 and np.all(s.usable) and np.all(s.movable)
    assert s.full_turn.any() and (~s.full_turn).any()          # rocking inputs are in the atlas
    assert set(np.unique(s.kind)) >= {"crank-rocker", "triple-rocker"}
    assert reference.settings["version"] == SPHERE_ATLAS_VERSION and np.all(reference.seeds == 13)


def test_build_signatures_are_sphere_signatures(reference):
    """The stored signature of a row is `sphere_signature` of its curve, from a denser polyline."""
    idx = [0, 7, 123]
    again = sphere_signature(reference.curves(idx, 4096), harmonics=6, samples=64)
    assert np.max(np.abs(again - reference.signatures[idx])) < 2e-3
    assert np.max(np.abs(again - reference.signatures[idx])) > 0.0       # not the same code path


def test_build_dask_identical(reference, client, same_atlas):
    """Two Dask workers give the atlas of one process, bit for bit."""
    assert len(client.nthreads()) == 2
    same_atlas(reference, build_sphere_atlas(500, **SETTINGS, client=client))


def test_build_dask_to_folder_identical(reference, client, tmp_path, same_atlas):
    same_atlas(reference, build_sphere_atlas(500, **SETTINGS, client=client, path=tmp_path / "a"))


@pytest.mark.parametrize("stop_after", [1, 2])
def test_build_resume_after_interrupt(reference, tmp_path, monkeypatch, stop_after, same_atlas):
    written = []
    real = build_module.write_part

    def interrupting(*args, **kwargs):
        if len(written) == stop_after:
            raise KeyboardInterrupt
        real(*args, **kwargs)
        written.append(args[0])

    monkeypatch.setattr(build_module, "write_part", interrupting)
    with pytest.raises(KeyboardInterrupt):
        build_sphere_atlas(500, **SETTINGS, path=tmp_path / "a")
    assert len(list((tmp_path / "a").glob("part-*.parquet"))) == stop_after
    monkeypatch.setattr(build_module, "write_part", real)
    resumed = []
    monkeypatch.setattr(build_module, "build_sphere_block",
                        lambda *a, _b=build_module.build_sphere_block: resumed.append(a[1]) or _b(*a))
    same_atlas(reference, build_sphere_atlas(500, **SETTINGS, path=tmp_path / "a", resume=True))
    assert min(resumed) == stop_after


def test_build_resume_refuses_other_build(tmp_path):
    build_sphere_atlas(40, seed=1, path=tmp_path / "a")
    with pytest.raises(ValueError, match="resume=True"):
        build_sphere_atlas(40, seed=1, path=tmp_path / "a")
    with pytest.raises(ValueError, match="Expected the parts of a build"):
        build_sphere_atlas(40, seed=2, path=tmp_path / "a", resume=True)
    with pytest.raises(ValueError, match="same settings"):
        build_sphere_atlas(40, seed=1, harmonics=4, path=tmp_path / "a", resume=True)


def test_parquet_roundtrip_and_append(reference, tmp_path):
    reference.to_parquet(tmp_path / "s")
    other = build_sphere_atlas(60, **{**SETTINGS, "seed": 14})
    other.to_parquet(tmp_path / "s", append=True)
    back = SphereAtlas.from_parquet(tmp_path / "s")
    assert len(back) == 560 and sorted(set(back.seeds.tolist())) == [13, 14]
    assert np.array_equal(back.signatures[:500], reference.signatures)
    assert np.array_equal(back.linkages.kind[500:], other.linkages.kind)
    part = sorted((tmp_path / "s").glob("part-*.parquet"))[0]
    assert json.loads(pq.read_schema(part).metadata[b"mech.atlas.sphere"])["version"] == 1
    with pytest.raises(ValueError, match="append=True"):
        reference.to_parquet(tmp_path / "s")
    with pytest.raises(ValueError, match="same settings"):
        build_sphere_atlas(20, seed=3, harmonics=4).to_parquet(tmp_path / "s", append=True)


def test_parquet_refuses_planar_version_and_empty(reference, tmp_path, bump_version):
    build_atlas(30, seed=1).to_parquet(tmp_path / "planar")
    with pytest.raises(ValueError, match="without spherical atlas metadata"):
        SphereAtlas.from_parquet(tmp_path / "planar")
    with pytest.raises(ValueError, match="holding a spherical atlas"):
        SphereAtlas.from_parquet(tmp_path / "none")
    part = reference.to_parquet(tmp_path / "v")
    bump_version(part, b"mech.atlas.sphere")
    with pytest.raises(ValueError, match="format version"):
        SphereAtlas.from_parquet(tmp_path / "v")


def test_build_progress_bar_and_bad_inputs(capsys):
    build_sphere_atlas(30, seed=3, progress=True)
    assert "atlas" in capsys.readouterr().err
    with pytest.raises(TypeError, match="Expected `client`"):
        build_sphere_atlas(10, client="tcp://localhost:8786")
    with pytest.raises(ValueError, match="Expected a `path`"):
        build_sphere_atlas(10, resume=True)
    with pytest.raises(ValueError, match="Expected `block`"):
        build_sphere_atlas(10, block=4)
