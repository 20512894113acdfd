"""Drawing on the unit sphere, shared by the figures of ``book/spherical/``.

Plain functions on Matplotlib 3-D axes (new ones when ``ax`` is None); points are unit
3-vectors. Nothing is computed or drawn at import.
"""

import numpy as np

from figures.spatial import axes3d

__all__ = ["axes3d", "globe", "great_arc", "arc", "small_circle", "circle", "point", "finish"]


def globe(ax=None, *, colour="0.6", alpha=0.06, meridians=12, parallels=6, resolution=73):
    """Draw a translucent unit sphere with a light grid of meridians and parallels."""
    ax = axes3d() if ax is None else ax
    u = np.linspace(0.0, 2 * np.pi, resolution)
    v = np.linspace(0.0, np.pi, resolution // 2 + 1)
    ax.plot_surface(np.outer(np.cos(u), np.sin(v)), np.outer(np.sin(u), np.sin(v)),
                    np.outer(np.ones_like(u), np.cos(v)), color=colour, alpha=alpha, linewidth=0)
    t = np.linspace(0.0, 2 * np.pi, resolution)
    for lon in np.linspace(0.0, np.pi, meridians // 2, endpoint=False):
        ax.plot(np.cos(lon) * np.cos(t), np.sin(lon) * np.cos(t), np.sin(t), color=colour, lw=0.3)
    for lat in np.linspace(-np.pi / 2, np.pi / 2, parallels + 1)[1:-1]:
        ax.plot(np.cos(lat) * np.cos(t), np.cos(lat) * np.sin(t), np.full_like(t, np.sin(lat)),
                color=colour, lw=0.3)
    return ax


def great_arc(p, q, n=64):
    """Points of the shorter great-circle arc from unit vector `p` to `q`, shape (n, 3)."""
    p, q = np.asarray(p, dtype=float), np.asarray(q, dtype=float)
    angle = np.arctan2(np.linalg.norm(np.cross(p, q)), np.dot(p, q))
    s = np.linspace(0.0, 1.0, n)[:, None]
    if angle < 1e-12:
        return np.repeat(p[None, :], n, axis=0)
    return (np.sin((1 - s) * angle) * p + np.sin(s * angle) * q) / np.sin(angle)


def arc(ax, p, q, **style):
    """Draw the great-circle arc from `p` to `q` (a link of a spherical linkage)."""
    pts = great_arc(p, q)
    style.setdefault("lw", 2.0)
    return ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], **style)


def small_circle(pole, radius, n=181):
    """Points of the circle at arc `radius` about the unit vector `pole`, shape (n, 3)."""
    pole = np.asarray(pole, dtype=float)
    pole = pole / np.linalg.norm(pole)
    helper = np.array([1.0, 0.0, 0.0]) if abs(pole[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(pole, helper)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(pole, e1)
    t = np.linspace(0.0, 2 * np.pi, n)[:, None]
    return np.cos(radius) * pole + np.sin(radius) * (np.cos(t) * e1 + np.sin(t) * e2)


def circle(ax, pole, radius, **style):
    """Draw the circle at arc `radius` about `pole` (radius pi/2 is the great circle)."""
    pts = small_circle(pole, radius)
    style.setdefault("lw", 0.8)
    return ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], **style)


def point(ax, p, label=None, *, colour="black", offset=1.08, size=14):
    """Mark the unit vector `p`, with an optional text label just outside the sphere."""
    p = np.asarray(p, dtype=float)
    ax.scatter(*p, color=colour, s=size, depthshade=False)
    if label:
        ax.text(*(offset * p), label, fontsize=10, color=colour)
    return ax


def finish(ax, *, elev=25.0, azim=35.0, limit=1.05, axes_off=True):
    """Equal scales on [-limit, limit]^3, a view direction, and optionally no axes box."""
    for setter in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        setter(-limit, limit)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=elev, azim=azim)
    if axes_off:
        ax.set_axis_off()
    return ax
