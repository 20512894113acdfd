"""The bad values, the table format and the check shared by the public-input tests (issue 11).

Every public callable of the package has an entry in a table ``CASES`` of the test file that
mirrors its subpackage (``tests/planar/test_planar_public_inputs.py`` for `mech.planar`, and
so on): a valid call, and the kind of each numeric argument ("slot"). For each slot the
valid value is replaced, one at a time, by bad values of every kind that makes no sense there
(complex, a string of a number, a boolean, None, an object, NaN, infinities, lists with a
string inside, ragged lists, dicts, wrong shapes ...). The call must raise ``ValueError`` or
``TypeError`` (this includes ``mech.InputTypeError`` and ``mech.AssemblyError``) whose message
names the argument in backticks and shows the bad value. The valid call must still succeed,
so a check that is too strict fails too. ``tests/test_public_inputs.py`` gathers the tables
and checks that every public callable is registered in one of them.
"""

import dataclasses
import math
import re

import numpy as np

import mech.planar as pl
import mech.spatial as sp
import mech.spherical as sph

__all__ = ["BAD", "KINDS", "Entry", "E", "bad_kinds", "check", "all_cases", "assert_rejected_by_name", "slotted", "first",
           "second2", "Opaque", "fourbar", "slider", "linkage", "rssr", "sfb", "sph_sixbar", "THETA", "MOTION",
           "MOTION2", "ABCD"]


# ----------------------------------------------------------------------------- bad values
class Opaque:
    def __repr__(self):
        return "<opaque object>"


#: name -> (value, texts of which the message must show one)
BAD = {
    "complex": (0.5 + 2j, ["0.5+2j"]),
    "complex_array": (np.array([0.5 + 2j]), ["0.5+2"]),
    "complex_zero_imag": (1 + 0j, ["1+0j", "1.+0.j"]),
    "numeric_string": ("10", ["'10'"]),
    "true": (True, ["True"]),
    "false": (False, ["False"]),
    "bool_array": (np.array([True, False]), ["True"]),
    "none": (None, ["None"]),
    "object": (Opaque(), ["<opaque object>"]),
    "nan": (math.nan, ["nan"]),
    "inf": (math.inf, ["inf"]),
    "-inf": (-math.inf, ["-inf"]),
    "complex_nan": (complex(math.nan, 0.0), ["nan"]),
    "complex_inf": (complex(0.0, math.inf), ["inf"]),
    "list_with_string": ([1.0, "a"], ["'a'"]),
    "empty_list": ([], ["[]", "(0,)"]),
    "ragged": ([[1.0], [1.0, 2.0]], ["[[1.0], [1.0, 2.0]]"]),
    "dict": ({}, ["{}"]),
    "short_vector": ([1.0, 2.0], ["[1.0, 2.0]", "(2,)", "[1. 2.]"]),
    "matrix_4x4": (np.eye(4), ["(4, 4)"]),
    "float_for_int": (2.5, ["2.5"]),
    "negative_int": (-1, ["-1"]),
    "large_int": (10**6, ["1000000"]),
    "zero_branch": (0, ["0"]),
    "two_branch": (2, ["2"]),
    "one_string": ("1", ["'1'"]),
    "int_for_bool": (1, ["1"]),
    "bogus_option": ("bogus", ["'bogus'"]),
    # NumPy reads the data under a mask, registers timedelta64 as an integer type, and
    # overflows on an int beyond the float range inside a list (audit of issue 11)
    "masked": (np.ma.array([0.5, 1.0], mask=[False, True]), ["--"]),
    "timedelta": (np.timedelta64(5, "s"), ["timedelta64"]),
    "huge_int_list": ([1.0, 10**400], ["10000000000"]),
}

_NUMERIC = ["complex", "complex_array", "complex_zero_imag", "numeric_string", "true", "false",
            "bool_array", "none", "object", "nan", "inf", "-inf", "list_with_string", "ragged",
            "dict", "masked", "timedelta", "huge_int_list"]
_POINT = ["numeric_string", "true", "false", "bool_array", "none", "object", "nan", "inf",
          "-inf", "complex_nan", "complex_inf", "list_with_string", "ragged", "dict", "masked",
          "timedelta", "huge_int_list"]

#: slot kind -> bad kinds tried there
KINDS = {
    "real": _NUMERIC,                                   # a real number or array
    "scalar": _NUMERIC + ["empty_list"],                # exactly one real number
    "realmap": [b for b in _NUMERIC if b != "dict"],    # real, or a mapping by driver
    "scalarmap": [b for b in _NUMERIC if b != "dict"] + ["empty_list"],  # one number, or a mapping
    "point": _POINT,                                    # planar points: complex allowed
    "point1": _POINT + ["empty_list"],                  # exactly one planar point
    "point_or_name": _POINT + ["empty_list"],           # one planar point, or a point's name
    "length_or_name": _NUMERIC + ["empty_list"],        # one length, or a driver's name
    "vec3": _NUMERIC + ["short_vector", "matrix_4x4"],  # shape (..., 3)
    "matrix": _NUMERIC + ["short_vector", "matrix_4x4"],  # a fixed shape (3, 3)
    "int": ["float_for_int", "true", "numeric_string", "none", "object", "complex", "nan",
            "bool_array", "dict", "empty_list", "timedelta"],
    "count": ["float_for_int", "negative_int", "true", "numeric_string", "none", "object",
              "complex", "nan", "dict", "timedelta"],
    "order": ["float_for_int", "negative_int", "two_branch_over", "true", "numeric_string",
              "none", "object", "complex", "timedelta"],
    "bool": ["int_for_bool", "one_string", "none", "object", "bool_array", "float_for_int"],
    "branch": ["true", "false", "zero_branch", "two_branch", "one_string", "none", "object",
               "float_for_int", "complex", "timedelta"],
    "option": ["bogus_option", "int_for_bool", "none", "object"],
    "tolerance": [b for b in _NUMERIC if b != "inf"] + ["empty_list"],  # one number; inf skips a check
    "real_nan": [b for b in _NUMERIC if b != "nan"],    # NaN passes through (did not assemble)
    "function": ["none", "object", "numeric_string", "complex", "dict", "true"],  # a callable
    "instance": ["none", "object", "numeric_string", "complex", "dict", "true"],  # a package object
    "seed": ["float_for_int", "true", "numeric_string", "object", "complex", "nan", "dict", "negative_int"],
}
BAD["two_branch_over"] = (3, ["3"])



# ----------------------------------------------------------------------------- the table
@dataclasses.dataclass
class Entry:
    """A valid call ``get()(**kwargs)`` and the kind of each numeric argument.

    ``slots`` maps an argument name to its kind, or to ``(kind, wrap)`` where ``wrap``
    puts a bad value where it belongs inside the argument (a tuple, a mapping ...), or to
    ``(kind, wrap, shown)`` when the message names the argument as ``shown``.
    """

    get: object
    kwargs: dict
    slots: dict = dataclasses.field(default_factory=dict)

    def call(self, **changes):
        return self.get()(**{**self.kwargs, **changes})

    def slot(self, name):
        """``(kind, wrap, shown)`` of the argument ``name``."""
        spec = self.slots[name]
        if isinstance(spec, str):
            return spec, (lambda v: v), name
        if len(spec) == 2:
            return spec[0], spec[1], name
        return spec


def E(get, slots=None, **kwargs):
    return Entry(get, kwargs, slots or {})


def first(v):
    return (v, 1.0)


def second2(v):
    return (0.3, v)



# ----------------------------------------------------------------------------- linkages used by several tables
def fourbar():
    return pl.FourBar(10, 40, 30, 35, coupler=(20, 10))


def slider():
    return pl.SliderCrank(30, 100, 20)


def linkage():
    return (pl.Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(40, 30)))


def sfb():
    return sph.SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.5))


def rssr():
    return sp.RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0)


def sph_sixbar():
    return sph.stephenson1(0.3, 0.9, 0.7, 1.0, E=(0.2, 0.8), F=(0.3, -1.0), arcs=(0.8, 0.7), coupler=(0.4, 0.5))


THETA = {"theta": "real"}
MOTION = {"theta": "real", "order": "order", "omega": "real", "alpha": "real", "strict": "bool"}
MOTION2 = dict(theta=[0.0, 1.0], order=2, omega=1.5, alpha=0.5, strict=False)
ABCD = {"a": "scalar", "b": "scalar", "c": "scalar", "d": "scalar"}


# ----------------------------------------------------------------------------- the check
def _name_pattern(shown):
    # The argument in backticks, maybe followed by an index or a qualifier
    # (`lengths[1] ...`, `at.real`, `length of crank`).
    return re.compile("`" + re.escape(shown) + r"[`\[ .]")


def check(entry, key, slot, bad_name, value=None, texts=None):
    """None if calling `entry` with `slot` bad raises an error that names it and shows the value,
    else the problem (`key` names the entry in the report)."""
    kind, wrap, shown = entry.slot(slot)
    if value is None and texts is None:
        value, texts = BAD[bad_name]
    try:
        entry.call(**{slot: wrap(value)})
    except (ValueError, TypeError) as exc:
        msg = str(exc)
        problems = []
        if not _name_pattern(shown).search(msg):
            problems.append(f"does not name `{shown}`")
        if not any(t in msg for t in texts):
            problems.append(f"does not show the value (one of {texts})")
        if problems:
            return f"{key}({slot}={bad_name}): {type(exc).__name__} {', '.join(problems)}: {msg!r}"
        return None
    except Exception as exc:  # noqa: BLE001 - the point is to report any other exception
        return f"{key}({slot}={bad_name}): bare {type(exc).__name__}: {exc}"
    return f"{key}({slot}={bad_name}): accepted {value!r}"


def bad_kinds(kind):
    """The bad kinds for a slot kind; a trailing "?" means None is a valid value there."""
    if kind.endswith("?"):
        return [b for b in KINDS[kind[:-1]] if b != "none"]
    return KINDS[kind]


def all_cases(cases):
    """Every ``(key, slot, bad kind)`` of the table `cases`."""
    for key, entry in cases.items():
        for slot in entry.slots:
            for bad_name in bad_kinds(entry.slot(slot)[0]):
                yield key, slot, bad_name


def slotted(cases):
    """The keys of `cases` with at least one numeric argument, sorted."""
    return sorted(k for k in cases if cases[k].slots)


def assert_rejected_by_name(cases, key):
    """Every bad value tried in every slot of ``cases[key]`` is refused by a message that
    names the argument and shows the value; the failure lists each one that is not."""
    entry = cases[key]
    failures = [f for slot in entry.slots for bad_name in bad_kinds(entry.slot(slot)[0])
                for f in [check(entry, key, slot, bad_name)] if f]
    assert not failures, "\n".join(failures)
