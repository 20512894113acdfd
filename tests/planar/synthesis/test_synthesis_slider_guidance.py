"""Slider (point-on-line) dyads for rigid-body guidance, checked against known slider-cranks.

Oracle: poses are taken from the coupler of a slider-crank written out by hand here (crank
pin B = a exp(1j phi), block pin C on the line y = e), so the slider pin (body point b on
the coupler's x axis) and the crank pin (body origin) are known; collinearity is
recomputed with mpmath at 50 digits from the float results.
"""

import mpmath as mp
import numpy as np
import pytest

from mech import InputTypeError
from mech.planar.synthesis import (
    GuidanceSliderCrank,
    SliderDyad,
    dyad_for_circle_point,
    guidance_slider_crank,
    slider_dyad_for_point,
    slider_dyads,
    slider_point_circle,
)

mp.mp.dps = 50


def crank_poses(a, b, e, phi, origin=0j, turn=0.0, scale=1.0):
    """Coupler poses (theta, d) of an offset slider-crank, placed by `origin` and `turn`.

    The body frame has its origin at the crank pin B and x towards the block pin C; all
    lengths (and `origin`) are multiplied by `scale` at the end.
    """
    phi = np.asarray(phi, dtype=float)
    B = a * np.exp(1j * phi)
    C = B.real + np.sqrt(b * b - (e - B.imag) ** 2) + 1j * e
    theta = np.angle(C - B) + turn
    return theta, (origin + np.exp(1j * turn) * B) * scale


def mp_collinearity(theta, d, z):
    """Largest |Im((B_j - B_1) conj(B_k - B_1))| / (|B_j - B_1| |B_k - B_1|) at 50 digits."""
    z = mp.mpc(complex(z))
    B = [mp.expj(mp.mpf(float(t))) * z + mp.mpc(complex(p)) for t, p in zip(theta, d)]
    worst = mp.mpf(0)
    for j in range(1, len(B)):
        for k in range(j + 1, len(B)):
            u, v = B[j] - B[0], B[k] - B[0]
            worst = max(worst, abs(mp.im(u * mp.conj(v))) / (abs(u) * abs(v)))
    return float(worst)


CASES = [  # a, b, e, crank angles
    (1.0, 3.0, 0.5, [0.2, 0.9, 1.6, 2.5]),
    (2.0, 5.0, -1.0, [-0.4, 0.5, 1.1, 2.0]),
    (1.0, 2.5, 0.0, [0.3, 1.2, 2.0, 3.0]),
]


@pytest.mark.parametrize("a, b, e, phi", CASES)
@pytest.mark.parametrize("scale", [1e-150, 1.0, 1e150])
def test_four_poses_find_the_known_slider_pin(a, b, e, phi, scale):
    theta, d = crank_poses(a, b, e, phi, origin=3 - 2j, turn=0.7, scale=scale)
    found = slider_dyads(theta, d)
    assert len(found) == 1
    g = found[0]
    assert abs(g.slider_point - b * scale) <= 1e-9 * b * scale
    assert mp_collinearity(theta, d, g.slider_point) < 1e-11
    # the guide is the placed line y = e, direction +-x turned by 0.7
    assert abs(np.imag(np.conj(np.exp(0.7j)) * g.direction)) < 1e-9


@pytest.mark.parametrize("a, b, e, phi", CASES)
def test_three_pose_circle_holds_the_pin_and_only_slider_points(a, b, e, phi):
    theta, d = crank_poses(a, b, e, phi[:3], origin=-1 + 4j, turn=-0.3)
    circle = slider_point_circle(theta, d)
    assert abs(abs(b - circle.centre) - circle.radius) <= 1e-12 * b
    pts = circle.points(24)
    assert max(mp_collinearity(theta, d, z) for z in pts[1:]) < 1e-11
    # the pole of poses 1 and 2 stays put between them (independent: the body map itself)
    P1 = np.exp(1j * theta[0]) * circle.pole + d[0]
    P2 = np.exp(1j * theta[1]) * circle.pole + d[1]
    assert abs(P1 - P2) <= 1e-12 * abs(d).max()
    # a point off the circle is no slider point
    with pytest.raises(ValueError, match="slider_point"):
        slider_dyad_for_point(theta, d, circle.centre + 1.1 * (b - circle.centre))


def test_circle_scales_with_the_unit_of_length():
    theta, d = crank_poses(1.0, 3.0, 0.5, [0.2, 0.9, 1.6])
    ref = slider_point_circle(theta, d)
    for k in (1e-300, 1e-100, 1e100, 1e300):
        got = slider_point_circle(theta, d * k)
        assert abs(got.centre / k - ref.centre) <= 1e-13 * ref.radius
        assert abs(got.radius / k - ref.radius) <= 1e-13 * ref.radius


@pytest.mark.parametrize("a, b, e, phi", CASES)
@pytest.mark.parametrize("n", [2, 3, 4])
@pytest.mark.parametrize("scale", [1e-200, 1.0, 1e200])
def test_guidance_slider_crank_passes_through_every_pose(a, b, e, phi, n, scale):
    theta, d = crank_poses(a, b, e, phi[:n], origin=5 + 1j, turn=1.3, scale=scale)
    # RR crank: the known crank pin (body origin) for 2 and 3 poses; four poses: the known one
    crank = dyad_for_circle_point(theta[:3], d[:3], 0.0) if n >= 3 else \
        dyad_for_circle_point(theta, d, 0.0, along=0.0)
    slider = slider_dyads(theta, d)[0] if n == 4 else slider_dyad_for_point(theta, d, b * scale)
    design = guidance_slider_crank(theta, d, crank, slider)
    assert isinstance(design, GuidanceSliderCrank)
    if n >= 3:      # the crank found is the original one: the design must work
        assert design.passes and design.direction == 1
        assert abs(crank.centre_point - (5 + 1j) * scale) <= 1e-9 * scale
    # independent check: solve the linkage and rebuild each pose from the pin positions
    sol = design.linkage.solve(design.theta_input)
    B, C = sol.points["B"], sol.points["C"]
    with np.errstate(invalid="ignore"):
        err = max(np.max(np.abs(B - (np.exp(1j * theta) * crank.circle_point + d))) / (b * scale),
                  np.max(np.abs(C - (np.exp(1j * theta) * slider.slider_point + d))) / (b * scale),
                  np.max(np.abs(np.angle(np.exp(1j * (np.angle(C - B) - theta))))))
    if n >= 3:
        assert np.all(sol.valid) and err <= 1e-9
    # a design passes only if the analysis really reproduces the poses
    assert not design.passes or (np.all(sol.valid) and err <= 1e-9)
    assert 0.0 < design.gamma_min <= np.min(design.gamma_at_poses) + 1e-15


def test_transmission_angle_is_the_hand_computed_one():
    a, b, e = 1.0, 3.0, 0.5
    theta, d = crank_poses(a, b, e, [0.2, 0.9, 1.6])
    design = guidance_slider_crank(theta, d, dyad_for_circle_point(theta, d, 0.0),
                                   slider_dyad_for_point(theta, d, b))
    # rod angle from the guide: sin = (e - a sin phi) / b; transmission angle = pi/2 - that
    phi = np.array([0.2, 0.9, 1.6])
    expect = 0.5 * np.pi - np.abs(np.arcsin((e - a * np.sin(phi)) / b))
    assert np.allclose(design.gamma_at_poses, expect, rtol=0, atol=1e-12)
    # over the motion the worst is at phi = pi/2 (B farthest from the guide), inside [0.2, 1.6]
    assert abs(design.gamma_min - (0.5 * np.pi - np.arcsin((a - e) / b))) < 1e-12


def test_order_of_the_poses_decides_the_direction():
    a, b, e = 1.0, 3.0, 0.5
    # clockwise from 0.2 round to 1.6, then on to 0.9: less than a turn, a full-turning crank
    theta, d = crank_poses(a, b, e, [0.2, 1.6, 0.9])
    design = guidance_slider_crank(theta, d, dyad_for_circle_point(theta, d, 0.0),
                                   slider_dyad_for_point(theta, d, b))
    assert design.passes and design.direction == -1
    # 0.2, 1.6, 0.9, 1.2: either way the crank turns more than a full turn
    theta, d = crank_poses(a, b, e, [0.2, 1.6, 0.9, 1.2])
    design = guidance_slider_crank(theta, d, dyad_for_circle_point(theta[:3], d[:3], 0.0),
                                   slider_dyad_for_point(theta, d, b))
    assert design.pose_error <= 1e-9
    assert not design.in_order and not design.passes and design.direction == 0


def test_rocking_crank_that_cannot_reach_is_not_passed():
    # a = 1, b = 1.2, e = 0.5: the rod reaches the guide only while |0.5 - sin phi| <= 1.2,
    # i.e. phi outside about (-2.37, -0.78): a rocking crank
    a, b, e = 1.0, 1.2, 0.5
    theta, d = crank_poses(a, b, e, [-0.7, 0.0, 2.0])
    crank = dyad_for_circle_point(theta, d, 0.0)
    design = guidance_slider_crank(theta, d, crank, slider_dyad_for_point(theta, d, b))
    # ccw: -0.7 -> 0.0 -> 2.0 stays in the reachable range
    assert design.passes and design.direction == 1
    theta, d = crank_poses(a, b, e, [-0.7, 2.0, 0.0])
    design = guidance_slider_crank(theta, d, dyad_for_circle_point(theta, d, 0.0),
                                   slider_dyad_for_point(theta, d, b))
    # ccw from 2.0 on to 0.0, or cw from -0.7 to 2.0, crosses -pi/2, where the rod cannot reach
    assert design.pose_error <= 1e-9 and design.direction == 0 and not design.passes


def test_two_poses_line_through_the_positions():
    theta, d = np.array([0.1, 0.8]), np.array([1 + 1j, 2 - 0.5j])
    g = slider_dyad_for_point(theta, d, 0.3 - 0.7j)
    B = np.exp(1j * theta) * (0.3 - 0.7j) + d
    assert isinstance(g, SliderDyad)
    assert abs(g.moving_pivot - B[0]) < 1e-15 and abs(g.line_point - B[0]) < 1e-15
    assert abs(g.line_point + g.s[1] * g.direction - B[1]) < 1e-14
    assert g.s[0] == 0.0 and abs(abs(g.direction) - 1) < 1e-15


def test_errors_name_the_argument():
    theta, d = crank_poses(1.0, 3.0, 0.5, [0.2, 0.9, 1.6])
    with pytest.raises(ValueError, match="3 poses"):
        slider_point_circle(theta[:2], d[:2])
    with pytest.raises(ValueError, match="4 poses"):
        slider_dyads(theta, d)
    with pytest.raises(InputTypeError, match="slider_point"):
        slider_dyad_for_point(theta, d, "1")
    with pytest.raises(ValueError, match="slider_point"):
        slider_dyad_for_point(theta, d, np.nan)
    with pytest.raises(InputTypeError, match="crank"):
        guidance_slider_crank(theta, d, None, slider_dyad_for_point(theta, d, 3.0))
    with pytest.raises(InputTypeError, match="slider"):
        guidance_slider_crank(theta, d, dyad_for_circle_point(theta, d, 0.0), 3.0)
    with pytest.raises(InputTypeError, match="`n`"):
        slider_point_circle(theta, d).points(2.0)
    # pure translations: the slider points are not a circle
    with pytest.raises(ValueError, match="line"):
        slider_point_circle([0.0, 0.0, 0.5], [0, 1, 1j])
    # a common pole has no guide direction
    with pytest.raises(ValueError, match="pole"):
        slider_dyad_for_point([0.0, 0.5], [0, 0], 0.0)
