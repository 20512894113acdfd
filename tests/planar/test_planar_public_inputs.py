"""`mech.planar` (its five subjects) rejects bad input by name: the table of its public callables
(the format and the check are in ``tests/public_inputs.py``) and the reported cases.
"""

import math

import numpy as np
import pytest

import mech
import mech.planar as pl
from tests.public_inputs import (ABCD, E, MOTION, MOTION2, THETA, assert_rejected_by_name, first, fourbar, linkage,
                                 slider, slotted)

CASES = {}
RECORDS = {}


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


CASES.update({
    # ------------------------------------------------------------------------- planar
    "planar.Cognate.place": E(lambda: pl.cognates(fourbar()).aegk.place, {"z": "point"}, z=1 + 1j),
    "planar.Cognate.solve": E(lambda: pl.cognates(fourbar()).aegk.solve,
                              {"theta": "real", "branch": "branch?", "strict": "bool"},
                              theta=[0.5, 1.0], branch=1, strict=False),
    "planar.Cognates": E(lambda: pl.Cognates, original=fourbar()),
    "planar.Cognates.joints": E(lambda: pl.cognates(fourbar()).joints, THETA, theta=[0.5, 1.0]),
    "planar.Cognates.path": E(lambda: pl.cognates(fourbar()).path, THETA, theta=[0.5, 1.0]),
    "planar.Cognates.branches": E(lambda: pl.cognates(fourbar()).branches, THETA, theta=[0.5, 1.0]),
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
    "planar.EllipticTrammel.solve": E(lambda: pl.EllipticTrammel(2.0).solve, MOTION, **MOTION2),
    "planar.EllipticTrammel.path_axes": E(lambda: pl.EllipticTrammel(2.0, point=(0.5, 0.1)).path_axes),
    "planar.EllipticTrammel.stroke": E(lambda: pl.EllipticTrammel(2.0).stroke),
    "planar.FourBar": E(lambda: pl.FourBar, {**ABCD, "branch": "branch", "coupler": ("real", first),
                                             "rtol": "scalar"},
                        a=10, b=40, c=30, d=35, branch=1, coupler=(20, 10), rtol=1e-12),
    "planar.FourBar.solve": E(lambda: fourbar().solve, MOTION, **MOTION2),
    "planar.FourBar.limit_positions": E(lambda: fourbar().limit_positions),
    "planar.FourBar.coupler_point_speed": E(lambda: fourbar().coupler_point_speed, {"theta": "real", "omega": "real"},
                                            theta=[0.0, 1.0], omega=2.0),
    "planar.FourBar.transmission_angle": E(lambda: fourbar().transmission_angle, THETA, theta=[0.0, 1.0]),
    "planar.FourBar.min_transmission_angle": E(lambda: fourbar().min_transmission_angle),
    "planar.Guide": E(lambda: pl.Guide, {"through": "point_or_name", "angle": "scalar"},
                      link="ground", through=1 + 2j, angle=0.3),
    "planar.GuideBar": E(lambda: pl.GuideBar, {"a": "scalar", "d": "scalar"}, a=150.0, d=300.0),
    "planar.GuideBar.from_swing": E(lambda: pl.GuideBar.from_swing, {"d": "scalar", "swing": "scalar"},
                                    d=300.0, swing=1.0),
    "planar.GuideBar.solve": E(lambda: pl.GuideBar(150.0, 300.0).solve,
                               {k: v for k, v in MOTION.items() if k != "strict"},
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
    "planar.Linkage.solve": E(lambda: linkage().solve,
                              {"inputs": "real", "order": "order", "omega": "realmap", "alpha": "realmap",
                               "strict": "bool"},
                              inputs=[0.0, 1.0], order=2, omega=1.5, alpha=0.5, strict=False),
    "planar.Linkage.assembly_range": E(lambda: linkage().assembly_range,
                                       {"start": "scalar", "end": "scalar", "samples": "count"},
                                       start=-3.0, end=3.0, samples=101),
    "planar.LinkageSolution.instant_centres": E(lambda: _fourbar_solution().instant_centres),
    "planar.LinkageSolution.direction": E(lambda: _example_2_10().direction, link="2"),
    "planar.OldhamCoupling": E(lambda: pl.OldhamCoupling, {"e0": "scalar"}, e0=0.1),
    "planar.OldhamCoupling.solve": E(lambda: pl.OldhamCoupling(0.1).solve, MOTION, **MOTION2),
    "planar.OldhamCoupling.inertia_force": E(lambda: pl.OldhamCoupling(0.1).inertia_force,
                                             {"m": "real", "omega": "real"}, m=2.0, omega=10.0),
    "planar.Polygon.segment": E(lambda: pl.velocity_polygon([_motion()]).segment, tail="p", head="c"),
    "planar.Polygon.lengths": E(lambda: pl.velocity_polygon([_motion()]).lengths, {"mu": "scalar"}, mu=50.0),
    "planar.RotatingGuideBar": E(lambda: pl.RotatingGuideBar, {"a": "scalar", "d": "scalar"}, a=2.0, d=1.0),
    "planar.RotatingGuideBar.solve": E(lambda: pl.RotatingGuideBar(2.0, 1.0).solve, MOTION, **MOTION2),
    "planar.RotatingGuideBar.guide_turns_per_crank_turn": E(
        lambda: pl.RotatingGuideBar(1.0, 1.0).guide_turns_per_crank_turn),
    "planar.ScotchYoke": E(lambda: pl.ScotchYoke, {"a": "scalar"}, a=2.0),
    "planar.ScotchYoke.solve": E(lambda: pl.ScotchYoke(2.0).solve, MOTION, **MOTION2),
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
    "planar.SliderCrank.solve": E(lambda: slider().solve, MOTION, **MOTION2),
    "planar.SliderCrank.limit_positions": E(lambda: slider().limit_positions),
    "planar.SliderCrank.stroke": E(lambda: slider().stroke),
    "planar.SliderCrank.extreme_angle": E(lambda: slider().extreme_angle),
    "planar.SliderCrank.time_ratio": E(lambda: slider().time_ratio),
    "planar.SliderCrank.transmission_angle": E(lambda: slider().transmission_angle, THETA, theta=[0.0, 1.0]),
    "planar.SliderCrank.min_transmission_angle": E(lambda: slider().min_transmission_angle),
    "planar.SliderCrank.approximate": E(lambda: pl.SliderCrank(30, 100).approximate, {"theta": "real", "omega": "real"},
                                        theta=[0.0, 1.0], omega=2.0),
    "planar.SwingingBlock": E(lambda: pl.SwingingBlock, {"a": "scalar", "d": "scalar"}, a=1.0, d=2.0),
    "planar.SwingingBlock.solve": E(lambda: pl.SwingingBlock(1.0, 2.0).solve, MOTION, **MOTION2),
    "planar.SwingingBlock.swing": E(lambda: pl.SwingingBlock(1.0, 2.0).swing),
    "planar.TangentMechanism": E(lambda: pl.TangentMechanism, {"L": "scalar"}, L=2.0),
    "planar.TangentMechanism.solve": E(lambda: pl.TangentMechanism(2.0).solve, MOTION, **MOTION2),
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
    "planar.cognates": E(lambda: pl.cognates, fourbar=fourbar()),
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
                               {**ABCD, "coupler": "point", "n": "count", "branch": "branch", "start": "scalar"},
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
    "planar.fourbar_dead_points": E(lambda: pl.fourbar_dead_points, {**ABCD, "branch": "branch"},
                                    a=10, b=40, c=30, d=35, branch=1),
    "planar.fourbar_mechanical_advantage": E(lambda: pl.fourbar_mechanical_advantage,
                                             {**ABCD, "theta": "real", "branch": "branch", "driver": "option"},
                                             a=30, b=70, c=60, d=80, theta=1.0, branch=1, driver="crank"),
    "planar.fourbar_pressure_angle": E(lambda: pl.fourbar_pressure_angle, {**ABCD, "theta": "real"},
                                       a=30, b=70, c=60, d=80, theta=[0.0, 1.0]),
    "planar.friction_angle": E(lambda: pl.friction_angle, {"mu": "real"}, mu=0.1),
    "planar.friction_circle": E(lambda: pl.friction_circle, {"mu0": "real", "r": "real"}, mu0=0.2, r=12.5),
    "planar.grashof": E(lambda: pl.grashof, {**ABCD, "rtol": "scalar"}, a=10, b=40, c=30, d=35, rtol=1e-12),
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
    "planar.limit_positions": E(lambda: pl.limit_positions, {**ABCD, "branch": "branch"},
                                a=10, b=40, c=30, d=35, branch=1),
    "planar.mechanical_advantage": E(lambda: pl.mechanical_advantage, {"method": "option"},
                                     solution=_mechanism_solution(), input="crank", output="rocker",
                                     method="velocities"),
    "planar.min_transmission_angle": E(lambda: pl.min_transmission_angle, ABCD, a=30, b=70, c=60, d=80),
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
    "planar.transmission_angle": E(lambda: pl.transmission_angle, {**ABCD, "theta": "real"},
                                   a=30, b=70, c=60, d=80, theta=[0.0, 1.0]),
    "planar.transmission_extremes": E(lambda: pl.transmission_extremes, ABCD, a=30, b=70, c=60, d=80),
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
})

CASES.update({
    "planar.fourbar_inputs": E(lambda: pl.fourbar_inputs, {**ABCD, "coupler": ("real", first), "rtol": "scalar"},
                               a=10, b=40, c=30, d=35, coupler=(20, 10), rtol=1e-12),
})


#: classes whose constructors are not walked: the package builds them (result records and the
#: exception type); the user reads them and never feeds numbers into them
RECORDS.update({
    "planar.AssemblyError": "exception type",
    **{f"planar.{n}": "result record built by the package" for n in (
        "AssemblyInterval", "Centre", "CentrodeSegment", "Cognate", "CognatePose", "CouplerCentrodes",
        "CouplerDashes", "DeadPoints", "Equation", "FourBarPose", "GrashofResult", "GuideBarPose", "Image",
        "InclineForces", "InstantCentres", "KindInterval", "LimitPositions", "LinkVelocities",
        "LinkageSolution", "OldhamPose", "Polygon", "RelativeMotion", "RotatingGuideBarPose",
        "ScotchYokePose", "ScrewResult", "Slide", "SliderCrankLimits", "SliderCrankPose",
        "SliderCrankSeries", "StaticForces", "Stroke", "TangentPose", "TenBarPose", "Term", "TrammelPose",
        "TransmissionExtremes", "TriadPose", "WedgePress", "WedgePressForces")},
})


@pytest.mark.parametrize("key", sorted(CASES))
def test_valid_call_succeeds(key):
    CASES[key].call()


@pytest.mark.parametrize("key", slotted(CASES))
def test_bad_values_rejected_by_name(key):
    assert_rejected_by_name(CASES, key)


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


@pytest.mark.parametrize("value, message", [(1, "1"), (1.0, "1.0"), ("yes", "'yes'"), (None, "None")])
def test_strict_must_be_a_bool(value, message):
    with pytest.raises(mech.InputTypeError, match=f"Expected `strict` to be True or False, got {message}"):
        pl.FourBar(10, 40, 30, 35).solve(0.5, strict=value)



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

