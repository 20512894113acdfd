"""Proving that an expression is identically zero, cheaply first.

``sm.simplify(e) == 0`` is the notebooks' usual proof of an identity, and on a large
trigonometric expression it tries many rewrites and takes seconds. `is_zero` first tries one
exact, complete route for the common case, and falls back to ``simplify`` only when that
route does not settle it, so it proves at least what ``simplify`` proves and never less:

1. write tan, cot, sec and csc through sin and cos, and expand sines and cosines of sums and
   integer multiples (``expand_trig``), both exact rewrites;
2. put the result over one denominator (``together``): where the expression is defined it
   is zero exactly when the numerator is;
3. replace each ``sin(u)``, ``cos(u)`` by new variables ``s_u``, ``c_u`` and reduce the
   expanded numerator modulo ``s_u**2 + c_u**2 - 1`` (these generators, with the ``c_u``
   first in lex order, are a Groebner basis, so the remainder is zero exactly when the
   numerator lies in the ideal they generate). A zero remainder proves the identity for
   every real ``u``: every actual value of the sines and cosines is a point of that ideal's
   variety. Arguments related to each other (``u`` and ``u/2``) are treated as independent,
   which can only make the route fail to prove, never prove a false statement; then
   ``simplify`` decides as before.

Anything else in the numerator (square roots, atan2, Abs) is a further polynomial variable:
again the route may fail to prove, never prove wrongly.
"""

from __future__ import annotations

import sympy as sm

__all__ = ["is_zero", "trig_zero", "simplify"]

_TO_SIN_COS = {
    sm.tan: lambda u: sm.sin(u) / sm.cos(u),
    sm.cot: lambda u: sm.cos(u) / sm.sin(u),
    sm.sec: lambda u: 1 / sm.cos(u),
    sm.csc: lambda u: 1 / sm.sin(u),
}


def trig_zero(expr):
    """True when steps 1-3 above prove ``expr`` identically zero; False when they do not
    settle it (which is no proof of the contrary)."""
    e = sm.sympify(expr)
    if e == 0:
        return True
    for f, g in _TO_SIN_COS.items():
        if e.has(f):
            e = e.replace(f, g)
    e = sm.expand_trig(e)
    num = sm.numer(sm.together(e))
    if num == 0:
        return True
    args = sorted({a.args[0] for a in num.atoms(sm.sin, sm.cos)}, key=sm.default_sort_key)
    if not args:
        return sm.expand(num) == 0
    c = sm.symbols(f"_c0:{len(args)}")
    s = sm.symbols(f"_s0:{len(args)}")
    table = {}
    for u, ci, si in zip(args, c, s):
        table[sm.cos(u)] = ci
        table[sm.sin(u)] = si
    poly_expr = sm.expand(num.xreplace(table))
    if poly_expr == 0:
        return True
    if poly_expr.has(sm.sin, sm.cos):     # a sine left inside another function
        return False
    try:
        others = [g for g in sm.Poly(poly_expr).gens if g not in c and g not in s]
        gens = list(c) + list(s) + others
        p = sm.Poly(poly_expr, *gens)
    except sm.PolynomialError:
        return False
    if p.domain not in (sm.ZZ, sm.QQ, sm.ZZ_I, sm.QQ_I):   # exact rational or Gaussian coefficients only
        return False
    circles = [sm.Poly(ci**2 + si**2 - 1, *gens) for ci, si in zip(c, s)]
    _, rem = sm.reduced(p, circles, *gens, order="lex")
    return rem.is_zero


def is_zero(expr):
    """True when ``expr`` (a scalar or a matrix, every entry) is identically zero: by
    `trig_zero` when it settles it, else by ``sm.simplify(expr) == 0`` as before."""
    e = sm.sympify(expr)
    if isinstance(e, sm.MatrixBase):
        return all(is_zero(v) for v in e)
    return trig_zero(e) or sm.simplify(e) == 0


def simplify(expr):
    """``sm.simplify(expr)``, except that an expression `trig_zero` proves zero is returned
    as 0 at once (entry by entry for a matrix): for checks displayed as their simplified
    value and asserted to be 0 afterwards."""
    e = sm.sympify(expr)
    if isinstance(e, sm.MatrixBase):
        return e.applyfunc(simplify)
    return sm.S.Zero if trig_zero(e) else sm.simplify(e)
