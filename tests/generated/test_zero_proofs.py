"""The notebooks' identity prover (``derivations/_zero.py``): it proves true identities by
its cheap route, never proves a false one, and falls back to ``simplify``."""

import pytest

sm = pytest.importorskip("sympy")

from derivations import _zero  # noqa: E402

x, y, a = sm.symbols("x y a", real=True)


@pytest.mark.parametrize("expr", [
    sm.sin(x) ** 2 + sm.cos(x) ** 2 - 1,
    sm.sin(2 * x) - 2 * sm.sin(x) * sm.cos(x),
    sm.cos(x + y) - sm.cos(x) * sm.cos(y) + sm.sin(x) * sm.sin(y),
    1 / sm.cos(a) - sm.cos(a) - sm.sin(a) * sm.tan(a),
    sm.tan(x) ** 2 + 1 - sm.sec(x) ** 2,
    (sm.cos(x) ** 4 - sm.sin(x) ** 4) - sm.cos(2 * x),
    sm.expand_complex(sm.exp(sm.I * x) * sm.exp(sm.I * y) - sm.exp(sm.I * (x + y))),
    sm.cos(a) / (sm.sin(x) ** 2 + sm.cos(a) ** 2 * sm.cos(x) ** 2)
    - sm.cos(a) / (1 - sm.sin(a) ** 2 * sm.cos(x) ** 2),
])
def test_true_identities_are_proved_by_the_cheap_route(expr):
    assert _zero.trig_zero(expr)
    assert _zero.is_zero(expr)


@pytest.mark.parametrize("expr", [
    sm.sin(x) ** 2 + sm.cos(x) ** 2 - 1 + sm.Rational(1, 10**30),
    sm.sin(2 * x) - 2 * sm.sin(x) * sm.cos(y),
    sm.tan(x) - sm.sin(x),
    sm.expand_complex(sm.exp(sm.I * x) - sm.cos(x) + sm.I * sm.sin(x)),
    sm.cos(x / 2) ** 2 - (1 + sm.cos(x)) / 2 + x,
    1.0000001 * (sm.sin(x) ** 2 + sm.cos(x) ** 2) - 1,
])
def test_false_identities_are_never_proved(expr):
    # checked at a point first, so that the statement is known to be false
    assert abs(complex(expr.subs({x: 0.7, y: 0.3, a: 0.2}).evalf(50))) > 0
    assert not _zero.trig_zero(expr)
    assert not _zero.is_zero(expr)


def test_related_arguments_fall_back_to_simplify():
    # cos(x) and cos(x/2) are related, which the cheap route treats as independent
    expr = sm.cos(x / 2) ** 2 - (1 + sm.cos(x)) / 2
    assert not _zero.trig_zero(expr)
    assert _zero.is_zero(expr)


def test_matrices_are_zero_entry_by_entry():
    R = sm.Matrix([[sm.cos(x), -sm.sin(x)], [sm.sin(x), sm.cos(x)]])
    assert _zero.is_zero(R * R.T - sm.eye(2))
    assert not _zero.is_zero(R * R - sm.eye(2))
