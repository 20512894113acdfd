"""Acceptance sweeps of the planar guidance functions (issue 24, item 3): 200 random and 50
near-degenerate pose sets each.

- `guidance_fourbars` (pose sets from the coupler of a random crank-rocker, so that
  designs pass): every passing four-bar, analysed by the test's own geometry (plain
  complex arithmetic), carries its two circle points on circles about its fixed pivots
  through the five poses, on one assembly branch (the sign of the triangle B C D never
  changes), with the link lengths it reports.
- `slider_dyads`: the slider points of four poses are where the two circles of points
  whose positions 1, 2, k (k = 3, 4) are collinear meet, other than the pole of poses 1
  and 2 (which both contain). A 60-digit solve of the same float64 input takes the radical
  axis of the two circles through the pole and finds the other intersection on it; the
  number of slider dyads found must equal the number of real finite intersections there,
  and each must lie within 1e-7 (of the pose set's size) of it.
"""

import cmath

import mpmath as mp
import numpy as np
import pytest

from mech.planar import FourBar
from mech.planar.synthesis import guidance_fourbars, slider_dyads
from tests.planar.synthesis.test_synthesis_properties import _near_degenerate, _pose_set


def _sets(n, seed, size=5):
    rng = np.random.default_rng(seed)
    out = [_pose_set(rng, size) for _ in range(n)]
    near = [_near_degenerate(rng, k % 4) for k in range(n // 4)]
    return out + [(t[:size], d[:size]) for t, d in near]


def _linkage_sets(n, seed):
    """Five poses of the coupler of a random crank-rocker (crank 1, other links 2 to 4) at
    increasing crank angles (random sets seldom have a passing design; these have one):
    `n` spread over up to 300 deg, and `n // 4` with two crank angles 1e-3 rad apart."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n + n // 4:
        b, c, d = rng.uniform(2.0, 4.0, 3)
        if 1.0 + max(b, c, d) > b + c + d - max(b, c, d):
            continue                                        # not a crank-rocker
        crank = np.sort(rng.uniform(0.0, np.radians(300.0), 5))
        if len(out) >= n:
            crank[2] = crank[1] + 1e-3
        pose = FourBar(1.0, b, c, d, branch=int(rng.choice([-1, 1]))).solve(crank)
        B, C = np.asarray(pose.B, complex), np.asarray(pose.C, complex)
        theta = np.angle(C - B)
        offset = rng.normal() + 1j * rng.normal()
        out.append((theta, B + np.exp(1j * theta) * offset))
    return out


def _fourbar_problems(theta, d):
    try:
        result = guidance_fourbars(theta, d)
    except ValueError:
        return []
    out = []
    c0 = sum(complex(x) for x in d) / len(d)
    size = max(abs(complex(x) - c0) for x in d)
    for c in result.passing:
        A, D = complex(c.input_dyad.centre_point), complex(c.output_dyad.centre_point)
        zB, zC = complex(c.input_dyad.circle_point), complex(c.output_dyad.circle_point)
        B = [cmath.exp(1j * float(t)) * zB + complex(x) for t, x in zip(theta, d)]
        C = [cmath.exp(1j * float(t)) * zC + complex(x) for t, x in zip(theta, d)]
        ra, rc = [abs(b - A) for b in B], [abs(x - D) for x in C]
        if max(ra) - min(ra) > 1e-7 * size or max(rc) - min(rc) > 1e-7 * size:
            out.append("a circle point leaves its circle")
        side = [((x - b).conjugate() * (D - x)).imag for b, x in zip(B, C)]
        if not (all(v > 0 for v in side) or all(v < 0 for v in side)):
            out.append("the poses lie on two branches")
        lengths = [abs(B[0] - A), abs(C[0] - B[0]), abs(C[0] - D), abs(D - A)]
        reported = [c.linkage.a, c.linkage.b, c.linkage.c, c.linkage.d]
        if max(abs(a - b) for a, b in zip(reported, lengths)) > 1e-8 * max(lengths):
            out.append("link lengths differ from the dyads'")
    return out


def slider_points_mp(theta, d, dps=60):
    """The slider points of four poses (a list of 0 or 1 complex), at `dps` digits."""
    with mp.workdps(dps):
        e = [mp.expj(mp.mpf(float(t))) for t in theta]
        dd = [mp.mpc(complex(x).real, complex(x).imag) for x in d]
        a = [e[j] - e[0] for j in range(4)]
        b = [dd[j] - dd[0] for j in range(4)]
        z0 = -b[1] / a[1]                                   # the pole of poses 1 and 2

        def f(k, z):                                        # positions 1, 2, k collinear
            return mp.im((a[1] * z + b[1]) * mp.conj(a[k] * z + b[k]))

        # the radical axis: f3 and f4 with their |z|^2 terms cancelled; a line through z0
        q3, q4 = mp.im(a[1] * mp.conj(a[2])), mp.im(a[1] * mp.conj(a[3]))

        def g(z):
            return q4 * f(2, z) - q3 * f(3, z)

        # g is affine in (x, y): its gradient is normal to the line
        gx, gy = g(z0 + 1) - g(z0), g(z0 + 1j) - g(z0)
        u = mp.mpc(-gy, gx)
        u /= abs(u)
        # along the line f3(z0 + t u) = t (c1 + c2 t): the other root is -c1 / c2
        h = [f(2, z0 + s * u) for s in (-1, 1)]
        c1, c2 = (h[1] - h[0]) / 2, (h[1] + h[0]) / 2
        scale = max(abs(x) for x in b[1:])
        if c2 == 0 or abs(c1 / c2) > 1e8 * scale:
            return []                                       # at infinity: parallel guides
        return [complex(z0 - (c1 / c2) * u)]


def _slider_problems(theta, d):
    try:
        found = slider_dyads(theta, d)
    except ValueError:
        return []
    c0 = sum(complex(x) for x in d) / 4
    size = max(abs(complex(x) - c0) for x in d)
    ref = slider_points_mp(theta, d)
    if len(found) != len(ref):
        return [f"{len(found)} slider dyads, 60-digit solve {len(ref)}"]
    return [f"slider point {complex(k.slider_point)!r} is not {z!r}" for k, z in zip(found, ref)
            if abs(complex(k.slider_point) - z) > 1e-7 * max(size, abs(z))]


def test_passing_fourbars_of_a_few_linkage_sets_meet_their_poses():
    sets = _linkage_sets(4, seed=3)
    assert sum(len(guidance_fourbars(t, d).passing) for t, d in sets) >= 4
    wrong = {k: p for k, (t, d) in enumerate(sets) if (p := _fourbar_problems(t, d))}
    assert not wrong, wrong


def test_slider_points_of_a_few_sets_agree_with_the_60_digit_solve():
    wrong = {k: p for k, (t, d) in enumerate(_sets(8, seed=3, size=4)) if (p := _slider_problems(t, d))}
    assert not wrong, wrong


@pytest.mark.exhaustive
def test_guidance_fourbars_sweep():
    sets = _linkage_sets(200, seed=24)
    wrong = {k: p for k, (t, d) in enumerate(sets) if (p := _fourbar_problems(t, d))}
    assert sum(len(guidance_fourbars(t, d).passing) for t, d in sets) >= 200
    assert not wrong, wrong
    assert not wrong, wrong


@pytest.mark.exhaustive
def test_slider_dyads_sweep():
    wrong = {k: p for k, (t, d) in enumerate(_sets(200, seed=24, size=4)) if (p := _slider_problems(t, d))}
    assert not wrong, wrong
