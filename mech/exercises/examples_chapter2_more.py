"""More worked examples of chapter 2 with variants: instant centres (E2-4, E2-5, E2-7), the forces of
a four-bar (E2-12), the wedge press (E2-11), the self-locking double slider (E2-14), the quick-return crank-rocker designed from a crank or a coupler (E2-17,
E2-18) and the gripper point of an open-chain manipulator (E2-25).

The same kind of records as :mod:`mech.exercises.examples_chapter2`: the example's numbers
(or, where the textbook gives none, the numbers its page in this book chose, with the
crank at a round angle) as defaults, a
solver on :mod:`mech.planar` that works the example by the textbook's method, and a sampler
of other numbers. Examples 2-4, 2-5 and 2-7 locate the instant centres (Kennedy's theorem) and
read the angular velocities off them; examples 2-17 and 2-18 design a crank-rocker from its
time ratio, the rocker's length and swing, and one more length, by the analytic model
(2-46) of §2.4 III; example 2-11 balances the forces on two wedges with friction, and
example 2-14 brackets the distance at which the force analysis finds the linkage locked,
and example 2-25 multiplies the manipulator's H-D matrices.

Examples
--------
>>> import math
>>> from mech.exercises import get
>>> s = get("E2-4").solve(theta1=math.degrees(0.7))     # the crank at 0.7 rad
>>> round(float(s["ω3"].value), 6)
-0.120816
>>> round(float(get("E2-17").solve()["coupler BC"].value), 2)
73.67
"""

from __future__ import annotations

import math

from mech._validate import positive_length, real_number
from mech.exercises import _figures
from mech.exercises._core import Parameter, Part, Result, Solution
from mech.exercises.examples_chapter2 import _example, _int

__all__ = ["EXAMPLES", "draw_example"]

_DEG = math.pi / 180.0
#: A centre farther than this (in link lengths) is taken as at infinity: the lines that
#: locate it are nearly parallel, and a sheet would print a meaningless large number.
_FAR = 50.0


def _crank_angle(p):
    theta = real_number("theta1", p["theta1"])
    w1 = real_number("omega1", p["omega1"])
    if w1 == 0.0:
        raise ValueError("Expected a turning crank, `omega1` != 0, got 0.0")
    return theta, w1


def _off_axis(rng):
    """A crank angle in steps of 5°, never a multiple of 90°: at 0° and 180° crank and rod
    of a slider-crank are in line (the slider stands still), which makes a dull variant."""
    return _int(rng, 5, 85, 5) + 90.0 * int(rng.integers(0, 4))


def _near(name, z, scale):
    """``z`` (complex), or ValueError when the centre is at infinity or nearly so."""
    if z is None or not math.isfinite(abs(z)) or abs(z) > _FAR * scale:
        raise ValueError(f"Expected the givens to place the instant centre `{name}` at a finite point, got it at or near infinity")
    return z


# ----------------------------------------------------------------------------- E2-4
def _solve_e2_4(p):
    from mech.planar import FourBar, centre_velocities, grashof, instant_centres

    a, b, c, d = (positive_length(n, p[n]) for n in "abcd")
    theta, w1 = _crank_angle(p)
    kind = grashof(a, b, c, d)
    if kind.kind != "crank-rocker" or kind.change_point:
        raise ValueError(f"Expected `a`, `b`, `c`, `d` of a crank-rocker with the crank `a`, got a={a!r}, b={b!r}, "
                         f"c={c!r}, d={d!r} ({kind.kind})")
    pose = FourBar(a, b, c, d).solve(theta * _DEG, order=1, omega=w1)
    centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): complex(d)})
    p13 = _near("P13", None if centres[1, 3].at_infinity else complex(centres[1, 3].point), d)
    p24 = _near("P24", None if centres[2, 4].at_infinity else complex(centres[2, 4].point), d)
    motion = centre_velocities(centres, frame=4, driver=1, omega=w1)
    how = "Kennedy's theorem: three centres of three links lie on one line"
    return Solution("E2-4", EXAMPLES_BY_NUMBER["E2-4"].title, dict(p), (
        "A at the origin, D on +x; C above the line AD; rates counter-clockwise positive.",
        "P14 = A, P12 = B, P23 = C and P34 = D are the joints.",), (
        Part("Instant centres", (
            Result("P13 (x)", p13.real, "mm", "P13 = BC ∩ AD: on the frame line, x from A"),
            Result("P24 (x)", p24.real, "mm", "P24 = AB ∩ CD"), Result("P24 (y)", p24.imag, "mm", "P24 = AB ∩ CD"),
        ), ("P13 is the common point of crank and rocker; P24 that of coupler and frame.",)),
        Part("Angular velocities", (
            Result("ω2", float(motion.omega[2]), "rad/s", "ω2 = ω1 P12P14/P12P24 (" + how + ")"),
            Result("ω3", float(motion.omega[3]), "rad/s", "ω3 = ω1 P13P14/P13P34"),
        ), ("Link 3 turns the same way as the crank when P13 lies outside AD.",)),
    ))


def _sample_e2_4(rng):
    return {"a": _int(rng, 8, 14), "b": _int(rng, 34, 46), "c": _int(rng, 25, 35), "d": _int(rng, 30, 40),
            "theta1": _off_axis(rng), "omega1": -_int(rng, 1, 10)}


# ----------------------------------------------------------------------------- E2-5
def _solve_e2_5(p):
    from mech.planar import SliderCrank, centre_velocities, instant_centres, prismatic

    a, b = positive_length("a", p["a"]), positive_length("b", p["b"])
    theta, w1 = _crank_angle(p)
    if not b > a:
        raise ValueError(f"Expected `b` > `a` so that the crank turns fully, got a={a!r}, b={b!r}")
    pose = SliderCrank(a, b).solve(theta * _DEG, order=1, omega=w1)
    centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): prismatic(1.0)})
    p13 = _near("P13", None if centres[1, 3].at_infinity else complex(centres[1, 3].point), b)
    motion = centre_velocities(centres, frame=4, driver=1, omega=w1)
    v3 = complex(motion.point_velocity(3, pose.C)).real
    return Solution("E2-5", EXAMPLES_BY_NUMBER["E2-5"].title, dict(p), (
        "A at the origin, the guide along +x through A (centric); B above the guide at small "
        "crank angles; rates counter-clockwise positive, the slider's velocity positive along +x.",
        "P34 lies at infinity, at right angles to the guide.",), (
        Part("Instant centres", (
            Result("P13 (y)", p13.imag, "mm", "P13 = BC ∩ the line through A at right angles to the guide"),
        ), ()),
        Part("Velocities", (
            Result("ω2", float(motion.omega[2]), "rad/s", "ω2 = ω1 P12P14/P12P24"),
            Result("v3", v3, "mm/s", "crank and slider share the velocity of P13: v3 = ω1 P14P13, eq. (F35)"),
        ), ()),
    ))


def _sample_e2_5(rng):
    return {"a": _int(rng, 20, 40), "b": _int(rng, 70, 120, 5), "theta1": _off_axis(rng),
            "omega1": _int(rng, 1, 10)}


# ----------------------------------------------------------------------------- E2-12
def _solve_e2_12(p):
    import numpy as np

    from mech.planar import FourBar, as_linkage, static_forces

    ab, bc, cd, ad, de = (positive_length(n, p[n]) for n in ("AB", "BC", "CD", "AD", "DE"))
    theta, Q = real_number("theta1", p["theta1"]), real_number("Q", p["Q"])
    if not Q > 0.0:
        raise ValueError(f"Expected a resistance `Q` > 0, got {Q!r}")
    if not de <= cd:
        raise ValueError(f"Expected E on the rocker, `DE` <= `CD`, got DE={de!r}, CD={cd!r}")
    lk = as_linkage(FourBar(ab, bc, cd, ad)).point("E", link="rocker", at=de)
    sol = lk.solve(theta * _DEG, order=1)                # ω1 = 1 rad/s; statics do not depend on it
    if not bool(np.all(sol.valid)):
        raise ValueError(f"Expected `theta1` at which the four-bar assembles, got {theta!r}")
    w3 = float(np.ravel(sol.omegas["rocker"])[0])
    if abs(w3) < 1e-3:
        raise ValueError(f"Expected the rocker to move at `theta1` = {theta!r} (it stands at a limit position)")
    u = complex(np.ravel(sol.direction("rocker"))[0])
    load = -math.copysign(1.0, w3) * 1j * u * Q          # across DE, against the rocker's motion
    sf = static_forces(sol, {"E": load})
    r12 = complex(np.ravel(sf.reactions[("crank", "coupler")])[0])
    return Solution("E2-12", EXAMPLES_BY_NUMBER["E2-12"].title, dict(p), (
        "A at the origin, D on +x, C above AD; the crank turns counter-clockwise; moments "
        "counter-clockwise positive; no friction, no weights, no inertia.",), (
        Part("Forces", (
            Result("R12", abs(r12), "N", "the coupler carries forces at its two pins only: R12 along BC; "
                                         "the rocker's three forces R23, Q and R43 meet in one point"),
            Result("M_d", float(np.ravel(sf.balancing)[0]), "N·mm", "the crank's balance about A; "
                                                                     "virtual work: M_d ω1 + Q·v_E = 0"),
        ), ()),
    ))


def _sample_e2_12(rng):
    return {"AB": _int(rng, 20, 35), "BC": _int(rng, 60, 80), "CD": _int(rng, 50, 70), "AD": _int(rng, 70, 90),
            "theta1": _off_axis(rng), "DE": _int(rng, 20, 45), "Q": _int(rng, 50, 500, 10)}


# ----------------------------------------------------------------------------- E2-14
def _solve_e2_14(p):
    import numpy as np

    from mech.planar import Guide, Linkage, friction_circle, static_forces

    l, r = positive_length("l", p["l"]), positive_length("r", p["r"])
    mu0, mu = real_number("mu0", p["mu0"]), real_number("mu", p["mu"])
    for name, v in (("mu0", mu0), ("mu", mu)):
        if not 0.0 < v < 1.0:
            raise ValueError(f"Expected a friction coefficient 0 < `{name}` < 1, got {v!r}")
    if not 2.0 * r * mu0 < l:
        raise ValueError(f"Expected the friction circles to fit the link, 2 `r` `mu0` < `l`, got r={r!r}, "
                         f"mu0={mu0!r}, l={l!r}")
    # slider 2 on the vertical guide through A, slider 3 on the horizontal one; x = AB's run
    ds = (Linkage({}).slider("slider2", guide=Guide("ground", 1j * l, -math.pi / 2), point="A")
          .rrp(("coupler", "slider3"), pin="A", guide=Guide("ground", 0j, 0.0), joint="B", length=l))
    rho = friction_circle(mu0, r)

    def locked(x):
        x = np.asarray(x, dtype=float)
        sol = ds.solve(l - np.sqrt(l * l - x * x), order=1)       # A moves down, B moves right
        return np.asarray(static_forces(sol, {"B": np.full(x.shape, -1.0)}, rho=rho, mu=mu).self_locking)

    lo, hi = 1e-6 * l, (1.0 - 1e-6) * l
    ends = locked(np.array([lo, hi]))
    if not ends[0] or ends[1]:
        raise ValueError(f"Expected slider 3 to lock near x = 0 and run near x = l, got `l` = {l!r}, `r` = {r!r}, "
                         f"`mu0` = {mu0!r}, `mu` = {mu!r}")
    for _ in range(8):                     # 64 solves at once per round: the bracket shrinks 64-fold
        x = np.linspace(lo, hi, 65)
        k = int(np.flatnonzero(locked(x))[-1])     # the verdict flips once, from locked to free
        lo, hi = x[k], x[min(k + 1, 64)]
    return Solution("E2-14", EXAMPLES_BY_NUMBER["E2-14"].title, dict(p), (
        "x is the horizontal distance from A to B; a small resistance on slider 3 (without one every "
        "force vanishes).",), (
        Part("Self-locking", (
            Result("x_lock", 0.5 * (lo + hi), "mm",
                   "the largest x at which no push P moves slider 3: the link's force along the crossing "
                   "tangent of the friction circles falls inside slider 3's friction cone; found by bracketing "
                   "on `static_forces(...).self_locking`"),
        ), ("The textbook's condition: x ≤ l sin[arctan μ + arcsin(2 r μ0 / l)].",)),
    ))


def _sample_e2_14(rng):
    return {"l": _int(rng, 80, 150, 5), "r": _int(rng, 5, 15), "mu0": _int(rng, 10, 20) / 100.0,
            "mu": _int(rng, 10, 30) / 100.0}


# ----------------------------------------------------------------------------- E2-17, E2-18
def _design(number, p, given):
    from mech.planar.synthesis import quick_return_crank_rocker

    K, c = real_number("K", p["K"]), positive_length("c", p["c"])
    phi = real_number("phi", p["phi"])
    if not 1.0 < K < 3.0:
        raise ValueError(f"Expected a time ratio 1 < `K` < 3, got {K!r}")
    if not 0.0 < phi < 180.0:
        raise ValueError(f"Expected a swing 0 < `phi` < 180 degrees, got {phi!r}")
    length = positive_length(given, p[given])
    q = quick_return_crank_rocker(K, c, phi * _DEG, **({"crank": length} if given == "a" else {"coupler": length}))
    m = q.check()
    a, b, _, d = q.lengths
    how = "the model of eq. (2-46): A on the circle through C1 and C2 that sees C1C2 under θ"
    found = (Result("coupler BC", b, "mm", how),) if given == "a" else (Result("crank AB", a, "mm", how),)
    return Solution(number, EXAMPLES_BY_NUMBER[number].title, dict(p), (
        "The frame pivot D on the side of A of the chord C1C2 (the textbook's family).",), (
        Part("Design", found + (
            Result("frame AD", d, "mm", how), Result("angle α = ∠AOC1", q.alpha, "rad", "fixed by the given length"),
            Result("extreme-position angle θ", math.pi * (K - 1.0) / (K + 1.0), "rad", "θ = 180° (K − 1)/(K + 1)"),
        ), ()),
        Part("Check by analysis", (
            Result("minimum transmission angle γ_min", m.min_transmission_angle, "rad",
                   "`FourBar` over a crank turn"),
        ), (f"Simulated over a crank turn: K = {m.time_ratio:.6g}, swing {math.degrees(m.output_range):.6g}°.",)),
    ))


def _sample_task(rng):
    return {"K": _int(rng, 110, 150, 5) / 100.0, "c": _int(rng, 80, 120, 5), "phi": _int(rng, 30, 60, 5)}


def _sample_e2_17(rng):
    p = _sample_task(rng)
    top = p["c"] * math.sin(p["phi"] * _DEG / 2)            # a < c sin(φ/2)
    return p | {"a": _int(rng, 0.3 * top, 0.95 * top, 0.5)}


def _sample_e2_18(rng):
    p = _sample_task(rng)
    low = p["c"] * math.sin(p["phi"] * _DEG / 2)            # c sin(φ/2) < b < c sin(φ/2)/sin(θ/2)
    high = low / math.sin(math.pi * (p["K"] - 1) / (p["K"] + 1) / 2)
    return p | {"b": _int(rng, low + 0.05 * (high - low), min(high, 4 * low), 0.5)}


# ----------------------------------------------------------------------------- E2-7
def _solve_e2_7(p):
    from mech.planar import centre_velocities, higher_pair, instant_centres, prismatic

    R, e = positive_length("R", p["R"]), positive_length("e", p["e"])
    theta, w1 = _crank_angle(p)
    if not e < R:
        raise ValueError(f"Expected the disc's centre inside it, `e` < `R`, got e={e!r}, R={R!r}")
    K = e * complex(math.cos(theta * _DEG), math.sin(theta * _DEG))
    T = 1j * (K.imag + math.sqrt(R * R - K.real * K.real))     # the tip on the upper side of the disc
    centres = instant_centres(3, {(1, 3): 0j, (2, 3): prismatic(1j), (1, 2): higher_pair(T, T - K)})
    p12 = _near("P12", None if centres[1, 2].at_infinity else complex(centres[1, 2].point), R)
    v2 = complex(centre_velocities(centres, frame=3, driver=1, omega=w1).point_velocity(2, T)).imag
    return Solution("E2-7", EXAMPLES_BY_NUMBER["E2-7"].title, dict(p), (
        "A at the origin, the follower on the vertical line through A, its tip T on the upper side "
        "of the disc; θ is the angle of A→K from +x; velocities positive upwards.",
        "P13 = A; P23 lies at infinity, across the follower's path.",), (
        Part("Instant centre P12", (
            Result("P12 (x)", p12.real, "mm", "on the line through A across the path (Kennedy) and on the "
                                               "common normal at T, which passes through K"),
        ), ()),
        Part("Follower", (
            Result("v2", v2, "mm/s", "the follower moves as the cam's point P12: v2 = ω1 P13P12, (F37)"),
        ), ()),
    ))


def _sample_e2_7(rng):
    return {"R": _int(rng, 20, 40), "e": _int(rng, 5, 15), "theta1": _off_axis(rng), "omega1": _int(rng, 1, 6)}


# ----------------------------------------------------------------------------- E2-11
def _solve_e2_11(p):
    from mech.planar import friction_angle, wedge_press, wedge_press_forces

    Q, lam, mu = (real_number(n, p[n]) for n in ("Q", "lam", "mu"))
    if not Q > 0.0:
        raise ValueError(f"Expected a pressing force `Q` > 0, got {Q!r}")
    if not 0.0 < mu < 1.0:
        raise ValueError(f"Expected a friction coefficient 0 < `mu` < 1, got {mu!r}")
    phi = friction_angle(mu)
    if not 0.0 < lam * _DEG < math.pi / 2 - 2 * phi:
        raise ValueError(f"Expected a wedge angle 0 < `lam` < 90° − 2φ = {90 - 2 * math.degrees(phi):.6g}° "
                         f"(else the push cannot press, eq. 2-27), got {lam!r}")
    w = wedge_press(lam * _DEG, phi)
    press = wedge_press_forces(Q, lam * _DEG, phi)
    return Solution("E2-11", EXAMPLES_BY_NUMBER["E2-11"].title, dict(p), (
        f"The friction angle φ = arctan μ = {math.degrees(phi):.6g}° on all three sliding faces.",), (
        Part("Pressing", (
            Result("push P", press.P.real, "N", "the force polygons of wedges 2 and 3: P = Q tan(λ + 2φ), (2-25)"),
            Result("efficiency η", w.efficiency, "", "η = tan λ / tan(λ + 2φ), (2-26)"),
        ), ()),
        Part("Release", (
            Result("push P′ on the release", Q * w.reverse_ratio, "N",
                   "friction reversed: P′ = Q tan(λ − 2φ)" + ("; negative: a pull is needed to let go"
                                                                 if w.reverse_locks else "")),
            Result("efficiency η′", w.reverse_efficiency, "", "η′ = tan(λ − 2φ) / tan λ, (2-28)"),
        ), ("The press holds the workpiece by itself after the push is removed exactly when "
            f"η′ ≤ 0, that is λ ≤ 2φ (2-29): here it {'holds' if w.reverse_locks else 'does not hold'}.",)),
    ))


def _sample_e2_11(rng):
    return {"Q": _int(rng, 500, 5000, 100), "lam": _int(rng, 4, 30), "mu": _int(rng, 5, 20) / 100.0}


# ----------------------------------------------------------------------------- E2-25
def _solve_e2_25(p):
    import numpy as np

    from mech.spatial import example_2_25_manipulator, example_2_25_reach

    s0, s2, pt = positive_length("S0", p["S0"]), positive_length("S2", p["S2"]), positive_length("p", p["p"])
    q = np.array([real_number("phi01", p["phi01"]) * _DEG, real_number("phi12", p["phi12"]) * _DEG, s2,
                  real_number("phi34", p["phi34"]) * _DEG])
    pose = example_2_25_manipulator(s0).pose(q, point=(0.0, 0.0, pt))
    x, y, z = (float(v) for v in np.ravel(pose.P))
    how = "the product M01 M12 M23 M34 of the H-D matrices, eq. (2-73)"
    return Solution("E2-25", EXAMPLES_BY_NUMBER["E2-25"].title, dict(p), (
        "Base frame 0 at A, z0 up; the gripper point P lies p along z4.",), (
        Part("Gripper point", (
            Result("P (x0)", x, "mm", how), Result("P (y0)", y, "mm", how), Result("P (z0)", z, "mm", how),
        ), ("The gripper's own turn φ34 moves its jaws, not the point P on its axis.",)),
        Part("Distance from the base", (
            Result("AP", float(example_2_25_reach(q[1], s2, s0, pt)), "mm",
                   "AP² = S0² + (p + S2)² − 2 S0 (p + S2) cos φ12, the triangle ABP"),
        ), ()),
    ))


def _sample_e2_25(rng):
    return {"S0": _int(rng, 300, 500, 10), "p": _int(rng, 50, 120, 10), "phi01": _off_axis(rng) - 180.0,
            "phi12": _int(rng, 20, 160, 5), "S2": _int(rng, 100, 400, 10), "phi34": _int(rng, -180, 180, 15)}


# ----------------------------------------------------------------------------- records
_TASK = ("a crank-rocker whose time ratio is K = {K}, whose rocker CD = {c} mm swings through "
         "φ = {phi}°, and ")
EXAMPLES = (
    _example("E2-4", "Worked example 2-4: angular velocities of a four-bar by instant centres",
             "In the four-bar ABCD the crank AB = {a} mm (link 1), the coupler BC = {b} mm (link 2), the "
             "rocker CD = {c} mm (link 3) and the frame AD = {d} mm (link 4). The crank is at θ1 = {theta1}° "
             "from AD and turns at ω1 = {omega1} rad/s (negative: clockwise). Locate the instant centres "
             "P13 and P24 and find from them ω2 and ω3 (counter-clockwise positive).",
             (Parameter("a", 10.0), Parameter("b", 40.0), Parameter("c", 30.0), Parameter("d", 35.0),
              Parameter("theta1", 40.0, "deg"), Parameter("omega1", -3.0, "rad/s")),
             _solve_e2_4, _sample_e2_4, tag="A"),     # the text gives no dimensions: they are chosen
    _example("E2-5", "Worked example 2-5: a slider-crank's velocities by instant centres",
             "In the centric slider-crank ABC the crank AB = {a} mm (link 1) and the rod BC = {b} mm "
             "(link 2) drive the slider C (link 3) along a guide through A. The crank is at θ1 = {theta1}° "
             "from the guide and turns at ω1 = {omega1} rad/s (counter-clockwise). Locate the instant centre "
             "P13 and find ω2 (counter-clockwise positive) and the slider's velocity v3 (positive along the "
             "guide, away from A at θ1 = 0).",
             (Parameter("a", 30.0), Parameter("b", 80.0), Parameter("theta1", 45.0, "deg"),
              Parameter("omega1", 2.0, "rad/s")), _solve_e2_5, _sample_e2_5, tag="A"),
    _example("E2-7", "Worked example 2-7: a disc cam's follower velocity by instant centres",
             "A circular disc cam (link 1) of radius R = {R} mm turns about A, e = {e} mm from its centre K, "
             "at ω1 = {omega1} rad/s (counter-clockwise). A knife-edge follower (link 2) slides on the "
             "vertical line through A, its tip on the upper side of the disc; the frame is link 3. With the "
             "line A→K at θ = {theta1}° from the horizontal, locate the instant centre P12 and find the "
             "follower's velocity v2 (positive upwards).",
             (Parameter("R", 30.0), Parameter("e", 12.0), Parameter("theta1", 40.0, "deg"),
              Parameter("omega1", 2.5, "rad/s")), _solve_e2_7, _sample_e2_7, tag="A"),
    _example("E2-11", "Worked example 2-11: forces and efficiency of a wedge press",
             "In a wedge press a horizontal wedge 2 of angle λ = {lam}°, pushed by P, lifts a vertical "
             "wedge 3 that presses the workpiece with Q = {Q} N. The base, the inclined face and the "
             "vertical guide all have the friction coefficient μ = {mu}. Find the push P and the "
             "efficiency η while pressing, and the push P′ and the efficiency η′ on the release (when the "
             "workpiece drives back). Does the press hold the workpiece by itself?",
             (Parameter("Q", 1000.0, "N"), Parameter("lam", 10.0, "deg"), Parameter("mu", 0.1, "")),
             _solve_e2_11, _sample_e2_11, tag="A"),   # the text gives no numbers: they are chosen
    _example("E2-12", "Worked example 2-12: the forces of a four-bar without friction",
             "A four-bar ABCD (AB = {AB} mm crank 1, BC = {BC} mm coupler 2, CD = {CD} mm rocker 3, AD = {AD} mm "
             "frame 4) turns slowly, its crank counter-clockwise, driven by a moment M_d on the crank. A "
             "resistance Q = {Q} N acts at the point E of the rocker, DE = {DE} mm from D, at right angles to "
             "DE and against the rocker's motion. With the crank at θ1 = {theta1}° from AD and no friction, "
             "find the force R12 between crank and coupler and the driving moment M_d (counter-clockwise "
             "positive).",
             (Parameter("AB", 30.0), Parameter("BC", 70.0), Parameter("CD", 60.0), Parameter("AD", 80.0),
              Parameter("theta1", 60.0, "deg"), Parameter("DE", 40.0), Parameter("Q", 100.0, "N")),
             _solve_e2_12, _sample_e2_12, tag="A"),   # the text gives no numbers: they are chosen
    _example("E2-14", "Worked example 2-14: when a double slider locks itself",
             "A link AB of length l = {l} mm joins slider 2 at A, which a push P drives down a vertical guide, "
             "to slider 3 at B on a horizontal guide through the foot of that vertical guide. Both pins have "
             "the radius r = {r} mm and the friction coefficient μ0 = {mu0}; both sliders have the friction "
             "coefficient μ = {mu}. Up to which horizontal distance x from A to B does the linkage lock "
             "itself (no push, however large, moves slider 3)?",
             (Parameter("l", 100.0), Parameter("r", 10.0), Parameter("mu0", 0.15, ""), Parameter("mu", 0.2, "")),
             _solve_e2_14, _sample_e2_14, tag="A"),   # the text gives no numbers: they are chosen
    _example("E2-17", "Worked example 2-17: a quick-return crank-rocker with a given crank",
             "Design " + _TASK + "whose crank AB = {a} mm: find the coupler BC, the frame AD and the "
             "minimum transmission angle γ_min.",
             (Parameter("K", 1.3, ""), Parameter("c", 100.0), Parameter("phi", 40.0, "deg"), Parameter("a", 31.4)),
             lambda p: _design("E2-17", p, "a"), _sample_e2_17),
    _example("E2-18", "Worked example 2-18: a quick-return crank-rocker with a given coupler",
             "Design " + _TASK + "whose coupler BC = {b} mm: find the crank AB, the frame AD and the "
             "minimum transmission angle γ_min.",
             (Parameter("K", 1.3, ""), Parameter("c", 100.0), Parameter("phi", 40.0, "deg"), Parameter("b", 73.67)),
             lambda p: _design("E2-18", p, "b"), _sample_e2_18),
    _example("E2-25", "Worked example 2-25: the gripper point of an RRPR manipulator",
             "A manipulator (joints R, R, P, R) turns its column about the vertical axis z0 through the base "
             "A by φ01 = {phi01}°; the shoulder B lies S0 = {S0} mm above A and tilts the arm by φ12 = "
             "{phi12}° (at φ12 = 0 the arm points straight down, at 90° it is level, along x0 when φ01 = 0); "
             "the forearm slides out S2 = {S2} mm from B along the arm and the gripper turns about the arm "
             "by φ34 = {phi34}°. Its H-D parameters (φ, λ, S, h) are (φ01, 90°, S0, 0), (φ12, 90°, 0, 0), "
             "(0, 0, S2, 0) and (φ34, 0, 0, 0). Find the coordinates (x0, y0, z0) of the gripper point P, "
             "p = {p} mm out along the gripper's axis z4, and its distance AP from the base.",
             (Parameter("S0", 400.0), Parameter("p", 80.0), Parameter("phi01", 30.0, "deg"),
              Parameter("phi12", 60.0, "deg"), Parameter("S2", 250.0), Parameter("phi34", 45.0, "deg")),
             _solve_e2_25, _sample_e2_25, tag="A"),   # the text gives no dimensions: they are chosen
)

#: The examples by number (the solvers read their titles here).
EXAMPLES_BY_NUMBER = {ex.number: ex for ex in EXAMPLES}


# ----------------------------------------------------------------------------- figures
def draw_example(number, p, fig):
    """Draw the figure of worked example ``number`` with the givens ``p`` into ``fig``
    (Matplotlib; the givens only, never an answer)."""
    from mech.exercises import _figures as F

    ax = fig.add_subplot(111)
    if number == "E2-4":
        lk, th = F._fourbar(p["a"], p["b"], p["c"], p["d"], p["theta1"])
        F.linkage(ax, lk, th, title=f"four-bar (a, b, c, d) = ({p['a']:g}, {p['b']:g}, {p['c']:g}, {p['d']:g}) mm, "
                                    f"θ1 = {p['theta1']:.4g}°")
    elif number == "E2-5":
        F.linkage(ax, F._slider_crank(p["a"], p["b"], 0.0), p["theta1"] * _DEG,
                  title=f"slider-crank, a = {p['a']:g} mm, b = {p['b']:g} mm, θ1 = {p['theta1']:.4g}°")
    elif number in ("E2-17", "E2-18"):
        c, phi = p["c"], p["phi"] * _DEG
        ax.plot([0.0, c * math.cos(math.pi / 2 + phi / 2)], [0.0, c * math.sin(math.pi / 2 + phi / 2)], "r-", lw=2)
        ax.plot([0.0, c * math.cos(math.pi / 2 - phi / 2)], [0.0, c * math.sin(math.pi / 2 - phi / 2)], "r-", lw=2)
        ax.plot([0.0], [0.0], "k^", ms=10)
        ax.annotate("D", (0.0, 0.0), textcoords="offset points", xytext=(6, -12))
        for name, s in (("C1", 1), ("C2", -1)):
            ax.annotate(name, (c * math.cos(math.pi / 2 + s * phi / 2), c * math.sin(math.pi / 2 + s * phi / 2)),
                        textcoords="offset points", xytext=(4, 4))
        ax.set_aspect("equal")
        ax.set_axis_off()
        given = f"AB = {p['a']:g} mm" if number == "E2-17" else f"BC = {p['b']:g} mm"
        ax.set_title(f"rocker CD = {c:g} mm at its limit positions, φ = {p['phi']:g}°, K = {p['K']:g}, {given}")
    elif number == "E2-7":
        k = p["e"] * complex(math.cos(p["theta1"] * _DEG), math.sin(p["theta1"] * _DEG))
        tip = k.imag + math.sqrt(p["R"] ** 2 - k.real**2)
        t = [2 * math.pi * i / 120 for i in range(121)]
        ax.plot([k.real + p["R"] * math.cos(a) for a in t], [k.imag + p["R"] * math.sin(a) for a in t], "-",
                color="tab:blue")
        ax.plot([0, k.real], [0, k.imag], "-", color="tab:blue")
        ax.plot([0, 0], [tip, tip + p["R"]], "-", color="tab:green", lw=3)
        ax.plot([0], [0], "k^", ms=10)
        for name, z in (("A", 0j), ("K", k)):
            ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(5, -10))
        ax.set_aspect("equal")
        ax.set_title(f"disc cam R = {p['R']:g} mm, e = {p['e']:g} mm, θ = {p['theta1']:g}°, knife-edge follower")
    elif number == "E2-12":
        lk, th = F._fourbar(p["AB"], p["BC"], p["CD"], p["AD"], p["theta1"])
        F.linkage(ax, lk, th, title=f"four-bar ({p['AB']:g}, {p['BC']:g}, {p['CD']:g}, {p['AD']:g}) mm, "
                                    f"θ1 = {p['theta1']:g}°, Q = {p['Q']:g} N at DE = {p['DE']:g} mm")
        import numpy as np

        c = complex(np.ravel(lk.solve(np.array([th])).points["C"])[0])
        u = (c - p["AD"]) / abs(c - p["AD"])
        e = p["AD"] + p["DE"] * u
        ax.plot([e.real], [e.imag], "ko", ms=5)
        ax.annotate("E", (e.real, e.imag), textcoords="offset points", xytext=(6, -4))
        tip = e + 0.3 * p["CD"] * 1j * u          # Q's line, across DE (its sense is the solution's)
        ax.annotate("", xy=(tip.real, tip.imag), xytext=(e.real, e.imag), arrowprops={"arrowstyle": "<->"})
        ax.annotate("line of Q", (tip.real, tip.imag), textcoords="offset points", xytext=(-20, 6), fontsize=8)
    elif number == "E2-14":
        from matplotlib.patches import Circle

        l, x = p["l"], 0.5 * p["l"]
        a, b = (0.0, math.sqrt(l * l - x * x)), (x, 0.0)
        ax.plot([-0.1 * l, 1.1 * l], [-0.05 * l, -0.05 * l], "k-", lw=1)
        ax.plot([-0.08 * l, -0.08 * l], [0, 1.1 * l], "k-", lw=1)
        ax.plot([a[0], b[0]], [a[1], b[1]], "-", color="tab:blue", lw=3)
        for (cx, cy), name in ((a, "A"), (b, "B")):
            ax.add_patch(Circle((cx, cy), p["r"], fill=False))             # the pin
            ax.annotate(name, (cx, cy), textcoords="offset points", xytext=(8, 6))
        ax.annotate("P", xy=(0, a[1] + p["r"]), xytext=(0.1 * l, a[1] + 0.25 * l), arrowprops={"arrowstyle": "->"})
        ax.set_aspect("equal")
        ax.set_axis_off()
        ax.set_title(f"double slider, l = {l:g} mm, r = {p['r']:g} mm, μ0 = {p['mu0']:g}, μ = {p['mu']:g} "
                     "(drawn at x = l/2)", fontsize=9)
    elif number == "E2-11":
        _draw_wedge_press(ax, p)
    elif number == "E2-25":
        _draw_manipulator(ax, p)
    else:
        raise ValueError(f"Expected `number` to be a worked example with a figure, got {number!r}")


def _draw_wedge_press(ax, p):
    """Wedge 2 on the base with its face at λ, wedge 3 above it in its vertical guide."""
    t = math.tan(p["lam"] * _DEG)
    w, h0 = 10.0, 2.0
    # the push P drives the thick end: the face under wedge 3 rises as wedge 2 moves right
    ax.fill([0, w, w, 0], [0, 0, h0, h0 + w * t], color="tab:blue", alpha=0.4)        # wedge 2
    ax.fill([3, 7, 7, 3], [h0 + 7 * t, h0 + 3 * t, 12, 12], color="tab:green", alpha=0.4)  # wedge 3
    ax.plot([-1, 12], [0, 0], "k-", lw=2)
    ax.plot([2.6, 2.6], [6, 13], "k-", lw=2)
    ax.plot([7.4, 7.4], [6, 13], "k-", lw=2)
    ax.annotate("P", xy=(0, 1), xytext=(-4, 1), arrowprops={"arrowstyle": "->"})
    ax.annotate("Q", xy=(5, 12), xytext=(4.8, 14.2), arrowprops={"arrowstyle": "->"})     # the load on wedge 3
    ax.set_ylim(-1.0, 15.0)
    ax.text(w - 2.5, 0.5, "λ", fontsize=12)
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title(f"wedge press, λ = {p['lam']:g}°, μ = {p['mu']:g}, Q = {p['Q']:g} N")


def _draw_manipulator(ax, p):
    """The manipulator seen from the side, in the plane of the arm: column AB, arm B->P."""
    s0, r = p["S0"], p["S2"] + p["p"]
    t = p["phi12"] * _DEG
    tip = (r * math.sin(t), s0 - r * math.cos(t))
    ax.plot([0, 0], [0, s0], "k-", lw=4)
    ax.plot([0, tip[0]], [s0, tip[1]], "-", color="tab:blue", lw=3)
    ax.plot([0], [0], "k^", ms=12)
    for name, xy in (("A", (0, 0)), ("B", (0, s0)), ("P", tip)):
        ax.annotate(name, xy, textcoords="offset points", xytext=(6, 4))
    ax.plot([-0.3 * s0, 0.3 * s0], [0, 0], "k-", lw=1)
    ax.set_aspect("equal")
    ax.set_title(f"RRPR manipulator in the plane of its arm: S0 = {s0:g} mm, φ12 = {p['phi12']:g}°, "
                 f"S2 + p = {r:g} mm", fontsize=9)


for _ex in EXAMPLES:
    _figures.EXAMPLE_DRAWERS[_ex.number] = draw_example
