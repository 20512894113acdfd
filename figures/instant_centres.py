"""Figures of instant centres and centrodes (``book/analysis/instant-centres.md``).

Plain plotting functions: they take centres and curves computed by ``mech``, draw them on
a Matplotlib ``Axes`` (a new figure when ``ax`` is None) and return the axes. Nothing runs
at import.
"""

import numpy as np

__all__ = ["centre_diagram", "centrode_diagram", "circle", "contact_normal", "velocity_arrows",
           "velocity_normals"]


def _axes(ax, size=(7.0, 5.6)):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def _label(pair):
    i, j = pair
    return rf"$P_{{{i}{j}}}$"


def _through(p, q):
    """(point, unit direction) of the line through two centres, or None."""
    if p.at_infinity and q.at_infinity:
        return None
    if p.at_infinity:
        p, q = q, p
    base = complex(p.point)
    d = complex(q.direction) if q.at_infinity else complex(q.point) - base
    return None if d == 0 else (base, d / abs(d))


def centre_diagram(centres, bodies, ax=None, *, extent=None, construction=True, title=None,
                   legend_loc="lower left"):
    """Draw a linkage with all its instant centres P_ij and the Kennedy construction lines.

    Parameters
    ----------
    centres : InstantCentres
        Centres at one pose (scalar entries).
    bodies : sequence of (sequence of complex, dict)
        Each link as a polyline (or polygon) of joint positions with Matplotlib style
        keywords, e.g. ``([A, B], {"color": "C0", "label": "1"})``.
    extent : (xmin, xmax, ymin, ymax), optional
        Plot window; centres outside it are shown by an arrow at the edge.
    construction : bool or sequence of pairs, optional
        Draw, for each derived centre (or only for the pairs listed), the lines P_ik P_jk
        it was found on.
    title : str, optional
    legend_loc : str, optional
        Matplotlib legend location.
    """
    ax = _axes(ax)
    finite = [complex(centres[p].point) for p in centres if not centres[p].at_infinity]
    pts = np.array(finite + [complex(z) for body, _ in bodies for z in body])
    if extent is None:
        pad = 0.15 * max(np.ptp(pts.real), np.ptp(pts.imag))
        extent = (pts.real.min() - pad, pts.real.max() + pad, pts.imag.min() - pad, pts.imag.max() + pad)
    x0, x1, y0, y1 = extent
    centre_of_view = complex((x0 + x1) / 2, (y0 + y1) / 2)
    span = max(x1 - x0, y1 - y0)

    def inside(z):
        return x0 <= z.real <= x1 and y0 <= z.imag <= y1

    if construction:
        for step in centres.construction:
            if step.round == 0 or (construction is not True and step.pair not in construction):
                continue
            i, j = step.pair
            for k in step.via:
                line = _through(centres[i, k], centres[j, k])
                if line is not None:
                    t = np.array([-3.0, 3.0]) * span
                    z = line[0] + t * line[1]
                    ax.plot(z.real, z.imag, color="0.65", lw=0.7, ls="--", zorder=1)
    for body, style in bodies:
        z = np.asarray(body, dtype=complex)
        ax.plot(z.real, z.imag, **{"lw": 2.2, "solid_capstyle": "round", "zorder": 2, **style})
    for pair in centres:
        c = centres[pair]
        direct = c.source in ("revolute", "prismatic")
        colour = "black" if direct else "tab:red"
        if c.at_infinity:
            u = complex(c.direction)
            tail = centre_of_view + 0.22 * span * u * np.exp(0.35j)
            ax.annotate("", xy=(tail.real + 0.1 * span * u.real, tail.imag + 0.1 * span * u.imag),
                        xytext=(tail.real, tail.imag), annotation_clip=False,
                        arrowprops={"arrowstyle": "->", "color": colour, "lw": 1.3})
            ax.text(tail.real, tail.imag, _label(pair) + r" $\infty$", color=colour, fontsize=9,
                    ha="right", va="bottom")
            continue
        z = complex(c.point)
        if inside(z):
            ax.plot([z.real], [z.imag], "o", ms=5, color=colour, zorder=4)
            ax.annotate(_label(pair), (z.real, z.imag), textcoords="offset points", xytext=(5, 5),
                        color=colour, fontsize=10)
        else:
            u = (z - centre_of_view) / abs(z - centre_of_view)
            r = 0.45 * span
            head = centre_of_view + r * u
            ax.annotate("", xy=(head.real, head.imag),
                        xytext=(head.real - 0.1 * span * u.real, head.imag - 0.1 * span * u.imag),
                        arrowprops={"arrowstyle": "->", "color": colour, "lw": 1.3})
            ax.text(head.real, head.imag, _label(pair) + " (off the page)", color=colour, fontsize=8)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.grid(alpha=0.2)
    if title:
        ax.set_title(title, fontsize=10)
    ax.plot([], [], "o", color="black", label="direct centres (joints)")
    ax.plot([], [], "o", color="tab:red", label="by the three-centre theorem")
    ax.plot([], [], ls="--", color="0.65", label="construction lines")
    ax.legend(loc=legend_loc, fontsize=8)
    return ax


def centrode_diagram(segments, placed, pole, joints, ax=None, *, extent=None):
    """Fixed centrode, moving centrode carried to one pose, and the linkage at that pose.

    Parameters
    ----------
    segments : list of CentrodeSegment
        Pieces of the fixed centrode (``segment.fixed``).
    placed : ndarray of complex
        The moving centrode carried with the coupler to the pose shown (NaN gaps allowed).
    pole : complex
        P24 at that pose, where the two centrodes touch.
    joints : (complex, complex, complex, complex)
        A, B, C, D at that pose.
    extent : (xmin, xmax, ymin, ymax), optional
    """
    ax = _axes(ax, (7.0, 6.0))
    for k, seg in enumerate(segments):
        ax.plot(seg.fixed.real, seg.fixed.imag, color="tab:blue", lw=1.6,
                label="fixed centrode (in the frame)" if k == 0 else None)
    ax.plot(placed.real, placed.imag, color="tab:orange", lw=1.6, ls="--",
            label="moving centrode (carried by the coupler)")
    A, B, C, D = joints
    ax.plot([A.real, B.real, C.real, D.real], [A.imag, B.imag, C.imag, D.imag], "-o", color="black",
            lw=2.0, ms=4, label="linkage at the pose shown")
    for z in (B, C):
        ax.plot([z.real, pole.real], [z.imag, pole.imag], color="0.6", lw=0.8, ls=":")
    ax.plot([pole.real], [pole.imag], "o", color="tab:red", ms=6, zorder=5)
    ax.annotate(r"$P_{24}$", (pole.real, pole.imag), textcoords="offset points", xytext=(6, 6),
                color="tab:red")
    for name, z in zip("ABCD", joints):
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(-10, -12), fontsize=9)
    if extent is not None:
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    ax.grid(alpha=0.2)
    ax.legend(loc="lower left", fontsize=8)
    return ax


def velocity_arrows(ax, points, velocities, *, scale=1.0, colour="tab:orange", labels=None, centre=None,
                    label=None):
    """Draw velocity arrows at points (Figs. 2-41, 2-44), optionally with the normals to the
    velocities through a centre.

    Parameters
    ----------
    points, velocities : sequence of complex
        Where the arrows start and the velocities there (e.g. from
        ``LinkVelocities.point_velocity``), drawn ``scale`` times their length.
    labels : sequence of str, optional
        Text at each arrow's head.
    centre : complex, optional
        The instant centre: a dashed line joins it to every point (each velocity is
        perpendicular to it).
    label : str, optional
        Legend entry for the arrows.
    """
    for k, (z, v) in enumerate(zip(points, velocities)):
        z, v = complex(z), complex(v) * scale
        if centre is not None:
            c = complex(centre)
            ax.plot([z.real, c.real], [z.imag, c.imag], ls=":", color=colour, lw=1.0, zorder=1)
        ax.annotate("", xy=(z.real + v.real, z.imag + v.imag), xytext=(z.real, z.imag),
                    arrowprops={"arrowstyle": "-|>", "color": colour, "lw": 1.8}, zorder=5)
        if labels:
            ax.text(z.real + 1.05 * v.real, z.imag + 1.05 * v.imag, labels[k], color=colour, fontsize=10)
    if label:
        ax.plot([], [], color=colour, lw=1.8, label=label)
        ax.legend(loc="lower left", fontsize=8)
    return ax


def velocity_normals(ax, points, velocities, *, length, colour="0.4", label=None):
    """Lines through `points` at right angles to `velocities`, ``length`` long each way
    (Fig. 2-42): they meet at the instant centre, or are parallel when it is at infinity."""
    for z, v in zip(points, velocities):
        z, v = complex(z), complex(v)
        n = 1j * v / abs(v)
        ends = z + np.array([-length, length]) * n
        ax.plot(ends.real, ends.imag, ls="-.", color=colour, lw=0.9, zorder=1, label=label)
        label = None
    return ax


def circle(centre, radius, n=181):
    """Points of a circle as a closed polyline of complex numbers (a disc cam's profile)."""
    return complex(centre) + radius * np.exp(1j * np.linspace(0.0, 2.0 * np.pi, n))


def contact_normal(ax, contact, normal, *, length, colour="tab:red", label="common normal"):
    """The common normal of a higher pair through its contact point (Figs. 2-43, 2-48)."""
    contact, normal = complex(contact), complex(normal)
    ends = contact + np.array([-length, length]) * normal / abs(normal)
    ax.plot(ends.real, ends.imag, color=colour, lw=1.0, ls=(0, (6, 2)), zorder=1, label=label)
    ax.plot([contact.real], [contact.imag], "s", color=colour, ms=4, zorder=5)
    return ax
