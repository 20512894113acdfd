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
                                 circles=(), ax=None):
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
    """
    ax = poses_figure(theta, d, length=length, ax=ax)
    B, C, d = (np.asarray(v, dtype=complex) for v in (B, C, d))
    path = np.asarray(path, dtype=complex)
    for k, (centre, radius) in enumerate(circles):
        ring = centre + radius * np.exp(1j * np.linspace(0.0, 2.0 * np.pi, 361))
        ax.plot(ring.real, ring.imag, "--", color=_DYAD_COLOURS[(k + 2) % len(_DYAD_COLOURS)], lw=0.9,
                label=f"slider circle {k + 1} (pose 1)")
    s = np.real(np.conj(direction) * (C - line_point))
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
