"""`mech.spherical.guidance` (and the six-bars it designs) rejects bad input by name: the table of its
public callables (the format and the check are in ``tests/public_inputs.py``).
"""

import numpy as np
import pytest

import mech.spherical as sph
from tests.public_inputs import ABCD, E, assert_rejected_by_name, first, slotted

CASES = {}
RECORDS = {}


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


_KEPT = {}


def _kept(build):
    """The design built by `build`, built once per process (keyed by its code: each factory
    below builds one fixed design, and rebuilding it for every bad value took most of the walk)."""
    if build.__code__ not in _KEPT:
        _KEPT[build.__code__] = build()
    return _KEPT[build.__code__]


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
                               {**ABCD, "E": ("scalar", first), "arcs": ("scalar", first), "H": ("scalar", first),
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
})
RECORDS["spherical.SphericalOptimalStephenson3"] = "result record built by the package"


CASES.update({
    "spherical.sixbar_curve": E(lambda: sph.sixbar_curve, {"linkage": "instance", "points": "vec3", "cone": "bool"},
                                linkage=_sx_watt2()[0], points=[[0.0, 0.6, 0.8]], cone=False),
})


@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", slotted(CASES))
def test_bad_values_rejected_by_name(key):
    assert_rejected_by_name(CASES, key)
