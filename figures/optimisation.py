"""Figures of ``book/synthesis/optimisation.md``: convergence curves, the steering trapezoid's
output against the ideal, a path-synthesis four-bar with its coupler curve, and the
illustrations of Figs. 2-110 (a constrained optimum) and 2-113 (barrier functions).
Nothing runs at import; Matplotlib is imported by the functions."""

import numpy as np

__all__ = ["convergence", "steering_curves", "path_design"]


def convergence(results, ax=None, *, title=None, reference=None):
    """Objective against evaluations for ``{label: OptimisationResult}`` (log-log axes).

    ``reference``: an objective value drawn as a dashed line (the best known, or a printed one).
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(6.0, 3.8))
    for label, res in results.items():
        h = np.asarray(res.history)
        keep = np.isfinite(h[:, 1]) & (h[:, 1] > 0)
        ax.plot(h[keep, 0], h[keep, 1], "-", marker="." if keep.sum() < 60 else None, label=label)
    if reference is not None:
        ax.axhline(reference[1], color="k", ls="--", lw=0.8, label=reference[0])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("objective evaluations")
    ax.set_ylabel("objective f at the current iterate")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def steering_curves(proofs, axes=None):
    """beta and beta' against theta (left) and the error beta' - beta (right), in degrees.

    ``proofs``: ``{label: SteeringProof}`` (from `SteeringTrapezoid.prove`).
    """
    import matplotlib.pyplot as plt

    if axes is None:
        _, axes = plt.subplots(1, 2, figsize=(9.0, 3.6))
    first = next(iter(proofs.values()))
    axes[0].plot(np.degrees(first.theta), np.degrees(first.beta_ideal), "k--", label="ideal β′")
    for label, p in proofs.items():
        axes[0].plot(np.degrees(p.theta), np.degrees(p.beta), label=f"β, {label}")
        axes[1].plot(np.degrees(p.theta), np.degrees(p.beta_ideal - p.beta), label=label)
    axes[0].set_xlabel("θ (deg)")
    axes[0].set_ylabel("rotation of CD (deg)")
    axes[1].set_xlabel("θ (deg)")
    axes[1].set_ylabel("β′ − β (deg)")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    return axes


def path_design(designs, points, ax=None, *, samples=1440):
    """Coupler curves of ``{label: CouplerPathDesign}`` with the target points.

    Each curve comes from ``FourBar.solve`` over a full crank turn, placed in the task's
    frame; the coupler points at the design's crank steps are marked, and the first
    design's linkage is drawn at the first step.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(6.5, 5.0))
    pts = np.asarray(points)
    for i, (label, design) in enumerate(designs.items()):
        fb = design.fourbar
        turn = fb.solve(np.linspace(0.0, 2.0 * np.pi, samples))
        curve = design.place(turn.P[turn.valid])
        line, = ax.plot(curve.real, curve.imag, lw=1.2, label=label)
        at = design.place(fb.solve(design.theta).P)
        ax.plot(at.real, at.imag, "o", ms=4, mfc="none", color=line.get_color())
        if i == 0:
            pose = fb.solve(design.theta[:1])
            A, D = design.place(0.0), design.place(design.x[3])        # D = l4 on +x
            B, C, P = (design.place(v[0]) for v in (pose.B, pose.C, pose.P))
            for u, v, c in ((A, B, "tab:blue"), (B, C, "0.4"), (C, D, "tab:red"), (B, P, "0.6"), (C, P, "0.6")):
                ax.plot([u.real, v.real], [u.imag, v.imag], color=c, lw=2)
            ax.plot([A.real, D.real], [A.imag, D.imag], "ks-", ms=5, lw=1)
            for name, z in (("A", A), ("B", B), ("C", C), ("D", D), ("P", P)):
                ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.plot(pts.real, pts.imag, "k+", ms=9, mew=1.5, label="target points")
    for k, z in enumerate(pts, 1):
        ax.annotate(f"P{k}", (z.real, z.imag), textcoords="offset points", xytext=(-6, 6), fontsize=7)
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    return ax



__all__ += ["constrained_optimum", "barrier_curves"]


def constrained_optimum(f, g, h, optima, box, ax=None, *, n=301):
    """Contours of ``f``, the feasible region of ``g <= 0``, the curve ``h = 0`` and the optima
    (like Fig. 2-110). ``f``, ``g``, ``h`` take arrays of points ``(..., 2)``; ``optima`` is a
    ``{label: (x1, x2)}`` mapping; ``box`` is ``[(lo, hi), (lo, hi)]``."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(6.0, 5.5))
    (x0, x1), (y0, y1) = box
    X, Y = np.meshgrid(np.linspace(x0, x1, n), np.linspace(y0, y1, n))
    pts = np.stack([X, Y], axis=-1)
    F = f(pts)
    feasible = np.all(g(pts) <= 0.0, axis=-1)
    ax.contourf(X, Y, feasible.astype(float), levels=[0.5, 1.5], colors=["tab:green"], alpha=0.15)
    cs = ax.contour(X, Y, F, levels=[0.25, 0.5, 1.0, 2.25, 4.0, 6.25, 9.0], colors="grey", linewidths=0.8)
    ax.clabel(cs, fontsize=7, fmt="%g")
    ax.contour(X, Y, h(pts)[..., 0], levels=[0.0], colors="tab:red", linewidths=1.5)
    for label, (u, v) in optima.items():
        ax.plot(u, v, "ko", ms=5)
        ax.annotate(label, (u, v), xytext=(5, 5), textcoords="offset points", fontweight="bold")
    ax.plot([], [], "-", color="tab:red", label="$h(x) = 0$")
    ax.fill([], [], color="tab:green", alpha=0.15, label="$g_i(x) \\leq 0$")
    ax.plot([], [], "-", color="grey", lw=0.8, label="contours of $f$")
    ax.set_xlabel("$x_1$")
    ax.set_ylabel("$x_2$")
    ax.set_aspect("equal")
    ax.legend(fontsize=8, loc="upper left")
    return ax


def barrier_curves(x, curves, minimisers, ax=None, *, objective=None):
    """Penalty functions phi(x, r) for several r, with their minimisers (like Fig. 2-113).

    ``curves`` maps a label to phi over ``x``; ``minimisers`` maps the same labels to
    ``(x_min, phi_min)``; ``objective``, if given, is f over ``x``, drawn dashed."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(6.0, 4.0))
    if objective is not None:
        ax.plot(x, objective, "k--", lw=1.0, label="$f(x) = x$")
    for label, phi in curves.items():
        line, = ax.plot(x, phi, lw=1.3, label=label)
        u, v = minimisers[label]
        ax.plot(u, v, "o", color=line.get_color(), ms=5)
    ax.axvline(1.0, color="grey", lw=3, alpha=0.35)
    ax.set_xlabel("$x$")
    ax.set_ylabel(r"$\phi(x, r)$")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.25)
    return ax


__all__ += ["path_parameters", "steering_variables", "grid_refinement", "conjugate_directions"]


def _seg(ax, u, v, **style):
    ax.plot([u.real, v.real], [u.imag, v.imag], **style)


def _arc_mark(ax, centre, radius, start, stop, text, *, color="k", scale=1.35):
    """An angle from direction `start` to `stop` (radians, counter-clockwise) with a label."""
    from figures.limit_positions import _angle_arc

    _angle_arc(ax, centre, radius, start, stop, text, color, scale=scale, fontsize=10, short=False)


def _length_label(ax, u, v, text, *, side=1.0, color="k", offset=10):
    """Write `text` beside the middle of segment u v, `offset` points to its left (side=+1)."""
    mid = 0.5 * (u + v)
    n = 1j * (v - u) / abs(v - u) * side
    ax.annotate(text, (mid.real, mid.imag), textcoords="offset points", xytext=(offset * n.real, offset * n.imag),
                ha="center", va="center", color=color, fontsize=10)


def path_parameters(design, ax=None):
    """The design variables of Example 2-24 (Fig. 2-108) on a `CouplerPathDesign` at its first step.

    The linkage is solved by ``design.fourbar.solve`` at ``design.theta[0]`` and placed in
    the task's frame: lengths l1..l4 (AB, BC, CD, AD), the coupler point P at l5 from B and
    alpha from BC, the crank pivot (xA, yA), the frame angle phi4 and the crank angle
    phi1 measured from AD.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 5.5))
    fb = design.fourbar
    pose = fb.solve(design.theta[:1])
    A, D = design.place(0.0), design.place(fb.d)
    B, C, P = (complex(design.place(v[0])) for v in (pose.B, pose.C, pose.P))
    A, D = complex(A), complex(D)
    ax.fill([B.real, C.real, P.real], [B.imag, C.imag, P.imag], color="0.6", alpha=0.15)
    _seg(ax, A, B, color="tab:blue", lw=2.2)
    _seg(ax, B, C, color="0.35", lw=2.2)
    _seg(ax, C, D, color="tab:red", lw=2.2)
    _seg(ax, B, P, color="0.55", lw=1.2, ls="--")
    _seg(ax, A, D, color="k", lw=1.0, ls="-.")
    _length_label(ax, A, B, "$l_1$", side=1)
    _length_label(ax, B, C, "$l_2$", side=1)
    _length_label(ax, C, D, "$l_3$", side=-1)
    _length_label(ax, A, D, "$l_4$", side=-1)
    _length_label(ax, B, P, "$l_5$", side=-1)
    size = abs(D - A)
    # frame angle phi4 from the x direction, crank angle phi1 from AD, alpha from BC to BP
    phi4 = float(np.angle(D - A))
    _seg(ax, A, A + 0.35 * size, color="0.5", lw=0.8)
    _arc_mark(ax, A, 0.25 * size, min(0.0, phi4), max(0.0, phi4), r"$\varphi_4$")
    _arc_mark(ax, A, 0.12 * fb.a + 0.08 * size, phi4, phi4 + float(np.angle((B - A) / (D - A))) % (2 * np.pi),
              r"$\varphi_1$", color="tab:blue")
    bc = float(np.angle(C - B))
    _arc_mark(ax, B, 0.18 * abs(P - B), bc, bc + float(np.angle((P - B) / (C - B))), r"$\alpha$", color="0.3")
    # the ground frame and the crank pivot's coordinates
    lo = min(0.0, A.real, B.real, C.real, D.real, P.real) - 0.1 * size
    low = min(0.0, A.imag, B.imag, C.imag, D.imag, P.imag) - 0.1 * size
    right = max(A.real, B.real, C.real, D.real, P.real) + 0.1 * size
    top = max(A.imag, B.imag, C.imag, D.imag, P.imag) + 0.1 * size
    ax.plot([lo, right], [low, low], color="k", lw=0.8)
    ax.plot([lo, lo], [low, top], color="k", lw=0.8)
    ax.plot([right], [low], ">", color="k", ms=5)
    ax.plot([lo], [top], "^", color="k", ms=5)
    ax.text(right, low - 0.04 * size, "x", ha="center", va="top", fontsize=10)
    ax.text(lo - 0.04 * size, top, "y", ha="right", va="center", fontsize=10)
    ax.text(lo - 0.03 * size, low - 0.03 * size, "O", ha="right", va="top", fontsize=10)
    _seg(ax, complex(A.real, low), A, color="0.6", lw=0.7, ls=":")
    _seg(ax, complex(lo, A.imag), A, color="0.6", lw=0.7, ls=":")
    ax.annotate("$x_A$", (A.real, low), textcoords="offset points", xytext=(0, -12), ha="center", fontsize=10)
    ax.annotate("$y_A$", (lo, A.imag), textcoords="offset points", xytext=(-14, 0), va="center", fontsize=10)
    for name, z in (("A", A), ("B", B), ("C", C), ("D", D), ("P", P)):
        ground = name in ("A", "D")
        ax.plot(z.real, z.imag, "s" if ground else "o", ms=6, mfc="k" if ground else "w", mec="k", zorder=5)
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(-14, 6) if name == "A" else (6, 6),
                    fontsize=11)
    ax.set_aspect("equal")
    ax.axis("off")
    return ax


def steering_variables(design, theta, ax=None):
    """The steering trapezoid of Example 2-23 (Fig. 2-112) straight ahead and turned by `theta`.

    `design` is a `SteeringTrapezoid`; both poses come from ``design.fourbar.solve`` at the
    input angles ``phi0`` and ``phi0 + theta``: kingpins A, D (track a), arms AB = CD = l1 at
    phi0 to the axle, tie rod BC = l2; turned, the arm AB has rotated by theta and CD by
    beta. The wheels (thick grey) turn with their arms.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(8.0, 4.0))
    pose = design.fourbar.solve(np.array([design.phi0, design.phi0 + theta]))
    a = design.a
    A, D = 0j, complex(a)
    beta = float(np.angle((pose.C[1] - D) / (pose.C[0] - D)))
    wheel = 0.22 * a
    for k, (B, C) in enumerate(zip(pose.B, pose.C)):
        straight = k == 0
        style = dict(lw=2.2 if straight else 1.2, ls="-" if straight else "--")
        _seg(ax, A, B, color="tab:blue", **style)
        _seg(ax, B, C, color="0.35", **style)
        _seg(ax, D, C, color="tab:red", **style)
        for pivot, turn, side in ((A, theta, -1.0), (D, beta, 1.0)):
            # a wheel just outside the kingpin, along the driving direction (+y), turned with its arm
            centre = pivot + side * 0.06 * a
            u = 1j * np.exp(1j * (turn if not straight else 0.0))
            _seg(ax, centre - 0.5 * wheel * u, centre + 0.5 * wheel * u, color="0.5",
                 lw=6 if straight else 3, alpha=0.6 if straight else 0.35, solid_capstyle="butt")
    _seg(ax, A, D, color="k", lw=3)
    B0, C0 = pose.B[0], pose.C[0]
    _length_label(ax, A, D, "a", side=-1, offset=12)
    _length_label(ax, A, B0, "$l_1$", side=-1, offset=10)
    _length_label(ax, D, C0, "$l_1$", side=1, offset=10)
    _length_label(ax, B0, C0, "$l_2$", side=1, offset=10)
    r = 0.3 * design.l1
    _arc_mark(ax, A, r, 0.0, design.phi0, r"$\varphi_0$", color="tab:blue", scale=1.5)
    _arc_mark(ax, D, r, np.pi - design.phi0, np.pi, r"$\varphi_0$", color="tab:red", scale=1.5)
    _arc_mark(ax, A, 0.75 * design.l1, design.phi0, design.phi0 + theta, r"$\theta$", color="tab:blue", scale=1.2)
    lo, hi = sorted((np.pi - design.phi0, np.pi - design.phi0 + beta))
    _arc_mark(ax, D, 0.75 * design.l1, lo, hi, r"$\beta$", color="tab:red", scale=1.2)
    for name, z, off in (("A", A, (-4, -16)), ("D", D, (-4, -16)), ("B", B0, (-14, 4)), ("C", C0, (6, 4))):
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=off, fontsize=11)
    ax.plot([0.0, a], [0.0, 0.0], "ks", ms=6)
    ax.set_aspect("equal")
    ax.axis("off")
    return ax


def grid_refinement(f, boxes, bests, ax=None, *, points=5, feasible=None, n=201, labels=("x1", "x2")):
    """The grid method with refinement (Fig. 2-111): each level's grid and its best point.

    ``boxes``: the box ``((lo1, hi1), (lo2, hi2))`` of each level; ``bests``: the best point
    after each level (e.g. ``grid_search(model, levels=k).x``); the first box also sets the
    contour plot of ``f`` (vectorised over points ``(..., 2)``); ``feasible`` (optional,
    same call form) shades the points where it is False.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(6.0, 5.0))
    (x0, x1), (y0, y1) = boxes[0]
    X, Y = np.meshgrid(np.linspace(x0, x1, n), np.linspace(y0, y1, n))
    XY = np.stack([X.ravel(), Y.ravel()], axis=-1)
    with np.errstate(all="ignore"):
        F = np.log10(f(XY)).reshape(X.shape)
    ax.contour(X, Y, np.where(np.isfinite(F), F, np.nan), levels=14, colors="0.6", linewidths=0.7)
    if feasible is not None:
        bad = ~np.asarray(feasible(XY), dtype=bool).reshape(X.shape)
        ax.contourf(X, Y, bad.astype(float), levels=[0.5, 1.5], colors=["0.85"])
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, ((lo1, hi1), (lo2, hi2)) in enumerate(boxes):
        c = colours[k % len(colours)]
        gx, gy = np.meshgrid(np.linspace(lo1, hi1, points), np.linspace(lo2, hi2, points))
        ax.plot(gx.ravel(), gy.ravel(), ".", color=c, ms=4)
        ax.plot([lo1, hi1, hi1, lo1, lo1], [lo2, lo2, hi2, hi2, lo2], "-", color=c, lw=1.0,
                label=f"level {k}")
        ax.plot(*bests[k], "o", color=c, ms=8, mfc="none", mew=1.5)
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    ax.legend(fontsize=8, loc="upper right")
    return ax


def conjugate_directions(f, centre, lines, minima, ax=None, *, box, n=301):
    """Concentric ellipses of a quadratic ``f`` with two parallel lines and their minima (Fig. 2-109).

    ``lines``: ``[(point, direction), ...]`` of the parallel search lines; ``minima``: the
    point where each line touches an ellipse (its line minimum). The line through the
    minima passes through the common centre and is conjugate to the search direction.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(6.0, 5.0))
    (x0, x1), (y0, y1) = box
    X, Y = np.meshgrid(np.linspace(x0, x1, n), np.linspace(y0, y1, n))
    F = f(np.stack([X, Y], axis=-1))
    levels = sorted({float(f(np.asarray(m, dtype=float))) for m in minima} |
                    set(np.linspace(0.0, F.max(), 12)[1:-1].tolist()))
    ax.contour(X, Y, F, levels=levels, colors="0.6", linewidths=0.8)
    span = max(x1 - x0, y1 - y0)
    for (p, d), m in zip(lines, minima):
        p, d = np.asarray(p, dtype=float), np.asarray(d, dtype=float) / np.linalg.norm(d)
        ends = np.array([p - 2 * span * d, p + 2 * span * d])
        ax.plot(ends[:, 0], ends[:, 1], "-", color="tab:blue", lw=1.0)
        ax.plot(*m, "o", color="tab:blue", ms=6)
    m = np.asarray(minima, dtype=float)
    u = (m[1] - m[0]) / np.linalg.norm(m[1] - m[0])
    ends = np.array([m[0] - 2 * span * u, m[0] + 2 * span * u])
    ax.plot(ends[:, 0], ends[:, 1], "--", color="tab:red", lw=1.2, label="conjugate direction")
    ax.plot(*centre, "k*", ms=10, label="common centre")
    for k, point in enumerate(m, 1):
        ax.annotate(f"$x^{{({k})}}$", tuple(point), textcoords="offset points", xytext=(6, -12), fontsize=10)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_xlabel("x1")
    ax.set_ylabel("x2")
    ax.legend(fontsize=8, loc="upper right")
    return ax
