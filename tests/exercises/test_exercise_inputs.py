"""Every exercise under hostile givens (issue 24, item 7).

For every exercise and every given, a value far from the textbook's (zero, negative,
subnormal, 1e-300, 1e15, 1e300 ...) either solves, with every numeric result finite and no
RuntimeWarning, or is refused by a ValueError (an AssemblyError included) that names a
given of the exercise in backticks; never another exception, never an internal argument
(`contact`, `length`, `rho`, `lam`, `a` ...) alone, never NaN. The reported cases are
pinned one by one.
"""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from mech.exercises import EXERCISES, get
from mech.planar.synthesis import crank_rocker_family

HOSTILE = (0.0, -1.0, 5e-324, 1e-300, 1e-15, 1e15, 1e300, -1e300)
SLOTS = [(number, p.name) for number, ex in EXERCISES.items() for p in ex.parameters]


def _numbers(value):
    """The float entries of a numeric result (empty for text, flags and formula-only results)."""
    if value is None or isinstance(value, (str, bool, np.bool_)):
        return np.empty(0)
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        return np.empty(0)
    return arr.ravel() if arr.dtype.kind in "fc" else np.empty(0)


def _check(number, overrides):
    """None if exercise `number` solves with `overrides` cleanly or refuses them by name."""
    ex = get(number)
    names = [p.name for p in ex.parameters]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            solution = ex.solve(**overrides)
        except ValueError as exc:                  # AssemblyError is a ValueError
            if not any(f"`{n}`" in str(exc) for n in names):
                return f"{number} {overrides}: names no given: {exc}"
            return None
        except Exception as exc:                   # noqa: BLE001 - any other type is the failure
            return f"{number} {overrides}: {type(exc).__name__}: {exc}"
    bad = [r.name for r in solution.results() if not np.all(np.isfinite(_numbers(r.value)))]
    return f"{number} {overrides}: not finite: {bad}" if bad else None


@settings(max_examples=150, deadline=None)
@given(data=st.data())
def test_hostile_given_solves_cleanly_or_is_refused_by_name(data):
    number, name = data.draw(st.sampled_from(SLOTS), label="given")
    value = data.draw(st.one_of(st.sampled_from(HOSTILE),
                                st.floats(allow_nan=False, allow_infinity=False, width=64)), label="value")
    failure = _check(number, {name: value})
    assert failure is None, failure


@pytest.mark.parametrize("number, overrides", [
    ("2-4", {"DE": 5e-324}),          # a reshape error
    ("2-4", {"EF": 1e300}),
    ("2-4", {"AB": 5e-324}),          # named `a`
    ("2-5", {"AC": 1e15}),            # SciPy's bracketing error
    ("2-5", {"AB": 1e-15}),
    ("2-7", {"AB": 1e-300}),
    ("2-9", {"r1": 1e-300}),          # NaN, no error
    ("2-9", {"r1": 1e-15}),
    ("2-10", {"AC": 1e300}),          # named `contact`
    ("2-21", {"mu": 0.0}),            # named `length`
    ("2-21", {"e": 5e-324}),
    ("2-22", {"d_pin": 5e-324}),      # named `r`
    ("2-22", {"d_pin": 1e15}),        # named `rho`
    ("2-23", {"alpha": 5e-324}),      # named `cone_half_angle`
    ("2-23", {"mu": 0.0}),            # ZeroDivisionError
    ("2-24", {"d2": 5e-324}),         # named `lam`
    ("2-24", {"p": 1e300}),
    ("2-26", {"Mr": 5e-324}),         # RuntimeWarning
])
def test_reported_cases(number, overrides):
    failure = _check(number, overrides)
    assert failure is None, failure


def test_subnormal_moment_of_2_26_gives_the_same_efficiency():
    """Forces scale with the moment; the efficiency does not (it was 1.0 at Mr = 5e-324)."""
    ref = get("2-26").solve()
    tiny = get("2-26").solve(Mr=5e-324)
    for r in ref.results():
        if "efficiency" in r.name:
            assert tiny[r.name].value == pytest.approx(r.value, rel=1e-9), r.name


@pytest.mark.parametrize("number", list(EXERCISES))
def test_textbook_givens_solve_without_warning(number):
    failure = _check(number, {})
    assert failure is None, failure


@pytest.mark.parametrize("samples", [0, 1])
def test_crank_rocker_family_too_few_samples_refused_by_name(samples):
    """Issue 24 item 7: `samples=0` reached NumPy's argmax of an empty sequence."""
    with pytest.raises(ValueError, match=f"`samples`.*got {samples}"):
        crank_rocker_family(1.25, 1, 0.5, samples=samples)
