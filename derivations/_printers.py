"""The code printers of the generator's backends, and the overflow-safe rewrite they share.

Every backend prints the same common-subexpression-eliminated expressions; only the
spelling of a call differs (``np.sin``, ``math.sin``, ``Math.sin``). Before elimination,
`overflow_safe` replaces each square root of a sum of squares by `hypot`, which every
backend prints as its library's hypot: ``sqrt(x**2 + y**2)`` overflows to inf once
``x**2`` does (``|x|`` above about 1.3e154), while ``hypot(x, y)`` stays finite for every
finite result, and it underflows to 0.0 only where the exact result does.
"""

from __future__ import annotations

import sympy as sm
from sympy.printing.jscode import JavascriptCodePrinter
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.precedence import precedence
from sympy.printing.pycode import PythonCodePrinter

__all__ = ["hypot", "overflow_safe", "numpy_code", "numpy_operand", "MathPrinter", "JSPrinter"]


class hypot(sm.Function):
    """``sqrt(x**2 + y**2)`` without overflow or underflow of the squares (printed only)."""

    nargs = 2

    def _eval_rewrite_as_sqrt(self, x, y, **kwargs):
        return sm.sqrt(x**2 + y**2)


def _square_root_of(term):
    """``u`` with ``term == u**2`` for a square (``c * v**2``, ``c`` a rational square), else None."""
    if term.is_Rational and term > 0:
        root = sm.sqrt(term)
        return root if root.is_Rational else None
    coeff, rest = term.as_coeff_Mul()
    if not (coeff.is_Rational and coeff > 0):
        return None
    root = sm.sqrt(coeff)
    if not root.is_Rational:
        return None
    if rest.is_Pow and rest.exp == 2:
        return root * rest.base if root != 1 else rest.base
    return None


def _as_hypot(base):
    """`hypot` of the roots of ``base`` when it is a sum of two or more squares, else None."""
    if not base.is_Add or len(base.args) < 2 or base.has(sm.I):
        return None
    roots = [_square_root_of(t) for t in base.args]
    if any(r is None for r in roots):
        return None
    acc = hypot(roots[0], roots[1])
    for r in roots[2:]:
        acc = hypot(acc, r)
    return acc


def overflow_safe(expr):
    """``expr`` with ``sqrt(u**2 + v**2 [+ ...])`` (and its reciprocal powers) as `hypot`."""
    expr = sm.sympify(expr)
    seen = {}   # a large expression repeats subtrees: visit each once

    def visit(e):
        if not e.args:
            return e
        if e in seen:
            return seen[e]
        seen[e] = out = _visit(e)
        return out

    def _visit(e):
        args = [visit(a) for a in e.args]
        if e.is_Pow and e.exp.is_Rational and e.exp.q == 2:
            h = _as_hypot(args[0])
            if h is not None:
                # sqrt(s)**k with k odd: hypot**k (k = 1 or -1 in practice)
                return h if e.exp.p == 1 else sm.Pow(h, e.exp.p, evaluate=False)
        return e.func(*args) if args != list(e.args) else e

    return visit(expr)


class _NumPyPrinter(NumPyPrinter):
    def _print_hypot(self, expr):
        return f"numpy.hypot({self._print(expr.args[0])}, {self._print(expr.args[1])})"


def numpy_code(expr):
    """NumPy source of ``expr`` (``np.`` prefixed), as the generated modules spell it."""
    return _NumPyPrinter({"fully_qualified_modules": True}).doprint(expr).replace("numpy.", "np.")


def numpy_operand(expr):
    """`numpy_code`, parenthesised unless a symbol or a non-negative number."""
    text = numpy_code(expr)
    return f"({text})" if not (expr.is_Symbol or (expr.is_Number and expr >= 0)) else text


class MathPrinter(PythonCodePrinter):
    """Scalar Python (``math``) for numba loops; ``_sign`` is the kernels' numpy.sign."""

    def _print_sign(self, expr):
        return f"_sign({self._print(expr.args[0])})"

    def _print_hypot(self, expr):
        return f"math.hypot({self._print(expr.args[0])}, {self._print(expr.args[1])})"


class JSPrinter(JavascriptCodePrinter):
    """ES2015 scalar code: ``Math`` functions; squares as products and numbers as the
    NumPy printer writes them, so both backends round the same operations."""

    def __init__(self, settings=None):
        super().__init__(settings or {})
        self._numpy = _NumPyPrinter({"fully_qualified_modules": True})

    def _print_hypot(self, expr):
        return f"Math.hypot({self._print(expr.args[0])}, {self._print(expr.args[1])})"

    def _print_Float(self, expr):
        return self._numpy._print_Float(expr)

    def _print_Rational(self, expr):
        return f"({expr.p}/{expr.q})"

    def _print_Pow(self, expr):
        PREC = precedence(expr)
        base, exp = expr.base, expr.exp
        if exp.is_Number and exp == int(exp) and not exp.is_Float:
            n = int(exp)
            if n == 2:
                b = self.parenthesize(base, PREC)
                return f"({b}*{b})"
            if n == -1:
                return f"1/{self.parenthesize(base, PREC)}"
        if exp.is_Float and float(exp) == -1.0:
            return f"1/{self.parenthesize(base, PREC)}"
        if exp == sm.S.Half:
            return f"Math.sqrt({self._print(base)})"
        if exp == -sm.S.Half:
            return f"1/Math.sqrt({self._print(base)})"
        return f"Math.pow({self._print(base)}, {self._print(exp)})"

    def _print_sign(self, expr):
        return f"Math.sign({self._print(expr.args[0])})"
