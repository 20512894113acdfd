"""Figures of static force analysis (``book/forces/static-forces.md``).

Plain plotting functions: they take points, forces and curves computed by ``mech`` and a
Matplotlib ``Axes`` (a new one when ``ax`` is None), draw, and return the axes. Nothing
runs at import.
"""

import numpy as np

__all__ = ["mechanism_with_forces", "force_polygon", "efficiency_curve", "effort_near_locking"]


def _axes(ax, size=(6.4, 4.2)):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def mechanism_with_forces(points, bars, forces=(), lines=(), circles=(), ground=(), guides=(), ax=None,
                          scale=1.0, title=None):
    """Draw a linkage as bars between points, with force arrows, lines of action and circles.

    Parameters
    ----------
    points : mapping of str to complex
        Named points, labelled on the drawing.
    bars : iterable of tuple of str
        Each a chain of point names drawn as one link.
    forces : iterable of (complex at, complex force, str label, str colour)
        Arrows drawn from ``at`` with length ``scale * |force|``.
    lines : iterable of (complex at, complex direction, str colour)
        Lines of action, drawn long through ``at``.
    circles : iterable of (complex centre, float radius)
        Friction circles (drawn dashed).
    ground : iterable of str
        Fixed pivots (drawn as triangles).
    guides : iterable of (complex a, complex b)
        Straight guides drawn as hatched segments.
    """
    ax = _axes(ax)
    for chain in bars:
        z = np.array([complex(points[p]) for p in chain])
        ax.plot(z.real, z.imag, "-", color="0.25", lw=2.2, solid_capstyle="round", zorder=2)
    for name, z in points.items():
        z = complex(z)
        ax.plot([z.real], [z.imag], "o", ms=5, mfc="white", mec="black", zorder=4)
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(5, 5), fontsize=10)
    for name in ground:
        z = complex(points[name])
        ax.plot([z.real], [z.imag], "^", ms=13, color="0.6", zorder=1)
    for a, b in guides:
        ax.plot([a.real, b.real], [a.imag, b.imag], color="0.5", lw=1.2, zorder=1)
    span = max(np.ptp([complex(z).real for z in points.values()]),
               np.ptp([complex(z).imag for z in points.values()]), 1e-9)
    for at, d, colour in lines:
        d = complex(d) / abs(complex(d)) * 2.0 * span
        ax.plot([(at - d).real, (at + d).real], [(at - d).imag, (at + d).imag], ls=":", lw=1.0,
                color=colour, zorder=1)
    for centre, r in circles:
        t = np.linspace(0, 2 * np.pi, 90)
        c = complex(centre) + r * np.exp(1j * t)
        ax.plot(c.real, c.imag, "--", color="tab:orange", lw=1.0, zorder=3)
    for at, f, label, colour in forces:
        at, f = complex(at), scale * complex(f)
        ax.annotate("", xy=(at.real + f.real, at.imag + f.imag), xytext=(at.real, at.imag),
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.6), zorder=5)
        ax.annotate(label, (at.real + f.real, at.imag + f.imag), color=colour, fontsize=10,
                    textcoords="offset points", xytext=(4, -12))
    zs = np.array([complex(z) for z in points.values()])
    pad = 0.3 * span
    ax.set_xlim(zs.real.min() - pad, zs.real.max() + pad)
    ax.set_ylim(zs.imag.min() - pad, zs.imag.max() + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    if title:
        ax.set_title(title)
    return ax


def force_polygon(vectors, ax=None, *, colours=None, title=None, dashed=()):
    """Draw force vectors head to tail (a closed polygon when they balance).

    ``vectors`` is a sequence of (label, complex force); ``dashed`` adds further
    (label, start, end) segments (for example a frictionless comparison).
    """
    ax = _axes(ax, (4.2, 4.2))
    start = 0j
    colours = colours or ["tab:red", "tab:blue", "tab:green", "tab:purple", "tab:brown"]
    for (label, f), colour in zip(vectors, colours):
        f = complex(f)
        end = start + f
        ax.annotate("", xy=(end.real, end.imag), xytext=(start.real, start.imag),
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.8))
        mid = start + 0.5 * f
        ax.annotate(label, (mid.real, mid.imag), color=colour, textcoords="offset points", xytext=(6, 4))
        ax.plot([start.real, end.real], [start.imag, end.imag], alpha=0)
        start = end
    for label, a, b in dashed:
        ax.plot([a.real, b.real], [a.imag, b.imag], "--", color="0.4", lw=1.2)
        ax.annotate(label, (b.real, b.imag), color="0.3", textcoords="offset points", xytext=(4, 4))
    ax.set_aspect("equal", adjustable="datalim")
    ax.margins(0.2)
    ax.set_xlabel("force x (N)")
    ax.set_ylabel("force y (N)")
    if title:
        ax.set_title(title)
    return ax


def efficiency_curve(theta, eta, ax=None, *, effort=None, effort0=None, label=None):
    """Instantaneous efficiency over a crank turn; optionally the two driving moments on a twin axis."""
    ax = _axes(ax, (7.0, 3.8))
    deg = np.degrees(np.asarray(theta))
    ax.plot(deg, eta, color="tab:blue", lw=1.8, label=label or r"$\eta = M_d^0 / M_d$")
    ax.set_xlabel("crank angle (degrees)")
    ax.set_ylabel("instantaneous efficiency")
    ax.set_ylim(0, 1.05)
    ax.grid(alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    if effort is not None:
        tw = ax.twinx()
        h1, = tw.plot(deg, effort, color="tab:red", lw=1.2, label=r"$M_d$ with friction")
        h2, = tw.plot(deg, effort0, color="tab:red", lw=1.0, ls="--", label=r"$M_d^0$ without")
        tw.set_ylabel("driving moment (N mm)")
        handles, labels = handles + [h1, h2], labels + [h1.get_label(), h2.get_label()]
    ax.legend(handles, labels, loc="lower center", fontsize=9, ncol=3)
    return ax


def effort_near_locking(x, effort, x_lock, ax=None):
    """Required driving force against a position, and its reciprocal crossing zero at ``x_lock``."""
    ax = _axes(ax, (7.0, 3.8))
    ax.plot(x, 1.0 / np.asarray(effort), color="tab:blue", lw=1.8, label="1 / P (computed)")
    ax.axvline(x_lock, color="tab:red", ls="--", lw=1.0,
               label=r"$x = l\,\sin[\arctan\mu + \arcsin(2r\mu_0/l)]$")
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.set_xlabel("x, horizontal distance A to B (mm)")
    ax.set_ylabel("1 / P  (1/N, for Q = 1 N)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9)
    return ax
