"""Textbook exercises with generated solutions and variants (chapter 2: 2-1 to 2-32).

Each exercise is an :class:`Exercise` record: a statement with named givens (the
textbook's numbers by default), a solver built on :mod:`mech.planar`, and a generator of
other valid numbers. Solutions render themselves as Markdown.

>>> import mech.exercises as ex
>>> list(ex.EXERCISES)
['2-1', '2-2', '2-3', '2-4', '2-5', '2-6', '2-7', '2-8', '2-9', '2-10', '2-11', '2-12', '2-13', '2-14', '2-15', '2-16', '2-17', '2-18', '2-19', '2-20', '2-21', '2-22', '2-23', '2-24', '2-25', '2-26', '2-27', '2-28', '2-29', '2-30', '2-31', '2-32']
>>> sol = ex.get("2-3").solve()
>>> round(float(sol["time ratio K"].value), 4)
1.2299

From the command line: ``python -m mech.exercises list``, ``... show 2-3``,
``... variant 2-3 --seed 7``, and for a class ``... sheet --students 30 --seed 2026 --out DIR``
(one variant per student, with an answer key) and ``... check 2-3 --seed 7 --answer K=1.2``.
"""

from types import MappingProxyType

from mech.exercises import (chapter2, chapter2_analysis, chapter2_instant_centres, chapter2_reactions,
                            chapter2_relative_motion, examples_chapter2, examples_chapter2_more)
from mech.exercises._core import Exercise, Interval, Parameter, Part, Result, Solution
from mech.exercises._core import register as _register

__all__ = [
    "EXAMPLES",
    "EXERCISES",
    "Exercise",
    "Interval",
    "Parameter",
    "Part",
    "Result",
    "Solution",
    "chapter2",
    "chapter2_analysis",
    "chapter2_instant_centres",
    "chapter2_reactions",
    "chapter2_relative_motion",
    "examples_chapter2",
    "examples_chapter2_more",
    "get",
]

#: Every exercise with a generated solution, keyed by the textbook's number.
EXERCISES = MappingProxyType({ex.number: ex for ex in chapter2.EXERCISES})
#: The textbook's worked examples with variants, keyed ``E2-1``, ``E2-2`` ... (the same
#: records, so that sheets and quizzes take them; see `mech.exercises.examples_chapter2`).
EXAMPLES = MappingProxyType({ex.number: ex for ex in sorted(
    examples_chapter2.EXAMPLES + examples_chapter2_more.EXAMPLES, key=lambda ex: int(ex.number[3:]))})
_register(EXERCISES.values())
_register(EXAMPLES.values())


def get(number):
    """Return the :class:`Exercise` with the textbook's number ``number``, e.g. ``"2-3"``, or
    the worked example ``"E2-1"`` (an example's number with the prefix E).

    Raises
    ------
    ValueError
        If no exercise has that number; the message lists the known numbers.

    Examples
    --------
    >>> get("2-2").title
    'Ranges of the crank length for each type of four-bar'
    >>> get("2-99")
    Traceback (most recent call last):
    ...
    ValueError: Expected `number` among 2-1, 2-2, 2-3, 2-4, 2-5, 2-6, 2-7, 2-8, 2-9, 2-10, 2-11, 2-12, 2-13, 2-14, 2-15, 2-16, 2-17, 2-18, 2-19, 2-20, 2-21, 2-22, 2-23, 2-24, 2-25, 2-26, 2-27, 2-28, 2-29, 2-30, 2-31, 2-32 (or a worked example among E2-1, E2-2, E2-3, E2-4, E2-5, E2-7, E2-8, E2-9, E2-11, E2-12, E2-14, E2-17, E2-18, E2-19, E2-20, E2-25), got '2-99'
    """
    key = number.strip() if isinstance(number, str) else None
    if key is not None and key[:1] in "eE" and key[1:] in {k[1:] for k in EXAMPLES}:
        return EXAMPLES["E" + key[1:]]
    if key not in EXERCISES:
        raise ValueError(f"Expected `number` among {', '.join(EXERCISES)} (or a worked example among "
                         f"{', '.join(EXAMPLES)}), got {number!r}")
    return EXERCISES[key]
