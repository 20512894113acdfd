"""Figures of pressure and transmission angles and force gain (``book/forces/transmission.md``).

Plain plotting functions: they take a `Linkage` with its `LinkageSolution`, or arrays
computed by ``mech``, and Matplotlib axes (new ones when None), and return the axes.
Nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["angle_at_joint", "angle_curves", "gain_curves", "guide_bar_block", "ram_line_choice",
           "slider_on_guide"]


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


def guide_bar_block(ax, linkage, solution, index, *, pin, pivot, bar, scale):
    """A guide-bar pose with the block's push on the bar and the bar's own velocity there
    (Fig. 2-73).

    The push acts along the bar's normal (no friction); the bar's point under the pin moves
    with ``1j * omega_bar * (pin - pivot)``, from the solution's angular velocity of
    ``bar``. Both arrows are ``scale`` long; the angle between them is the pressure angle.
    """
    from figures.linkages import draw_linkage

    ax = _axes(ax, (4.5, 4.5))
    draw_linkage(ax, linkage, solution, index, labels=True)
    J = complex(np.asarray(solution.points[pin])[index])
    D = complex(np.asarray(solution.points[pivot])[index])
    w = float(np.asarray(solution.omegas[bar])[index])
    v = 1j * w * (J - D)                                    # the bar's point at J
    n = 1j * complex(np.asarray(solution.direction(bar))[index])
    push = n * np.sign((v * np.conj(n)).real)               # the block drives the bar
    for d, colour in ((push, "tab:red"), (v / abs(v), "tab:blue")):
        tip = J + scale * d
        ax.annotate("", xy=(tip.real, tip.imag), xytext=(J.real, J.imag),
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=2.0 if colour == "tab:red" else 1.2))
    alpha = np.degrees(abs(np.angle(v / push)))
    ax.plot([], [], color="tab:red", label="push of the block on the bar")
    ax.plot([], [], color="tab:blue", label=f"velocity of the bar at {pin}")
    ax.plot([], [], ls="none", label=f"α = {alpha:.1e}°, γ = {90 - alpha:.4f}°")
    ax.legend(loc="lower left", fontsize=7)
    ax.set_aspect("equal")
    return ax


def slider_on_guide(ax, pin, offset, half_length, forces, line, ends, *, scale, title=None):
    """A block in a horizontal slot with its pin ``offset`` above the lower face (Fig. 2-85).

    ``forces`` maps a label to (point, force) for the applied forces (the rod's push at the
    pin, the working resistance at the face); ``line`` is the point where the guide's
    single normal force acts (``StaticForces.lines``); ``ends`` are the vertical reactions
    (signed, up positive) at the block's two ends, an upward one drawn on the lower face
    and a downward one on the upper face. Arrows are ``scale`` per unit of force.
    """
    ax = _axes(ax, (5.0, 3.0))
    pin = complex(pin)
    x0, y_low, h = pin.real, pin.imag - offset, 2.0 * offset
    box = np.array([x0 - half_length, x0 + half_length, x0 + half_length + 1j * h,
                    x0 - half_length + 1j * h, x0 - half_length]) + 1j * y_low
    ax.fill(box.real, box.imag, color="#fdd0a2", ec="tab:orange", lw=1.4, zorder=1)
    for y in (y_low, y_low + h):
        ax.plot([x0 - 2.6 * half_length, x0 + 2.6 * half_length], [y, y], color="0.3", lw=2.0)
    ax.plot([pin.real], [pin.imag], "o", color="black", ms=6, zorder=4)
    ax.annotate("C", (pin.real, pin.imag), textcoords="offset points", xytext=(4, 4))
    for (label, (at, f)), colour in zip(forces.items(), ("tab:green", "tab:red", "tab:purple")):
        at, f = complex(at), scale * complex(f)
        ax.annotate("", xy=((at + f).real, (at + f).imag), xytext=(at.real, at.imag),
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.8), zorder=5)
        ax.text((at + f).real, (at + f).imag + 0.15 * offset, label, color=colour, fontsize=9)
    for k, (x, n) in enumerate(zip((x0 - half_length, x0 + half_length), ends)):
        face = y_low if n > 0 else y_low + h
        tail = x + 1j * (face - scale * n)
        ax.annotate("", xy=(x, face), xytext=(tail.real, tail.imag),
                    arrowprops=dict(arrowstyle="-|>", color="tab:blue", lw=1.8), zorder=5)
        ax.text(x, tail.imag, f"$N_{k + 1}$ = {abs(n):.0f}", color="tab:blue", fontsize=9, ha="center",
                va="top" if n > 0 else "bottom")
    line = complex(line)
    ax.axvline(line.real, color="tab:blue", ls=":", lw=1.0)
    ax.text(line.real, y_low + 1.1 * h, "normal force's line", color="tab:blue", fontsize=8, ha="right")
    reach = scale * max(abs(n) for n in ends) + 0.6 * offset
    ax.set_ylim(y_low - reach, y_low + h + reach)
    ax.set_xlim(min(x0 - 2.7 * half_length, line.real - 0.2 * half_length),
                max(x0 + 2.7 * half_length, line.real + 0.2 * half_length))
    ax.set_aspect("equal")
    ax.grid(alpha=0.2)
    if title:
        ax.set_title(title, fontsize=10)
    return ax
