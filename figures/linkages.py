"""Figures of the ready-made linkages (``book/analysis/linkages.md``).

Plain plotting functions: each takes a `Linkage`, its `LinkageSolution` (or arrays
computed by ``mech``) and Matplotlib axes (new ones when None) and returns the axes.
Nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["draw_linkage", "draw_paths", "gallery", "assembly_modes", "stroke_plot", "dwell_press"]

LINK = dict(color="black", lw=2.0, solid_capstyle="round", zorder=2)


def _axes(ax, size=(5.0, 4.0)):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def _block(ax, z, direction, size):
    from matplotlib.patches import Polygon

    w, h = size, 0.55 * size
    c = np.array([-w - h * 1j, w - h * 1j, w + h * 1j, -w + h * 1j]) / 2 * direction + z
    ax.add_patch(Polygon(np.c_[c.real, c.imag], closed=True, fc="white", ec="black", lw=1.2, zorder=3))


def _ground(ax, z, size):
    """A fixed pivot: a small triangle on a hatched base."""
    from matplotlib.patches import Polygon

    tri = np.array([z, z - size * (0.5 + 0.9j), z + size * (0.5 - 0.9j)])
    ax.add_patch(Polygon(np.c_[tri.real, tri.imag], closed=True, fc="white", ec="black", lw=1.0, zorder=1))
    y = z.imag - 0.9 * size
    ax.plot([z.real - 0.8 * size, z.real + 0.8 * size], [y, y], color="black", lw=1.0)
    for k in np.linspace(-0.7, 0.7, 5):
        ax.plot([z.real + k * size, z.real + (k - 0.3) * size], [y, y - 0.3 * size], color="black", lw=0.7)


def _polyline(zs):
    """Points of one link in drawing order: closed triangle/polygon when 3 or more."""
    zs = list(zs)
    return zs + zs[:1] if len(zs) >= 3 else zs


def draw_linkage(ax, linkage, solution, index=0, *, sketch=None, size=None, labels=True, title=None):
    """Draw ``linkage`` at pose ``index`` of ``solution``.

    Links are polylines (filled light grey when they carry three or more points), fixed
    pivots are hatched triangles, blocks are boxes along their link, and a block sliding on
    the frame has its guide drawn dashed.
    """
    from mech.planar.special._library import sketch as make_sketch

    ax = _axes(ax)
    sk = sketch or make_sketch(linkage)
    P = {k: complex(np.asarray(v)[index]) for k, v in solution.points.items()}
    pts = np.array(list(P.values()))
    span = max(np.ptp(pts.real), np.ptp(pts.imag), 1e-9)
    size = size or 0.05 * span
    for link, names in sk["links"].items():
        z = np.array([P[n] for n in _polyline(names)])
        if len(names) >= 3:
            ax.fill(z.real, z.imag, color="0.88", zorder=1)
        ax.plot(z.real, z.imag, **LINK)
    for name, link in sk["guides"]:
        d = complex(np.asarray(solution.direction(link))[index])
        g = P[name] + np.array([-0.45, 0.45]) * span * d
        ax.plot(g.real, g.imag, color="grey", lw=1.0, ls="--", zorder=0)
    for name, link in sk["blocks"]:
        _block(ax, P[name], complex(np.asarray(solution.direction(link))[index]), 1.6 * size)
    for name in sk["ground"]:
        _ground(ax, P[name], size)
    moving = [n for n in P if n not in sk["ground"]]
    z = np.array([P[n] for n in moving])
    ax.plot(z.real, z.imag, "o", ms=4, mfc="white", mec="black", zorder=4)
    if labels:
        for n, zz in P.items():
            ax.annotate(n, (zz.real, zz.imag), xytext=(4, 4), textcoords="offset points", fontsize=7)
    if title:
        ax.set_title(title, fontsize=9)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xticks([])
    ax.set_yticks([])
    return ax


def draw_paths(ax, solution, names, *, colors=None):
    """Draw the paths of the named points over all poses of ``solution``."""
    ax = _axes(ax)
    colors = colors or ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
    for k, name in enumerate(names):
        z = np.asarray(solution.points[name])
        ax.plot(z.real, z.imag, color=colors[k % len(colors)], lw=1.0, label=f"path of {name}")
    return ax


def gallery(items, *, ncols=2, cell=4.0):
    """Grid of linkages: ``items`` is a list of (title, linkage, solution, index, path names)."""
    import matplotlib.pyplot as plt

    nrows = -(-len(items) // ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(cell * ncols, cell * 0.8 * nrows), squeeze=False)
    for ax in axes.ravel()[len(items):]:
        ax.axis("off")
    for ax, (title, linkage, sol, index, names) in zip(axes.ravel(), items):
        draw_paths(ax, sol, names)
        draw_linkage(ax, linkage, sol, index, title=title)
        ax.legend(fontsize=6, loc="best")
    fig.tight_layout()
    return axes


def assembly_modes(panels, *, cell=2.6):
    """Both assembly modes of each group: ``panels`` is a list of (title, dict) where the
    dict has ``links`` (lists of complex points, drawn black), ``other`` (the same for the
    other mode, drawn dashed), ``ground`` (known pins) and ``guide`` (optional pair)."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(panels), figsize=(cell * len(panels), cell * 0.9), squeeze=False)
    for ax, (title, p) in zip(axes[0], panels):
        if p.get("guide"):
            g = np.array(p["guide"])
            ax.plot(g.real, g.imag, color="grey", lw=1.0, ls="--")
        for link in p.get("other", ()):
            z = np.array(link)
            ax.plot(z.real, z.imag, color="tab:red", lw=1.5, ls="--")
        for link in p["links"]:
            z = np.array(link)
            ax.plot(z.real, z.imag, **LINK)
        for z in p.get("ground", ()):
            ax.plot(z.real, z.imag, "o", ms=6, color="black", zorder=4)
        for z, text in p.get("notes", ()):
            ax.annotate(text, (z.real, z.imag), xytext=(3, 3), textcoords="offset points", fontsize=7)
        ax.set_title(title, fontsize=8)
        ax.set_aspect("equal", adjustable="datalim")
        ax.margins(0.15)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.tight_layout()
    return axes


def stroke_plot(ax, theta, curves, *, ylabel="ram velocity"):
    """Plot curves (dict label -> array over ``theta``, radians) against the crank angle."""
    ax = _axes(ax, (6.0, 3.2))
    for label, y in curves.items():
        ax.plot(np.degrees(theta), y, lw=1.2, label=label)
    ax.axhline(0.0, color="grey", lw=0.6)
    ax.set_xlabel("crank angle (degrees)")
    ax.set_ylabel(ylabel)
    ax.set_xlim(0, 360)
    ax.legend(fontsize=7)
    return ax


def dwell_press(axes, linkage, solution, theta, index, *, pin, slider, centre, radius, window):
    """A press whose punch dwells (Fig. 2-24c): left, the linkage at pose ``index`` with the
    path of the coupler point ``pin``, the circle of radius ``radius`` about ``centre`` that
    a stretch of it follows (dashed), and the punch ``slider``; right, the punch's position
    along its guide against the crank angle, with the crank angles ``window`` (degrees)
    shaded."""
    left, right = axes
    draw_paths(left, solution, [pin])
    t = np.linspace(0.0, 2.0 * np.pi, 181)
    ring = complex(centre) + radius * np.exp(1j * t)
    left.plot(ring.real, ring.imag, ls="--", color="0.5", lw=0.9, label=f"circle of radius {radius:g} about O")
    draw_linkage(left, linkage, solution, index)
    left.legend(fontsize=7, loc="lower right")
    y = np.asarray(solution.points[slider]).imag
    deg = np.degrees(theta)
    right.plot(deg, y - y.min(), color="tab:red")
    right.axvspan(window[0], window[1], color="tab:green", alpha=0.15, label="dwell")
    right.set_xlabel("crank angle θ (deg)")
    right.set_ylabel(f"height of {slider} above its lowest (mm)")
    right.set_xticks(np.arange(0, 361, 60))
    right.grid(alpha=0.3)
    right.legend(fontsize=8)
    return axes
