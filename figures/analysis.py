"""Kinematic-analysis chapter overview (``book/analysis/index.md``): plotting functions.

Each function takes arrays computed by ``mech`` and a Matplotlib ``Axes`` (a new figure
when None) and returns the axes; nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["two_methods"]


def two_methods(theta, analytic, by_centres, ax=None):
    """Angular velocities of several links over a crank turn by two methods.

    Parameters
    ----------
    theta : array_like
        Crank angles, radians (drawn in degrees).
    analytic, by_centres : mapping of str to array_like
        Link name to angular velocity from the Assur-group solution and from the
        instant centres. Drawn as lines and as markers on every tenth sample.
    """
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(7.0, 4.0))
    deg = np.degrees(theta)
    for name, w in analytic.items():
        line, = ax.plot(deg, w, lw=1.4, label=f"{name} (Assur groups)")
        ax.plot(deg[::10], np.asarray(by_centres[name])[::10], "o", ms=4, mfc="none",
                color=line.get_color(), label=f"{name} (instant centres)")
    ax.set_xlabel("crank angle (deg)")
    ax.set_ylabel("angular velocity (rad/s)")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.legend(fontsize=8, ncol=2)
    ax.grid(alpha=0.3)
    return ax
