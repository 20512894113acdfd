"""Problem sheets for a class, their answer keys, and checking a student's numbers.

A sheet gives every student their own variant of each chosen exercise. The variants come
from one class seed: student ``k`` gets the seed :func:`student_seeds` derives from it, and
the same seed reproduces that student's numbers with ``python -m mech.exercises variant``
or checks their answers with ``python -m mech.exercises check``. Only NumPy is imported
here; the HTML converter (markdown-it-py, which MyST already uses) is imported when HTML is
asked for.
"""

from __future__ import annotations

import math
import re
import unicodedata
from dataclasses import dataclass

import numpy as np

from mech._validate import integer, real_number
from mech.exercises._grade import Verdict

__all__ = [
    "DEFAULT_EXERCISES",
    "Quantity",
    "Verdict",
    "answer_quantities",
    "check_answers",
    "make_sheet",
    "markdown_to_html",
    "solved_variant",
    "student_seeds",
]

#: Exercises of a sheet when none are named: quick to solve, with numeric answers.
DEFAULT_EXERCISES = ("2-3", "2-6", "2-20", "2-24")

_GREEK = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon", "η": "eta",
    "θ": "theta", "λ": "lambda", "μ": "mu", "ρ": "rho", "φ": "phi", "ψ": "psi", "ω": "omega",
}


def _normal(text):
    """Lower case, Greek letters spelt out, every other run of symbols one underscore."""
    text = "".join(_GREEK.get(ch, ch) for ch in unicodedata.normalize("NFC", text.strip().lower()))
    return re.sub(r"[^0-9a-z]+", "_", text).strip("_")


@dataclass(frozen=True)
class Quantity:
    """A numeric answer of an exercise: its result name, the key to answer it by, its value
    in the unit a student uses (degrees for angles), that unit, what the key asks for, and
    other names that ``check`` accepts for it (the keys spelt before the vocabulary)."""

    name: str
    key: str
    value: float
    unit: str
    what: str = ""
    aliases: tuple = ()

    def tolerance(self, rtol=0.01, atol=0.01):
        """The absolute tolerance of this answer: ``rtol * |value| + atol``."""
        return rtol * abs(self.value) + atol


_SYMBOL = re.compile(r"[A-Z][A-Za-z0-9]{0,3}|[A-Za-z][A-Za-z0-9]*_[A-Za-z0-9_]+|[α-ω](?:_[A-Za-z0-9]+)?")


def _symbol(name):
    """The first word of a result name that reads as a symbol (K, H, l_AB, γ_min), or None."""
    for word in name.split():
        word = word.strip("(),:;")
        if _SYMBOL.fullmatch(word):
            return word
    return None


def _spelt_keys(solution):
    """The keys spelt from the result names (the scheme before the vocabulary), as
    ``Quantity`` records of every finite numeric result."""
    found = []
    for r in solution.results():
        v = r.value
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)):
            continue
        v = float(v)
        if not math.isfinite(v):
            continue
        unit = r.unit
        if unit == "rad":
            v, unit = math.degrees(v), "deg"
        found.append((r.name, v, unit))
    symbols = [_symbol(name) for name, _, _ in found]
    spelt = [None if s is None else "".join(_GREEK.get(ch, ch) for ch in s) for s in symbols]
    out, used = [], set()
    for (name, v, unit), key in zip(found, spelt):
        if key is None or sum(_normal(k or "") == _normal(key) for k in spelt) > 1:
            key = _normal(name) or "value"
        base, n = key, 1
        while _normal(key) in used:
            n += 1
            key = f"{base}_{n}"
        used.add(_normal(key))
        out.append(Quantity(name, key, v, unit))
    return tuple(out)


def answer_quantities(solution):
    """The answers that the statement of ``solution``'s exercise asks for, as a tuple of
    `Quantity`, keyed by the vocabulary of :mod:`mech.exercises._answers` (``gamma_min``,
    ``K``, ``l_AB`` ...). Angles are in degrees. Each quantity lists as aliases the key
    spelt from its result name before the vocabulary and the result's full name.
    """
    from mech.exercises._answers import answers

    spelt = {q.name: q.key for q in _spelt_keys(solution)}
    return tuple(Quantity(name, key, value, unit, what,
                          tuple(a for a in (spelt.get(name), name) if a and _normal(a) != _normal(key)))
                 for key, name, value, unit, what in answers(solution))


def _lookup(quantities, given, number, extra=()):
    """The quantity that the answer name ``given`` means: a key of the vocabulary, one of
    its aliases, or else a result outside the vocabulary by its spelt key or full name
    (``extra``, from `_spelt_keys`)."""
    exact = [q for q in quantities if q.key == given.strip()]
    if len(exact) == 1:                      # keys that differ in case only (H, h) stay apart
        return exact[0]
    want = _normal(given)
    for pool in ([q for q in quantities if want == _normal(q.key)],
                 [q for q in quantities if any(want == _normal(a) for a in q.aliases)],
                 [q for q in extra if want in (_normal(q.key), _normal(q.name))]):
        if len(pool) == 1:
            return pool[0]
        if len(pool) > 1:
            raise ValueError(f"Expected one quantity of exercise {number} for the answer name {given!r}, "
                             f"got several: {', '.join(q.key for q in pool)}; use one of these keys")
    keys = ", ".join(q.key for q in quantities)
    raise ValueError(f"Expected an answer name of exercise {number} among {keys}, got {given!r}")


def solved_variant(exercise, seed, *, max_tries=1000):
    """Draw the variant of ``seed`` (as ``exercise.variant(seed)`` does) and solve it.

    Returns ``(params, solution)``. The variant is solvable (the solver accepted it and
    checked it by analysis: simulation, closure or the defining equations, as each exercise
    states), and every numeric answer is finite; otherwise ``ValueError``.
    """
    # the solve that accepted the variant is the solution (no second solve of the same numbers)
    params, solution = exercise._solved_variant(seed, max_tries=max_tries)
    bad = [r.name for r in solution.results()
           if isinstance(r.value, (float, np.floating)) and not math.isfinite(float(r.value))]
    if bad:
        raise ValueError(f"Expected finite results for exercise {exercise.number} with seed {seed}, "
                         f"got {bad[0]!r} = {solution[bad[0]].value}")
    return params, solution


def student_seeds(seed, students):
    """The variant seed of each student of a class (a list of int, one per student).

    Derived from the class ``seed`` by NumPy's ``SeedSequence``, so one class seed always
    gives the same list, and lists for different class seeds are unrelated.
    """
    seed = integer("seed", seed, minimum=0)
    students = integer("students", students, minimum=1, maximum=1000)
    children = np.random.SeedSequence(seed).spawn(students)
    return [int(c.generate_state(1, np.uint32)[0] >> 1) for c in children]


def make_sheet(numbers=DEFAULT_EXERCISES, *, students=30, seed=0, title="Problem sheet"):
    """Build a problem sheet and its answer key as two Markdown strings.

    Parameters
    ----------
    numbers : sequence of str
        Exercise numbers, e.g. ``("2-3", "2-6")``.
    students : int
        Number of students (1 to 1000); each gets their own variant of every exercise.
    seed : int
        The class seed; see `student_seeds`.
    title : str
        Heading of both documents.

    Returns
    -------
    sheet, key : str
        The problems (numbers only) and the answer key (every solution, with the numbers
        to check and their keys for ``check``).
    """
    from mech.exercises import get

    if isinstance(numbers, str):
        numbers = (numbers,)
    exercises = [get(n) for n in numbers]
    if not exercises:
        raise ValueError("Expected `numbers` to name at least one exercise, got none")
    seeds = student_seeds(seed, students)
    head = (f"Class seed {seed}, {students} students. Each student has a seed of their own: "
            "`python -m mech.exercises check NUMBER --seed SEED --answer KEY=VALUE ...` "
            "checks answers against it (angles in degrees).")
    sheet = [f"# {title}", "", head, ""]
    key = [f"# {title}: answer key", "", head, ""]
    for k, s in enumerate(seeds, start=1):
        sheet += [f"## Student {k:02d} (seed {s})", ""]
        key += [f"## Student {k:02d} (seed {s})", ""]
        for ex in exercises:
            params, solution = solved_variant(ex, s)
            quantities = answer_quantities(solution)
            keys = "; ".join(f"`{q.key}` ({q.name})" for q in quantities)
            sheet += [f"### Exercise {ex.number}: {ex.title}", "", ex.statement_text(params), ""]
            if keys:
                sheet += [f"Answer keys for `check`: {keys}.", ""]
            key += [f"### Exercise {ex.number}", "", "| key | quantity | value |", "|---|---|---|"]
            key += [f"| `{q.key}` | {q.name} | {q.value:.6g} {q.unit} |" for q in quantities]
            key += ["", solution.as_markdown(), ""]
    return "\n".join(sheet).rstrip() + "\n", "\n".join(key).rstrip() + "\n"


def markdown_to_html(text, *, title="Problem sheet"):
    """Convert the Markdown of a sheet to a standalone HTML page (markdown-it-py, tables,
    ``$...$`` math kept as TeX in ``math`` elements; no file outside the page is loaded)."""
    from html import escape

    from markdown_it import MarkdownIt
    from mdit_py_plugins.dollarmath import dollarmath_plugin

    md = MarkdownIt("commonmark").enable("table").use(dollarmath_plugin)
    body = md.render(text)
    style = ("body{font-family:sans-serif;max-width:52em;margin:2em auto;line-height:1.45}"
             "table{border-collapse:collapse}td,th{border:1px solid #999;padding:2px 6px}"
             "h2{page-break-before:always;border-top:1px solid #ccc;padding-top:.5em}"
             ".math{font-family:serif}")
    return (f"<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<title>{escape(title)}</title>\n<style>{style}</style>\n</head>\n<body>\n{body}</body>\n</html>\n")


def check_answers(exercise, seed, answers, *, rtol=0.01, atol=0.01):
    """Check a student's answers for the variant ``seed`` of ``exercise``.

    Parameters
    ----------
    exercise : Exercise
    seed : int
        The student's seed (as on their sheet, or as given to ``variant``).
    answers : mapping or sequence of (str, float or str)
        Answer names (keys of the vocabulary, their aliases, or full result names) and
        values: numbers in the quantity's unit (degrees for angles), or text with a unit
        (``"0.5 rad"``, ``"1.2 m"``), converted.
    rtol, atol : float
        An answer is right when ``|given - value| <= rtol * |value| + atol`` (defaults: 1 %
        plus 0.01 in the quantity's unit); the same tolerance is written into quizzes.

    Returns
    -------
    tuple of Verdict
        One per answer; a value that does not read as a number with a fitting unit is
        graded "malformed", with the reason.

    Raises
    ------
    ValueError
        Naming an answer name that the exercise does not have, or a bad tolerance.
    """
    from mech.exercises._grade import judge

    rtol, atol = tolerances(rtol, atol)
    pairs = list(answers.items()) if hasattr(answers, "items") else list(answers)
    if not pairs:
        raise ValueError(f"Expected at least one answer NAME=VALUE for exercise {exercise.number}, got none")
    _, solution = solved_variant(exercise, seed)
    quantities, extra = answer_quantities(solution), _spelt_keys(solution)
    return tuple(judge(_lookup(quantities, name, exercise.number, extra), value, rtol, atol)
                 for name, value in pairs)


def tolerances(rtol, atol):
    """Checked ``(rtol, atol)``: real, not negative, not both zero."""
    rtol = real_number("rtol", rtol)
    atol = real_number("atol", atol)
    if rtol < 0 or atol < 0 or rtol + atol == 0:
        raise ValueError(f"Expected `rtol`, `atol` >= 0, not both zero, got rtol={rtol!r}, atol={atol!r}")
    return rtol, atol
