"""3-D figures of spatial transforms and open chains (``book/spatial/``): plain plotting
functions that take data computed by ``mech`` and Matplotlib 3-D axes (new ones when
``ax`` is None) and return the axes; nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["frame", "chain", "sphere", "axes3d", "equal_aspect", "frame_panels"]

_AXIS_COLOURS = ("tab:red", "tab:green", "tab:blue")


def axes3d(figsize=(6.0, 5.5)):
    """A new figure with one 3-D axes."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=figsize)
    return fig.add_subplot(projection="3d")


def frame(M, label, ax=None, *, length=0.3, alpha=1.0, linestyle="-"):
    """Draw the frame of the 4x4 transform `M` (its origin and unit axes x, y, z as arrows).

    Parameters
    ----------
    M : array_like, shape (4, 4)
        Homogeneous transform of the frame into the drawing frame.
    label : str
        Text written at the origin (e.g. ``"0"`` gives O_0, x_0, ...).
    length : float
        Drawn length of the unit axes.
    """
    ax = axes3d() if ax is None else ax
    M = np.asarray(M)
    o = M[:3, 3]
    for k, (name, colour) in enumerate(zip("xyz", _AXIS_COLOURS)):
        d = M[:3, k] * length
        ax.quiver(*o, *d, color=colour, alpha=alpha, linestyle=linestyle, arrow_length_ratio=0.15, lw=1.5)
        ax.text(*(o + 1.12 * d), f"${name}_{{{label}}}$", color=colour, fontsize=9, alpha=alpha)
    ax.scatter(*o, color="black", s=10, alpha=alpha)
    return ax


def chain(frames, ax=None, *, point=None, colour="0.25", labels=None, length=0.25):
    """Draw an open chain: links as a polyline through the frame origins, each frame's axes.

    Parameters
    ----------
    frames : sequence of array_like, shape (4, 4)
        M_00 = I, M_01, M_02, ..., M_0n (products of the chain, e.g. from `OpenChain.solve`
        of the chain's prefixes).
    point : array_like, shape (3,), optional
        The end point P, joined to the last origin.
    labels : sequence of str, optional
        Frame labels (default "0", "1", ...).
    """
    ax = axes3d() if ax is None else ax
    origins = [np.asarray(M)[:3, 3] for M in frames]
    if point is not None:
        origins.append(np.asarray(point))
    xyz = np.array(origins)
    ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], "-", color=colour, lw=3.0, alpha=0.7, solid_capstyle="round")
    labels = [str(k) for k in range(len(frames))] if labels is None else labels
    for M, label in zip(frames, labels):
        frame(M, label, ax, length=length)
    if point is not None:
        ax.scatter(*point, color="black", s=30, marker="o")
        ax.text(*(np.asarray(point) + 0.03), "$P$", fontsize=11)
    return ax


def sphere(centre, radius, ax=None, *, colour="tab:blue", alpha=0.08, resolution=40):
    """Draw a translucent sphere (e.g. the workspace of the manipulator of example 2-25)."""
    ax = axes3d() if ax is None else ax
    u = np.linspace(0.0, 2 * np.pi, resolution)
    v = np.linspace(0.0, np.pi, resolution // 2)
    x = centre[0] + radius * np.outer(np.cos(u), np.sin(v))
    y = centre[1] + radius * np.outer(np.sin(u), np.sin(v))
    z = centre[2] + radius * np.outer(np.ones_like(u), np.cos(v))
    ax.plot_surface(x, y, z, color=colour, alpha=alpha, linewidth=0)
    ax.plot_wireframe(x, y, z, color=colour, alpha=alpha * 2, linewidth=0.3, rstride=4, cstride=4)
    return ax


def equal_aspect(ax, points, *, margin=0.1):
    """Give the 3-D axes equal scales, fitting `points` (shape (k, 3)) with a margin."""
    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2 * (1 + margin) + 1e-9
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    return ax


def frame_panels(panels, *, titles=None, length=0.6, points=None, view=(22, -55), figsize=None):
    """Side-by-side 3-D panels, each drawing several frames (e.g. a frame before and after a
    rotation, Figs. 2-117 to 2-119).

    Parameters
    ----------
    panels : sequence of sequence of (array_like, str, bool)
        Per panel, the frames to draw as ``(M, label, faint)``: ``M`` a 4x4 transform into
        the drawing frame, ``label`` the axis subscript, ``faint`` draws it dashed and pale.
    titles : sequence of str, optional
        A title per panel.
    points : sequence of sequence of (array_like, array_like, str), optional
        Per panel, arrows ``(start, end, text)`` to add (a position vector, an origin shift).

    Returns
    -------
    list of Axes3D
    """
    import matplotlib.pyplot as plt

    n = len(panels)
    fig = plt.figure(figsize=figsize or (4.2 * n, 4.2))
    axes = []
    for k, frames in enumerate(panels):
        ax = fig.add_subplot(1, n, k + 1, projection="3d")
        extent = [[0.0, 0.0, 0.0]]
        for M, label, faint in frames:
            frame(M, label, ax, length=length, alpha=0.35 if faint else 1.0, linestyle="--" if faint else "-")
            M = np.asarray(M)
            extent += [M[:3, 3], M[:3, 3] + length * M[:3, :3].sum(axis=1) * 1.15]
            extent += [M[:3, 3] + 1.15 * length * M[:3, j] for j in range(3)]
        for start, end, text in (points[k] if points else ()):
            start, end = np.asarray(start, float), np.asarray(end, float)
            ax.quiver(*start, *(end - start), color="0.2", arrow_length_ratio=0.08, lw=1.2)
            ax.text(*(0.5 * (start + end) + 0.04), text, fontsize=10)
            extent += [start, end]
        equal_aspect(ax, extent, margin=0.05)
        ax.view_init(elev=view[0], azim=view[1])
        if titles:
            ax.set_title(titles[k], fontsize=10)
        axes.append(ax)
    fig.tight_layout()
    return axes
