"""figures.live: what a live figure writes at build time (controls, first read-out, spec)."""

import doctest
import json
import re

import numpy as np
import pytest

import figures.live as live
from figures.animate import animate, view3d


def test_doctests():
    assert doctest.testmod(live, optionflags=doctest.NORMALIZE_WHITESPACE).failed == 0


def _data(html):
    return json.loads(re.search(r'class="mech-data">(.*?)</script>', html).group(1).replace("<\\/", "</"))


def test_fourbar_player_carries_spec_controls_and_readout():
    theta = np.radians(np.arange(0.0, 360.0, 30.0))
    spec = live.fourbar(10, 40, 30, 35, theta, couplers={"P": (20, 10)})
    out = animate({"A": 0, "D": 35, "B": 10 * np.exp(1j * theta), "P": 0}, [("A", "B")], live=spec).data
    d = _data(out)
    assert d["live"]["type"] == "fourbar" and len(d["live"]["theta"]) == theta.size and d["live"]["curve"] == 720
    for key in "abcdpq":
        assert f'type="number" data-k="{key}"' in out and f'type="range" data-k="{key}"' in out
    assert 'class="mech-branch">branch +1<' in out
    # the read-out by an independent route: the limit positions from the crank-rocker's triangles
    a, b, c, d = 10, 40, 30, 35
    th_ext = np.arccos(((a + b) ** 2 + d * d - c * c) / (2 * (a + b) * d))   # A B C in line, extended
    th_fold = np.arccos(((b - a) ** 2 + d * d - c * c) / (2 * (b - a) * d))  # folded: B on the far side
    assert f"limit positions θ = {np.degrees(th_ext):.1f}°, −{180 - np.degrees(th_fold):.1f}°" in out
    gamma0 = np.arccos((b * b + c * c - (d - a) ** 2) / (2 * b * c))     # at theta = 0, BD = d - a
    assert f"smallest transmission angle {np.degrees(gamma0):.1f}° at θ = 0.0°" in out


def test_none_says_why_and_loads_nothing():
    out = view3d({"P": [0.0, 0.0, 1.0]}, live=live.none("six-bar linkages")).data
    assert "the page cannot solve six-bar linkages yet" in out
    assert _data(out)["live"]["type"] == "none"


def test_spherical_readout_and_names():
    from mech.spherical import SphericalFourBar

    spec = live.spherical_fourbar(SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.5)), [0.0], curve=True)
    assert spec["drawCurve"] and spec["names"] == list("ABCDP")
    text = live.readout(spec)
    assert text["kind"] == "crank-rocker" and text["limits"] == "the input turns fully"


def test_bad_input_is_refused_with_the_argument_named():
    with pytest.raises(ValueError, match="`branch`"):
        live.fourbar(10, 40, 30, 35, [0.0], branch=2)
    with pytest.raises(ValueError, match="`theta`"):
        live.slider_crank(30, 100, 20, [np.nan])
    with pytest.raises(ValueError, match="`a` < `d`"):
        live.guide_bar(400, 300, [0.0])


def test_step_built_linkage_spec_and_readout():
    """figures.live_chains: the Watt six-bar's fields are its five lengths; its smallest
    transmission angle is at C, where the first loop (20, 50, 45, 50) has it by the law of
    cosines with BD = d - a = 30."""
    from mech.planar import watt_six_bar

    spec = live.linkage(watt_six_bar(), np.radians([0.0, 90.0]))
    assert [f[2] for f in spec["fields"]] == [20.0, 50.0, 45.0, 24.0, 18.0]
    gamma = np.degrees(np.arccos((50.0 ** 2 + 45.0 ** 2 - 30.0 ** 2) / (2 * 50.0 * 45.0)))
    assert live.readout(spec)["transmission"].startswith(f"smallest transmission angle {gamma:.1f}° (joints C, G;")
    out = animate({"A": 0, "B": 20 * np.exp(1j * np.radians([0.0, 90.0]))}, [("A", "B")], live=spec).data
    assert 'type="range" data-k="L4"' in out and 'class="mech-branch"' in out


def test_step_built_bad_input_is_refused():
    with pytest.raises(ValueError, match="`sweep`"):
        live.open_chain(0.4, 0.08, np.zeros((3, 3)))
    with pytest.raises(ValueError, match="`theta`"):
        live.rssr(dict(l1=1.0, l2=4.0, l3=2.0, s0=0.5, s3=0.8, h0=3.0, lam=1.0), [np.inf])
