"""Exercises as data plus a solver: the records behind ``mech.exercises``.

An :class:`Exercise` states a textbook exercise with named parameters (the textbook's
numbers are the defaults), draws other valid numbers with :meth:`Exercise.variant`, and
solves it with :meth:`Exercise.solve`, which returns a :class:`Solution`: named results with
units and a note on how each was computed, grouped by the parts of the exercise, that
renders itself as Markdown. Only NumPy is imported here.
"""

from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass, field, replace
from typing import Any, Callable

import numpy as np

from mech._errors import AssemblyError, InputTypeError
from mech._validate import integer, real_number

__all__ = ["Parameter", "Interval", "Result", "Part", "Solution", "Exercise"]


# ----------------------------------------------------------------------------- formatting
def _fmt_number(x, digits=6):
    """Format a float with ``digits`` significant digits, integers without a point."""
    x = float(x)
    if math.isfinite(x) and x == round(x) and abs(x) < 1e12:
        return str(int(round(x)))
    return f"{x:.{digits}g}"


def _fmt_value(value, unit):
    """Render a result value with its unit; radians are shown in degrees as well."""
    if isinstance(value, (bool, np.bool_)):
        return "yes" if value else "no"
    if isinstance(value, str):
        return value
    if isinstance(value, tuple) and all(isinstance(v, Interval) for v in value):
        if not value:
            return "none (empty)"
        return f"{' ∪ '.join(str(v) for v in value)} {unit}".rstrip()
    if isinstance(value, (frozenset, set)):
        return ", ".join(sorted(value)) if value else "none"
    if unit == "rad":
        return f"{math.degrees(float(value)):.4f}° ({float(value):.6f} rad)"
    return f"{_fmt_number(value)} {unit}".rstrip()


# ----------------------------------------------------------------------------- records
@dataclass(frozen=True)
class Parameter:
    """One given quantity of an exercise: a name used in templates, a default, a unit."""

    name: str
    default: float
    unit: str = "mm"
    description: str = ""


@dataclass(frozen=True)
class Interval:
    """A real interval with open or closed ends, rendered as ``(15, 45]``."""

    low: float
    high: float
    closed_low: bool = False
    closed_high: bool = False

    def __contains__(self, x):
        above = x >= self.low if self.closed_low else x > self.low
        below = x <= self.high if self.closed_high else x < self.high
        return bool(above and below)

    def __str__(self):
        left = "[" if self.closed_low else "("
        right = "]" if self.closed_high else ")"
        return f"{left}{_fmt_number(self.low)}, {_fmt_number(self.high)}{right}"


@dataclass(frozen=True)
class Result:
    """A named result: its value, unit and how it was computed.

    ``value`` is a float (angles in radians with ``unit="rad"``), a bool, a string, a
    frozenset of joint names, or a tuple of :class:`Interval`. ``latex`` optionally holds
    a formula (without dollars) shown before the value.
    """

    name: str
    value: Any
    unit: str = ""
    how: str = ""
    latex: str = ""

    def as_markdown(self):
        """Return one Markdown list item for this result."""
        formula = f"${self.latex}$" if self.latex else ""
        if formula and self.value is not None:
            formula += ", "
        shown = "" if self.value is None else _fmt_value(self.value, self.unit)
        how = f" — {self.how}" if self.how else ""
        return f"- **{self.name}**: {formula}{shown}{how}"


@dataclass(frozen=True)
class Part:
    """One part of a solution: a heading, its results and explanatory remarks."""

    title: str
    results: tuple = ()
    remarks: tuple = ()


@dataclass(frozen=True)
class Solution:
    """The solution of one exercise for one set of given values.

    Attributes
    ----------
    number : str
        The textbook's exercise number, e.g. ``"2-3"``.
    params : dict
        The given values used (name to float).
    conventions : tuple of str
        Assumptions and conventions the solution states before its results.
    parts : tuple of Part
        The answers, part by part.
    units : dict
        The unit of each given value (name to unit), for display.
    assumptions : tuple of str
        For an exercise whose figure is lost (tag "A"): the assumed layout, rendered
        first, with a warning that another reading of the figure may give other results.
    """

    number: str
    title: str
    params: dict
    conventions: tuple = ()
    parts: tuple = ()
    units: dict = field(default_factory=dict)
    assumptions: tuple = ()

    def results(self):
        """Return every :class:`Result` of every part, in order."""
        return tuple(r for part in self.parts for r in part.results)

    def __getitem__(self, name):
        for r in self.results():
            if r.name == name:
                return r
        names = ", ".join(r.name for r in self.results())
        raise KeyError(f"Expected a result name among {names}; got {name!r}")

    def values(self):
        """Return a dict of result name to value."""
        return {r.name: r.value for r in self.results()}

    def as_markdown(self, *, heading_level=None):
        """Render the solution as Markdown (LaTeX between dollars, angles in degrees).

        The title is a heading of ``heading_level`` (1 to 6), or bold text when None (the
        default, safe inside a book page's output).
        """
        if heading_level is not None:
            heading_level = integer("heading_level", heading_level, minimum=1, maximum=6)
        title = f"Solution of exercise {self.number}"
        title = f"{'#' * heading_level} {title}" if heading_level else f"**{title}**"
        given = ", ".join(
            f"{k} = {_fmt_number(v)} {self.units.get(k, '')}".rstrip() for k, v in self.params.items()
        )
        lines = [title, "", f"Given: {given}.", ""]
        if self.assumptions:
            lines += [
                "Assumed layout (the figure is not in the text; a different reading of the "
                "figure could give a different result):",
                "",
            ] + [f"- {a}" for a in self.assumptions] + [""]
        if self.conventions:
            lines += ["Conventions:", ""] + [f"- {c}" for c in self.conventions] + [""]
        for part in self.parts:
            lines += [f"**{part.title}**", ""]
            lines += [r.as_markdown() for r in part.results]
            if part.results:
                lines.append("")
            for remark in part.remarks:
                lines += [remark, ""]
        return "\n".join(lines).rstrip() + "\n"

    def _repr_markdown_(self):
        return self.as_markdown()


@dataclass(frozen=True)
class Exercise:
    """A textbook exercise stated as data, with a solver and a variant generator.

    Attributes
    ----------
    number : str
        The textbook's number, e.g. ``"2-3"``.
    title : str
        A short English title.
    tag : str
        How far the text fixes the answer: ``"N"`` (the text alone determines it), ``"A"``
        (the figure is needed and a layout is assumed) or ``"G"`` (a graphical exercise).
    statement : str
        The problem in English, a ``str.format`` template over the parameter names.
    parameters : tuple of Parameter
        The givens; their defaults are the textbook's numbers.
    solver : callable
        ``solver(params: dict) -> Solution``; raises ``ValueError`` when the numbers do
        not make a valid instance of the problem.
    sampler : callable
        ``sampler(rng: numpy.random.Generator) -> dict``, a candidate variant; candidates
        the solver rejects are drawn again.

    Notes
    -----
    Lengths are plain numbers in the exercise's unit (millimetres in chapter 2); angles in
    results are radians, shown in degrees only when rendered. The exercises of the book
    page ``book-exercises`` are the records in :mod:`mech.exercises.chapter2`.

    Examples
    --------
    >>> from mech.exercises import get
    >>> ex = get("2-6")
    >>> ex.defaults
    {'r': 30.0, 'l': 100.0, 'e': 20.0}
    >>> s = ex.solve(e=0.0)                      # override one given value
    >>> float(s["stroke, centric"].value)
    60.0
    >>> ex.variant(7) == ex.variant(7)           # a seed gives the same numbers
    True
    >>> ex.solve(r=90.0)
    Traceback (most recent call last):
    ...
    ValueError: Expected `r` + `e` < `l` so that the crank turns fully, got r + e = 110.0 >= l = 100.0
    """

    number: str
    title: str
    tag: str
    statement: str
    parameters: tuple
    solver: Callable = field(repr=False)
    sampler: Callable = field(repr=False)

    @property
    def defaults(self):
        """The textbook's givens as a dict of name to value."""
        return {p.name: p.default for p in self.parameters}

    def params(self, params=None, **overrides):
        """Return a complete dict of givens: defaults, updated by ``params`` and overrides."""
        out = self.defaults
        given = dict(params or {}, **overrides)
        unknown = sorted(set(given) - set(out))
        if unknown:
            raise ValueError(
                f"Expected parameters of exercise {self.number} among {', '.join(out)}, "
                f"got {unknown[0]!r}"
            )
        out.update({k: real_number(k, v) for k, v in given.items()})
        return out

    def statement_text(self, params=None, **overrides):
        """Return the statement with the given values filled in."""
        p = self.params(params, **overrides)
        return self.statement.format(**{k: _fmt_number(v) for k, v in p.items()})

    def solve(self, params=None, **overrides):
        """Solve the exercise for the textbook's numbers, or for the given ones.

        Raises
        ------
        ValueError
            If the givens make no valid instance of the exercise; the message names the
            given at fault, or every given with its value when the fault lies in a quantity
            derived from several of them. A result that would not be finite is refused so.
        AssemblyError
            If a pose of an analysed linkage cannot be assembled.
        """
        return self._run(self.params(params, **overrides))

    def _run(self, given):
        """The solver on complete givens: its `Solution` with units, or an error naming givens."""
        # floating-point warnings of a computation that ends in a named error are dropped (the
        # error says what is wrong); those of a solve that succeeds are passed on
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", RuntimeWarning)
            try:
                solution = self.solver(given)
            except (ValueError, ArithmeticError) as exc:
                failed = exc
            else:
                failed = None
        for w in caught:
            if failed is None or not issubclass(w.category, RuntimeWarning):
                warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
        try:
            if failed is not None:
                raise failed
        except AssemblyError:
            raise
        except (ValueError, ArithmeticError) as exc:
            # ArithmeticError: ZeroDivisionError, OverflowError, FloatingPointError
            if isinstance(exc, ValueError) and (getattr(exc, "_names_givens", False)
                                                or any(f"`{k}`" in str(exc) for k in given)):
                raise
            raise _naming_givens(self.number, given, f"({type(exc).__name__}: {exc})") from exc
        bad = [r.name for r in solution.results() if not _finite(r.value)]
        if bad:
            raise _naming_givens(self.number, given, f"(not finite: {', '.join(bad)})")
        return replace(solution, units={p.name: p.unit for p in self.parameters})

    def variant(self, rng=None, *, max_tries=1000):
        """Draw other valid givens (a dict) from ``rng`` (a Generator, a seed, or None)."""
        return self._solved_variant(rng, max_tries=max_tries)[0]

    def _solved_variant(self, rng=None, *, max_tries=1000):
        """`variant`'s givens and their `Solution` (the solve that accepted them, kept)."""
        max_tries = integer("max_tries", max_tries, minimum=1)
        if isinstance(rng, (bool, np.bool_, float, complex, str, bytes)):
            raise InputTypeError(f"Expected `rng` to be a Generator, an integer seed or None, got {rng!r}")
        try:
            rng = np.random.default_rng(rng)
        except (TypeError, ValueError) as exc:
            raise InputTypeError(f"Expected `rng` to be a Generator, an integer seed or None, got {rng!r} "
                                 f"({exc})") from None
        for _ in range(max_tries):
            candidate = self.params(self.sampler(rng))
            try:
                solution = self._run(candidate)
            except ValueError:
                continue
            return candidate, solution
        raise ValueError(f"Expected a valid variant of exercise {self.number} within `max_tries` = "
                         f"{max_tries} draws, got none")


def _finite(value):
    """False for a numeric result (number or array) with a NaN or infinite entry; True otherwise."""
    if value is None or isinstance(value, (str, bool, np.bool_)):
        return True
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        return True
    if arr.dtype.kind not in "fc":
        return True
    return bool(np.all(np.isfinite(arr)))


def _naming_givens(number, given, why):
    """A ValueError that names every given of exercise ``number`` with its value, and why."""
    listed = [f"`{k}`" for k in given]
    names = ", ".join(listed[:-1]) + " and " + listed[-1] if len(listed) > 1 else listed[0]
    shown = ", ".join(f"{k}={v!r}" for k, v in given.items())
    err = ValueError(f"Expected {names} for which exercise {number} can be solved, got {shown} {why}")
    err._names_givens = True
    return err


def check_links_close(*, resolved=False, **links):
    """Raise ValueError naming, with the exercise's own names, a link not shorter than the
    other three together (the library's checks call them `a`, `b`, `c`, `d`); with
    ``resolved=True`` also one below 2**-1074 times the longest, which the limit positions
    and transmission extremes cannot resolve."""
    longest = max(links.values())
    for name, x in links.items():
        if resolved and math.ldexp(x, -math.frexp(longest)[1]) == 0.0:
            raise ValueError(f"Expected `{name}` at least 2**-1074 times the longest link ({longest!r}) so "
                             f"that the linkage can be solved, got {x!r}")
        rest = math.fsum(v for k, v in links.items() if k != name)   # not total - x: 0.0 beside 1e300
        if not x < rest:
            others = " + ".join(f"`{k}`" for k in links if k != name)
            shown = ", ".join(f"{k}={v!r}" for k, v in links.items())
            raise ValueError(f"Expected `{name}` shorter than the other three links together ({others} = "
                             f"{rest!r}), got {shown}")


#: Every exercise by its number, filled by `register` when `mech.exercises` is imported (the
#: package imports the chapters, which build on this module, so the table is full before a
#: solver runs).
_BY_NUMBER = {}


def register(exercises):
    """Record `exercises` by number, for the messages of `names_givens`."""
    _BY_NUMBER.update((ex.number, ex) for ex in exercises)


def names_givens(number):
    """Decorate a solver or layout function of exercise ``number`` (its first argument the
    givens, complete or partial) so that an error raised deeper down, which names the
    library's own arguments or none (`a`, "a pose that does not close", a ZeroDivisionError),
    is raised again as a ValueError that names every given of the exercise in backticks with
    the values used. A message that already names a given in backticks passes unchanged, and
    so does an `AssemblyError` (a pose that cannot be assembled, by input)."""
    def decorate(func):
        @functools.wraps(func)
        def wrapper(params=None, *args, **kwargs):
            try:
                return func(params, *args, **kwargs)
            except AssemblyError:
                raise
            except (ValueError, ZeroDivisionError, OverflowError, FloatingPointError) as exc:
                if getattr(exc, "_names_givens", False):
                    raise
                given = _BY_NUMBER[number].params(params)
                msg = str(exc)
                if isinstance(exc, ValueError) and any(f"`{k}`" in msg for k in given):
                    raise
                listed = [f"`{k}`" for k in given]
                names = ", ".join(listed[:-1]) + " and " + listed[-1] if len(listed) > 1 else listed[0]
                shown = ", ".join(f"{k}={v!r}" for k, v in given.items())
                err = ValueError(f"Expected {names} of an assumed layout of exercise {number} that closes "
                                 f"and can be solved, got {shown} ({type(exc).__name__}: {msg})")
                err._names_givens = True
                raise err from exc
        return wrapper
    return decorate
