"""Figures of ``book/synthesis/quick-return.md``: quick-return designs drawn at their limit
positions (with the circle that sees the output's limit positions under the extreme angle),
gamma_min against alpha, and the shaper of exercise 2-32. Positions come from the analysis
classes. Nothing runs at import; Matplotlib is imported by the functions."""

import math

import numpy as np

from figures.limit_positions import _angle_arc

__all__ = ["crank_rocker_limits", "slider_crank_limits", "guide_bar_limits", "gamma_alpha_curves", "shaper",
           "marked_table", "crank_rocker_construction", "slider_crank_construction", "fourbar_limits",
           "REASONS", "table_differences", "slider_design", "crank_rocker_design", "difference_table"]


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
    for B, psi, name in zip(pose.B, pose.psi, ("1", "2")):
        end = d + design.min_guide_length * np.exp(1j * psi)
        ax.plot([d, end.real], [0.0, end.imag], color="tab:red", lw=1.6)
        ax.plot([0.0, B.real], [0.0, B.imag], color="tab:blue", lw=2.0)
        ax.plot([B.real], [B.imag], "s", ms=7, mfc="w", mec="k")
        _label(ax, B, "B" + name, -14 if B.real < 0 else 6, 6 if B.imag > 0 else -14)
    # the bisector of the guide's swing is the frame line; the swing equals theta
    _angle(ax, complex(d), 0.45 * d, float(pose.psi[0]), float(pose.psi[1]), "θ",
           color="tab:red", scale=1.2)
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


def _angle(ax, centre, radius, start, stop, text, *, color="k", scale=1.3):
    """Mark the angle between directions `start` and `stop` (radians, the short way) at `centre`."""
    _angle_arc(ax, centre, radius, start, stop, text, color, scale=scale, fontsize=10)


def _circle(ax, centre, radius, **style):
    ring = centre + radius * np.exp(1j * np.linspace(0.0, 2 * np.pi, 361))
    ax.plot(ring.real, ring.imag, **style)


def _segment(ax, p, q, **style):
    ax.plot([p.real, q.real], [p.imag, q.imag], **style)


def _circumcentre(p, q, r):
    """Centre of the circle through three points (complex)."""
    w = (r - p) / (q - p)
    return p + (q - p) * (w - abs(w) ** 2) / (w - w.conjugate())


def _direction(p, q):
    return float(np.angle(q - p))


def crank_rocker_construction(design, ax=None, *, given="crank", title=None):
    """The construction of a `QuickReturnCrankRocker` in its design frame (Figs. 2-95 to 2-97, 2-101).

    Drawn from the design's computed positions, placed with ``design.placement``: the rocker
    DC at its two limit positions (the isosceles triangle D C1 C2), the right triangle C2 C1 N
    whose angle at N is theta, the circle through C1, C2 and N about O (radius R, O at
    height H above D), the crank pivot A on it at the central angle alpha from C1, the lines
    AC1 = b - a and AC2 = b + a. With ``given="crank"`` (example 2-17) the point E on AC2
    with AE = AC1 marks EC2 = 2a; with ``given="coupler"`` (example 2-18) the point A' on C1A
    extended with AA' = AC2 marks C1A' = 2b, and A' lies on the circle through C1 and C2 on
    which they subtend theta/2 (dotted).
    """
    if given not in ("crank", "coupler"):
        raise ValueError(f"Expected `given` 'crank' or 'coupler', got {given!r}")
    ax = _axes(ax, (6.5, 6.5))
    a, b, c, d = design.lengths
    origin, rotation = design.placement
    turn = np.exp(1j * rotation)
    pose = design.fourbar.solve(np.array([design.theta_extended, design.theta_folded]))
    A, D = origin, origin + turn * d
    B2, B1 = origin + turn * pose.B
    C2, C1 = origin + turn * pose.C
    O = _circumcentre(A, C1, C2)
    R = abs(C1 - O)
    N = 2.0 * O - C2                               # C2 N is a diameter: the angle at C1 is right
    E = A + abs(C1 - A) * (C2 - A) / abs(C2 - A)
    pts = {"A": A, "D": D, "O": O, "N": N, "C1": C1, "C2": C2, "B1": B1, "B2": B2}
    if given == "crank":
        pts["E"] = E
    _circle(ax, O, R, ls="--", color="tab:green", lw=1.0)
    _segment(ax, C1, C2, color="k", lw=0.8)
    _segment(ax, C2, N, color="tab:green", lw=0.8, ls=":")
    _segment(ax, C1, N, color="tab:green", lw=0.8, ls=":")
    for C in (C1, C2):
        _segment(ax, D, C, color="tab:red", lw=1.8)
    _segment(ax, O, A, color="tab:green", lw=0.8)
    _segment(ax, O, C1, color="tab:green", lw=0.8)
    _segment(ax, O, D, color="0.5", lw=0.8, ls="-.")
    _segment(ax, A, C2, color="0.45", lw=1.0)
    _segment(ax, A, C1, color="0.45", lw=1.0)
    _segment(ax, A, B2, color="tab:blue", lw=2.4)
    _segment(ax, A, B1, color="tab:blue", lw=1.2)
    _segment(ax, A, D, color="k", lw=2.5)
    for name, z in pts.items():
        ax.plot([z.real], [z.imag], "s" if name in ("A", "D") else "o", ms=5,
                mfc="k" if name in ("A", "D") else "w", mec="k", zorder=5)
    size = abs(C2 - C1)
    for name, z in pts.items():
        away = z - (O if name != "O" else D)
        off = 12 * away / abs(away) if abs(away) > 0 else 0j
        off = complex(8, 2) if name == "E" else off
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(off.real - 4, off.imag - 4),
                    fontsize=10)
    r = 0.18 * size
    _angle(ax, A, r, _direction(A, C1), _direction(A, C2), "θ")
    _angle(ax, N, r, _direction(N, C1), _direction(N, C2), "θ", color="tab:green")
    _angle(ax, O, 0.25 * R, _direction(O, C1), _direction(O, A), "α",
           color="tab:green", scale=1.45)
    _angle(ax, D, 0.3 * c, _direction(D, C1), _direction(D, C2), "φ", color="tab:red")
    ax.text(*((O + 0.55 * (A - O)).real, (O + 0.55 * (A - O)).imag), "R", color="tab:green", fontsize=10)
    mid = 0.5 * (O + D)
    ax.annotate("H", (mid.real, mid.imag), textcoords="offset points", xytext=(8, -4), color="0.4", fontsize=10)
    if given == "crank":
        _segment(ax, E, C2, color="tab:purple", lw=3.0, alpha=0.6, solid_capstyle="butt")
    else:
        A2 = A + abs(C2 - A) * (A - C1) / abs(A - C1)
        O2 = _circumcentre(A2, C1, C2)
        _circle(ax, O2, abs(C1 - O2), ls=":", color="tab:purple", lw=1.0)
        _segment(ax, C1, A2, color="tab:purple", lw=3.0, alpha=0.6, solid_capstyle="butt")
        _segment(ax, A2, C2, color="tab:purple", lw=0.8)
        ax.plot([A2.real], [A2.imag], "o", ms=5, mfc="w", mec="tab:purple", zorder=5)
        ax.annotate("A'", (A2.real, A2.imag), textcoords="offset points", xytext=(-14, 4), color="tab:purple",
                    fontsize=10)
        _angle(ax, A2, 1.5 * r, _direction(A2, C1), _direction(A2, C2),
               "θ/2", color="tab:purple", scale=1.6)
        pts["A'"] = A2
    # the view: the first circle and every named point (the theta/2 circle may leave it)
    box = np.array(list(pts.values()) + [O + R * np.exp(1j * t) for t in np.linspace(0, 2 * np.pi, 73)])
    pad = 0.08 * R
    ax.set_xlim(box.real.min() - pad, box.real.max() + pad)
    ax.set_ylim(box.imag.min() - pad, box.imag.max() + pad)
    ax.axis("off")
    ax.set_aspect("equal")
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def slider_crank_construction(design, ax=None, *, title=None):
    """The construction of a `QuickReturnSliderCrank` (Figs. 2-98 and 2-103).

    The slider's limit positions C1 and C2 are H apart on the guide; the circle through
    them on which they subtend theta (centre O) carries the crank pivot A, which lies at the
    offset e from the guide and at the central angle alpha from C1. Both limit positions
    are drawn from the design's `SliderCrank` (extended bold).
    """
    ax = _axes(ax, (6.5, 5.0))
    a, b, e = design.lengths
    pose = design.slider_crank.solve(np.array([design.theta_extended, design.theta_folded]))
    A = 0j
    B2, B1 = pose.B
    C2, C1 = pose.C
    O = _circumcentre(A, C1, C2)
    R = abs(C1 - O)
    _circle(ax, O, R, ls="--", color="tab:green", lw=1.0)
    span = np.array([min(-a, O.real - R), C2.real + 0.15 * design.stroke])
    ax.plot(span, [e, e], "k-", lw=1.0)
    ax.plot(span, [0.0, 0.0], ":", color="0.5", lw=0.8)
    foot = complex(A.real, e)
    _segment(ax, A, foot, color="0.5", lw=0.8)
    ax.text(A.real + 0.02 * design.stroke, 0.5 * e, "e", color="0.3", fontsize=10)
    _segment(ax, O, A, color="tab:green", lw=0.8)
    _segment(ax, O, C1, color="tab:green", lw=0.8)
    _segment(ax, O, C2, color="tab:green", lw=0.8)
    for B, C, lw in ((B2, C2, 2.4), (B1, C1, 1.1)):
        _segment(ax, A, B, color="tab:blue", lw=lw)
        _segment(ax, B, C, color="0.45", lw=lw)
        ax.plot([C.real], [C.imag], "s", ms=9, mfc="w", mec="tab:red", zorder=5)
    _segment(ax, A, C1, color="0.6", lw=0.8, ls="--")
    r = 0.12 * design.stroke
    _angle(ax, A, 1.5 * r, _direction(A, C2), _direction(A, C1), "θ", scale=1.35)
    _angle(ax, O, 0.3 * R, _direction(O, C1), _direction(O, A), "α",
           color="tab:green", scale=1.35)
    ax.annotate("", xy=(C2.real, e + 0.12 * design.stroke), xytext=(C1.real, e + 0.12 * design.stroke),
                arrowprops=dict(arrowstyle="<->", color="k", lw=0.8))
    ax.text(0.5 * (C1.real + C2.real), e + 0.15 * design.stroke, "H", ha="center", fontsize=10)
    for name, z, off in (("A", A, (-12, -12)), ("O", O, (4, -12)), ("C1", C1, (-20, 5)), ("C2", C2, (6, 5)),
                         ("B1", B1, (-14, -4)), ("B2", B2, (4, 4))):
        ax.plot([z.real], [z.imag], "o", ms=4, color="k", zorder=6)
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=off, fontsize=10)
    ax.axis("off")
    return _finish(ax, title)


def fourbar_limits(fourbar, ax=None, *, title=None):
    """Draw a crank-rocker `FourBar` at its limit positions from `FourBar.limit_positions`,
    with the line through C1 and C2 (for K = 1 it passes through A, Fig. 2-100)."""
    ax = _axes(ax, (6.0, 4.5))
    lp = fourbar.limit_positions()
    pose = fourbar.solve(np.array([lp.theta_extended, lp.theta_folded]))
    d = fourbar.d
    C2, C1 = pose.C
    u = (C2 - C1) / abs(C2 - C1)
    s = np.real((0j - C1) * np.conj(u))           # A's abscissa along C1 -> C2
    span = abs(C2 - C1)
    ends = C1 + u * np.array([min(s, 0.0) - 0.6 * fourbar.a, max(s, span) + 0.3 * span])
    ax.plot(ends.real, ends.imag, ":", color="tab:green", lw=1.0)
    ax.plot([0.0, d], [0.0, 0.0], "k-", lw=3)
    a = fourbar.a
    _circle(ax, 0j, a, ls=":", color="tab:blue", lw=1.0)
    for i, (B, C, name) in enumerate(zip(pose.B, pose.C, ("2", "1"))):
        lw = 2.4 if i == 0 else 1.0
        _segment(ax, 0j, B, color="tab:blue", lw=lw)
        _segment(ax, B, C, color="0.45", lw=lw)
        _segment(ax, complex(d), C, color="tab:red", lw=lw)
        ax.plot([B.real, C.real], [B.imag, C.imag], "o", ms=3.5, color="k")
        _label(ax, B, "B" + name)
        _label(ax, C, "C" + name)
    _angle(ax, complex(d), 0.35 * fourbar.c, _direction(complex(d), C1),
           _direction(complex(d), C2), "φ", color="tab:red")
    ax.plot([0.0, d], [0.0, 0.0], "ks", ms=6)
    _label(ax, 0j, "A", 4, -14)
    _label(ax, complex(d), "D", 4, -12)
    return _finish(ax, title)


#: Why a printed cell differs from the regenerated one (see `table_differences`).
REASONS = {
    "flat": "flat optimum: a design with the printed value is as good to the table's digits",
    "rounding": "rounding: one unit in the last printed digit, and the printed design is worse",
    "misprint": "misprint: more than one unit off, and the printed design is worse",
    "lost": "lost: the printed cell is empty",
}


def table_differences(printed, computed, design, *, ratio_unit=0.001, angle_unit=0.01,
                      angle_keys=("gamma", "theta")):
    """Every printed cell that differs from the regenerated one by more than half a unit of
    its last digit, with the reason.

    `printed` and `computed` map a row key ("a/c", "gamma", ...) to the values over the
    table's K; `computed` also holds "alpha" (degrees, the optimal design parameter) and
    "gamma". `design(i, alpha_deg)` gives the ratios and "gamma" of the family of column i at
    the parameter alpha. For a ratio cell the parameter at which the family takes the printed
    value is found next to the optimum (`design` None skips this: a table of angles only);
    if the minimum transmission angle there is within
    half a unit of the optimum's, the cell is "flat" (the optimum is too flat for the table's
    digits to pin it), otherwise "rounding" (one unit) or "misprint". Returns a list of
    ``(row_key, index, printed, computed, reason, gamma_at_printed)``.
    """
    from scipy.optimize import brentq

    out = []
    for key, row in printed.items():
        unit = angle_unit if key in angle_keys else ratio_unit
        for i, (p, c) in enumerate(zip(row, computed[key])):
            if p != p:
                out.append((key, i, p, float(c), "lost", float("nan")))
                continue
            if abs(p - c) <= 0.5 * unit + 1e-12:
                continue
            gamma_at = float("nan")
            if key not in angle_keys and design is not None:
                best = float(computed["alpha"][i])
                f = lambda al: design(i, al)[key] - p
                for step in (0.5, 1.0, 2.0, 4.0):
                    lo, hi = best - step, best + step
                    # the side of the optimum on which the family passes the printed value
                    if f(lo) * f(best) < 0:
                        gamma_at = design(i, brentq(f, lo, best, xtol=1e-12))["gamma"]
                        break
                    if f(hi) * f(best) < 0:
                        gamma_at = design(i, brentq(f, best, hi, xtol=1e-12))["gamma"]
                        break
            if gamma_at == gamma_at and float(computed["gamma"][i]) - gamma_at < 0.5 * angle_unit:
                reason = "flat"
            elif abs(p - c) <= unit + 1e-12:
                reason = "rounding"
            else:
                reason = "misprint"
            out.append((key, i, p, float(c), reason, gamma_at))
    return out


def slider_design(time_ratios):
    """`design` of `table_differences` for table 2-5 (offset slider-cranks, H = 1)."""
    from mech.planar.synthesis import quick_return_slider_crank

    def design(i, alpha_deg):
        q = quick_return_slider_crank(time_ratios[i], 1.0, alpha=math.radians(alpha_deg))
        a, b, e = q.lengths[:3]
        return {"a/H": a, "b/H": b, "e/H": e, "gamma": math.degrees(q.check().min_transmission_angle)}
    return design


def crank_rocker_design(time_ratios, swing_deg):
    """`design` of `table_differences` for one row group of table 2-3 (crank-rockers, c = 1)."""
    from mech.planar.synthesis import quick_return_crank_rocker

    def design(i, alpha_deg):
        q = quick_return_crank_rocker(time_ratios[i], 1.0, math.radians(swing_deg), alpha=math.radians(alpha_deg))
        a, b, _, d = q.lengths
        return {"a/c": a, "b/c": b, "d/c": d, "gamma": math.degrees(q.check().min_transmission_angle)}
    return design


def difference_table(differences, time_ratios, *, groups=None):
    """A Markdown table with one row per differing cell of `table_differences`; `groups`, if
    given, labels each row with its swing (table 2-3)."""
    head = "| " + ("swing (°) | " if groups is not None else "") + \
        "K | quantity | printed | regenerated | $\\gamma_{\\min}$ of the printed value (°) | reason |"
    lines = [head, "|" + "---|" * (7 if groups is not None else 6)]
    for n, (key, i, p, c, reason, gamma_at) in enumerate(differences):
        gam = "" if gamma_at != gamma_at else f"{gamma_at:.3f}"
        shown = "lost" if p != p else f"{p:g}"
        digits = 2 if key in ("gamma", "theta") else 4
        lines.append("| " + (f"{groups[n]} | " if groups is not None else "") +
                     f"{time_ratios[i]:.2f} | {key} | {shown} | {c:.{digits}f} | {gam} | {reason} |")
    return "\n".join(lines)
