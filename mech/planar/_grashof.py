"""Grashof classification of the four-bar (stub, being written)."""

__all__ = ["GrashofResult", "grashof"]


class GrashofResult:
    pass


def grashof(a, b, c, d, *, rtol=1e-12):
    raise NotImplementedError
