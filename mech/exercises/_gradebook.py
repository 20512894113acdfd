"""A whole class graded in one call, and its gradebook CSV.

Kept apart from ``_grade`` (answers, units, answer files) because it solves each student's
variant through ``_sheet``, which itself judges answers with ``_grade``: here the two meet
without an import cycle.
"""

from __future__ import annotations

import csv
from pathlib import Path

from mech.exercises._grade import Entry, Verdict, judge  # noqa: F401
from mech.exercises._sheet import _lookup, _spelt_keys, answer_quantities, solved_variant

__all__ = ["grade_class", "gradebook_rows", "write_gradebook"]


def grade_class(entries, *, rtol=0.01, atol=0.01):
    """Grade every `Entry` against its student's variant; return a list of (Entry, Verdict).

    Each student's variant is solved once per exercise. An entry whose seed, exercise or
    answer name is bad is graded "malformed", with the reason.
    """
    from mech.exercises import get

    solved = {}
    out = []
    for e in entries:
        def bad(why):
            out.append((e, Verdict(None, None, False, e.text if e.key == "" else f"{e.key} = {e.text!r}",
                                   "malformed", why)))
        if e.key == "":
            bad(f"expected a line KEY = VALUE, got {e.text!r}")
            continue
        try:
            seed = int(str(e.seed).strip())
            if seed < 0:
                raise ValueError
        except (TypeError, ValueError):
            bad(f"expected the student's seed, a whole number >= 0, got {e.seed!r}")
            continue
        if e.exercise is None:
            bad(f"expected the answer name as NUMBER:KEY (e.g. 2-3:K), got {e.key!r}")
            continue
        try:
            ex = get(e.exercise)
        except ValueError as err:
            bad(str(err))
            continue
        if (ex.number, seed) not in solved:
            _, solution = solved_variant(ex, seed)
            solved[ex.number, seed] = (answer_quantities(solution), _spelt_keys(solution))
        quantities, extra = solved[ex.number, seed]
        try:
            q = _lookup(quantities, e.key, ex.number, extra)
        except ValueError as err:
            bad(str(err))
            continue
        out.append((e, judge(q, e.text, rtol, atol)))
    return out


GRADEBOOK_COLUMNS = ("student", "seed", "exercise", "key", "quantity", "given", "given_in_unit", "expected",
                     "unit", "tolerance", "verdict", "why")


def gradebook_rows(graded):
    """The gradebook as a list of dicts with the keys of ``GRADEBOOK_COLUMNS``."""
    rows = []
    for e, v in graded:
        q = v.quantity
        rows.append({
            "student": e.student, "seed": e.seed, "exercise": e.exercise or "", "key": e.key,
            "quantity": q.name if q is not None else "", "given": e.text,
            "given_in_unit": "" if v.given is None else f"{v.given:.6g}",
            "expected": "" if q is None else f"{q.value:.6g}", "unit": "" if q is None else q.unit,
            "tolerance": "" if q is None else f"{v.tolerance:.4g}", "verdict": v.status, "why": v.why,
        })
    return rows


def write_gradebook(path, graded):
    """Write the gradebook CSV of `grade_class`'s result to ``path``; return its rows."""
    rows = gradebook_rows(graded)
    path = Path(path)
    try:
        with path.open("w", newline="", encoding="utf-8") as f:
            w = csv.DictWriter(f, GRADEBOOK_COLUMNS)
            w.writeheader()
            w.writerows(rows)
    except OSError as err:
        raise ValueError(f"Expected `path` to be a writable gradebook path, got {str(path)!r} ({err.strerror})") from None
    return rows
