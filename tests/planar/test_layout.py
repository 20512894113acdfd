"""The layout of `mech.planar`: one subpackage per section of the chapter, names unchanged.

Issue 12 grouped the flat folder of private modules by subject. These tests pin the public
names of ``mech.planar`` as they were before the move, and check that every name is
re-exported from exactly one subject subpackage and is the object defined there.
"""

import importlib
import pathlib
import pkgutil

import pytest

import mech
import mech.planar

SUBJECTS = ("structure", "kinematics", "coupler", "forces", "special")

# sorted(mech.planar.__all__) before the modules were grouped (issue 12, item 8), plus the
# names added since: WedgePressForces and wedge_press_forces (issue 18, Fig. 2-68) and
# coupler_sextic (issue 14).
PLANAR_ALL = [
    "AssemblyError", "AssemblyInterval", "Centre", "CentrodeSegment", "Cognate", "CognatePose",
    "Cognates", "CouplerCentrodes", "CouplerDashes", "DeadPoints", "EllipticTrammel", "Equation",
    "FRICTION_TABLE_2_2", "FourBar", "FourBarPose", "GrashofResult", "Guide", "GuideBar",
    "GuideBarPose", "Image", "InclineForces", "InstantCentres", "JANSEN_HOLY_NUMBERS",
    "KindInterval", "LimitPositions", "LinkVelocities", "Linkage", "LinkageSolution",
    "OldhamCoupling", "OldhamPose", "Polygon", "RelativeMotion", "RotatingGuideBar",
    "RotatingGuideBarPose", "ScotchYoke", "ScotchYokePose", "ScrewJack", "ScrewResult", "Slide",
    "SliderCrank", "SliderCrankLimits", "SliderCrankPose", "SliderCrankSeries", "StaticForces",
    "Stroke", "SwingingBlock", "TangentMechanism", "TangentPose", "TenBarPose", "Term",
    "TrammelPose", "TransmissionExtremes", "TriadPose", "TriadSixBar", "WedgePress", "WedgePressForces",
    "acceleration_image", "acceleration_polygon", "as_linkage", "centre_count",
    "centre_velocities", "cognates", "coincident_motion", "collar_friction_radius",
    "coupler_centrodes", "coupler_dashes", "coupler_sextic", "curved_contact_mu", "design_check",
    "eccentric_clamp_locks", "eccentric_clamp_max_angle", "efficiency", "efficiency_from_drive",
    "efficiency_from_resistance", "extreme_angle", "fourbar_dead_points",
    "fourbar_mechanical_advantage", "fourbar_pressure_angle", "friction_angle", "friction_circle",
    "grashof", "guide_bar_pressure_angle", "hand_press", "higher_pair", "incline_forces",
    "instant_centres", "is_self_locking", "jansen_linkage", "jaw_crusher",
    "joint_transmission_angle", "journal_mu", "journal_state", "kind_intervals", "lead_angle",
    "limit_positions", "mechanical_advantage", "min_transmission_angle", "omega_ratio",
    "parallel_efficiency", "pressure_angle", "prismatic", "push_rod", "quick_return_crank_rocker",
    "quick_return_guide_bar", "quick_return_slider_crank", "ram_stroke", "relative_motion",
    "revolute", "rolling_mill_max_thickness", "screw_efficiency", "series_efficiency",
    "shaper_stephenson", "shaper_watt", "slider_crank_dead_points",
    "slider_crank_mechanical_advantage", "slider_crank_min_transmission_angle",
    "slider_crank_pressure_angle", "slider_state", "spreading_wedge_force", "static_forces",
    "step_ratio", "stephenson_six_bar", "thread_friction_angle", "thrust_friction_moment",
    "time_ratio", "total_reaction", "transmission_angle", "transmission_extremes",
    "two_force_tilt_angle", "velocity_image", "velocity_polygon", "vgroove_mu", "watt_six_bar",
    "watt_transmission_angles", "wedge_press", "wedge_press_forces",
]

PLANAR_DIR = pathlib.Path(mech.planar.__file__).parent


def _subject(name):
    return importlib.import_module(f"mech.planar.{name}")


def _owner(name):
    """The subject subpackages whose ``__all__`` lists ``name``."""
    return [s for s in SUBJECTS if name in _subject(s).__all__]


def test_planar_all_unchanged():
    assert sorted(mech.planar.__all__) == PLANAR_ALL
    assert len(set(mech.planar.__all__)) == len(mech.planar.__all__)


def test_pinned_list_is_sorted_and_complete():
    """The pin itself: sorted, no duplicates, 136 names (so a lost name cannot hide in it)."""
    assert PLANAR_ALL == sorted(set(PLANAR_ALL))
    assert len(PLANAR_ALL) == 136


@pytest.mark.parametrize("name", [n for n in PLANAR_ALL if n != "AssemblyError"])
def test_name_lives_in_one_subject(name):
    """Each public name comes from exactly one subject and is the object defined there."""
    owners = _owner(name)
    assert len(owners) == 1, f"{name} is exported by {owners}"
    subject = _subject(owners[0])
    obj = getattr(mech.planar, name)
    assert obj is getattr(subject, name)
    module = getattr(obj, "__module__", None)
    if module is not None and callable(obj):
        # Defined in a private module of that subject, and that module holds the same object.
        assert module.startswith(f"mech.planar.{owners[0]}._"), module
        assert getattr(importlib.import_module(module), name) is obj


def test_assembly_error_is_the_package_error():
    assert mech.planar.AssemblyError is mech.AssemblyError
    assert all("AssemblyError" not in _subject(s).__all__ for s in SUBJECTS)


def test_subject_all_lists_match_planar_all():
    """The subjects' ``__all__`` lists together are exactly ``mech.planar``'s names."""
    union = [n for s in SUBJECTS for n in _subject(s).__all__]
    assert sorted(union) == [n for n in PLANAR_ALL if n != "AssemblyError"]
    for s in SUBJECTS:
        names = _subject(s).__all__
        assert names == sorted(names)
        assert all(hasattr(_subject(s), n) for n in names)


@pytest.mark.parametrize("subject", [*SUBJECTS, "synthesis"])
def test_subject_is_a_documented_small_package(subject):
    package = _subject(subject)
    assert package.__doc__ and package.__doc__.strip()
    modules = [m.name for m in pkgutil.iter_modules(package.__path__)]
    assert modules, subject
    assert len(modules) <= 12, modules
    assert all(m.startswith("_") for m in modules), modules


def test_no_flat_private_modules_left():
    """Only the package's ``__init__`` stays at the top of ``mech/planar``."""
    flat = sorted(p.name for p in PLANAR_DIR.glob("*.py"))
    assert flat == ["__init__.py"]
    folders = sorted(p.name for p in PLANAR_DIR.iterdir() if (p / "__init__.py").is_file())
    assert folders == sorted([*SUBJECTS, "synthesis"])
