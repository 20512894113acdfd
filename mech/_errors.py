"""Exceptions shared by every part of the package."""

__all__ = ["AssemblyError", "InputTypeError"]


class AssemblyError(ValueError):
    """A linkage cannot be assembled at the requested input.

    Raised by ``solve(..., strict=True)``; the message names the first failing input.
    Without ``strict``, such inputs give NaN and ``valid == False`` instead.
    """


class InputTypeError(TypeError, ValueError):
    """An argument has the wrong type: complex, boolean, string, ``None`` or another object.

    It is both a ``TypeError`` and a ``ValueError``, so ``except ValueError`` still catches
    every bad input. The message names the argument and shows the value.
    """


class UnknownKeyError(KeyError, ValueError):
    """A key names nothing known: a ``KeyError`` for mapping protocols, and a ``ValueError``
    like every other bad input (private; the message names the key)."""

    def __str__(self):
        return str(self.args[0]) if self.args else ""
