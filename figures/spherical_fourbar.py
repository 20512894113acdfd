"""Figures of the spherical four-bar page (``book/spherical/fourbar.md``).

Plain functions taking solved data and axes; the drawing on the sphere uses the shared
``figures.sphere``. Nothing is computed or drawn at import.
"""

import numpy as np

from figures import sphere

__all__ = ["linkage_on_sphere", "output_angles", "angular_velocities", "gallery"]


def _zoom(ax, zoom):
    ax.set_box_aspect((1, 1, 1), zoom=zoom)
    return ax


def linkage_on_sphere(A, D, poses, curve, ax=None, *, labels=True, elev=25.0, azim=35.0,
                      colours=("0.15", "0.45", "0.7"), zoom=1.45):
    """Draw the linkage at a few poses, as great arcs on the globe, with a coupler curve.

    Parameters
    ----------
    A, D : array_like, shape (3,)
        Input and output pivots.
    poses : sequence of (B, C, P)
        Unit vectors of the pins and the coupler point, one triple per drawn pose.
    curve : ndarray, shape (n, 3)
        Coupler curve (NaN rows break it).
    """
    ax = sphere.globe(ax)
    sphere.arc(ax, A, D, color="black", lw=2.5)
    for k, (B, C, P) in enumerate(poses):
        colour = colours[k % len(colours)]
        sphere.arc(ax, A, B, color=colour)
        sphere.arc(ax, B, C, color=colour)
        sphere.arc(ax, C, D, color=colour)
        sphere.arc(ax, B, P, color=colour, lw=1.0, ls="--")
        sphere.arc(ax, C, P, color=colour, lw=1.0, ls="--")
        sphere.point(ax, B, "B" if labels and k == 0 else None, colour=colour)
        sphere.point(ax, C, "C" if labels and k == 0 else None, colour=colour)
        sphere.point(ax, P, "P" if labels and k == 0 else None, colour="tab:red")
    ax.plot(curve[:, 0], curve[:, 1], curve[:, 2], color="tab:red", lw=1.2)
    sphere.point(ax, A, "A" if labels else None)
    sphere.point(ax, D, "D" if labels else None)
    return _zoom(sphere.finish(ax, elev=elev, azim=azim), zoom)


def output_angles(theta, curves, ax=None):
    """Plot psi against theta (degrees) for several labelled curves.

    `curves` is a sequence of dicts with ``label``, ``psi`` and optional ``style``.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 3.6))
    for item in curves:
        ax.plot(np.degrees(theta), np.degrees(item["psi"]), item.get("style", "-"), label=item["label"])
    ax.set_xlabel(r"input angle $\theta$ (degrees)")
    ax.set_ylabel(r"output angle $\psi$ (degrees)")
    ax.grid(True, lw=0.3)
    ax.legend(loc="best", fontsize=9)
    return ax


def angular_velocities(A, D, B, C, P, vectors, ax=None, *, scale=0.35, elev=25.0, azim=35.0, zoom=1.45):
    """Draw one pose and the angular velocity vectors of its links as arrows from the centre.

    `vectors` maps a label to ``(vector, colour)``; each arrow is `scale` times the vector.
    """
    ax = sphere.globe(ax)
    for p, q in ((A, B), (B, C), (C, D), (A, D)):
        sphere.arc(ax, p, q, color="0.3")
    for p, name in ((A, "A"), (B, "B"), (C, "C"), (D, "D"), (P, "P")):
        sphere.point(ax, p, name)
    for label, (vector, colour) in vectors.items():
        v = scale * np.asarray(vector, dtype=float)
        ax.quiver(0, 0, 0, *v, color=colour, lw=2.0, arrow_length_ratio=0.12)
        ax.text(*(1.12 * v), label, color=colour, fontsize=11)
    return _zoom(sphere.finish(ax, elev=elev, azim=azim), zoom)


def gallery(items, *, elev=25.0, azim=35.0):
    """A row of globes, each with one linkage drawn at one pose and its coupler curve.

    `items` is a sequence of dicts with ``A, D, pose`` (B, C, P), ``curve`` and ``title``.
    """
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(3.3 * len(items), 3.6))
    for k, item in enumerate(items):
        ax = fig.add_subplot(1, len(items), k + 1, projection="3d")
        linkage_on_sphere(item["A"], item["D"], [item["pose"]], item["curve"], ax, labels=False,
                          elev=elev, azim=azim, zoom=1.3)
        ax.set_title(item["title"], fontsize=9)
    return fig
