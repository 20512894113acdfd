"""The package's one task layer: checks that a design task (what a synthesis function is asked
to meet) is a task at all, before any equation is built from it.

`mech._validate` checks each argument on its own (type, shape, finite values). A design
task can pass all of those checks and still be no task: two of its poses may be the same
pose (equal, or one whole turn apart with the same translation), all its data may
coincide, or a point the design needs may be at infinity. Such a task makes the design
equations dependent, and a solver would otherwise fail deep inside (an SVD that does not
converge), or quietly return a design for fewer poses than were given.

Every check here compares the data with the task's own size (the spread of its
translations or points; the turn of its orientations), never with a fixed length, so a
task scaled by any power of ten from 1e-200 to 1e200 is accepted or refused alike. A
refusal is a ``ValueError`` naming the arguments and the offending entries, counted from 1
as the textbooks count poses: "Expected distinct poses in `theta`/`d`, got poses 1 and 5
the same pose (a whole number of turns apart): ...".

The module also holds what the solvers need to check their answers against the task:
how far a planar or spherical crank misses its poses (`planar_dyad_error`,
`spherical_dyad_error`, relative to the task's size again), and which polished roots are
distinct real solutions (`single_roots`). A Burmester solver lists a dyad only when it
meets the task; it does not trust the imaginary part of a root.

This is an internal shared module: the synthesis functions of `mech.planar.synthesis` and
`mech.spherical` call it (`pose_set` and `orientation_set` for every pose or orientation
set); it is not part of the public interface.
"""

import numpy as np

__all__ = ["SAME", "distinct_poses", "distinct_orientations", "distinct_pairs", "precision_points",
           "single_roots", "planar_dyad_error", "spherical_dyad_error"]

# Two entries of a task closer than this, relative to the task's size, are one entry. It is
# far above rounding (a pose and the same pose plus a whole turn differ by about 1e-15 of
# the angle) and far below any difference a designer means.
SAME = 1e-12


def _wrapped(turn):
    return turn - 2.0 * np.pi * np.round(turn / (2.0 * np.pi))


def _pair_text(i, j):
    return f"{i + 1} and {j + 1}"


def distinct_poses(theta, d, names=("theta", "d")):
    """Refuse a planar pose set in which two poses are the same pose.

    Poses ``(theta_i, d_i)`` and ``(theta_j, d_j)`` are the same when their relative turn,
    less its nearest whole number of turns, is within `SAME` of the larger angle (at least
    one turn) and their translations differ by at most `SAME` times the spread of all the
    translations. A set whose translations all coincide and whose angles all coincide (the
    all-zero set, for one) is refused by its first two poses.

    Parameters
    ----------
    theta : ndarray, shape (n,)
        Pose angles (already checked by `mech._validate`).
    d : ndarray of complex, shape (n,)
        Pose translations.
    names : tuple of str
        The names of the two arguments, for the message.

    Raises
    ------
    ValueError
        "poses i and j of `theta`/`d` are the same pose", with their values.
    """
    n = theta.size
    if n < 2:
        return
    centre = d.mean() if np.all(np.isfinite(d.mean())) else d[0]
    spread = float(np.max(np.abs(d - centre)))
    for i in range(n - 1):
        for j in range(i + 1, n):
            angle_scale = max(2.0 * np.pi, abs(float(theta[i])), abs(float(theta[j])))
            turn = abs(float(_wrapped(theta[j] - theta[i])))
            moved = abs(complex(d[j] - d[i]))
            if turn <= SAME * angle_scale and moved <= SAME * spread:
                whole = "" if theta[i] == theta[j] else " (a whole number of turns apart)"
                raise ValueError(
                    f"Expected distinct poses in `{names[0]}`/`{names[1]}`, got poses {_pair_text(i, j)} "
                    f"the same pose{whole}: {names[0]} = {float(theta[i])!r} and {float(theta[j])!r}, "
                    f"{names[1]} = {complex(d[i])!r} and {complex(d[j])!r}")


def _rotation_gap(Ri, Rj):
    """The angle of the relative rotation of two orientations, from their difference."""
    chord = np.linalg.norm(Ri - Rj) / (2.0 * np.sqrt(2.0))        # sin(angle / 2)
    return 2.0 * np.arcsin(min(1.0, chord))


def distinct_orientations(R, name="R"):
    """Refuse a set of orientations in which two are the same orientation.

    Orientations are compared by the angle of their relative rotation; two are the same
    when it is at most `SAME` times the largest such angle in the set (an exact repeat, or
    one rounded from the other), or when every orientation in the set is equal.

    Raises
    ------
    ValueError
        "orientations i and j of `R` are the same orientation", naming their angle.
    """
    n = R.shape[0]
    if n < 2:
        return
    gaps = np.zeros((n, n))
    for i in range(n - 1):
        for j in range(i + 1, n):
            gaps[i, j] = _rotation_gap(R[i], R[j])
    size = float(np.max(gaps))
    for i in range(n - 1):
        for j in range(i + 1, n):
            if gaps[i, j] <= SAME * size:
                raise ValueError(
                    f"Expected distinct orientations in `{name}`, got orientations {_pair_text(i, j)} the same "
                    f"orientation (relative turn {float(gaps[i, j])!r} rad, largest turn in the set {size!r} rad)")


def _same_angle(a, b):
    """Whether two angles are one direction: equal, or a whole number of turns apart, to
    `SAME` of the larger angle (at least one turn)."""
    scale = max(2.0 * np.pi, abs(float(a)), abs(float(b)))
    return abs(float(_wrapped(float(b) - float(a)))) <= SAME * scale


def _entries(idx):
    idx = [k + 1 for k in idx]
    return ", ".join(map(str, idx[:-1])) + " and " + str(idx[-1])


def distinct_pairs(x, y, names=("x", "y"), exact=True):
    """Refuse function-generation pairs ``(x_i, y_i)`` that repeat or contradict each other.

    A four-bar (planar or spherical) meets a pair through ``cos`` and ``sin`` of the input
    and output angles only, so two pairs whose inputs are one direction (equal, or whole
    turns apart, to `SAME`) are one pair when their outputs are one direction too, and
    contradict each other when they are not (one input angle, two outputs). With `exact`
    (precision pairs, met exactly) three pairs may not share one output direction either:
    at a fixed output angle Freudenstein's equation, planar or spherical, is
    ``A cos(theta) + B sin(theta) = C``, met at two input angles of a turn at most. A fit
    (``exact=False``) is refused only when every output is one direction (the output does
    not move).

    Parameters
    ----------
    x, y : ndarray, shape (n,)
        Input and output rotations, radians (already checked by `mech._validate`).
    names : tuple of str
        The names of the two arguments, for the message.
    exact : bool
        Whether the pairs are to be met exactly (precision pairs) or fitted.

    Raises
    ------
    ValueError
        Naming both arguments and the offending pairs (counted from 1) with their values.
    """
    nx, ny = names
    n = x.size
    for i in range(n - 1):
        for j in range(i + 1, n):
            if not _same_angle(x[i], x[j]):
                continue
            if _same_angle(y[i], y[j]):
                raise ValueError(
                    f"Expected distinct pairs in `{nx}`/`{ny}`, got pairs {_pair_text(i, j)} the same pair (a whole "
                    f"number of turns apart): {nx} = {float(x[i])!r} and {float(x[j])!r}, "
                    f"{ny} = {float(y[i])!r} and {float(y[j])!r}")
            raise ValueError(
                f"Expected one output in `{ny}` for one input direction in `{nx}`, got pairs {_pair_text(i, j)} with "
                f"{nx} = {float(x[i])!r} and {float(x[j])!r} (one direction) but {ny} = {float(y[i])!r} and "
                f"{float(y[j])!r}")
    groups = []
    for i in range(n):
        for g in groups:
            if _same_angle(y[g[0]], y[i]):
                g.append(i)
                break
        else:
            groups.append([i])
    for g in groups:
        if (exact and len(g) >= 3) or (not exact and n >= 2 and len(g) == n):
            shown = ", ".join(repr(float(y[k])) for k in g)
            raise ValueError(
                f"Expected outputs in `{ny}` that {'no three pairs share' if exact else 'move'} (a four-bar's output "
                f"has one angle at two inputs of a turn at most), got pairs {_entries(g)} of `{nx}`/`{ny}` with one "
                f"output direction: {ny} = {shown}")


def precision_points(Q, theta, names=("points", "theta"), one_point=True):
    """Refuse precision points of a path with timing that are no task.

    The input angles must move one way within one turn, so no two name one crank position
    (equal, or a whole turn apart); the unit vectors `Q` (already normalised) may not all
    be one point (a coupler point that does not move). Two points may coincide (a coupler
    curve can cross itself) when their input angles differ. ``one_point=False`` skips the
    last check (for verifying a given linkage against points, which any points can be).

    Raises
    ------
    ValueError
        Naming the argument and the offending entries (counted from 1) with their values.
    """
    nq, nt = names
    n = theta.size
    step = np.diff(theta)
    sign = 1.0 if step.size and step[0] > 0 else -1.0
    for i in range(n - 1):
        if not sign * step[i] > 0:
            word = "repeat" if step[i] == 0 else "turn back"
            raise ValueError(
                f"Expected `{nt}` strictly monotonic within one turn, got entries {_pair_text(i, i + 1)} that "
                f"{word}: {float(theta[i])!r} and {float(theta[i + 1])!r}")
    if n >= 2 and abs(float(theta[-1] - theta[0])) >= 2.0 * np.pi:
        j = next(k for k in range(1, n) if abs(float(theta[k] - theta[0])) >= 2.0 * np.pi)
        raise ValueError(
            f"Expected `{nt}` strictly monotonic within one turn, got entries {_pair_text(0, j)} a whole turn or "
            f"more apart: {float(theta[0])!r} and {float(theta[j])!r}")
    arcs = np.arctan2(np.linalg.norm(np.cross(Q, Q[0]), axis=1), Q @ Q[0])
    if one_point and n >= 2 and not np.max(arcs) > 4.0 * np.finfo(float).eps:
        raise ValueError(
            f"Expected precision points in `{nq}` that are not all one point, got {n} points within "
            f"{float(np.max(arcs))!r} rad of point 1 = {Q[0].tolist()!r}")


def planar_dyad_error(theta, d, z, A):
    """How far a planar crank (circle point `z`, centre point `A`) misses its poses.

    The largest difference of the crank's radii ``|exp(1j*theta_j)*z + d_j - A|`` over the
    poses, divided by the spread of the translations (the task's size), so a crank that
    meets the task to rounding gives about 1e-15 at any unit. Computed on the data moved
    to their centroid and scaled by their spread, so nothing overflows.
    """
    centre = d.mean()
    size = float(np.max(np.abs(d - centre)))
    size = size if size > 0 else max(abs(complex(z)), abs(complex(A - centre)), np.finfo(float).tiny)
    with np.errstate(over="ignore", invalid="ignore"):
        Z = np.exp(1j * theta) * (z / size) + (d - centre) / size
        radii = np.abs(Z - (A - centre) / size)
        err = float(np.max(radii) - np.min(radii))
    return err if np.isfinite(err) else np.inf


def spherical_dyad_error(R, z, u):
    """How far a spherical crank (body axis `z`, fixed axis `u`) misses its orientations.

    The largest difference of the crank's arcs (atan2 form) over the orientations,
    divided by the task's size: the largest arc that the body point moves between two
    orientations, so that near the planar limit, where the translations are small, the
    error is still measured against them.
    """
    W = np.einsum("nij,j->ni", R, z)
    arcs = np.arctan2(np.linalg.norm(np.cross(W, u), axis=1), W @ u)
    moved = max(float(np.max(np.linalg.norm(W - W[k], axis=1))) for k in range(len(W)))
    size = moved if moved > 0 else 1.0
    return float(np.max(arcs) - np.min(arcs)) / size


def single_roots(points, drifts, close):
    """Which polished roots of a design equation are distinct real solutions.

    Each root of a solver's polynomial is moved onto the real line and polished by real
    Newton steps; ``points[k]`` is where root k ends and ``drifts[k]`` how far it moved.
    Several roots can end at one point: the two roots of a complex pair (their real parts,
    or their projections onto the unit circle, are equal) or a root far from the real
    line that Newton's method carries to a real solution some other root already found.
    Within such a group the root that moved least is the real one when it moved at most
    half as far as any other; otherwise (a tie, as for a complex pair, whose two roots move
    equally far, or by a factor of at most 1.5 for the pair ``x``, ``1/conj(x)`` of a
    spherical solver within 0.5 of the unit circle; or a double root) none is.
    ``close(p, q)`` says whether two points are one.

    Returns
    -------
    list of int
        The indices kept, in order.
    """
    n = len(points)
    group = list(range(n))
    for i in range(n):
        for j in range(i):
            if close(points[i], points[j]):
                old, new = group[i], group[j]
                group = [new if g == old else g for g in group]
    kept = []
    for g in sorted(set(group)):
        members = sorted((k for k in range(n) if group[k] == g), key=lambda k: drifts[k])
        if len(members) == 1 or 2.0 * drifts[members[0]] < drifts[members[1]]:
            kept.append(members[0])
    return sorted(kept)
