"""Limit positions of the crank-rocker (stub, being written)."""

__all__ = ["LimitPositions", "limit_positions"]


class LimitPositions:
    pass


def limit_positions(a, b, c, d, *, branch=1):
    raise NotImplementedError
