"""Figures of the exercises, drawn from a variant's own numbers (Matplotlib, imported here
only when a figure is asked for).

The textbook's figures (2-19, 2-20, 2-24 ...) and the assumed layouts of the exercises whose
figure is lost are drawn again for each variant: a linkage in the pose the statement names,
with its fixed pivots, guides and point names; a wheel, a wedge, a brake or a screw jack as
a labelled schematic with the variant's dimensions. The drawings show the givens only,
never an answer; they are schematic (not a construction to measure from).
:func:`figure_png` returns PNG bytes for sheets, quizzes and PDFs.
"""

from __future__ import annotations

import io
import math

import numpy as np

__all__ = ["figure_png", "draw"]


def _xy(z):
    z = np.asarray(z, dtype=complex)
    return z.real, z.imag


def _pivot(ax, z, size):
    x, y = _xy(z)
    ax.fill([x, x - size, x + size], [y, y - 1.6 * size, y - 1.6 * size], color="0.85", ec="0.3", lw=0.8, zorder=1)
    ax.plot([x - 1.5 * size, x + 1.5 * size], [y - 1.6 * size] * 2, color="0.3", lw=1.0)


def _input(lk, p):
    """The driver's value for the pose the statement names (its crank angle), in radians."""
    for name in ("theta", "theta1", "phi1"):
        if name in p:
            return math.radians(p[name])
    return math.radians(60.0)


def linkage(ax, lk, value, *, title=None):
    """Draw the `mech.planar.Linkage` ``lk`` at the driver value ``value``: every moving link
    as a polygon through its points, fixed pivots as triangles, fixed guides dashed."""
    sol = lk.solve(np.array([value]))
    if not bool(np.all(sol.valid)):
        for v in np.linspace(0.0, 2 * math.pi, 25):
            sol = lk.solve(np.array([v]))
            if bool(np.all(sol.valid)):
                break
    pts = {k: complex(np.ravel(v)[0]) for k, v in sol.points.items()}
    members, guides, ground = {}, [], []
    for step in lk._steps:                       # the assembly steps say which points share a link
        d = dict(step.data)
        links = step.links
        if step.kind == "ground":
            ground.append(step.label)
        elif step.kind == "crank":
            members.setdefault(links[0], []).extend([d["pivot"], d["tip"]])
        elif step.kind == "rrr":
            members.setdefault(links[0], []).extend([d["pins"][0], d["joint"]])
            members.setdefault(links[1], []).extend([d["pins"][1], d["joint"]])
        elif step.kind in ("rrp", "slider"):
            pin = d.get("pin")
            joint = d.get("joint", d.get("point"))
            if pin:
                members.setdefault(links[0], []).extend([pin, joint])
            guides.append((d["guide"], joint))
        elif step.kind == "rpr":
            members.setdefault(links[0], []).extend(list(d["pins"]))
        elif step.kind == "point":
            members.setdefault(links[0], []).append(step.label)
        else:
            for key in ("pin", "joint", "point"):
                if isinstance(d.get(key), str):
                    members.setdefault(links[0], []).append(d[key])
    every = np.array(list(pts.values()))
    span = float(max(np.ptp(every.real), np.ptp(every.imag))) or 1.0
    for guide, joint in guides:
        if guide.link != "ground":
            continue
        through = pts.get(guide.through) if isinstance(guide.through, str) else complex(guide.through)
        if through is None:
            continue
        e = complex(math.cos(guide.angle), math.sin(guide.angle))
        ax.axline(_xy(through), _xy(through + e), color="0.5", lw=0.9, ls="--", zorder=0)
        if joint in pts:
            x, y = _xy(pts[joint])
            w = 0.05 * span
            ax.add_patch(__import__("matplotlib.patches", fromlist=["Rectangle"]).Rectangle(
                (x - w, y - w / 2), 2 * w, w, angle=math.degrees(guide.angle), rotation_point="center",
                fc="white", ec="tab:blue", lw=1.5, zorder=3))
    for k, (name, names) in enumerate(members.items()):
        chain = list(dict.fromkeys(n for n in names if n in pts))
        if len(chain) < 2:
            continue
        if len(chain) > 2:
            chain.append(chain[0])
        ax.plot(*_xy([pts[n] for n in chain]), "-o", color="tab:blue", lw=2.0, ms=4, zorder=2)
    for name in ground:
        if name in pts:
            _pivot(ax, pts[name], 0.025 * span)
    for name, z in pts.items():
        ax.annotate(name, _xy(z), xytext=(5, 5), textcoords="offset points", fontsize=9)
    ax.set_aspect("equal")
    ax.margins(0.12)
    ax.grid(alpha=0.2)
    if title:
        ax.set_title(title, fontsize=9)


def _fourbar(a, b, c, d, theta):
    from mech.planar import Linkage

    return (Linkage({"A": 0.0, "D": complex(d)}).crank("AB", pivot="A", tip="B", length=a)
            .rrr(("BC", "CD"), pins=("B", "D"), joint="C", lengths=(b, c), branch=1)), math.radians(theta)


def _slider_crank(r, l, e):
    from mech.planar import Guide, Linkage

    return (Linkage({"A": 0.0}).crank("AB", pivot="A", tip="B", length=r)
            .rrp(("BC", "slider"), pin="B", guide=Guide("ground", through=complex(0, e), angle=0.0), joint="C",
                 length=l, branch=1))


def _guide_bar(a, d):
    from mech.planar import Linkage

    return (Linkage({"A": 0.0, "D": complex(d)}).crank("AB", pivot="A", tip="B", length=a)
            .rpr(("guide", "block"), pins=("D", "B"), offset=0.0, branch=1))


def _text(ax, lines):
    ax.text(0.02, 0.98, "\n".join(lines), transform=ax.transAxes, va="top", fontsize=8,
            bbox={"fc": "white", "ec": "0.7", "alpha": 0.9})


def _circle(ax, c, r, **kw):
    t = np.linspace(0, 2 * math.pi, 181)
    ax.plot(*_xy(c + r * np.exp(1j * t)), **kw)


def _dim(ax, z1, z2, label, off=0j):
    ax.annotate("", _xy(z2 + off), _xy(z1 + off), arrowprops={"arrowstyle": "<->", "lw": 0.8})
    ax.annotate(label, _xy((z1 + z2) / 2 + off), xytext=(3, 3), textcoords="offset points", fontsize=8)


def _axes_off(ax):
    ax.set_aspect("equal")
    ax.margins(0.1)
    ax.set_xticks([])
    ax.set_yticks([])


#: Drawers of figures defined outside this module, by example number or by the prefix "E"
#: (the worked examples).
EXAMPLE_DRAWERS = {}


# ----------------------------------------------------------------------------- per exercise
def draw(number, p, fig):
    """Draw the figure of exercise ``number`` with the givens ``p`` into ``fig``."""
    from mech.exercises import chapter2_analysis as an
    from mech.exercises import chapter2_instant_centres as ic
    from mech.exercises import chapter2_reactions as rx
    from mech.exercises import chapter2_relative_motion as rm

    if number.startswith("E"):
        # the worked examples draw their own figures with the helpers here, and register the
        # drawer when their module is imported (this module does not import theirs: no cycle)
        drawer = EXAMPLE_DRAWERS.get(number, EXAMPLE_DRAWERS.get("E"))
        if drawer is None:
            raise ValueError(f"Expected `number` to be an exercise with a figure, got {number!r}")
        return drawer(number, p, fig)
    ax = fig.add_subplot(111) if number not in ("2-1", "2-8", "2-23", "2-30") else None
    if number == "2-1":
        axs = fig.subplots(1, 3)
        lk, th = _fourbar(p["a"], p["b"], p["c"], p["d"], 60.0)
        linkage(axs[0], lk, th, title="(a) four-bar")
        linkage(axs[1], _slider_crank(p["r"], p["l"], p["e"]), math.radians(60), title="(b) slider-crank")
        linkage(axs[2], _guide_bar(p["g"], p["h"]), math.radians(60), title="(c) guide-bar")
    elif number in ("2-2", "2-3"):
        a = p["AB"] if "AB" in p else min(p["BC"], p["CD"], p["AD"]) / 2
        lk, th = _fourbar(a, p["BC"], p["CD"], p["AD"], 60.0)
        linkage(ax, lk, th, title="AB = " + ("?" if number == "2-2" else f"{a:g} mm") + ", frame AD")
    elif number == "2-4":
        linkage(ax, an.linkage_2_4(p), math.radians(60))
    elif number == "2-5":
        linkage(ax, an.linkage_2_5(p), math.radians(60))
    elif number == "2-6":
        linkage(ax, _slider_crank(p["r"], p["l"], p["e"]), math.radians(60), title=f"offset e = {p['e']:g} mm")
    elif number == "2-7":
        linkage(ax, an.linkage_2_7(p), math.radians(60))
    elif number == "2-8":
        axs = fig.subplots(1, 3)
        for a_, (name, lk) in zip(axs, ic.mechanisms_2_8(p).items()):
            linkage(a_, lk, math.radians(p["theta"]), title=name)
    elif number == "2-9":
        g = ic.wheels_2_9(p)
        for c, r, k in ((g["A"], p["r1"], 1), (g["B"], p["r2"], 2), (g["C"], p["r3"], 3)):
            _circle(ax, c, r, color="tab:blue")
            ax.annotate(f"{k}", _xy(c), fontsize=10, ha="center")
        ax.plot(*_xy([g["A"], g["B"], g["C"]]), "k--", lw=0.8)
        _text(ax, [f"r1 = {p['r1']:g} mm, r2 = {p['r2']:g} mm, r3 = {p['r3']:g} mm", f"angle ABC = {p['beta']:g}°"])
        _axes_off(ax)
    elif number == "2-10":
        g = an.cam_2_10(p)
        _circle(ax, g["O"], g["r"], color="tab:blue")
        ax.plot(*_xy([g["A"], g["O"]]), "-o", color="tab:blue")
        ax.plot(*_xy([g["C"], g["K"] + 0.3 * (g["K"] - g["C"])]), "-", color="tab:orange", lw=2)
        for k in ("A", "C", "O"):
            ax.annotate(k, _xy(g[k]), xytext=(4, 4), textcoords="offset points")
        _pivot(ax, g["A"], 3)
        _pivot(ax, g["C"], 3)
        _text(ax, [f"r = {p['r']:g} mm, OA = {p['OA']:g} mm, AC = {p['AC']:g} mm", f"φ1 = {p['phi1']:g}°, "
                   f"ω1 = {p['omega1']:g} rad/s"])
        _axes_off(ax)
    elif number == "2-11":
        lk, th = _fourbar(p["a"], p["b"], p["c"], p["d"], p["theta"])
        linkage(ax, lk, th)
    elif number in ("2-12", "2-13", "2-14", "2-15", "2-16", "2-17", "2-18"):
        build = {"2-12": rm.linkage_2_12, "2-13": rm.linkage_2_13, "2-14": rm.linkage_2_14, "2-15": rm.linkage_2_15,
                 "2-16": rm.linkage_2_16, "2-17": rx.linkage_2_17, "2-18": rx.linkage_2_18}[number]
        lk = build(p)
        if isinstance(lk, tuple):                # 2-17 and 2-18 return (linkage, crank angle)
            lk, value = lk
        elif number == "2-15":
            value = math.radians(45.0)
        elif number == "2-13":
            value = 0.0
        else:
            value = _input(lk, p)
        linkage(ax, lk, value)
        if number in ("2-17", "2-18"):
            _text(ax, [f"P5 = {p['P5']:g} N, AB = {p['AB']:g} mm"])
    elif number == "2-22":
        linkage(ax, rx.linkage_2_22(), math.radians(0))
        _text(ax, [f"P = {p['P']:g} N, pins d = {p['d_pin']:g} mm, μ0 = {p['mu0']:g}"])
    elif number == "2-25":
        lk, angle = rx.linkage_2_25(p)
        linkage(ax, lk, angle)
        _text(ax, [f"G = {p['G']:g} N, disc R = {p['R']:g} mm, e = {p['e']:g} mm", f"μ = {p['mu']:g}, shafts "
                   f"{p['rs']:g} mm"])
    elif number == "2-26":
        linkage(ax, _slider_crank(p["r"], p["l"], 0.0), math.radians(45))
        _text(ax, [f"r = {p['r']:g} mm, l = {p['l']:g} mm, journals {p['d']:g} mm", f"μ0 = {p['mu0']:g}, μ = "
                   f"{p['mu']:g}, M_r = {p['Mr']:g} N·m"])
    elif number == "2-19":
        t = math.radians(p["theta"])
        h = 100.0
        w = h * math.tan(t)
        ax.fill([-w, w, 0], [h, h, 0], fc="0.85", ec="k")
        ax.fill([-w - 80, -w, 0, -80], [h, h, 0, 0], fc="#cde", ec="k")
        ax.fill([w + 80, w, 0, 80], [h, h, 0, 0], fc="#cde", ec="k")
        ax.annotate("P", (0, h + 10), (0, h + 50), arrowprops={"arrowstyle": "->"}, ha="center")
        for s, name in ((-1, "A"), (1, "B")):
            ax.annotate(f"{p['Q']:g} N", (s * 60, 40), (s * 140, 40), arrowprops={"arrowstyle": "->"}, va="center")
            ax.text(s * 45, 60, name)
        ax.text(0, 30, "C", ha="center")
        _text(ax, [f"θ = {p['theta']:g}° (each face from the vertical)", f"friction angle φ = {p['phi']:g}°"])
        _axes_off(ax)
    elif number == "2-20":
        R = p["D"] / 2
        gap = p["a"]
        for s in (1, -1):
            _circle(ax, complex(0, s * (R + gap / 2)), R, color="tab:blue")
        ax.fill([-1.2 * R, 0, 0, -1.2 * R], [-0.2 * R, -0.05 * R, 0.05 * R, 0.2 * R], fc="0.8", ec="k")
        ax.text(-1.1 * R, 0.25 * R, "workpiece 1")
        _dim(ax, complex(0.1 * R, -gap / 2), complex(0.1 * R, gap / 2), f"a = {gap:g} mm")
        _text(ax, [f"D = {p['D']:g} mm, a = {gap:g} mm, μ = {p['mu']:g}"])
        _axes_off(ax)
    elif number == "2-21":
        e = p["e"]
        ax.fill([-10, 10, 10, -10], [0, 0, 300, 300], fc="0.9", ec="k")
        ax.plot([-14, -14], [60, 200], "k", lw=3)
        ax.plot([14, 14], [60, 200], "k", lw=3)
        ax.plot([0, e], [300, 300], "k", lw=2)
        ax.annotate("P", (e, 300), (e, 230), arrowprops={"arrowstyle": "<-"}, ha="center")
        _dim(ax, complex(-30, 60), complex(-30, 200), "L")
        _dim(ax, complex(0, 320), complex(e, 320), f"e = {e:g} mm")
        _text(ax, [f"μ = {p['mu']:g}"])
        _axes_off(ax)
    elif number == "2-23":
        axs = fig.subplots(1, 2)
        r1, r2 = p["d1"] / 2, p["d2"] / 2
        for a_, title in zip(axs, ("flat", "conical")):
            _axes_off(a_)
            a_.set_title(title, fontsize=9)
        axs[0].fill([r1, r2, r2, r1], [0, 0, 20, 20], fc="0.8", ec="k")
        axs[0].fill([-r1, -r2, -r2, -r1], [0, 0, 20, 20], fc="0.8", ec="k")
        _dim(axs[0], complex(-r1, -10), complex(r1, -10), f"d1 = {p['d1']:g}")
        _dim(axs[0], complex(-r2, 35), complex(r2, 35), f"d2 = {p['d2']:g}")
        a = math.radians(p["alpha"])
        r1p = p["d1p"] / 2
        hgt = (r2 - r1p) / math.tan(a)
        for s in (1, -1):
            axs[1].fill([s * r1p, s * r2, s * (r2 + 15), s * (r1p + 15)], [0, hgt, hgt, 0], fc="0.8", ec="k")
        _dim(axs[1], complex(-r1p, -10), complex(r1p, -10), f"d1' = {p['d1p']:g}")
        _dim(axs[1], complex(-r2, hgt + 15), complex(r2, hgt + 15), f"d2 = {p['d2']:g}")
        _text(axs[1], [f"α = {p['alpha']:g}°, μ = {p['mu']:g}"])
    elif number == "2-24":
        d2, D, d0, l = p["d2"], p["D"], p["d0"], p["l"]
        ax.fill([-d2 / 2, d2 / 2, d2 / 2, -d2 / 2], [0, 0, 120, 120], fc="0.9", ec="k")
        for y in np.arange(0, 120, p["p"] * 3):
            ax.plot([-d2 / 2, d2 / 2], [y, y + p["p"] * 1.5], "k", lw=0.5)
        ax.fill([-D / 2, D / 2, D / 2, -D / 2], [120, 120, 130, 130], fc="#cde", ec="k")
        ax.plot([0, min(l, 4 * D)], [110, 110], "k", lw=3)
        ax.annotate(f"F = {p['F']:g} N", (min(l, 4 * D), 110), (min(l, 4 * D), 70), arrowprops={"arrowstyle": "<-"})
        ax.annotate("Q", (0, 130), (0, 175), arrowprops={"arrowstyle": "->"}, ha="center")
        _text(ax, [f"d2 = {d2:g} mm, pitch p = {p['p']:g} mm", f"collar D = {D:g} mm, d0 = {d0:g} mm",
                   f"handle l = {l:g} mm (shortened), μ = {p['mu']:g}"])
        _axes_off(ax)
    elif number == "2-27":
        B1, C1 = complex(p["xB1"], p["yB1"]), complex(p["xC1"], p["yC1"])
        B2, C2 = complex(p["xB2"], p["yB2"]), complex(p["xC2"], p["yC2"])
        ax.plot(*_xy([B1, C1]), "-o", color="tab:blue", lw=3, label="closed")
        ax.plot(*_xy([B2, C2]), "-o", color="tab:orange", lw=3, label="open")
        for n, z in (("B1", B1), ("C1", C1), ("B2", B2), ("C2", C2)):
            ax.annotate(n, _xy(z), xytext=(4, 4), textcoords="offset points")
        ax.axvline(p["x0"], color="0.4", ls="--", lw=1)
        ax.text(p["x0"], min(p["yC1"], p["yB1"]), f" x = {p['x0']:g}", fontsize=8)
        ax.legend(fontsize=8)
        ax.set_aspect("equal")
        ax.grid(alpha=0.2)
    elif number == "2-28":
        lk, _ = _fourbar(p["AB"], p["BC"], p["CD"], p["AD"], 60.0)
        linkage(ax, lk, math.radians(60))
        D = complex(p["AD"])
        for k in (1, 2, 3):
            psi = math.radians(p[f"psi{k}"])
            ax.plot(*_xy([D, D + p["CD"] * complex(math.cos(psi), math.sin(psi))]), "--", color="tab:orange", lw=1)
            x = p["AD"] + p[f"xF{k}"]
            ax.plot([x], [p["e"]], "s", color="tab:green")
            ax.annotate(f"F{k}", (x, p["e"]), xytext=(0, -12), textcoords="offset points", fontsize=8)
        ax.axhline(p["e"], color="0.5", ls="--", lw=0.8)
    elif number == "2-29":
        A, D = 0j, complex(p["AD"])
        for k in (1, 2, 3):
            phi, psi = math.radians(p[f"phi{k}"]), math.radians(p[f"psi{k}"])
            c = f"C{k - 1}"
            ax.plot(*_xy([A, A + 0.4 * p["AD"] * np.exp(1j * phi)]), color=c, lw=2, label=f"φ{k}, ψ{k}")
            ax.plot(*_xy([D, D + 0.4 * p["AD"] * np.exp(1j * psi)]), color=c, lw=2, ls="--")
        ax.plot(*_xy([A, D]), "k-o")
        _pivot(ax, A, 3)
        _pivot(ax, D, 3)
        ax.annotate("A", _xy(A), xytext=(-10, -12), textcoords="offset points")
        ax.annotate("D", _xy(D), xytext=(4, -12), textcoords="offset points")
        ax.legend(fontsize=8)
        _text(ax, [f"AD = {p['AD']:g} mm; angles from +x"])
        _axes_off(ax)
    elif number in ("2-30", "2-31", "2-32"):
        ax = ax or fig.add_subplot(111)
        if number == "2-30":
            D = 0j
            half = math.radians(p["psi"]) / 2
            for s in (1, -1):
                ax.plot(*_xy([D, D + p["l_CD"] * np.exp(1j * (math.pi / 2 + s * half))]), "-o", color="tab:blue", lw=2)
            ax.annotate(f"ψ = {p['psi']:g}°", _xy(D + 0.6 * p["l_CD"] * 1j), ha="center")
            _pivot(ax, D, 0.03 * p["l_CD"])
            _text(ax, [f"CD = {p['l_CD']:g} mm, K = {p['K']:g}", f"(1) AB = {p['l_AB']:g} mm; (2) BC = {p['l_BC']:g} mm",
                       f"[γ] = {p['gamma_allowed']:g}°"])
        elif number == "2-31":
            D, A = complex(p["l_AD"]), 0j
            phi = math.radians(p["phi"])
            C = D + p["l_CD"] * np.exp(1j * (math.pi - phi))
            ax.plot(*_xy([A, D]), "k-o")
            ax.plot(*_xy([D, C]), "-o", color="tab:blue", lw=2)
            for n, z in (("A", A), ("D", D), ("C", C)):
                ax.annotate(n, _xy(z), xytext=(4, 4), textcoords="offset points")
            _pivot(ax, A, 3)
            _pivot(ax, D, 3)
            _text(ax, [f"AD = {p['l_AD']:g} mm, CD = {p['l_CD']:g} mm", f"K = {p['K']:g}, φ = {p['phi']:g}°"])
        else:
            _circle(ax, 0j, p["l_AB"], color="tab:blue", ls=":")
            ax.plot([0, p["l_AB"] * 0.5], [0, p["l_AB"] * 0.866], "-o", color="tab:blue", lw=2)
            y = 2.5 * p["l_AB"]
            ax.plot([-p["H"] / 2, p["H"] / 2], [y, y], "-", color="tab:orange", lw=4)
            _dim(ax, complex(-p["H"] / 2, y + 15), complex(p["H"] / 2, y + 15), f"H = {p['H']:g} mm")
            ax.text(0, y - 25, "ram", ha="center")
            _pivot(ax, 0j, 6)
            _text(ax, [f"AB = {p['l_AB']:g} mm, DE = {p['l_DE']:g} mm, K = {p['K']:g}"])
        _axes_off(ax)
    else:
        raise ValueError(f"Expected `number` to be an exercise with a figure, got {number!r}")


def figure_png(number, params, *, dpi=96):
    """PNG bytes of the figure of exercise ``number`` with the givens ``params``."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    wide = number in ("2-1", "2-8", "2-23")
    fig = Figure(figsize=(9.0, 3.2) if wide else (5.6, 3.8))
    draw(number, params, fig)
    what = f"Worked example {number[1:]}" if number.startswith("E") else f"Exercise {number}"
    fig.suptitle(f"{what} (schematic)", fontsize=9)
    fig.subplots_adjust(left=0.08, right=0.98, bottom=0.1, top=0.86, wspace=0.25)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi)
    return buf.getvalue()
