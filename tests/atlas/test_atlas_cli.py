"""The command line ``python -m mech.atlas build/query`` (run in-process through ``main``)."""

import numpy as np
import pytest

pytest.importorskip("pyarrow")

from mech.atlas import Atlas  # noqa: E402
from mech.atlas.__main__ import main  # noqa: E402


def test_cli_build_append_query(tmp_path, capsys):
    folder = tmp_path / "atlas"
    assert main(["build", str(folder), "-n", "300", "--seed", "4", "--quiet"]) == 0
    assert main(["build", str(folder), "-n", "100", "--seed", "5", "--append", "--quiet"]) == 0
    atlas = Atlas.from_parquet(folder)
    assert len(atlas) == 400 and set(np.unique(atlas.seeds)) == {4, 5}
    curve = atlas.curves(42, 300)[0]
    target = 1 - 2j + 0.5 * np.exp(2j) * curve
    np.savetxt(tmp_path / "t.csv", np.c_[target.real, target.imag], delimiter=",", header="x,y", comments="")
    capsys.readouterr()
    assert main(["query", str(folder), str(tmp_path / "t.csv"), "-k", "2"]) == 0
    out = capsys.readouterr().out
    assert "#0  row 42 " in out and "AEGK" in out and "DFHK" in out


def test_cli_errors_are_messages(tmp_path, capsys):
    assert main(["query", str(tmp_path / "none"), str(tmp_path / "t.csv")]) == 2
    assert "Expected `path`" in capsys.readouterr().err
    folder = tmp_path / "a"
    assert main(["build", str(folder), "-n", "50", "--quiet"]) == 0
    assert main(["build", str(folder), "-n", "50", "--quiet"]) == 2
    assert "resume=True" in capsys.readouterr().err


def test_cli_build_resume_and_dask(tmp_path, capsys):
    """A build resumed on disk, and one on a local Dask cluster, give the atlas built in one go."""
    pytest.importorskip("distributed")
    from mech.atlas import build_atlas

    reference = build_atlas(300, seed=4, block=64)
    folder = tmp_path / "atlas"
    assert main(["build", str(folder), "-n", "300", "--seed", "4", "--block", "64", "--quiet"]) == 0
    for part in sorted(folder.glob("part-*.parquet"))[2:]:
        part.unlink()                                   # as if stopped after two blocks
    assert main(["build", str(folder), "-n", "300", "--seed", "4", "--block", "64", "--resume", "--quiet"]) == 0
    assert np.array_equal(Atlas.from_parquet(folder).signatures, reference.signatures)
    other = tmp_path / "dask"
    assert main(["build", str(other), "-n", "300", "--seed", "4", "--block", "64", "--dask", "local:2",
                 "--quiet"]) == 0
    assert np.array_equal(Atlas.from_parquet(other).signatures, reference.signatures)
    assert main(["build", str(other), "-n", "10", "--dask", "local:x", "--quiet"]) == 2
    assert "Expected --dask local:N" in capsys.readouterr().err


def test_cli_query_open_arc(tmp_path, capsys):
    folder = tmp_path / "atlas"
    assert main(["build", str(folder), "-n", "300", "--seed", "4", "--quiet"]) == 0
    from mech.atlas._planar._sampling import coupler_points

    atlas = Atlas.from_parquet(folder)
    row = int(np.flatnonzero(atlas.linkages.full_turn)[0])
    arc = coupler_points(atlas.linkages.take([row]).columns(), np.linspace(0.5, 0.5 + np.pi, 150)[None, :])[0]
    np.savetxt(tmp_path / "arc.csv", np.c_[arc.real, arc.imag], delimiter=",")
    capsys.readouterr()
    assert main(["query", str(folder), str(tmp_path / "arc.csv"), "-k", "1", "--open"]) == 0
    out = capsys.readouterr().out
    assert "curve parameter u from" in out
    # issue 28: the open-arc index is kept beside the parts, so the next process loads it
    assert (folder / "arcs" / "arcs-0.5-64.npz").is_file()
