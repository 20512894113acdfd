"""The spherical path functions under hostile inputs (issue 24, item 5).

`coupler_octic(M, [0, 0, 0])` returned (0, 0) against its docstring (points are non-zero
vectors) and `coupler_quartic(M, [0, 0, 0])` a number; `coupler_quartic(M, P * 1e300)`
returned NaN with a warning; `path_verify(m, P * 1e-300, th)` reported "a norm of 0.0"; a
1e-200 linkage made `coupler_octic` report "a point of length 1.0". Properties: the quartic
takes directions (the same value for a point in any unit of length, no warning), the octic
is homogeneous of degree 8 wherever |x|**8 is a float and a named error where it is not,
zero points and linkages too small for the octic are refused by name, and `path_verify`
shows the true length of a point that is not a unit vector.
"""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from mech.spherical import SphericalFourBar
from mech.spherical.path import coupler_octic, coupler_quartic, path_verify

M = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, 0.8))
THETA = np.linspace(0.0, 1.5, 5)
P = M.solve(THETA).P
OFF = np.array([[0.3, -0.2, 0.9], [0.1, 0.8, -0.4], [-0.7, 0.1, 0.2]])


def _quiet(f, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return f(*args, **kwargs)


@pytest.mark.parametrize("f", [coupler_octic, coupler_quartic])
@pytest.mark.parametrize("zero", [[0.0, 0.0, 0.0], [[1.0, 0.0, 0.0], [0.0, -0.0, 0.0]]])
def test_zero_point_refused_by_name(f, zero):
    with pytest.raises(ValueError, match="non-zero `points`"):
        f(M, zero)


@settings(max_examples=60, deadline=None)
@given(exponent=st.integers(min_value=-300, max_value=300), on_curve=st.booleans())
def test_quartic_takes_directions(exponent, on_curve):
    x = P if on_curve else OFF
    s = 10.0**exponent
    value, grad = _quiet(coupler_quartic, M, x * s)
    ref, ref_grad = coupler_quartic(M, x / np.linalg.norm(x, axis=-1, keepdims=True))
    assert np.all(np.isfinite(value)) and np.all(np.isfinite(grad))
    np.testing.assert_allclose(value, ref, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(grad, ref_grad, rtol=1e-12, atol=1e-14)


@settings(max_examples=60, deadline=None)
@given(exponent=st.integers(min_value=-300, max_value=300))
def test_octic_is_homogeneous_or_refused_by_name(exponent):
    s = 10.0**exponent
    ref, ref_grad = coupler_octic(M, OFF)
    if 8 * exponent > 300:                         # |x|**8 beyond the float range
        with pytest.raises(ValueError, match="`points` small enough"):
            _quiet(coupler_octic, M, OFF * s)
        return
    value, grad = _quiet(coupler_octic, M, OFF * s)
    assert np.all(np.isfinite(value)) and np.all(np.isfinite(grad))
    if 7 * exponent > -300:                        # |x|**7 still a normal float
        np.testing.assert_allclose(value, ref * s**8, rtol=1e-9)
        np.testing.assert_allclose(grad, ref_grad * s**7, rtol=1e-9)


@pytest.mark.parametrize("size", [1e-200, 1e-30, 2.0**-83])
def test_octic_of_a_linkage_too_small_refused_by_name(size):
    tiny = SphericalFourBar(size, 3.5 * size, 3 * size, 3.2 * size, coupler=(1.7 * size, 0.49))
    with pytest.raises(ValueError, match=r"`linkage` of size.*" + f"{3.5 * size!r}".replace(".", r"\.")
                       .replace("+", r"\+")):
        coupler_octic(tiny, [1.3 * size, 2.1 * size, 1.0])


@pytest.mark.parametrize("size", [1e-20, 1e-12, 1e-6])
def test_octic_of_a_small_linkage_finite_everywhere(size):
    small = SphericalFourBar(size, 3.5 * size, 3 * size, 3.2 * size, coupler=(1.7 * size, 0.49))
    x = np.array([[1.3 * size, 2.1 * size, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, -1e-9], [0.0, 0.0, -1.0]])
    value, grad = _quiet(coupler_octic, small, x)
    assert np.all(np.isfinite(value)) and np.all(np.isfinite(grad))


@pytest.mark.parametrize("s", [1e-300, 1e-200, 1e-20, 2.0, 1e20, 1e300])
def test_path_verify_shows_the_true_length(s):
    with pytest.raises(ValueError, match=r"unit vectors, got a norm of ") as info:
        _quiet(path_verify, M, P * s, THETA)
    shown = float(str(info.value).rsplit(" ", 1)[-1])
    assert shown == pytest.approx(s, rel=1e-12, abs=0)


def test_path_verify_of_unit_points_passes():
    v = _quiet(path_verify, M, P, THETA)
    assert v["passes"] and np.isfinite(v["max_error"])
