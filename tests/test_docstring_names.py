"""Names written as ```mech.<...>``` in the docstrings and comments of every module of ``mech``
resolve to a real module or attribute (a reader who types them must not meet an
AttributeError)."""

import importlib
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
#: every module of the package (no hand-kept list: a new module is checked from its first commit)
FILES = sorted(ROOT.glob("mech/**/*.py"))
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
