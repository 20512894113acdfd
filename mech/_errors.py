"""Exceptions shared by every part of the package."""

__all__ = ["AssemblyError"]


class AssemblyError(ValueError):
    """A linkage cannot be assembled at the requested input.

    Raised by ``solve(..., strict=True)``; the message names the first failing input.
    Without ``strict``, such inputs give NaN and ``valid == False`` instead.
    """
