"""Transmission angle of the four-bar (stub, being written)."""

__all__ = ["transmission_angle", "min_transmission_angle"]


def transmission_angle(a, b, c, d, theta):
    raise NotImplementedError


def min_transmission_angle(a, b, c, d):
    raise NotImplementedError
