"""`Linkage` does not depend on the unit of length, from 1e-300 to 1e300.

Every length, ground point, guide point, offset and distance input is multiplied by a scale
s; the angles, angular rates and `valid` must stay the same, and positions, linear rates
and slides must scale by s. The unscaled solution is the reference, itself checked against
mpmath in ``test_linkage.py`` and ``test_linkage_branches.py``. No scale may overflow,
underflow to a wrong value, or warn (pytest turns warnings into errors).
"""

import math

import numpy as np
import pytest

from mech import AssemblyError
from mech.planar import Guide, Linkage

SCALES = [1e-300, 1e-200, 1e-160, 1e-150, 1e-110, 1e-50, 1.0, 1e50, 1e110, 1e160, 1e200, 1e300]
THETA = np.linspace(-7.0, 7.0, 2001)


def fourbar(s):
    """Example 2-1 as a crank and an RRR group."""
    return (Linkage({"A": 0, "D": 35 * s}).crank("crank", pivot="A", tip="B", length=10 * s)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(40 * s, 30 * s))
            .point("P", link="coupler", at=(20 + 10j) * s))


def parallelogram(s):
    """A change-point linkage: the modes meet at 0 and pi."""
    return (Linkage({"A": 0, "D": 3 * s}).crank("crank", pivot="A", tip="B", length=2 * s)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(3 * s, 2 * s)))


def slider_crank(s):
    """Offset slider-crank on a guide through a fixed point, crank + RRP."""
    return (Linkage({"A": (1 - 2j) * s}).crank("crank", pivot="A", tip="B", length=1 * s)
            .rrp(("rod", "block"), pin="B", guide=Guide("ground", (0.3 - 1.5j) * s, 0.2), joint="C",
                 length=3 * s))


def guide_bar(s):
    """Crank + RPR with an offset guide, then an RRP ram on the bar's point (a shaper)."""
    return (Linkage({"A": 0, "D": -4j * s}).crank("crank", pivot="A", tip="B", length=1.5 * s)
            .rpr(("bar", "block"), pins=("D", "B"), offset=0.4 * s)
            .point("E", link="bar", at=(6 + 0.2j) * s)
            .rrp(("rod", "ram"), pin="E", guide=Guide("ground", 2j * s, 0.0), joint="F", length=2.5 * s))


def six_bar(s):
    """A drag link driving a parallelogram second loop (change points in the second loop)."""
    return (Linkage({"A": 0, "D": 1.0 * s, "F": 3.5 * s}).crank("crank", pivot="A", tip="B", length=3.0 * s)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(4.0 * s, 3.5 * s))
            .point("E", link="rocker", at=2.0 * s)
            .rrr(("link5", "output"), pins=("E", "F"), joint="G", lengths=(2.5 * s, 2.0 * s)))


def prp_rpp(s):
    """Crank, then a PRP cross-slide and an RPP group on a second crank-driven link."""
    return (Linkage({"A": 0, "O": (5 + 1j) * s}).crank("crank", pivot="A", tip="B", length=1.2 * s)
            .prp(("b1", "b2"), guides=(Guide("crank", 0.5 * s, 0.3), Guide("ground", (2 + 0j) * s, 1.1)),
                 joint="J")
            .rpp(("pinned", "sliding"), pin="B", guide=Guide("ground", "O", 0.0), angle=1.2, point="K",
                 offset=0.3 * s))


LINKAGES = {"fourbar": fourbar, "parallelogram": parallelogram, "slider_crank": slider_crank,
            "guide_bar": guide_bar, "six_bar": six_bar, "prp_rpp": prp_rpp}


def slider_driven(s):
    """A linear driver (distance input) moving a pin, then an RRR group to the ground."""
    return (Linkage({"O": 0, "H": (2 + 1j) * s})
            .slider("carriage", guide=Guide("ground", 0j, 0.3), point="S")
            .rrr(("l1", "l2"), pins=("S", "H"), joint="T", lengths=(1.5 * s, 1.8 * s)))


def actuator(s):
    """A lever raised by a hydraulic cylinder: an RRR group whose second length is a driver."""
    return (Linkage({"A": 0, "C": 2.0 * s})
            .rrr(("lever", "cylinder"), pins=("A", "C"), joint="B", lengths=(1.5 * s, "stroke")))


def _compare(ref, got, s):
    assert np.array_equal(got.valid, ref.valid)
    ok = ref.valid
    for link in ref.angles:
        assert np.max(np.abs(np.angle(got.direction(link)[ok] / ref.direction(link)[ok])), initial=0) < 1e-12
        # rates lose digits within a few 1e-2 rad of a change point (see Linkage.solve Notes)
        for table, tol in (("omegas", 1e-9), ("alphas", 1e-7)):
            r, g = getattr(ref, table)[link][ok], getattr(got, table)[link][ok]
            assert np.max(np.abs(g - r) / (1 + np.abs(r)), initial=0) < tol
    for table, tol in (("points", 1e-12), ("velocities", 1e-9), ("accelerations", 1e-7)):
        for name, r in getattr(ref, table).items():
            g = getattr(got, table)[name][ok] / s
            r = r[ok]
            assert np.all(np.isfinite(g))
            assert np.max(np.abs(g - r) / (1 + np.abs(r)), initial=0) < tol, (table, name)
    for key, r in ref.slides.items():
        g = got.slides[key]
        for field in ("s", "v", "a", "coriolis"):
            rv, gv = getattr(r, field), getattr(g, field)
            if rv is None:
                continue
            rv, gv = np.broadcast_to(rv, ok.shape)[ok], np.broadcast_to(gv, ok.shape)[ok] / s
            assert np.max(np.abs(gv - rv) / (1 + np.abs(rv)), initial=0) < 1e-7, (key, field)


@pytest.mark.parametrize("name", list(LINKAGES))
@pytest.mark.parametrize("s", SCALES)
def test_solve_scale_invariance(name, s):
    build = LINKAGES[name]
    # the cross-slide's guides are parallel at 0.8 + k pi, where J runs off to infinity and
    # its acceleration exceeds the float range at s = 1e300: stay 0.1 rad away
    th = THETA[np.abs(np.sin(THETA - 0.8)) > 0.1] if name == "prp_rpp" else THETA
    ref = build(1.0).solve(th, order=2, omega=1.3, alpha=-0.7)
    got = build(s).solve(th, order=2, omega=1.3, alpha=-0.7)
    assert ref.valid.any()
    _compare(ref, got, s)
    assert not np.any(np.isnan(got.points[list(got.points)[-1]][got.valid]))


@pytest.mark.parametrize("s", SCALES)
def test_solve_scale_distance_drivers(s):
    """Slider and actuator inputs are distances: they scale with the linkage, and so do their rates."""
    x = np.linspace(-3.0, 3.0, 601)
    ref = slider_driven(1.0).solve(x, order=2, omega=0.5, alpha=0.25)
    got = slider_driven(s).solve(x * s, order=2, omega=0.5 * s, alpha=0.25 * s)
    _compare(ref, got, s)
    stroke = np.linspace(0.4, 3.6, 322)
    ref = actuator(1.0).solve(stroke, order=2, omega=0.2, alpha=0.1)
    got = actuator(s).solve(stroke * s, order=2, omega=0.2 * s, alpha=0.1 * s)
    _compare(ref, got, s)
    assert ref.valid.any() and not ref.valid.all()


@pytest.mark.parametrize("s", [1e-300, 1e-160, 1e160, 1e300])
def test_solve_scale_strict_and_ranges(s):
    """Errors and assembly ranges at extreme scales: the same angles, messages naming the input."""
    lk = (Linkage({"A": 0, "D": 35 * s}).crank("crank", pivot="A", tip="B", length=10 * s)
          .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(20 * s, 10 * s)))
    ref = (Linkage({"A": 0, "D": 35.0}).crank("crank", pivot="A", tip="B", length=10.0)
           .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(20.0, 10.0)))
    got, want = lk.assembly_range(), ref.assembly_range()
    assert len(got) == len(want) == 1
    assert got[0].start == pytest.approx(want[0].start, abs=1e-12)
    assert got[0].end == pytest.approx(want[0].end, abs=1e-12)
    with pytest.raises(AssemblyError, match="crank = 2.0"):
        lk.solve([0.0, 2.0], strict=True)
    lk.solve(np.linspace(got[0].start + 1e-9, got[0].end - 1e-9, 101), order=2, strict=True)


@pytest.mark.parametrize("s", [1e-300, 1e300])
def test_solve_scale_change_point_exact(s):
    """At the parallelogram's meeting points themselves, at extreme scales: assembled, finite."""
    sol = parallelogram(s).solve([0.0, math.pi, -math.pi, 1e-300], order=2)
    assert sol.valid.all()
    exact = 3 * s + 2 * s * np.exp(1j * np.array([0.0, math.pi, -math.pi, 1e-300]))
    assert np.max(np.abs(sol.points["C"] - exact)) < 1e-13 * s
    assert np.max(np.abs(sol.omegas["rocker"] - 1.0)) < 1e-10


@pytest.mark.parametrize("s", [2.0**-1074, 1e306, 4e306])
def test_solve_scale_float_limits(s):
    """Lengths at the ends of the float range: the unit itself must not overflow."""
    th = np.linspace(-4.0, 4.0, 81)
    ref = fourbar(1.0).solve(th)
    got = (Linkage({"A": 0, "D": 35 * s}).crank("crank", pivot="A", tip="B", length=10 * s)
           .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(40 * s, 30 * s))).solve(th)
    assert np.array_equal(got.valid, ref.valid)
    assert np.max(np.abs(got.angles["rocker"] - ref.angles["rocker"])) < 1e-12


@pytest.mark.parametrize("rtol", [0.0, -1e-12, float("nan"), "1e-12", True])
def test_linkage_rtol_checked(rtol):
    with pytest.raises(ValueError, match="`rtol`"):
        Linkage({"A": 0}, rtol=rtol)
