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
