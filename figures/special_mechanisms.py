"""Figures of the special mechanisms (``book/analysis/special-mechanisms.md``).

Plain plotting functions: each takes poses or arrays computed by ``mech`` and Matplotlib
axes (new ones when None) and returns the axes. A *panel* is a dict describing one
kinematic diagram (links, ground pivots, sliders, guides, paths); the ``*_panel``
helpers build panels from poses. Nothing is computed or drawn at import.
"""

import numpy as np

__all__ = [
    "draw_panel",
    "panel_grid",
    "fourbar_panel",
    "slider_crank_panel",
    "guide_bar_panel",
    "block_panel",
    "fixed_block_panel",
    "scotch_yoke_panel",
    "tangent_panel",
    "oldham_panel",
    "trammel_panel",
    "motion_grid",
    "trammel_centrodes",
    "oldham_orbit",
    "guide_bar_vs_crank_rocker",
]

LINK = dict(color="black", lw=2.0, solid_capstyle="round")


def _new_axes(ax, size=(5.0, 4.0)):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def _slider(ax, z, angle, size, colour="white"):
    from matplotlib.patches import Polygon

    w, h = size, 0.6 * size
    corners = np.array([-w + -h * 1j, w - h * 1j, w + h * 1j, -w + h * 1j]) / 2 * np.exp(1j * angle) + z
    ax.add_patch(Polygon(np.c_[corners.real, corners.imag], closed=True, fc=colour, ec="black", lw=1.2, zorder=3))


def _shade(ax, deg, start, length, colour="tab:blue"):
    """Shade the input-angle interval [start, start + length) (radians), modulo a turn."""
    start, length = np.degrees(start) % 360.0, np.degrees(length)
    for lo in (start - 360.0, start):
        left, right = max(lo, deg[0]), min(lo + length, deg[-1])
        if right > left:
            ax.axvspan(left, right, color=colour, alpha=0.08, lw=0)


def draw_panel(ax, panel, *, size=None):
    """Draw one kinematic diagram described by a panel dict.

    Keys (all optional but ``title``): ``links`` (list of point lists, drawn as
    polylines), ``ground`` (fixed pivots), ``joints`` (moving pins), ``sliders`` (list of
    ``(z, angle)``), ``guides`` (list of ``(z1, z2)`` lines), ``paths`` (arrays of complex,
    drawn thin), ``circles`` (list of ``(centre, radius)``), ``notes`` (list of
    ``(z, text)``).
    """
    pts = [z for link in panel.get("links", ()) for z in link] + list(panel.get("ground", ()))
    span = np.ptp(np.real(pts)) + np.ptp(np.imag(pts)) if pts else 1.0
    size = size or 0.09 * span
    for path in panel.get("paths", ()):
        path = np.asarray(path)
        ax.plot(path.real, path.imag, color="tab:blue", lw=0.9, alpha=0.8)
    for centre, radius in panel.get("circles", ()):
        t = np.linspace(0, 2 * np.pi, 241)
        z = centre + radius * np.exp(1j * t)
        ax.plot(z.real, z.imag, color="tab:orange", lw=1.0)
    for z1, z2 in panel.get("guides", ()):
        ax.plot([z1.real, z2.real], [z1.imag, z2.imag], color="grey", lw=1.0, ls="--")
    for link in panel.get("links", ()):
        link = np.asarray(link)
        ax.plot(link.real, link.imag, **LINK)
    for z, angle in panel.get("sliders", ()):
        _slider(ax, z, angle, size)
    for z in panel.get("joints", ()):
        ax.plot(z.real, z.imag, "o", ms=4, mfc="white", mec="black", zorder=4)
    for z in panel.get("ground", ()):
        ax.plot(z.real, z.imag, "^", ms=8, color="black", zorder=4)
    for z, text in panel.get("notes", ()):
        ax.annotate(text, (z.real, z.imag), xytext=(3, 4), textcoords="offset points", fontsize=7)
    ax.set_title(panel["title"], fontsize=8)
    ax.set_aspect("equal", adjustable="datalim")
    ax.margins(0.12)
    ax.set_xticks([])
    ax.set_yticks([])
    return ax


def panel_grid(panels, ncols, *, column_titles=None, cell=2.2):
    """Draw panels in a grid (row-major); None leaves a cell empty. Returns the axes."""
    import matplotlib.pyplot as plt

    nrows = -(-len(panels) // ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(cell * ncols, cell * nrows * 0.85), squeeze=False)
    for ax, panel in zip(axes.ravel(), list(panels) + [None] * (nrows * ncols - len(panels))):
        if panel is None:
            ax.axis("off")
        else:
            draw_panel(ax, panel)
    for ax, title in zip(axes[0], column_titles or ()):
        ax.annotate(title, (0.5, 1.28), xycoords="axes fraction", ha="center", fontsize=9, weight="bold")
    fig.tight_layout()
    return axes


def fourbar_panel(pose, d, title, *, frame_name="AD"):
    """A four-bar in one pose (`FourBar.solve` result, scalar) with pivots 0 and d."""
    B, C = complex(pose.B), complex(pose.C)
    return dict(title=title, links=[[0j, B, C, d + 0j]], ground=[0j, d + 0j], joints=[B, C],
                guides=[(0j, d + 0j)])


def slider_crank_panel(pose, title, *, reach=None):
    """A slider-crank in one pose (`SliderCrank.solve` result, scalar); guide y = e."""
    B, C = complex(pose.B), complex(pose.C)
    reach = reach or 1.3 * abs(C.real) + abs(B)
    return dict(title=title, links=[[0j, B, C]], ground=[0j], joints=[B], sliders=[(C, 0.0)],
                guides=[(-reach + 1j * C.imag, reach + 1j * C.imag)])


def guide_bar_panel(pose, d, title, *, length=None):
    """A guide-bar: crank 0 -> B, block at B sliding on the bar through the pivot d."""
    B, psi = complex(pose.B), float(pose.psi)
    length = length or 1.25 * (abs(B - d) + abs(B))
    end = d + length * np.exp(1j * psi)
    back = d - 0.25 * length * np.exp(1j * psi)
    return dict(title=title, links=[[0j, B], [back, end]], ground=[0j, d + 0j], joints=[B],
                sliders=[(B, psi)])


def block_panel(pose, d, title, *, rod=None):
    """An oscillating or turning block: crank 0 -> B, rod from B through the block at d."""
    B, psi = complex(pose.B), float(pose.psi)
    rod = rod or 1.3 * (abs(B - d) + abs(B))
    end = B - rod * np.exp(1j * psi)                    # the rod runs from B through D
    return dict(title=title, links=[[0j, B], [B, end]], ground=[0j], joints=[B],
                sliders=[(d + 0j, psi)], notes=[(d + 0j, "block")])


def fixed_block_panel(pose, title):
    """Fixed block: link C->B (a `SliderCrank` crank about the block C = 0) and rod B->A;
    A is on the guide rod that slides through the fixed block."""
    B, A = complex(pose.B), complex(pose.C)
    reach = abs(A) + abs(B)
    guide_end = A + 0.6 * reach * np.sign(A.real or 1.0)
    return dict(title=title, links=[[0j, B, A], [A - 1.2 * reach * np.sign(A.real or 1.0), guide_end]],
                ground=[0j], joints=[B, A], sliders=[(0j, 0.0)])


def scotch_yoke_panel(pose, a, title):
    """Sine mechanism: crank 0 -> B, yoke slot through B perpendicular to the x guide."""
    B, x = complex(pose.B), float(pose.x)
    return dict(title=title, links=[[0j, B], [x - 1.2j * a, x + 1.2j * a], [x + 0j, x + 2.2 * a]],
                ground=[0j], joints=[B], sliders=[(B, np.pi / 2)], guides=[(-2.5 * a + 0j, 3.4 * a + 0j)])


def tangent_panel(pose, theta, L, title):
    """Tangent mechanism: bar through the pivot 0 at angle theta, slider S on x = L."""
    S = complex(pose.S)
    tip = 1.2 * S
    return dict(title=title, links=[[0j, tip]], ground=[0j], sliders=[(S, float(theta))],
                guides=[(L - 0.3j * L, L + 1j * (S.imag + 0.5 * L))])


def oldham_panel(pose, e0, title):
    """Oldham coupling: shaft tongues through O1 = 0 and O3 = e0, cross at S."""
    S, t = complex(pose.S), float(pose.phi_slider)
    u = np.exp(1j * t)
    r = 1.5 * e0
    return dict(title=title, links=[[-r * u, r * u], [e0 - r * 1j * u, e0 + r * 1j * u]],
                ground=[0j, e0 + 0j], sliders=[(S, t)], circles=[(e0 / 2, e0 / 2)])


def trammel_panel(pose, L, title, *, path=None):
    """Elliptic trammel: crank O -> M, coupler B -> C, sliders on the two axes."""
    B, C, M, P = (complex(getattr(pose, k)) for k in ("B", "C", "M", "P"))
    links = [[0j, M], [B, C]] + ([[B, P]] if abs(P - B) > 0 and abs(P - C) > 0 else [])
    return dict(title=title, links=links, ground=[0j], joints=[M, P], sliders=[(B, 0.0), (C, np.pi / 2)],
                guides=[(-1.1 * L + 0j, 1.1 * L + 0j), (-1.1j * L, 1.1j * L)],
                paths=[path] if path is not None else [])


def motion_grid(theta, columns, *, shade=None):
    """Motion diagrams: one column per mechanism, rows = displacement, velocity, acceleration.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Input angles, radians (drawn in degrees).
    columns : sequence of dict
        Keys ``title``, ``rows`` (three arrays of shape (n,) or lists of (array, label)
        pairs) and ``ylabels`` (three strings).
    shade : sequence of (start, length) or None, optional
        Per column, an input-angle interval (radians) to shade.
    """
    import matplotlib.pyplot as plt

    deg = np.degrees(np.asarray(theta))
    fig, axes = plt.subplots(3, len(columns), figsize=(3.2 * len(columns), 6.4), sharex=True, squeeze=False)
    for j, col in enumerate(columns):
        for i in range(3):
            ax = axes[i, j]
            curves = col["rows"][i]
            curves = curves if isinstance(curves, list) else [(curves, None)]
            for k, (y, label) in enumerate(curves):
                ax.plot(deg, y, ("-", "--", ":")[k % 3], color="black", lw=1.1, label=label)
            if any(label for _, label in curves):
                ax.legend(fontsize=7, loc="best")
            if shade is not None and shade[j] is not None:
                _shade(ax, deg, *shade[j])
            ax.axhline(0.0, color="grey", lw=0.5)
            ax.set_ylabel(col["ylabels"][i], fontsize=8)
            ax.grid(alpha=0.3)
            ax.tick_params(labelsize=7)
        axes[0, j].set_title(col["title"], fontsize=9)
        axes[-1, j].set_xlabel(r"input angle $\theta$ (degrees)", fontsize=8)
        axes[-1, j].set_xticks(np.arange(deg[0], deg[-1] + 1, 90.0))
    fig.tight_layout()
    return axes


def trammel_centrodes(L, path_pose, pose, ax=None):
    """The trammel in one pose with the ellipse of its coupler point, the fixed centrode
    (radius L about O), the moving centrode (diameter L about M, the rolling circle of
    Fig. 2-60) and the instant centre I; `path_pose` is a solve over a full turn."""
    ax = _new_axes(ax, (5.5, 5.5))
    t = np.linspace(0, 2 * np.pi, 361)
    M, I = complex(pose.M), complex(pose.I)
    fixed = L * np.exp(1j * t)
    moving = M + L / 2 * np.exp(1j * t)
    ax.plot(fixed.real, fixed.imag, color="tab:red", lw=1.2, label="fixed centrode (radius L about O)")
    ax.plot(moving.real, moving.imag, color="tab:green", lw=1.2,
            label="moving centrode = rolling circle (diameter L)")
    P = np.asarray(path_pose.P)
    ax.plot(P.real, P.imag, color="tab:blue", lw=1.0, label="path of P (ellipse)")
    Mp = np.asarray(path_pose.M)
    ax.plot(Mp.real, Mp.imag, color="tab:blue", lw=0.8, ls=":", label="path of M (circle)")
    draw_panel(ax, trammel_panel(pose, L, ""))
    ax.set_aspect("equal", adjustable="box")
    ax.plot([I.real, complex(pose.B).real], [I.imag, complex(pose.B).imag], color="grey", lw=0.7)
    ax.plot([I.real, complex(pose.C).real], [I.imag, complex(pose.C).imag], color="grey", lw=0.7)
    ax.plot(I.real, I.imag, "o", color="tab:red", ms=6)
    for z, name in ((0j, "O"), (M, "M"), (I, "I"), (complex(pose.B), "B"), (complex(pose.C), "C"),
                    (complex(pose.P), "P")):
        ax.annotate(name, (z.real, z.imag), xytext=(4, -10), textcoords="offset points", fontsize=9)
    ax.legend(fontsize=7, loc="lower left")
    ax.set_xlim(-1.15 * L, 1.15 * L)
    ax.set_ylim(-1.15 * L, 1.15 * L)
    return ax


def oldham_orbit(e0, poses, ax=None):
    """Successive poses of an Oldham cross-slider: the centre S on its circle of diameter
    e0 and the slider's orientation (a cross), labelled with the shaft angle."""
    ax = _new_axes(ax, (5.5, 5.0))
    t = np.linspace(0, 2 * np.pi, 361)
    circle = e0 / 2 + e0 / 2 * np.exp(1j * t)
    ax.plot(circle.real, circle.imag, color="tab:blue", lw=1.0)
    arm = 0.18 * e0
    for pose in poses:
        S, th = complex(pose.S), float(pose.phi_slider)
        u = arm * np.exp(1j * th)
        for v in (u, 1j * u):
            ax.plot([S.real - v.real, S.real + v.real], [S.imag - v.imag, S.imag + v.imag], color="black", lw=1.6)
        ax.plot([0.0, S.real], [0.0, S.imag], color="grey", lw=0.6, ls="--")
        ax.annotate(f"{np.degrees(th):.0f}°", (S.real, S.imag), xytext=(5, 5), textcoords="offset points", fontsize=7)
    ax.plot([0.0, e0], [0.0, 0.0], "k^", ms=9)
    ax.annotate("$O_1$", (0.0, 0.0), xytext=(-14, -14), textcoords="offset points")
    ax.annotate("$O_3$", (e0, 0.0), xytext=(4, -14), textcoords="offset points")
    ax.set_aspect("equal")
    ax.margins(0.15)
    ax.set_title("cross-slider: centre on the circle of diameter $e_0$, orientation = shaft angle", fontsize=9)
    return ax


def guide_bar_vs_crank_rocker(theta, curves, axes=None, *, shade=None):
    """Fig. 2-59: output angular velocity and acceleration against the crank angle.

    `curves` is a sequence of dicts with ``label``, ``omega`` and ``alpha`` (arrays over
    `theta`) and an optional ``style``; `shade` lists (start, length, colour) intervals.
    """
    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(2, 1, figsize=(7.0, 5.5), sharex=True)
    deg = np.degrees(np.asarray(theta))
    for ax, key, ylabel in zip(axes, ("omega", "alpha"),
                               (r"$\omega_{out}/\omega$", r"$\alpha_{out}/\omega^2$")):
        for curve in curves:
            ax.plot(deg, curve[key], curve.get("style", "-"), color="black", lw=1.2, label=curve["label"])
        for start, length, colour in shade or ():
            _shade(ax, deg, start, length, colour)
        ax.axhline(0.0, color="grey", lw=0.5)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel(r"crank angle $\theta$ (degrees)")
    axes[-1].set_xticks(np.arange(deg[0], deg[-1] + 1, 60.0))
    axes[-1].set_xlim(deg[0], deg[-1])
    return axes
