"""Screw pairs and the screw jack (mech.planar.forces._screw) against independent routes: the nut
as a block on the unrolled thread solved by components, virtual work per turn, mpmath at
50 digits, and bisection for the self-locking lead angle."""

import math

import mpmath
import numpy as np
import pytest
from scipy.optimize import brentq

from mech.planar.forces._screw import ScrewJack, lead_angle, screw_efficiency, thread_friction_angle
from mech.planar.forces._friction import vgroove_mu

RNG = np.random.default_rng(6002)


def _thread_torque(Q, d2, lam, mu_v, sense):
    """Torque on the nut at the mean radius: block on the unrolled thread, by components.

    Unknowns F (horizontal push at d2/2) and N; friction mu_v N against the sliding
    (sense=+1 raising, -1 lowering with the load driving)."""
    A = np.array([[math.cos(lam), -sense * mu_v], [-math.sin(lam), 1.0]])
    F, _ = np.linalg.solve(A, [Q * math.sin(lam), Q * math.cos(lam)])
    return F * d2 / 2


def test_lead_angle_exercise_2_24():
    assert lead_angle(4.0, 22.0) == pytest.approx(math.atan(4 / (math.pi * 22)), rel=1e-15)
    assert lead_angle(4.0, 22.0, starts=2) == pytest.approx(math.atan(8 / (math.pi * 22)), rel=1e-15)


def test_lead_angle_bad_starts():
    with pytest.raises(ValueError, match=r"Expected `starts` to be an integer in \[1, 1000000\], got 0"):
        lead_angle(4.0, 22.0, starts=0)


def test_thread_friction_angle_is_a_v_groove():
    beta = math.radians(30)
    assert math.tan(thread_friction_angle(0.1, beta)) == pytest.approx(vgroove_mu(0.1, math.pi / 2 - beta), rel=1e-14)
    assert thread_friction_angle(0.1) == pytest.approx(math.atan(0.1), rel=1e-15)


def test_screw_efficiency_virtual_work():
    for _ in range(100):
        Q, d2, mu = RNG.uniform(10, 1e4), RNG.uniform(5, 60), RNG.uniform(0.02, 0.3)
        lead, mu_c, r_c = RNG.uniform(1, 30), RNG.uniform(0, 0.2), RNG.uniform(0, 40)
        lam = math.atan(lead / (math.pi * d2))
        s = screw_efficiency(Q, d2, lam, math.atan(mu), mu_c, r_c)
        M = _thread_torque(Q, d2, lam, mu, 1) + mu_c * Q * r_c
        assert s.raise_torque == pytest.approx(M, rel=1e-11)
        assert s.efficiency == pytest.approx(Q * lead / (2 * math.pi * M), rel=1e-11)   # work out / work in
        hold = _thread_torque(Q, d2, lam, mu, -1) - mu_c * Q * r_c
        assert s.hold_torque == pytest.approx(hold, rel=1e-9, abs=1e-9 * Q * d2)


@pytest.mark.parametrize("mu_c, r_c", [(0.0, 0.0), (0.1, 23.0)])
def test_screw_reverse_efficiency_crosses_zero_at_lock_angle(mu_c, r_c):
    Q, d2, mu = 1000.0, 22.0, 0.1
    root = brentq(lambda lam: _thread_torque(Q, d2, lam, mu, -1) - mu_c * Q * r_c, 1e-4, 1.2, xtol=1e-15)
    s = screw_efficiency(Q, d2, root, math.atan(mu), mu_c, r_c)
    assert s.lock_angle == pytest.approx(root, rel=1e-12)
    below, above = screw_efficiency(Q, d2, np.array([0.999, 1.001]) * root, math.atan(mu), mu_c, r_c).reverse_efficiency
    assert below < 0 < above
    if mu_c == 0:
        assert root == pytest.approx(math.atan(mu), rel=1e-12)    # lambda <= phi, not 2 phi (erratum)


def test_screw_textbook_2phi_condition_is_wrong():
    # a lead angle between phi and 2 phi: the text says it holds; it runs down
    phi = math.atan(0.1)
    s = screw_efficiency(1.0, 22.0, 1.5 * phi, phi)
    assert not s.self_locking and s.reverse_efficiency > 0


def test_self_locking_thread_wastes_more_than_half():
    for phi in (0.05, 0.1, 0.2):
        assert screw_efficiency(1.0, 20.0, phi, phi).efficiency < 0.5


def test_exercise_2_24_numbers_with_mpmath():
    with mpmath.workdps(50):
        lam, phi = mpmath.atan(mpmath.mpf(4) / (mpmath.pi * 22)), mpmath.atan(mpmath.mpf("0.1"))
        for condition, rc in (("run-in", mpmath.mpf(23)),
                              ("new", mpmath.mpf(2) / 3 * (25**3 - 21**3) / mpmath.mpf(25**2 - 21**2))):
            M = 11 * mpmath.tan(lam + phi) + mpmath.mpf("0.1") * rc
            jack = ScrewJack(22.0, 4.0, 0.1, collar=(50.0, 42.0), collar_condition=condition)
            r = jack.solve(1.0)
            assert r.raise_torque == pytest.approx(float(M), rel=1e-14)
            assert r.efficiency == pytest.approx(float(4 / (2 * mpmath.pi * M)), rel=1e-14)


def test_screw_jack_without_collar():
    r = ScrewJack(22.0, 4.0, 0.1).solve(1.0)
    assert r.efficiency == pytest.approx(math.tan(lead_angle(4.0, 22.0)) / math.tan(lead_angle(4.0, 22.0) + math.atan(0.1)))


def test_screw_efficiency_bad_input():
    with pytest.raises(ValueError, match="Expected `lam` < pi/2"):
        screw_efficiency(1.0, 22.0, 2.0, 0.1)
    with pytest.raises(ValueError, match="Expected `d2` > 0, got -1.0"):
        screw_efficiency(1.0, -1.0, 0.1, 0.1)
