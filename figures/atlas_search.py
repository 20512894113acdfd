"""A search of the coupler-curve atlas: the target, the best matches placed on it, and the best
linkage drawn at several input angles with its cognates' pivots.

Plain plotting function: takes the target points and the ``Match`` records that
``mech.atlas.query`` returned, draws, and returns the axes. Nothing is computed at import.
"""

import numpy as np

__all__ = ["arc_figure", "search_figure"]


def _poses(match, count):
    """Pin positions (A, B, C, D, P) of the placed match at `count` input angles in its range."""
    f = match.linkage.fourbar
    lo, hi = match.theta_range
    theta = np.linspace(lo, hi, count, endpoint=match.full_turn is False)
    if not match.full_turn:                          # stay inside the rocking range
        theta = 0.5 * (lo + hi) + 0.45 * (hi - lo) * np.sin(np.linspace(-np.pi / 2, np.pi / 2, count))
    pose = f.solve(theta)
    A, D = match.linkage.pivots
    return [(A, match.linkage.place(b), match.linkage.place(c), D, match.linkage.place(p))
            for b, c, p, ok in zip(pose.B, pose.C, pose.P, pose.valid) if ok]


def search_figure(target, matches, axes=None, poses=4):
    """Draw the target and the matches (left), and the best match at `poses` input angles (right)."""
    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(1, 2, figsize=(11.0, 6.0), layout="constrained")
    left, right = axes
    left.plot(target.real, target.imag, ".", color="0.3", ms=3, label="target (noisy)")
    for m in matches:
        curve = np.append(m.curve, m.curve[0])
        left.plot(curve.real, curve.imag, lw=2.5 if m.rank == 0 else 1.0,
                  label=f"#{m.rank}: row {m.index}, {m.kind}, error {100 * m.relative_error:.2g} %")
    left.set_title("Target and best matches, placed on it")
    left.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14))
    best = matches[0]
    curve = np.append(best.curve, best.curve[0])
    right.plot(curve.real, curve.imag, color="tab:blue", lw=1.5)
    for A, B, C, D, P in _poses(best, poses):
        right.plot([A.real, B.real, C.real, D.real], [A.imag, B.imag, C.imag, D.imag], "-o",
                   color="black", lw=1.2, ms=3)
        right.fill([B.real, C.real, P.real], [B.imag, C.imag, P.imag], color="tab:orange", alpha=0.3)
        right.plot(P.real, P.imag, "o", color="tab:red", ms=4)
    A, D = best.linkage.pivots
    right.plot([A.real, D.real], [A.imag, D.imag], "k^", ms=9, label="pivots A, D")
    if best.cognates:
        K = best.cognates[0].pivots[1]
        right.plot(K.real, K.imag, "s", color="tab:green", ms=8, label="third pivot K of the cognates")
    right.set_title(f"Best match at {poses} input angles")
    right.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14))
    for ax in axes:
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
    return axes


def arc_figure(target, matches, wholes, ax=None):
    """Draw an open target (dots), the matched parts of the matches' curves (solid) and
    the rest of each closed curve (dashed); ``wholes[i]`` is match i's closed curve, placed."""
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(7.0, 5.5), layout="constrained")
    ax.plot(target.real, target.imag, ".", color="0.3", ms=3, label="target arc (noisy)")
    for m, whole in zip(matches, wholes):
        closed = np.append(whole, whole[0])
        line, = ax.plot(m.curve.real, m.curve.imag, lw=2.5 if m.rank == 0 else 1.2,
                        label=f"#{m.rank}: row {m.index}, {m.kind}, error {100 * m.relative_error:.2g} %")
        ax.plot(closed.real, closed.imag, "--", lw=0.8, color=line.get_color())
        A, D = m.linkage.pivots
        ax.plot([A.real, D.real], [A.imag, D.imag], "^", color=line.get_color(), ms=7)
    ax.set_title("An open target and the parts of closed coupler curves that match it")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12))
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    return ax


def slider_figure(target, match, ax=None, poses=4):
    """Draw a slider-crank match: the target, the placed coupler curve, the guide line and
    the linkage at `poses` crank angles."""
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(7.0, 5.5), layout="constrained")
    placed = match.linkage
    sc = placed.slider
    p, q = placed.coupler
    ax.plot(target.real, target.imag, ".", color="0.3", ms=3, label="target (noisy)")
    curve = np.append(match.curve, match.curve[0])
    ax.plot(curve.real, curve.imag, color="tab:blue", lw=1.5,
            label=f"row {match.index}, {match.kind}, error {100 * match.relative_error:.2g} %")
    theta = np.linspace(0.0, 2.0 * np.pi, poses, endpoint=False) + 0.3
    pose = sc.solve(theta)
    P = pose.B + (p + 1j * q) * np.exp(1j * pose.phi)
    A = placed.origin
    B, C, P = placed.place(pose.B), placed.place(pose.C), placed.place(P)
    xs = np.concatenate([[0.0], pose.C.real])
    ends = placed.place(np.array([xs.min() - 0.3 * sc.b, xs.max() + 0.3 * sc.b]) + 1j * sc.e)
    ax.plot(ends.real, ends.imag, "--", color="0.5", lw=1.0, label="guide line")
    for b, c, pt in zip(B, C, P):
        ax.plot([A.real, b.real, c.real], [A.imag, b.imag, c.imag], "-o", color="black", lw=1.2, ms=3)
        ax.fill([b.real, c.real, pt.real], [b.imag, c.imag, pt.imag], color="tab:orange", alpha=0.3)
        ax.plot(pt.real, pt.imag, "o", color="tab:red", ms=4)
    ax.plot(A.real, A.imag, "k^", ms=9, label="crank pivot A")
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12))
    return ax
