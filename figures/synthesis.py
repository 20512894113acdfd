"""Rigid-body guidance: poses, Burmester dyads and the designed four-bar, like Figs. 2-87, 2-89.

Plain plotting functions: they take poses and points computed by ``mech`` (complex numbers
in the task's ground frame) and a Matplotlib ``Axes`` (a new figure when ``ax`` is None),
draw, and return the axes. Nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["poses_figure", "burmester_figure", "curves_figure", "guidance_fourbar_figure"]

_DYAD_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown", "tab:pink")


def _axes(ax, size=(7.5, 6.5)):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def poses_figure(theta, d, *, length, ax=None, colour="black", labels=True):
    """Draw each pose as its reference point and an arrow along its reference line.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Pose angles, radians.
    d : array_like of complex, shape (n,)
        Reference points (the translations of the poses).
    length : float
        Length of the drawn reference lines.
    labels : bool, optional
        Write P_1, P_2, ... beside the reference points.
    """
    ax = _axes(ax)
    theta, d = np.asarray(theta, dtype=float), np.asarray(d, dtype=complex)
    tips = d + length * np.exp(1j * theta)
    for k, (p, t) in enumerate(zip(d, tips), start=1):
        ax.annotate("", xy=(t.real, t.imag), xytext=(p.real, p.imag),
                    arrowprops={"arrowstyle": "-|>", "color": colour, "lw": 1.6})
        ax.plot(p.real, p.imag, "o", color=colour, ms=5)
        if labels:
            ax.annotate(f"$P_{k}$", (p.real, p.imag), xytext=(-14, 4), textcoords="offset points", fontsize=10)
    ax.set_aspect("equal")
    ax.grid(alpha=0.25)
    return ax


def burmester_figure(theta, d, centres, circle_positions, *, length, ax=None, labels=None):
    """Draw the poses, and for each dyad its centre point, circle and circle-point positions.

    Parameters
    ----------
    theta, d : array_like, shape (n,)
        The poses, as in `poses_figure`.
    centres : array_like of complex, shape (k,)
        Centre points (fixed pivots).
    circle_positions : array_like of complex, shape (k, n)
        Position of each dyad's circle point in each pose.
    length : float
        Length of the drawn reference lines.
    labels : sequence of str, optional
        One legend entry per dyad.
    """
    ax = poses_figure(theta, d, length=length, ax=ax, labels=False)
    centres = np.asarray(centres, dtype=complex)
    circle_positions = np.asarray(circle_positions, dtype=complex)
    labels = labels or [f"dyad {k + 1}" for k in range(centres.size)]
    turn = np.exp(1j * np.linspace(0, 2 * np.pi, 361))
    for k, (A, Z) in enumerate(zip(centres, circle_positions)):
        colour = _DYAD_COLOURS[k % len(_DYAD_COLOURS)]
        r = np.abs(Z[0] - A)
        ring = A + r * turn
        ax.plot(ring.real, ring.imag, "-", color=colour, lw=0.8, alpha=0.6)
        ax.plot(Z.real, Z.imag, "o", mfc="white", color=colour, ms=6)
        ax.plot(A.real, A.imag, "^", color=colour, ms=10, label=labels[k])
        ax.plot([A.real, Z[0].real], [A.imag, Z[0].imag], "-", color=colour, lw=1.5)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return ax


def curves_figure(theta, d, curves, *, length, axes=None, labels=None, marks=None, limits=None):
    """Draw circle-point curves (left, at pose 1) and centre-point curves (right) of pose sets.

    Parameters
    ----------
    theta, d : array_like, shape (n,)
        The poses, as in `poses_figure`.
    curves : sequence of (array_like of complex, array_like of complex)
        For each curve, its circle points in the ground frame at pose 1 and its centre
        points (any shape; NaN entries are skipped).
    length : float
        Length of the drawn reference lines.
    axes : pair of Axes, optional
        Where to draw; a new figure with two panels when None.
    labels : sequence of str, optional
        One legend entry per curve.
    marks : (array_like of complex, array_like of complex), optional
        Points to mark on the two panels (e.g. the Burmester moving pivots and centre points).
    limits : sequence of two (xmin, xmax, ymin, ymax), optional
        Axis limits of the two panels.
    """
    from matplotlib.lines import Line2D

    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(1, 2, figsize=(12.0, 6.0))
    labels = labels or [f"curve {k + 1}" for k in range(len(curves))]
    handles = []
    for side, (ax, title) in enumerate(zip(axes, ("circle points (pose 1)", "centre points"))):
        poses_figure(theta, d, length=length, ax=ax, labels=False)
        for k, pair in enumerate(curves):
            colour = _DYAD_COLOURS[k % len(_DYAD_COLOURS)]
            pts = np.asarray(pair[side], dtype=complex).ravel()
            pts = pts[np.isfinite(pts)]
            ax.plot(pts.real, pts.imag, ".", color=colour, ms=1.5)
            if side == 0:
                handles.append(Line2D([], [], color=colour, marker="o", ls="", label=labels[k]))
        if marks is not None:
            m = np.asarray(marks[side], dtype=complex)
            ax.plot(m.real, m.imag, "^" if side else "o", mfc="none", mec="black", ms=11, mew=1.5)
        if limits is not None:
            ax.set_xlim(*limits[side][:2])
            ax.set_ylim(*limits[side][2:])
        ax.set_title(title, fontsize=10)
    if marks is not None:
        handles.append(Line2D([], [], color="black", marker="^", mfc="none", ls="", label="Burmester dyads (5 poses)"))
    axes[1].legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return axes


def guidance_fourbar_figure(theta, d, A, D, B, C, path, *, length, ax=None):
    """Draw a guidance four-bar at each precision pose and the path of its reference point.

    Parameters
    ----------
    theta, d : array_like, shape (n,)
        The poses, as in `poses_figure`.
    A, D : complex
        Fixed pivots.
    B, C : array_like of complex, shape (n,)
        Moving pivots at the precision poses.
    path : array_like of complex, shape (m,)
        The reference point over the motion from the first pose to the last.
    length : float
        Length of the drawn reference lines.
    """
    ax = poses_figure(theta, d, length=length, ax=ax)
    B, C, d = (np.asarray(v, dtype=complex) for v in (B, C, d))
    path = np.asarray(path, dtype=complex)
    ax.plot(path.real, path.imag, "-", color="tab:red", lw=1.2, alpha=0.8, label="path of the reference point")
    for k, (b, c, p) in enumerate(zip(B, C, d)):
        alpha = 1.0 if k == 0 else 0.45
        ax.plot([A.real, b.real, c.real, D.real], [A.imag, b.imag, c.imag, D.imag], "-o",
                color="tab:blue", lw=2.0 if k == 0 else 1.0, ms=4, alpha=alpha)
        ax.fill([b.real, c.real, p.real], [b.imag, c.imag, p.imag], color="tab:blue", alpha=0.12)
    for name, z in (("A", A), ("D", D)):
        ax.plot(z.real, z.imag, "k^", ms=11)
        ax.annotate(name, (z.real, z.imag), xytext=(6, -12), textcoords="offset points", fontweight="bold")
    ax.annotate("$B_1$", (B[0].real, B[0].imag), xytext=(-16, 4), textcoords="offset points")
    ax.annotate("$C_1$", (C[0].real, C[0].imag), xytext=(6, 4), textcoords="offset points")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return ax


__all__ += ["guidance_slider_crank_figure"]


def guidance_slider_crank_figure(theta, d, A, B, C, line_point, direction, path, *, length,
                                 circles=(), through=(), ax=None):
    """Draw a guidance slider-crank at each pose, its guide, and the path of the reference point.

    Parameters
    ----------
    theta, d : array_like, shape (n,)
        The poses, as in `poses_figure`.
    A : complex
        The crank's fixed pivot.
    B, C : array_like of complex, shape (n,)
        The crank pin and the block pin at the poses.
    line_point, direction : complex
        A point of the guide and its unit direction.
    path : array_like of complex, shape (m,)
        The reference point over the motion from the first pose to the last.
    length : float
        Length of the drawn reference lines.
    circles : sequence of (complex, float), optional
        Slider circles (centre, radius) already placed in the ground frame, drawn dashed.
    through : sequence of complex, optional
        Further points on the guide that the drawn guide must reach (A, for a centric
        slider-crank).
    """
    ax = poses_figure(theta, d, length=length, ax=ax)
    B, C, d = (np.asarray(v, dtype=complex) for v in (B, C, d))
    path = np.asarray(path, dtype=complex)
    for k, (centre, radius) in enumerate(circles):
        ring = centre + radius * np.exp(1j * np.linspace(0.0, 2.0 * np.pi, 361))
        ax.plot(ring.real, ring.imag, "--", color=_DYAD_COLOURS[(k + 2) % len(_DYAD_COLOURS)], lw=0.9,
                label=f"slider circle {k + 1} (pose 1)")
    s = np.real(np.conj(direction) * (np.append(C, np.asarray(through, dtype=complex)) - line_point))
    span = s.max() - s.min()
    ends = line_point + direction * np.array([s.min() - 0.3 * span, s.max() + 0.3 * span])
    ax.plot(ends.real, ends.imag, "-", color="grey", lw=3.0, alpha=0.5, label="guide")
    ax.plot(path.real, path.imag, "-", color="tab:red", lw=1.2, alpha=0.8, label="path of the reference point")
    for k, (b, c, p) in enumerate(zip(B, C, d)):
        alpha = 1.0 if k == 0 else 0.45
        ax.plot([A.real, b.real, c.real], [A.imag, b.imag, c.imag], "-o",
                color="tab:blue", lw=2.0 if k == 0 else 1.0, ms=4, alpha=alpha)
        ax.fill([b.real, c.real, p.real], [b.imag, c.imag, p.imag], color="tab:blue", alpha=0.12)
        ax.plot(c.real, c.imag, "s", mfc="none", mec="tab:blue", ms=12, mew=1.5, alpha=alpha)
    ax.plot(A.real, A.imag, "k^", ms=11)
    ax.annotate("A", (A.real, A.imag), xytext=(6, -12), textcoords="offset points", fontweight="bold")
    ax.annotate("$B_1$", (B[0].real, B[0].imag), xytext=(-16, 4), textcoords="offset points")
    ax.annotate("$C_1$", (C[0].real, C[0].imag), xytext=(6, 4), textcoords="offset points")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return ax


__all__ += ["two_position_figure", "rocker_slider_figure"]


def two_position_figure(A, D, B, C, sweep_B, sweep_C, *, x0, ax=None):
    """Draw a two-position guidance four-bar (exercise 2-27): bisectors, frame line, motion.

    Parameters
    ----------
    A, D : complex
        Fixed pivots.
    B, C : array_like of complex, shape (2,)
        The moving hinges in the two positions (the body is the bar B C, drawn thick).
    sweep_B, sweep_C : array_like of complex, shape (m,)
        B and C over the motion from the first position to the second (from the analysis).
    x0 : float
        The vertical frame line that carries A and D.
    """
    ax = _axes(ax, (7.0, 6.0))
    B, C = np.asarray(B, dtype=complex), np.asarray(C, dtype=complex)
    sweep_B, sweep_C = np.asarray(sweep_B, dtype=complex), np.asarray(sweep_C, dtype=complex)
    pts = np.concatenate([B, C, [A, D]])
    lo, hi = pts.imag.min(), pts.imag.max()
    pad = 0.15 * (hi - lo)
    ax.plot([x0, x0], [lo - pad, hi + pad], "-", color="grey", lw=4, alpha=0.35, label=f"frame line x = {x0:g}")
    for P, Q, pivot, colour in ((B[0], B[1], A, "tab:blue"), (C[0], C[1], D, "tab:orange")):
        mid = 0.5 * (P + Q)
        ax.plot([mid.real, pivot.real], [mid.imag, pivot.imag], ":", color=colour, lw=1.2)
        ax.plot([P.real, Q.real], [P.imag, Q.imag], ":", color=colour, lw=0.8, alpha=0.6)
    ax.plot(sweep_B.real, sweep_B.imag, "-", color="tab:blue", lw=1.0, alpha=0.7, label="path of B")
    ax.plot(sweep_C.real, sweep_C.imag, "-", color="tab:orange", lw=1.0, alpha=0.7, label="path of C")
    for k, (b, c) in enumerate(zip(B, C)):
        alpha = 1.0 if k == 0 else 0.55
        ax.plot([A.real, b.real], [A.imag, b.imag], "-o", color="tab:blue", lw=1.6, ms=4, alpha=alpha)
        ax.plot([D.real, c.real], [D.imag, c.imag], "-o", color="tab:orange", lw=1.6, ms=4, alpha=alpha)
        ext = 0.25 * (c - b)
        ax.plot([(b - ext).real, (c + ext).real], [(b - ext).imag, (c + ext).imag], "-", color="black",
                lw=6, alpha=0.35 * alpha + 0.1, solid_capstyle="butt",
                label="door, closed (1) and open (2)" if k == 0 else None)
        ax.annotate(f"$B_{k + 1}$", (b.real, b.imag), xytext=(-18, 4), textcoords="offset points")
        ax.annotate(f"$C_{k + 1}$", (c.real, c.imag), xytext=(-18, -12), textcoords="offset points")
    for name, z in (("A", A), ("D", D)):
        ax.plot(z.real, z.imag, "k^", ms=11)
        ax.annotate(name, (z.real, z.imag), xytext=(8, -4), textcoords="offset points", fontweight="bold")
    ax.set_aspect("equal")
    ax.grid(alpha=0.25)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return ax


def rocker_slider_figure(A, D, B, C, E, F, inverted, centre, *, guide_y, ax=None):
    """Draw the six-bar of exercise 2-28 at its three positions and the inversion that made it.

    Parameters
    ----------
    A, D : complex
        Fixed pivots of the crank-rocker.
    B, C, E, F : array_like of complex, shape (3,)
        Crank pin, rocker pin, hinge on the rocker and slider pin at the three positions.
    inverted : array_like of complex, shape (3,)
        The slider pin's positions turned back with the rocker into its first position.
    centre : complex
        The hinge E at the first position (centre of the circle through `inverted`).
    guide_y : float
        Height of the slider's line.
    """
    ax = _axes(ax, (7.5, 5.5))
    B, C, E, F, inverted = (np.asarray(v, dtype=complex) for v in (B, C, E, F, inverted))
    xs = np.concatenate([[A, D], B, C, E, F, inverted]).real
    ax.plot([xs.min() - 20, xs.max() + 20], [guide_y, guide_y], "-", color="grey", lw=3, alpha=0.4,
            label="slider's line")
    radius = abs(inverted[0] - centre)
    ring = centre + radius * np.exp(1j * np.linspace(0.0, 2.0 * np.pi, 361))
    ax.plot(ring.real, ring.imag, "--", color="tab:green", lw=0.9, label="circle about $E_1$ (inversion)")
    ax.plot(inverted.real, inverted.imag, "x", color="tab:green", ms=8, mew=2,
            label="$F_j$ turned back with the rocker")
    for k in range(3):
        alpha = 1.0 if k == 0 else 0.5
        ax.plot([A.real, B[k].real, C[k].real, D.real], [A.imag, B[k].imag, C[k].imag, D.imag], "-o",
                color="tab:blue", lw=1.8 if k == 0 else 1.0, ms=3, alpha=alpha,
                label="crank-rocker ABCD" if k == 0 else None)
        ax.fill([D.real, C[k].real, E[k].real], [D.imag, C[k].imag, E[k].imag], color="tab:blue", alpha=0.12)
        ax.plot([E[k].real, F[k].real], [E[k].imag, F[k].imag], "-o", color="tab:red", lw=1.8 if k == 0 else 1.0,
                ms=3, alpha=alpha, label="new link EF" if k == 0 else None)
        ax.plot(F[k].real, F[k].imag, "s", mfc="none", mec="tab:red", ms=11, mew=1.5, alpha=alpha)
        ax.annotate(f"$F_{k + 1}$", (F[k].real, F[k].imag), xytext=(-4, -18), textcoords="offset points")
        ax.annotate(f"$C_{k + 1}$", (C[k].real, C[k].imag), xytext=(4, 4), textcoords="offset points")
    ax.annotate("$E_1$", (E[0].real, E[0].imag), xytext=(6, -2), textcoords="offset points")
    for name, z in (("A", A), ("D", D)):
        ax.plot(z.real, z.imag, "k^", ms=11)
        ax.annotate(name, (z.real, z.imag), xytext=(6, -14), textcoords="offset points", fontweight="bold")
    ax.set_aspect("equal")
    ax.grid(alpha=0.25)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return ax


__all__ += ["displacement_figure"]


def _body(ax, pts, colour, name, *, ls="-", lw=1.6, label_p=True):
    """A body drawn by its points ``[P, a, B]``: the triangle, the reference line P->a, the hinge B."""
    P, a, B = pts[:3]
    ax.fill([P.real, a.real, B.real], [P.imag, a.imag, B.imag], color=colour, alpha=0.12)
    ax.plot([B.real, P.real], [B.imag, P.imag], ls=ls, color=colour, lw=0.9)
    ax.annotate("", xy=(a.real, a.imag), xytext=(P.real, P.imag),
                arrowprops={"arrowstyle": "-|>", "color": colour, "lw": lw, "ls": ls})
    ax.plot([P.real, B.real], [P.imag, B.imag], "o", color=colour, ms=4, mfc="white")
    if label_p:
        ax.annotate(f"$P_{{{name}}}$", (P.real, P.imag), xytext=(-16, -12), textcoords="offset points",
                    color=colour, fontsize=10)
    ax.annotate(f"$B_{{{name}}}$", (B.real, B.imag), xytext=(5, 4), textcoords="offset points",
                color=colour, fontsize=10)


def displacement_figure(positions, pole_point, *, axes=None):
    """The three panels of Fig. 2-88: a planar displacement, a translation and a rotation.

    Parameters
    ----------
    positions : array_like of complex, shape (3, m)
        Ground positions of the body points ``[P, a, B, ...]`` (reference point, tip of the
        reference line, hinge) in pose 1, in the translated pose i' (angle of pose 1,
        reference point of pose i) and in pose i, e.g. from `displacement_matrix`.
    pole_point : complex
        The pole of poses 1 and i (from `pole`).
    axes : three Axes, optional
        (a) pose 1 to pose i, with the pole: one rotation about it does the whole
        displacement; (b) the translation 1 -> i'; (c) the rotation i' -> i about P_i.
    """
    import matplotlib.pyplot as plt

    if axes is None:
        _, axes = plt.subplots(1, 3, figsize=(13.0, 4.6))
    one, moved, end = (np.asarray(p, dtype=complex) for p in positions)
    turn = float(np.angle((end[1] - end[0]) / (one[1] - one[0])))
    for ax in axes:
        ax.set_aspect("equal")
        ax.axis("off")
    # (a) the displacement and its pole
    ax = axes[0]
    _body(ax, one, "tab:blue", "1")
    _body(ax, end, "tab:red", "i")
    _body(ax, moved, "0.55", "i'", ls="--", lw=1.0, label_p=False)
    Q = complex(pole_point)
    for k in (0, 2):
        ax.plot([one[k].real, Q.real, end[k].real], [one[k].imag, Q.imag, end[k].imag], ":", color="k", lw=0.8)
    ax.plot(Q.real, Q.imag, "k*", ms=10)
    ax.annotate("pole $P_{1i}$", (Q.real, Q.imag), xytext=(8, -4), textcoords="offset points", fontsize=10)
    r = 0.35 * abs(one[0] - Q)
    start = float(np.angle(one[0] - Q))
    arc = Q + r * np.exp(1j * np.linspace(start, start + turn, 40))
    ax.plot(arc.real, arc.imag, color="k", lw=0.9)
    mid = Q + 1.25 * r * np.exp(1j * (start + 0.5 * turn))
    ax.text(mid.real, mid.imag, r"$\theta_{i1}$", ha="center", va="center", fontsize=10)
    ax.set_title("(a) displacement 1 → i", fontsize=10)
    # (b) the translation: every point moves by the same vector
    ax = axes[1]
    _body(ax, one, "tab:blue", "1")
    _body(ax, moved, "0.35", "i'")
    for k in (0, 2):
        ax.annotate("", xy=(moved[k].real, moved[k].imag), xytext=(one[k].real, one[k].imag),
                    arrowprops={"arrowstyle": "->", "color": "tab:green", "lw": 1.0})
    ax.set_title("(b) translation 1 → i′", fontsize=10)
    # (c) the rotation about the reference point of pose i
    ax = axes[2]
    _body(ax, moved, "0.35", "i'", label_p=False)
    _body(ax, end, "tab:red", "i")
    P = end[0]
    for k in (1, 2):
        r = abs(moved[k] - P)
        start = float(np.angle(moved[k] - P))
        arc = P + r * np.exp(1j * np.linspace(start, start + turn, 40))
        ax.plot(arc.real, arc.imag, ":", color="tab:green", lw=1.0)
    r = 0.4 * abs(moved[1] - P)
    start = float(np.angle(moved[1] - P))
    mid = P + 1.3 * r * np.exp(1j * (start + 0.5 * turn))
    ax.text(mid.real, mid.imag, r"$\theta_{i1}$", ha="center", va="center", fontsize=10)
    ax.set_title(r"(c) rotation i′ → i about $P_i$", fontsize=10)
    # one scale for all panels
    pts = np.concatenate([one, moved, end, [Q]])
    pad = 0.08 * np.ptp(pts.real)
    for ax in axes:
        ax.set_xlim(pts.real.min() - pad, pts.real.max() + pad)
        ax.set_ylim(pts.imag.min() - pad, pts.imag.max() + pad)
    return axes


__all__ += ["mirrored_pair_figure"]


def mirrored_pair_figure(links, paths, axis_x, *, ax=None):
    """Two guidance four-bars side by side, mirror images across a vertical line (like Fig. 2-86).

    Parameters
    ----------
    links : sequence of two dict
        Joint positions ``{"A", "B", "C", "D", "P"}`` (complex, ground frame) of each
        four-bar at the drawn instant; P is the guided point (the claw's tip).
    paths : sequence of two array_like of complex
        The path of each P over a full crank turn.
    axis_x : float
        The mirror line (the middle of the conveyor).
    """
    ax = _axes(ax, (8.0, 5.5))
    for k, (pts, path) in enumerate(zip(links, paths)):
        colour = _DYAD_COLOURS[k]
        path = np.asarray(path, dtype=complex)
        ax.plot(path.real, path.imag, "-", color=colour, lw=1.0, alpha=0.7)
        A, B, C, D, P = (complex(pts[n]) for n in "ABCDP")
        ax.plot([A.real, B.real, C.real, D.real], [A.imag, B.imag, C.imag, D.imag], "-o", color=colour, lw=2.0, ms=4)
        ax.fill([B.real, C.real, P.real], [B.imag, C.imag, P.imag], color=colour, alpha=0.25)
        ax.plot([A.real, D.real], [A.imag, D.imag], "k^", ms=10)
        ax.plot(P.real, P.imag, "o", color=colour, ms=7)
    top = max(np.max(np.asarray(p).imag) for p in paths)
    low = min(min(np.asarray(p).imag.min(), *(complex(z).imag for z in l.values())) for p, l in zip(paths, links))
    ax.plot([axis_x, axis_x], [low, top], "-.", color="grey", lw=1.0, label="mirror line (conveyor axis)")
    ax.set_aspect("equal")
    ax.grid(alpha=0.25)
    ax.legend(fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0))
    return ax
