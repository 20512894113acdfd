"""Every public callable rejects every kind of bad input by name (issue 11).

The test walks ``__all__`` of ``mech`` and its subpackages (and the public methods of the
public classes). Each callable has an entry in ``CASES``: a valid call, and the kind of
each numeric argument ("slot"). For each slot the valid value is replaced, one at a time,
by bad values of every kind that makes no sense there (complex, a string of a number, a
boolean, None, an object, NaN, infinities, lists with a string inside, ragged lists, dicts,
wrong shapes ...). The call must raise ``ValueError`` or ``TypeError`` (this includes
``mech.InputTypeError`` and ``mech.AssemblyError``) whose message names the argument in
backticks and shows the bad value. The valid call must still succeed, so a check that is
too strict fails too. A completeness check makes every new public callable register here.
"""

import dataclasses
import functools
import warnings
import inspect
import math
import re
from types import ModuleType

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import mech
import mech.exercises as ex
import mech.planar as pl
import mech.spatial as sp
import mech.spherical as sph
import mech.planar.synthesis as sy
import mech.atlas as at
import mech.planar.export as xp
from mech.exercises import (chapter2, chapter2_analysis, chapter2_instant_centres, chapter2_quick_return,
                            chapter2_reactions, chapter2_relative_motion, chapter2_synthesis)

MODULES = {"mech": mech, "planar": pl, "spatial": sp, "spherical": sph, "exercises": ex,
           "exercises.chapter2": chapter2, "exercises.chapter2_analysis": chapter2_analysis,
           "planar.synthesis": sy, "exercises.chapter2_synthesis": chapter2_synthesis,
           "exercises.chapter2_quick_return": chapter2_quick_return,
           "exercises.chapter2_relative_motion": chapter2_relative_motion,
           "exercises.chapter2_reactions": chapter2_reactions,
           "exercises.chapter2_instant_centres": chapter2_instant_centres, "atlas": at,
           "planar.export": xp}


# ----------------------------------------------------------------------------- bad values
class _Opaque:
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
    "object": (_Opaque(), ["<opaque object>"]),
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


def _sph_path_task():
    x = np.array([0.3, 1.2, 0.4, 0.5, 1.1, 0.9, 1.2, 0.6, 0.8])
    m = sph.SphericalFourBar(*x[3:7], coupler=tuple(x[7:]), frame=sph.ground_frame(*x[:3]))
    th = np.linspace(0.2, 1.2, 4)
    return m.solve(th).P, th, x + 0.02


def _sph_path6_task():
    from mech.spherical.path._synthesis import _stephenson

    x = np.array([0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.2, 0.8, 0.3, -1.0, 0.8, 0.7, 0.4, 0.5])
    th = np.linspace(0.0, 1.2, 5)
    return _stephenson(x, (1, 1)).solve(th).points["P"], th, x + 0.01


_SPH_PATH = _sph_path_task()
_SPH_PATH6 = _sph_path6_task()


def _fourbar():
    return pl.FourBar(10, 40, 30, 35, coupler=(20, 10))


def _slider():
    return pl.SliderCrank(30, 100, 20)


def _linkage():
    return (pl.Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(40, 30)))


def _crank_only():
    return pl.Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)


def _fourbar_solution():
    return pl.as_linkage(pl.FourBar(1, 3, 2.5, 3)).solve(0.5, order=1)


def _mechanism_solution():
    return (pl.Linkage({"A": 0, "D": 80}).crank("crank", pivot="A", tip="B", length=30)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(70, 60))
            .solve(1.0, order=1))


def _example_2_10():
    from mech.planar.kinematics._polygons import example_2_10
    return example_2_10()


def _example_2_9():
    from mech.planar.kinematics._polygons import example_2_9
    return example_2_9()


def _motion():
    return pl.relative_motion(_example_2_10(), "C", base="B", link="2", pivot="D", pivot_link="3")


def _centres():
    return pl.instant_centres(4, {(1, 4): 0j, (1, 2): 3 + 4j, (2, 3): 8 + 0j, (3, 4): pl.prismatic(1)})


def _sfb():
    return sph.SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.5))


def _rssr():
    return sp.RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0)


def _generator():
    x = np.radians([10.0, 30.0, 50.0, 70.0])
    g, = sph.precision_pairs(x, 0.5 * np.sin(x), theta0=np.radians(40.0), psi0=np.radians(80.0))
    return g


def _polygon():
    return sph.close_polygon(np.random.default_rng(1).normal(size=(5, 3)))


_THETA = {"theta": "real"}
def _sph_ground():
    return sph.SphericalLinkage({"A": (0.0, 0.0, 1.0), "D": (np.sin(1.0), 0.0, np.cos(1.0))})


def _sph_crank():
    return _sph_ground().crank("AB", pivot="A", tip="B", arc=0.3, reference="D")


def _sph_sixbar():
    return sph.stephenson1(0.3, 0.9, 0.7, 1.0, E=(0.2, 0.8), F=(0.3, -1.0), arcs=(0.8, 0.7), coupler=(0.4, 0.5))


_MOTION = {"theta": "real", "order": "order", "omega": "real", "alpha": "real", "strict": "bool"}
_MOTION2 = dict(theta=[0.0, 1.0], order=2, omega=1.5, alpha=0.5, strict=False)
_ABCD = {"a": "scalar", "b": "scalar", "c": "scalar", "d": "scalar"}
_P3 = [[0.0, 0.0, 1.0], [0.0, 0.6, 0.8]]
_DUAL = ("real", first, None)


def _dual_slot(name):
    return ("real", lambda v: (v, 0.2), name)


CASES = {
    # ------------------------------------------------------------------------- backend
    # the valid call sets the backend in force when the tests started (no numeric slot)
    "mech.set_backend": E(lambda: mech.set_backend, name=mech.get_backend()),
    "mech.get_backend": E(lambda: mech.get_backend),
    # ------------------------------------------------------------------------- planar
    "planar.Cognate.place": E(lambda: pl.cognates(_fourbar()).aegk.place, {"z": "point"}, z=1 + 1j),
    "planar.Cognate.solve": E(lambda: pl.cognates(_fourbar()).aegk.solve,
                              {"theta": "real", "branch": "branch?", "strict": "bool"},
                              theta=[0.5, 1.0], branch=1, strict=False),
    "planar.Cognates": E(lambda: pl.Cognates, original=_fourbar()),
    "planar.Cognates.joints": E(lambda: pl.cognates(_fourbar()).joints, _THETA, theta=[0.5, 1.0]),
    "planar.Cognates.path": E(lambda: pl.cognates(_fourbar()).path, _THETA, theta=[0.5, 1.0]),
    "planar.Cognates.branches": E(lambda: pl.cognates(_fourbar()).branches, _THETA, theta=[0.5, 1.0]),
    "planar.CouplerCentrodes.moving_placed": E(
        lambda: pl.coupler_centrodes(pl.FourBar(10, 40, 30, 35), [0.7, 2.0]).moving_placed,
        {"index": "int"}, index=1),
    "planar.CouplerCentrodes.segments": E(
        lambda: pl.coupler_centrodes(pl.FourBar(10, 40, 30, 35), [0.7, 2.0]).segments,
        {"limit": "scalar"}, limit=100.0),
    "planar.EllipticTrammel": E(lambda: pl.EllipticTrammel, {"L": "scalar", "point": ("real", first)},
                                L=2.0, point=(0.5, 0.0)),
    "planar.EllipticTrammel.from_crank": E(lambda: pl.EllipticTrammel.from_crank,
                                           {"a": "scalar", "point": ("real", first)}, a=1.5, point=(0.5, 0.0)),
    "planar.EllipticTrammel.solve": E(lambda: pl.EllipticTrammel(2.0).solve, _MOTION, **_MOTION2),
    "planar.EllipticTrammel.path_axes": E(lambda: pl.EllipticTrammel(2.0, point=(0.5, 0.1)).path_axes),
    "planar.EllipticTrammel.stroke": E(lambda: pl.EllipticTrammel(2.0).stroke),
    "planar.FourBar": E(lambda: pl.FourBar, {**_ABCD, "branch": "branch", "coupler": ("real", first),
                                             "rtol": "scalar"},
                        a=10, b=40, c=30, d=35, branch=1, coupler=(20, 10), rtol=1e-12),
    "planar.FourBar.solve": E(lambda: _fourbar().solve, _MOTION, **_MOTION2),
    "planar.FourBar.limit_positions": E(lambda: _fourbar().limit_positions),
    "planar.FourBar.transmission_angle": E(lambda: _fourbar().transmission_angle, _THETA, theta=[0.0, 1.0]),
    "planar.FourBar.min_transmission_angle": E(lambda: _fourbar().min_transmission_angle),
    "planar.Guide": E(lambda: pl.Guide, {"through": "point_or_name", "angle": "scalar"},
                      link="ground", through=1 + 2j, angle=0.3),
    "planar.GuideBar": E(lambda: pl.GuideBar, {"a": "scalar", "d": "scalar"}, a=150.0, d=300.0),
    "planar.GuideBar.from_swing": E(lambda: pl.GuideBar.from_swing, {"d": "scalar", "swing": "scalar"},
                                    d=300.0, swing=1.0),
    "planar.GuideBar.solve": E(lambda: pl.GuideBar(150.0, 300.0).solve,
                               {k: v for k, v in _MOTION.items() if k != "strict"},
                               theta=[0.0, 1.0], order=2, omega=1.5, alpha=0.5),
    "planar.GuideBar.swing": E(lambda: pl.GuideBar(150.0, 300.0).swing),
    "planar.GuideBar.extreme_angle": E(lambda: pl.GuideBar(150.0, 300.0).extreme_angle),
    "planar.GuideBar.time_ratio": E(lambda: pl.GuideBar(150.0, 300.0).time_ratio),
    "planar.GuideBar.min_guide_length": E(lambda: pl.GuideBar(150.0, 300.0).min_guide_length),
    "planar.InstantCentres.pairs": E(lambda: _centres().pairs),
    "planar.LinkVelocities.point_velocity": E(
        lambda: pl.centre_velocities(_centres(), frame=4, driver=1, omega=2.0).point_velocity,
        {"z": "point"}, link=3, z=1 + 1j),
    "planar.Linkage": E(lambda: pl.Linkage, {"ground": ("point1", lambda v: {"A": v})},
                        ground={"A": 0, "D": 35}),
    "planar.Linkage.ground": E(lambda: pl.Linkage().ground, {"at": "point1"}, name="A", at=1 + 1j),
    "planar.Linkage.point": E(lambda: _crank_only().point, {"at": "point1"}, name="P", link="crank", at=1 + 1j),
    "planar.Linkage.crank": E(lambda: pl.Linkage({"A": 0}).crank, {"length": "scalar"},
                              link="crank", pivot="A", tip="B", length=10.0),
    "planar.Linkage.slider": E(lambda: pl.Linkage({"A": 0}).slider, link="block",
                               guide=pl.Guide("ground", 0j, 0.0), point="B"),
    "planar.Linkage.rrr": E(lambda: _crank_only().rrr, {"lengths": ("length_or_name", first), "branch": "branch"},
                            links=("coupler", "rocker"), pins=("B", "D"), joint="C",
                            lengths=(40.0, 30.0), branch=1),
    "planar.Linkage.rrp": E(lambda: _crank_only().rrp, {"length": "scalar", "branch": "branch"},
                            links=("rod", "block"), pin="B", guide=pl.Guide("ground", 0j, 0.0),
                            joint="C", length=40.0, branch=1),
    "planar.Linkage.rpr": E(lambda: _crank_only().rpr, {"offset": "scalar", "branch": "branch"},
                            links=("guide", "block"), pins=("D", "B"), offset=0.0, branch=1),
    "planar.Linkage.prp": E(lambda: _crank_only().prp, links=("b1", "b2"),
                            guides=(pl.Guide("ground", 0j, 0.0), pl.Guide("crank", "B", 1.5)), joint="E"),
    "planar.Linkage.rpp": E(lambda: _crank_only().rpp, {"angle": "scalar", "offset": "scalar"},
                            links=("pinned", "sliding"), pin="B", guide=pl.Guide("ground", 0j, 0.0),
                            angle=1.2, point="Q", offset=0.0),
    "planar.Linkage.solve": E(lambda: _linkage().solve,
                              {"inputs": "real", "order": "order", "omega": "realmap", "alpha": "realmap",
                               "strict": "bool"},
                              inputs=[0.0, 1.0], order=2, omega=1.5, alpha=0.5, strict=False),
    "planar.Linkage.assembly_range": E(lambda: _linkage().assembly_range,
                                       {"start": "scalar", "end": "scalar", "samples": "count"},
                                       start=-3.0, end=3.0, samples=101),
    "planar.LinkageSolution.instant_centres": E(lambda: _fourbar_solution().instant_centres),
    "planar.LinkageSolution.direction": E(lambda: _example_2_10().direction, link="2"),
    "planar.OldhamCoupling": E(lambda: pl.OldhamCoupling, {"e0": "scalar"}, e0=0.1),
    "planar.OldhamCoupling.solve": E(lambda: pl.OldhamCoupling(0.1).solve, _MOTION, **_MOTION2),
    "planar.OldhamCoupling.inertia_force": E(lambda: pl.OldhamCoupling(0.1).inertia_force,
                                             {"m": "real", "omega": "real"}, m=2.0, omega=10.0),
    "planar.Polygon.segment": E(lambda: pl.velocity_polygon([_motion()]).segment, tail="p", head="c"),
    "planar.Polygon.lengths": E(lambda: pl.velocity_polygon([_motion()]).lengths, {"mu": "scalar"}, mu=50.0),
    "planar.RotatingGuideBar": E(lambda: pl.RotatingGuideBar, {"a": "scalar", "d": "scalar"}, a=2.0, d=1.0),
    "planar.RotatingGuideBar.solve": E(lambda: pl.RotatingGuideBar(2.0, 1.0).solve, _MOTION, **_MOTION2),
    "planar.RotatingGuideBar.guide_turns_per_crank_turn": E(
        lambda: pl.RotatingGuideBar(1.0, 1.0).guide_turns_per_crank_turn),
    "planar.ScotchYoke": E(lambda: pl.ScotchYoke, {"a": "scalar"}, a=2.0),
    "planar.ScotchYoke.solve": E(lambda: pl.ScotchYoke(2.0).solve, _MOTION, **_MOTION2),
    "planar.ScotchYoke.stroke": E(lambda: pl.ScotchYoke(2.0).stroke),
    "planar.ScrewJack": E(lambda: pl.ScrewJack,
                          {"d2": "scalar", "pitch": "scalar", "mu": "scalar", "starts": "int",
                           "flank_angle": "scalar", "collar": ("scalar", lambda v: (50.0, v)),
                           "mu_collar": "scalar?", "collar_condition": "option"},
                          d2=22.0, pitch=4.0, mu=0.1, starts=1, flank_angle=0.2, collar=(50.0, 42.0),
                          mu_collar=0.12, collar_condition="run-in"),
    "planar.ScrewJack.solve": E(lambda: pl.ScrewJack(22.0, 4.0, 0.1, collar=(50.0, 42.0)).solve,
                                {"Q": "real"}, Q=1.0),
    "planar.SliderCrank": E(lambda: pl.SliderCrank, {"a": "scalar", "b": "scalar", "e": "scalar",
                                                     "branch": "branch"}, a=30, b=100, e=20, branch=1),
    "planar.SliderCrank.solve": E(lambda: _slider().solve, _MOTION, **_MOTION2),
    "planar.SliderCrank.limit_positions": E(lambda: _slider().limit_positions),
    "planar.SliderCrank.stroke": E(lambda: _slider().stroke),
    "planar.SliderCrank.extreme_angle": E(lambda: _slider().extreme_angle),
    "planar.SliderCrank.time_ratio": E(lambda: _slider().time_ratio),
    "planar.SliderCrank.transmission_angle": E(lambda: _slider().transmission_angle, _THETA, theta=[0.0, 1.0]),
    "planar.SliderCrank.min_transmission_angle": E(lambda: _slider().min_transmission_angle),
    "planar.SliderCrank.approximate": E(lambda: pl.SliderCrank(30, 100).approximate, {"theta": "real", "omega": "real"},
                                        theta=[0.0, 1.0], omega=2.0),
    "planar.SwingingBlock": E(lambda: pl.SwingingBlock, {"a": "scalar", "d": "scalar"}, a=1.0, d=2.0),
    "planar.SwingingBlock.solve": E(lambda: pl.SwingingBlock(1.0, 2.0).solve, _MOTION, **_MOTION2),
    "planar.SwingingBlock.swing": E(lambda: pl.SwingingBlock(1.0, 2.0).swing),
    "planar.TangentMechanism": E(lambda: pl.TangentMechanism, {"L": "scalar"}, L=2.0),
    "planar.TangentMechanism.solve": E(lambda: pl.TangentMechanism(2.0).solve, _MOTION, **_MOTION2),
    "planar.TriadSixBar": E(lambda: pl.TriadSixBar,
                            {"a": "scalar", "b": "scalar", "cd": "scalar", "ce": "scalar", "angle": "scalar",
                             "g": "scalar", "f": "scalar", "G": "point1", "F": "point1"},
                            a=10, b=60, cd=36, ce=36, angle=-np.pi / 2, g=40, f=40, G=118 + 41j, F=91 - 48j),
    "planar.TriadSixBar.solve": E(
        lambda: pl.TriadSixBar(10, 60, 36, 36, -np.pi / 2, 40, 40, 118 + 41j, 91 - 48j).solve,
        {"theta": "real", "start": ("point1", lambda v: (v, np.pi / 3), "start"), "omega": "real",
         "tol": "scalar", "max_iter": "count", "strict": "bool"},
        theta=np.pi / 2, start=(60 + 10j, np.pi / 3), omega=1.0, tol=1e-14, max_iter=50, strict=False),
    "planar.acceleration_image": E(lambda: pl.acceleration_image, sol=_example_2_10(), link="3", base="D",
                                   points=["C", "D", "E"]),
    "planar.acceleration_polygon": E(lambda: pl.acceleration_polygon, motions=[_motion()]),
    "planar.as_linkage": E(lambda: pl.as_linkage, mechanism=pl.FourBar(1, 3, 2.5, 3)),
    "planar.centre_count": E(lambda: pl.centre_count, {"n": "count"}, n=4),
    "planar.centre_velocities": E(lambda: pl.centre_velocities, {"omega": "real"},
                                  centres=_centres(), frame=4, driver=1, omega=2.0),
    "planar.cognates": E(lambda: pl.cognates, fourbar=_fourbar()),
    "planar.coupler_sextic": E(lambda: pl.coupler_sextic, {"linkage": "vec3", "points": "point"},
                               linkage=[0.2, -0.1, 0.4, 1.0, 3.5, 3.0, 3.2, 1.5, 0.8], points=[1 + 1j, 2.0]),
    "planar.coincident_motion": E(lambda: pl.coincident_motion, sol=_example_2_9(), point="B",
                                  carrier="2", link="3", pivot="C"),
    "planar.collar_friction_radius": E(lambda: pl.collar_friction_radius,
                                       {"r_out": "real", "r_in": "real", "condition": "option"},
                                       r_out=25.0, r_in=21.0, condition="new"),
    "planar.coupler_centrodes": E(lambda: pl.coupler_centrodes, {"theta": "real"},
                                  fourbar=pl.FourBar(10, 40, 30, 35), theta=[0.7, 2.0]),
    "planar.coupler_dashes": E(lambda: pl.coupler_dashes,
                               {**_ABCD, "coupler": "point", "n": "count", "branch": "branch", "start": "scalar"},
                               a=1, b=2, c=2.5, d=3, coupler=[0.5 + 0.5j, 1 + 1j], n=12, branch=1, start=0.0),
    "planar.curved_contact_mu": E(lambda: pl.curved_contact_mu, {"mu": "real", "k": "real"}, mu=0.1, k=1.2),
    "planar.design_check": E(lambda: pl.design_check, {"gamma_min": "scalar", "high_speed": "bool"},
                             gamma_min=0.8, high_speed=False),
    "planar.eccentric_clamp_locks": E(lambda: pl.eccentric_clamp_locks,
                                      {"alpha": "real", "e": "real", "r_disc": "real", "rho_pin": "real",
                                       "phi": "real"},
                                      alpha=[0.7, 1.0], e=10.0, r_disc=40.0, rho_pin=1.0, phi=0.15),
    "planar.eccentric_clamp_max_angle": E(lambda: pl.eccentric_clamp_max_angle,
                                          {"e": "real", "r_disc": "real", "rho_pin": "real", "phi": "real"},
                                          e=10.0, r_disc=40.0, rho_pin=1.0, phi=0.15),
    "planar.efficiency": E(lambda: pl.efficiency, {"useful": "real", "driving": "real"}, useful=80.0, driving=100.0),
    "planar.efficiency_from_drive": E(lambda: pl.efficiency_from_drive, {"ideal": "real", "actual": "real"},
                                      ideal=30.0, actual=40.0),
    "planar.efficiency_from_resistance": E(lambda: pl.efficiency_from_resistance,
                                           {"actual": "real", "ideal": "real"}, actual=45.0, ideal=50.0),
    "planar.extreme_angle": E(lambda: pl.extreme_angle, {"time_ratio": "real"}, time_ratio=[1.0, 1.4]),
    "planar.fourbar_dead_points": E(lambda: pl.fourbar_dead_points, {**_ABCD, "branch": "branch"},
                                    a=10, b=40, c=30, d=35, branch=1),
    "planar.fourbar_mechanical_advantage": E(lambda: pl.fourbar_mechanical_advantage,
                                             {**_ABCD, "theta": "real", "branch": "branch", "driver": "option"},
                                             a=30, b=70, c=60, d=80, theta=1.0, branch=1, driver="crank"),
    "planar.fourbar_pressure_angle": E(lambda: pl.fourbar_pressure_angle, {**_ABCD, "theta": "real"},
                                       a=30, b=70, c=60, d=80, theta=[0.0, 1.0]),
    "planar.friction_angle": E(lambda: pl.friction_angle, {"mu": "real"}, mu=0.1),
    "planar.friction_circle": E(lambda: pl.friction_circle, {"mu0": "real", "r": "real"}, mu0=0.2, r=12.5),
    "planar.grashof": E(lambda: pl.grashof, {**_ABCD, "rtol": "scalar"}, a=10, b=40, c=30, d=35, rtol=1e-12),
    "planar.guide_bar_pressure_angle": E(lambda: pl.guide_bar_pressure_angle, {"s": "real", "e": "real"},
                                         s=[10.0, 200.0], e=10.0),
    "planar.hand_press": E(lambda: pl.hand_press,
                           {"lever": "scalar", "handle": "scalar", "pivot": "point1", "link2": "scalar",
                            "link3": "scalar", "link4": "scalar"},
                           lever=25.0, handle=250.0, pivot=70 - 75j, link2=70.0, link3=50.0, link4=50.0),
    "planar.higher_pair": E(lambda: pl.higher_pair, {"contact": "point", "normal": "point"},
                            contact=1 + 1j, normal=1j),
    "planar.incline_forces": E(lambda: pl.incline_forces,
                               {"Q": "real", "incline": "real", "mu": "real", "push_angle": "real?"},
                               Q=100.0, incline=0.5, mu=0.2, push_angle=0.1),
    "planar.instant_centres": E(lambda: pl.instant_centres,
                                {"links": "count", "direct": ("point", lambda v: {(1, 4): 0j, (1, 2): v,
                                                                                    (2, 3): 10 + 6j,
                                                                                    (3, 4): 8 + 0j})},
                                links=4, direct={(1, 4): 0j, (1, 2): 3 + 4j, (2, 3): 10 + 6j, (3, 4): 8 + 0j}),
    "planar.is_self_locking": E(lambda: pl.is_self_locking, {"eta": "real"}, eta=[-0.1, 0.0, 0.4]),
    "planar.jansen_linkage": E(lambda: pl.jansen_linkage, {"a": "scalar"}, a=50.0),
    "planar.jaw_crusher": E(lambda: pl.jaw_crusher,
                            {"crank": "scalar", "pitman": "scalar", "toggle_back": "scalar",
                             "toggle_front": "scalar", "jaw": "scalar", "back_pivot": "point1",
                             "jaw_pivot": "point1"},
                            crank=12.0, pitman=250.0, toggle_back=90.0, toggle_front=90.0, jaw=300.0,
                            back_pivot=88 - 268j, jaw_pivot=-100 + 32j),
    "planar.joint_transmission_angle": E(lambda: pl.joint_transmission_angle,
                                         solution=pl.watt_six_bar().solve(0.0), joint="C", force="B", pivot="D"),
    "planar.journal_mu": E(lambda: pl.journal_mu, {"mu": "real", "condition": "option"}, mu=0.1, condition="new"),
    "planar.journal_state": E(lambda: pl.journal_state, {"h": "real", "rho": "real"}, h=[1.0, 2.5, 3.0], rho=2.5),
    "planar.kind_intervals": E(lambda: pl.kind_intervals,
                               {"lengths": ("scalar", lambda v: (20, v, 40)), "vary": "option",
                                "rtol": "scalar"},
                               lengths=(20, 50, 40), vary="d", rtol=1e-12),
    "planar.lead_angle": E(lambda: pl.lead_angle, {"pitch": "real", "d2": "real", "starts": "int"},
                           pitch=4.0, d2=22.0, starts=1),
    "planar.limit_positions": E(lambda: pl.limit_positions, {**_ABCD, "branch": "branch"},
                                a=10, b=40, c=30, d=35, branch=1),
    "planar.mechanical_advantage": E(lambda: pl.mechanical_advantage, {"method": "option"},
                                     solution=_mechanism_solution(), input="crank", output="rocker",
                                     method="velocities"),
    "planar.min_transmission_angle": E(lambda: pl.min_transmission_angle, _ABCD, a=30, b=70, c=60, d=80),
    "planar.omega_ratio": E(lambda: pl.omega_ratio, centres=_centres(), i=3, j=1, frame=4),
    "planar.parallel_efficiency": E(lambda: pl.parallel_efficiency, {"etas": "real", "powers": "real"},
                                    etas=[0.9, 0.6], powers=[3.0, 1.0]),
    "planar.pressure_angle": E(lambda: pl.pressure_angle, solution=_mechanism_solution(), joint="C", force="B"),
    "planar.prismatic": E(lambda: pl.prismatic, {"direction": "point"}, direction=1 + 1j),
    "planar.push_rod": E(lambda: pl.push_rod, {"mu": "real", "offset": "real", "length": "real"},
                         mu=0.2, offset=100.0, length=80.0),
    "planar.quick_return_crank_rocker": E(lambda: pl.quick_return_crank_rocker,
                                          {"crank": "scalar", "coupler": "scalar", "rocker": "scalar",
                                           "frame": "scalar", "lever": "scalar", "lever_angle": "scalar",
                                           "rod": "scalar", "height": "scalar?"},
                                          crank=60.0, coupler=120.0, rocker=180.0, frame=160.0, lever=400.0,
                                          lever_angle=-0.8552113334772214, rod=150.0, height=None),
    "planar.quick_return_guide_bar": E(lambda: pl.quick_return_guide_bar,
                                       {"crank": "scalar", "frame": "scalar", "bar": "scalar", "rod": "scalar"},
                                       crank=124.0, frame=400.0, bar=485.0, rod=120.0),
    "planar.quick_return_slider_crank": E(lambda: pl.quick_return_slider_crank,
                                          {"crank": "scalar", "rod": "scalar", "offset": "scalar"},
                                          crank=129.0, rod=280.0, offset=120.0),
    "planar.ram_stroke": E(lambda: pl.ram_stroke, {"direction": "point1", "samples": "count"},
                           linkage=pl.quick_return_slider_crank(), point="F", direction=1 + 0j, samples=360),
    "planar.relative_motion": E(lambda: pl.relative_motion, sol=_example_2_10(), point="C", base="B", link="2",
                                pivot="D", pivot_link="3"),
    "planar.revolute": E(lambda: pl.revolute, {"point": "point"}, point=1 + 1j),
    "planar.rolling_mill_max_thickness": E(lambda: pl.rolling_mill_max_thickness,
                                           {"diameter": "real", "gap": "real", "mu": "real"},
                                           diameter=1200.0, gap=25.0, mu=0.3),
    "planar.screw_efficiency": E(lambda: pl.screw_efficiency,
                                 {"Q": "real", "d2": "real", "lam": "real", "phi_v": "real", "mu_c": "real",
                                  "r_c": "real"},
                                 Q=1.0, d2=22.0, lam=0.06, phi_v=0.1, mu_c=0.1, r_c=20.0),
    "planar.series_efficiency": E(lambda: pl.series_efficiency, {"etas": "real"}, etas=[0.95, 0.9, 0.8]),
    "planar.shaper_stephenson": E(lambda: pl.shaper_stephenson,
                                  {"crank": "scalar", "frame": "scalar", "bar": "scalar", "rod": "scalar",
                                   "height": "scalar?"},
                                  crank=120.0, frame=300.0, bar=600.0, rod=400.0, height=None),
    "planar.shaper_watt": E(lambda: pl.shaper_watt,
                            {"crank": "scalar", "frame": "scalar", "bar": "scalar", "rod": "scalar",
                             "height": "scalar?"},
                            crank=124.0, frame=400.0, bar=485.0, rod=120.0, height=None),
    "planar.slider_crank_dead_points": E(lambda: pl.slider_crank_dead_points,
                                         {"a": "scalar", "b": "scalar", "e": "scalar", "branch": "branch"},
                                         a=30, b=100, e=10, branch=1),
    "planar.slider_crank_mechanical_advantage": E(
        lambda: pl.slider_crank_mechanical_advantage,
        {"a": "scalar", "b": "scalar", "e": "scalar", "theta": "real", "branch": "branch", "driver": "option"},
        a=30, b=100, e=0, theta=1.0, branch=1, driver="crank"),
    "planar.slider_crank_min_transmission_angle": E(lambda: pl.slider_crank_min_transmission_angle,
                                                    {"a": "scalar", "b": "scalar", "e": "scalar"},
                                                    a=30, b=100, e=20),
    "planar.slider_crank_pressure_angle": E(lambda: pl.slider_crank_pressure_angle,
                                            {"a": "scalar", "b": "scalar", "e": "scalar", "theta": "real"},
                                            a=30, b=100, e=20, theta=[0.0, 1.0]),
    "planar.slider_state": E(lambda: pl.slider_state, {"alpha": "real", "phi": "real"}, alpha=[0.05, 0.2], phi=0.1),
    "planar.spreading_wedge_force": E(lambda: pl.spreading_wedge_force,
                                      {"Q": "real", "theta": "real", "phi": "real", "base_friction": "bool"},
                                      Q=1000.0, theta=0.26, phi=0.2, base_friction=True),
    "planar.static_forces": E(lambda: pl.static_forces,
                              {"forces": ("point", lambda v: {"C": v}), "rho": "scalarmap", "mu": "scalarmap",
                               "tol": "scalar", "max_iter": "count"},
                              solution=_fourbar_solution(), forces={"C": -10}, couples=None, rho=0.0, mu=0.0,
                              tol=1e-12, max_iter=60),
    "planar.step_ratio": E(lambda: pl.step_ratio, {"axis": "int"},
                           solution=pl.jansen_linkage().solve(np.linspace(0, 6, 61)), axis=-1),
    "planar.stephenson_six_bar": E(lambda: pl.stephenson_six_bar,
                                   {"crank": "scalar", "coupler": "scalar", "rocker": "scalar", "frame": "scalar",
                                    "point": "point1", "pivot": "point1", "link5": "scalar", "output": "scalar"},
                                   crank=20.0, coupler=50.0, rocker=45.0, frame=50.0, point=55 + 15j,
                                   pivot=54 - 27j, link5=82.3, output=8.0),
    "planar.thread_friction_angle": E(lambda: pl.thread_friction_angle, {"mu": "real", "flank_angle": "real"},
                                      mu=0.1, flank_angle=0.5),
    "planar.thrust_friction_moment": E(lambda: pl.thrust_friction_moment,
                                       {"Q": "real", "mu": "real", "r_out": "real", "r_in": "real",
                                        "condition": "option", "cone_half_angle": "real"},
                                       Q=1.0, mu=0.3, r_out=100.0, r_in=50.0, condition="run-in",
                                       cone_half_angle=1.2),
    "planar.time_ratio": E(lambda: pl.time_ratio, {"extreme_angle": "real"}, extreme_angle=[0.0, 0.5]),
    "planar.total_reaction": E(lambda: pl.total_reaction,
                               {"normal": "point", "velocity": "point", "mu": "real", "normal_force": "real?"},
                               normal=1j, velocity=1.0, mu=0.1, normal_force=50.0),
    "planar.transmission_angle": E(lambda: pl.transmission_angle, {**_ABCD, "theta": "real"},
                                   a=30, b=70, c=60, d=80, theta=[0.0, 1.0]),
    "planar.transmission_extremes": E(lambda: pl.transmission_extremes, _ABCD, a=30, b=70, c=60, d=80),
    "planar.two_force_tilt_angle": E(lambda: pl.two_force_tilt_angle,
                                     {"length": "real", "rho_a": "real", "rho_b": "real", "cross": "bool"},
                                     length=100.0, rho_a=2.5, rho_b=2.5, cross=True),
    "planar.velocity_image": E(lambda: pl.velocity_image, sol=_example_2_10(), link="2", base="B",
                               points=["B", "C"]),
    "planar.velocity_polygon": E(lambda: pl.velocity_polygon, motions=[_motion()]),
    "planar.vgroove_mu": E(lambda: pl.vgroove_mu, {"mu": "real", "half_angle": "real"}, mu=0.1, half_angle=0.5),
    "planar.watt_six_bar": E(lambda: pl.watt_six_bar,
                             {"crank": "scalar", "coupler": "scalar", "rocker": "scalar", "frame": "scalar",
                              "lever": "scalar", "lever_angle": "scalar", "pivot": "point1", "link5": "scalar",
                              "output": "scalar"},
                             crank=20.0, coupler=50.0, rocker=45.0, frame=50.0, lever=44.0,
                             lever_angle=-2.6179938779914944, pivot=68 - 9j, link5=24.0, output=18.0),
    "planar.watt_transmission_angles": E(lambda: pl.watt_transmission_angles,
                                         solution=pl.watt_six_bar().solve(0.0)),
    "planar.wedge_press": E(lambda: pl.wedge_press, {"lam": "real", "phi": "real"}, lam=0.17, phi=0.1),
    "planar.wedge_press_forces": E(lambda: pl.wedge_press_forces,
                                   {"Q": "real", "lam": "real", "phi": "real", "release": "bool"},
                                   Q=1000.0, lam=0.17, phi=0.1, release=False),
    "planar.static_forces#couples": E(lambda: pl.static_forces, {"couples": ("real", lambda v: {"rocker": v})},
                                      solution=_fourbar_solution(), forces={"C": -10}, couples={"rocker": 1.0}),
    "planar.pressure_angle#direction": E(lambda: pl.pressure_angle, {"force": "point"},
                                         solution=_mechanism_solution(), joint="C", force=1 + 1j),
    "planar.joint_transmission_angle#direction": E(lambda: pl.joint_transmission_angle, {"force": "point"},
                                                   solution=pl.watt_six_bar().solve(0.0, order=1), joint="C",
                                                   force=1 + 1j, pivot="D"),
    # ------------------------------------------------------------------------- spatial
    "spatial.AssemblyRange.contains": E(lambda: sp.RSSR(2.0, 2.5, 1.5, 0.3, -0.4, 1.5, 0.8).assembly_range().contains,
                                        {"phi01": "real"}, phi01=[0.0, 1.0]),
    "spatial.DoubleUniversalJoint": E(lambda: sp.DoubleUniversalJoint,
                                      {"alpha1": "scalar", "alpha2": "scalar", "phase": "scalar"},
                                      alpha1=0.5, alpha2=0.5, phase=0.1),
    "spatial.DoubleUniversalJoint.solve": E(lambda: sp.DoubleUniversalJoint(0.5, 0.4).solve,
                                            {"theta1": "real", "order": "order", "omega": "real",
                                             "epsilon": "real"},
                                            theta1=[0.0, 1.0], order=2, omega=1.5, epsilon=0.5),
    "spatial.DoubleUniversalJoint.ratio_range": E(lambda: sp.DoubleUniversalJoint(0.5, 0.4).ratio_range),
    "spatial.Joint": E(lambda: sp.Joint,
                       {"kind": "option", "phi": "scalar", "lam": "scalar", "s": "scalar", "h": "scalar",
                        "pitch": "scalar"},
                       kind="H", phi=0.1, lam=0.2, s=0.3, h=0.4, pitch=0.5),
    "spatial.OpenChain": E(lambda: sp.OpenChain, joints=[sp.Joint("R", h=1.0), sp.Joint("R", h=1.0)]),
    "spatial.OpenChain.solve": E(lambda: sp.OpenChain([sp.Joint("R", h=1.0), sp.Joint("P", h=1.0)]).solve,
                                 {"q": "real", "order": "order", "qdot": "real?", "qddot": "real?",
                                  "point": ("real", lambda v: (v, 0.0, 0.0), "point")},
                                 q=[0.3, 0.5], order=2, qdot=[1.0, 0.5], qddot=[0.1, 0.2], point=(1.0, 0.0, 0.0)),
    "spatial.OpenChain.frames": E(lambda: sp.example_2_25_manipulator(0.5).frames, {"q": "real"},
                                  q=[0.1, 0.2, 0.3, 0.4]),
    "spatial.OpenChain.pose": E(lambda: sp.example_2_25_manipulator(0.5).pose,
                                {"q": "real", "point": ("real", lambda v: (v, 0.0, 0.0), "point")},
                                q=[0.1, 0.2, 0.3, 0.4], point=(1.0, 0.0, 0.0)),
    "spatial.RCCC": E(lambda: sp.RCCC,
                      {"a": ("scalar", first), "b": ("scalar", first), "c": ("scalar", first),
                       "d": ("scalar", first), "s1": "scalar", "branch": "branch"},
                      a=(0.6, 0.2), b=(1.2, 0.5), c=(1.0, 0.1), d=(1.3, 0.4), s1=0.3, branch=1),
    "spatial.RCCC.solve": E(lambda: sp.RCCC((0.6, 0.2), (1.2, 0.5), (1.0, 0.1), (1.3, 0.4)).solve,
                            {"theta": "real", "order": "order", "omega": "real", "strict": "bool"},
                            theta=[0.0, 1.0], order=1, omega=1.5, strict=False),
    "spatial.RSSR": E(lambda: sp.RSSR,
                      {"l1": "scalar", "l2": "scalar", "l3": "scalar", "s0": "scalar", "s3": "scalar",
                       "h0": "scalar", "lam": "scalar", "branch": "branch",
                       "coupler": ("scalar", lambda v: (v, 0.0, 0.0)), "rtol": "scalar"},
                      l1=1.0, l2=4.0, l3=2.0, s0=0.5, s3=0.8, h0=3.0, lam=1.0, branch=1, coupler=(0.1, 0.2, 0.3),
                      rtol=1e-12),
    "spatial.RSSR.coefficients": E(lambda: _rssr().coefficients, {"phi01": "real"}, phi01=[0.0, 1.0]),
    "spatial.RSSR.points": E(lambda: _rssr().points, {"phi01": "real", "phi03": "real"}, phi01=[0.0, 1.0],
                             phi03=0.5),
    "spatial.RSSR.discriminant": E(lambda: _rssr().discriminant, {"phi01": "real"}, phi01=[0.0, 1.0]),
    "spatial.RSSR.solve": E(lambda: _rssr().solve,
                            {"phi01": "real", "order": "order", "omega": "real", "alpha": "real", "strict": "bool"},
                            phi01=[0.0, 1.0], order=2, omega=1.5, alpha=0.5, strict=False),
    "spatial.RSSR.assembly_range": E(lambda: _rssr().assembly_range),
    "spatial.RSSR.change_angles": E(lambda: _rssr().change_angles),
    "spatial.example_2_25_manipulator": E(lambda: sp.example_2_25_manipulator, {"s0": "scalar"}, s0=0.5),
    "spatial.example_2_25_pose": E(lambda: sp.example_2_25_pose,
                                   {"phi01": "real", "phi12": "real", "s2": "real", "phi34": "real", "s0": "real",
                                    "p": "real"},
                                   phi01=0.0, phi12=np.pi / 2, s2=0.3, phi34=0.0, s0=0.5, p=0.1),
    "spatial.example_2_25_reach": E(lambda: sp.example_2_25_reach,
                                    {"phi12": "real", "s2": "real", "s0": "real", "p": "real"},
                                    phi12=np.pi / 2, s2=0.2, s0=0.3, p=0.2),
    "spatial.hd": E(lambda: sp.hd, {"phi": "real", "lam": "real", "s": "real", "h": "real"},
                    phi=0.5, lam=0.3, s=1.0, h=2.0),
    "spatial.hd_inv": E(lambda: sp.hd_inv, {"phi": "real", "lam": "real", "s": "real", "h": "real"},
                        phi=0.5, lam=0.3, s=1.0, h=2.0),
    "spatial.homogeneous": E(lambda: sp.homogeneous, {"R": "matrix", "p": "vec3"}, R=np.eye(3), p=[1.0, 2.0, 3.0]),
    "spatial.hooke_acceleration": E(lambda: sp.hooke_acceleration,
                                    {"theta1": "real", "alpha": "real", "omega": "real", "epsilon": "real"},
                                    theta1=[0.0, 1.0], alpha=0.5, omega=10.0, epsilon=0.5),
    "spatial.hooke_output": E(lambda: sp.hooke_output, {"theta1": "real", "alpha": "real"},
                              theta1=[0.0, 1.0], alpha=0.5),
    "spatial.hooke_ratio": E(lambda: sp.hooke_ratio, {"theta1": "real", "alpha": "real"},
                             theta1=[0.0, 1.0], alpha=0.5),
    "spatial.mobility": E(lambda: sp.mobility, {"moving_links": "count", "pairs": "option"}, moving_links=3,
                          pairs="RSSR"),
    "spatial.rot_x": E(lambda: sp.rot_x, {"lam": "real"}, lam=[0.5, 1.5]),
    "spatial.rot_z": E(lambda: sp.rot_z, {"phi": "real"}, phi=[0.5, 1.5]),
    # ------------------------------------------------------------------------- spherical
    "spherical.Circle.residual": E(lambda: sph.circle_through([1, 0, 0], [0, 1, 0], [0, 0, 1]).residual,
                                   {"p": "vec3"}, p=_P3),
    "spherical.Dual": E(lambda: sph.Dual, {"real": "real", "dual": "real"}, real=0.5, dual=1.0),
    "spherical.FunctionGenerator.output": E(lambda: _generator().output, {"x": "real"}, x=[0.3, 0.5]),
    "spherical.FunctionGenerator.structural_error": E(lambda: _generator().structural_error,
                                                      {"x": "real", "y": "real"}, x=[0.3, 0.5], y=[0.1, 0.2]),
    "spherical.FunctionGenerator.points": E(lambda: _generator().points, {"x": "real"}, x=[0.3, 0.5]),
    "spherical.PolygonRelations.family": E(lambda: sph.polygon_relations(_polygon().arcs, _polygon().angles).family,
                                           {"name": "option"}, name="cosine"),
    "spherical.PolygonRelations.worst": E(lambda: sph.polygon_relations(_polygon().arcs, _polygon().angles).worst),
    "spherical.SphericalFourBar": E(lambda: sph.SphericalFourBar,
                                    {**_ABCD, "branch": "branch", "coupler": ("scalar", first),
                                     "frame": "matrix?"},
                                    a=0.3, b=0.9, c=0.7, d=1.0, branch=1, coupler=(0.4, 0.5), frame=np.eye(3)),
    "spherical.SphericalFourBar.solve": E(lambda: _sfb().solve, _MOTION, **_MOTION2),
    "spherical.SphericalFourBar.assembly_range": E(lambda: _sfb().assembly_range),
    "spherical.SphericalFourBar.coupler_curve": E(lambda: _sfb().coupler_curve, {"n": "count"}, n=50),
    "spherical.SphericalFourBar.coupler_curve_polynomial": E(lambda: _sfb().coupler_curve_polynomial),
    "spherical.CouplerOctic": E(lambda: sph.CouplerOctic, {"linkage": "instance"}, linkage=_sfb()),
    "spherical.CouplerOctic.quartic": E(lambda: _sfb().coupler_curve_polynomial().quartic, {"points": "vec3"},
                                        points=[[0.0, 0.6, 0.8]]),
    "spherical.CouplerOctic.lonlat": E(lambda: _sfb().coupler_curve_polynomial().lonlat, {"lon": "real", "lat": "real"},
                                       lon=0.3, lat=[0.2, 0.4]),
    "spherical.coupler_octic": E(lambda: sph.coupler_octic, {"linkage": "vec3", "points": "vec3", "form": "option",
                                                             "small": "scalar"},
                                 linkage=[0.1, 0.2, 0.3, 0.5, 1.1, 0.9, 1.2, 0.6, 0.8], points=[[0.0, 0.6, 0.8]],
                                 form="auto", small=0.1),
    "spherical.coupler_quartic": E(lambda: sph.coupler_quartic, {"linkage": "vec3", "points": "vec3"},
                                   linkage=[0.1, 0.2, 0.3, 0.5, 1.1, 0.9, 1.2, 0.6, 0.8], points=[[0.0, 0.6, 0.8]]),
    "spherical.path_fourbar": E(lambda: sph.path_fourbar,
                                {"points": "vec3", "theta": "real", "start": "vec3", "formulation": "option",
                                 "metric": "option", "branch": "branch", "tol": "tolerance"},
                                points=_SPH_PATH[0], theta=_SPH_PATH[1], start=_SPH_PATH[2], formulation="distance",
                                metric="arc", branch=1, tol=1e-3),
    "spherical.path_stephenson1": E(lambda: sph.path_stephenson1,
                                    {"points": "vec3", "theta": "real", "start": "vec3", "metric": "option",
                                     "branches": ("branch", first), "tol": "tolerance",
                                     "min_transmission": "scalar?"},
                                    points=_SPH_PATH6[0], theta=_SPH_PATH6[1], start=_SPH_PATH6[2], metric="chord",
                                    branches=(1, 1), tol=1e-3, min_transmission=0.5),
    "spherical.path_verify": E(lambda: sph.path_verify,
                               {"linkage": "instance", "points": "vec3", "theta": "real", "tol": "tolerance"},
                               linkage=_sfb(), points=_SPH_PATH[0], theta=_SPH_PATH[1], tol=1e-3),
    "spherical.nine_parameters": E(lambda: sph.nine_parameters, {"linkage": "instance"}, linkage=_sfb()),
    "spherical.SphericalLinkage": E(lambda: sph.SphericalLinkage, {"ground": ("vec3", lambda v: {"A": v})},
                                    ground={"A": [0.0, 0.0, 1.0]}),
    "spherical.SphericalLinkage.ground": E(lambda: sph.SphericalLinkage().ground, {"at": "vec3"},
                                           name="A", at=[0.0, 0.0, 1.0]),
    "spherical.SphericalLinkage.crank": E(lambda: _sph_ground().crank, {"arc": "scalar"},
                                          link="AB", pivot="A", tip="B", arc=0.3, reference="D"),
    "spherical.SphericalLinkage.point": E(lambda: _sph_crank().point, {"at": ("scalar", first)},
                                          name="P", link="AB", at=(0.2, 0.5)),
    "spherical.SphericalLinkage.rrr": E(lambda: _sph_crank().rrr, {"arcs": ("scalar", first), "branch": "branch"},
                                        links=("BC", "DC"), pins=("B", "D"), joint="C", arcs=(0.9, 0.7), branch=1),
    "spherical.SphericalLinkage.solve": E(lambda: _sph_sixbar().solve, _MOTION, **_MOTION2),
    "spherical.SphericalLinkage.coupler_curve": E(lambda: _sph_sixbar().coupler_curve,
                                                  {"theta": "real", "order": "order", "omega": "real", "alpha": "real"},
                                                  theta=[0.0, 1.0], order=2, omega=1.5, alpha=0.5),
    **{f"spherical.{name}": E(lambda name=name: getattr(sph, name),
                              {**_ABCD, "E": ("scalar", first), "F": ("scalar", first), "arcs": ("scalar", first),
                               "coupler": ("scalar", first), "branches": ("branch", first), "frame": "matrix?"},
                              a=0.3, b=0.9, c=0.7, d=1.0, E=(0.2, 0.8), F=(0.3, -1.0), arcs=(0.8, 0.7),
                              coupler=(0.4, 0.5), branches=(1, 1), frame=np.eye(3))
       for name in ("stephenson1", "stephenson2", "watt1", "watt2")},
    "spherical.SphericalPolygon.relations": E(lambda: _polygon().relations),
    "spherical.angle_at": E(lambda: sph.angle_at, {"a": "vec3", "b": "vec3", "c": "vec3"},
                            a=[0, 0, 1], b=[1, 0, 0], c=[0, 1, 0]),
    "spherical.angle_between": E(lambda: sph.angle_between, {"pole1": "vec3", "pole2": "vec3"},
                                 pole1=[0, 0, 1], pole2=[0, 1, 0]),
    "spherical.antipode_reduction": E(lambda: sph.antipode_reduction, _ABCD, a=2.5, b=2.0, c=0.7, d=1.0),
    "spherical.arcs_from_coefficients": E(lambda: sph.arcs_from_coefficients,
                                          {"k1": "scalar", "k2": "scalar", "k3": "scalar", "k4": "scalar"},
                                          **dict(zip(("k1", "k2", "k3", "k4"),
                                                     (float(v) for v in sph.freudenstein_coefficients(0.4, 0.9, 0.7, 1.0))))),
    "spherical.bisector": E(lambda: sph.bisector, {"a": "vec3", "b": "vec3"}, a=[1, 0, 0], b=[0, 1, 0]),
    "spherical.chain_components": E(lambda: sph.chain_components, {"arcs": "real", "angles": "real"},
                                    arcs=[np.pi / 2, np.pi / 2], angles=[np.pi / 2]),
    "spherical.chebyshev_spacing": E(lambda: sph.chebyshev_spacing, {"x0": "scalar", "x1": "scalar", "n": "count"},
                                     x0=1.0, x1=10.0, n=3),
    "spherical.circle_through": E(lambda: sph.circle_through, {"a": "vec3", "b": "vec3", "c": "vec3"},
                                  a=[1, 0, 0], b=[0, 1, 0], c=[0, 0, 1]),
    "spherical.classify": E(lambda: sph.classify, {**_ABCD, "tol": "scalar"}, a=0.3, b=0.9, c=0.7, d=1.0, tol=1e-12),
    "spherical.close_polygon": E(lambda: sph.close_polygon, {"axes": "vec3"}, axes=np.eye(3)),
    "spherical.collinearity": E(lambda: sph.collinearity, {"a": "vec3", "b": "vec3", "c": "vec3"},
                                a=[1, 0, 0], b=[0, 1, 0], c=[0, 0.6, 0.8]),
    "spherical.cosine_law": E(lambda: sph.cosine_law, {"arcs": "real", "angles": "real", "j": "int", "k": "int"},
                              arcs=_polygon().arcs, angles=_polygon().angles, j=2, k=4),
    "spherical.deltoid": E(lambda: sph.deltoid, {"a": "scalar", "b": "scalar", "branch": "branch"},
                           a=0.3, b=0.8, branch=1),
    "spherical.deltoid_input": E(lambda: sph.deltoid_input, {"psi": "real", "a": "scalar", "b": "scalar"},
                                 psi=[0.5, 1.0], a=0.3, b=0.8),
    "spherical.distance": E(lambda: sph.distance, {"p": "vec3", "q": "vec3"}, p=[0, 0, 1], q=_P3),
    "spherical.distance_lonlat": E(lambda: sph.distance_lonlat,
                                   {"lon1": "real", "lat1": "real", "lon2": "real", "lat2": "real"},
                                   lon1=0.0, lat1=0.0, lon2=[1e-9, np.pi], lat2=0.0),
    "spherical.distance_to_great_circle": E(lambda: sph.distance_to_great_circle, {"p": "vec3", "pole": "vec3"},
                                            p=_P3, pole=[0, 0, 1]),
    "spherical.dual": E(lambda: sph.dual, {"real": "real", "dual": "real"}, real=0.5, dual=2.0),
    "spherical.dual_fourbar_joints": E(lambda: sph.dual_fourbar_joints,
                                       {n: _dual_slot(n) for n in ("a_hat", "c_hat", "d_hat", "theta_hat",
                                                                   "psi_hat")},
                                       a_hat=(0.6, 0.2), c_hat=(1.0, 0.1), d_hat=(1.3, 0.4), theta_hat=(0.5, 0.3),
                                       psi_hat=sph.dual_fourbar_output((0.6, 0.2), (1.2, 0.5), (1.0, 0.1),
                                                                       (1.3, 0.4), (0.5, 0.3))),
    "spherical.dual_fourbar_output": E(lambda: sph.dual_fourbar_output,
                                       {**{n: _dual_slot(n) for n in ("a_hat", "b_hat", "c_hat", "d_hat",
                                                                      "theta_hat")}, "branch": "branch"},
                                       a_hat=(0.6, 0.2), b_hat=(1.2, 0.5), c_hat=(1.0, 0.1), d_hat=(1.3, 0.4),
                                       theta_hat=(0.5, 0.3), branch=1),
    "spherical.freudenstein_coefficients": E(lambda: sph.freudenstein_coefficients, _ABCD,
                                             a=0.4, b=0.9, c=0.7, d=1.0),
    "spherical.from_xyz": E(lambda: sph.from_xyz, {"v": "vec3"}, v=_P3),
    "spherical.great_circle_at": E(lambda: sph.great_circle_at, {"a": "vec3", "inclination": "real"},
                                   a=[0, 0, 1], inclination=0.5),
    "spherical.great_circle_through": E(lambda: sph.great_circle_through, {"a": "vec3", "b": "vec3"},
                                        a=[1, 0, 0], b=[0, 1, 0]),
    "spherical.ground_frame": E(lambda: sph.ground_frame, {"lon": "scalar", "lat": "scalar", "heading": "scalar"},
                                lon=0.3, lat=0.2, heading=1.0),
    "spherical.inclination": E(lambda: sph.inclination, {"a": "vec3", "b": "vec3"}, a=[0, 0, 1], b=[0, 1, 1]),
    "spherical.intersect": E(lambda: sph.intersect, {"pole1": "vec3", "pole2": "vec3"},
                             pole1=[0, 0, 1], pole2=[1, 0, 0]),
    "spherical.inversions": E(lambda: sph.inversions, {**_ABCD, "tol": "scalar"}, a=0.3, b=0.9, c=0.7, d=1.0,
                              tol=1e-12),
    "spherical.isogram": E(lambda: sph.isogram, {"a": "scalar", "b": "scalar", "branch": "branch"},
                           a=0.4, b=0.9, branch=1),
    "spherical.isogram_output": E(lambda: sph.isogram_output,
                                  {"theta": "real", "a": "scalar", "b": "scalar", "crossed": "bool"},
                                  theta=[0.5, 1.0], a=0.4, b=0.9, crossed=False),
    "spherical.law_count": E(lambda: sph.law_count, {"n": "count"}, n=4),
    "spherical.least_squares": E(lambda: sph.least_squares,
                                 {"x": "real", "y": "real", "theta0": "scalar", "psi0": "scalar",
                                  "kind": "option", "fit_start": "bool"},
                                 x=np.linspace(0.0, 1.0, 11), y=0.5 * np.sin(np.linspace(0.0, 1.0, 11)),
                                 theta0=0.7, psi0=1.4, kind="structural", fit_start=False),
    "spherical.local_frame": E(lambda: sph.local_frame, {"p": "vec3"}, p=_P3),
    "spherical.open_chain_axes": E(lambda: sph.open_chain_axes,
                                   {"arcs": "real", "angles": "real", "frame": "matrix?"},
                                   arcs=[np.pi / 2] * 3, angles=[np.pi / 2] * 2, frame=np.eye(3)),
    "spherical.point_at": E(lambda: sph.point_at, {"a": "vec3", "arc": "real", "inclination": "real"},
                            a=[1, 0, 0], arc=[0.1, 0.2], inclination=0.0),
    "spherical.polygon_relations": E(lambda: sph.polygon_relations, {"arcs": "real", "angles": "real"},
                                     arcs=_polygon().arcs, angles=_polygon().angles),
    "spherical.precision_pairs": E(lambda: sph.precision_pairs,
                                   {"x": "real", "y": "real", "theta0": "scalar?", "psi0": "scalar?",
                                    "keep_defective": "bool"},
                                   x=np.radians([10.0, 30.0, 50.0, 70.0]),
                                   y=0.5 * np.sin(np.radians([10.0, 30.0, 50.0, 70.0])),
                                   theta0=np.radians(40.0), psi0=np.radians(80.0), keep_defective=False),
    "spherical.rotate_about": E(lambda: sph.rotate_about, {"p": "vec3", "axis": "vec3", "angle": "real"},
                                p=_P3, axis=[1, 0, 0], angle=0.5),
    "spherical.rotation_matrix": E(lambda: sph.rotation_matrix, {"axis": "vec3", "angle": "real"},
                                   axis=[0, 0, 1], angle=0.5),
    "spherical.rssr_from_transference": E(lambda: sph.rssr_from_transference,
                                          {"l1": "scalar", "l2": "scalar", "l3": "scalar", "s0": "scalar",
                                           "s3": "scalar", "h0": "scalar", "lam": "scalar", "phi01": "real",
                                           "branch": "branch"},
                                          l1=1.0, l2=4.0, l3=2.0, s0=0.5, s3=0.8, h0=3.0, lam=1.0,
                                          phi01=[0.0, 1.0], branch=1),
    "spherical.sine_cosine_law": E(lambda: sph.sine_cosine_law,
                                   {"arcs": "real", "angles": "real", "j": "int", "k": "int"},
                                   arcs=_polygon().arcs, angles=_polygon().angles, j=2, k=4),
    "spherical.sine_law": E(lambda: sph.sine_law, {"arcs": "real", "angles": "real", "j": "int", "k": "int"},
                            arcs=_polygon().arcs, angles=_polygon().angles, j=2, k=4),
    "spherical.slider_crank_stroke": E(lambda: sph.slider_crank_stroke, {"a": "scalar", "b": "scalar", "e": "scalar"},
                                       a=0.3, b=0.8, e=0.1),
    "spherical.spherical_slider_crank": E(lambda: sph.spherical_slider_crank,
                                          {"a": "scalar", "b": "scalar", "e": "scalar", "branch": "branch"},
                                          a=0.3, b=0.8, e=0.1, branch=1),
    "spherical.tangent": E(lambda: sph.tangent, {"a": "vec3", "b": "vec3"}, a=[0, 0, 1], b=[0, 1, 1]),
    "spherical.to_xyz": E(lambda: sph.to_xyz, {"lon": "real", "lat": "real"}, lon=[0.0, 1.0], lat=0.5),
    "spherical.triangle_point": E(lambda: sph.triangle_point,
                                  {"a": "vec3", "b": "vec3", "gamma": "real", "arc": "real"},
                                  a=[0, 0, 1], b=[1, 0, 0], gamma=0.5, arc=0.7),
    "spherical.turn": E(lambda: sph.turn, {"a": "vec3", "b": "vec3", "gamma": "real"},
                        a=[0, 0, 1], b=[1, 0, 1], gamma=0.5),
    "spherical.universal_joint": E(lambda: sph.universal_joint, {"shaft_angle": "scalar"}, shaft_angle=0.5),
    "spherical.velocity": E(lambda: sph.velocity, {"omega": "vec3", "p": "vec3"}, omega=[0, 0, 2.0], p=[1, 0, 0]),
    "spherical.precision_pairs#three": E(lambda: sph.precision_pairs,
                                         {"x": "real", "y": "real", "theta0": "scalar?", "psi0": "scalar?",
                                          "d": "scalar"},
                                         x=np.radians([10.0, 30.0, 50.0]), y=0.5 * np.sin(np.radians([10.0, 30.0, 50.0])),
                                         theta0=0.7, psi0=1.4, d=1.0),
    # ------------------------------------------------------------------------- exercises
    "exercises.Exercise.params": E(lambda: ex.get("2-3").params, {"AB": "scalar"}, AB=28.0),
    "exercises.Exercise.statement_text": E(lambda: ex.get("2-3").statement_text, {"AB": "scalar"}, AB=28.0),
    "exercises.Exercise.solve": E(lambda: ex.get("2-3").solve, {"AB": "scalar"}, AB=28.0),
    "exercises.Exercise.variant": E(lambda: ex.get("2-3").variant, {"max_tries": "count", "rng": "seed"},
                                    rng=7, max_tries=100),
    "exercises.Exercise.params#dict": E(lambda: ex.get("2-3").params, {"params": ("scalar", lambda v: {"AB": v}, "AB")},
                                        params={"AB": 28.0}),
    "exercises.Exercise.solve#dict": E(lambda: ex.get("2-3").solve, {"params": ("scalar", lambda v: {"AB": v}, "AB")},
                                       params={"AB": 28.0}),
    "exercises.Result.as_markdown": E(lambda: ex.get("2-3").solve().results()[0].as_markdown),
    "exercises.Solution.results": E(lambda: ex.get("2-3").solve().results),
    "exercises.Solution.values": E(lambda: ex.get("2-3").solve().values),
    "exercises.Solution.as_markdown": E(lambda: ex.get("2-3").solve().as_markdown, {"heading_level": "count?"},
                                        heading_level=2),
    "exercises.get": E(lambda: ex.get, {"number": "option"}, number="2-3"),
    "exercises.chapter2.merge_intervals": E(lambda: chapter2.merge_intervals,
                                            intervals=[ex.Interval(0.0, 1.0), ex.Interval(1.0, 2.0, True)]),
    "exercises.chapter2_analysis.cam_2_10": E(lambda: chapter2_analysis.cam_2_10, {"side": "branch"}, side=-1),
    "exercises.chapter2_analysis.linkage_2_4": E(lambda: chapter2_analysis.linkage_2_4, {"h": "scalar?"}, h=5.0),
    "exercises.chapter2_analysis.linkage_2_4#dict": E(lambda: chapter2_analysis.linkage_2_4,
                                                      {"params": ("scalar", lambda v: {"AB": v}, "AB")},
                                                      params={"AB": 30.0}),
    "exercises.chapter2_analysis.linkage_2_5": E(lambda: chapter2_analysis.linkage_2_5, {"y": "scalar"}, y=10.0),
    "exercises.chapter2_analysis.linkage_2_7": E(lambda: chapter2_analysis.linkage_2_7, {"bc": "scalar?"}, bc=80.0),
    **{f"exercises.chapter2_relative_motion.linkage_2_{n}": E(
        lambda n=n: getattr(chapter2_relative_motion, f"linkage_2_{n}"),
        {"params": ("scalar", lambda v, k=k: {k: v}, k)}, params={k: d})
       for n, k, d in (("12", "a", 100.0), ("13", "OA", 150.0), ("14", "AB", 40.0), ("15", "AB", 150.0),
                       ("16", "AB", 200.0))},
    **{f"exercises.chapter2_reactions.linkage_2_{n}": E(
        lambda n=n: getattr(chapter2_reactions, f"linkage_2_{n}"),
        {"params": ("scalar", lambda v, k=k: {k: v}, k)}, params={k: d})
       for n, k, d in (("17", "AB", 50.0), ("18", "AB", 100.0), ("25", "R", 40.0))},
    **{f"exercises.chapter2_instant_centres.{f}": E(
        lambda f=f: getattr(chapter2_instant_centres, f), {"params": ("scalar", lambda v, k=k: {k: v}, k)},
        params={k: d})
       for f, k, d in (("mechanisms_2_8", "a", 30.0), ("wheels_2_9", "r1", 20.0), ("centres_2_11", "a", 30.0))},
    "exercises.chapter2_reactions.linkage_2_22": E(lambda: chapter2_reactions.linkage_2_22,
                                                   {"layout": ("scalar", lambda v: {"AB": v}, "AB")},
                                                   layout={"AB": 400.0}),
    "exercises.chapter2_reactions.linkage_2_26": E(lambda: chapter2_reactions.linkage_2_26, {"theta": "scalar"},
                                                   theta=45.0),
}

#: Public classes whose constructors are not walked, and why: the package builds them (result
#: records and exception types); the user reads them and never feeds numbers into them.
RECORDS = {
    "mech.AssemblyError": "exception type",
    "mech.InputTypeError": "exception type",
    "planar.AssemblyError": "exception type",
    **{f"planar.{n}": "result record built by the package" for n in (
        "AssemblyInterval", "Centre", "CentrodeSegment", "Cognate", "CognatePose", "CouplerCentrodes",
        "CouplerDashes", "DeadPoints", "Equation", "FourBarPose", "GrashofResult", "GuideBarPose", "Image",
        "InclineForces", "InstantCentres", "KindInterval", "LimitPositions", "LinkVelocities",
        "LinkageSolution", "OldhamPose", "Polygon", "RelativeMotion", "RotatingGuideBarPose",
        "ScotchYokePose", "ScrewResult", "Slide", "SliderCrankLimits", "SliderCrankPose",
        "SliderCrankSeries", "StaticForces", "Stroke", "TangentPose", "TenBarPose", "Term", "TrammelPose",
        "TransmissionExtremes", "TriadPose", "WedgePress", "WedgePressForces")},
    **{f"spatial.{n}": "result record built by the package" for n in (
        "AssemblyRange", "ChainPose", "DoubleJointPose", "RCCCPose", "RSSRPose")},
    **{f"spherical.{n}": "result record built by the package" for n in (
        "Circle", "Collinearity", "FunctionGenerator", "Intersection", "PolygonRelations", "SliderStroke",
        "SphericalFourBarPose", "SphericalLinkagePose", "SphericalPathDesign", "SphericalPolygon", "SphericalType")},
    **{f"exercises.{n}": "record of the exercise catalogue built by the package" for n in (
        "Exercise", "Interval", "Parameter", "Part", "Result", "Solution")},
}


# ----------------------------------------------------------------------------- planar synthesis
_GT = np.array([0.0, 0.3, 0.7])                      # three poses of a moving body
_GD = np.array([0, 1 + 0.2j, 1.8 + 0.9j])
_P15 = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j])
_T15 = np.radians([0.0, 8.88, 22.1, 63.68, -3.0])   # example 2-15
_FX = np.radians([0.0, 30.0, 60.0])                  # three precision pairs (docstring)
_FY = np.radians([0.0, 20.0, 35.0])
_FG = dict(theta0=np.radians(60.0), psi0=np.radians(30.0))


def _fgen():
    g, = sy.precision_pairs(_FX, _FY, d=100.0, **_FG)
    return g


def _fmap():
    return sy.FunctionMap(np.log10, (1.0, 10.0), np.radians(100.0), np.radians(60.0))


def _burmester_curve():
    return sy.circle_point_curve(_T15[:4], _P15[:4], samples=24)


def _guidance():
    return sy.guidance_fourbars(_T15, _P15).passing[0]


def _model():
    return sy.DesignModel(lambda x: ((x - 0.3) ** 2).sum(-1), [(0, 1), (0, 1)],
                          inequality=lambda x: x[..., :1] - 0.9, equality=lambda x: x[..., 1:] - 0.3)


def _grid_model():
    return sy.DesignModel(lambda x: ((x - 0.3) ** 2).sum(-1), [(0, 1), (0, 1)], inequality=lambda x: x[..., :1] - 0.9)


def _qr_rocker():
    return sy.quick_return_crank_rocker(1.25, 100.0, np.radians(40.0), alpha=0.6)


def _qr_slider():
    return sy.quick_return_slider_crank(1.25, 100.0, alpha=np.radians(30.0))


_POINTS_2_24 = np.array([1 + 1j, 2 + 1.5j, 3 + 1j])
_X_2_24 = np.array([1.7, 5.8, 5.4, 7.0, 8.0, 2.0, 2.2, np.radians(80), np.radians(-70), np.radians(90)])


_P21 = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 32.95 + 99.62j,
                 44.74 + 113.95j, 58.62 + 127.98j, 66.27 + 215.07j])   # example 2-21
_B21, _C21, _D21 = -95.524 + 80.407j, 76.791 + 170.535j, 174.194 + 18.575j
_P22 = np.array([12.42, 7.98 + 1.89j, 0.76 + 1.47j, 1.30 - 0.85j, 8.83 + 0.3j])   # example 2-22
_A22 = np.radians([4.2, 64.87, 145.82, 219.24, 303.45])
_DESIGN22 = np.array([-5.46 + 1.17j, 0.74 + 1.54j, 16.9 + 15.29j, 9.34 - 20.54j, 12.42 + 0j])


def _path():
    return sy.path_design(0j, _B21, _C21, _D21, _P21)


def _p_slot(defaults, key):
    """A bad value put into one entry of an exercise's parameter mapping ``p``."""
    return ("scalar", lambda v: {**defaults, key: v}, key)


_D27 = chapter2_synthesis.EXERCISE_2_27.defaults
_D28 = chapter2_synthesis.EXERCISE_2_28.defaults
_D29 = chapter2_synthesis.EXERCISE_2_29.defaults
_D30 = chapter2_quick_return.EXERCISE_2_30.defaults
_D31 = chapter2_quick_return.EXERCISE_2_31.defaults
_D32 = chapter2_quick_return.EXERCISE_2_32.defaults

CASES.update({
    "planar.synthesis.displacement_matrix": E(lambda: sy.displacement_matrix,
                                              {"theta_1": "real", "d_1": "point", "theta_i": "real", "d_i": "point"},
                                              theta_1=[0.0, 1.0], d_1=0, theta_i=0.5, d_i=1j),
    "planar.synthesis.pole": E(lambda: sy.pole, {"theta_1": "real", "d_1": "point", "theta_i": "real", "d_i": "point"},
                               theta_1=0.0, d_1=0.0, theta_i=np.pi / 2, d_i=1 + 1j),
    "planar.synthesis.dyad_for_circle_point": E(lambda: sy.dyad_for_circle_point,
                                                {"theta": "real", "d": "point", "circle_point": "point",
                                                 "along": "scalar"},
                                                theta=_GT, d=_GD, circle_point=0.5 + 0.5j, along=0.0),
    "planar.synthesis.dyad_for_centre_point": E(lambda: sy.dyad_for_centre_point,
                                                {"theta": "real", "d": "point", "centre_point": "point",
                                                 "along": "scalar"},
                                                theta=_GT, d=_GD, centre_point=-1 + 2j, along=0.0),
    "planar.synthesis.circle_point_curve": E(lambda: sy.circle_point_curve,
                                             {"theta": "real", "d": "point", "samples": "count", "phi": "real?"},
                                             theta=_T15[:4], d=_P15[:4], samples=24, phi=None),
    "planar.synthesis.circle_point_curve#phi": E(lambda: sy.circle_point_curve, {"phi": "real?"},
                                                 theta=_T15[:4], d=_P15[:4], phi=[0.3, 1.0]),
    "planar.synthesis.BurmesterCurve.dyad": E(lambda: _burmester_curve().dyad, {"i": "int", "k": "int"}, i=0, k=1),
    "planar.synthesis.burmester": E(lambda: sy.burmester,
                                    {"theta": "real", "d": "point", "imag_tol": "scalar", "rank_tol": "scalar"},
                                    theta=_T15, d=_P15, imag_tol=1e-7, rank_tol=1e-12),
    "planar.synthesis.guidance_fourbars": E(lambda: sy.guidance_fourbars,
                                            {"theta": "real", "d": "point", "rtol": "scalar", "dyads": "instance?"},
                                            theta=_T15, d=_P15, rtol=1e-9, dyads=None),
    "planar.synthesis.GuidanceFourBar.to_ground": E(lambda: _guidance().to_ground, {"w": "point"}, w=[0.0, 1 + 1j]),
    "planar.synthesis.GuidanceFourBar.coupler_poses": E(lambda: _guidance().coupler_poses, {"theta_input": "real"},
                                                        theta_input=[0.0, 0.5]),
    "planar.synthesis.FunctionGenerator": E(lambda: sy.FunctionGenerator,
                                            {"lengths": "real", "theta0": "scalar", "psi0": "scalar",
                                             "branch": "branch", "x": "real", "y": "real", "samples": "count",
                                             "tol": "tolerance", "x_range": ("real?", first), "target": "function?"},
                                            lengths=tuple(_fgen().lengths), theta0=_fgen().theta0,
                                            psi0=_fgen().psi0, branch=_fgen().branch, x=_FX, y=_FY, samples=61,
                                            tol=1e-9),
    "planar.synthesis.FunctionGenerator.solve": E(lambda: _fgen().solve, {"x": "real", "order": "order"},
                                                  x=[0.1, 0.5], order=2),
    "planar.synthesis.FunctionGenerator.output": E(lambda: _fgen().output, {"x": "real"}, x=[0.1, 0.5]),
    "planar.synthesis.FunctionGenerator.structural_error": E(lambda: _fgen().structural_error,
                                                             {"x": "real", "y": "real?"}, x=_FX, y=_FY),
    "planar.synthesis.FunctionGenerator.errors": E(lambda: _fgen().errors, {"samples": "count"}, samples=61),
    "planar.synthesis.FunctionMap": E(lambda: sy.FunctionMap,
                                      {"f": "function", "x_range": ("real", first), "theta_range": "scalar",
                                       "psi_range": "scalar"},
                                      f=np.log10, x_range=(1.0, 10.0), theta_range=1.7, psi_range=1.0),
    "planar.synthesis.FunctionMap.input_rotation": E(lambda: _fmap().input_rotation, {"x": "real"}, x=[2.0, 5.0]),
    "planar.synthesis.FunctionMap.input_value": E(lambda: _fmap().input_value, {"X": "real"}, X=[0.2, 0.5]),
    "planar.synthesis.FunctionMap.output_rotation": E(lambda: _fmap().output_rotation, {"y": "real"}, y=[0.2, 0.5]),
    "planar.synthesis.FunctionMap.output_value": E(lambda: _fmap().output_value, {"Y": "real_nan"}, Y=[0.2, np.nan]),
    "planar.synthesis.FunctionMap.rotations": E(lambda: _fmap().rotations, {"x": "real"}, x=[2.0, 5.0]),
    "planar.synthesis.chebyshev_spacing": E(lambda: sy.chebyshev_spacing, {"x0": "scalar", "x1": "scalar", "n": "count"},
                                            x0=1.0, x1=10.0, n=3),
    "planar.synthesis.freudenstein_coefficients": E(lambda: sy.freudenstein_coefficients, _ABCD,
                                                    a=10, b=40, c=30, d=35),
    "planar.synthesis.least_squares": E(lambda: sy.least_squares,
                                        {"x": "real", "y": "real", "theta0": "scalar", "psi0": "scalar", "d": "scalar",
                                         "kind": "option", "fit_start": "bool", "samples": "count", "tol": "tolerance",
                                         "x_range": ("real?", first), "target": "function?", "start": "real?"},
                                        x=np.linspace(0.0, 1.0, 7), y=0.6 * np.linspace(0.0, 1.0, 7) ** 1.2,
                                        theta0=np.radians(60.0), psi0=np.radians(30.0), d=100.0, kind="structural",
                                        fit_start=False, samples=61, tol=1e-9),
    "planar.synthesis.lengths_from_coefficients": E(lambda: sy.lengths_from_coefficients,
                                                    {"k1": "scalar", "k2": "scalar", "k3": "scalar", "d": "scalar"},
                                                    k1=3.5, k2=35 / 30, k3=625 / 600, d=35.0),
    "planar.synthesis.precision_pairs": E(lambda: sy.precision_pairs,
                                          {"x": "real", "y": "real", "theta0": "scalar?", "psi0": "scalar?",
                                           "d": "scalar", "samples": "count", "tol": "tolerance",
                                           "x_range": ("real?", first), "target": "function?"},
                                          x=_FX, y=_FY, d=100.0, samples=61, tol=1e-9, **_FG),
    "planar.synthesis.QuickReturnCrankRocker.check": E(lambda: _qr_rocker().check,
                                                       {"samples": "count", "xtol": "scalar"}, samples=256, xtol=1e-13),
    "planar.synthesis.QuickReturnSliderCrank.check": E(lambda: _qr_slider().check,
                                                       {"samples": "count", "xtol": "scalar"}, samples=256, xtol=1e-13),
    "planar.synthesis.QuickReturnGuideBar.check": E(lambda: sy.quick_return_guide_bar(1.5, 100.0).check,
                                                    {"samples": "count", "xtol": "scalar"}, samples=256, xtol=1e-13),
    "planar.synthesis.QuickReturnFamily.designs": E(
        lambda: sy.slider_crank_family(1.25, 100.0, samples=101).designs, {"n": "count"}, n=3),
    "planar.synthesis.crank_rocker_family": E(lambda: sy.crank_rocker_family,
                                              {"time_ratio": "scalar", "rocker": "scalar", "swing": "scalar",
                                               "min_transmission": "scalar", "side": "branch", "samples": "count",
                                               "xtol": "scalar"},
                                              time_ratio=1.25, rocker=100.0, swing=np.radians(40.0),
                                              min_transmission=0.0, side=1, samples=101, xtol=1e-12),
    "planar.synthesis.slider_crank_family": E(lambda: sy.slider_crank_family,
                                              {"time_ratio": "scalar", "stroke": "scalar",
                                               "min_transmission": "scalar", "samples": "count", "xtol": "scalar"},
                                              time_ratio=1.25, stroke=100.0, min_transmission=0.0, samples=101,
                                              xtol=1e-12),
    "planar.synthesis.quick_return_crank_rocker": E(lambda: sy.quick_return_crank_rocker,
                                                    {"time_ratio": "scalar", "rocker": "scalar", "swing": "scalar",
                                                     "alpha": "scalar?", "side": "branch"},
                                                    time_ratio=1.25, rocker=100.0, swing=np.radians(40.0), alpha=0.6,
                                                    side=1),
    "planar.synthesis.quick_return_crank_rocker#crank": E(lambda: sy.quick_return_crank_rocker, {"crank": "scalar?"},
                                                          time_ratio=1.25, rocker=100.0, swing=np.radians(40.0),
                                                          crank=30.0),
    "planar.synthesis.quick_return_crank_rocker#coupler": E(lambda: sy.quick_return_crank_rocker,
                                                            {"coupler": "scalar?"}, time_ratio=1.25, rocker=100.0,
                                                            swing=np.radians(40.0), coupler=100.0),
    "planar.synthesis.quick_return_guide_bar": E(lambda: sy.quick_return_guide_bar,
                                                 {"time_ratio": "scalar", "frame": "scalar"}, time_ratio=1.5,
                                                 frame=100.0),
    "planar.synthesis.quick_return_slider_crank": E(lambda: sy.quick_return_slider_crank,
                                                    {"time_ratio": "scalar", "stroke": "scalar", "alpha": "scalar?"},
                                                    time_ratio=1.25, stroke=100.0, alpha=np.radians(30.0)),
    "planar.synthesis.quick_return_slider_crank#offset": E(lambda: sy.quick_return_slider_crank,
                                                           {"offset": "scalar?"}, time_ratio=1.25, stroke=100.0,
                                                           offset=20.0),
    "planar.synthesis.simulate_quick_return": E(lambda: sy.simulate_quick_return,
                                                {"linkage": "instance", "samples": "count", "xtol": "scalar"},
                                                linkage=pl.FourBar(10, 40, 30, 35), samples=256, xtol=1e-13),
    "planar.synthesis.DesignModel": E(lambda: sy.DesignModel, {"objective": "function", "inequality": "function?",
                                                               "bounds": ("real", lambda v: [v, (0, 1)])},
                                      objective=lambda x: (x ** 2).sum(-1), bounds=[(0, 1), (0, 1)]),
    "planar.synthesis.DesignModel.f": E(lambda: _model().f, {"x": "real"}, x=[0.5, 0.5]),
    "planar.synthesis.DesignModel.g": E(lambda: _model().g, {"x": "real"}, x=[0.5, 0.5]),
    "planar.synthesis.DesignModel.h": E(lambda: _model().h, {"x": "real"}, x=[0.5, 0.5]),
    "planar.synthesis.DesignModel.feasible": E(lambda: _model().feasible, {"x": "real", "tol": "scalar"},
                                               x=[0.5, 0.5], tol=0.0),
    "planar.synthesis.OptimisationResult.as_dict": E(lambda: sy.grid_search(_grid_model(), points=5, levels=2).as_dict),
    "planar.synthesis.grid_search": E(lambda: sy.grid_search,
                                      {"model": "instance", "points": "count", "levels": "count", "shrink": "scalar",
                                       "max_points": "count", "progress": "bool", "every": "count"},
                                      model=_grid_model(), points=5, levels=2, shrink=0.5, max_points=1000,
                                      progress=False, every=1),
    "planar.synthesis.penalty_method": E(lambda: sy.penalty_method,
                                         {"model": "instance", "x0": "real", "r0": "scalar?", "factor": "scalar", "stages": "count",
                                          "iterations": "count", "step": "scalar", "ftol": "scalar",
                                          "xtol": "scalar", "progress": "bool", "every": "count"},
                                         model=_model(), x0=[0.5, 0.5], r0=None, factor=0.3, stages=2, iterations=20,
                                         step=0.05, ftol=1e-13, xtol=1e-11, progress=False, every=200),
    "planar.synthesis.scipy_minimize": E(lambda: sy.scipy_minimize, {"model": "instance", "x0": "real", "method": "option"},
                                         model=_model(), x0=[0.5, 0.5], method="SLSQP"),
    "planar.synthesis.CouplerPathDesign": E(lambda: sy.CouplerPathDesign, {"x": "real", "points": "point"},
                                            x=_X_2_24, points=_POINTS_2_24),
    "planar.synthesis.CouplerPathDesign.place": E(lambda: sy.CouplerPathDesign(_X_2_24, _POINTS_2_24).place,
                                                  {"z": "point"}, z=[0.0, 1 + 1j]),
    "planar.synthesis.CouplerPathDesign.prove": E(lambda: sy.CouplerPathDesign(_X_2_24, _POINTS_2_24).prove,
                                                  {"samples": "count"}, samples=360),
    "planar.synthesis.SteeringTrapezoid": E(lambda: sy.SteeringTrapezoid,
                                            {"l1": "scalar", "phi0": "scalar", "a": "scalar", "h": "scalar"},
                                            l1=148.0, phi0=1.2263, a=1480.0, h=2960.0),
    "planar.synthesis.SteeringTrapezoid.beta": E(lambda: sy.SteeringTrapezoid(148.0, 1.2263).beta,
                                                 {"theta": "real"}, theta=[0.0, 0.3]),
    "planar.synthesis.SteeringTrapezoid.beta_ideal": E(lambda: sy.SteeringTrapezoid(148.0, 1.2263).beta_ideal,
                                                       {"theta": "real"}, theta=[0.0, 0.3]),
    "planar.synthesis.SteeringTrapezoid.prove": E(lambda: sy.SteeringTrapezoid(148.0, 1.2263).prove,
                                                  {"theta_max": "scalar", "steps": "count"}, theta_max=0.5, steps=5),
    "planar.synthesis.path_synthesis_model": E(lambda: sy.path_synthesis_model,
                                               {"points": "point", "gamma_min": "scalar"},
                                               points=_POINTS_2_24, gamma_min=np.radians(30.0)),
    "planar.synthesis.steering_trapezoid_model": E(lambda: sy.steering_trapezoid_model,
                                                   {"a": "scalar", "h": "scalar", "theta_max": "scalar",
                                                    "steps": "count", "arm_range": ("real", first),
                                                    "clearance": "scalar"},
                                                   a=1480.0, h=2960.0, theta_max=0.5, steps=5, arm_range=(0.1, 0.4),
                                                   clearance=0.6),
    "planar.synthesis.PathFourBar.to_ground": E(lambda: _path().to_ground, {"w": "point"}, w=[0.0, 1 + 1j]),
    "planar.synthesis.PathFourBar.coupler_point": E(lambda: _path().coupler_point, {"theta_input": "real"},
                                                    theta_input=[0.0, 1.0]),
    "planar.synthesis.path_design": E(lambda: sy.path_design,
                                      {"A": "point1", "B1": "point1", "C1": "point1", "D": "point1",
                                       "points": "point", "rtol": "scalar"},
                                      A=0j, B1=_B21, C1=_C21, D=_D21, points=_P21, rtol=1e-9),
    "planar.synthesis.path_residuals": E(lambda: sy.path_residuals,
                                         {"design": "point", "points": "point", "crank_angles": "real"},
                                         design=_DESIGN22, points=_P22[:2], crank_angles=_A22[:2]),
    "planar.synthesis.path_residuals#result": E(lambda: sy.path_residuals, {"points": "point", "crank_angles": "real"},
                                                design=_path(), points=_P21[:2], crank_angles=[0.0, 0.5]),
    "planar.synthesis.path_timed": E(lambda: sy.path_timed,
                                     {"points": "point", "crank_angles": "real", "rtol": "scalar",
                                      "imag_tol": "scalar"},
                                     points=_P22, crank_angles=_A22, rtol=1e-9, imag_tol=1e-7),
    "planar.synthesis.path_untimed": E(lambda: sy.path_untimed,
                                       {"points": "point", "A": "point1?", "D": "point1?",
                                        "initial": ("point", lambda v: [v]), "starts": "count", "seed": "seed",
                                        "max_steps": "count", "tol": "scalar", "distinct_tol": "scalar",
                                        "rtol": "scalar"},
                                       points=_P22, A=_DESIGN22[0], D=_DESIGN22[3], initial=[_DESIGN22[:4]],
                                       starts=1, seed=0, max_steps=20, tol=1e-10, distinct_tol=1e-6, rtol=1e-9),
    # ------------------------------------------------------------------------- exercises 2-27 to 2-32
    "exercises.chapter2_synthesis.design_2_27": E(lambda: chapter2_synthesis.design_2_27, None, p=_D27),
    "exercises.chapter2_synthesis.design_2_28": E(lambda: chapter2_synthesis.design_2_28, None, p=_D28),
    "exercises.chapter2_synthesis.design_2_29": E(lambda: chapter2_synthesis.design_2_29,
                                                  {"interior": "bool"},
                                                  p=_D29, interior=False),
    "exercises.chapter2_quick_return.designs_2_30": E(lambda: chapter2_quick_return.designs_2_30,
                                                      {"given": "option"},
                                                      p=_D30, given="a"),
    "exercises.chapter2_quick_return.designs_2_31": E(lambda: chapter2_quick_return.designs_2_31,
                                                      None, p=_D31),
    "exercises.chapter2_quick_return.shaper_2_32": E(lambda: chapter2_quick_return.shaper_2_32,
                                                     None, p=_D32),
    "exercises.chapter2_quick_return.Shaper.ram": E(lambda: chapter2_quick_return.shaper_2_32(_D32).ram,
                                                    {"theta": "real", "order": "order"}, theta=[0.0, 1.0], order=2),
    "exercises.chapter2_quick_return.Shaper.pressure_angle": E(
        lambda: chapter2_quick_return.shaper_2_32(_D32).pressure_angle, {"theta": "real"}, theta=[0.0, 1.0]),
    "exercises.chapter2_quick_return.Shaper.measure": E(lambda: chapter2_quick_return.shaper_2_32(_D32).measure,
                                                        {"samples": "count", "xtol": "scalar"}, samples=256,
                                                        xtol=1e-13),
})

# every entry of the parameter mappings `p` that a function reads, and the exercises' own solve
_P_FUNCTIONS = [  # (key, function, defaults, the entries it reads, other arguments)
    ("design_2_27", lambda: chapter2_synthesis.design_2_27, _D27, list(_D27), {}),
    ("design_2_28", lambda: chapter2_synthesis.design_2_28, _D28, list(_D28), {}),
    ("design_2_29", lambda: chapter2_synthesis.design_2_29, _D29, list(_D29), {}),
    ("designs_2_30", lambda: chapter2_quick_return.designs_2_30, _D30, ["l_CD", "psi", "K", "l_AB"], {"given": "a"}),
    ("designs_2_30", lambda: chapter2_quick_return.designs_2_30, _D30, ["l_BC"], {"given": "b"}),
    ("designs_2_31", lambda: chapter2_quick_return.designs_2_31, _D31, list(_D31), {}),
    ("shaper_2_32", lambda: chapter2_quick_return.shaper_2_32, _D32, list(_D32), {}),
]
for _func, _get, _defaults, _read, _extra in _P_FUNCTIONS:
    _module = "chapter2_synthesis" if _func.startswith("design_2_") else "chapter2_quick_return"
    for _name in _read:
        CASES[f"exercises.{_module}.{_func}#{_name}"] = E(_get, {"p": _p_slot(_defaults, _name)}, p=_defaults,
                                                         **_extra)
for _number, _defaults in (("2-27", _D27), ("2-28", _D28), ("2-29", _D29), ("2-30", _D30), ("2-31", _D31), ("2-32", _D32),
                           *((n, ex.get(n).defaults) for n in ("2-1", "2-8", "2-9", "2-11", "2-12", "2-13", "2-14", "2-15", "2-16", "2-17", "2-18", "2-25", "2-26"))):
    CASES[f"exercises.Exercise.solve#{_number}"] = E(lambda n=_number: ex.get(n).solve,
                                                     {k: "scalar" for k in _defaults}, **_defaults)

RECORDS.update({
    **{f"planar.synthesis.{n}": "result record built by the package" for n in (
        "Dyad", "BurmesterCurve", "BurmesterPoints", "GuidanceFourBar", "GuidanceSynthesis", "QuickReturnCheck",
        "QuickReturnCrankRocker", "QuickReturnFamily", "QuickReturnGuideBar", "QuickReturnSliderCrank",
        "OptimisationResult", "PathFourBar", "PathSynthesis")},
    "exercises.chapter2_quick_return.Shaper": "result record built by the package (shaper_2_32)",
    "exercises.chapter2_synthesis.RockerSlider": "result record built by the package (design_2_28)",
})


# slider (point-on-line) dyads and guidance slider-cranks
_ST = np.array([0.2, 0.9, 1.6, 2.5])                 # a slider-crank a = 1, b = 3, e = 0.5 (docstring)
_SB = np.exp(1j * _ST)
_SC = _SB.real + np.sqrt(9 - (0.5 - _SB.imag) ** 2) + 0.5j
_STH = np.angle(_SC - _SB)


def _slider_crank_design():
    return sy.guidance_slider_crank(_STH[:3], _SB[:3], sy.dyad_for_circle_point(_STH[:3], _SB[:3], 0.0),
                                    sy.slider_dyad_for_point(_STH[:3], _SB[:3], 3.0))


CASES.update({
    "planar.synthesis.slider_dyad_for_point": E(lambda: sy.slider_dyad_for_point,
                                                {"theta": "real", "d": "point", "slider_point": "point1",
                                                 "rtol": "scalar"},
                                                theta=_STH[:3], d=_SB[:3], slider_point=3.0, rtol=1e-9),
    "planar.synthesis.slider_point_circle": E(lambda: sy.slider_point_circle, {"theta": "real", "d": "point"},
                                              theta=_STH[:3], d=_SB[:3]),
    "planar.synthesis.SliderCircle.points": E(lambda: sy.slider_point_circle(_STH[:3], _SB[:3]).points,
                                              {"n": "count"}, n=12),
    "planar.synthesis.slider_dyads": E(lambda: sy.slider_dyads, {"theta": "real", "d": "point", "rtol": "scalar"},
                                       theta=_STH, d=_SB, rtol=1e-9),
    "planar.synthesis.guidance_slider_crank": E(
        lambda: sy.guidance_slider_crank,
        {"theta": "real", "d": "point", "crank": "instance", "slider": "instance", "rtol": "scalar"},
        theta=_STH[:3], d=_SB[:3], crank=sy.dyad_for_circle_point(_STH[:3], _SB[:3], 0.0),
        slider=sy.slider_dyad_for_point(_STH[:3], _SB[:3], 3.0), rtol=1e-9),
    "planar.synthesis.GuidanceSliderCrank.coupler_poses": E(lambda: _slider_crank_design().coupler_poses,
                                                            {"theta_input": "real"}, theta_input=[0.2, 0.5]),
})
RECORDS.update({f"planar.synthesis.{n}": "result record built by the package"
                for n in ("SliderDyad", "SliderCircle", "GuidanceSliderCrank", "CentricSliderCrank")})


# centric slider-cranks of four poses (2-42): poses of example 2-15, 1-4
_CP = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j])
_CTH = np.radians([0.0, 8.88, 22.1, 63.68])


def _centric_design():
    return sy.centric_slider_cranks(_CTH, _CP)[0]


CASES.update({
    "planar.synthesis.centric_slider_cranks": E(lambda: sy.centric_slider_cranks,
                                                {"theta": "real", "d": "point", "rtol": "scalar",
                                                 "imag_tol": "scalar"},
                                                theta=_CTH, d=_CP, rtol=1e-9, imag_tol=1e-7),
    "planar.synthesis.CentricSliderCrank.coupler_poses": E(lambda: _centric_design().coupler_poses,
                                                           {"theta_input": "real"}, theta_input=[0.2, 0.5]),
    "planar.synthesis.CentricSliderCrank.to_ground": E(lambda: _centric_design().to_ground, {"w": "point"}, w=1 + 1j),
})


# ----------------------------------------------------------------------------- atlas (issue 13)
# The small atlases (and their folders) are built once per process: every bad value of
# every slot called a fresh build (seeded, so the same atlas), most of this walk's time.
@functools.lru_cache(maxsize=None)
def _small_atlas():
    return at.build_atlas(40, seed=1)


@functools.lru_cache(maxsize=None)
def _atlas_dir():
    import tempfile

    folder = tempfile.mkdtemp(prefix="mech-atlas-")
    _small_atlas().to_parquet(folder)
    return folder


def _points_csv():
    import tempfile

    handle, name = tempfile.mkstemp(suffix=".csv")
    with open(handle, "w") as f:
        f.write("x,y\n0,0\n1,0\n1,1\n0,1\n")
    return name


def _path_svg():
    import tempfile

    handle, name = tempfile.mkstemp(suffix=".svg")
    with open(handle, "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 10 0 L 10 10 Z"/></svg>')
    return name


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


def _new_dir():
    import tempfile

    return tempfile.mkdtemp(prefix="mech-atlas-") + "/atlas"


_SQUARE = [0, 1, 1 + 1j, 1j]
_SPHERE_CURVE = [[0.6, 0.0, 0.8], [0.0, 0.6, 0.8], [-0.6, 0.0, 0.8], [0.0, -0.5, 0.8], [0.3, -0.3, 0.9]]


@functools.lru_cache(maxsize=None)
def _small_slider_atlas():
    return at.build_atlas(40, seed=1, mechanism="slider-crank")


@functools.lru_cache(maxsize=None)
def _small_sphere_atlas():
    return at.build_sphere_atlas(8, seed=1, harmonics=3, samples=16)


def _sphere_match():
    return at.query_sphere(_small_sphere_atlas(), _SPHERE_CURVE, k=1, shortlist=4)[0]


@functools.lru_cache(maxsize=None)
def _sphere_atlas_dir():
    import tempfile

    folder = tempfile.mkdtemp(prefix="mech-sphere-atlas-")
    _small_sphere_atlas().to_parquet(folder)
    return folder
CASES.update({
    "atlas.curve_signature": E(lambda: at.curve_signature,
                               {"points": "point", "closed": "bool", "harmonics": "count", "samples": "count",
                                "resampled": "bool"},
                               points=_SQUARE, closed=True, harmonics=4, samples=32, resampled=False),
    "atlas.resample": E(lambda: at.resample, {"points": "point", "samples": "count", "closed": "bool"},
                        points=_SQUARE, samples=16, closed=True),
    "atlas.read_points": E(lambda: functools.partial(at.read_points, _points_csv())),
    "atlas.read_target": E(lambda: functools.partial(at.read_target, _points_csv()), {"samples": "count"}, samples=50),
    "atlas.read_svg": E(lambda: functools.partial(at.read_svg, _path_svg()), {"samples": "count"}, samples=50),
    "atlas.sample_fourbars": E(lambda: at.sample_fourbars,
                               {"n": "count", "seed": "seed", "lengths": ("scalar", lambda v: (v, 5.0)),
                                "coupler": ("scalar", lambda v: (v, 2.0, -1.0, 1.0)), "branch": "branch?",
                                "min_transmission": "scalar"},
                               n=20, seed=3, lengths=(0.2, 5.0), coupler=(-1.0, 2.0, -1.0, 1.0), branch=None,
                               min_transmission=0.1),
    "atlas.FourBarSamples.take": E(lambda: at.sample_fourbars(10).take, {"index": "int"}, index=[1, 2]),
    "atlas.FourBarSamples.columns": E(lambda: at.sample_fourbars(10).columns),
    "atlas.FourBarSamples.fourbar": E(lambda: _small_atlas().linkages.fourbar, {"i": "int"}, i=3),
    "atlas.FourBarSamples.curves": E(lambda: _small_atlas().linkages.curves, {"samples": "count"}, samples=16),
    "atlas.build_atlas": E(lambda: at.build_atlas,
                           {"n": "count", "seed": "seed", "harmonics": "count", "samples": "count",
                            "lengths": ("scalar", lambda v: (v, 5.0)),
                            "coupler": ("scalar", lambda v: (v, 2.0, -1.0, 1.0)), "min_transmission": "scalar",
                            "block": "count", "progress": "bool", "resume": "bool"},
                           n=30, seed=2, harmonics=4, samples=32, lengths=(0.2, 5.0), coupler=(-1.0, 2.0, -1.0, 1.0),
                           min_transmission=0.0, block=64, progress=False, resume=False),
    "atlas.build_atlas#slider-crank": E(lambda: at.build_atlas,
                                         {"n": "count", "lengths": ("scalar", lambda v: (v, 5.0)),
                                          "offsets": ("scalar", lambda v: (v, 2.0)), "mechanism": "option"},
                                         n=20, lengths=(0.3, 5.0), offsets=(-2.0, 2.0), mechanism="slider-crank",
                                         block=64),
    "atlas.sample_slider_cranks": E(lambda: at.sample_slider_cranks,
                                    {"n": "count", "seed": "seed", "rods": ("scalar", lambda v: (v, 5.0)),
                                     "offsets": ("scalar", lambda v: (v, 2.0)),
                                     "coupler": ("scalar", lambda v: (v, 2.0, -1.0, 1.0)), "branch": "branch?",
                                     "min_transmission": "scalar"},
                                    n=20, seed=3, rods=(0.3, 5.0), offsets=(-2.0, 2.0), coupler=(-1.0, 2.0, -1.0, 1.0),
                                    branch=None, min_transmission=0.1),
    "atlas.SliderCrankSamples.take": E(lambda: at.sample_slider_cranks(10).take, {"index": "int"}, index=[1, 2]),
    "atlas.SliderCrankSamples.columns": E(lambda: at.sample_slider_cranks(10).columns),
    "atlas.SliderCrankSamples.slider_crank": E(lambda: _small_slider_atlas().linkages.slider_crank,
                                               {"i": "int"}, i=3),
    "atlas.SliderCrankSamples.curves": E(lambda: at.sample_slider_cranks(10).curves, {"samples": "count"},
                                         samples=16),
    "atlas.PlacedSliderCrank.place": E(lambda: at.query(_small_slider_atlas(), _SQUARE, k=1)[0].linkage.place,
                                       {"z": "point"}, z=[0.0, 1 + 1j]),
    "atlas.Atlas.curves": E(lambda: _small_atlas().curves, {"index": "int", "samples": "count?"},
                            index=[0, 3], samples=None),
    "atlas.Atlas.to_parquet": E(lambda: functools.partial(_small_atlas().to_parquet, _new_dir()),
                                {"append": "bool"}, append=False),
    "atlas.Atlas.from_parquet": E(lambda: functools.partial(at.Atlas.from_parquet, _atlas_dir())),
    "atlas.query": E(lambda: functools.partial(at.query, _small_atlas()),
                     {"target": "point", "k": "count", "shortlist": "count", "resampled": "bool",
                      "closed": "bool", "span": "scalar", "starts": "count"},
                     target=_SQUARE, k=2, shortlist=8, resampled=False, closed=True, span=0.5, starts=8),
    "atlas.refine": E(lambda: functools.partial(at.refine, at.query(_small_atlas(), _SQUARE, k=1)[0]),
                      {"target": "point", "samples": "count", "iterations": "count"},
                      target=_SQUARE, samples=32, iterations=3),
    "atlas.find_linkages": E(lambda: functools.partial(at.find_linkages, _small_atlas()),
                             {"target": "point", "starts": "count", "goal": "scalar?", "samples": "count",
                              "iterations": "count"},
                             target=_SQUARE, starts=2, goal=0.5, samples=32, iterations=3),
    "atlas.Constraints": E(lambda: at.Constraints, {"crank": "bool", "min_transmission": "tolerance"},
                           crank=True, min_transmission=0.5),
    "atlas.Constraints.none": E(lambda: at.Constraints.none),
    "atlas.Constraints.violations": E(lambda: functools.partial(at.Constraints().violations,
                                                                pl.FourBar(10, 40, 30, 35))),
    "atlas.sphere_signature": E(lambda: at.sphere_signature,
                                {"points": "vec3", "harmonics": "count", "samples": "count", "resampled": "bool",
                                 "closed": "bool"},
                                points=_SPHERE_CURVE, harmonics=3, samples=16, resampled=False, closed=True),
    "atlas.build_sphere_atlas": E(lambda: at.build_sphere_atlas,
                                  {"n": "count", "seed": "seed", "harmonics": "count", "samples": "count",
                                   "arcs": ("scalar", lambda v: (v, 1.4)),
                                   "coupler_arc": ("scalar", lambda v: (v, 1.2)), "min_transmission": "scalar",
                                   "block": "count", "progress": "bool", "resume": "bool"},
                                  n=3, seed=1, harmonics=3, samples=16, arcs=(0.15, 1.4), coupler_arc=(0.1, 1.2),
                                  min_transmission=0.0, block=64, progress=False, resume=False),
    "atlas.query_sphere": E(lambda: functools.partial(at.query_sphere, _small_sphere_atlas()),
                            {"target": "vec3", "k": "count", "shortlist": "count", "resampled": "bool",
                             "closed": "bool", "span": "scalar", "starts": "count"},
                            target=_SPHERE_CURVE, k=1, shortlist=4, resampled=False, closed=True, span=0.5, starts=4),
    "atlas.refine_sphere": E(lambda: functools.partial(at.refine_sphere, _sphere_match()),
                             {"target": "vec3", "samples": "count", "iterations": "count"},
                             target=_SPHERE_CURVE, samples=16, iterations=2),
    "atlas.find_sphere_linkages": E(lambda: functools.partial(at.find_sphere_linkages, _small_sphere_atlas()),
                                    {"target": "vec3", "starts": "count", "goal": "scalar?", "samples": "count",
                                     "iterations": "count"},
                                    target=_SPHERE_CURVE, starts=1, goal=0.5, samples=16, iterations=2),
    "atlas.sample_sphere_fourbars": E(lambda: at.sample_sphere_fourbars,
                                      {"n": "count", "seed": "seed", "arcs": ("scalar", lambda v: (v, 1.4)),
                                       "coupler_arc": ("scalar", lambda v: (v, 1.2)), "branch": "branch?",
                                       "min_transmission": "scalar"},
                                      n=10, seed=3, arcs=(0.15, 1.4), coupler_arc=(0.1, 1.2), branch=None,
                                      min_transmission=0.1),
    "atlas.SphereSamples.take": E(lambda: at.sample_sphere_fourbars(10).take, {"index": "int"}, index=[1, 2]),
    "atlas.SphereSamples.columns": E(lambda: at.sample_sphere_fourbars(10).columns),
    "atlas.SphereSamples.fourbar": E(lambda: _small_sphere_atlas().linkages.fourbar, {"i": "int", "frame": "matrix?"},
                                     i=1, frame=None),
    "atlas.SphereSamples.curves": E(lambda: _small_sphere_atlas().linkages.curves, {"samples": "count"}, samples=16),
    "atlas.SphereAtlas.to_parquet": E(lambda: functools.partial(_small_sphere_atlas().to_parquet, _new_dir()),
                                      {"append": "bool"}, append=False),
    "atlas.SphereAtlas.from_parquet": E(lambda: functools.partial(at.SphereAtlas.from_parquet, _sphere_atlas_dir())),
    "atlas.SphereAtlas.fourbar": E(lambda: _small_sphere_atlas().fourbar, {"i": "int"}, i=1),
    "atlas.SphereAtlas.curves": E(lambda: _small_sphere_atlas().curves, {"samples": "count?"},
                                  index=[0, 1], samples=None),
    "atlas.PlacedLinkage.place": E(lambda: at.query(_small_atlas(), _SQUARE, k=1)[0].linkage.place,
                                   {"z": "point"}, z=[0.0, 1 + 1j]),
})
RECORDS.update({f"atlas.{n}": "result record built by the package"
                for n in ("Atlas", "FourBarSamples", "Match", "PlacedLinkage", "PlacedSliderCrank",
                          "SliderCrankSamples", "SphereAtlas", "SphereMatch", "SphereSamples")})


# ----------------------------------------------------------------------------- spherical guidance (issue 15)
def _sg_set(n):
    axes = [[0, 0, 1], [0.2, 0.1, 1], [-0.3, 0.2, 1], [0.1, -0.4, 1], [0.5, 0.3, 1]]
    angles = [0.0, 0.5, 1.0, 1.4, 1.9]
    return np.stack([sph.rotation_matrix(a, t) for a, t in zip(axes[:n], angles[:n])])


def _sg_five():
    rng = np.random.default_rng(3)
    return np.stack([sph.rotation_matrix(rng.normal(size=3), rng.uniform(0.1, 1.2)) for _ in range(5)])


def _sg_slider():
    curve = sph.slider_point_curve(_sg_set(3), samples=12)
    return curve.dyad(*np.argwhere(curve.valid)[0])


def _sg_crank():
    return sph.dyad_for_circle_point(_sg_set(3), [0.3, 0.2, 0.93])


_SGZ = [0.3, 0.2, 0.93]
CASES.update({
    "spherical.relative_rotation": E(lambda: sph.relative_rotation, {"R_1": "matrix", "R_j": "matrix"},
                                     R_1=np.eye(3), R_j=_sg_set(2)[1]),
    "spherical.rotation_pole": E(lambda: sph.rotation_pole, {"R_1": "matrix", "R_j": "matrix"},
                                 R_1=np.eye(3), R_j=_sg_set(2)[1]),
    "spherical.pole_triangle": E(lambda: sph.pole_triangle, {"R": "matrix"}, R=_sg_set(3)),
    "spherical.crank_residual": E(lambda: sph.crank_residual,
                                  {"R_1": "matrix", "R_j": "matrix", "circle_point": "vec3", "centre_point": "vec3"},
                                  R_1=np.eye(3), R_j=_sg_set(2)[1], circle_point=_SGZ, centre_point=[0, 0, 1]),
    "spherical.slider_residual": E(lambda: sph.slider_residual,
                                   {"R_j": "matrix", "slider_point": "vec3", "guide_pole": "vec3"},
                                   R_j=_sg_set(2)[1], slider_point=_SGZ, guide_pole=[0, 0, 1]),
    "spherical.planar_orientations": E(lambda: sph.planar_orientations,
                                       {"theta": "real", "d": "point", "scale": "scalar"},
                                       theta=[0.0, 0.5], d=[0.0, 2 + 1j], scale=1e-3),
    "spherical.dyad_for_circle_point": E(lambda: sph.dyad_for_circle_point,
                                         {"R": "matrix", "circle_point": "vec3", "along": "scalar"},
                                         R=_sg_set(3), circle_point=_SGZ, along=0.0),
    "spherical.dyad_for_centre_point": E(lambda: sph.dyad_for_centre_point,
                                         {"R": "matrix", "centre_point": "vec3", "along": "scalar"},
                                         R=_sg_set(2), centre_point=[0.1, -0.2, 0.97], along=0.3),
    "spherical.slider_dyad_for_point": E(lambda: sph.slider_dyad_for_point,
                                         {"R": "matrix", "slider_point": "vec3", "rtol": "scalar"},
                                         R=_sg_set(2), slider_point=_SGZ, rtol=1e-9),
    "spherical.circle_point_curve": E(lambda: sph.circle_point_curve,
                                      {"R": "matrix", "samples": "count", "phi": "real?"},
                                      R=_sg_set(4), samples=24, phi=None),
    "spherical.slider_point_curve": E(lambda: sph.slider_point_curve,
                                      {"R": "matrix", "samples": "count", "phi": "real?"},
                                      R=_sg_set(3), samples=24, phi=None),
    "spherical.SphericalBurmesterCurve.dyad": E(lambda: sph.circle_point_curve(_sg_set(4), samples=24).dyad,
                                                {"i": "int", "k": "int"}, i=0, k=0),
    "spherical.slider_dyads": E(lambda: sph.slider_dyads, {"R": "matrix", "imag_tol": "scalar"}, R=_sg_set(4),
                                imag_tol=1e-6),
    "spherical.burmester": E(lambda: sph.burmester, {"R": "matrix", "imag_tol": "scalar"}, R=_sg_five(),
                             imag_tol=1e-6),
    "spherical.guidance_fourbars": E(lambda: sph.guidance_fourbars,
                                     {"R": "matrix", "rtol": "scalar", "dyads": "instance?"},
                                     R=_sg_five(), rtol=1e-9, dyads=None),
    "spherical.guidance_slider_crank": E(lambda: sph.guidance_slider_crank,
                                         {"R": "matrix", "crank": "instance", "slider": "instance", "rtol": "scalar"},
                                         R=_sg_set(3), crank=_sg_crank(), slider=_sg_slider(), rtol=1e-9),
    "spherical.SphericalGuidanceFourBar.coupler_orientations": E(
        lambda: sph.guidance_fourbars(_sg_five()).candidates[0].coupler_orientations, {"theta_input": "real"},
        theta_input=[0.1, 0.4]),
})


def _sg_nine():
    """Nine coupler orientations of a crank-rocker (as in tests/spherical/guidance/test_spherical_optimal.py)."""
    lk = sph.SphericalFourBar(0.35, 0.75, 0.6, 0.8)
    pose = lk.solve(np.linspace(0.3, 2.6, 9))
    zB, zC = np.array([0.0, 0.0, 1.0]), np.array([np.sin(0.75), 0.0, np.cos(0.75)])

    def frame(p, q):
        t = q - np.sum(p * q, axis=-1, keepdims=True) * p
        t = t / np.linalg.norm(t, axis=-1, keepdims=True)
        return np.stack([p, t, np.cross(p, t)], axis=-1)
    return frame(pose.B, pose.C) @ frame(zB, zC).T


CASES.update({
    "spherical.guidance_motion": E(lambda: sph.guidance_motion, {"design": "instance", "theta_input": "real"},
                                   design=sph.guidance_fourbars(_sg_five()).candidates[0], theta_input=[0.1, 0.4]),
    "spherical.optimal_guidance": E(lambda: sph.optimal_guidance,
                                    {"R": "matrix", "start": "instance?", "objective": "option",
                                     "theta_input": "real?", "rtol": "scalar"},
                                    R=_sg_nine(), start=None, objective="orientation",
                                    theta_input=np.linspace(0.0, 2.3, 9), rtol=1e-2),
    "spherical.minimax": E(lambda: sph.minimax,
                           {"x": "real", "y": "real", "theta0": "scalar", "psi0": "scalar", "start": "instance?",
                            "tol": "scalar", "max_iter": "count"},
                           x=np.linspace(0.0, 1.0, 41), y=0.5 * np.sin(np.linspace(0.0, 1.0, 41)),
                           theta0=0.7, psi0=1.4, start=None, tol=1e-10, max_iter=40),
})
RECORDS.update({f"spherical.{n}": "result record built by the package" for n in (
    "SphericalDyad", "SphericalBurmesterCurve", "SphericalBurmesterPoints", "SphericalGuidanceFourBar",
    "SphericalGuidanceMotion", "SphericalOptimalGuidance", "SphericalGuidanceSixBar", "SphericalOptimalSixBar")})


_KEPT = {}


def _kept(build):
    """The design built by `build`, built once per process (keyed by its code: each factory
    below builds one fixed design, and rebuilding it for every bad value took most of the walk)."""
    if build.__code__ not in _KEPT:
        _KEPT[build.__code__] = build()
    return _KEPT[build.__code__]


def _sx_watt2():
    lk = sph.watt2(0.3, 0.9, 0.7, 1.0, E=(0.3, 0.5), F=(1.4, 0.4), arcs=(0.6, 0.5), coupler=(0.3, 0.4))
    return lk, np.array([0.2, 0.7, 1.3, 1.9, 2.6])


def _sx_nine():
    # five exact orientations: the optimiser, started from an exact design clear of its
    # dead points, stops at once (a search through noisy orientations takes seconds, and the
    # walk calls it at many values)
    lk, theta = _sx_watt2()
    return sph.sixbar_orientations(lk, theta), theta


def _sx_start():
    R, theta = _sx_nine()
    return [d for d in sph.guidance_watt2(R, theta, [0.3, -0.2, 0.93], sweep=41) if d.passes][1]


CASES.update({
    "spherical.sixbar_orientations": E(lambda: sph.sixbar_orientations, {"linkage": "instance", "theta": "real"},
                                       linkage=_sx_watt2()[0], theta=[0.1, 0.4]),
    "spherical.guidance_watt2": E(lambda: sph.guidance_watt2,
                                  {"R": "matrix", "theta": "real", "crank_pivot": "real", "dyads": "instance?",
                                   "crank_tip": "real?", "rtol": "scalar", "sweep": "count"},
                                  R=sph.sixbar_orientations(*_sx_watt2()), theta=_sx_watt2()[1],
                                  crank_pivot=[0.0, 0.0, 1.0], dyads=None, crank_tip=None, rtol=1e-9, sweep=41),
    "spherical.SphericalGuidanceSixBar.guided_orientations": E(
        lambda: _kept(lambda: sph.guidance_watt2(sph.sixbar_orientations(*_sx_watt2()), _sx_watt2()[1],
                                                 [0.0, 0.0, 1.0], sweep=41)[0]).guided_orientations,
        {"theta": "real"}, theta=[0.2, 0.5]),
    "spherical.optimal_guidance_watt2": E(lambda: sph.optimal_guidance_watt2,
                                          {"R": "matrix", "theta": "real", "start": "instance", "rtol": "scalar",
                                           "sweep": "count"},
                                          R=_sx_nine()[0], theta=_sx_nine()[1], start=_sx_start(), rtol=1e-2, sweep=41),
    "spherical.SphericalOptimalSixBar.guided_orientations": E(
        lambda: _kept(lambda: sph.optimal_guidance_watt2(*_sx_nine(), _sx_start(), sweep=41)).guided_orientations,
        {"theta": "real"}, theta=[0.2, 0.5]),
})


def _sx_watt1():
    lk = sph.watt1(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
    theta = np.array([0.0, 0.3, 0.6, 0.9, 1.2])
    return sph.sixbar_orientations(lk, theta), theta


_SX_EXACT = {"R": "matrix", "theta": "real", "crank_pivot": "real", "circle_points": "real?", "along": "real",
             "rtol": "scalar", "sweep": "count"}
CASES.update({
    f"spherical.{name}": E((lambda name=name: getattr(sph, name)), _SX_EXACT, R=_sx_watt1()[0], theta=_sx_watt1()[1],
                           crank_pivot=[0.0, 0.0, 1.0], circle_points=None, along=(1.0, 1.0, 1.0), rtol=1e-9, sweep=41)
    for name in ("guidance_stephenson1", "guidance_stephenson2", "guidance_watt1")
})
RECORDS["spherical.SphericalExactSixBar"] = "result record built by the package"
CASES["spherical.SphericalExactSixBar.guided_orientations"] = E(
    lambda: sph.guidance_watt1(*_sx_watt1(), [0.0, 0.0, 1.0], sweep=41)[0].guided_orientations,
    {"theta": "real"}, theta=[0.2, 0.5])


def _s3():
    return sph.stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
                           coupler=(0.3, 0.4), mu=0.8)


def _s3_task():
    theta = np.array([0.0, 0.25, 0.5, 0.75, 1.0])
    return _s3().orientations(theta), theta


RECORDS["spherical.SphericalGuidanceStephenson3"] = "result record built by the package"
CASES.update({
    "spherical.stephenson3": E(lambda: sph.stephenson3,
                               {**_ABCD, "E": ("scalar", first), "arcs": ("scalar", first), "H": ("scalar", first),
                                "coupler": ("scalar", first), "mu": "scalar", "branch": "branch", "frame": "matrix?"},
                               a=0.35, b=0.9, c=0.8, d=1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
                               coupler=(0.3, 0.4), mu=0.8, branch=1, frame=np.eye(3)),
    "spherical.SphericalStephenson3": E(lambda: sph.SphericalStephenson3,
                                        {"points": ("vec3", lambda v: {**_s3().assembly, "C": v}, "points['C']"),
                                         "coupler": "vec3?"},
                                        points=_s3().assembly, coupler=None),
    "spherical.SphericalStephenson3.rotations": E(lambda: _s3().rotations, {"theta": "real"}, theta=[0.0, 0.5]),
    "spherical.SphericalStephenson3.orientations": E(lambda: _s3().orientations, {"theta": "real"},
                                                     theta=[0.0, 0.5]),
    "spherical.SphericalStephenson3.solve": E(lambda: _s3().solve, {"theta": "real", "strict": "bool"},
                                              theta=[0.0, 0.5], strict=False),
    "spherical.SphericalStephenson3.closure": E(lambda: _s3().closure, {"pose": "instance"},
                                                pose=_s3().solve([0.0, 0.5])),
    "spherical.guidance_stephenson3": E(lambda: sph.guidance_stephenson3,
                                        {"R": "matrix", "theta": "real", "crank_pivot": "real", "subset": "int?",
                                         "rtol": "scalar"},
                                        R=_s3_task()[0], theta=_s3_task()[1], crank_pivot=[0.0, 0.0, 1.0],
                                        subset=None, rtol=1e-9),
    "spherical.SphericalGuidanceStephenson3.guided_orientations": E(
        lambda: sph.guidance_stephenson3(*_s3_task(), [0.0, 0.0, 1.0])[0].guided_orientations,
        {"theta": "real"}, theta=[0.2, 0.5]),
})


# ----------------------------------------------------------------------------- issue 29
def _sx_w1_start():
    # five exact orientations of a Watt-1: the optimiser starts at an exact design and stops
    return [d for d in sph.guidance_watt1(*_sx_watt1(), [0.3, -0.2, 0.93], sweep=41) if d.passes][0]


def _s3_start():
    return sph.guidance_stephenson3(*_s3_task(), _s3().assembly["A"])[0]


_SX_PATH = {"points": "vec3", "theta": "real", "start": "vec3", "metric": "option",
            "branches": ("branch", first), "tol": "tolerance", "min_transmission": "scalar?"}
CASES.update({
    f"spherical.{name}": E((lambda name=name: getattr(sph, name)), _SX_PATH,
                           points=_SPH_PATH6[0], theta=_SPH_PATH6[1], start=_SPH_PATH6[2], metric="chord",
                           branches=(1, 1), tol=1e-3, min_transmission=0.5)
    for name in ("path_stephenson2", "path_watt1", "path_watt2")
})
CASES.update({
    "spherical.optimal_guidance_sixbar": E(lambda: sph.optimal_guidance_sixbar,
                                           {"R": "matrix", "theta": "real", "start": "instance", "rtol": "scalar",
                                            "sweep": "count"},
                                           R=_sx_watt1()[0], theta=_sx_watt1()[1], start=_sx_w1_start(), rtol=1e-2,
                                           sweep=41),
    "spherical.optimal_guidance_stephenson3": E(lambda: sph.optimal_guidance_stephenson3,
                                                {"R": "matrix", "theta": "real", "start": "instance",
                                                 "rtol": "scalar", "sweep": "count"},
                                                R=_s3_task()[0], theta=_s3_task()[1], start=_s3_start(), rtol=1e-2,
                                                sweep=41),
    "spherical.SphericalOptimalStephenson3.guided_orientations": E(
        lambda: _kept(lambda: sph.optimal_guidance_stephenson3(*_s3_task(), _s3_start(), sweep=41))
        .guided_orientations,
        {"theta": "real"}, theta=[0.2, 0.5]),
    "planar.fourbar_inputs": E(lambda: pl.fourbar_inputs, {**_ABCD, "coupler": ("real", first), "rtol": "scalar"},
                               a=10, b=40, c=30, d=35, coupler=(20, 10), rtol=1e-12),
})
RECORDS["spherical.SphericalOptimalStephenson3"] = "result record built by the package"


CASES.update({
    "spherical.sixbar_curve": E(lambda: sph.sixbar_curve, {"linkage": "instance", "points": "vec3", "cone": "bool"},
                                linkage=_sx_watt2()[0], points=[[0.0, 0.6, 0.8]], cone=False),
})

# ----------------------------------------------------------------------------- the walk
def _public_callables():
    """Qualified names of every public function, class and public method of a public class."""
    found = set()
    for prefix, module in MODULES.items():
        for name in module.__all__:
            obj = getattr(module, name)
            key = f"{prefix}.{name}" if prefix != "mech" else f"mech.{name}"
            if isinstance(obj, ModuleType) or not callable(obj):
                continue
            found.add(key)
            if inspect.isclass(obj):
                # its own methods and those it inherits from private mech bases (shared code)
                own = [k for k in obj.__mro__
                       if k is obj or (k.__name__.startswith("_") and k.__module__.startswith("mech."))]
                for attr, value in (item for k in own for item in vars(k).items()):
                    func = value.__func__ if isinstance(value, (classmethod, staticmethod)) else value
                    if not attr.startswith("_") and inspect.isfunction(func):
                        found.add(f"{key}.{attr}")
    return found


def test_every_public_callable_is_registered():
    registered = {k.split("#")[0] for k in CASES} | set(RECORDS)
    missing = sorted(_public_callables() - registered)
    assert not missing, f"register these public callables in CASES or RECORDS: {missing}"
    stale = sorted(registered - _public_callables())
    assert not stale, f"these entries name nothing public: {stale}"


def _name_pattern(shown):
    # The argument in backticks, maybe followed by an index or a qualifier
    # (`lengths[1] ...`, `at.real`, `length of crank`).
    return re.compile("`" + re.escape(shown) + r"[`\[ .]")


def _check(key, slot, bad_name, value=None, texts=None):
    entry = CASES[key]
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


def _all_cases():
    for key, entry in CASES.items():
        for slot in entry.slots:
            for bad_name in bad_kinds(entry.slot(slot)[0]):
                yield key, slot, bad_name


@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", sorted(k for k in CASES if CASES[k].slots))
def test_bad_values_rejected_by_name(key):
    failures = [f for k, slot, bad in _all_cases() if k == key for f in [_check(k, slot, bad)] if f]
    assert not failures, "\n".join(failures)


def test_table_size():
    """The walk is as wide as reported (callables, slots, bad kinds, cases)."""
    slots = sum(len(e.slots) for e in CASES.values())
    cases = sum(1 for _ in _all_cases())
    assert len({k.split("#")[0] for k in CASES}) + len(RECORDS) == len(_public_callables())
    assert slots > 300 and cases > 3000


# ----------------------------------------------------------------------------- Hypothesis
_SLOTTED = sorted((k, s) for k, e in CASES.items() for s in e.slots)
_finite = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e6, max_value=1e6)


#: non-finite values that are valid for a slot kind (inf as a tolerance skips a check)
_ALLOWED = {("tolerance", math.inf), ("real_nan", math.nan)}


def _random_bad(kind):
    """Random bad values for a slot kind, with the texts the message must show."""
    strategies = [
        st.sampled_from(bad_kinds(kind)).map(lambda n: (n, *BAD[n])),
        st.sampled_from([x for x in (math.nan, math.inf, -math.inf) if (kind.rstrip("?"), x) not in _ALLOWED])
        .map(lambda x: ("nonfinite", x, [repr(x)])),
    ]
    if kind not in ("option", "point_or_name", "length_or_name"):     # there a string is a name
        strategies.append(st.text(alphabet="0123456789.-e", min_size=1, max_size=8).map(
            lambda s: ("str", s, [repr(s)])))
    kind = kind.rstrip("?")
    if kind not in ("point", "point1", "point_or_name", "int", "count", "order", "bool", "branch", "option"):
        strategies.append(st.tuples(_finite, _finite.filter(lambda y: y != 0.0)).map(
            lambda t: ("complex", complex(*t), [repr(complex(*t)).strip("()")])))
        strategies.append(st.lists(st.booleans(), min_size=1, max_size=4).map(
            lambda b: ("bools", np.array(b), [str(b[0])])))
    if kind in ("real", "scalar", "realmap", "scalarmap", "point", "point1", "point_or_name",
                "length_or_name", "vec3", "matrix"):
        strategies.append(st.tuples(st.lists(_finite, max_size=3), st.text(min_size=1, max_size=4)).map(
            lambda t: ("list+str", [*t[0], t[1]], [repr(t[1])])))
    return st.one_of(strategies)


@settings(max_examples=1500, deadline=None)
@given(data=st.data())
def test_random_bad_values_rejected_by_name(data):
    key, slot = data.draw(st.sampled_from(_SLOTTED), label="slot")
    kind = CASES[key].slot(slot)[0]
    label, value, texts = data.draw(_random_bad(kind), label="bad value")
    failure = _check(key, slot, label, value, texts)
    assert failure is None, failure


# ----------------------------------------------------------------------------- the reported cases
def test_fourbar_strings_and_booleans_rejected():
    """Issue 11, item 9: ``FourBar("10", "40", "30", True)`` built a four-bar with d = 1."""
    with pytest.raises(mech.InputTypeError, match="Expected `a`.*'10'"):
        pl.FourBar("10", 40, 30, 35)
    with pytest.raises(mech.InputTypeError, match="Expected `d`.*True"):
        pl.FourBar(10, 40, 30, True)
    with pytest.raises(mech.InputTypeError, match="Expected `coupler`.*True"):
        pl.FourBar(10, 40, 30, 35, coupler=(True, 0.0))


def test_friction_angle_complex_named():
    """Issue 11, item 8: ``friction_angle(1+1j)`` leaked "float() argument must be ..."."""
    with pytest.raises(mech.InputTypeError, match=r"Expected `mu`.*\(1\+1j\)"):
        pl.friction_angle(1 + 1j)


@pytest.mark.parametrize("bad", [math.nan, math.inf, complex(math.nan, 0.0), complex(0.0, -math.inf)])
def test_linkage_ground_rejects_nonfinite(bad):
    """Issue 11, item 7: NaN or infinite ground points were accepted."""
    with pytest.raises(ValueError, match=r"Expected finite `ground\['D'\]`"):
        pl.Linkage({"A": 0, "D": bad})
    with pytest.raises(ValueError, match="Expected finite `at`"):
        pl.Linkage({"A": 0}).ground("D", bad)


@pytest.mark.parametrize("make", [sph.Dual, sph.dual])
@pytest.mark.parametrize("real, dual, name", [(math.nan, 0.0, "real"), (0.5, math.inf, "dual"),
                                              (0.5, -math.inf, "dual")])
def test_dual_rejects_nonfinite(make, real, dual, name):
    """Issue 11, item 7: NaN or infinite parts of `Dual` and `dual` were accepted."""
    with pytest.raises(ValueError, match=f"Expected finite `{name}`"):
        make(real, dual)


@pytest.mark.parametrize("bad", ["0.5", True, 0.5 + 0j, None])
def test_dual_rejects_wrong_types(bad):
    with pytest.raises(mech.InputTypeError, match="Expected `real`"):
        sph.Dual(bad, 1.0)
    with pytest.raises(mech.InputTypeError, match="Expected `dual`"):
        sph.dual(0.5, bad)


def test_dual_arithmetic_still_carries_nan():
    """The check is on the user's parts only: arithmetic may still produce NaN (0/0)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        q = sph.Dual(0.0, 1.0) / sph.Dual(0.0, 0.0)
    assert np.isnan(q.real_part)


def test_planar_point_accepts_real_and_complex():
    from mech._validate import planar_point, planar_points

    assert planar_point("at", 3) == 3 + 0j
    assert planar_point("at", np.float64(2.5)) == 2.5 + 0j
    assert planar_point("at", 1 - 2j) == 1 - 2j
    np.testing.assert_array_equal(planar_points("at", [1, 2j, 3 + 4j]), np.array([1, 2j, 3 + 4j]))
    with pytest.raises(mech.InputTypeError, match="Expected `at`.*True"):
        planar_points("at", [1.0, True])
    with pytest.raises(ValueError, match="Expected `at` to be a single point"):
        planar_point("at", [1, 2])


@pytest.mark.parametrize("value, message", [(1, "1"), (1.0, "1.0"), ("yes", "'yes'"), (None, "None")])
def test_strict_must_be_a_bool(value, message):
    with pytest.raises(mech.InputTypeError, match=f"Expected `strict` to be True or False, got {message}"):
        pl.FourBar(10, 40, 30, 35).solve(0.5, strict=value)


# ----------------------------------------------------------------------------- user functions (synthesis)
@pytest.mark.parametrize("f", ["log10", None, 3.0, _Opaque()])
def test_function_map_rejects_non_callables(f):
    with pytest.raises(ValueError, match="Expected `f` to be callable"):
        sy.FunctionMap(f, (1.0, 10.0), 1.7, 1.0)


def test_function_map_names_complex_and_nan_values_of_f():
    """A user function's complex or NaN values are errors naming it, not silently used."""
    with pytest.raises(mech.InputTypeError, match=r"Expected `f\(1\.0\)` to be a real number"):
        sy.FunctionMap(lambda x: np.log10(x) + 1j, (1.0, 10.0), 1.7, 1.0)
    hole = sy.FunctionMap(lambda x: np.where(np.abs(x - 6.0) < 0.1, np.nan, np.log10(x)), (1.0, 10.0), 1.7, 1.0)
    with pytest.raises(ValueError, match=r"Expected finite `f\(x\)`, got nan"):
        hole.rotations([2.0, 6.0])
    with pytest.raises(ValueError, match=r"Expected finite `f\(x\)`, got nan"):
        hole(np.array([0.5, 5.0 / 9.0 * 1.7]))
    with pytest.raises(ValueError, match=r"Expected finite `f\(10\.0\)`, got nan"):
        sy.FunctionMap(lambda x: np.where(x > 5.0, np.nan, np.log10(x)), (1.0, 10.0), 1.7, 1.0)


@pytest.mark.parametrize("name", ["objective", "inequality", "equality"])
def test_design_model_rejects_non_callables_and_complex_values(name):
    kwargs = {"objective": lambda x: (x ** 2).sum(-1), name: "x ** 2"}
    with pytest.raises(ValueError, match=f"Expected `{name}` to be callable, got 'x \\*\\* 2'"):
        sy.DesignModel(bounds=[(0, 1)], **kwargs)
    complex_valued = {"objective": lambda x: (x ** 2).sum(-1), name: lambda x: x + 1j}
    model = sy.DesignModel(bounds=[(0, 1)], **complex_valued)
    method = {"objective": model.f, "inequality": model.g, "equality": model.h}[name]
    with pytest.raises(ValueError, match=f"Expected `{name}` to return real numbers"):
        method([0.5])


# ----------------------------------------------------------------------------- path generation
def test_path_coupler_point_keeps_nan_of_unassembled_poses():
    """`to_ground` rejects NaN input, but `coupler_point` still reports unassembled poses as NaN."""
    design = (0j, 1 + 0j, 3 + 1j, 3 + 0j, 2 + 0.5j)      # a = c = 1, d = 3: the crank cannot turn fully
    out = sy.path_residuals(design, np.zeros(3), [0.0, np.pi, 0.5])
    assert np.isfinite(out[0]) and np.isnan(out[1]) and np.isfinite(out[2])
    with pytest.raises(ValueError, match=r"Expected finite `w`"):
        _path().to_ground(complex(math.nan, 0.0))


# ----------------------------------------------------------------------------- audit of issue 11
def test_masked_entries_rejected_unmasked_arrays_accepted():
    """NumPy reads the arbitrary data under a mask: a masked entry is an error, not a number."""
    four_bar = pl.FourBar(10, 40, 30, 35)
    theta = np.ma.array([0.5, 99.0], mask=[False, True])
    with pytest.raises(ValueError, match=r"Expected `theta` without masked entries, got \[0.5 --\]"):
        four_bar.solve(theta)
    with pytest.raises(ValueError, match="Expected `bounds` without masked entries"):
        sy.DesignModel(objective=lambda x: (x ** 2).sum(-1), bounds=[theta, (0, 1)])
    with pytest.raises(ValueError, match="Expected `at` without masked entries"):
        pl.Linkage().ground("A", np.ma.array([1 + 1j], mask=[True]))
    plain = np.ma.array([0.5, 1.0], mask=[False, False])
    np.testing.assert_array_equal(four_bar.solve(plain).psi, four_bar.solve(np.array([0.5, 1.0])).psi)


@pytest.mark.parametrize("value", [np.timedelta64(1), np.timedelta64(2, "s"), np.datetime64("2020-01-01")])
def test_time_values_are_not_numbers(value):
    """`timedelta64` is a NumPy integer type: ``order=np.timedelta64(1)`` solved order 1."""
    four_bar = pl.FourBar(10, 40, 30, 35)
    with pytest.raises(mech.InputTypeError, match="Expected `order`"):
        four_bar.solve(0.3, order=value)
    with pytest.raises(mech.InputTypeError, match="Expected `branch`"):
        pl.FourBar(10, 40, 30, 35, branch=value)
    with pytest.raises(mech.InputTypeError, match="Expected `coupler`"):
        pl.FourBar(10, 40, 30, 35, coupler=(value, 1.0))
    with pytest.raises(mech.InputTypeError, match="Expected `n`"):
        pl.centre_count(value)


def test_huge_int_inside_point_list_named():
    """``[1.0, 10**400]`` overflowed with a bare OverflowError where points are read."""
    with pytest.raises(mech.InputTypeError, match=r"Expected `at` to be points.*10000000000"):
        pl.Linkage().ground("A", [1.0, 10**400])
    with pytest.raises(mech.InputTypeError, match="Expected `theta`"):
        pl.FourBar(10, 40, 30, 35).solve([1.0, 10**400])


def test_integer_message_shows_the_users_entries():
    """The message shows ``False`` and ``2j`` as given, not NumPy's ``0.`` and ``0.+2.j``."""
    with pytest.raises(mech.InputTypeError, match=r"got \[1.0, False\]"):
        pl.coupler_dashes(1, 2, 2.5, 3, [0.5 + 0.5j], n=[1.0, False])
    with pytest.raises(mech.InputTypeError, match=r"got \[1.0, 2j\]"):
        sph.chebyshev_spacing(0.0, 1.0, [1.0, 2j])


def test_sample_counts_are_bounded():
    """``samples=10**400`` reached NumPy's "Maximum allowed size exceeded" without a name."""
    x = np.linspace(0.0, 1.0, 7)
    with pytest.raises(ValueError, match="Expected `samples` to be an integer in"):
        sy.least_squares(x, 0.6 * x ** 1.2, theta0=0.5, psi0=1.0, samples=10**400)


@pytest.mark.parametrize("bad", [np.array([1, 2]), True, [1, 2]])
def test_link_names_reject_flags_and_arrays(bad):
    """``omega_ratio(..., i=True)`` matched link 1 (``True == 1``); an array raised NumPy's
    "truth value ... is ambiguous" without a name."""
    centres = pl.instant_centres(4, {(1, 4): 0j, (1, 2): 3 + 4j, (2, 3): 8 + 0j, (3, 4): pl.prismatic(1)})
    with pytest.raises(ValueError, match="Expected `i` among"):
        pl.omega_ratio(centres, bad, 3, frame=1)
    with pytest.raises(ValueError, match="Expected `driver` among"):
        pl.centre_velocities(centres, frame=4, driver=bad, omega=2.0)


@pytest.mark.parametrize("links", [np.array(4.0 + 2j), [[1], [1, 2]], [1, float("nan")], [True, False]])
def test_instant_centres_links_named(links):
    """A 0-d array, unhashable, NaN or boolean link labels raised bare errors or unnamed ones."""
    with pytest.raises(ValueError, match="Expected `links`"):
        pl.instant_centres(links, {(1, 2): 0j})


def _motion_calls():
    """Solvers of a driver angle with rates, each as ``call(theta, omega, alpha)``."""
    fb = pl.FourBar(10, 40, 30, 35)
    return {
        "FourBar": lambda t, w, a: fb.solve(t, order=2, omega=w, alpha=a),
        "SliderCrank": lambda t, w, a: _slider().solve(t, order=2, omega=w, alpha=a),
        "GuideBar": lambda t, w, a: pl.GuideBar(150.0, 300.0).solve(t, order=2, omega=w, alpha=a),
        "RotatingGuideBar": lambda t, w, a: pl.RotatingGuideBar(2.0, 1.0).solve(t, order=2, omega=w, alpha=a),
        "SwingingBlock": lambda t, w, a: pl.SwingingBlock(1.0, 2.0).solve(t, order=2, omega=w, alpha=a),
        "EllipticTrammel": lambda t, w, a: pl.EllipticTrammel(2.0).solve(t, order=2, omega=w, alpha=a),
        "Linkage": lambda t, w, a: _linkage().solve(t, order=2, omega=w, alpha=a),
        "RSSR": lambda t, w, a: _rssr().solve(t, order=2, omega=w, alpha=a),
        "SphericalFourBar": lambda t, w, a: _sfb().solve(t, order=2, omega=w, alpha=a),
        "SphericalLinkage": lambda t, w, a: _sph_sixbar().solve(t, order=2, omega=w, alpha=a),
    }


@pytest.mark.parametrize("name", sorted(_motion_calls()))
def test_rates_of_another_shape_are_named(name):
    """``omega`` of shape (2,) with ``theta`` of shape (3,) raised NumPy's "operands could not
    be broadcast together" naming no argument (all but `FourBar`, `RSSR` and the sphere)."""
    call = _motion_calls()[name]
    with pytest.raises(ValueError, match=r"Expected shapes that broadcast together, got .*`omega` \(2,\)"):
        call([0.1, 0.2, 0.3], [1.0, 2.0], 0.0)
    with pytest.raises(ValueError, match=r"Expected shapes that broadcast together, got .*`alpha` \(2,\)"):
        call([0.1, 0.2, 0.3], 1.0, [1.0, 2.0])


@pytest.mark.parametrize("name", sorted(_motion_calls()))
def test_empty_input_solves_to_empty_poses(name):
    """An empty `theta` is valid input: ``order >= 1`` raised "cannot reshape array of size 0"."""
    pose = _motion_calls()[name](np.zeros((0, 3)), 1.0, 0.0)
    assert np.shape(pose.valid) == (0, 3)


@pytest.mark.parametrize("call, names", [
    (lambda: sph.to_xyz([1.0, 2.0], [1.0, 2.0, 3.0]), ("lon", "lat")),
    (lambda: sph.distance_lonlat([1.0, 2.0], 0.0, [1.0, 2.0, 3.0], 0.0), ("lon1", "lon2")),
    (lambda: sph.rotate_about(np.eye(3)[:2], [0.0, 0.0, 1.0], [0.1, 0.2, 0.3]), ("p", "angle")),
    (lambda: sph.point_at(np.eye(3)[:2], 0.5, [0.1, 0.2, 0.3]), ("a", "inclination")),
    (lambda: sp.hooke_output([0.1, 0.2, 0.3], [0.2, 0.3]), ("theta1", "alpha")),
    (lambda: sp.hooke_acceleration([0.1, 0.2, 0.3], 0.2, omega=[1.0, 2.0]), ("theta1", "omega")),
    (lambda: pl.slider_state([0.1, 0.2, 0.3], [0.2, 0.3]), ("alpha", "phi")),
    (lambda: pl.journal_state([0.1, 0.2, 0.3], [0.2, 0.3]), ("h", "rho")),
    (lambda: sy.displacement_matrix([0.1, 0.2], [1j, 2j], [0.1, 0.2, 0.3], [1j, 2j]), ("theta_1", "theta_i")),
])
def test_arguments_of_other_shapes_are_named(call, names):
    with pytest.raises(ValueError, match="Expected shapes that broadcast together") as info:
        call()
    assert all(f"`{n}`" in str(info.value) for n in names), str(info.value)


def test_static_loads_of_another_shape_are_named():
    sol = pl.as_linkage(pl.FourBar(1, 3, 2.5, 3)).solve([0.5, 0.6], order=1)
    with pytest.raises(ValueError, match=r"Expected shapes that broadcast together, got `couples\['rocker'\]` \(3,\)"):
        pl.static_forces(sol, couples={"rocker": [1.0, 2.0, 3.0]})


def test_tilt_angle_radii_are_single_numbers():
    """An array `rho_a` reached ``float()`` and raised "only 0-dimensional arrays ..."."""
    with pytest.raises(ValueError, match="Expected `rho_a` to be a single number"):
        pl.two_force_tilt_angle(10.0, np.array([]), 0.5)


def test_coupler_below_the_float_range_of_the_longest_link_named():
    """b = 5e-324 beside 80 scaled to 0.0 and raised ZeroDivisionError in the generated code."""
    with pytest.raises(ValueError, match="Expected `b` at least 2\\*\\*-1022 times the longest link, got 5e-324"):
        pl.FourBar(30, 5e-324, 60, 80)
    with pytest.raises(ValueError, match="Expected `b`"):
        pl.fourbar_mechanical_advantage(30, 5e-324, 60, 80, 1.0)


def test_freudenstein_coefficients_beyond_the_float_range_named():
    """k2 = 1e300 squared raised a bare OverflowError (Python floats in the generated code)."""
    k = [float(v) for v in sph.freudenstein_coefficients(0.4, 0.9, 0.7, 1.0)]
    with pytest.raises(ValueError, match="Expected `k1` .. `k4`"):
        sph.arcs_from_coefficients(k[0], 1e300, 1e300, k[3])
    with pytest.raises(ValueError, match="Expected `k1` .. `k4` with \\|cos b\\| < 1"):
        sph.arcs_from_coefficients(k[0], k[1], k[2], 1e300)
    arcs = sph.arcs_from_coefficients(k[0], 1e300, k[2], k[3])      # a tiny crank arc: fine
    assert np.all(np.isfinite(arcs)) and 0.0 < arcs[0] < 1e-299


def test_steering_model_ratio_beyond_the_float_range_named():
    with pytest.raises(ValueError, match="Expected `a` / `h` within the float range"):
        sy.steering_trapezoid_model(a=1480.0, h=5e-324, theta_max=0.5, steps=5, arm_range=(0.1, 0.4))


@pytest.mark.parametrize("name", sorted(_motion_calls()))
def test_huge_input_speed_is_quiet_and_masked(name):
    """omega = 1e200: omega**2 overflowed with a RuntimeWarning (guide bars, double sliders).
    Beyond the float range a rate is masked: never inf or NaN where `valid` is True."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pose = _motion_calls()[name](np.array([0.0, 0.3, 1.0]), 1e200, 0.0)
    valid = np.asarray(pose.valid)
    fields = getattr(pose, "_fields", {})
    for key, value in fields.items():
        value = np.asarray(value)
        if value.dtype.kind in "fc" and value.shape[: valid.ndim] == valid.shape:
            finite = np.isfinite(value).reshape(valid.shape + (-1,)).all(axis=-1)
            assert np.all(finite | ~valid), key


def test_hooke_acceleration_huge_speed_at_a_stationary_angle():
    """At theta1 = 0 the slope of the ratio is 0: 0 * (1e200)**2 gave NaN (0 times inf)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert sp.hooke_acceleration(0.0, 0.5, omega=1e200) == 0.0
