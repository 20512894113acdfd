"""A coupler-curve atlas page like Fig. 2-30 (``book/analysis/coupler-curves.md``).

Plain plotting functions: they take dashes computed by ``mech`` (``coupler_dashes``) and
draw them; nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["atlas_page", "dashed_curve"]


def dashed_curve(ax, points, valid, *, gap=0.35, colour="tab:blue", width=1.2):
    """Draw one curve as dashes, one per step, each leaving `gap` of its step blank."""
    from matplotlib.collections import LineCollection

    points = np.asarray(points)
    start = points[:-1]
    stop = start + (1.0 - gap) * np.diff(points)
    segs = np.stack([np.stack([start.real, start.imag], -1), np.stack([stop.real, stop.imag], -1)], -2)
    ax.add_collection(LineCollection(segs[np.asarray(valid)], colors=colour, linewidths=width))


def atlas_page(dashes, B, C, d, *, gap=0.35, figure=None):
    """One panel per lattice point: the linkage, the coupler triangle and the dashed curve.

    Parameters
    ----------
    dashes : CouplerDashes
        From ``coupler_dashes`` with a 2-D lattice of coupler points (rows, columns).
    B, C : complex
        Crank pin and rocker pin in the pose drawn.
    d : float
        Ground length: pivots A = 0 and D = d.
    gap : float, optional
        Fraction of each step left blank, so that the dashes can be counted.

    Returns
    -------
    ndarray of Axes, shape (rows, columns)
    """
    import matplotlib.pyplot as plt

    points = np.asarray(dashes.points)
    rows, cols = points.shape[:2]
    fig = figure or plt.figure(figsize=(2.6 * cols, 2.4 * rows))
    axes = fig.subplots(rows, cols, sharex=True, sharey=True, squeeze=False)
    unit = (C - B) / abs(C - B)
    for (r, k), ax in np.ndenumerate(axes):
        w = complex(dashes.coupler[r, k])
        M = B + w * unit
        ax.fill([B.real, C.real, M.real], [B.imag, C.imag, M.imag], color="0.88", zorder=0)
        ax.plot([0.0, B.real, C.real, d], [0.0, B.imag, C.imag, 0.0], "-", color="0.45", lw=1.2)
        ax.plot([0.0, d], [0.0, 0.0], "^", color="0.3", ms=6)
        dashed_curve(ax, points[r, k], dashes.valid[r, k], gap=gap)
        ax.plot(M.real, M.imag, "o", mfc="white", mec="tab:red", ms=5, zorder=3)
        ax.set_title(f"p = {w.real:g}, q = {w.imag:g}", fontsize=8)
        ax.set_aspect("equal")
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.2)
    axes[0, 0].autoscale_view()
    fig.tight_layout()
    return axes
