"""Figures of friction and efficiency (``book/forces/friction.md``, ``book/forces/efficiency.md``).

Plain plotting functions: they take numbers computed by ``mech`` and a Matplotlib ``Axes``
(a new figure when ``ax`` is None), draw, and return the axes. Nothing runs at import.
"""

import numpy as np

__all__ = ["journal_friction_circle", "two_force_member", "efficiency_curves", "thrust_pressure"]


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
