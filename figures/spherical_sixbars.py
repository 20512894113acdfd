"""Figures of the spherical six-bars (book page spherical/six-bars)."""

import numpy as np

from figures import sphere

LINK_COLOURS = {"ground": "black", "AB": "tab:blue", "BC": "tab:orange", "DC": "tab:green",
                "EG": "tab:red", "FG": "tab:purple"}


def link_arcs(linkage):
    """Every pair of points of every link, as (link, p, q): a ternary link is a triangle."""
    out = []
    for link, names in linkage.members.items():
        for i, p in enumerate(names):
            for q in names[i + 1:]:
                out.append((link, p, q))
    return out


def draw(ax, linkage, theta, *, curve_theta=None, elev=30.0, azim=-40.0, title=None):
    """Draw `linkage` on the sphere at input `theta`, with the path of P over `curve_theta`."""
    sphere.globe(ax)
    pose = linkage.solve(theta)
    P = {k: np.asarray(v, dtype=float) for k, v in pose.points.items()}
    for link, p, q in link_arcs(linkage):
        sphere.arc(ax, P[p], P[q], color=LINK_COLOURS.get(link, "0.3"), lw=2.4 if link != "ground" else 1.2,
                   ls="-" if link != "ground" else "--")
    if curve_theta is not None:
        path = linkage.solve(curve_theta).points["P"]
        ax.plot(*path.T, color="tab:red", lw=1.0, alpha=0.8)
    for name, v in P.items():
        sphere.point(ax, v, name, colour="black" if name in linkage.members["ground"] else "0.2", size=10)
    sphere.finish(ax, elev=elev, azim=azim)
    if title:
        ax.set_title(title)
    return ax
