"""`mech.planar.export` rejects bad input by name: the table of its public callables (the format and
the check are in ``tests/public_inputs.py``).
"""

import functools

import pytest

import mech.planar as pl
import mech.planar.export as xp
from tests.public_inputs import E, assert_rejected_by_name, slotted

CASES = {}
RECORDS = {}


def _design():
    return xp.design_of(pl.FourBar(30, 70, 60, 80, coupler=(20, 10)))


def _tmp_file(suffix):
    import tempfile

    handle, name = tempfile.mkstemp(suffix=suffix)
    import os

    os.close(handle)
    return name


_CUT = {"link_width": "scalar?", "hole_diameter": "scalar?"}
CASES.update({
    "planar.export.design_of": E(lambda: xp.design_of, {"obj": "instance", "theta": "scalar?"},
                                 obj=pl.FourBar(30, 70, 60, 80), theta=0.5),
    "planar.export.Design.linkage": E(lambda: _design().linkage),
    "planar.export.Design.place": E(lambda: _design().place, {"w": "point"}, w=[1.0, 2j]),
    "planar.export.to_json": E(lambda: functools.partial(xp.to_json, _design()), _CUT, link_width=4.0,
                               hole_diameter=2.0),
    "planar.export.from_json": E(lambda: functools.partial(xp.from_json, xp.to_json(_design()))),
    "planar.export.svg_text": E(lambda: functools.partial(xp.svg_text, _design()), _CUT, link_width=4.0,
                                hole_diameter=2.0),
    "planar.export.write_json": E(lambda: functools.partial(xp.write_json, _design(), _tmp_file(".json"))),
    "planar.export.read_json": E(lambda: functools.partial(xp.read_json, _json_file())),
    "planar.export.write_svg": E(lambda: functools.partial(xp.write_svg, _design(), _tmp_file(".svg"))),
    "planar.export.write_dxf": E(lambda: functools.partial(xp.write_dxf, _design(), _tmp_file(".dxf")), _CUT,
                                 link_width=4.0, hole_diameter=2.0),
})
RECORDS["planar.export.Design"] = "result record built by the package (design_of)"


def _json_file():
    name = _tmp_file(".json")
    xp.write_json(_design(), name)
    return name



@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", slotted(CASES))
def test_bad_values_rejected_by_name(key):
    assert_rejected_by_name(CASES, key)
