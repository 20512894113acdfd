"""Names written as ```mech.<...>``` in the docstrings and comments of every module of the
package resolve to a real module or attribute (a reader who types them must not meet an
AttributeError). The modules are found by walking ``mech/``, so a new module is checked
without being listed here."""

import importlib
import importlib.util
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
#: every module of the package; the numba kernels are left out where numba is missing, since
#: importing them is how a name in them would be resolved
FILES = sorted(p for p in (ROOT / "mech").rglob("*.py")
               if importlib.util.find_spec("numba") or not p.name.endswith("_numba.py"))
#: names that are not Python objects: Parquet metadata keys
NOT_OBJECTS = {"mech.atlas.sphere", "mech.atlas"}


def _resolves(dotted):
    parts = dotted.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for p in parts[i:]:
            if not hasattr(obj, p):
                return False
            obj = getattr(obj, p)
        return True
    return False


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(ROOT)))
def test_mech_names_in_backticks_resolve(path):
    names = set(re.findall(r"`(mech(?:\.\w+)+)`", path.read_text())) - NOT_OBJECTS
    missing = sorted(n for n in names if not _resolves(n))
    assert not missing, f"{path.name} names {missing}, which do not exist"


def test_walk_covers_every_subpackage():
    """The walk reaches every subpackage, and a name that does not exist is caught."""
    packages = {p.parent.relative_to(ROOT).as_posix() for p in ROOT.glob("mech/**/__init__.py")}
    walked = {p.parent.relative_to(ROOT).as_posix() for p in FILES}
    assert packages <= walked
    assert _resolves("mech.planar.FourBar") and not _resolves("mech.planar.NoSuchLinkage")
