"""Grading: answers with units, answer files and class CSVs, and the gradebook.

An answer is a number with an optional unit (``32.07deg``, ``0.56 rad``, ``1.2 m``,
``15 N*m``); it is converted to the unit of the quantity it answers, so a student may
answer in radians or metres. A class is graded in one call: :func:`read_answers` reads a
CSV with a row per student (or text files, one per student), :func:`grade_class` checks
every entry against the student's own variant (``_gradebook``, which needs the solved
variants of ``_sheet``), and :func:`write_gradebook` writes a CSV
with a row per student and quantity: what was given, the expected value, the tolerance,
the verdict and why. A malformed entry (not a number, a unit of the wrong kind, an unknown
answer name, a bad seed) is graded "malformed" with the student, the quantity and the text
named. Only the standard library and NumPy are used here.
"""

from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass
from pathlib import Path

__all__ = ["UNITS", "Entry", "Verdict", "convert", "parse_answer", "read_answers"]

_DEG = math.pi / 180.0
#: Unit spellings a student may use -> (kind, factor to the kind's base unit). Bases: deg,
#: mm, N, N·m, m/s, m/s², rad/s, rad/s², mm/s, and no unit.
UNITS = {
    "deg": ("angle", 1.0), "degree": ("angle", 1.0), "degrees": ("angle", 1.0), "°": ("angle", 1.0),
    "rad": ("angle", 1.0 / _DEG), "radian": ("angle", 1.0 / _DEG), "radians": ("angle", 1.0 / _DEG),
    "mm": ("length", 1.0), "cm": ("length", 10.0), "m": ("length", 1000.0),
    "N": ("force", 1.0), "kN": ("force", 1000.0),
    "N·m": ("moment", 1.0), "N m": ("moment", 1.0), "N*m": ("moment", 1.0), "Nm": ("moment", 1.0),
    "N.m": ("moment", 1.0), "N mm": ("moment", 1e-3), "N*mm": ("moment", 1e-3), "N·mm": ("moment", 1e-3),
    "Nmm": ("moment", 1e-3), "kN m": ("moment", 1e3), "kN*m": ("moment", 1e3), "kN·m": ("moment", 1e3),
    "m/s": ("speed", 1.0), "mm/s": ("speed", 1e-3),
    "m/s²": ("acceleration", 1.0), "m/s^2": ("acceleration", 1.0), "m/s2": ("acceleration", 1.0),
    "mm/s²": ("acceleration", 1e-3), "mm/s^2": ("acceleration", 1e-3), "mm/s2": ("acceleration", 1e-3),
    "rad/s": ("angular speed", 1.0), "1/s": ("angular speed", 1.0), "deg/s": ("angular speed", _DEG),
    "rpm": ("angular speed", 2 * math.pi / 60), "r/min": ("angular speed", 2 * math.pi / 60),
    "rad/s²": ("angular acceleration", 1.0), "rad/s^2": ("angular acceleration", 1.0),
    "rad/s2": ("angular acceleration", 1.0), "deg/s^2": ("angular acceleration", _DEG),
    "": ("number", 1.0), "%": ("number", 0.01),
}
_KIND_OF_QUANTITY = {"deg": "angle", "mm": "length", "N": "force", "N·m": "moment", "m/s": "speed",
                     "mm/s": "speed", "m/s²": "acceleration", "mm/s²": "acceleration", "rad/s": "angular speed",
                     "rad/s²": "angular acceleration", "": "number"}
_SHOWN = {"angle": "deg, degrees, rad", "length": "mm, cm, m", "force": "N, kN", "moment": "N m, N*m, N mm",
          "speed": "m/s, mm/s", "acceleration": "m/s^2, mm/s^2", "angular speed": "rad/s, rpm",
          "angular acceleration": "rad/s^2", "number": "no unit"}
_NUMBER = re.compile(r"\s*([-+−]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*")


def _unit_key(text):
    """A unit spelling as the table writes it (spaces squeezed, 'deg'/'Deg' alike)."""
    text = re.sub(r"\s+", " ", text.strip())
    if text in UNITS:
        return text
    low = {k.lower(): k for k in UNITS if k not in ("N", "kN", "m", "mm", "cm")}
    return low.get(text.lower())


def parse_answer(text, unit):
    """Read ``text`` (a number with an optional unit) as a value in ``unit``, the unit of the
    quantity it answers (``"deg"``, ``"mm"``, ``"N·m"``, ``"m/s"`` ...).

    Returns
    -------
    float

    Raises
    ------
    ValueError
        When the text is not a number, the unit is unknown, or it measures another kind of
        quantity; the message quotes the text.

    Examples
    --------
    >>> round(parse_answer("0.5 rad", "deg"), 4)
    28.6479
    >>> parse_answer("1.2 m", "mm")
    1200.0
    >>> parse_answer("15 N*m", "N·m")
    15.0
    >>> parse_answer("3 N", "deg")
    Traceback (most recent call last):
    ...
    ValueError: Expected an angle (deg, degrees, rad), got '3 N' (a force)
    """
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        value = float(text)
        if not math.isfinite(value):
            raise ValueError(f"Expected `text` to be a finite number, got {text!r}")
        return value
    if not isinstance(text, str):
        raise ValueError(f"Expected `text` to be a number with an optional unit, got {text!r}")
    m = _NUMBER.fullmatch(text)
    if not m:
        raise ValueError(f"Expected `text` to be a number with an optional unit, got {text!r}")
    if m.group(2)[:1] in set("0123456789.,+-−"):
        raise ValueError(f"Expected `text` to be a number with an optional unit, got {text!r}")
    value = float(m.group(1).replace("−", "-"))
    if not math.isfinite(value):                 # "1e400" reads as infinity
        raise ValueError(f"Expected `text` to be a finite number, got {text!r}")
    spelt = _unit_key(m.group(2))
    if spelt is None:
        raise ValueError(f"Expected `text` in a known unit (deg, rad, mm, m, N, N m, N mm, m/s, m/s^2, rad/s, rpm ...), "
                         f"got {text!r}")
    kind, factor = UNITS[spelt]
    want = _KIND_OF_QUANTITY.get(unit, "number")
    if not m.group(2):
        return value                         # a bare number is in the quantity's own unit
    if kind != want:
        names = _SHOWN.get(want, "no unit")
        article = "an" if want[0] in "aeiou" else "a"
        raise ValueError(f"Expected {article} {want} ({names or 'no unit'}), got {text!r} (a {kind})")
    base = UNITS.get(unit, (want, 1.0))[1]
    return value * factor / base


def convert(text, unit):
    """`parse_answer`, returning ``(value, None)`` or ``(None, why)`` instead of raising."""
    try:
        return parse_answer(text, unit), None
    except ValueError as err:
        return None, str(err)


@dataclass(frozen=True)
class Entry:
    """One answer of one student: who (name and seed), which exercise and key, the text."""

    student: str
    seed: object
    exercise: str
    key: str
    text: str


@dataclass(frozen=True)
class Verdict:
    """One graded answer. ``status`` is ``"right"``, ``"wrong"``, ``"missing"`` or
    ``"malformed"``; ``why`` says why in words; ``quantity`` is None when the name is not an
    answer of the exercise."""

    quantity: object
    given: float | None
    right: bool
    text: str = ""
    status: str = ""
    why: str = ""
    tolerance: float = math.nan

    def line(self):
        q = self.quantity
        unit = f" {q.unit}" if q is not None and q.unit else ""
        if q is None:
            return f"MALFORMED  {self.text}: {self.why}"
        if self.status == "malformed":
            return f"MALFORMED  {q.key} ({q.name}) = {self.text!r}: {self.why}"
        if self.right:
            return f"right  {q.key} ({q.name}) = {self.given:g}{unit}"
        if self.given is None:
            return f"MISSING  {q.key} ({q.name})"
        sense = "too high" if self.given > q.value else "too low"
        return f"WRONG  {q.key} ({q.name}) = {self.given:g}{unit}: {sense}"


def judge(q, text, rtol, atol):
    """Grade one answer ``text`` against the quantity ``q``."""
    tol = q.tolerance(rtol, atol)
    if text is None or (isinstance(text, str) and not text.strip()):
        return Verdict(q, None, False, "", "missing", "no answer given", tol)
    value, why = convert(text, q.unit)
    if value is None:
        return Verdict(q, None, False, str(text), "malformed", why, tol)
    err = value - q.value
    if abs(err) <= tol:
        return Verdict(q, value, True, str(text), "right", f"off by {abs(err):.4g} <= tolerance {tol:.4g}", tol)
    sense = "too high" if err > 0 else "too low"
    return Verdict(q, value, False, str(text), "wrong", f"{sense} by {abs(err):.4g} > tolerance {tol:.4g}", tol)


# ----------------------------------------------------------------------------- reading
def _split_name(name, exercise):
    """``"2-3:K"`` -> ("2-3", "K"); a bare ``"K"`` belongs to ``exercise``."""
    number, sep, key = name.partition(":")
    if sep and re.fullmatch(r"\s*\d+-\d+\s*", number):
        return number.strip(), key.strip()
    return exercise, name.strip()


def read_answers(path, *, exercise=None):
    """Read answers from a file: a CSV with a row per student (``.csv``), or a text file of
    one student.

    The CSV has a column ``student`` (a name or number), a column ``seed`` (the student's
    seed, as on their sheet) and one column per answer, headed ``NUMBER:KEY`` (``2-3:K``), or
    just ``KEY`` when ``exercise`` is given. A text file holds lines ``student = NAME``,
    ``seed = SEED`` and ``KEY = VALUE`` (or ``NUMBER:KEY = VALUE``); ``#`` starts a comment.

    Returns
    -------
    list of Entry
        Every answer, empty cells included (graded "missing").
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as err:
        raise ValueError(f"Expected `path` to be a readable answer file, got {str(path)!r} ({err.strerror})") from None
    entries = []
    if path.suffix.lower() == ".csv":
        rows = list(csv.reader(io.StringIO(text)))
        if not rows:
            raise ValueError(f"Expected `path` to begin with a header row, got an empty file {str(path)!r}")
        head = [h.strip() for h in rows[0]]
        low = [h.lower() for h in head]
        if "seed" not in low:
            raise ValueError(f"Expected a column `seed` in {str(path)!r}, got columns {', '.join(head)}")
        i_seed = low.index("seed")
        i_student = low.index("student") if "student" in low else None
        for n, row in enumerate(rows[1:], start=2):
            if not any(c.strip() for c in row):
                continue
            row = row + [""] * (len(head) - len(row))
            who = row[i_student].strip() if i_student is not None else f"row {n}"
            for j, h in enumerate(head):
                if j in (i_seed, i_student) or not h:
                    continue
                number, key = _split_name(h, exercise)
                entries.append(Entry(who, row[i_seed].strip(), number, key, row[j].strip()))
        return entries
    who, seed = path.stem, None
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        name, sep, value = line.partition("=")
        if not sep:
            entries.append(Entry(who, seed, exercise, "", line))   # graded "malformed"
            continue
        name, value = name.strip(), value.strip()
        if name.lower() == "student":
            who = value
        elif name.lower() == "seed":
            seed = value
        else:
            number, key = _split_name(name, exercise)
            entries.append(Entry(who, seed, number, key, value))
    # the seed may come after the answers in the file: it holds for the whole file
    return [Entry(who, seed, e.exercise, e.key, e.text) for e in entries]
