"""Inputs a few ulps inside a dead point assemble, in every solver (issue 24, item 8).

Within `DEAD_POINT_RTOL` of a dead point the input counts as the dead point: a pose that
a rounding kept from assembling is the dead point's. The reference is a 50-digit solve of
the same float input: every input that assembles there must be `valid` (positions), with
finite points on both branches. The spherical four-bar had no band: one input per branch,
an ulp inside the limit of a triple rocker, was NaN.
"""

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar, Linkage, SliderCrank
from mech.spherical import SphericalFourBar

mpmath.mp.dps = 50
ULPS = np.arange(-120, 121)


def _around(t):
    return t + ULPS * np.spacing(t)


@pytest.mark.parametrize("lengths", [(3.0, 2.0, 2.5, 4.0), (1.0, 2.0, 3.0, 1.0), (2.0, 1.0, 3.0, 2.0)])
@pytest.mark.parametrize("scale", [1.0, 1e-200, 1e200])
def test_planar_fourbar_and_linkage(lengths, scale):
    a, b, c, d = lengths
    limits = []
    for k in (b + c, abs(b - c)):
        cos_t = (mpmath.mpf(a) ** 2 + d * d - k * k) / (2 * a * d)
        if abs(cos_t) <= 1:
            limits.append(float(mpmath.acos(cos_t)))
    theta = np.concatenate([_around(t) for t in limits] + [-_around(t) for t in limits])

    def assembles(th):
        bd = mpmath.sqrt((mpmath.mpf(d) - a) ** 2 + 4 * a * d * mpmath.sin(mpmath.mpf(th) / 2) ** 2)
        return abs(b - c) <= bd <= b + c

    expected = np.array([assembles(t) for t in theta])
    L = [x * scale for x in lengths]
    for branch in (1, -1):
        pose = FourBar(*L, branch=branch).solve(theta)
        assert np.all(pose.valid[expected]) and np.all(np.isfinite(pose.C[expected]))
        lk = (Linkage({"A": 0.0, "D": L[3]}).crank("crank", pivot="A", tip="B", length=L[0])
              .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(L[1], L[2]), branch=branch))
        assert np.all(np.asarray(lk.solve(theta).valid)[expected])


@pytest.mark.parametrize("a, b, e", [(2.0, 1.0, 0.5), (3.0, 2.0, -0.5)])
def test_slider_crank(a, b, e):
    t = float(mpmath.asin((mpmath.mpf(b) + e) / a))
    theta = _around(t)
    expected = np.array([abs(a * mpmath.sin(mpmath.mpf(th)) - e) <= b for th in theta])
    for branch in (1, -1):
        pose = SliderCrank(a, b, e, branch=branch).solve(theta)
        assert np.all(pose.valid[expected])


@pytest.mark.parametrize("arcs", [(0.9, 0.6, 0.75, 1.2), (0.5, 0.4, 0.3, 0.8)])
def test_spherical_fourbar(arcs):
    A, B, C, D = (mpmath.mpf(x) for x in arcs)

    def bd(th):
        return mpmath.acos(mpmath.cos(A) * mpmath.cos(D) + mpmath.sin(A) * mpmath.sin(D) * mpmath.cos(th))

    thetas = []
    for k in (B + C, abs(B - C)):
        cos_t = (mpmath.cos(k) - mpmath.cos(A) * mpmath.cos(D)) / (mpmath.sin(A) * mpmath.sin(D))
        if abs(cos_t) <= 1:
            thetas.append(_around(float(mpmath.acos(cos_t))))
    assert thetas
    theta = np.concatenate(thetas)
    expected = np.array([abs(B - C) <= bd(mpmath.mpf(t)) <= B + C for t in theta])
    for branch in (1, -1):
        linkage = SphericalFourBar(*arcs, branch=branch, coupler=(0.4, 0.7))
        pose = linkage.solve(theta)
        assert np.all(pose.valid[expected]), theta[expected & ~pose.valid]
        ok = pose.valid
        # the poses found keep their arcs: BC = b and CD = c
        Dv = np.array([np.sin(arcs[3]), 0.0, np.cos(arcs[3])])
        np.testing.assert_allclose(np.sum(pose.B[ok] * pose.C[ok], axis=-1), np.cos(arcs[1]), atol=1e-13)
        np.testing.assert_allclose(pose.C[ok] @ Dv, np.cos(arcs[2]), atol=1e-13)
        assert np.all(np.isfinite(pose.P[ok]))
