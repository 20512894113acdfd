"""Scalar helpers at extreme finite inputs: no RuntimeWarning, no silent inf or NaN.

At 1e+-300, 1e154 and 5e-324 (the smallest subnormal) each helper either returns the true
result, computed without overflow where it is finite, or raises a ValueError naming the
arguments whose values put the result beyond the float range ("Expected `a` and `b` so
that ... is finite, got a=..., b=..."). The calls come from the registry of
`test_public_inputs.py` (valid templates), one slot changed at a time.
"""

import math
import warnings

import numpy as np
import pytest

import mech.planar as pl
import mech.spherical as sph
from test_public_inputs import CASES

# the helpers that warned (and returned inf or NaN) at these inputs before
HELPERS = [
    "planar.efficiency", "planar.efficiency_from_drive", "planar.efficiency_from_resistance",
    "planar.screw_efficiency", "planar.lead_angle", "planar.push_rod", "planar.wedge_press",
    "planar.thrust_friction_moment", "planar.collar_friction_radius", "planar.vgroove_mu",
    "planar.rolling_mill_max_thickness", "planar.slider_crank_mechanical_advantage",
    "planar.eccentric_clamp_locks", "planar.eccentric_clamp_max_angle", "planar.Polygon.lengths",
    "planar.static_forces#couples", "spherical.freudenstein_coefficients",
    "spherical.dual_fourbar_joints", "spherical.dual_fourbar_output",
    "planar.synthesis.quick_return_crank_rocker", "planar.synthesis.crank_rocker_family",
]
EXTREMES = (1e300, -1e300, 1e-300, -1e-300, 1e154, 5e-324)


def _cases():
    for key in HELPERS:
        entry = CASES[key]
        for slot in entry.slots:
            kind, wrap, shown = entry.slot(slot)
            if kind.rstrip("?") in ("real", "scalar", "realmap", "scalarmap", "tolerance"):
                for value in EXTREMES:
                    yield pytest.param(key, slot, value, id=f"{key}-{slot}={value!r}")


def _leaves(result):
    """The float arrays of a result (tuples, records, mappings, duals)."""
    if isinstance(result, (float, int, np.floating, np.ndarray)):
        yield np.asarray(result, dtype=float) if np.asarray(result).dtype.kind in "fiub" else np.zeros(0)
    elif isinstance(result, (tuple, list)):
        for r in result:
            yield from _leaves(r)
    elif isinstance(result, dict) or hasattr(result, "values") and callable(result.values):
        for r in result.values():
            yield from _leaves(r)
    elif isinstance(result, sph.Dual):
        yield np.asarray(result.real_part)
        yield np.asarray(result.dual_part)


def test_helpers_registered():
    assert all(key in CASES for key in HELPERS) and len(HELPERS) == 21


@pytest.mark.parametrize("key, slot, value", list(_cases()))
def test_helper_extreme_input_no_warning(key, slot, value):
    entry = CASES[key]
    kind, wrap, shown = entry.slot(slot)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            result = entry.call(**{slot: wrap(value)})
        except (ValueError, TypeError) as exc:
            assert "`" in str(exc), str(exc)
            return
    if key in ("planar.slider_crank_mechanical_advantage", "planar.wedge_press"):
        return          # documented infinities: the gain at a dead centre, the forward push
    for leaf in _leaves(result):
        assert not np.isinf(leaf).any(), (key, slot, value, result)


def test_finite_results_computed_without_overflow():
    """Where the true result is finite it is returned: references by scaling the unit case
    and by the limits of the formulas."""
    assert pl.collar_friction_radius(1e300) == pytest.approx(1e300 * pl.collar_friction_radius(1.0), rel=1e-15)
    assert pl.collar_friction_radius(3e300, 1e300) == pytest.approx(1e300 * pl.collar_friction_radius(3.0, 1.0),
                                                                     rel=1e-15)
    assert pl.thrust_friction_moment(2.0, 0.1, 1e300) == pytest.approx(
        1e300 * pl.thrust_friction_moment(2.0, 0.1, 1.0), rel=1e-15)
    assert pl.thrust_friction_moment(2.0, 0.0, 1.0, cone_half_angle=5e-324) == 0.0
    # h = a + D (1 - cos(atan(mu))) -> a + D as mu grows
    assert pl.rolling_mill_max_thickness(500.0, 5.0, 1e300) == 505.0
    assert pl.rolling_mill_max_thickness(500.0, 5.0, 1e154) == 505.0
    assert pl.lead_angle(1.0, 5e-324) == math.pi / 2
    # capped clamp: phi + pi/2 once r sin(phi) + rho >= e, however small e is
    for e in (5e-324, 1e-300, 0.05):
        assert pl.eccentric_clamp_max_angle(e, 1.0, 0.1, 0.1) == pytest.approx(0.1 + math.pi / 2, rel=1e-15)
    assert pl.efficiency(1e-300, 5e-324) == pytest.approx(1e-300 / 5e-324)


@pytest.mark.parametrize("call, names", [
    (lambda: pl.vgroove_mu(0.1, half_angle=5e-324), ("`mu`", "`half_angle`", "half_angle=5e-324")),
    (lambda: pl.efficiency(1.0, 5e-324), ("`useful`", "`driving`", "driving=5e-324")),
    (lambda: pl.push_rod(0.1, 1.0, 5e-324), ("`length`", "length=5e-324")),
    (lambda: pl.thrust_friction_moment(1.0, 0.1, 1.0, cone_half_angle=5e-324), ("`cone_half_angle`",)),
    (lambda: sph.freudenstein_coefficients(5e-324, 0.9, 0.7, 1.0), ("`a`", "a=5e-324")),
])
def test_overflow_raises_naming_the_arguments(call, names):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ValueError, match="so that .* is finite") as info:
            call()
    for name in names:
        assert name in str(info.value)
