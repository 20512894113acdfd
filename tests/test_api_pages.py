"""The API reference (book/api/): every public name of every public package has an entry, and
the pages that use a name link to it (book/_ext/api_pages.py)."""

import importlib
import importlib.util
import inspect
import re
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
API = ROOT / "book" / "api"

spec = importlib.util.spec_from_file_location("api_pages", ROOT / "book" / "_ext" / "api_pages.py")
api_pages = importlib.util.module_from_spec(spec)
spec.loader.exec_module(api_pages)


def _documented_packages():
    """``{package: page}`` for every ``mech-api`` directive of the API pages."""
    found = {}
    for page in sorted(API.glob("*.md")):
        for package in re.findall(r"^```\{mech-api\}\s+(\S+)\s*$", page.read_text(), re.M):
            assert package not in found, f"{package} is documented on {found[package]} and {page.name}"
            found[package] = page.name
    return found


def test_public_packages_found_by_walking():
    packages = api_pages.public_packages()
    for name in ("mech", "mech.planar", "mech.planar.kinematics", "mech.spherical.guidance",
                 "mech.atlas", "mech.exercises", "mech.index", "mech.spatial"):
        assert name in packages
    assert not [p for p in packages if "._" in p]


def test_every_public_package_has_a_section():
    documented = _documented_packages()
    missing = sorted(set(api_pages.public_packages()) - set(documented))
    assert not missing, f"public packages without a `mech-api` section in book/api/: {missing}"
    unknown = sorted(set(documented) - set(api_pages.public_packages()))
    assert not unknown, f"book/api/ documents packages that are not public: {unknown}"


@pytest.mark.parametrize("package", api_pages.public_packages())
def test_every_name_in_all_has_an_entry(package):
    """Each name of ``__all__`` is described in a documented package that exports the same
    object: its own, or the subpackage that defines it."""
    documented = _documented_packages()
    homes = api_pages.homes()
    module = importlib.import_module(package)
    for name in module.__all__:
        obj = getattr(module, name)
        if inspect.ismodule(obj):
            # a subpackage has its own section; a plain module its docstring in the package's
            assert obj.__name__ in documented or not hasattr(obj, "__path__"), \
                f"{package}.{name} (a subpackage) has no section"
            continue
        home, home_name = homes[api_pages.key(name, obj)]
        assert home in documented, f"{package}.{name} lives in {home}, which has no page"
        assert getattr(importlib.import_module(home), home_name) is obj
        assert home_name in importlib.import_module(home).__all__


def test_home_is_the_defining_subpackage():
    import mech.planar
    import mech.spherical

    homes = api_pages.homes()
    assert homes[api_pages.key("FourBar", mech.planar.FourBar)] == ("mech.planar.kinematics", "FourBar")
    assert homes[api_pages.key("grashof", mech.planar.grashof)] == ("mech.planar.structure", "grashof")
    assert homes[api_pages.key("CouplerOctic", mech.spherical.CouplerOctic)] == ("mech.spherical.path", "CouplerOctic")
    # defined in mech._errors and re-exported by subpackages: its home is the top level
    assert homes[api_pages.key("AssemblyError", mech.planar.AssemblyError)] == ("mech", "AssemblyError")


def test_api_pages_are_in_the_table_of_contents():
    toc = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text())
    files = set()

    def walk(entries):
        for entry in entries:
            if "file" in entry:
                files.add(entry["file"])
            for k in ("chapters", "sections", "parts"):
                walk(entry.get(k, []))

    walk(toc.get("parts", []) + toc.get("chapters", []))
    pages = {f"api/{p.stem}" for p in API.glob("*.md")}
    assert pages <= files, f"API pages missing from book/_toc.yml: {sorted(pages - files)}"


def test_used_names_follow_imports_and_aliases():
    import mech.planar

    homes = api_pages.homes()
    code = ["import mech\nimport mech.planar as pl\nfrom mech.spherical import guidance as g\nimport numpy as np\n"
            "%matplotlib inline\n",
            "fb = pl.FourBar(1, 3, 2, 4)\nfb.solve(np.linspace(0, 1, 5))\n"
            "g.pole_triangle\nmech.planar.grashof(1, 3, 2, 4)\n",
            "from mech.planar.forces import transmission_angle\nprint(transmission_angle)\n",
            "this is not python (\n"]
    used = api_pages.used_names(code, homes)
    assert used == [("mech.planar.forces", "transmission_angle"), ("mech.planar.kinematics", "FourBar"),
                    ("mech.planar.structure", "grashof"), ("mech.spherical.guidance", "pole_triangle")]
    assert mech.planar.FourBar  # the names resolve to the objects the pages document
    # without an import of mech, a name that happens to match is not a use
    assert api_pages.used_names(["FourBar(1, 2, 3, 4)\n"], homes) == []


BUILT = ROOT / "book" / "_build" / "html"


@pytest.mark.skipif(not (BUILT / "objects.inv").exists(), reason="the book is not built")
def test_built_inventory_has_every_entry():
    from sphinx.util.inventory import InventoryFile

    with open(BUILT / "objects.inv", "rb") as f:
        inventory = InventoryFile.load(f, "", lambda base, uri: uri)
    names = {n for kind, entries in inventory.items() if kind.startswith("py:") for n in entries}
    missing = sorted(f"{p}.{n}" for p, n in set(api_pages.homes().values()) if f"{p}.{n}" not in names)
    assert not missing, f"names without an entry in the built API pages: {missing[:20]}"
