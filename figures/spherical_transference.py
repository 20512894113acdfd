"""Figures of book/spherical/transference.md: an RCCC beside its spherical image."""

import numpy as np

from figures import sphere

__all__ = ["rccc_and_image", "slide_curves"]

COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red")


def rccc_and_image(frames, fig=None, *, half_length=1.2):
    """Left: the four joint axes of an RCCC (lines) with the common normals between them;
    right: the spherical image, the axis directions as points on the unit sphere joined by
    great arcs (the links' twists).

    Parameters
    ----------
    frames : ndarray, shape (4, 4, 4)
        The H-D frames of joints 1..4 in the ground frame (z column on the joint axis).
    """
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(10.0, 4.8)) if fig is None else fig
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    names = ("A (R)", "B (C)", "C (C)", "D (C)")
    for k, (F, colour) in enumerate(zip(frames, COLOURS)):
        o, z = F[:3, 3], F[:3, 2]
        seg = np.stack([o - half_length * z, o + half_length * z])
        ax.plot(*seg.T, color=colour, lw=2.0)
        ax.text(*(o + half_length * z), names[k], color=colour)
    for k in range(4):
        F, G = frames[k], frames[(k + 1) % 4]
        # the common normal from axis k to axis k+1 ends at G's origin, along G's x axis
        foot_k = G[:3, 3] - G[:3, 0] * np.dot(G[:3, 3] - F[:3, 3], G[:3, 0])
        ax.plot(*np.stack([foot_k, G[:3, 3]]).T, color="0.3", lw=1.0, ls="--")
    ax.set_title("RCCC: joint axes and common normals")
    pts = np.concatenate([np.stack([F[:3, 3] - half_length * F[:3, 2], F[:3, 3] + half_length * F[:3, 2]])
                          for F in frames])
    centre, span = pts.mean(axis=0), np.ptp(pts, axis=0).max() / 2
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        setter(c - span, c + span)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=20, azim=40)
    ax2 = fig.add_subplot(1, 2, 2, projection="3d")
    sphere.globe(ax2)
    dirs = [F[:3, 2] for F in frames]
    for k in range(4):
        sphere.arc(ax2, dirs[k], dirs[(k + 1) % 4], color="0.2")
    for d, colour, name in zip(dirs, COLOURS, "ABCD"):
        sphere.point(ax2, d, name, colour=colour)
    sphere.finish(ax2, elev=20, azim=40)
    ax2.set_title("spherical image: axes through one point")
    return fig


def slide_curves(theta, s4, s4_dual, phi41, ax=None):
    """Output slide and angle of an RCCC over a turn, by two routes (closed form, dual)."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 3.6))
    deg = np.degrees(theta)
    ax.plot(deg, s4, color="tab:red", lw=2.0, label="output slide $S_4$ (closed form (4))")
    ax.plot(deg, s4_dual, color="k", lw=0.8, ls="--", label="$S_4$ by dual numbers")
    ax.set_xlabel(r"input angle $\varphi_{12}$, degrees")
    ax.set_ylabel("slide")
    ax2 = ax.twinx()
    ax2.plot(deg, np.degrees(np.unwrap(phi41)), color="tab:blue", lw=1.2, label=r"output angle $\varphi_{41}$")
    ax2.set_ylabel("degrees")
    lines = ax.get_lines() + ax2.get_lines()
    ax.legend(lines, [line.get_label() for line in lines], loc="upper center", fontsize=8,
              bbox_to_anchor=(0.5, -0.2), ncol=3)
    return ax
