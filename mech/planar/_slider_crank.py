"""The slider-crank (stub, being written)."""

__all__ = ["SliderCrank", "SliderCrankPose"]


class SliderCrankPose:
    pass


class SliderCrank:
    pass
