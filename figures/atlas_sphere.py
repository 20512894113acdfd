"""Figures of the spherical atlas page (``book/atlas/sphere.md``): matches drawn on the sphere.

Nothing is computed or drawn at import.
"""

import numpy as np

from figures import sphere

__all__ = ["facing", "draw_linkage", "matches_on_sphere"]

_COLOURS = ("tab:red", "tab:blue", "tab:green", "tab:purple", "tab:orange")


def facing(points):
    """(elev, azim) in degrees that turn the view towards the mean direction of `points`."""
    m = np.mean(np.asarray(points, dtype=float), axis=0)
    m /= np.linalg.norm(m)
    return float(np.degrees(np.arcsin(np.clip(m[2], -1, 1)))), float(np.degrees(np.arctan2(m[1], m[0])))


def draw_linkage(ax, fourbar, theta, *, colour="black"):
    """Draw a placed `SphericalFourBar` at the input angle `theta`: its links as great-circle
    arcs, the coupler triangle B-C-P, and the ground pivots A, D."""
    pose = fourbar.solve(theta)
    frame = np.eye(3) if fourbar.frame is None else fourbar.frame
    A = frame @ np.array([0.0, 0.0, 1.0])
    D = frame @ np.array([np.sin(fourbar.d), 0.0, np.cos(fourbar.d)])
    for p, q in ((A, pose.B), (pose.B, pose.C), (pose.C, D)):
        sphere.arc(ax, p, q, color=colour, lw=1.8)
    for p, q in ((pose.B, pose.P), (pose.C, pose.P)):
        sphere.arc(ax, p, q, color=colour, lw=0.8, ls="--")
    for p, label in ((A, "A"), (D, "D"), (pose.B, "B"), (pose.C, "C"), (pose.P, "P")):
        sphere.point(ax, p, label, colour=colour)
    return ax


def matches_on_sphere(target, matches, *, ax=None, theta=0.6, title=None):
    """The target points and the turned curves of `matches` on a globe, the best linkage drawn."""
    import matplotlib.pyplot as plt

    target = np.asarray(target, dtype=float)
    if ax is None:
        ax = plt.figure(figsize=(6.0, 6.0)).add_subplot(projection="3d")
    sphere.globe(ax)
    ax.scatter(*target[::3].T, s=6, color="black", depthshade=False, label="target")
    for m, colour in zip(matches, _COLOURS):
        c = np.vstack([m.curve, m.curve[:1]]) if m.arc is None else m.curve
        ax.plot(*c.T, color=colour, lw=1.4, label=f"#{m.rank}: row {m.index} ({m.kind}), "
                                                   f"error {100 * m.relative_error:.2f} %")
    best = matches[0]
    lo, hi = best.theta_range
    draw_linkage(ax, best.placed, theta if best.full_turn else 0.5 * (lo + hi), colour=_COLOURS[0])
    elev, azim = facing(target)
    sphere.finish(ax, elev=elev, azim=azim)
    ax.legend(loc="lower center", fontsize=7, frameon=False)
    if title:
        ax.set_title(title, fontsize=10)
    return ax
