"""Figures of ``book/synthesis/function-generation.md``: a planar function generator drawn at
its precision positions, its output against the target, and structural-error curves.
Nothing runs at import; Matplotlib is imported by the functions."""

import numpy as np

__all__ = ["linkage_positions", "output_curves", "error_curves"]


def linkage_positions(generator, x, ax=None, *, title=None):
    """Draw the four-bar of a `FunctionGenerator` at the input rotations `x`.

    The ground AD is black, the input AB blue, the coupler BC grey and the output DC red; the
    first position is bold, the others thin. Positions come from ``generator.solve``.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(5.5, 4.5))
    d = generator.lengths[3]
    pose = generator.solve(np.asarray(x, dtype=float))
    ax.plot([0.0, d], [0.0, 0.0], "k-", lw=3)
    for i, (B, C) in enumerate(zip(np.atleast_1d(pose.B), np.atleast_1d(pose.C))):
        lw = 2.4 if i == 0 else 1.0
        ax.plot([0.0, B.real], [0.0, B.imag], color="tab:blue", lw=lw)
        ax.plot([B.real, C.real], [B.imag, C.imag], color="0.45", lw=lw)
        ax.plot([d, C.real], [0.0, C.imag], color="tab:red", lw=lw)
        ax.plot([B.real, C.real], [B.imag, C.imag], "o", ms=3.5, color="k")
        if i == 0:
            ax.annotate("B", (B.real, B.imag), textcoords="offset points", xytext=(4, 4))
            ax.annotate("C", (C.real, C.imag), textcoords="offset points", xytext=(4, 4))
    ax.plot([0.0, d], [0.0, 0.0], "ks", ms=6)
    ax.annotate("A", (0.0, 0.0), textcoords="offset points", xytext=(-12, -12))
    ax.annotate("D", (d, 0.0), textcoords="offset points", xytext=(4, -12))
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def output_curves(u, curves, target, ax=None, *, xlabel="x", ylabel="y"):
    """Generated values against the function's argument `u`, with the target dashed.

    `curves` maps a label to generated values over `u` (NaN where the linkage does not
    assemble: the curve stops there); `target` is the function's values over `u`.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 3.6))
    ax.plot(u, target, "k--", lw=1.2, label="target")
    for label, values in curves.items():
        ax.plot(u, values, lw=1.4, label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return ax


def error_curves(u, errors, pairs=None, ax=None, *, xlabel="x", ylabel="structural error in y"):
    """Structural errors (in the function's units) against the function's argument `u`.

    `errors` maps a label to an array over `u`; `pairs` maps the same labels to the
    arguments of their precision points, marked on the zero line.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 3.6))
    for label, err in errors.items():
        line, = ax.plot(u, err, label=label, lw=1.4)
        if pairs and label in pairs:
            ax.plot(pairs[label], np.zeros(len(pairs[label])), "o", ms=4, color=line.get_color())
    ax.axhline(0.0, color="0.5", lw=0.6)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return ax


__all__ += ["inversion"]


def inversion(D, C1, A_inverted, B_inverted, ax=None, *, title=None):
    """The inversion of Figs. 2-92 and 2-93: the input link seen from the output link's first position.

    Holding the output link DC at its first position DC1 and turning the frame the other way
    about D, the input link AB takes the positions A_i B'_i (``A_inverted``,
    ``B_inverted``, ground frame of position 1): they are poses of a coupler whose pin B'_i
    stays on a circle about C1. Drawn: the output link (red), the inverted input-link
    positions (blue, the first bold), the reference points A_i on their circle about D
    (dotted), and the circle through the B'_i about C1 (green) with the coupler radii.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(5.5, 4.5))
    D, C1 = complex(D), complex(C1)
    A_i, B_i = np.asarray(A_inverted, dtype=complex), np.asarray(B_inverted, dtype=complex)
    ring = np.exp(1j * np.linspace(0.0, 2.0 * np.pi, 361))
    ax.plot((D + abs(A_i[0] - D) * ring).real, (D + abs(A_i[0] - D) * ring).imag, ":", color="0.5", lw=0.9)
    radius = abs(B_i[0] - C1)
    ax.plot((C1 + radius * ring).real, (C1 + radius * ring).imag, "--", color="tab:green", lw=1.0)
    ax.plot([D.real, C1.real], [D.imag, C1.imag], color="tab:red", lw=2.4)
    for k, (a, b) in enumerate(zip(A_i, B_i)):
        lw = 2.4 if k == 0 else 1.2
        ax.plot([D.real, a.real], [D.imag, a.imag], color="k", lw=0.8 if k else 2.5, ls="-" if k == 0 else ":")
        ax.plot([a.real, b.real], [a.imag, b.imag], color="tab:blue", lw=lw)
        ax.plot([b.real, C1.real], [b.imag, C1.imag], color="tab:green", lw=0.8)
        ax.plot([a.real], [a.imag], "s", ms=5, color="k" if k == 0 else "0.5")
        ax.plot([b.real], [b.imag], "o", ms=5, mfc="w", mec="tab:blue")
        sub = str(k + 1)
        ax.annotate("A" if k == 0 else f"$A_{sub}$", (a.real, a.imag), textcoords="offset points",
                    xytext=(-14, -12), fontsize=10)
        ax.annotate("$B_1$" if k == 0 else f"$B'_{sub}$", (b.real, b.imag), textcoords="offset points",
                    xytext=(5, 4), fontsize=10)
    ax.plot([D.real], [D.imag], "ks", ms=6)
    ax.annotate("D", (D.real, D.imag), textcoords="offset points", xytext=(5, -12), fontsize=10)
    ax.plot([C1.real], [C1.imag], "o", ms=6, color="tab:green")
    ax.annotate("$C_1$", (C1.real, C1.imag), textcoords="offset points", xytext=(6, 4), fontsize=10)
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    if title:
        ax.set_title(title, fontsize=10)
    return ax
