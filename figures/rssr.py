"""Figures of the RSSR spatial four-bar (``book/spatial/rssr.md``): plain plotting functions.

Each function takes data computed by ``mech`` and Matplotlib axes (new ones when ``axes``
is None) and returns the axes; nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["rssr_3d", "rssr_output"]


def rssr_3d(A, D, z3, B, C, axes=None, *, axis_length=2.0, labels=True):
    """Draw an RSSR in 3-D: the two skew axes, and crank, coupler, rocker in a few poses.

    Parameters
    ----------
    A, D : array_like, shape (3,)
        Crank pivot A (on the z0 axis) and rocker pivot D (on the rocker axis).
    z3 : array_like, shape (3,)
        Unit direction of the rocker axis (the crank axis is z0).
    B, C : array_like, shape (n, 3)
        Crank and rocker pins of the poses to draw (the first drawn darkest).
    axes : Axes3D, optional
        A 3-D axes; a new figure when None.
    axis_length : float, optional
        Half-length of the drawn joint axes.
    labels : bool, optional
        Label the pivots and the pins of the first pose.
    """
    if axes is None:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=(7.0, 6.0))
        axes = fig.add_subplot(projection="3d")
    A, D, z3 = (np.asarray(v, dtype=float) for v in (A, D, z3))
    B, C = np.atleast_2d(B), np.atleast_2d(C)
    O, OK = np.zeros(3), np.array([D[0], 0.0, 0.0])
    for centre, direction, name in ((A, np.array([0.0, 0.0, 1.0]), "$z_0$"), (D, z3, "$z_3$")):
        ends = np.array([centre - axis_length * direction, centre + axis_length * direction])
        axes.plot(*ends.T, "-.", color="gray", lw=1.0)
        axes.text(*ends[1], name, color="gray")
    axes.plot(*np.array([O, OK]).T, ":", color="gray", lw=1.0)        # common perpendicular x0
    axes.text(*OK, "$O_K$", color="gray")
    axes.text(*O, "$O$", color="gray")
    shades = np.linspace(0.0, 0.65, len(B))
    for b, c, g in zip(B, C, shades):
        colour = (g, g, g)
        axes.plot(*np.array([A, b]).T, "-", color=colour, lw=2.2)      # crank
        axes.plot(*np.array([b, c]).T, "-", color=colour, lw=1.4)      # coupler
        axes.plot(*np.array([D, c]).T, "-", color=colour, lw=2.2)      # rocker
        axes.plot(*np.array([b, c]).T, "o", color=colour, ms=3.5)
    if labels:
        for point, name in ((A, "A"), (D, "D"), (B[0], "B"), (C[0], "C")):
            axes.text(*point, f" {name}")
    axes.set_xlabel("$x_0$")
    axes.set_ylabel("$y_0$")
    axes.set_zlabel("$z_0$")
    everything = np.vstack([B, C, A[None], D[None], O[None]])
    centre = 0.5 * (everything.max(axis=0) + everything.min(axis=0))
    half = 0.5 * np.max(everything.max(axis=0) - everything.min(axis=0))
    for setter, mid in zip((axes.set_xlim, axes.set_ylim, axes.set_zlim), centre):
        setter(mid - half, mid + half)
    return axes


def rssr_output(phi01, curves, axes=None, *, ranges=()):
    """Rocker angle against crank angle, one curve per assembly mode.

    Parameters
    ----------
    phi01 : array_like, shape (n,)
        Crank angles, radians (drawn in degrees).
    curves : sequence of dict
        Keys ``label``, ``phi03`` (radians, NaN where not assembled) and optional ``style``.
    axes : Axes, optional
        A new figure when None.
    ranges : sequence of (float, float), optional
        Crank-angle intervals (radians) to shade, e.g. where the linkage assembles.
    """
    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(figsize=(7.0, 3.8))
    deg = np.degrees(np.asarray(phi01))
    for curve in curves:
        y = np.degrees(np.unwrap(np.nan_to_num(curve["phi03"])))
        y[np.isnan(curve["phi03"])] = np.nan
        axes.plot(deg, y, curve.get("style", "-"), color="black", lw=1.3, label=curve["label"])
    for start, end in ranges:
        for shift in (-360.0, 0.0, 360.0):
            axes.axvspan(np.degrees(start) + shift, np.degrees(end) + shift, color="tab:blue", alpha=0.08, lw=0)
    axes.set_xlim(deg[0], deg[-1])
    axes.set_xlabel(r"crank angle $\varphi_{01}$ (deg)")
    axes.set_ylabel(r"rocker angle $\varphi_{03}$ (deg)")
    axes.grid(True, lw=0.4, alpha=0.5)
    axes.legend(loc="best", frameon=False)
    return axes
