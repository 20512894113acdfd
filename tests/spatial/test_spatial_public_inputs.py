"""`mech.spatial` rejects bad input by name: the table of its public callables (the format and
the check are in ``tests/public_inputs.py``).
"""

import warnings

import numpy as np
import pytest

import mech.spatial as sp
from tests.public_inputs import E, assert_rejected_by_name, first, rssr, slotted

CASES = {}
RECORDS = {}


CASES.update({
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
    "spatial.RSSR.coefficients": E(lambda: rssr().coefficients, {"phi01": "real"}, phi01=[0.0, 1.0]),
    "spatial.RSSR.points": E(lambda: rssr().points, {"phi01": "real", "phi03": "real"}, phi01=[0.0, 1.0],
                             phi03=0.5),
    "spatial.RSSR.discriminant": E(lambda: rssr().discriminant, {"phi01": "real"}, phi01=[0.0, 1.0]),
    "spatial.RSSR.solve": E(lambda: rssr().solve,
                            {"phi01": "real", "order": "order", "omega": "real", "alpha": "real", "strict": "bool"},
                            phi01=[0.0, 1.0], order=2, omega=1.5, alpha=0.5, strict=False),
    "spatial.RSSR.assembly_range": E(lambda: rssr().assembly_range),
    "spatial.RSSR.change_angles": E(lambda: rssr().change_angles),
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
})

RECORDS.update({
    **{f"spatial.{n}": "result record built by the package" for n in (
        "AssemblyRange", "ChainPose", "DoubleJointPose", "RCCCPose", "RSSRPose")},
})


@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", slotted(CASES))
def test_bad_values_rejected_by_name(key):
    assert_rejected_by_name(CASES, key)


def test_hooke_acceleration_huge_speed_at_a_stationary_angle():
    """At theta1 = 0 the slope of the ratio is 0: 0 * (1e200)**2 gave NaN (0 times inf)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert sp.hooke_acceleration(0.0, 0.5, omega=1e200) == 0.0
