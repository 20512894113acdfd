"""`python -m mech.atlas query --target FILE.svg|FILE.csv` with --json, --svg and --dxf (issue 28, item 4)."""

import numpy as np
import pytest

from mech.atlas.__main__ import main
from mech.planar import FourBar

ezdxf = pytest.importorskip("ezdxf")
pytest.importorskip("svgelements")


def _svg(path, z, closed):
    d = "M " + " L ".join(f"{p.real:.12g},{-p.imag:.12g}" for p in z) + (" Z" if closed else "")
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="-200 -200 400 400"><path d="{d}"/></svg>')
    return path


@pytest.fixture(scope="module")
def atlas(tmp_path_factory):
    folder = tmp_path_factory.mktemp("atlas") / "a"
    assert main(["build", str(folder), "-n", "400", "--seed", "3", "--quiet"]) == 0
    return folder


def test_query_svg_target_writes_files(atlas, tmp_path, capsys):
    from mech.planar.export import read_json

    curve = FourBar(30, 70, 60, 80, coupler=(20, 10)).solve(np.linspace(0, 2 * np.pi, 200, endpoint=False)).P
    target = _svg(tmp_path / "drawn.svg", curve, closed=True)
    out = [tmp_path / n for n in ("best.json", "best.svg", "best.dxf")]
    assert main(["query", str(atlas), "--target", str(target), "-k", "2", "--units", "mm",
                 "--json", str(out[0]), "--svg", str(out[1]), "--dxf", str(out[2])]) == 0
    text = capsys.readouterr().out
    assert "closed curve of 256 points" in text
    assert text.count("minimum transmission angle") == 2 and "motor at" in text
    design = read_json(out[0])
    assert design.units == "mm" and design.type == "four-bar"
    # the printed best linkage is the one written: its lengths appear in the first match's line
    assert f"a={design.spec['a']:.5g}" in text.split("#1")[0]
    layers = {layer.dxf.name for layer in ezdxf.readfile(out[2]).layers}
    assert set(design.links) <= layers
    assert out[1].read_text().startswith("<svg")


def test_query_open_svg_and_csv_targets(atlas, tmp_path, capsys):
    curve = FourBar(30, 70, 60, 80, coupler=(20, 10)).solve(np.linspace(0, 2.5, 60)).P
    assert main(["query", str(atlas), "--target", str(_svg(tmp_path / "arc.svg", curve, closed=False)), "-k", "1"]) == 0
    assert "open arc" in capsys.readouterr().out
    csv = tmp_path / "t.csv"
    csv.write_text("x,y\n" + "\n".join(f"{p.real},{p.imag}" for p in curve))
    assert main(["query", str(atlas), "--target", str(csv), "--open", "-k", "1"]) == 0
    assert "open arc of 60 points" in capsys.readouterr().out


def test_query_needs_one_target(atlas, tmp_path, capsys):
    assert main(["query", str(atlas)]) == 2
    assert "one target file" in capsys.readouterr().err
