"""A page of the step-built live figures for the browser test, written from the figure
functions: the Watt six-bar and Jansen's leg (planar), the spherical Watt-1, the RSSR with
both modes and the open chain of example 2-25, as the book draws them."""

import numpy as np

from _live_page import STATIC  # noqa: F401  (the same modules as the book ships)


def figures():
    from figures import live
    from figures.animate import animate_linkage, great_circle, view3d
    from mech.planar import jansen_linkage, shaper_watt, watt_six_bar
    from mech.spatial import RSSR, example_2_25_manipulator
    from mech.spherical import watt1

    turn = np.radians(np.arange(0.0, 360.0, 4.0))
    out = {}
    for name, lk, trace in (("watt", watt_six_bar(), ["E", "G"]), ("jansen", jansen_linkage(), ["F"]),
                            ("shaper", shaper_watt(), ["E", "F"])):
        out[name] = animate_linkage(lk, lk.solve(turn), trace=trace, inputs=np.degrees(turn),
                                    live=live.linkage(lk, turn)).data
    lk = watt1(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
    pose = lk.solve(turn)
    arcs = [("A", "B"), ("B", "C"), ("D", "C"), ("C", "E"), ("B", "E"), ("E", "G"), ("F", "G")]
    arcs = [(p, q) for p, q in arcs if p in pose.points and q in pose.points]
    out["sphsix"] = view3d(dict(pose.points), arcs=arcs, still=[(great_circle([0, 0, 1]), "grid")], sphere=True,
                           trace=["P"], inputs=np.degrees(turn), yaw=20.0, pitch=50.0,
                           live=live.spherical_linkage(lk, turn)).data
    dims = dict(l1=1.0, l2=4.0, l3=2.0, s0=0.5, s3=0.8, h0=3.0, lam=np.radians(60.0))
    lam = dims["lam"]
    A = np.array([0.0, 0.0, dims["s0"]])
    D = np.array([dims["h0"], dims["s3"] * np.sin(lam), dims["s3"] * np.cos(lam)])
    z3 = np.array([0.0, np.sin(lam), np.cos(lam)])
    runs = {b: RSSR(**dims, branch=b).solve(turn) for b in (1, -1)}
    out["rssr"] = view3d({"A": A, "D": D, "O": np.zeros(3), "OK": [D[0], 0.0, 0.0], "B": runs[1].B, "C": runs[1].C,
                          "C'": runs[-1].C}, links=[("A", "B"), ("B", "C"), ("C", "D"), ("B", "C'"), ("C'", "D")],
                         still=[([A - [0, 0, 1.5], A + [0, 0, 1.5]], "axis"), ([D - 1.5 * z3, D + 1.5 * z3], "axis"),
                                ([np.zeros(3), [D[0], 0.0, 0.0]], "grid")],
                         trace=["C", "C'"], inputs=np.degrees(turn), live=live.rssr(dims, turn)).data
    s0, p = 0.40, 0.08
    t = np.linspace(0.0, 2 * np.pi, 91)
    sweep = np.stack([t, np.radians(60.0) + np.radians(25.0) * np.sin(2 * t), 0.25 + 0.05 * np.sin(3 * t), 2 * t], -1)
    arm = example_2_25_manipulator(s0)
    chain = arm.frames(sweep)
    tip = arm.pose(sweep, point=(0.0, 0.0, p))
    jaw = chain[:, -1, :3, :3] @ [0.05, 0.0, 0.0] + chain[:, -1, :3, 3]
    out["chain"] = view3d({"A": np.zeros(3), "B": [0.0, 0.0, s0], "O3": chain[:, 3, :3, 3], "P": tip.P, "J": jaw},
                          links=[("A", "B"), ("B", "O3"), ("O3", "P"), ("P", "J")], trace=["P"],
                          inputs=np.degrees(t), live=live.open_chain(s0, p, sweep)).data
    A, B, C = (np.array(v) / np.linalg.norm(v) for v in ([1.0, 0.2, 0.6], [0.3, 1.0, 0.4], [0.2, 0.4, 1.0]))
    from mech.spherical import great_circle_through, intersect, stephenson3

    n1, n2 = great_circle_through(A, B).pole, great_circle_through(B, C).pole
    x = intersect(n1, n2)
    out["circles"] = view3d({"A": A, "B": B, "C": C, "X": x.point, "\u2212X": x.antipode, "N1": n1, "N2": n2},
                            arcs=[("A", "B"), ("B", "C"), ("C", "A")],
                            still=[(great_circle(n1), "curve"), (great_circle(n2), "path"),
                                   (great_circle([0, 0, 1]), "grid"), ([np.zeros(3), n1], "axis"),
                                   ([np.zeros(3), n2], "axis")],
                            sphere=True, live=live.great_circles(A, B, C)).data
    lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6), coupler=(0.3, 0.4), mu=0.8)
    run = np.linspace(-0.5, 1.0, 31)
    pose = lk.solve(run)
    out["triad"] = view3d(dict(pose.points), arcs=[("A", "B"), ("A", "E"), ("B", "E"), ("B", "C"), ("E", "G"),
                                                   ("D", "H"), ("C", "G"), ("G", "H"), ("C", "H")],
                          still=[(great_circle([0, 0, 1]), "grid")], sphere=True, trace=["C", "H"],
                          inputs=np.degrees(run), live=live.stephenson3(lk, run)).data
    return out


def write(folder):
    """Write the page (index.html) and the modules into `folder`; returns the page's path."""
    import _live_page

    page = _live_page.write(folder)
    body = "".join(f'<section id="{name}">{text}</section>' for name, text in figures().items())
    page.write_text('<!DOCTYPE html><html lang="en" data-content_root="./"><head><meta charset="utf-8">'
                    f"<title>Live step-built figures</title></head><body>{body}</body></html>", encoding="utf-8")
    return page
