"""Figure of the transmission angle over a crank turn (``book/kinematics/examples.md``).

A plain plotting function: it takes angles computed by ``mech`` and a Matplotlib ``Axes``
(a new figure when ``ax`` is None), draws, and returns the axes. Nothing runs at import.
"""

import numpy as np

__all__ = ["transmission_angle_curve"]


def transmission_angle_curve(theta, gamma, ax=None, *, minimum=None, allowable=None, label=None):
    """Plot the transmission angle against the crank angle, both in degrees (F50-F55).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Crank angles, radians.
    gamma : array_like, shape (n,)
        Transmission angle at `theta`, radians (NaN where the linkage cannot be assembled
        leaves a gap).
    minimum : (float, float), optional
        ``(gamma_min, theta_at)`` in radians, marked with a dot.
    allowable : float, optional
        A design limit in radians (e.g. 40 degrees, F51), drawn as a horizontal line.
    label : str, optional
        Legend label of the curve.
    """
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(7.0, 3.6))
    deg = np.degrees(np.asarray(theta))
    ax.plot(deg, np.degrees(np.asarray(gamma)), color="tab:blue", lw=1.6, label=label or r"$\gamma(\theta)$")
    if allowable is not None:
        ax.axhline(np.degrees(allowable), color="tab:red", lw=1.0, ls="--",
                   label=rf"allowable $\gamma$ = {np.degrees(allowable):.0f}°")
    if minimum is not None:
        g, t = np.degrees(minimum[0]), np.degrees(minimum[1])
        ax.plot([t], [g], "o", color="black", zorder=3)
        ax.annotate(rf"$\gamma_{{\min}}$ = {g:.2f}° at $\theta$ = {t:.0f}°", (t, g),
                    textcoords="offset points", xytext=(10, -14), fontsize=9)
    ax.set_xlim(deg[0], deg[-1])
    ax.set_ylim(0.0, 95.0)
    ax.set_xticks(np.arange(np.ceil(deg[0] / 60.0) * 60.0, deg[-1] + 1.0, 60.0))
    ax.set_xlabel(r"crank angle $\theta$ (degrees)")
    ax.set_ylabel(r"transmission angle $\gamma$ (degrees)")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    return ax
