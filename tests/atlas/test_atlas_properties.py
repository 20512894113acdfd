"""Properties of the atlas under hostile inputs (issue 24, items 4 and 7).

A target curve given in any unit of length, from 1e-300 to 1e300, finds the same linkages
with the same relative error, and lengths (links, pivots, errors, curves) that are the
unit's multiples of those found at unit size; no RuntimeWarning is raised on the way; a
point near the end of the float range gives a finite signature; a seed that does not fit
the atlas's 64-bit seed column is refused by name. The scales are powers of ten, not of
two, so the comparison allows the rounding of the scaled input (rtol 1e-9).
"""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from mech.atlas import (build_atlas, build_sphere_atlas, curve_signature, find_linkages, query, query_sphere, refine, resample,
                        sample_fourbars, sample_slider_cranks, sample_sphere_fourbars)

EXPONENTS = st.integers(min_value=-300, max_value=300)


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(300, seed=2)


@pytest.fixture(scope="module")
def target(atlas):
    curve = atlas.curves(17)[0]
    return 5 + 2j + 3 * np.exp(1j) * np.roll(curve, 40)[::-1]


def _quiet(f, *args, **kwargs):
    """Call f with every warning raised as an error (no RuntimeWarning on valid input)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return f(*args, **kwargs)


def _same_match(m, ref, s):
    """A match at scale `s` against the one at scale 1: same row, same relative error,
    lengths multiplied by s."""
    assert m.index == ref.index and m.direction == ref.direction
    assert np.isfinite(m.relative_error) and np.isfinite(m.error)
    assert m.relative_error == pytest.approx(ref.relative_error, rel=1e-6, abs=1e-12)
    assert m.error == pytest.approx(ref.error * s, rel=1e-6, abs=1e-12 * s)
    assert np.all(np.isfinite(m.curve))
    np.testing.assert_allclose(m.curve / s, ref.curve, rtol=0, atol=1e-7 * np.max(np.abs(ref.curve)))
    f, g = m.linkage.fourbar, ref.linkage.fourbar
    np.testing.assert_allclose(np.array([f.a, f.b, f.c, f.d, *f.coupler]) / s,
                               [g.a, g.b, g.c, g.d, *g.coupler], rtol=1e-6, atol=1e-9 * g.d)
    assert m.linkage.rotation == pytest.approx(ref.linkage.rotation, abs=1e-6)
    assert len(m.cognates) == len(ref.cognates)


@settings(max_examples=12, deadline=None)
@given(exponent=EXPONENTS)
def test_query_is_unit_free(atlas, target, exponent):
    """Issue 24 item 4: `query(atlas, target * 1e200)` warned of overflow and gave a NaN
    relative error; 1e-200 gave 0/0."""
    s = 10.0**exponent
    ref = query(atlas, target, k=2)
    got = _quiet(query, atlas, target * s, k=2)
    for m, r in zip(got, ref):
        _same_match(m, r, s)


@pytest.mark.parametrize("s", [1e-300, 1e-200, 1e200, 1e300])
def test_query_open_arc_and_refine_are_unit_free(atlas, target, s):
    arc = target[:60]
    ref = query(atlas, arc, k=1, closed=False)[0]
    got = _quiet(query, atlas, arc * s, k=1, closed=False)[0]
    assert got.index == ref.index and got.relative_error == pytest.approx(ref.relative_error, rel=1e-6)
    start = query(atlas, target * s, k=1)[0]
    better = _quiet(refine, start, target * s, iterations=15)
    assert np.isfinite(better.relative_error) and np.isfinite(better.error)
    assert better.relative_error <= start.relative_error * (1 + 1e-9)


@pytest.mark.parametrize("s", [1e-200, 1e200])
def test_slider_crank_atlas_is_unit_free(s):
    sliders = build_atlas(100, seed=5, mechanism="slider-crank")
    curve = sliders.curves(3)[0]
    ref = query(sliders, curve, k=1)[0]
    got = _quiet(query, sliders, curve * s, k=1)[0]
    assert got.index == ref.index
    assert got.relative_error == pytest.approx(ref.relative_error, rel=1e-6, abs=1e-12)
    assert got.linkage.slider.a / s == pytest.approx(ref.linkage.slider.a, rel=1e-6)


@settings(max_examples=25, deadline=None)
@given(exponent=EXPONENTS, data=st.data())
def test_signature_and_resample_are_unit_free(target, exponent, data):
    s = 10.0**exponent
    closed = data.draw(st.booleans(), label="closed")
    ref = curve_signature(target, closed=closed)
    got = _quiet(curve_signature, target * s, closed=closed)
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-9)
    points = _quiet(resample, target * s, 32, closed=closed)
    assert np.all(np.isfinite(points))
    np.testing.assert_allclose(points / s, resample(target, 32, closed=closed), rtol=0, atol=1e-9 * 8)


def test_one_point_at_the_end_of_the_float_range(atlas, target):
    """Issue 24 item 4: one point at 1e308 gave a NaN signature (overflow in the arc length);
    a query whose matches would be longer than the float range is refused by name."""
    t = target.copy()
    t[3] = 1e308
    assert np.all(np.isfinite(_quiet(curve_signature, t)))
    assert np.all(np.isfinite(_quiet(resample, t, 16)))
    assert np.all(np.isfinite(_quiet(curve_signature, np.array([-1.7e308, 1.7e308, 1.7e308j]))))
    with pytest.raises(ValueError, match="`target`"):
        _quiet(query, atlas, t, k=1)


@pytest.mark.parametrize("s", [1e-300, 1e-150, 1e150, 1e300])
def test_query_sphere_takes_directions_of_any_length(s):
    """Issue 24 item 4: `query_sphere(atlas, curve * 1e-300)` said "without zero vectors"."""
    sphere = build_sphere_atlas(60, seed=1)
    curve = sphere.curves(5)[0]
    ref = query_sphere(sphere, curve, k=1)[0]
    got = _quiet(query_sphere, sphere, curve * s, k=1)[0]
    assert got.index == ref.index
    assert got.error == pytest.approx(ref.error, rel=1e-6, abs=1e-12)


@pytest.mark.parametrize("call", [
    lambda seed: build_atlas(20, seed=seed),
    lambda seed: build_atlas(20, seed=seed, mechanism="slider-crank"),
    lambda seed: sample_fourbars(5, seed=seed),
    lambda seed: sample_slider_cranks(5, seed=seed),
    lambda seed: sample_sphere_fourbars(5, seed=seed),
    lambda seed: build_sphere_atlas(5, seed=seed),
])
@pytest.mark.parametrize("seed", [2**63, 10**29])
def test_seed_beyond_int64_refused_by_name(call, seed):
    """Issue 24 item 7: `build_atlas(20, seed=2**63)` raised OverflowError."""
    with pytest.raises(ValueError, match=r"`seed`.*" + str(seed)):
        call(seed)


def test_largest_seed_accepted():
    assert len(build_atlas(20, seed=2**63 - 1)) == 20


@settings(max_examples=40, deadline=None)
@given(low=st.integers(min_value=-300, max_value=300), width=st.integers(min_value=1, max_value=600),
       u=st.integers(min_value=-300, max_value=300))
def test_sampling_ranges_sample_cleanly_or_are_refused_by_name(low, width, u):
    """Any range of ratios and coupler box: samples with no warning, or a ValueError naming it."""
    lengths = (10.0**low, 10.0 ** min(low + width, 308))
    box = (-(10.0**u), 10.0**u, -(10.0**u), 10.0**u)
    for name, call in (("lengths", lambda: sample_fourbars(30, seed=1, lengths=lengths, coupler=box)),
                       ("rods", lambda: sample_slider_cranks(30, seed=1, rods=lengths, coupler=box))):
        try:
            samples = _quiet(call)
        except ValueError as exc:
            assert f"`{name}`" in str(exc) or "`coupler`" in str(exc), str(exc)
        else:
            usable = samples.take(samples.usable)
            assert np.all(np.isfinite(usable.gamma_min))


@pytest.mark.parametrize("s", [1e-310, 1e-320])
def test_subnormal_target(atlas, target, s):
    """A target in subnormal numbers: the complex division by its subnormal scale overflowed."""
    best = _quiet(query, atlas, target * s, k=1)[0]
    assert np.isfinite(best.relative_error) and np.isfinite(best.error) and np.all(np.isfinite(best.curve))
    assert np.all(np.isfinite(_quiet(curve_signature, target * s)))
    assert best.index == 17 if s > 1e-315 else True


@pytest.mark.parametrize("s", [1e-200, 1e200])
def test_find_linkages_is_unit_free(atlas, target, s):
    """The driven-crank check of `find_linkages` squared the link lengths: a target of 1e200
    overflowed (OverflowError) and one of 1e-200 divided by zero."""
    ref = find_linkages(atlas, target, starts=2, samples=32, iterations=3)
    got = _quiet(find_linkages, atlas, target * s, starts=2, samples=32, iterations=3)
    assert len(got) == len(ref)
    for m, r in zip(got, ref):
        assert np.isfinite(m.relative_error)
        assert m.relative_error == pytest.approx(r.relative_error, rel=1e-6, abs=1e-12)
        assert m.linkage.fourbar.d / s == pytest.approx(r.linkage.fourbar.d, rel=1e-6)
