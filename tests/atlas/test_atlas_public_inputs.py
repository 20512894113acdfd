"""`mech.atlas` rejects bad input by name: the table of its public callables (the format and the
check are in ``tests/public_inputs.py``).
"""

import functools

import pytest

import mech.atlas as at
import mech.planar as pl
from tests.public_inputs import E, assert_rejected_by_name, slotted

CASES = {}
RECORDS = {}


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



@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", slotted(CASES))
def test_bad_values_rejected_by_name(key):
    assert_rejected_by_name(CASES, key)
