"""Figures of ``book/spherical/guidance.md``: the Burmester cubics of four orientations on
the sphere, and a designed four-bar drawn in its five orientations. Nothing runs at import."""

import numpy as np

from figures import sphere

__all__ = ["cubics", "fourbar_positions"]


def _polyline(ax, pts, **style):
    """Draw points (m, 3) joined in order, broken where consecutive points are far apart."""
    pts = np.asarray(pts, dtype=float)
    jumps = np.linalg.norm(np.diff(pts, axis=0), axis=1) > 0.15
    start = 0
    for stop in list(np.flatnonzero(jumps) + 1) + [len(pts)]:
        seg = pts[start:stop]
        if len(seg) > 1:
            ax.plot(seg[:, 0], seg[:, 1], seg[:, 2], **style)
        start = stop
    return ax


def _ordered(points):
    """Order scattered curve points by a greedy nearest-neighbour walk (for a line plot)."""
    pts = list(np.asarray(points, dtype=float))
    if not pts:
        return np.empty((0, 3))
    out = [pts.pop(0)]
    while pts:
        d = [np.linalg.norm(p - out[-1]) for p in pts]
        out.append(pts.pop(int(np.argmin(d))))
    return np.array(out)


def cubics(curve, poles=(), ax=None, *, elev=30.0, azim=-50.0, title=None):
    """Draw the circle-point curve (blue) and centre-point curve (red) of a
    `SphericalBurmesterCurve` on the globe, each with its antipodal half dashed, and
    mark `poles` (a sequence of (label, unit vector))."""
    ax = sphere.globe(ax)
    for field, colour in (("moving_pivot", "tab:blue"), ("centre_point", "tab:red")):
        pts = getattr(curve, field)[curve.valid]
        for sign, ls in ((1.0, "-"), (-1.0, ":")):
            _polyline(ax, _ordered(sign * pts), color=colour, lw=1.2, ls=ls)
    for label, p in poles:
        sphere.point(ax, p, label, colour="black", size=10)
    if title:
        ax.set_title(title, fontsize=10)
    return sphere.finish(ax, elev=elev, azim=azim)


def fourbar_positions(design, R, ax=None, *, elev=30.0, azim=-50.0, title=None, body=None, limit=1.05):
    """Draw a `SphericalGuidanceFourBar` in its orientations: ground AD black, crank AB blue,
    coupler BC grey, output DC red; the first orientation bold. `body` (unit vectors, body
    coordinates) is a shape drawn with the coupler in every orientation (green)."""
    ax = sphere.globe(ax)
    pose = design.linkage.solve(design.theta_input)
    A, D = design.linkage.A, design.linkage.D
    sphere.arc(ax, A, D, color="black", lw=2.5)
    for i in range(len(design.theta_input)):
        lw = 2.2 if i == 0 else 1.0
        sphere.arc(ax, A, pose.B[i], color="tab:blue", lw=lw)
        sphere.arc(ax, pose.B[i], pose.C[i], color="0.45", lw=lw)
        sphere.arc(ax, D, pose.C[i], color="tab:red", lw=lw)
        if body is not None:
            shape = np.asarray(body) @ R[i].T
            for p, q in zip(shape, np.roll(shape, -1, axis=0)):
                sphere.arc(ax, p, q, color="tab:green", lw=0.9)
    sphere.point(ax, A, "A")
    sphere.point(ax, D, "D")
    if title:
        ax.set_title(title, fontsize=10)
    return sphere.finish(ax, elev=elev, azim=azim, limit=limit)
