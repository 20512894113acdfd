"""mech: a symbolic-numeric companion to linkage kinematics.

Every formula in this package was derived in a SymPy notebook under ``derivations/`` and
emitted as NumPy code in ``mech._generated``; the subpackages add the conventions, branch
selection, validation and documentation.

Subpackages are imported on first use, so ``import mech`` stays light:

>>> import mech
>>> mech.planar.time_ratio(0.0)
1.0
"""

import importlib as _importlib

from mech._backend import get_backend, set_backend
from mech._errors import AssemblyError, InputTypeError

__all__ = ["AssemblyError", "InputTypeError", "atlas", "exercises", "get_backend", "planar", "set_backend",
           "spatial", "spherical"]
__version__ = "0.1.0"

_SUBPACKAGES = {"atlas", "exercises", "planar", "spatial", "spherical"}


def __getattr__(name):
    if name in _SUBPACKAGES:
        return _importlib.import_module(f"mech.{name}")
    raise AttributeError(f"module 'mech' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | _SUBPACKAGES)
