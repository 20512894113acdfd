"""Figures of ``book/synthesis/quick-return.md``: quick-return designs drawn at their limit
positions (with the circle that sees the output's limit positions under the extreme angle),
gamma_min against alpha, and the shaper of exercise 2-32. Positions come from the analysis
classes. Nothing runs at import; Matplotlib is imported by the functions."""

import numpy as np

__all__ = ["crank_rocker_limits", "slider_crank_limits", "guide_bar_limits", "gamma_alpha_curves", "shaper",
           "marked_table"]


def marked_table(header, rows, errata, *, digits=3):
    """A Markdown table of regenerated values; a wrong printed entry shows as **value** (printed: p).

    `rows` is a list of ``(label, row_key, values)``; `errata` a list of
    ``(row_key, index, printed, computed)`` from `table_errata`. A printed NaN (lost) shows
    as "lost".
    """
    wrong = {(r, i): p for r, i, p, _ in errata}
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for label, key, values in rows:
        cells = []
        for i, v in enumerate(values):
            text = f"{v:.{digits}f}"
            if (key, i) in wrong:
                p = wrong[(key, i)]
                text = f"**{text}** (printed: {'lost' if p != p else p})"
            cells.append(text)
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def _axes(ax, size=(5.5, 4.5)):
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=size)
    return ax


def _label(ax, z, text, dx=4, dy=4):
    ax.annotate(text, (z.real, z.imag), textcoords="offset points", xytext=(dx, dy))


def _finish(ax, title):
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def crank_rocker_limits(design, ax=None, *, title=None):
    """Draw a `QuickReturnCrankRocker` at its extended (bold) and folded (thin) limit positions.

    The dashed circle is the circle through A, C1 and C2 on which A sees the rocker's two
    limit positions under the extreme angle theta; the crank circle is dotted.
    """
    ax = _axes(ax)
    fb = design.fourbar
    a, _, _, d = design.lengths
    pose = fb.solve(np.array([design.theta_extended, design.theta_folded]))
    origin, rotation = design.placement
    centre = -origin * np.exp(-1j * rotation)
    t = np.linspace(0.0, 2 * np.pi, 361)
    ax.plot((centre + abs(origin) * np.exp(1j * t)).real, (centre + abs(origin) * np.exp(1j * t)).imag,
            "--", color="tab:green", lw=1.0)
    ax.plot(a * np.cos(t), a * np.sin(t), ":", color="tab:blue", lw=1.0)
    ax.plot([0.0, d], [0.0, 0.0], "k-", lw=3)
    for i, (B, C, name) in enumerate(zip(pose.B, pose.C, ("2", "1"))):
        lw = 2.4 if i == 0 else 1.0
        ax.plot([0.0, B.real], [0.0, B.imag], color="tab:blue", lw=lw)
        ax.plot([B.real, C.real], [B.imag, C.imag], color="0.45", lw=lw)
        ax.plot([d, C.real], [0.0, C.imag], color="tab:red", lw=lw)
        ax.plot([B.real, C.real], [B.imag, C.imag], "o", ms=3.5, color="k")
        _label(ax, B, "B" + name)
        _label(ax, C, "C" + name)
    ax.plot([0.0, d], [0.0, 0.0], "ks", ms=6)
    _label(ax, 0j, "A", -12, -12)
    _label(ax, complex(d), "D", 4, -12)
    return _finish(ax, title)


def slider_crank_limits(design, ax=None, *, title=None):
    """Draw a `QuickReturnSliderCrank` at its two limit positions, with the guide line."""
    ax = _axes(ax)
    sc = design.slider_crank
    a, b, e = design.lengths
    pose = sc.solve(np.array([design.theta_extended, design.theta_folded]))
    t = np.linspace(0.0, 2 * np.pi, 361)
    ax.plot(a * np.cos(t), a * np.sin(t), ":", color="tab:blue", lw=1.0)
    x = np.array([-a, a + b]) * 1.05
    ax.plot(x, [e, e], "k-", lw=1.0)
    for i, (B, C, name) in enumerate(zip(pose.B, pose.C, ("2", "1"))):
        lw = 2.4 if i == 0 else 1.0
        ax.plot([0.0, B.real], [0.0, B.imag], color="tab:blue", lw=lw)
        ax.plot([B.real, C.real], [B.imag, C.imag], color="0.45", lw=lw)
        ax.plot([C.real], [C.imag], "s", ms=8, mfc="w", mec="tab:red")
        _label(ax, C, "C" + name, 4, 8)
    ax.plot([0.0], [0.0], "ks", ms=6)
    _label(ax, 0j, "A", -12, -12)
    return _finish(ax, title)


def guide_bar_limits(design, ax=None, *, title=None):
    """Draw a `QuickReturnGuideBar` with the guide at its two limit positions (tangent to the crank circle)."""
    ax = _axes(ax)
    gb = design.guide_bar
    a, d = gb.a, gb.d
    # at a limit the crank is perpendicular to the guide: cos(theta) = a / d
    theta = np.array([1.0, -1.0]) * (np.pi / 2 - design.extreme_angle / 2)
    pose = gb.solve(theta)
    t = np.linspace(0.0, 2 * np.pi, 361)
    ax.plot(a * np.cos(t), a * np.sin(t), ":", color="tab:blue", lw=1.0)
    ax.plot([0.0, d], [0.0, 0.0], "k-", lw=3)
    for B, psi in zip(pose.B, pose.psi):
        end = d + design.min_guide_length * np.exp(1j * psi)
        ax.plot([d, end.real], [0.0, end.imag], color="tab:red", lw=1.6)
        ax.plot([0.0, B.real], [0.0, B.imag], color="tab:blue", lw=2.0)
        ax.plot([B.real], [B.imag], "s", ms=7, mfc="w", mec="k")
    ax.plot([0.0, d], [0.0, 0.0], "ks", ms=6)
    _label(ax, 0j, "A", -12, -12)
    _label(ax, complex(d), "D", 4, -12)
    return _finish(ax, title)


def gamma_alpha_curves(alpha, curves, ax=None, *, permitted=None, title=None):
    """gamma_min (degrees) against alpha (degrees): `curves` maps a label to values (NaN: no design)."""
    ax = _axes(ax, (6.0, 4.0))
    for label, values in curves.items():
        ax.plot(alpha, values, label=label)
    if permitted is not None:
        ax.axhline(permitted, color="k", lw=0.8, ls="--")
    ax.set_xlabel("alpha = angle AOC1 (°)")
    ax.set_ylabel("minimum transmission angle (°)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def shaper(design, ax=None, *, title=None):
    """Draw the shaper of exercise 2-32 at the two limit positions of its ram."""
    ax = _axes(ax, (5.0, 6.0))
    gb = design.guide_bar
    a, d = gb.a, gb.d
    beta = np.pi / 2 - np.arcsin(a / d)          # crank angles where the guide is tangent
    theta = np.array([beta, -beta])
    pose = gb.solve(theta)
    t = np.linspace(0.0, 2 * np.pi, 361)
    ax.plot(a * np.cos(t), a * np.sin(t), ":", color="tab:blue", lw=1.0)
    yE = design.ram(theta)
    for B, psi, y in zip(pose.B, pose.psi, yE):
        D = d + design.l_CD * np.exp(1j * psi)
        E = complex(design.x_ram, y)
        ax.plot([d, D.real], [0.0, D.imag], color="tab:red", lw=1.6)
        ax.plot([0.0, B.real], [0.0, B.imag], color="tab:blue", lw=2.0)
        ax.plot([D.real, E.real], [D.imag, E.imag], color="0.45", lw=1.6)
        ax.plot([E.real], [E.imag], "s", ms=8, mfc="w", mec="k")
    ax.axvline(design.x_ram, color="k", lw=0.8)
    ax.plot([0.0, d], [0.0, 0.0], "ks", ms=6)
    _label(ax, 0j, "A", -12, -12)
    _label(ax, complex(d), "C", 4, -12)
    return _finish(ax, title)
