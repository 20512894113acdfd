"""The Roberts-Chebyshev cognates and their common coupler curve, like Fig. 2-32.

Plain plotting function: takes joints and paths computed by ``mech`` (``Cognates.joints``
and ``Cognates.path``) and a Matplotlib ``Axes`` (a new figure when ``ax`` is None),
draws, and returns the axes. Nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["cognates_figure"]

_COLOURS = {"ABCD": "black", "AEGK": "tab:blue", "DFHK": "tab:orange"}


def cognates_figure(pose, curves, ax=None):
    """Draw the three cognates in one pose (the ten-bar) and the common coupler curve.

    Parameters
    ----------
    pose : TenBarPose
        Joints ``A .. M`` at ONE crank angle (scalars), from ``Cognates.joints``.
    curves : array_like of complex, shape (3, n)
        The coupler points of ABCD, AEGK and DFHK over a crank turn (``Cognates.path``).
    """
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(8.0, 6.5))
    j = {name: complex(getattr(pose, name)) for name in "ABCDEFGHK"}
    j["M"] = complex(np.asarray(pose.M).reshape(-1)[0])
    curves = np.asarray(curves)
    for curve, name, style, width, alpha in zip(curves, _COLOURS, ("-", "--", ":"), (7.0, 2.0, 2.0),
                                                (0.25, 1.0, 1.0)):
        ax.plot(curve.real, curve.imag, style, color=_COLOURS[name], lw=width, alpha=alpha,
                label=f"coupler curve of {name}")
    for name, chain in (("ABCD", "ABCD"), ("AEGK", "AEGK"), ("DFHK", "DFHK")):
        pts = [j[ch] for ch in chain]
        ax.plot([z.real for z in pts], [z.imag for z in pts], "-o", color=_COLOURS[name], lw=2, ms=4)
    for tri, name in (("BCM", "ABCD"), ("EGM", "AEGK"), ("FHM", "DFHK")):
        pts = [j[ch] for ch in tri]
        ax.fill([z.real for z in pts], [z.imag for z in pts], color=_COLOURS[name], alpha=0.18)
    ax.fill([j["A"].real, j["D"].real, j["K"].real], [j["A"].imag, j["D"].imag, j["K"].imag],
            facecolor="none", edgecolor="0.4", hatch="//", lw=0.8)
    for name in "ADK":
        ax.plot(j[name].real, j[name].imag, "k^", ms=10)
    for name, z in j.items():
        ax.annotate(name, (z.real, z.imag), xytext=(5, 4), textcoords="offset points", fontsize=10,
                    fontweight="bold" if name in "ADKM" else "normal")
    ax.set_aspect("equal")
    ax.grid(alpha=0.25)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return ax
