"""Figures of pressure and transmission angles and force gain (``book/forces/transmission.md``).

Plain plotting functions: they take a `Linkage` with its `LinkageSolution`, or arrays
computed by ``mech``, and Matplotlib axes (new ones when None), and return the axes.
Nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["angle_at_joint", "angle_curves", "gain_curves", "ram_line_choice"]


def _axes(ax, size=(5.0, 4.0)):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def angle_at_joint(ax, linkage, solution, index, *, joint, force_from, arm_from, gamma, scale=None):
    """Draw a pose with the force line, the joint's velocity and the transmission angle.

    Parameters
    ----------
    linkage, solution : the linkage and its solution (order >= 1).
    index : int
        Which pose.
    joint, force_from, arm_from : str
        The joint J, the other pin of the two-force coupler (force along it -> J), and the
        follower's pivot (the arm pivot -> J). ``force_from`` and ``arm_from`` may instead
        be complex directions, sequences over the poses (the force on a block pressing
        normal to a slot, the normal of a slider's guide).
    gamma : float
        The transmission angle at this pose, radians (written in the legend).
    """
    from figures.linkages import draw_linkage

    ax = _axes(ax)
    draw_linkage(ax, linkage, solution, index)
    P = {k: complex(np.asarray(v)[index]) for k, v in solution.points.items()}
    def _direction(spec, sign):
        if isinstance(spec, str):
            d = sign * (J - P[spec])
        else:
            d = complex(np.asarray(spec, dtype=complex).reshape(-1)[index if np.size(spec) > 1 else 0])
        return d / abs(d)

    J = P[joint]
    v = complex(np.asarray(solution.velocities[joint])[index])
    u = _direction(force_from, 1.0)
    arm = _direction(arm_from, 1.0)
    L = scale or 0.45 * (abs(J - P[arm_from]) if isinstance(arm_from, str) else abs(J))
    ax.annotate("", xy=((J + L * u).real, (J + L * u).imag),
                xytext=(J.real, J.imag), arrowprops=dict(arrowstyle="-|>", color="tab:red", lw=1.8))
    w = v / abs(v) * L
    ax.annotate("", xy=((J + w).real, (J + w).imag), xytext=(J.real, J.imag),
                arrowprops=dict(arrowstyle="-|>", color="tab:blue", lw=1.8))
    # arc of gamma between the force line and the arm line at J
    a0, a1 = np.angle(u), np.angle(arm)
    for ref in (arm, -arm):
        d = np.angle(ref / u)
        if abs(abs(d) - gamma) < 1e-6:
            a1 = a0 + d
            break
    t = np.linspace(a0, a1, 40)
    r = 0.3 * L
    ax.plot(J.real + r * np.cos(t), J.imag + r * np.sin(t), color="tab:green", lw=1.5)
    ax.plot([J.real, J.real - L * arm.real * 0.6], [J.imag, J.imag - L * arm.imag * 0.6], ":", color="grey")
    ends = np.array([J + L * u, J + w, J - 0.6 * L * arm])
    ax.plot(ends.real, ends.imag, ls="none")                  # let the limits include the arrows
    ax.relim()
    ax.autoscale_view()
    ax.plot([], [], color="tab:red", label="force F (along the coupler)")
    ax.plot([], [], color="tab:blue", label="velocity v")
    ax.plot([], [], color="tab:green", label=f"γ = {np.degrees(gamma):.1f}°, α = {90 - np.degrees(gamma):.1f}°")
    ax.legend(loc="best", fontsize=8)
    ax.set_aspect("equal")
    return ax


def angle_curves(ax, x, curves, *, minima=(), limits=(40.0, 50.0), xlabel="crank angle θ (deg)"):
    """Angles in degrees against `x` (radians, shown in degrees), with minima and limits.

    ``curves``: mapping label -> angle array (radians); ``minima``: (x, angle, label)
    triples in radians; ``limits``: horizontal design lines in degrees (F51).
    """
    ax = _axes(ax, (6.0, 3.6))
    xd = np.degrees(x)
    for label, y in curves.items():
        ax.plot(xd, np.degrees(y), label=label)
    for xm, ym, label in minima:
        ax.plot(np.degrees(xm), np.degrees(ym), "o", color="black")
        ax.annotate(label, (np.degrees(xm), np.degrees(ym)), textcoords="offset points", xytext=(6, -12),
                    fontsize=8)
    for lim in limits:
        ax.axhline(lim, color="grey", ls="--", lw=0.8)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("angle (deg)")
    ax.set_ylim(0, 92)
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(alpha=0.3)
    return ax


def gain_curves(ax, x, curves, *, xlabel, ylabel="|mechanical advantage|", log=True, marks=()):
    """Absolute force gain against `x`, on a log axis by default; `marks` are vertical lines."""
    ax = _axes(ax, (6.0, 3.6))
    for label, y in curves.items():
        ax.plot(x, np.abs(y), label=label)
    for xm in marks:
        ax.axvline(xm, color="grey", ls=":", lw=1.0)
    if log:
        ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    return ax


def ram_line_choice(ax, linkage, solution, indices, pin, lines):
    """A linkage at some poses with the path of the pin driving a ram and candidate ram lines
    (Fig. 2-82): ``lines`` maps a label to a height y; the pin's path comes from ``solution``."""
    from figures.linkages import draw_linkage

    ax = _axes(ax, (5.0, 5.0))
    for i in indices:
        draw_linkage(ax, linkage, solution, i, labels=i == indices[0])
    path = np.asarray(solution.points[pin])
    ax.plot(path.real, path.imag, color="tab:brown", lw=2.5, alpha=0.6, label=f"path of {pin}")
    x0, x1 = path.real.min() - 0.6 * np.ptp(path.real), path.real.max() + 0.6 * np.ptp(path.real)
    for (label, y), colour in zip(lines.items(), ("C0", "C1", "C2")):
        ax.plot([x0, x1], [y, y], ls="--", color=colour, lw=1.2, label=label)
    ax.set_aspect("equal")
    ax.legend(loc="lower left", fontsize=8)
    return ax
