"""Figures of the slider-crank (``book/kinematics/motion-diagrams.md``): plain plotting functions.

Each function takes data computed by ``mech`` and Matplotlib axes (new ones when ``axes``
is None) and returns the axes; nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["motion_diagrams"]


def motion_diagrams(theta, curves, axes=None, *, shade=None):
    """Draw displacement, velocity and acceleration against the crank angle (Fig. 2-26).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Crank angles, radians (drawn in degrees).
    curves : sequence of dict
        One entry per mechanism with keys ``label``, ``x``, ``v``, ``acc`` (arrays of
        shape (n,)) and optional ``style`` (a Matplotlib line style such as ``"--"``).
    axes : sequence of three Axes, optional
        Axes for x, v and acc; a new figure with three stacked axes when None.
    shade : (float, float), optional
        A crank-angle interval (radians, start and length) to shade, e.g. a slow stroke.
    """
    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(3, 1, figsize=(7.0, 7.0), sharex=True)
    deg = np.degrees(np.asarray(theta))
    names = (("x", "displacement $x$"), ("v", r"velocity $v$"), ("acc", r"acceleration $a_C$"))
    for ax, (key, ylabel) in zip(axes, names):
        for curve in curves:
            ax.plot(deg, curve[key], curve.get("style", "-"), color="black", lw=1.2,
                    label=curve["label"])
        if shade is not None:
            start, length = np.degrees(shade[0]) % 360.0, np.degrees(shade[1])
            for lo in (start - 360.0, start):
                ax.axvspan(max(lo, deg[0]), min(lo + length, deg[-1]), color="tab:blue", alpha=0.08, lw=0)
        ax.axhline(0.0, color="grey", lw=0.6)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    axes[0].legend(loc="lower left", fontsize=8)
    axes[-1].set_xlabel(r"crank angle $\theta$ (degrees)")
    axes[-1].set_xlim(deg[0], deg[-1])
    axes[-1].set_xticks(np.arange(deg[0], deg[-1] + 1, 60.0))
    return axes
