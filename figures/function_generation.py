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
