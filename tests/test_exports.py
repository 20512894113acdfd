"""Every public package builds its ``__all__`` from its modules' ``__all__`` (`mech._exports`).

A package's ``__init__`` names the modules it re-exports and calls `reexport`; it keeps no
list of function names, so a new function needs only its own module's ``__all__``. The
expected names here are derived the same way, from the ``reexport`` call read with `ast`,
never from a hand-kept list.
"""

import ast
import importlib
import inspect
import pkgutil

import pytest

import mech
from mech._exports import public_names

#: public packages that hold code or data of their own rather than re-exports, and why
NOT_REEXPORTING = {
    "mech": "subpackages are imported on first use (import mech stays light)",
    "mech.exercises": "the exercise registry is built in the package itself",
    "mech.index": "the textbook index is the package's own code",
    "mech.atlas": "the atlas package is being regrouped; its names are listed by hand until then",
}


def _public_packages():
    found = ["mech"]
    for info in pkgutil.walk_packages(mech.__path__, "mech."):
        if info.ispkg and not any(part.startswith("_") for part in info.name.split(".")):
            found.append(info.name)
    return sorted(found)


def _reexport_call(package):
    """The ``reexport(globals(), ...)`` call of `package`'s ``__init__`` and the literal
    names listed beside it in ``__all__`` (None if there is no such call)."""
    tree = ast.parse(inspect.getsource(importlib.import_module(package)))
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", None) == "__all__" for t in node.targets):
            calls = [n for n in ast.walk(node.value) if isinstance(n, ast.Call) and getattr(n.func, "id", "") == "reexport"]
            literals = [n.value for n in ast.walk(node.value) if isinstance(n, ast.Constant) and isinstance(n.value, str)]
            return (calls[0], literals) if calls else None
    return None


PACKAGES = [p for p in _public_packages() if p not in NOT_REEXPORTING]


def test_walk_finds_the_packages():
    assert {"mech.planar", "mech.planar.synthesis", "mech.spherical", "mech.spherical.guidance",
            "mech.spherical.path", "mech.spherical.linkage", "mech.spatial"} <= set(PACKAGES)
    assert set(NOT_REEXPORTING) <= set(_public_packages())


@pytest.mark.parametrize("package", PACKAGES)
def test_all_is_the_union_of_the_modules_all(package):
    found = _reexport_call(package)
    assert found, f"{package}.__init__ builds __all__ without reexport (a hand-kept list)"
    call, literals = found
    module = importlib.import_module(package)
    sources = [getattr(module, arg.id) for arg in call.args[1:]]
    expected = sorted({*public_names(*sources), *literals})
    assert sorted(module.__all__) == expected
    assert len(set(module.__all__)) == len(module.__all__)
    for source in sources:
        for name in source.__all__:
            assert getattr(module, name) is getattr(source, name), f"{package}.{name}"


@pytest.mark.parametrize("package", PACKAGES)
def test_init_imports_modules_not_names(package):
    """The ``__init__`` imports whole modules from its own package: a ``from ._x import f``
    would be a second list of public names."""
    tree = ast.parse(inspect.getsource(importlib.import_module(package)))
    for node in tree.body:
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith(package + "."):
            pytest.fail(f"{package} imports names from {node.module}: {[a.name for a in node.names]}")


def test_a_planted_name_reaches_both_spherical_packages(monkeypatch):
    """A name added to a module's ``__all__`` is re-exported by its subpackage and by
    `mech.spherical`, with no other edit."""
    import mech.spherical
    import mech.spherical.path
    from mech.spherical.path import _octic

    monkeypatch.setattr(_octic, "__all__", [*_octic.__all__, "planted_formula"])
    monkeypatch.setattr(_octic, "planted_formula", lambda: 42, raising=False)
    try:
        path = importlib.reload(mech.spherical.path)
        spherical = importlib.reload(mech.spherical)
        assert "planted_formula" in path.__all__ and "planted_formula" in spherical.__all__
        assert spherical.planted_formula() == 42
    finally:
        monkeypatch.undo()
        importlib.reload(mech.spherical.path)
        importlib.reload(mech.spherical)
    assert "planted_formula" not in mech.spherical.__all__
