"""Re-exports built from the modules' ``__all__``: a package lists its modules, not their names.

A subpackage's ``__init__`` calls `reexport` with the modules whose public names it
offers; each module's ``__all__`` is the one list of what it makes public, so a new
function needs only its own module's ``__all__``. The tests derive the expected public
names the same way (`public_names`), never from a hand-kept list.
"""

__all__ = ["public_names", "reexport"]


def public_names(*modules):
    """The sorted union of the ``__all__`` lists of `modules`.

    Raises ValueError if two modules offer different objects under one name.

    Examples
    --------
    >>> from mech._exports import public_names
    >>> from mech.planar.structure import _grashof, _quick_return
    >>> public_names(_quick_return, _grashof)[:3]
    ['GrashofResult', 'KindInterval', 'extreme_angle']
    """
    owner = {}
    for module in modules:
        for name in module.__all__:
            obj = getattr(module, name)
            if name in owner and getattr(owner[name], name) is not obj:
                raise ValueError(f"Expected `modules` to offer one object named {name!r}, got one in {owner[name].__name__} "
                                 f"and another in {module.__name__}")
            owner.setdefault(name, module)
    return sorted(owner)


def reexport(namespace, *modules):
    """Bind the public names of `modules` in `namespace` (a package's ``globals()``).

    Returns the sorted list of those names, for the package's ``__all__``.
    """
    names = public_names(*modules)
    for module in modules:
        for name in module.__all__:
            namespace[name] = getattr(module, name)
    return names
