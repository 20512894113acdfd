"""Time ratio and extreme angle (stub, being written)."""

__all__ = ["time_ratio", "extreme_angle"]


def time_ratio(extreme_angle):
    raise NotImplementedError


def extreme_angle(time_ratio):
    raise NotImplementedError
