"""Figures of the page book/spherical/types.md: spherical four-bars of each kind, the
antipode move, and the special types. Functions take computed data; nothing runs at import.
"""

import numpy as np

from figures import sphere

__all__ = ["draw_linkage", "kinds_gallery", "antipode_move", "universal_joint_panels", "output_curves"]

_COLOURS = {"ground": "0.35", "a": "tab:red", "b": "tab:blue", "c": "tab:green"}


def draw_linkage(ax, A, B, C, D, *, labels=True, lw=2.0, alpha=1.0, circles=True, style="-"):
    """Draw one pose of a spherical four-bar: ground AD (grey), AB, BC, CD, and the circles
    that B and C run on (about A and D)."""
    sphere.arc(ax, A, D, color=_COLOURS["ground"], lw=lw + 1, alpha=alpha, ls=style)
    sphere.arc(ax, A, B, color=_COLOURS["a"], lw=lw, alpha=alpha, ls=style)
    sphere.arc(ax, B, C, color=_COLOURS["b"], lw=lw, alpha=alpha, ls=style)
    sphere.arc(ax, D, C, color=_COLOURS["c"], lw=lw, alpha=alpha, ls=style)
    if circles:
        sphere.circle(ax, A, float(np.arccos(np.clip(A @ B, -1, 1))), color=_COLOURS["a"], lw=0.6, alpha=0.6)
        sphere.circle(ax, D, float(np.arccos(np.clip(D @ C, -1, 1))), color=_COLOURS["c"], lw=0.6, alpha=0.6)
    for name, p in zip("ABCD", (A, B, C, D)):
        sphere.point(ax, p, name if labels else None)
    return ax


def kinds_gallery(poses, titles, *, elev=35.0, azim=-60.0):
    """One small globe per kind: `poses` is a list of (A, B, C, D) unit vectors."""
    import matplotlib.pyplot as plt

    columns = min(3, len(poses))
    rows = -(-len(poses) // columns)
    fig = plt.figure(figsize=(3.6 * columns, 3.6 * rows))
    for i, ((A, B, C, D), title) in enumerate(zip(poses, titles)):
        ax = fig.add_subplot(rows, columns, i + 1, projection="3d")
        sphere.globe(ax, meridians=8, parallels=4)
        draw_linkage(ax, A, B, C, D)
        sphere.finish(ax, elev=elev, azim=azim)
        ax.set_title(title, fontsize=10)
    fig.tight_layout()
    return fig


def antipode_move(A, B, C, D, *, elev=20.0, azim=-35.0):
    """A pose and the same pose with joint B marked at its antipode -B (dashed arcs)."""
    ax = sphere.axes3d(figsize=(5.5, 5.0))
    sphere.globe(ax)
    draw_linkage(ax, A, B, C, D, circles=False)
    Bm = -np.asarray(B)
    sphere.arc(ax, A, Bm, color=_COLOURS["a"], lw=1.5, ls="--")
    sphere.arc(ax, Bm, C, color=_COLOURS["b"], lw=1.5, ls="--")
    ax.plot(*np.stack([B, Bm]).T, color="0.2", lw=0.8, ls=":")   # the joint axis through the centre
    sphere.point(ax, Bm, "-B", colour="tab:purple")
    sphere.finish(ax, elev=elev, azim=azim)
    return ax


def universal_joint_panels(pose, theta, psi_plus, hooke, alpha_deg):
    """Left: the universal joint as a spherical four-bar; right: psi + pi/2 and hooke_output
    against the input angle (degrees)."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(10.0, 4.2))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    sphere.globe(ax)
    draw_linkage(ax, *pose)
    sphere.finish(ax, elev=20.0, azim=-50.0)
    ax.set_title(f"a = b = c = 90°, d = {alpha_deg:g}°", fontsize=9)
    ax2 = fig.add_subplot(1, 2, 2)
    deg = np.degrees
    ax2.plot(deg(theta), deg(psi_plus), lw=3, alpha=0.5, label="SphericalFourBar: ψ + 90°")
    ax2.plot(deg(theta), deg(hooke), "k--", lw=1, label="hooke_output(θ1, α)")
    ax2.plot(deg(theta), deg(theta), color="0.6", lw=0.8, label="θ3 = θ1")
    ax2.set_xlabel("input angle θ = θ1 (degrees)")
    ax2.set_ylabel("output angle θ3 (degrees)")
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    return fig


def output_curves(ax, theta, curves, *, xlabel="input angle θ (degrees)", ylabel="output angle ψ (degrees)"):
    """Plot named curves `{label: (x, y)}` in degrees on plain axes."""
    for label, (x, y) in curves.items():
        ax.plot(np.degrees(x), np.degrees(y), label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return ax
