"""Figures of the universal joint (``book/spatial/universal-joint.md``, Fig. 2-123).

Plain plotting functions: they take numbers computed by ``mech`` and a Matplotlib ``Axes``
(a new figure when ``ax`` is None), draw, and return the axes. Nothing runs at import.
"""

import numpy as np

__all__ = ["ratio_curves", "fluctuation_curves", "joint_sketch"]


def _axes(ax, figsize):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=figsize)
    return ax


def ratio_curves(theta1, curves, ax=None, *, title=None):
    """Plot velocity ratios i31 against the input angle in degrees (Fig. 2-123a).

    Parameters
    ----------
    theta1 : array_like, shape (n,)
        Input angles, radians.
    curves : sequence of (str, array_like)
        Legend label and the ratio at `theta1`, one pair per curve.
    title : str, optional
        Axes title.
    """
    ax = _axes(ax, (7.0, 3.8))
    deg = np.degrees(np.asarray(theta1))
    styles = ("-", "--", "-.", ":", (0, (5, 1, 1, 1)), (0, (1, 1)))
    for (label, ratio), ls in zip(curves, styles * 4):
        ax.plot(deg, np.asarray(ratio), ls=ls, lw=1.6, label=label)
    ax.axhline(1.0, color="black", lw=0.6)
    ax.set_xlim(deg[0], deg[-1])
    ax.set_xticks(np.arange(np.ceil(deg[0] / 90.0) * 90.0, deg[-1] + 1.0, 90.0))
    ax.set_xlabel(r"input angle $\theta_1$ (degrees)")
    ax.set_ylabel(r"velocity ratio $i_{31}=\omega_3/\omega_1$")
    if title:
        ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=3, frameon=False)
    return ax


def fluctuation_curves(x, curves, ax=None, *, xlabel, marks=None):
    """Plot the ratio's fluctuation max(i31) - min(i31), in percent, against an angle.

    Parameters
    ----------
    x : array_like, shape (n,)
        The angle on the horizontal axis, radians (plotted in degrees).
    curves : sequence of (str, array_like)
        Legend label and the fluctuation (a fraction, plotted in percent) at `x`.
    xlabel : str
        Label of the horizontal axis.
    marks : sequence of (float, float, str), optional
        Points ``(x, fluctuation, text)`` to mark and annotate.
    """
    ax = _axes(ax, (7.0, 3.8))
    deg = np.degrees(np.asarray(x))
    for (label, f), ls in zip(curves, ("-", "--", "-.", ":") * 4):
        ax.plot(deg, 100.0 * np.asarray(f), ls=ls, lw=1.6, label=label)
    for xm, fm, text in marks or ():
        ax.plot([np.degrees(xm)], [100.0 * fm], "o", color="black", ms=4, zorder=3)
        ax.annotate(text, (np.degrees(xm), 100.0 * fm), textcoords="offset points",
                    xytext=(-60, 8), fontsize=8)
    ax.set_xlim(deg[0], deg[-1])
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(r"$\max i_{31} - \min i_{31}$ (%)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    return ax


def _rx(lam):
    c, s = np.cos(lam), np.sin(lam)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def _yoke(ax, axis, arm, *, color, length=1.75, radius=1.0):
    """A shaft along -`axis` (from the centre outwards) and its fork with tips at +-`arm`."""
    back = -axis * 0.45
    ax.plot(*np.array([back, -axis * length]).T, color=color, lw=5, solid_capstyle="round")
    for sign in (1.0, -1.0):
        tip = sign * radius * arm
        ax.plot(*np.array([back, back + tip, tip]).T, color=color, lw=2.5)


def joint_sketch(alpha, theta1, theta3, ax=None):
    """A 3-D sketch of a universal joint: two shafts, their yokes and the cross.

    The input shaft lies along -z (frame 4), the output shaft along +z' with
    z' = R_x(-alpha) z (frame 4'); the input yoke arm is e1 = (-sin theta1, cos theta1, 0)
    in frame 4, the output arm e3 = R_x(-alpha) (cos theta3, sin theta3, 0), as in (F73).

    Parameters
    ----------
    alpha : float
        Shaft angle, radians.
    theta1, theta3 : float
        Input and output yoke angles, radians (theta3 from ``mech``).
    ax : mpl_toolkits.mplot3d.Axes3D, optional
        A 3-D axes (a new figure when None).
    """
    if ax is None:
        import matplotlib.pyplot as plt

        ax = plt.figure(figsize=(5.5, 4.5)).add_subplot(projection="3d")
    R = _rx(-alpha)
    z_in = np.array([0.0, 0.0, 1.0])
    z_out = R @ z_in
    e1 = np.array([-np.sin(theta1), np.cos(theta1), 0.0])
    e3 = R @ np.array([np.cos(theta3), np.sin(theta3), 0.0])
    _yoke(ax, z_in, e1, color="tab:blue")           # input shaft 1 comes from -z
    _yoke(ax, -z_out, e3, color="tab:orange")       # output shaft 3 leaves along +z'
    for arm, color in ((e1, "tab:blue"), (e3, "tab:orange")):
        ax.plot(*np.array([-arm, arm]).T, color="black", lw=3)
        ax.scatter(*np.array([-arm, arm]).T, color=color, s=25, depthshade=False)
    ax.text(*(-1.8 * z_in), "shaft 1", fontsize=9)
    ax.text(*(1.8 * z_out), "shaft 3", fontsize=9)
    ax.text(*(1.15 * e1), r"$e^{(1)}$", fontsize=9)
    ax.text(*(1.15 * e3), r"$e^{(3)}$", fontsize=9)
    lim = 1.8
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_zlim(-lim, lim)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("$x_4$")
    ax.set_ylabel("$y_4$")
    ax.set_zlabel("$z_4$")
    ax.view_init(elev=18, azim=-25)
    return ax
