"""Figures for the chapter "Structure and types of four-bars" (textbook section 2.1).

Plain plotting functions: they take data and Matplotlib axes and draw; nothing runs at
import. Used by ``book/structure/index.md``.
"""

import numpy as np

__all__ = ["KIND_COLORS", "joint_sweeps", "plot_joint_types", "plot_prismatic_chain", "plot_reachable_region",
           "plot_kind_map", "plot_snapshots"]

#: One colour per four-bar kind, shared by every figure of the chapter.
KIND_COLORS = {
    "double-crank": "#4c72b0",
    "crank-rocker": "#55a868",
    "rocker-crank": "#8fbf7f",
    "double-rocker": "#dd8452",
    "triple-rocker": "#c44e52",
}


def plot_reachable_region(ax, a, b, c, d, *, title=None, n=721):
    """Draw the reachable-region test for joint A (the textbook's Fig. 2-4a).

    Ground pivots A = 0 and D = d. The pin B' of link AB moves on the circle of radius
    ``a`` about A; the pin B'' of link BC, held by CD, can reach the annulus about D with
    radii |b - c| and b + c (shaded). Arcs of the circle outside the annulus, where the
    chain cannot close, are drawn in red.
    """
    from matplotlib.patches import Wedge

    inner, outer = abs(b - c), b + c
    ax.add_patch(
        Wedge((d, 0.0), outer, 0, 360, width=outer - inner, facecolor="#c6dbef",
              edgecolor="#4c72b0", linewidth=1.0, label=r"reach of $B''$ about $D$")
    )
    theta = np.linspace(0.0, 2.0 * np.pi, n)
    B = a * np.exp(1j * theta)
    dist = np.abs(B - d)
    ok = (dist >= inner) & (dist <= outer)
    ax.plot(B.real, B.imag, color="black", linewidth=1.6, label=r"path of $B'$ about $A$")
    bad = np.where(ok, np.nan, 1.0)
    if not np.all(ok):
        ax.plot(B.real * bad, B.imag * bad, color="#c44e52", linewidth=3.0,
                label="chain cannot close")
    ax.plot([0.0, d], [0.0, 0.0], color="0.3", linewidth=2.5)
    ax.plot([0.0, d], [0.0, 0.0], "o", color="black", markersize=5)
    ax.annotate("A", (0.0, 0.0), textcoords="offset points", xytext=(-10, -12))
    ax.annotate("D", (d, 0.0), textcoords="offset points", xytext=(4, -12))
    ax.set_aspect("equal")
    span = max(outer, a) * 1.08
    ax.set_xlim(min(-a, d - outer) - 0.05 * span, max(a, d + outer) + 0.05 * span)
    ax.set_ylim(-span, span)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    if title:
        ax.set_title(title, fontsize=10)
    ax.legend(loc="lower left", fontsize=8, framealpha=0.9)
    return ax


def plot_kind_map(ax, intervals, *, name="length", marks=()):
    """Draw a type map: coloured bands of one varying link length, one per interval.

    ``intervals`` are records with ``low``, ``high``, ``kind``, ``closed_low`` and
    ``closed_high`` (as returned by ``mech.planar.kind_intervals``). A boundary length
    that belongs to an interval (a closed end) gets a dot in that interval's colour.
    ``marks`` are extra lengths to label on the axis.
    """
    seen = set()
    for r in intervals:
        color = KIND_COLORS[r.kind]
        label = r.kind if r.kind not in seen else None
        seen.add(r.kind)
        if r.high > r.low:
            ax.axvspan(r.low, r.high, ymin=0.3, ymax=0.7, facecolor=color, alpha=0.85,
                       label=label)
        else:
            ax.axvline(r.low, ymin=0.2, ymax=0.8, color=color, linewidth=3, label=label)
        for x, closed in ((r.low, r.closed_low), (r.high, r.closed_high)):
            if closed:
                ax.plot([x], [0.5], "o", color=color, markeredgecolor="black", markersize=7,
                        zorder=3)
    boundaries = sorted({r.low for r in intervals} | {r.high for r in intervals})
    ax.set_xticks(sorted(set(boundaries) | set(marks)))
    ax.set_xlim(boundaries[0], boundaries[-1])
    ax.set_ylim(0.0, 1.0)
    ax.set_yticks([])
    ax.set_xlabel(name)
    ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=len(seen), fontsize=8,
              frameon=False)
    return ax


def plot_snapshots(ax, linkage, thetas, *, kind=None, title=None):
    """Draw a `FourBar` at several crank angles, faint to solid in crank order, with the
    path of C (Fig. 2-5). ``kind`` picks the colour from `KIND_COLORS`."""
    from figures.fourbar import linkage_snapshot

    colour = KIND_COLORS.get(kind, "C0")
    thetas = np.asarray(thetas, dtype=float)
    for k, t in enumerate(thetas):
        linkage_snapshot(ax, linkage, t, color=colour, alpha=0.25 + 0.75 * (k + 1) / len(thetas))
    path = linkage.solve(np.linspace(thetas.min(), thetas.max(), 721)).C
    ax.plot(path.real, path.imag, ":", color="0.4", lw=1.0)
    ax.plot([0.0, linkage.d], [0.0, 0.0], color="black", lw=2.5)
    ax.set_aspect("equal")
    ax.grid(alpha=0.2)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def joint_sweeps(a, b, c, d, n=7201):
    """The poses of one circuit of the chain and the relative angle swept at each joint,
    in degrees: 360 minus the largest gap in the angles it takes (Fig. 2-6).

    A Grashof chain keeps to one assembly branch of `FourBar` over a crank turn (the other
    branch is the mirror circuit, reached only by taking the chain apart); a non-Grashof
    chain runs through both branches, meeting at its limit poses, in one circuit. Returns
    ``(poses, swept)``, poses a list of (theta, B, C) arrays, one per branch used.
    """
    from mech.planar import FourBar, grashof

    theta = np.linspace(0.0, 2.0 * np.pi, n)
    poses, rel = [], {j: [] for j in "ABCD"}
    for branch in ((1,) if grashof(a, b, c, d).grashof else (1, -1)):
        pose = FourBar(a, b, c, d, branch=branch).solve(theta)
        ok = pose.valid
        A, D = 0j, complex(d)
        B, C = pose.B[ok], pose.C[ok]
        poses.append((theta[ok], B, C))
        rel["A"].append(np.angle((B - A) / (D - A)))
        rel["B"].append(np.angle((C - B) / (A - B)))
        rel["C"].append(np.angle((D - C) / (B - C)))
        rel["D"].append(np.angle((A - D) / (C - D)))
    swept = {}
    for j, parts in rel.items():
        t = np.sort(np.mod(np.degrees(np.concatenate(parts)), 360.0))
        gaps = np.diff(np.concatenate([t, [t[0] + 360.0]]))
        swept[j] = 360.0 - gaps.max()
    return poses, swept


def plot_joint_types(ax, a, b, c, d, *, every=12, title=None):
    """Draw a chain at poses spread over its whole motion, marking each joint filled when
    `grashof` counts it fully rotatable and open when it rocks, with the angle the joint
    sweeps in a simulation (Fig. 2-6)."""
    from mech.planar import grashof

    r = grashof(a, b, c, d)
    colour = KIND_COLORS[r.kind]
    poses, swept = joint_sweeps(a, b, c, d)
    theta, B, C = poses[0]
    picks = np.linspace(0, len(theta) - 1, every).astype(int)
    for k in picks:
        z = np.array([0j, B[k], C[k], complex(d)])
        ax.plot(z.real, z.imag, "-", color=colour, alpha=0.35, lw=1.2)
    for _, Bb, Cb in poses:
        ax.plot(Bb.real, Bb.imag, ":", color="0.4", lw=0.8)
        ax.plot(Cb.real, Cb.imag, ":", color="0.4", lw=0.8)
    k = picks[len(picks) // 3]
    last = {"A": 0j, "B": complex(B[k]), "C": complex(C[k]), "D": complex(d)}
    z = np.array(list(last.values()))
    ax.plot(z.real, z.imag, "-", color=colour, lw=2.4)
    for name, p in last.items():
        full = name in r.revolving
        ax.plot([p.real], [p.imag], "o", ms=9, mec="black", mfc="black" if full else "white", zorder=4)
        ax.annotate(f"{name}: {swept[name]:.0f}°", (p.real, p.imag), textcoords="offset points",
                    xytext=(6, 6), fontsize=9)
    ax.plot([0.0, d], [0.0, 0.0], color="black", lw=2.5)
    ax.set_aspect("equal")
    ax.grid(alpha=0.2)
    ax.set_title(title or f"{r.kind} ({a:g}, {b:g}, {c:g}, {d:g})", fontsize=10)
    return ax


def plot_prismatic_chain(ax, solution, indices, *, title=None):
    """The R-P-P-P chain (Fig. 2-12a) at several poses of a `LinkageSolution`, faint to solid.

    The frame carries the sliding lines of DA (through D) and of BC (through C), dashed;
    AB is drawn from A to B, DA from D's line point to A, BC from C to B. The angle DAB at
    the revolute A, from the solved points, is written at A.
    """
    P = {k: np.asarray(v) for k, v in solution.points.items()}
    D, C = complex(P["D"].flat[0]), complex(P["C"].flat[0])
    u_da = complex(np.asarray(solution.direction("DA")).flat[0])
    u_bc = complex(np.asarray(solution.direction("BC")).flat[0])
    far = max(abs(P["A"]).max(), abs(P["B"] - C).max()) * 1.15
    for base, u in ((D, u_da), (C, u_bc)):
        ax.plot([base.real, (base + far * u).real], [base.imag, (base + far * u).imag], "--", color="0.55", lw=1.0)
    ax.plot([D.real, C.real], [D.imag, C.imag], color="black", lw=2.5)
    for k, i in enumerate(indices):
        alpha = 0.3 + 0.7 * (k + 1) / len(indices)
        A, B = complex(P["A"][i]), complex(P["B"][i])
        for z0, z1, colour in ((D + 0.35 * (A - D), A, "tab:blue"), (A, B, "tab:green"), (C + 0.35 * (B - C), B, "tab:purple")):
            ax.plot([z0.real, z1.real], [z0.imag, z1.imag], color=colour, lw=2.4, alpha=alpha,
                    solid_capstyle="round")
        ax.plot([A.real], [A.imag], "o", ms=6, mfc="white", mec="black", alpha=alpha, zorder=4)
        at_a = abs(np.degrees(np.angle((B - A) / (D - A))))
        ax.annotate(f"∠DAB = {at_a:.4f}°", (A.real, A.imag), textcoords="offset points", xytext=(8, -6),
                    fontsize=8, alpha=alpha)
    for name, z in (("D", D), ("C", C)):
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(-4, -14))
    ax.set_aspect("equal")
    ax.grid(alpha=0.2)
    if title:
        ax.set_title(title, fontsize=10)
    return ax
