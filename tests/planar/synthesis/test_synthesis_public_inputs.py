"""`mech.planar.synthesis` rejects bad input by name: the table of its public callables (the format
and the check are in ``tests/public_inputs.py``) and the reported cases of user functions.
"""

import math

import numpy as np
import pytest

import mech
import mech.planar as pl
import mech.planar.synthesis as sy
from tests.public_inputs import ABCD, E, assert_rejected_by_name, first, Opaque, slotted

CASES = {}
RECORDS = {}


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
    "planar.synthesis.freudenstein_coefficients": E(lambda: sy.freudenstein_coefficients, ABCD,
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
})

RECORDS.update({
    **{f"planar.synthesis.{n}": "result record built by the package" for n in (
        "Dyad", "BurmesterCurve", "BurmesterPoints", "GuidanceFourBar", "GuidanceSynthesis", "QuickReturnCheck",
        "QuickReturnCrankRocker", "QuickReturnFamily", "QuickReturnGuideBar", "QuickReturnSliderCrank",
        "OptimisationResult", "PathFourBar", "PathSynthesis")},
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


@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", slotted(CASES))
def test_bad_values_rejected_by_name(key):
    assert_rejected_by_name(CASES, key)


# ----------------------------------------------------------------------------- user functions (synthesis)
@pytest.mark.parametrize("f", ["log10", None, 3.0, Opaque()])
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



def test_sample_counts_are_bounded():
    """``samples=10**400`` reached NumPy's "Maximum allowed size exceeded" without a name."""
    x = np.linspace(0.0, 1.0, 7)
    with pytest.raises(ValueError, match="Expected `samples` to be an integer in"):
        sy.least_squares(x, 0.6 * x ** 1.2, theta0=0.5, psi0=1.0, samples=10**400)



def test_steering_model_ratio_beyond_the_float_range_named():
    with pytest.raises(ValueError, match="Expected `a` / `h` within the float range"):
        sy.steering_trapezoid_model(a=1480.0, h=5e-324, theta_max=0.5, steps=5, arm_range=(0.1, 0.4))

