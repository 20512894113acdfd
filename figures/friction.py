"""Figures of friction and efficiency (``book/forces/friction.md``, ``book/forces/efficiency.md``).

Plain plotting functions: they take numbers computed by ``mech`` and a Matplotlib ``Axes``
(a new figure when ``ax`` is None), draw, and return the axes. Nothing runs at import.
"""

import numpy as np

__all__ = ["journal_friction_circle", "two_force_member", "efficiency_curves", "thrust_pressure",
           "friction_cone", "vgroove", "wedge_press_free_bodies"]


def _axes(ax, size=(5.0, 4.0)):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def journal_friction_circle(r, rho, h, ax=None, *, title=None, scale=1.0):
    """A journal of radius r, its friction circle rho, a vertical load at offset h (Fig. 2-64).

    The load Q' acts downward along the line x = h; the bearing's total reaction acts upward
    along x = rho (tangent to the friction circle, its moment opposing the clockwise turn) if
    the journal turns (h >= rho), or along the load line itself when it stays locked (h < rho).
    ``scale`` enlarges rho and h in the drawing only (the labels show the true values).
    """
    ax = _axes(ax)
    label_rho, label_h = rho, h
    rho, h = scale * rho, scale * h
    t = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(r * np.cos(t), r * np.sin(t), color="black", lw=1.4, label="journal")
    ax.plot(rho * np.cos(t), rho * np.sin(t), color="tab:red", lw=1.0, ls="--",
            label=rf"friction circle $\rho$ = {label_rho:.3g}" + (f" (×{scale:g})" if scale != 1 else ""))
    top, bottom = 1.6 * r, -1.6 * r
    ax.annotate("", xy=(h, 0.15 * r), xytext=(h, top), arrowprops=dict(arrowstyle="-|>", color="tab:blue", lw=1.6))
    ax.text(h, top, rf" $Q'$ at $h$ = {label_h:.3g}", color="tab:blue", va="bottom", fontsize=9)
    x_r = rho if h >= rho else h
    ax.annotate("", xy=(x_r, -0.15 * r), xytext=(x_r, bottom), arrowprops=dict(arrowstyle="-|>", color="tab:green", lw=1.6))
    ax.text(x_r, bottom, r" $R_{21}$", color="tab:green", va="top", fontsize=9)
    ax.plot([0], [0], "k+")
    ax.set_aspect("equal")
    ax.set_xlim(-1.8 * r, 1.8 * r)
    ax.set_ylim(-2.0 * r, 2.0 * r)
    ax.set_xticks([])
    ax.set_yticks([])
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def two_force_member(A, B, rho_a, rho_b, tilt, ax=None, *, title=None):
    """A link between pins A and B (complex), their friction circles and the cross tangent.

    ``tilt`` is the angle of the force line from AB (from ``two_force_tilt_angle``); the line
    passes to the right of A->B at A and to its left at B, tangent to both circles.
    """
    ax = _axes(ax, (7.0, 2.8))
    A, B = complex(A), complex(B)
    u = (B - A) / abs(B - A)
    t = np.linspace(0.0, 2.0 * np.pi, 181)
    ax.plot([A.real, B.real], [A.imag, B.imag], color="0.6", lw=6, solid_capstyle="round", zorder=1)
    for P, rho, name in ((A, rho_a, "A"), (B, rho_b, "B")):
        ax.plot(P.real + rho * np.cos(t), P.imag + rho * np.sin(t), color="tab:red", lw=1.0)
        ax.plot([P.real], [P.imag], "ko", ms=3)
        ax.annotate(name, (P.real, P.imag), textcoords="offset points", xytext=(-4, -16), fontsize=9)
    d = u * np.exp(1j * tilt)                                   # direction of the force line
    n = 1j * d
    start = A - rho_a * n                                       # the tangent point on circle A
    ends = start + d * np.array([-0.15, 1.15]) * abs(B - A)
    ax.plot(ends.real, ends.imag, color="tab:green", lw=1.3,
            label=rf"force line, tilted {np.degrees(tilt):.2f}° from AB")
    ax.set_aspect("equal")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_xticks([])
    ax.set_yticks([])
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def efficiency_curves(angle, curves, ax=None, *, lock_angle=None, lock_label=None, xlabel="angle (degrees)",
                      points=None):
    """Efficiencies against an angle (degrees on the axis), with the self-locking angle marked.

    ``curves`` maps a label to an array of efficiencies at ``angle`` (radians). Where a
    curve crosses zero the motion it describes becomes self-locking. ``points`` maps a label
    to one ``(angle, eta)`` pair to mark (a design point).
    """
    ax = _axes(ax, (7.0, 3.8))
    deg = np.degrees(np.asarray(angle))
    for label, eta in curves.items():
        ax.plot(deg, eta, lw=1.6, label=label)
    ax.axhline(0.0, color="black", lw=0.8)
    if lock_angle is not None:
        ax.axvline(np.degrees(lock_angle), color="tab:red", lw=1.0, ls="--",
                   label=lock_label or f"self-locking limit {np.degrees(lock_angle):.3f}°")
    for label, (at, eta) in (points or {}).items():
        ax.plot([np.degrees(at)], [eta], "o", color="black", zorder=3)
        ax.annotate(label, (np.degrees(at), eta), textcoords="offset points", xytext=(8, 6), fontsize=8)
    ax.set_xlim(deg[0], deg[-1])
    ax.set_ylim(-1.0, 1.0)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(r"efficiency $\eta$")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    return ax


def thrust_pressure(r_in, r_out, ax=None):
    """Pressure across a thrust face carrying a unit load: uniform (new) and p s = const (run in)."""
    ax = _axes(ax, (6.0, 3.2))
    s = np.linspace(r_in, r_out, 200)
    area = np.pi * (r_out**2 - r_in**2)
    ax.plot(s, np.full_like(s, 1.0 / area), lw=1.6, label="new: uniform pressure")
    ax.plot(s, 1.0 / (2.0 * np.pi * (r_out - r_in) * s), lw=1.6, label=r"run in: $p\,s$ = const")
    ax.set_xlabel("radius $s$")
    ax.set_ylabel("pressure per unit load")
    ax.set_xlim(0.0, r_out)
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return ax


def _arrow(ax, tail, head, colour, text, *, lw=1.6, offset=0.0):
    tail, head = complex(tail), complex(head)
    ax.annotate("", xy=(head.real, head.imag), xytext=(tail.real, tail.imag),
                arrowprops=dict(arrowstyle="-|>", color=colour, lw=lw))
    at = head + offset
    ax.text(at.real, at.imag, text, color=colour, fontsize=9, ha="center", va="center")


def friction_cone(phi, push_angle, reaction, ax=None, *, title=None, size=1.0):
    """A slider on a horizontal guide, its friction cone and the forces on it (Fig. 2-61).

    ``phi`` is the friction angle, ``push_angle`` the angle of the push P from the guide's
    normal (leaning forward, toward +x), ``reaction`` the unit total reaction of the guide on
    the slider (complex, e.g. ``total_reaction(1j, 1.0, mu)``) when it slides, or NaN when it
    does not. The cone is the pair of lines at ``phi`` either side of the normal.
    """
    ax = _axes(ax)
    w, h = 1.2 * size, 0.5 * size
    from matplotlib.patches import Rectangle

    ax.add_patch(Rectangle((-w / 2, 0.0), w, h, facecolor="0.9", edgecolor="black"))
    ax.plot([-1.3 * size, 1.3 * size], [0.0, 0.0], color="black", lw=1.2)
    ax.fill_between([-1.3 * size, 1.3 * size], -0.08 * size, 0.0, color="0.75", hatch="///", lw=0)
    L = 1.5 * size
    for s in (-1.0, 1.0):                        # the cone, about the normal through the contact
        ax.plot([0.0, L * np.sin(s * phi)], [0.0, L * np.cos(phi)], color="tab:red", lw=1.0, ls="--")
    ax.fill([0.0, -L * np.sin(phi), L * np.sin(phi)], [0.0, L * np.cos(phi), L * np.cos(phi)],
            color="tab:red", alpha=0.08)
    top = complex(-0.3 * w, h)                    # P acts on the slider's top, R at the contact
    push = complex(np.sin(push_angle), -np.cos(push_angle))
    _arrow(ax, top - 0.9 * size * push, top, "tab:blue", "", lw=1.8)
    tail = top - 0.9 * size * push
    ax.text(tail.real, tail.imag, "$P$", color="tab:blue", fontsize=10, ha="right", va="bottom")
    reaction = complex(reaction)
    if np.isfinite(reaction.real):
        _arrow(ax, 0.0, 1.1 * size * reaction, "tab:green", r"$R$", offset=0.1 * size * reaction)
        ax.text(-1.25 * size, -0.25 * size, r"slides: $R$ leans $\varphi$ back on the cone", fontsize=8)
    else:
        ax.text(-1.25 * size, -0.25 * size, r"stuck: $R = -P$ lies inside the cone", fontsize=8)
        _arrow(ax, 0.0, -0.9 * size * push, "tab:green", r"$R$", offset=-0.1 * size * push)
    ax.text(0.05 * size, 1.55 * size, rf"$\varphi$ = {np.degrees(phi):.1f}°,  $\alpha$ = {np.degrees(push_angle):.1f}°",
            fontsize=9, ha="center")
    ax.set_aspect("equal")
    ax.set_xlim(-1.35 * size, 1.35 * size)
    ax.set_ylim(-0.35 * size, 1.75 * size)
    ax.axis("off")
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def vgroove(half_angle, load, flank_force, ax=None, *, title=None):
    """Cross-section of a V-groove slider carrying ``load`` down, with the two flank normal
    forces ``flank_force`` (each, along the flank normals) drawn to the load's scale (Fig. 2-62).
    ``half_angle`` is the angle between a flank and the plane of symmetry.
    """
    ax = _axes(ax, (4.0, 4.0))
    t = half_angle
    depth = 1.0
    xs = depth * np.tan(t)
    ax.plot([-1.6 * xs - 0.3, -xs, 0.0, xs, 1.6 * xs + 0.3], [depth, depth, 0.0, depth, depth], color="black", lw=1.4)
    ax.fill([-0.75 * xs, 0.0, 0.75 * xs], [0.75 * depth, 0.0, 0.75 * depth], color="0.85", ec="black")
    scale = 0.6 / load
    top = complex(0.0, 0.75 * depth)
    _arrow(ax, top + 1j * load * scale, top, "tab:blue", "")
    ax.text(0.05, (top + 1j * load * scale).imag, f" Q = {load:g}", color="tab:blue", fontsize=9, va="top")
    for s in (-1.0, 1.0):
        foot = complex(s * 0.4 * xs, 0.4 * depth)        # a point of the flank
        n = complex(-s * np.cos(t), np.sin(t))           # flank normal, into the slider
        tail = foot - flank_force * scale * n
        _arrow(ax, tail, foot, "tab:green", "")
        ax.text(tail.real, tail.imag, f"N = {flank_force:.3g}", color="tab:green", fontsize=9,
                ha="right" if s < 0 else "left", va="top")
    ax.set_aspect("equal")
    ax.axis("off")
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def wedge_press_free_bodies(lam, forces, ax=None, *, scale=0.03, length=100.0, gap=18.0):
    """The two wedges of the wedge press drawn apart, each with its forces (Fig. 2-68a).

    ``forces`` is a `WedgePressForces` (from ``mech.planar.wedge_press_forces``); each arrow
    is ``scale`` mm per N. The shapes follow the model of that function: wedge 2 on the
    base y = 0, its upper face falling towards +x at ``lam``; wedge 3 above it, bearing on
    the vertical guide on its +x side. Wedge 3 is lifted by ``gap`` to separate the bodies.
    """
    ax = _axes(ax, (5.5, 5.0))
    slope = np.tan(lam)
    h0 = 18.0 + length * slope                   # wedge 2's height at its thick end
    top = lambda x: h0 - x * slope               # noqa: E731  (wedge 2's upper face)
    x3, w3 = 0.8 * length, 0.3 * length          # the guide's line and wedge 3's width
    wedge2 = np.array([0, length, length + 1j * top(length), 1j * h0, 0])
    foot = [x3 - w3 + 1j * top(x3 - w3), x3 + 1j * top(x3)]
    wedge3 = np.array([foot[0], foot[1], x3 + 1j * (h0 + 60), x3 - w3 + 1j * (h0 + 60), foot[0]]) + 1j * gap
    ax.fill(wedge2.real, wedge2.imag, color="#c6dbef", ec="tab:blue", lw=1.4)
    ax.fill(wedge3.real, wedge3.imag, color="#fdd0a2", ec="tab:orange", lw=1.4)
    ax.plot([-0.2 * length, 1.2 * length], [0, 0], color="0.3", lw=1.0)
    ax.plot([x3, x3], [top(x3) + gap, h0 + 60 + gap], color="0.3", lw=3.0, alpha=0.4)
    mid = (foot[0] + foot[1]) / 2
    s = scale
    # every force drawn with its head on the body: at the face it acts on, or the load's point
    arrows = [
        (1j * h0 / 2, forces.P, "P", "tab:red"),
        (0.5 * x3, forces.R12, r"$R_{12}$", "tab:green"),
        (mid, forces.R32, r"$R_{32}$", "tab:purple"),
        (mid + 1j * gap, forces.R23, r"$R_{23}$", "tab:purple"),
        (x3 + 1j * (h0 + 30 + gap), forces.R13, r"$R_{13}$", "tab:brown"),
        (x3 - w3 / 2 + 1j * (h0 + 60 + gap), forces.Q, "Q", "tab:red"),
    ]
    for head, f, text, colour in arrows:
        tail = head - s * complex(f)
        _arrow(ax, tail, head, colour, text, offset=-1.1 * s * complex(f) + 0j)
    for name, z in (("2", 0.25 * length + 0.3j * h0), ("3", x3 - w3 / 2 + 1j * (h0 + 45 + gap))):
        ax.text(z.real, z.imag, name, fontsize=12, ha="center", va="center")
    ax.set_aspect("equal")
    ax.set_xlim(-0.35 * length, 1.35 * length)
    ax.set_ylim(-s * abs(complex(forces.R12)) - 8, h0 + 60 + gap + s * abs(complex(forces.Q)) + 10)
    ax.grid(alpha=0.2)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    return ax
