"""Kinematic diagrams of a four-bar: output angle, rate and acceleration against the crank angle."""

import matplotlib.pyplot as plt
import numpy as np


def kinematic_diagrams(theta, poses, labels, *, title=None):
    """Three stacked panels (psi, omega_output, alpha_output) against theta in degrees.

    `poses` are `FourBarPose` objects solved with ``order=2`` at `theta`.
    """
    fig, axes = plt.subplots(3, 1, figsize=(7, 7), sharex=True)
    deg = np.degrees(theta)
    rows = [("psi", "rocker angle $\\psi$ (deg)", np.degrees),
            ("omega_output", "$\\dot\\psi$ (rad/s)", lambda v: v),
            ("alpha_output", "$\\ddot\\psi$ (rad/s$^2$)", lambda v: v)]
    for ax, (name, ylabel, convert) in zip(axes, rows):
        for pose, label, style in zip(poses, labels, ("-", "--", ":")):
            ax.plot(deg, convert(getattr(pose, name)), style, label=label)
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
    axes[0].legend(loc="best")
    axes[-1].set_xlabel("crank angle $\\theta$ (deg)")
    axes[-1].set_xticks(np.arange(0, 361, 60))
    if title:
        axes[0].set_title(title)
    fig.tight_layout()
    return fig


def linkage_snapshot(ax, linkage, theta, *, color="C0", alpha=1.0, label=None):
    """Draw the links A-B-C-D of `linkage` at one crank angle on `ax`."""
    pose = linkage.solve(theta)
    points = np.array([0, pose.B, pose.C, linkage.d])
    ax.plot(points.real, points.imag, "-o", color=color, alpha=alpha, label=label, ms=4)
    return pose
