"""`mech.exercises` rejects bad input by name: the table of its public callables (the format and the
check are in ``tests/public_inputs.py``).
"""

import pytest

import mech.exercises as ex
from mech.exercises import chapter2, chapter2_analysis, chapter2_instant_centres, chapter2_quick_return, chapter2_reactions, chapter2_relative_motion, chapter2_synthesis
from tests.public_inputs import E, assert_rejected_by_name, slotted

CASES = {}
RECORDS = {}


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
})

CASES.update({
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
    **{f"exercises.{n}": "record of the exercise catalogue built by the package" for n in (
        "Exercise", "Interval", "Parameter", "Part", "Result", "Solution")},
    "exercises.chapter2_quick_return.Shaper": "result record built by the package (shaper_2_32)",
    "exercises.chapter2_synthesis.RockerSlider": "result record built by the package (design_2_28)",
})


@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", slotted(CASES))
def test_bad_values_rejected_by_name(key):
    assert_rejected_by_name(CASES, key)
