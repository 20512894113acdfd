"""Figures of limit positions (``book/kinematics/examples.md``, Figs 2-37, 2-39, 2-40).

Plain plotting functions: each takes points computed by ``mech`` (complex numbers
``x + 1j*y``) and a Matplotlib ``Axes`` (a new figure when ``ax`` is None), draws, and
returns the axes. Nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["fourbar_limit_positions", "guide_bar_limit_positions", "slider_crank_limit_positions"]

_BRANCH_COLOURS = ("tab:blue", "tab:orange")


def _axes(ax, size):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def _label(ax, z, text, offset=(4, 4), **kw):
    ax.annotate(text, (z.real, z.imag), textcoords="offset points", xytext=offset, fontsize=9, **kw)


def _angle_arc(ax, centre, radius, start, stop, text, colour, *, scale=1.18, fontsize=9, short=True):
    """An arc from angle ``start`` to ``stop`` (radians) with a label at ``scale * radius``.

    The short way round by default; ``short=False`` sweeps counter-clockwise from ``start``
    to ``stop``. Shared by the limit-position, quick-return and optimisation figures.
    """
    sweep = (stop - start + np.pi) % (2 * np.pi) - np.pi if short else stop - start
    t = start + np.linspace(0.0, sweep, 40)
    arc = centre + radius * np.exp(1j * t)
    ax.plot(arc.real, arc.imag, color=colour, lw=0.9)
    mid = centre + scale * radius * np.exp(1j * (start + sweep / 2))
    if text:
        ax.text(mid.real, mid.imag, text, color=colour, fontsize=fontsize, ha="center", va="center",
                bbox={"facecolor": "white", "edgecolor": "none", "pad": 0.5, "alpha": 0.8})


def _finish(ax):
    ax.margins(0.08)
    ax.set_aspect("equal")
    ax.grid(alpha=0.25)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.legend(loc="lower left", fontsize=8)
    return ax


def fourbar_limit_positions(d, branches, ax=None):
    """Draw a crank-rocker in its two limit positions, for each assembly mode (Fig. 2-37).

    Parameters
    ----------
    d : float
        Ground length AD (A = 0, D = d).
    branches : sequence of dict
        One entry per assembly mode with keys ``label`` (str), ``B`` and ``C`` (complex,
        shape (2,): extended then folded limit position), and optional ``swing`` and
        ``extreme_angle`` (str labels drawn as arcs at D and A).
    """
    ax = _axes(ax, (7.0, 6.0))
    a = abs(branches[0]["B"][0])
    t = np.linspace(0.0, 2.0 * np.pi, 241)
    ax.plot(a * np.cos(t), a * np.sin(t), ":", color="0.5", lw=1.0)
    ax.plot([0.0, d], [0.0, 0.0], color="black", lw=3.0, solid_capstyle="round")
    for entry, colour in zip(branches, _BRANCH_COLOURS):
        B, C = np.asarray(entry["B"]), np.asarray(entry["C"])
        c = abs(C[0] - d)
        psi = np.angle(C - d)
        arc = d + c * np.exp(1j * np.linspace(psi[0], psi[1], 60))
        ax.plot(arc.real, arc.imag, "-", color=colour, lw=4.0, alpha=0.18)
        for i, (style, name) in enumerate(((("-", "extended")), ("--", "folded"))):
            pts = np.array([0.0, B[i], C[i], d])
            ax.plot(pts.real, pts.imag, style, marker="o", ms=4, color=colour, lw=1.4,
                    label=f"{entry['label']}, {name}")
            # the line A-C that carries crank and coupler at a limit position
            ax.plot([0.0, C[i].real], [0.0, C[i].imag], ":", color=colour, lw=0.8)
            _label(ax, C[i], "C" + "′" * (i + 1), color=colour)
            _label(ax, B[i], "B" + "′" * (i + 1), offset=(-14, 4), color=colour)
        if "swing" in entry:
            _angle_arc(ax, d, 0.35 * c, psi[0], psi[1], entry["swing"], colour)
        if "extreme_angle" in entry:
            # the angle C'AC'' between the two lines that carry crank and coupler
            _angle_arc(ax, 0j, 0.6 * abs(C[1]), np.angle(C[0]), np.angle(C[1]),
                       entry["extreme_angle"], colour)
    _label(ax, 0j, "A", offset=(-12, -12))
    _label(ax, complex(d), "D", offset=(4, -12))
    return _finish(ax)


def slider_crank_limit_positions(e, B, C, ax=None, *, stroke_label="H", angle_label=r"$\theta$"):
    """Draw an offset slider-crank in its two limit positions (Fig. 2-40).

    Parameters
    ----------
    e : float
        Offset: the slider pin moves on the line y = e.
    B, C : array_like of complex, shape (2,)
        Crank pin and slider pin at the extended and the folded limit position.
    """
    ax = _axes(ax, (7.0, 4.2))
    B, C = np.asarray(B), np.asarray(C)
    a = abs(B[0])
    t = np.linspace(0.0, 2.0 * np.pi, 241)
    ax.plot(a * np.cos(t), a * np.sin(t), ":", color="0.5", lw=1.0)
    lo, hi = min(C.real.min(), -a) - 0.1 * a, C.real.max() + 0.4 * a
    ax.plot([lo, hi], [e, e], "-.", color="0.4", lw=1.0, label="guide line y = e")
    for i, (style, name, colour) in enumerate((("-", "extended", "tab:blue"), ("--", "folded", "tab:orange"))):
        pts = np.array([0.0, B[i], C[i]])
        ax.plot(pts.real, pts.imag, style, marker="o", ms=4, color=colour, lw=1.4, label=name)
        ax.plot([0.0, C[i].real], [0.0, C[i].imag], ":", color=colour, lw=0.8)
        ax.add_patch(_slider_patch(C[i], 0.12 * a, colour))
        _label(ax, C[i], f"C$_{i + 1}$", offset=(4, -14), color=colour)
        _label(ax, B[i], "B" + "′" * (i + 1), offset=(-14, 4), color=colour)
    y_dim = e + 0.45 * a
    for x in C.real:
        ax.plot([x, x], [e, y_dim + 0.08 * a], color="black", lw=0.6)
    ax.annotate("", (C[0].real, y_dim), (C[1].real, y_dim),
                arrowprops={"arrowstyle": "<->", "color": "black", "lw": 0.9})
    ax.text(C.real.mean(), y_dim + 0.05 * a, stroke_label, ha="center", va="bottom", fontsize=10)
    _angle_arc(ax, 0.0, 0.55 * abs(C[1]), np.angle(C[0]), np.angle(C[1]), angle_label, "black")
    _label(ax, 0j, "A", offset=(-12, -12))
    return _finish(ax)


def _slider_patch(z, size, colour):
    from matplotlib.patches import Rectangle

    return Rectangle((z.real - size, z.imag - 0.6 * size), 2 * size, 1.2 * size,
                     fill=False, edgecolor=colour, lw=1.2)


def guide_bar_limit_positions(d, B, guide_length, ax=None, *, swing_label=r"$\varphi$",
                              angle_label=r"$\theta$"):
    """Draw an oscillating guide-bar in its two limit positions (Fig. 2-39).

    Parameters
    ----------
    d : float
        Frame length AD (crank centre A = 0, guide pivot D = d).
    B : array_like of complex, shape (2,)
        Crank pin at the two limit positions of the guide.
    guide_length : float
        Length drawn for the guide bar from D (at least the largest distance DB).
    """
    ax = _axes(ax, (6.0, 6.0))
    B = np.asarray(B)
    a = abs(B[0])
    t = np.linspace(0.0, 2.0 * np.pi, 241)
    ax.plot(a * np.cos(t), a * np.sin(t), ":", color="0.5", lw=1.0)
    ax.plot([0.0, d], [0.0, 0.0], color="black", lw=3.0, solid_capstyle="round")
    for i, (style, colour) in enumerate((("-", "tab:blue"), ("--", "tab:orange"))):
        u = (B[i] - d) / abs(B[i] - d)
        end = d + guide_length * u
        ax.plot([d, end.real], [0.0, end.imag], style, color="0.3", lw=2.0)
        ax.plot([0.0, B[i].real], [0.0, B[i].imag], style, marker="o", ms=4, color=colour, lw=1.6,
                label=f"limit position {i + 1}")
        ax.add_patch(_slider_patch(B[i], 0.08 * a, colour))
        _label(ax, B[i], "B" + "′" * (i + 1), offset=(6, 0), color=colour)
    g = np.angle(B - d)
    _angle_arc(ax, complex(d), 0.35 * d, g[0], g[1], swing_label, "black")
    # the extreme angle: between AB' and the extension of AB'' beyond A
    ext = -1.6 * B[1]
    ax.plot([0.0, ext.real], [0.0, ext.imag], ":", color="tab:orange", lw=0.9)
    _angle_arc(ax, 0j, 0.7 * a, np.angle(B[0]), np.angle(-B[1]), angle_label, "black")
    _label(ax, 0j, "A", offset=(-12, -12))
    _label(ax, complex(d), "D", offset=(4, -12))
    return _finish(ax)
