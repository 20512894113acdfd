"""Figures of ``book/synthesis/path-generation.md``: a path-generating four-bar drawn in the
task frame with its coupler curve and the precision points. Nothing runs at import;
Matplotlib is imported by the functions."""

import numpy as np

__all__ = ["path_linkage"]


def path_linkage(design, ax=None, *, title=None, samples=721):
    """Draw a `PathFourBar` at its first point, its coupler curve, and the path points.

    The curve is the analysed coupler point over a full turn of the input (gaps where the
    linkage cannot be assembled); the part from the first point to the last, when the
    design meets them in order, is drawn bold. Ground black, crank blue, coupler grey,
    output red; path points numbered.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(5.5, 4.5))
    theta = design.theta_input[0] + np.linspace(0.0, 2.0 * np.pi, samples)
    ax.plot(design.coupler_point(theta).real, design.coupler_point(theta).imag, color="0.6", lw=1.0)
    if design.in_order:
        turn = np.remainder(design.direction * (design.theta_input[-1] - design.theta_input[0]), 2.0 * np.pi)
        run = design.theta_input[0] + design.direction * np.linspace(0.0, turn, samples)
        P = design.coupler_point(run)
        ax.plot(P.real, P.imag, color="tab:green", lw=2.2)
    A, B, C, D, P1 = design.A, design.B1, design.C1, design.D, design.points[0]
    ax.plot([A.real, D.real], [A.imag, D.imag], "k-", lw=3)
    ax.plot([A.real, B.real], [A.imag, B.imag], color="tab:blue", lw=2.2)
    ax.fill([B.real, C.real, P1.real], [B.imag, C.imag, P1.imag], color="0.85", ec="0.45", lw=1.6)
    ax.plot([D.real, C.real], [D.imag, C.imag], color="tab:red", lw=2.2)
    ax.plot([A.real, D.real], [A.imag, D.imag], "ks", ms=6)
    for name, z in (("A", A), ("B", B), ("C", C), ("D", D)):
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(4, 4))
    pts = design.points
    ax.plot(pts.real, pts.imag, "o", ms=5, mfc="white", mec="k")
    for i, z in enumerate(pts, start=1):
        ax.annotate(f"P{i}", (z.real, z.imag), textcoords="offset points", xytext=(5, -10), fontsize=8)
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


__all__ += ["crank_displacements"]


def crank_displacements(A, B, alpha, points=None, ax=None, *, title=None):
    """The crank as a displaced body (Fig. 2-106): its marker point A and marker angles alpha_i.

    ``B``: the crank pin in each position (e.g. from `displacement_matrix` with A as the
    reference point of every pose); ``alpha``: the marker angles (radians), drawn as arrows
    from A; ``points``: the path points P_i, joined to B_i by dashed lines (the coupler).
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(6.0, 5.0))
    A = complex(A)
    B = np.asarray(B, dtype=complex)
    r = abs(B[0] - A)
    ring = A + r * np.exp(1j * np.linspace(0.0, 2.0 * np.pi, 361))
    ax.plot(ring.real, ring.imag, ":", color="tab:blue", lw=0.9)
    ax.plot([A.real, A.real + 1.25 * r], [A.imag, A.imag], color="0.5", lw=0.8)
    for k, (b, al) in enumerate(zip(B, np.asarray(alpha, dtype=float)), start=1):
        ax.plot([A.real, b.real], [A.imag, b.imag], color="tab:blue", lw=2.2 if k == 1 else 1.2)
        tip = A + 0.55 * r * np.exp(1j * al)
        ax.annotate("", xy=(tip.real, tip.imag), xytext=(A.real, A.imag),
                    arrowprops={"arrowstyle": "-|>", "color": "tab:orange", "lw": 1.2})
        t = np.linspace(0.0, al, 40)
        rad = (0.12 + 0.06 * k) * r
        arc = A + rad * np.exp(1j * t)
        ax.plot(arc.real, arc.imag, color="tab:orange", lw=0.7)
        ax.annotate(f"$\\alpha_{k}$", (tip.real, tip.imag), textcoords="offset points", xytext=(3, 3),
                    color="tab:orange", fontsize=9)
        ax.plot([b.real], [b.imag], "o", ms=5, mfc="w", mec="tab:blue")
        ax.annotate(f"$B_{k}$", (b.real, b.imag), textcoords="offset points", xytext=(5, -12), fontsize=10)
        if points is not None:
            p = complex(np.asarray(points)[k - 1])
            ax.plot([b.real, p.real], [b.imag, p.imag], "--", color="0.5", lw=0.9)
            ax.plot([p.real], [p.imag], "k+", ms=8)
            ax.annotate(f"$P_{k}$", (p.real, p.imag), textcoords="offset points", xytext=(4, 4), fontsize=9)
    ax.plot([A.real], [A.imag], "ks", ms=7)
    ax.annotate("A", (A.real, A.imag), textcoords="offset points", xytext=(-14, -12), fontsize=11)
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    if title:
        ax.set_title(title, fontsize=10)
    return ax
