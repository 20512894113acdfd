"""Building an atlas in blocks: on a Dask cluster, to a folder, stopped and resumed."""

import pytest

pytest.importorskip("pyarrow")

import mech.atlas._planar._build as build_module  # noqa: E402
from mech.atlas import Atlas, build_atlas  # noqa: E402

SETTINGS = {"seed": 11, "block": 128, "harmonics": 6, "samples": 64}


@pytest.fixture(scope="module")
def reference():
    """The build in this process that the others must reproduce bit for bit."""
    return build_atlas(700, **SETTINGS)


def test_build_atlas_dask_identical(reference, client, same_atlas):
    """Two Dask workers give the same atlas, bit for bit, as one process (same seed)."""
    assert len(client.nthreads()) == 2
    same_atlas(reference, build_atlas(700, **SETTINGS, client=client))


def test_build_atlas_dask_to_folder_identical(reference, client, tmp_path, same_atlas):
    same_atlas(reference, build_atlas(700, **SETTINGS, client=client, path=tmp_path / "a"))


def test_build_atlas_block_seeds_differ():
    """Block seeds come from the master seed and the block index, all different."""
    seeds = {build_module.block_seed(s, i) for s in range(3) for i in range(100)}
    assert len(seeds) == 300


def test_build_atlas_path_parts(reference, tmp_path, same_atlas):
    atlas = build_atlas(700, **SETTINGS, path=tmp_path / "a")
    same_atlas(reference, atlas)
    parts = sorted((tmp_path / "a").glob("part-*.parquet"))
    assert len(parts) >= 2
    same_atlas(reference, Atlas.from_parquet(tmp_path / "a"))


@pytest.mark.parametrize("stop_after", [1, 3])
def test_build_atlas_resume_after_interrupt(reference, tmp_path, monkeypatch, stop_after, same_atlas):
    """A build stopped after k parts and resumed gives the uninterrupted build."""
    written = []
    real = build_module.write_part

    def interrupting(*args, **kwargs):
        if len(written) == stop_after:
            raise KeyboardInterrupt
        real(*args, **kwargs)
        written.append(args[0])

    monkeypatch.setattr(build_module, "write_part", interrupting)
    with pytest.raises(KeyboardInterrupt):
        build_atlas(700, **SETTINGS, path=tmp_path / "a")
    assert len(list((tmp_path / "a").glob("part-*.parquet"))) == stop_after
    assert len(Atlas.from_parquet(tmp_path / "a")) < 700
    monkeypatch.setattr(build_module, "write_part", real)
    resumed = []
    monkeypatch.setattr(build_module, "build_block",
                        lambda *a, _b=build_module.build_block: resumed.append(a[1]) or _b(*a))
    same_atlas(reference, build_atlas(700, **SETTINGS, path=tmp_path / "a", resume=True))
    assert min(resumed) == stop_after           # the blocks on disk were not drawn again


def test_build_atlas_resume_finished_is_a_read(reference, tmp_path, monkeypatch, same_atlas):
    build_atlas(700, **SETTINGS, path=tmp_path / "a")
    monkeypatch.setattr(build_module, "build_block", None)     # nothing may be computed
    same_atlas(reference, build_atlas(700, **SETTINGS, path=tmp_path / "a", resume=True))


def test_build_atlas_path_refuses_existing(tmp_path):
    build_atlas(50, seed=1, path=tmp_path / "a")
    with pytest.raises(ValueError, match="resume=True"):
        build_atlas(50, seed=1, path=tmp_path / "a")


def test_build_atlas_resume_refuses_other_build(tmp_path):
    build_atlas(50, seed=1, path=tmp_path / "a")
    with pytest.raises(ValueError, match="Expected the parts of a build"):
        build_atlas(50, seed=2, path=tmp_path / "a", resume=True)
    with pytest.raises(ValueError, match="Expected atlas parts with the same settings"):
        build_atlas(50, seed=1, harmonics=4, path=tmp_path / "a", resume=True)
    build_atlas(30, seed=1).to_parquet(tmp_path / "b")
    with pytest.raises(ValueError, match="Expected the parts of a build"):
        build_atlas(30, seed=1, path=tmp_path / "b", resume=True)


def test_build_atlas_bad_client_and_resume():
    with pytest.raises(TypeError, match="Expected `client`"):
        build_atlas(10, client="tcp://localhost:8786")
    with pytest.raises(ValueError, match="Expected a `path`"):
        build_atlas(10, resume=True)
