"""The planar four-bar (stub, being written)."""

__all__ = ["FourBar", "FourBarPose"]


class FourBarPose:
    pass


class FourBar:
    pass
