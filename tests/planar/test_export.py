"""Designs written as JSON, SVG and DXF (mech.planar.export), and targets read from SVG (issue 28, item 4).

The DXF is read back by ezdxf, the SVG by an XML parser and by svgelements; hole centres
are compared with the pins computed by `FourBar.solve` (or the linkage's own solve), and
the smallest transmission angle with a dense sampling of the solved poses, a different
route from the closed form the export uses.
"""

import json
import math
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from mech.planar import FourBar, SliderCrank
from mech.planar.export import design_of, from_json, read_json, svg_text, to_json, write_dxf, write_json, write_svg
from mech.planar.special import stephenson_six_bar, watt_six_bar

ezdxf = pytest.importorskip("ezdxf")
pytest.importorskip("svgelements")

LINKAGES = {
    "crank-rocker": lambda: FourBar(30, 70, 60, 80, coupler=(20, 10)),
    "rocker-crank": lambda: FourBar(60, 70, 30, 80, branch=-1, coupler=(35, -15)),
    "triple-rocker": lambda: FourBar(50, 40, 45, 60, coupler=(5, 20)),
    "slider-crank": lambda: SliderCrank(30, 100, 20),
    "watt": watt_six_bar,
    "stephenson": stephenson_six_bar,
}


@pytest.fixture(params=sorted(LINKAGES))
def design(request):
    return design_of(LINKAGES[request.param](), units="mm")


# -------------------------------------------------------------------------------- DXF
def test_dxf_read_back(design, tmp_path):
    path = tmp_path / "links.dxf"
    w, h = write_dxf(design, path, link_width=0.1 * design.size, hole_diameter=0.04 * design.size)
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    layers = {layer.dxf.name for layer in doc.layers} - {"0", "Defpoints"} - {"guide"}
    assert layers == set(design.links)
    tol = 1e-9 * design.size
    holes = 0
    for name, pins in design.links.items():
        circles = msp.query(f'CIRCLE[layer=="{name}"]')
        assert len(circles) == len(pins)
        holes += len(circles)
        for circle, pin in zip(circles, pins):
            centre = complex(circle.dxf.center.x, circle.dxf.center.y)
            assert abs(centre - design.joints[pin]) <= tol
            assert circle.dxf.radius == pytest.approx(0.5 * h, rel=1e-12)
        outline = msp.query(f'LWPOLYLINE[layer=="{name}"]')
        assert len(outline) == 1 and outline[0].closed
        # every vertex of the outline lies half a width from the nearest pin of its link
        z = np.array([complex(x, y) for x, y, *_ in outline[0].get_points("xyb")])
        pinz = np.array([design.joints[p] for p in pins])
        nearest = np.min(np.abs(z[:, None] - pinz[None, :]), axis=1)
        if name == "slider":
            assert np.all(nearest >= 0.5 * w - tol)
        else:
            assert np.allclose(nearest, 0.5 * w, rtol=0, atol=tol)
    assert holes == sum(len(p) for p in design.links.values())
    assert float(doc.header.custom_vars.get("link_width")) == w
    assert doc.header["$INSUNITS"] == 4                     # millimetres


def test_dxf_holes_are_the_solved_pins(tmp_path):
    """Hole centres against FourBar.solve, placed by hand: an independent route to the pins."""
    f = FourBar(30, 70, 60, 80, coupler=(20, 10))
    d = design_of(f, theta=0.7)
    write_dxf(d, tmp_path / "fb.dxf")
    pose = f.solve(0.7)
    expected = {"crank": [0, pose.B], "coupler": [pose.B, pose.C, pose.P], "rocker": [80, pose.C], "frame": [0, 80]}
    msp = ezdxf.readfile(tmp_path / "fb.dxf").modelspace()
    for layer, pins in expected.items():
        got = list(complex(c.dxf.center.x, c.dxf.center.y) for c in msp.query(f'CIRCLE[layer=="{layer}"]'))
        got = np.array(sorted(got, key=lambda z: (z.real, z.imag)))
        want = np.array(sorted(map(complex, pins), key=lambda z: (z.real, z.imag)))
        assert np.max(np.abs(got - want)) <= 1e-9 * 80


def test_dxf_bad_cutting_sizes(tmp_path):
    d = design_of(FourBar(30, 70, 60, 80))
    with pytest.raises(ValueError, match="hole_diameter"):
        write_dxf(d, tmp_path / "x.dxf", link_width=4, hole_diameter=5)
    with pytest.raises(ValueError, match="link_width"):
        write_dxf(d, tmp_path / "x.dxf", link_width=float("nan"))
    with pytest.raises(TypeError, match="design"):
        write_dxf(FourBar(30, 70, 60, 80), tmp_path / "x.dxf")


# -------------------------------------------------------------------------------- SVG
def test_svg_parses(design, tmp_path):
    write_svg(design, tmp_path / "d.svg")
    root = ET.parse(tmp_path / "d.svg").getroot()
    ns = {"s": "http://www.w3.org/2000/svg"}
    circles = root.findall(".//s:g[@id='holes']/s:circle", ns)
    assert {c.get("id") for c in circles} == {f"pin-{n}" for n in design.joints}
    for c in circles:
        z = design.joints[c.get("id")[4:]]
        assert float(c.get("cx")) == pytest.approx(z.real, abs=1e-9 * design.size)
        assert float(c.get("cy")) == pytest.approx(-z.imag, abs=1e-9 * design.size)   # y down in SVG
    assert {p.get("id") for p in root.findall(".//s:g[@id='links']/s:path", ns)} == {f"link-{n}" for n in design.links}


def test_svg_coupler_curve_reads_back(tmp_path):
    """The drawn coupler curve, read by read_svg (svgelements), lies on the solved curve."""
    from mech.atlas import read_svg

    f = FourBar(30, 70, 60, 80, coupler=(20, 10))
    write_svg(design_of(f), tmp_path / "d.svg")
    z, closed = read_svg(tmp_path / "d.svg", element="coupler-curve", samples=300)
    dense = f.solve(np.linspace(0, 2 * np.pi, 20001)).P
    # the reference is sampled 0.015 apart along the curve, so a point between samples is up to 0.008 off
    assert np.max(np.min(np.abs(z[:, None] - dense[None, :]), axis=1)) < 1e-2


# ------------------------------------------------------------------------------- JSON
def test_json_round_trip(design, tmp_path):
    write_json(design, tmp_path / "d.json", link_width=3.0)
    again = read_json(tmp_path / "d.json")
    assert again == design
    data = json.loads((tmp_path / "d.json").read_text())
    assert data["units"] == "mm" and data["cutting"]["link_width"] == 3.0
    assert data["motor"]["joint"] in data["fixed"]
    theta = np.linspace(0, 2 * np.pi, 50)
    a, b = design.linkage().solve(theta), again.linkage().solve(theta)
    assert np.array_equal(a.valid, b.valid)


def test_json_rejects_other_text():
    with pytest.raises(ValueError, match="to_json"):
        from_json('{"format": "other"}')
    with pytest.raises(TypeError, match="text"):
        from_json(3)


# -------------------------------------------------------------- motor and transmission
def _sampled_gamma(f, at):
    """Smallest folded angle at C (driven at A) or at B (driven at D), from solved positions."""
    theta = np.linspace(-np.pi, np.pi, 200001)
    gam = []
    for branch in (1, -1):
        s = FourBar(f.a, f.b, f.c, f.d, branch=branch).solve(theta)
        A, D = 0, f.d
        B, C = s.B[s.valid], s.C[s.valid]
        u, v = (B - C, D - C) if at == "A" else (A - B, C - B)
        g = np.abs(np.angle(u * np.conj(v)))
        gam.append(np.min(np.minimum(g, np.pi - g)))
        if at == "A":
            break            # a crank at A sweeps every pose on one branch
    return min(gam)


@pytest.mark.parametrize("lengths, motor", [((30, 70, 60, 80), "A"), ((60, 70, 30, 80), "D"),
                                            ((20, 60, 50, 55), "A"), ((45, 30, 25, 50), "D")])
def test_motor_and_transmission(lengths, motor):
    f = FourBar(*lengths)
    d = design_of(f)
    assert d.motor == motor and d.full_turn
    assert set(d.links[d.driven]) >= {motor}
    assert d.gamma_min == pytest.approx(_sampled_gamma(f, motor), abs=1e-6)


def test_slider_crank_transmission():
    d = design_of(SliderCrank(30, 100, 20))
    theta = np.linspace(-np.pi, np.pi, 200001)
    assert d.gamma_min == pytest.approx(float(np.min(SliderCrank(30, 100, 20).transmission_angle(theta))), abs=1e-8)
    assert math.degrees(d.gamma_min) == pytest.approx(60.0, abs=1e-12)     # cos = (30 + 20)/100


# ------------------------------------------------------------------ synthesis results
def test_synthesis_results_export(tmp_path):
    from mech.planar.synthesis import (centric_slider_cranks, guidance_fourbars, path_timed,
                                       quick_return_crank_rocker, quick_return_slider_crank)

    P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j]
    theta = np.radians([0.0, 8.88, 22.1, 63.68, -3.0])
    g = guidance_fourbars(theta, P).passing[0]
    d = design_of(g, theta=float(g.theta_input[0]))
    assert abs(d.joints["A"] - g.input_dyad.centre_point) < 1e-9 * d.size
    assert abs(d.joints["D"] - g.output_dyad.centre_point) < 1e-9 * d.size
    assert abs(d.joints["B"] - g.to_ground(g.linkage.solve(g.theta_input[0]).B)) < 1e-9 * d.size
    pts = [12.42, 7.98 + 1.89j, 0.76 + 1.47j, 1.30 - 0.85j, 8.83 + 0.3j]
    k = path_timed(pts, np.radians([4.2, 64.87, 145.82, 219.24, 303.45])).candidates[0]
    d = design_of(k, theta=float(k.theta_input[0]))
    assert max(abs(d.joints[n] - getattr(k, m)) for n, m in (("A", "A"), ("B", "B1"), ("C", "C1"), ("D", "D"))) \
        < 1e-9 * d.size
    assert abs(d.joints["P"] - pts[0]) < 1e-6 * d.size
    c = centric_slider_cranks(theta[:4], P[:4])[0]
    d = design_of(c, theta=float(c.theta_input[0]))
    assert d.type == "slider-crank" and abs(d.joints["A"] - c.origin) < 1e-12 * d.size
    # the same slider-crank built as a Linkage (crank and RRP group): sampled against closed form
    g = design_of(c.guidance)
    assert g.type == "slider-crank linkage" and g.links["block"] == ("C",)
    assert g.gamma_min == pytest.approx(d.gamma_min, abs=1e-5)
    assert abs((g.guide[0] - d.guide[0]) / d.guide[1]).imag < 1e-9 * d.size     # one guide line
    assert from_json(to_json(g)) == g
    write_dxf(g, tmp_path / "g.dxf")
    block = ezdxf.readfile(tmp_path / "g.dxf").modelspace().query('LWPOLYLINE[layer=="block"]')
    assert len(block) == 1 and len(block[0]) == 4
    for obj in (quick_return_crank_rocker(1.3, 100.0, np.radians(40.0), crank=31.4),
                quick_return_slider_crank(1.25, 100.0, alpha=np.radians(25.0))):
        d = design_of(obj)
        assert from_json(to_json(d)) == d and d.full_turn
        write_dxf(d, tmp_path / "q.dxf")
        write_svg(d, tmp_path / "q.svg")


def test_design_of_bad_input():
    with pytest.raises(TypeError, match="FourBar"):
        design_of("ABCD")
    with pytest.raises(TypeError, match="units"):
        design_of(FourBar(30, 70, 60, 80), units=4)
    with pytest.raises(ValueError, match="theta"):
        design_of(FourBar(50, 40, 45, 60), theta=0.0 + 3.0)     # a triple-rocker outside its range


def test_import_mech_does_not_load_ezdxf():
    probe = ("import mech, mech.planar.export, mech.atlas, sys; "
             "print(sorted({'ezdxf', 'svgelements'} & {m.split('.')[0] for m in sys.modules}))")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True, timeout=120)
    assert out.stdout.strip() == "[]"


# ------------------------------------------------------------------------ SVG targets
def _write(tmp_path, body, name="t.svg"):
    path = tmp_path / name
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200">{body}</svg>')
    return path


def test_read_svg_circle_with_transform(tmp_path):
    from mech.atlas import read_svg

    # a circle of radius 30 about (50, 40) drawn with two arcs, moved by (10, 5)
    path = _write(tmp_path, '<g transform="translate(10 5)"><path d="M 80 40 A 30 30 0 0 1 20 40 '
                            'A 30 30 0 0 1 80 40 Z"/></g>')
    z, closed = read_svg(path, samples=200)
    assert closed and z.shape == (200,)
    assert np.allclose(np.abs(z - (60 - 45j)), 30, atol=1e-6)              # y flipped
    step = np.abs(np.diff(np.append(z, z[0])))
    assert np.ptp(step) < 1e-4 * step.mean()                              # uniform in arc length


def test_read_svg_open_polyline(tmp_path):
    from mech.atlas import read_svg, read_target

    path = _write(tmp_path, '<path id="arc" d="M 0 0 L 30 0 L 30 40"/><rect id="frame" x="0" y="0" width="5" height="5"/>')
    z, closed = read_svg(path, samples=71)
    assert not closed
    assert z[0] == 0 and abs(z[-1] - (30 - 40j)) < 1e-12
    assert np.allclose(np.abs(np.diff(z)), 1.0, atol=1e-9)                # 70 steps over 70 units
    assert read_target(path, samples=71)[1] is False
    with pytest.raises(ValueError, match="element"):
        read_svg(path, element="none")


def test_read_svg_bad_files(tmp_path):
    from mech.atlas import read_svg

    two = _write(tmp_path, '<path d="M 0 0 L 1 0"/><path d="M 0 5 L 1 5"/>')
    with pytest.raises(ValueError, match="one path"):
        read_svg(two)
    strokes = _write(tmp_path, '<path d="M 0 0 L 1 0 M 0 5 L 1 5"/>', "s.svg")
    with pytest.raises(ValueError, match="one stroke"):
        read_svg(strokes)
    with pytest.raises(ValueError, match="readable SVG"):
        read_svg(tmp_path / "missing.svg")
    with pytest.raises(TypeError, match="path"):
        read_svg(3)
