"""Figures of ``book/spherical/coupler-curve.md``: the eighth-order coupler curve on the
sphere with its antipodal branch, and the implicit curve in longitude and latitude.

Every number comes from ``mech`` (``SphericalFourBar.solve`` for the parametric curve,
``coupler_octic`` / ``CouplerOctic.lonlat`` for the implicit one). Nothing runs at import.
"""

import numpy as np

from figures import sphere

__all__ = ["curve_views", "lonlat_map"]


def _branches(linkage_cls, params, n=1441):
    from mech.spherical import ground_frame

    curves = []
    for branch in (1, -1):
        m = linkage_cls(*params[3:7], branch=branch, coupler=tuple(params[7:]), frame=ground_frame(*params[:3]))
        curves.append(m.coupler_curve(n)[1])
    return m, curves


def curve_views(params, views=((25.0, 35.0), (25.0, 215.0))):
    """The coupler curve (both assembly branches), its antipodal image (dashed), the linkage
    at one pose, from several directions. Returns the figure."""
    import matplotlib.pyplot as plt

    from mech.spherical import SphericalFourBar

    m, curves = _branches(SphericalFourBar, params)
    pose = m.solve(1.0)
    fig = plt.figure(figsize=(5.0 * len(views), 5.0))
    for k, (elev, azim) in enumerate(views):
        ax = fig.add_subplot(1, len(views), k + 1, projection="3d")
        sphere.globe(ax)
        for curve, colour in zip(curves, ("tab:blue", "tab:green")):
            ax.plot(*curve.T, color=colour, lw=1.6)
            ax.plot(*(-curve).T, color=colour, lw=1.0, ls="--")
        for p, q in ((m.A, pose.B), (pose.B, pose.C), (pose.C, m.D)):
            sphere.arc(ax, p, q, color="black", lw=1.5)
        sphere.arc(ax, m.A, m.D, color="0.3", lw=2.5)
        sphere.arc(ax, pose.B, pose.P, color="tab:red", lw=1.0)
        sphere.arc(ax, pose.C, pose.P, color="tab:red", lw=1.0)
        for p, label in ((m.A, "A"), (m.D, "D"), (pose.B, "B"), (pose.C, "C"), (pose.P, "P")):
            sphere.point(ax, p, label)
        sphere.finish(ax, elev=elev, azim=azim)
        ax.set_title(f"view from elevation {elev:.0f}°, azimuth {azim:.0f}°", fontsize=9)
    return fig


def lonlat_map(params, n=361):
    """Sign of the quartic Q over longitude and latitude, its zero contour (the implicit
    curve), the parametric points on top, and the antipodal curve (Q(-x) = 0)."""
    import matplotlib.pyplot as plt

    from mech.spherical import SphericalFourBar, coupler_quartic, to_xyz

    m, curves = _branches(SphericalFourBar, params, n=181)
    lon, lat = np.meshgrid(np.linspace(-np.pi, np.pi, 2 * n), np.linspace(-np.pi / 2, np.pi / 2, n))
    x = to_xyz(lon, lat)
    q_plus = coupler_quartic(params, x)[0]
    q_minus = coupler_quartic(params, -x)[0]
    fig, ax = plt.subplots(figsize=(9.0, 4.5))
    ax.contourf(np.degrees(lon), np.degrees(lat), np.sign(q_plus), levels=[-1.5, 0, 1.5],
                colors=["#dde8f5", "#f7efe0"])
    ax.contour(np.degrees(lon), np.degrees(lat), q_plus, levels=[0.0], colors="tab:blue", linewidths=1.2)
    ax.contour(np.degrees(lon), np.degrees(lat), q_minus, levels=[0.0], colors="0.4", linewidths=0.9,
               linestyles="--")
    for curve in curves:
        ok = np.all(np.isfinite(curve), axis=-1)
        c = curve[ok][::6]
        ax.plot(np.degrees(np.arctan2(c[:, 1], c[:, 0])), np.degrees(np.arcsin(np.clip(c[:, 2], -1, 1))),
                ".", color="tab:red", ms=2.5)
    ax.set_xlabel("longitude θ (degrees)")
    ax.set_ylabel("latitude φ (degrees)")
    ax.set_aspect("equal")
    return fig
