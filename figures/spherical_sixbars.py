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


ASSEMBLIES = ((1, 1), (1, -1), (-1, 1), (-1, -1))
ASSEMBLY_COLOURS = ("tab:red", "tab:blue", "tab:green", "tab:purple")


def all_assemblies(ax, make, theta, *, elev=30.0, azim=-40.0, title=None):
    """The coupler path of every assembly of both dyads on the sphere (the whole real curve);
    ``make(branches)`` builds the six-bar on the given branches."""
    sphere.globe(ax)
    for branches, colour in zip(ASSEMBLIES, ASSEMBLY_COLOURS):
        pose = make(branches).solve(theta)
        P = np.where(pose.valid[:, None], pose.points["P"], np.nan)
        ax.plot(*P.T, color=colour, lw=1.2, label=f"branches {branches}")
    sphere.finish(ax, elev=elev, azim=azim)
    if title:
        ax.set_title(title)
    return ax


def implicit_map(ax, make, theta, values, lon, lat, *, title=None):
    """The sign of the implicit curve's polynomial on a longitude-latitude grid, its zero
    contour (black) and the parametric points of every assembly (coloured dots) on top."""
    ax.contourf(np.degrees(lon), np.degrees(lat), np.sign(values), levels=[-1.5, 0, 1.5],
                colors=["#dde6f3", "#f6e3d3"])
    ax.contour(np.degrees(lon), np.degrees(lat), values, levels=[0.0], colors="black", linewidths=0.8)
    for branches, colour in zip(ASSEMBLIES, ASSEMBLY_COLOURS):
        pose = make(branches).solve(theta)
        P = pose.points["P"][pose.valid]
        ax.plot(np.degrees(np.arctan2(P[:, 1], P[:, 0])), np.degrees(np.arcsin(np.clip(P[:, 2], -1, 1))), ".",
                color=colour, ms=1.5)
    ax.set_xlim(np.degrees(lon.min()), np.degrees(lon.max()))
    ax.set_ylim(np.degrees(lat.min()), np.degrees(lat.max()))
    ax.set_xlabel("longitude (deg)")
    ax.set_ylabel("latitude (deg)")
    if title:
        ax.set_title(title)
    return ax
