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


def _modules_of(subject):
    """The private modules of a subject subpackage."""
    package = importlib.import_module(f"mech.planar.{subject}")
    return [importlib.import_module(f"{package.__name__}.{m.name}") for m in pkgutil.iter_modules(package.__path__)]


def _declared(subject):
    """A subject's public names as its modules' ``__all__`` lists declare them (no hand-kept list)."""
    return sorted({n for module in _modules_of(subject) for n in module.__all__})


#: mech.planar's public names, derived from the modules' ``__all__``: adding a function to a
#: module's ``__all__`` adds it here, and to both ``__init__`` files, with no other edit
PLANAR_ALL = sorted({"AssemblyError", *(n for s in SUBJECTS for n in _declared(s))})

PLANAR_DIR = pathlib.Path(mech.planar.__file__).parent


def _subject(name):
    return importlib.import_module(f"mech.planar.{name}")


def _owner(name):
    """The subject subpackages whose ``__all__`` lists ``name``."""
    return [s for s in SUBJECTS if name in _subject(s).__all__]


def test_planar_all_unchanged():
    assert sorted(mech.planar.__all__) == PLANAR_ALL
    assert len(set(mech.planar.__all__)) == len(mech.planar.__all__)


def test_no_name_lost_since_the_grouping():
    """The 136 names of issue 12 (and those added since) are all still there, a few checked by name."""
    assert len(PLANAR_ALL) >= 136
    for name in ("FourBar", "Linkage", "grashof", "transmission_angle", "static_forces", "cognates",
                 "jansen_linkage", "time_ratio", "velocity_polygon", "wedge_press_forces"):
        assert name in PLANAR_ALL, name


def test_subject_all_is_built_from_its_modules():
    """Each subject's ``__all__`` is the union of its modules' ``__all__`` (none is left out)."""
    for s in SUBJECTS:
        assert _subject(s).__all__ == _declared(s), s


def test_a_new_name_in_a_module_all_is_reexported(monkeypatch):
    """The re-export follows a module's ``__all__``: a planted name reaches both packages."""
    import importlib as _il

    from mech.planar.structure import _grashof

    monkeypatch.setattr(_grashof, "__all__", [*_grashof.__all__, "planted_formula"], raising=True)
    monkeypatch.setattr(_grashof, "planted_formula", lambda: 42, raising=False)
    try:
        structure = _il.reload(_subject("structure"))
        planar = _il.reload(mech.planar)
        assert "planted_formula" in structure.__all__ and "planted_formula" in planar.__all__
        assert planar.planted_formula() == 42
    finally:
        monkeypatch.undo()
        _il.reload(_subject("structure"))
        _il.reload(mech.planar)
    assert "planted_formula" not in mech.planar.__all__


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
    assert folders == sorted([*SUBJECTS, "synthesis", "export"])
