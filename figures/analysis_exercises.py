"""Figures of the page ``book/analysis/exercises.md``: assumed layouts of exercises 2-4, 2-5,
2-7 and 2-10, drawn from data computed by ``mech``.

Plain plotting functions: each takes points (complex numbers) and a Matplotlib ``Axes``
(a new figure when ``ax`` is None) and returns the axes. Nothing is computed or drawn at
import.
"""

import numpy as np

__all__ = ["cam_centres", "linkage_poses", "pressure_angle_curves"]

_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red")


def _axes(ax, size):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def _xy(z):
    z = np.asarray(z, dtype=complex)
    return z.real, z.imag


def _ground(ax, z, size):
    """A fixed pivot: a small triangle under the point, hatched base."""
    x, y = _xy(z)
    ax.fill([x, x - size, x + size], [y, y - 1.6 * size, y - 1.6 * size], color="0.85",
            ec="0.3", lw=0.8, zorder=1)
    ax.plot([x - 1.5 * size, x + 1.5 * size], [y - 1.6 * size] * 2, color="0.3", lw=1.0)


def linkage_poses(poses, links, *, ground=(), guides=(), paths=None, labels=None,
                  names=(), ax=None, size=(7.0, 4.6)):
    """Draw a linkage in one or more poses, with its fixed pivots, guides and paths.

    Parameters
    ----------
    poses : sequence of mapping of str to complex
        Each pose maps point names to positions; drawn in turn, the first one solid.
    links : sequence of tuple of str
        Each tuple is a polyline of point names (a link, or a rigid body's outline).
    ground : sequence of str
        Names of fixed pivots, marked with a triangle.
    guides : sequence of (complex, complex)
        Fixed straight guides as (point, unit direction); drawn as long dashed lines.
    paths : mapping of str to complex ndarray, optional
        Traced paths of points (dotted).
    labels : sequence of str, optional
        Legend text for each pose.
    names : sequence of str
        Points whose names are written next to them, in the first pose.
    """
    ax = _axes(ax, size)
    every = np.concatenate([np.ravel(np.asarray(list(p.values()), dtype=complex)) for p in poses])
    span = float(max(np.ptp(every.real), np.ptp(every.imag))) or 1.0
    for Q, e in guides:          # infinite lines that do not change the axis limits
        ax.axline(_xy(complex(Q)), _xy(complex(Q) + complex(e)), color="0.5", lw=0.9, ls="--", zorder=0)
    for name, z in (paths or {}).items():
        ax.plot(*_xy(z), color="0.6", lw=0.8, ls=":", zorder=0)
    for k, pose in enumerate(poses):
        colour = _COLOURS[k % len(_COLOURS)]
        alpha = 1.0 if k == 0 else 0.55
        for chain in links:
            ax.plot(*_xy([pose[n] for n in chain]), "-o", color=colour, lw=2.0, ms=4, alpha=alpha,
                    label=(labels[k] if labels and chain == links[0] else None))
    for name in ground:
        _ground(ax, poses[0][name], 0.02 * span)
    for name in names:
        x, y = _xy(poses[0][name])
        ax.annotate(name, (x, y), xytext=(5, 5), textcoords="offset points", fontsize=10)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.grid(alpha=0.25)
    if labels:
        ax.legend(loc="best", fontsize=8)
    return ax


def cam_centres(geometry, p12, ax=None, size=(7.0, 4.6)):
    """Draw the disc cam of exercise 2-10 with its follower face and instant centres.

    Parameters
    ----------
    geometry : mapping
        From `mech.exercises.chapter2_analysis.cam_2_10`: points ``A, C, O, K`` and ``r``.
    p12 : complex
        The relative instant centre of cam and follower.
    """
    ax = _axes(ax, size)
    A, C, O, K, r = (geometry[k] for k in ("A", "C", "O", "K", "r"))
    t = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.fill(*_xy(O + r * np.exp(1j * t)), color="tab:blue", alpha=0.15, ec="tab:blue")
    face = K - C
    ax.plot(*_xy([C - 0.15 * face, K + 0.4 * face]), color="tab:orange", lw=2.5, label="follower face")
    ends = np.array([min(A.real, C.real, p12.real), max(A.real, C.real, p12.real)])
    ax.plot(ends + np.array([-15.0, 15.0]), [0.0, 0.0], color="0.4", lw=0.9, ls="--", label="line AC")
    ax.plot(*_xy([K, O, p12]), color="tab:red", lw=1.0, ls="-.", label="common normal")
    ax.plot(*_xy([A, O]), color="tab:blue", lw=2.0)
    for z, text in ((A, "A = P13"), (C, "C = P23"), (O, "O"), (K, "K"), (p12, "P12")):
        ax.plot(*_xy(z), "o", color="k", ms=4)
        ax.annotate(text, _xy(z), xytext=(5, -12 if text == "P12" else 5), textcoords="offset points")
    for z in (A, C):
        _ground(ax, z, 3.0)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.grid(alpha=0.25)
    ax.legend(loc="lower right", fontsize=8)
    return ax


def pressure_angle_curves(theta, curves, ax=None, size=(7.0, 3.2)):
    """Plot pressure angles against the crank angle, both in degrees.

    Parameters
    ----------
    theta : array_like
        Crank angles, radians.
    curves : mapping of str to array_like
        Label to the pressure angle at ``theta``, radians.
    """
    ax = _axes(ax, size)
    for (label, alpha), colour in zip(curves.items(), _COLOURS):
        ax.plot(np.degrees(theta), np.degrees(alpha), color=colour, label=label)
    ax.set_xlabel("crank angle θ (°)")
    ax.set_ylabel("pressure angle α (°)")
    ax.set_xlim(np.degrees(theta[0]), np.degrees(theta[-1]))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return ax
