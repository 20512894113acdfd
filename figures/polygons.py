"""Figures of the relative-motion method (``book/analysis/relative-motion.md``).

Plain plotting functions: a mechanism diagram, a velocity polygon and an acceleration
polygon drawn from the vectors that ``mech.planar.kinematics._polygons`` computes, labelled like the
textbook (``p, b, c, e`` and ``p', b', n'_cb, c'``). They take data and Matplotlib axes (a
new figure when ``ax`` is None) and return the axes. Nothing runs at import.
"""

import re

import numpy as np

__all__ = ["mechanism_diagram", "polygon_diagram", "relative_motion_figure", "term_label", "vertex_label"]

# colour by the kind of term: absolute, normal, tangential, sliding, Coriolis
_COLOURS = {"abs": "C0", "n": "C1", "t": "C2", "r": "C4", "k": "C3", "rel": "C2"}
_KIND_NAMES = {"abs": "absolute", "rel": "relative (turning)", "n": "normal", "t": "tangential",
               "r": "relative (sliding)", "k": "Coriolis"}


def _axes(ax, size=(5.0, 4.5)):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def _sub(text):
    """'B3B2' -> 'B_3B_2': digits written as subscripts inside a subscript."""
    return re.sub(r"([A-Za-z])(\d+)", r"\1_{\2}", text)


def term_label(name):
    """Mathtext for a term name: ``"a_CB^t"`` -> ``$a^{t}_{CB}$``, ``"v_B3B2"`` -> ``$v_{B_{3}B_{2}}$``."""
    head, _, rest = name.partition("_")
    sub, _, sup = rest.partition("^")
    sup = f"^{{{sup}}}" if sup else ""
    return rf"${head}{sup}_{{{_sub(sub)}}}$"


def vertex_label(name, prime=False):
    """Mathtext for a vertex: ``"n_cb"`` -> ``$n'_{cb}$`` (with ``prime``), ``"b3"`` -> ``$b_3$``."""
    mark = r"^{\prime}" if prime else ""
    if "_" in name:
        head, sub = name.split("_", 1)
        return rf"${head}{mark}_{{{sub}}}$"
    m = re.fullmatch(r"([a-z]+)(\d*)", name)
    if m and m.group(2):
        return rf"${m.group(1)}{mark}_{{{m.group(2)}}}$"
    return rf"${name}{mark}$"


def _kind(term):
    if term.tail == "p":
        return "abs" if "^" not in term.name else term.name.rsplit("^", 1)[1]
    if "^" in term.name:
        return term.name.rsplit("^", 1)[1]
    return "r" if re.search(r"\d", term.name) else "rel"


def mechanism_diagram(bodies, points, ax=None, *, fixed=(), title=None, offsets=None):
    """Draw a linkage at one pose: links as thick polylines, joints, labelled points.

    Parameters
    ----------
    bodies : sequence of (sequence of complex, dict)
        Each link as a polyline of positions with Matplotlib style keywords.
    points : mapping of str to complex
        Points to mark and label.
    fixed : sequence of str
        Names of ground pivots (drawn with a hatched base).
    offsets : mapping of str to complex, optional
        Label offsets as fractions of the drawing size (default: up and to the right).
    """
    ax = _axes(ax)
    pts = np.array([complex(z) for z in points.values()] + [complex(z) for b, _ in bodies for z in b])
    span = max(np.ptp(pts.real), np.ptp(pts.imag), 1e-300)
    for body, style in bodies:
        z = np.array([complex(w) for w in body])
        ax.plot(z.real, z.imag, lw=2.4, solid_capstyle="round", zorder=2, **style)
    for name, z in points.items():
        z = complex(z)
        if name in fixed:
            ax.plot([z.real - 0.03 * span, z.real + 0.03 * span], [z.imag - 0.03 * span] * 2, color="k", lw=1.2)
            ax.plot(z.real, z.imag, marker="^", ms=9, mfc="w", mec="k", zorder=3)
        ax.plot(z.real, z.imag, marker="o", ms=5, mfc="w", mec="k", zorder=4)
        off = (offsets or {}).get(name, 0.03 + 0.03j) * span
        ax.annotate(name, (z.real + off.real, z.imag + off.imag), fontsize=11)
    ax.set_aspect("equal")
    ax.margins(0.12)
    ax.set_xticks([])
    ax.set_yticks([])
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def polygon_diagram(polygon, ax=None, *, mu=None, unit="", title=None, term_labels=True):
    """Draw a velocity or acceleration polygon from its computed vectors.

    Every term of every equation is an arrow from its tail vertex to its head vertex;
    colours mark the kind of term (absolute, normal, tangential, relative sliding,
    Coriolis). Vertices at one place share one label ("p', n'_c").

    Parameters
    ----------
    polygon : Polygon
        From ``velocity_polygon`` or ``acceleration_polygon`` at one pose (scalars).
    mu : float, optional
        The drawing scale, noted in the title with ``unit`` (e.g. ``"(m/s)/mm"``).
    term_labels : bool
        Write each term's name next to its arrow.
    """
    ax = _axes(ax)
    prime = polygon.kind == "acceleration"
    V = {k: complex(np.asarray(v)) for k, v in polygon.vertices.items()}
    span = max(max(abs(z - w) for z in V.values() for w in V.values()), 1e-300)
    seen, kinds = set(), set()
    for eq in polygon.equations:
        for t in eq.terms:
            if t.name in seen:
                continue
            seen.add(t.name)
            z0, z1 = V[t.tail], V[t.tail] + complex(np.asarray(t.vector))
            if abs(z1 - z0) < 1e-9 * span:
                continue
            kind = _kind(t)
            kinds.add(kind)
            ax.annotate("", xy=(z1.real, z1.imag), xytext=(z0.real, z0.imag),
                        arrowprops=dict(arrowstyle="-|>", color=_COLOURS[kind], lw=1.6,
                                        shrinkA=0, shrinkB=0, mutation_scale=12), zorder=3)
            if term_labels and abs(z1 - z0) > 0.06 * span:
                mid, d = 0.5 * (z0 + z1), (z1 - z0) / abs(z1 - z0)
                nrm = 1j * d * 0.035 * span
                ax.annotate(term_label(t.name), (mid.real + nrm.real, mid.imag + nrm.imag), fontsize=9,
                            color=_COLOURS[kind], ha="center", va="center")
    groups = {}
    for name, z in V.items():
        key = next((k for k in groups if abs(k - z) < 1e-9 * span), z)
        groups.setdefault(key, []).append(name)
    centre = np.mean(list(groups))
    for z, names in groups.items():
        # the tip of a zero normal or Coriolis term sits on another vertex: name that one only
        shown = [n for n in names if not n.startswith(("n_", "k_"))] or names
        ax.plot(z.real, z.imag, "o", ms=3.5, color="k", zorder=4)
        away = z - centre
        away = away / abs(away) if abs(away) > 1e-9 * span else 1 + 1j
        ax.annotate(", ".join(vertex_label(n, prime) for n in shown), (z.real, z.imag),
                    xytext=(9 * away.real, 9 * away.imag), textcoords="offset points", fontsize=11,
                    ha="left" if away.real >= 0 else "right", va="bottom" if away.imag >= 0 else "top")
    for kind in sorted(kinds):
        ax.plot([], [], color=_COLOURS[kind], lw=1.6, label=_KIND_NAMES[kind])
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.01), ncol=3, frameon=False)
    ax.set_aspect("equal", adjustable="datalim")
    ax.margins(0.15)
    ax.set_xticks([])
    ax.set_yticks([])
    name = "velocity polygon" if not prime else "acceleration polygon"
    note = f", $\\mu_{{{'a' if prime else 'v'}}}$ = {mu:g} {unit}" if mu is not None else ""
    ax.set_title(title or (name + note), fontsize=10, pad=16)
    return ax


def relative_motion_figure(bodies, points, vpoly, apoly, *, fixed=(), mu_v=None, mu_a=None,
                           units=("", ""), titles=(None, None, None), offsets=None, size=(13.0, 4.6)):
    """The textbook's three panels side by side: diagram, velocity polygon, acceleration polygon.

    ``units`` are the unit strings of ``mu_v`` and ``mu_a``. Returns the three axes.
    """
    import matplotlib.pyplot as plt

    fig, axs = plt.subplots(1, 3, figsize=size, gridspec_kw={"width_ratios": [1.2, 1, 1]})
    mechanism_diagram(bodies, points, axs[0], fixed=fixed, title=titles[0] or "mechanism", offsets=offsets)
    polygon_diagram(vpoly, axs[1], mu=mu_v, unit=units[0], title=titles[1])
    polygon_diagram(apoly, axs[2], mu=mu_a, unit=units[1], title=titles[2])
    fig.tight_layout()
    return axs
