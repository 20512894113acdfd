"""Figures of ``book/spherical/coupler-atlas.md``: a grid of spherical coupler curves
(small multiples) over the arcs and the coupler point.

Every curve comes from ``mech`` (``SphericalFourBar.coupler_curve`` on each assembly
branch) and every label from ``mech.spherical.classify``. Nothing runs at import.
"""

import numpy as np

__all__ = ["BRANCH_COLOURS", "curve_grid", "panel_curves", "view_basis"]

#: colours of the assembly branches +1 and -1
BRANCH_COLOURS = {1: "tab:blue", -1: "tab:orange"}


def panel_curves(arcs, coupler, *, n=721):
    """The linkage of one panel and its coupler curve on each assembly branch.

    Returns ``(linkage, {branch: P})`` with ``P`` of shape (n', 3) from
    `SphericalFourBar.coupler_curve` (NaN rows between the intervals where a branch does not
    assemble).
    """
    from mech.spherical import SphericalFourBar

    curves = {}
    for branch in (1, -1):
        linkage = SphericalFourBar(*arcs, branch=branch, coupler=tuple(coupler))
        curves[branch] = linkage.coupler_curve(n)[1]
    return linkage, curves


def view_basis(points, up):
    """An orthonormal basis ``(e1, e2, v)`` looking at the sphere along ``-v`` from outside:
    ``v`` is the normalised mean of the finite `points` (so they face the reader) and ``e2``
    the direction of `up` across the screen."""
    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    v = pts.mean(axis=0)
    v = v / np.linalg.norm(v)
    e2 = np.asarray(up, dtype=float) - (np.asarray(up, dtype=float) @ v) * v
    if np.linalg.norm(e2) < 1e-9:
        e2 = np.cross(v, [1.0, 0.0, 0.0]) if abs(v[0]) < 0.9 else np.cross(v, [0.0, 1.0, 0.0])
    e2 = e2 / np.linalg.norm(e2)
    return np.cross(e2, v), e2, v


def _draw(ax, xyz, basis, **style):
    """Orthographic projection: the near side solid, the far side faint."""
    e1, e2, v = basis
    xyz = np.asarray(xyz, dtype=float)
    near = xyz @ v >= 0.0
    u, w = xyz @ e1, xyz @ e2
    ax.plot(np.where(near, u, np.nan), np.where(near, w, np.nan), **style)
    faint = dict(style, alpha=0.25, lw=0.6)
    ax.plot(np.where(near, np.nan, u), np.where(near, np.nan, w), **faint)


def curve_grid(rows, couplers, *, n=721, size=2.1):
    """A grid of coupler curves on the sphere: one row per set of arcs, one column per
    coupler point.

    Parameters
    ----------
    rows : sequence of (a, b, c, d)
        Arcs of each row, radians.
    couplers : sequence of (r, gamma)
        Coupler point of each column (`SphericalFourBar`'s ``coupler``).
    n : int
        Input angles per branch.
    size : float
        Width and height of one panel, inches.

    Returns
    -------
    matplotlib.figure.Figure
        Each panel shows the sphere seen from the side of the linkage (orthographic
        projection, the far side faint), the ground arc AD, and the curve of each assembly
        branch in the colours of `BRANCH_COLOURS`; it is labelled with its type (from
        `mech.spherical.classify`), its arcs and its coupler point in degrees.
    """
    import matplotlib.pyplot as plt

    from figures import sphere
    from mech.spherical import classify

    fig, axes = plt.subplots(len(rows), len(couplers), figsize=(size * len(couplers), size * len(rows)),
                             squeeze=False)
    t = np.linspace(0.0, 2 * np.pi, 181)
    for i, arcs in enumerate(rows):
        kinds = classify(*arcs)
        kind = kinds.kind + (", change point" if kinds.change_point else "")
        panels = [panel_curves(arcs, coupler, n=n) for coupler in couplers]
        linkage = panels[0][0]
        # one view per row, with A above D, so that the columns compare directly
        basis = view_basis(np.vstack([linkage.A, linkage.D, *(P for _, c in panels for P in c.values())]),
                           linkage.A - linkage.D)
        for j, (coupler, (linkage, curves)) in enumerate(zip(couplers, panels)):
            ax = axes[i, j]
            ax.plot(np.cos(t), np.sin(t), color="0.6", lw=0.6)
            _draw(ax, sphere.great_arc(linkage.A, linkage.D), basis, color="0.35", lw=2.0)
            for p in (linkage.A, linkage.D):
                _draw(ax, p[None, :], basis, color="black", marker="o", ms=2.5, ls="none")
            for branch, P in curves.items():
                _draw(ax, P, basis, color=BRANCH_COLOURS[branch], lw=1.1)
            degrees = ", ".join(f"{np.degrees(x):.0f}" for x in arcs)
            ax.set_title(f"{kind}\na, b, c, d = {degrees}°\nr, γ = {np.degrees(coupler[0]):.0f}°, "
                         f"{np.degrees(coupler[1]):.0f}°", fontsize=7, pad=2)
            ax.set_xlim(-1.05, 1.05)
            ax.set_ylim(-1.05, 1.05)
            ax.set_aspect("equal")
            ax.axis("off")
    fig.tight_layout(pad=0.3, h_pad=0.6, w_pad=0.2)
    return fig
