"""`mech.spherical` (its base modules and `mech.spherical.path`) rejects bad input by name: the table
of their public callables (the format and the check are in ``tests/public_inputs.py``).
"""

import math

import numpy as np
import pytest

import mech
import mech.spherical as sph
from tests.public_inputs import ABCD, E, MOTION, MOTION2, assert_rejected_by_name, first, sfb, slotted, sph_sixbar

CASES = {}
RECORDS = {}


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

def _generator():
    x = np.radians([10.0, 30.0, 50.0, 70.0])
    g, = sph.precision_pairs(x, 0.5 * np.sin(x), theta0=np.radians(40.0), psi0=np.radians(80.0))
    return g


def _polygon():
    return sph.close_polygon(np.random.default_rng(1).normal(size=(5, 3)))


def _sph_ground():
    return sph.SphericalLinkage({"A": (0.0, 0.0, 1.0), "D": (np.sin(1.0), 0.0, np.cos(1.0))})


def _sph_crank():
    return _sph_ground().crank("AB", pivot="A", tip="B", arc=0.3, reference="D")


_P3 = [[0.0, 0.0, 1.0], [0.0, 0.6, 0.8]]
_DUAL = ("real", first, None)


def _dual_slot(name):
    return ("real", lambda v: (v, 0.2), name)


CASES.update({
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
                                    {**ABCD, "branch": "branch", "coupler": ("scalar", first),
                                     "frame": "matrix?"},
                                    a=0.3, b=0.9, c=0.7, d=1.0, branch=1, coupler=(0.4, 0.5), frame=np.eye(3)),
    "spherical.SphericalFourBar.solve": E(lambda: sfb().solve, MOTION, **MOTION2),
    "spherical.SphericalFourBar.assembly_range": E(lambda: sfb().assembly_range),
    "spherical.SphericalFourBar.coupler_curve": E(lambda: sfb().coupler_curve, {"n": "count"}, n=50),
    "spherical.SphericalFourBar.coupler_curve_polynomial": E(lambda: sfb().coupler_curve_polynomial),
    "spherical.CouplerOctic": E(lambda: sph.CouplerOctic, {"linkage": "instance"}, linkage=sfb()),
    "spherical.CouplerOctic.quartic": E(lambda: sfb().coupler_curve_polynomial().quartic, {"points": "vec3"},
                                        points=[[0.0, 0.6, 0.8]]),
    "spherical.CouplerOctic.lonlat": E(lambda: sfb().coupler_curve_polynomial().lonlat, {"lon": "real", "lat": "real"},
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
                               linkage=sfb(), points=_SPH_PATH[0], theta=_SPH_PATH[1], tol=1e-3),
    "spherical.nine_parameters": E(lambda: sph.nine_parameters, {"linkage": "instance"}, linkage=sfb()),
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
    "spherical.SphericalLinkage.solve": E(lambda: sph_sixbar().solve, MOTION, **MOTION2),
    "spherical.SphericalLinkage.coupler_curve": E(lambda: sph_sixbar().coupler_curve,
                                                  {"theta": "real", "order": "order", "omega": "real", "alpha": "real"},
                                                  theta=[0.0, 1.0], order=2, omega=1.5, alpha=0.5),
    **{f"spherical.{name}": E(lambda name=name: getattr(sph, name),
                              {**ABCD, "E": ("scalar", first), "F": ("scalar", first), "arcs": ("scalar", first),
                               "coupler": ("scalar", first), "branches": ("branch", first), "frame": "matrix?"},
                              a=0.3, b=0.9, c=0.7, d=1.0, E=(0.2, 0.8), F=(0.3, -1.0), arcs=(0.8, 0.7),
                              coupler=(0.4, 0.5), branches=(1, 1), frame=np.eye(3))
       for name in ("stephenson1", "stephenson2", "watt1", "watt2")},
    "spherical.SphericalPolygon.relations": E(lambda: _polygon().relations),
    "spherical.angle_at": E(lambda: sph.angle_at, {"a": "vec3", "b": "vec3", "c": "vec3"},
                            a=[0, 0, 1], b=[1, 0, 0], c=[0, 1, 0]),
    "spherical.angle_between": E(lambda: sph.angle_between, {"pole1": "vec3", "pole2": "vec3"},
                                 pole1=[0, 0, 1], pole2=[0, 1, 0]),
    "spherical.antipode_reduction": E(lambda: sph.antipode_reduction, ABCD, a=2.5, b=2.0, c=0.7, d=1.0),
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
    "spherical.classify": E(lambda: sph.classify, {**ABCD, "tol": "scalar"}, a=0.3, b=0.9, c=0.7, d=1.0, tol=1e-12),
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
    "spherical.freudenstein_coefficients": E(lambda: sph.freudenstein_coefficients, ABCD,
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
    "spherical.inversions": E(lambda: sph.inversions, {**ABCD, "tol": "scalar"}, a=0.3, b=0.9, c=0.7, d=1.0,
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
})

RECORDS.update({
    **{f"spherical.{n}": "result record built by the package" for n in (
        "Circle", "Collinearity", "FunctionGenerator", "Intersection", "PolygonRelations", "SliderStroke",
        "SphericalFourBarPose", "SphericalLinkagePose", "SphericalPathDesign", "SphericalPolygon", "SphericalType")},
})

_SX_PATH = {"points": "vec3", "theta": "real", "start": "vec3", "metric": "option",
            "branches": ("branch", first), "tol": "tolerance", "min_transmission": "scalar?"}
CASES.update({
    f"spherical.{name}": E((lambda name=name: getattr(sph, name)), _SX_PATH,
                           points=_SPH_PATH6[0], theta=_SPH_PATH6[1], start=_SPH_PATH6[2], metric="chord",
                           branches=(1, 1), tol=1e-3, min_transmission=0.5)
    for name in ("path_stephenson2", "path_watt1", "path_watt2")
})


@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", slotted(CASES))
def test_bad_values_rejected_by_name(key):
    assert_rejected_by_name(CASES, key)


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


def test_freudenstein_coefficients_beyond_the_float_range_named():
    """k2 = 1e300 squared raised a bare OverflowError (Python floats in the generated code)."""
    k = [float(v) for v in sph.freudenstein_coefficients(0.4, 0.9, 0.7, 1.0)]
    with pytest.raises(ValueError, match="Expected `k1` .. `k4`"):
        sph.arcs_from_coefficients(k[0], 1e300, 1e300, k[3])
    with pytest.raises(ValueError, match="Expected `k1` .. `k4` with \\|cos b\\| < 1"):
        sph.arcs_from_coefficients(k[0], k[1], k[2], 1e300)
    arcs = sph.arcs_from_coefficients(k[0], 1e300, k[2], k[3])      # a tiny crank arc: fine
    assert np.all(np.isfinite(arcs)) and 0.0 < arcs[0] < 1e-299

