"""Every public callable rejects every kind of bad input by name (issue 11): the walk.

The test walks ``__all__`` of ``mech`` and its subpackages (and the public methods of the
public classes). Each callable has an entry in the table ``CASES`` of the test file that
mirrors its subpackage (every ``tests/**/test_*_public_inputs.py``; the format and the check
are in ``tests/public_inputs.py``), or in ``RECORDS`` when the package builds it and a user
never feeds numbers into it. Here: the completeness check that makes every new public
callable register, random bad values over all tables (Hypothesis), and the cases that cross
subpackages.
"""

import importlib.util
import inspect
import math
import sys
import warnings
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import mech
import mech.atlas as at
import mech.exercises as ex
import mech.planar as pl
import mech.planar.export as xp
import mech.planar.synthesis as sy
import mech.spatial as sp
import mech.spherical as sph
from mech.exercises import (chapter2, chapter2_analysis, chapter2_instant_centres, chapter2_quick_return,
                            chapter2_reactions, chapter2_relative_motion, chapter2_synthesis)
from tests.public_inputs import BAD, E, all_cases, bad_kinds, check, linkage, rssr, sfb, slider, sph_sixbar

MODULES = {"mech": mech, "planar": pl, "spatial": sp, "spherical": sph, "exercises": ex,
           "exercises.chapter2": chapter2, "exercises.chapter2_analysis": chapter2_analysis,
           "planar.synthesis": sy, "exercises.chapter2_synthesis": chapter2_synthesis,
           "exercises.chapter2_quick_return": chapter2_quick_return,
           "exercises.chapter2_relative_motion": chapter2_relative_motion,
           "exercises.chapter2_reactions": chapter2_reactions,
           "exercises.chapter2_instant_centres": chapter2_instant_centres, "atlas": at,
           "planar.export": xp}


#: the backend's own entries (the valid call sets the backend in force when the tests started)
OWN_CASES = {
    "mech.set_backend": E(lambda: mech.set_backend, name=mech.get_backend()),
    "mech.get_backend": E(lambda: mech.get_backend),
}
OWN_RECORDS = {
    "mech.AssemblyError": "exception type",
    "mech.InputTypeError": "exception type",
}


def _load(path):
    """The test module at `path`, imported once: under the name pytest gives it (its file's
    stem, its folder on ``sys.path``), so collecting it later reuses this module object."""
    for module in list(sys.modules.values()):
        if getattr(module, "__file__", None) == str(path):
            return module
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[path.stem] = module
    spec.loader.exec_module(module)
    return module


#: the tables of the subpackages, found by their file names (a new table is gathered unlisted)
TABLES = sorted(Path(__file__).resolve().parent.rglob("test_*_public_inputs.py"))
CASES = dict(OWN_CASES)
RECORDS = dict(OWN_RECORDS)
for _table in map(_load, TABLES):
    assert not set(_table.CASES) & set(CASES), _table.__file__
    CASES.update(_table.CASES)
    RECORDS.update(_table.RECORDS)


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


@pytest.mark.parametrize("key", sorted(OWN_CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


def test_table_size():
    """The walk is as wide as reported (callables, slots, bad kinds, cases), over one table per
    tested subpackage, each in the test folder of its subpackage."""
    names = {p.relative_to(Path(__file__).resolve().parent).as_posix() for p in TABLES}
    assert names == {"planar/test_planar_public_inputs.py", "planar/test_export_public_inputs.py",
                     "planar/synthesis/test_synthesis_public_inputs.py", "spatial/test_spatial_public_inputs.py",
                     "spherical/test_spherical_public_inputs.py",
                     "spherical/guidance/test_guidance_public_inputs.py", "atlas/test_atlas_public_inputs.py",
                     "exercises/test_exercises_public_inputs.py"}
    slots = sum(len(e.slots) for e in CASES.values())
    cases = sum(1 for _ in all_cases(CASES))
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
    failure = check(CASES[key], key, slot, label, value, texts)
    assert failure is None, failure


# ----------------------------------------------------------------------------- cases across subpackages
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


def test_integer_message_shows_the_users_entries():
    """The message shows ``False`` and ``2j`` as given, not NumPy's ``0.`` and ``0.+2.j``."""
    with pytest.raises(mech.InputTypeError, match=r"got \[1.0, False\]"):
        pl.coupler_dashes(1, 2, 2.5, 3, [0.5 + 0.5j], n=[1.0, False])
    with pytest.raises(mech.InputTypeError, match=r"got \[1.0, 2j\]"):
        sph.chebyshev_spacing(0.0, 1.0, [1.0, 2j])


def test_zero_d_integer_array_is_a_count():
    """A 0-d integer array is taken as its integer, as NumPy takes ``np.zeros(np.array(3))``
    (issue 24); a 0-d array of any other type is refused and said to be one, so that
    ``np.array(16.0)`` is not shown as if the float 16.0 had been passed."""
    from mech._validate import integer, nonnegative_int

    assert np.zeros(np.array(3)).shape == (3,)                       # NumPy's own rule
    for count in (np.array(16), np.array(16, dtype=np.uint8), np.array(16, dtype=np.int32)):
        assert integer("samples", count, minimum=2) == 16 and type(integer("samples", count)) is int
        assert nonnegative_int("samples", count, 100) == 16
    by_int = sy.crank_rocker_family(1.25, 1, 0.5, samples=16)
    by_array = sy.crank_rocker_family(1.25, 1, 0.5, samples=np.array(16))
    np.testing.assert_array_equal(by_array.intervals, by_int.intervals)
    np.testing.assert_array_equal(by_array.min_transmission, by_int.min_transmission)
    for bad, shown in ((np.array(16.0), "a 0-d array 16.0"), (np.array(True), "a 0-d array True"),
                       (np.ma.array(16, mask=True), "a 0-d array")):
        with pytest.raises(mech.InputTypeError, match=f"Expected `samples` to be an integer.*got {shown}"):
            integer("samples", bad, minimum=2)
        with pytest.raises(mech.InputTypeError, match=f"got {shown}"):
            nonnegative_int("samples", bad, 100)
    with pytest.raises(ValueError, match=r"Expected `samples` to be an integer >= 2, got 1$"):
        integer("samples", np.array(1), minimum=2)
    with pytest.raises(mech.InputTypeError, match=r"got \[16\]"):   # one entry is not a count
        integer("samples", np.array([16]))


def _motion_calls():
    """Solvers of a driver angle with rates, each as ``call(theta, omega, alpha)``."""
    fb = pl.FourBar(10, 40, 30, 35)
    return {
        "FourBar": lambda t, w, a: fb.solve(t, order=2, omega=w, alpha=a),
        "SliderCrank": lambda t, w, a: slider().solve(t, order=2, omega=w, alpha=a),
        "GuideBar": lambda t, w, a: pl.GuideBar(150.0, 300.0).solve(t, order=2, omega=w, alpha=a),
        "RotatingGuideBar": lambda t, w, a: pl.RotatingGuideBar(2.0, 1.0).solve(t, order=2, omega=w, alpha=a),
        "SwingingBlock": lambda t, w, a: pl.SwingingBlock(1.0, 2.0).solve(t, order=2, omega=w, alpha=a),
        "EllipticTrammel": lambda t, w, a: pl.EllipticTrammel(2.0).solve(t, order=2, omega=w, alpha=a),
        "Linkage": lambda t, w, a: linkage().solve(t, order=2, omega=w, alpha=a),
        "RSSR": lambda t, w, a: rssr().solve(t, order=2, omega=w, alpha=a),
        "SphericalFourBar": lambda t, w, a: sfb().solve(t, order=2, omega=w, alpha=a),
        "SphericalLinkage": lambda t, w, a: sph_sixbar().solve(t, order=2, omega=w, alpha=a),
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
