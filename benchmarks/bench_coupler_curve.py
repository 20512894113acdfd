"""Benchmark: run time against error for the coupler curve of one planar four-bar.

Every method computes the coupler point P(theta) of the same crank-rocker (and, at order 2,
its velocity and acceleration for omega = 1, alpha = 0) at N equally spaced input angles:

- ``mech``: ``FourBar.solve(theta, order=0 | 2)`` (generated code with common subexpressions
  eliminated);
- ``naive-codegen``: the same ``FourBar.solve`` with its generated module(s) swapped for the
  project's code generator run with ``cse=False``;
- ``naive-lambdify``: the same, with plain ``sympy.lambdify(..., cse=False)`` functions;
- ``scipy-root``: a per-angle Newton-type solve of the two loop equations with
  ``scipy.optimize.root`` (warm-started), then the linear velocity/acceleration systems;
- ``pylinkage``: pylinkage 1.3.0's numba-compiled simulation loop, timed warm.

Errors are measured against ``benchmarks/reference.py`` (mpmath, 50 digits, a route that does
not use the generated formulas) on a subsample of the angles. Results go to
``benchmarks/results/coupler_curve.json``; goals are printed as PASS/FAIL, never asserted
(the machine is shared: absolute times are noise, ratios matter).

    python benchmarks/bench_coupler_curve.py            # full run
    python benchmarks/bench_coupler_curve.py --quick    # small sizes, nothing written
"""

from __future__ import annotations

import argparse
import contextlib
import datetime as _dt
import importlib
import importlib.metadata
import json
import os
import platform
import sys
import time
import types
from pathlib import Path
from unittest import mock

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

from reference import DPS, coupler_reference, self_check  # noqa: E402

#: The linkage: a crank-rocker (s + l = 1 + 4 <= 3 + 3.5, shortest link is the crank).
GEOMETRY = {"a": 1.0, "b": 4.0, "c": 3.0, "d": 3.5}
BRANCH = 1
COUPLER = (2.0, 1.0)
SIZES = (10_000, 1_000_000)
#: Angles per size where the mpmath reference is evaluated.
SAMPLES = 2000
#: The per-angle root solve is timed on a slice of this many angles and scaled up.
SCIPY_SLICE = 10_000
SCIPY_XTOL = (1e-6, 1e-13)
OUTPUT = HERE / "results" / "coupler_curve.json"

GOALS = {
    "mech_vs_pylinkage_1e4": 3.0,
    "mech_vs_pylinkage_1e6": 5.0,
    "mech_vs_naive": 10.0,
    "order2_vs_order0": 3.0,
}


# ----------------------------------------------------------------------------- helpers


def grid(n):
    """Input angles 2 pi k / n, k = 0 .. n-1."""
    return 2.0 * np.pi * np.arange(n) / n


def sample_index(n, samples=SAMPLES):
    """Indices of the angles where errors are measured: spread over the whole turn."""
    return np.unique(np.linspace(0, n - 1, min(samples, n)).astype(np.int64))


def timed(fn, repeats):
    """Call ``fn()`` ``repeats`` times; return (list of seconds, last result)."""
    times, result = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - start)
    return times, result


def max_error(got, ref, scale):
    """Largest |got - ref| / scale over the samples; None if any value is not finite."""
    if got is None:
        return None
    diff = np.abs(np.asarray(got) - ref)
    if not np.all(np.isfinite(diff)):
        return None
    return float(np.max(diff) / scale)


def versions():
    names = ["numpy", "scipy", "sympy", "mpmath", "pylinkage", "numba", "llvmlite"]
    out = {"python": platform.python_version()}
    for name in names:
        try:
            out[name] = importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            out[name] = None
    return out


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {
        "system": f"{platform.system()} {platform.release()}",
        "cpu": cpu,
        "logical_cpus": os.cpu_count(),
        "usable_cpus": len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else None,
        "load_average_at_start": list(os.getloadavg()) if hasattr(os, "getloadavg") else None,
    }


# ----------------------------------------------------------------------------- mech


def mech_available():
    try:
        from mech.planar import FourBar
    except ImportError:
        return False
    return callable(getattr(FourBar, "solve", None))


def mech_runner(order):
    """Return ``theta -> (P, vP, aP)`` through ``FourBar.solve`` (NumPy backend, as installed
    without the ``fast`` extra; ``bench_speed.py`` times the numba backend)."""
    import mech
    from mech.planar import FourBar

    mech.set_backend("numpy")

    linkage = FourBar(**GEOMETRY, branch=BRANCH, coupler=COUPLER)

    def run(theta):
        pose = linkage.solve(theta, order=order)
        if order >= 2:
            return pose.P, pose.vP, pose.aP
        return pose.P, None, None

    return run


# ----------------------------------------------------------------------------- naive


def _generated_names():
    """Names in ``mech.planar.kinematics._fourbar`` bound to generated modules or functions."""
    import mech.planar.kinematics._fourbar as fourbar

    found = {}
    for name, obj in vars(fourbar).items():
        mod = obj.__name__ if isinstance(obj, types.ModuleType) else getattr(obj, "__module__", "")
        if isinstance(mod, str) and mod.startswith("mech._generated."):
            found[name] = obj
    return found


def _captured_write_calls(stem):
    """Run the derivation notebook of ``stem``, capturing its ``_codegen.write`` calls.

    Nothing is written: ``write`` is replaced by a recorder for the run.
    """
    from derivations import _codegen
    from derivations.__main__ import run

    paths = sorted((ROOT / "derivations").rglob(f"{stem}.md"))
    if not paths:
        raise FileNotFoundError(f"no derivation notebook for generated module {stem!r}")
    calls = []

    def record(stem_, notebook, equations, functions, **kwargs):
        calls.append((stem_, notebook, equations, list(functions)))
        return _codegen.GENERATED_DIR / f"{stem_}.py"

    with mock.patch.dict(os.environ, {"MECH_CODEGEN": "check"}), mock.patch.object(_codegen, "write", record):
        run(paths[0])
    return [c for c in calls if c[0] == stem]


def naive_modules():
    """For each generated module used by ``_fourbar``: (cse=False module, plain-lambdify module)."""
    import sympy as sm

    from derivations import _codegen

    out = {}
    stems = set()
    for obj in _generated_names().values():
        mod = obj.__name__ if isinstance(obj, types.ModuleType) else obj.__module__
        stems.add(mod.rsplit(".", 1)[1])
    for stem in sorted(stems):
        calls = _captured_write_calls(stem)
        if not calls:
            raise RuntimeError(f"notebook for {stem!r} made no _codegen.write call for it")
        _, notebook, equations, functions = calls[-1]
        text = _codegen.render(stem, notebook, equations, functions, cse=False)
        rendered = types.ModuleType(f"naive_{stem}")
        exec(compile(text, f"<naive {stem}>", "exec"), rendered.__dict__)
        plain = types.ModuleType(f"lambdify_{stem}")
        for f in functions:
            exprs = f.exprs()
            target = exprs[0] if len(exprs) == 1 else tuple(exprs)
            setattr(plain, f.name, sm.lambdify(f.symbols(), target, modules="numpy", cse=False))
        generated = importlib.import_module(f"mech._generated.{stem}")
        for module in (rendered, plain):
            # the solver calls the out= kernels: here they run the naive functions and copy
            module.WORK_ROWS = getattr(generated, "WORK_ROWS", {})
            for f in functions:
                if f.vector:
                    setattr(module, f"{f.name}_into", _into_from(getattr(module, f.name)))
        out[stem] = (rendered, plain, text)
    return out


def _into_from(function):
    """An ``<name>_into(*args, out, work)`` kernel that calls `function` and copies its outputs."""

    def into(*args):
        *args, out, _work = args
        for target, value in zip(out, function(*args)):
            target[...] = value

    return into


@contextlib.contextmanager
def swapped_generated(modules, which):
    """Swap the generated code used by ``_fourbar`` for naive versions (which = 0 or 1)."""
    import mech.planar.kinematics._fourbar as fourbar

    with contextlib.ExitStack() as stack:
        for name, obj in _generated_names().items():
            if isinstance(obj, types.ModuleType):
                stem = obj.__name__.rsplit(".", 1)[1]
                stack.enter_context(mock.patch.object(fourbar, name, modules[stem][which]))
            else:
                stem = obj.__module__.rsplit(".", 1)[1]
                replacement = getattr(modules[stem][which], obj.__name__)
                stack.enter_context(mock.patch.object(fourbar, name, replacement))
        yield


def naive_runner(modules, which, order):
    base = mech_runner(order)

    def run(theta):
        with swapped_generated(modules, which):
            return base(theta)

    return run


# ----------------------------------------------------------------------------- scipy


def _loop_residual(x, t, a, b, c, d):
    phi, psi = x
    return [a * np.cos(t) + b * np.cos(phi) - d - c * np.cos(psi), a * np.sin(t) + b * np.sin(phi) - c * np.sin(psi)]


def _loop_jacobian(x, t, a, b, c, d):
    phi, psi = x
    return [[-b * np.sin(phi), c * np.sin(psi)], [b * np.cos(phi), -c * np.cos(psi)]]


def scipy_runner(order, xtol):
    """Per-angle ``scipy.optimize.root`` on the loop equations, warm-started by extrapolation."""
    from scipy.optimize import root

    a, b, c, d = GEOMETRY["a"], GEOMETRY["b"], GEOMETRY["c"], GEOMETRY["d"]
    z = complex(*COUPLER)

    def start(t):
        # Only the first angle: a rough closed-form guess on the requested branch.
        B = a * np.exp(1j * t)
        e = d - B
        L = abs(e)
        along = (b * b - c * c + L * L) / (2 * L)
        C = B + (along + 1j * BRANCH * np.sqrt(max(b * b - along * along, 0.0))) * e / L
        return np.array([np.angle(C - B), np.angle(C - d)])

    def run(theta):
        n = theta.size
        sol = np.empty((n, 2))
        prev = prev2 = None
        for k in range(n):
            if prev is None:
                x0 = start(theta[k])
            elif prev2 is None:
                x0 = prev
            else:
                x0 = 2 * prev - prev2
            res = root(_loop_residual, x0, args=(theta[k], a, b, c, d), jac=_loop_jacobian, method="hybr", tol=xtol)
            prev2, prev = prev, res.x
            sol[k] = res.x
        phi, psi = sol[:, 0], sol[:, 1]
        eB, ephi, epsi = np.exp(1j * theta), np.exp(1j * phi), np.exp(1j * psi)
        P = a * eB + z * ephi
        if order < 2:
            return P, None, None
        # Velocity and acceleration: the loop equation differentiated once and twice.
        M = np.empty((n, 2, 2))
        M[:, 0, 0], M[:, 0, 1] = -b * ephi.imag, c * epsi.imag
        M[:, 1, 0], M[:, 1, 1] = b * ephi.real, -c * epsi.real
        omega, alpha = 1.0, 0.0
        rhs = -1j * a * omega * eB
        w = np.linalg.solve(M, np.stack([rhs.real, rhs.imag], axis=-1)[..., None])[..., 0]
        w2, w3 = w[:, 0], w[:, 1]
        rhs = -(1j * alpha - omega**2) * a * eB + w2**2 * b * ephi - w3**2 * c * epsi
        al = np.linalg.solve(M, np.stack([rhs.real, rhs.imag], axis=-1)[..., None])[..., 0]
        a2 = al[:, 0]
        vP = 1j * a * omega * eB + z * 1j * w2 * ephi
        aP = (1j * alpha - omega**2) * a * eB + z * (1j * a2 - w2**2) * ephi
        return P, vP, aP

    return run


# ----------------------------------------------------------------------------- pylinkage


def pylinkage_available():
    try:
        import numba  # noqa: F401
        import pylinkage  # noqa: F401
    except ImportError:
        return False
    return True


def pylinkage_build(n):
    """The same four-bar in pylinkage: crank AB, RRR dyad C, fixed dyad P on BC.

    The crank turns 2 pi / n per step from -2 pi / n, so step k is at theta = 2 pi k / n.
    The dyad's starting hint lies on the side of B->D named by the branch; pylinkage then
    follows the nearest intersection at each step.
    """
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import FixedDyad, RRRDyad
    from pylinkage.simulation import Linkage

    a, b, c, d = GEOMETRY["a"], GEOMETRY["b"], GEOMETRY["c"], GEOMETRY["d"]
    h = 2.0 * np.pi / n
    A = Ground(0.0, 0.0, name="A")
    D = Ground(d, 0.0, name="D")
    crank = Crank(anchor=A, radius=a, angular_velocity=h, initial_angle=-h, name="B")
    B0 = a * np.exp(-1j * h)
    hint = (B0 + d) / 2 + 1j * BRANCH * b * (d - B0) / abs(d - B0)
    C = RRRDyad(crank.output, D, distance1=b, distance2=c, x=hint.real, y=hint.imag, name="C")
    P = FixedDyad(crank.output, C, distance=abs(complex(*COUPLER)), angle=float(np.angle(complex(*COUPLER))), name="P")
    linkage = Linkage([A, D, crank, C, P], name="crank-rocker")
    linkage.set_input_velocity(crank, omega=1.0, alpha=0.0)
    linkage.compile()
    return linkage, linkage.components.index(P)


def _pylinkage_step(linkage, ip, order, n):
    if order >= 2:
        pos, vel, acc = linkage.step_fast_with_kinematics(iterations=n, dt=1.0)
        c = lambda arr: arr[:, ip, 0] + 1j * arr[:, ip, 1]  # noqa: E731
        return c(pos), c(vel), c(acc)
    pos = linkage.step_fast(iterations=n, dt=1.0)
    return pos[:, ip, 0] + 1j * pos[:, ip, 1], None, None


def interleaved(preparers, repeats):
    """Time several methods round-robin: repeat r runs every method once, in turn.

    ``preparers`` maps a key to a function that does the untimed set-up of one repeat and
    returns the call to time. Each method is called once, untimed, before the repeats.
    Interleaving spreads a shared machine's load changes over all
    methods alike, which keeps the ratios between them honest.
    Returns {key: (list of seconds, result of the last call)}.
    """
    times = {k: [] for k in preparers}
    results = {}
    for prepare in preparers.values():  # one untimed full-size call each: warm memory and caches
        prepare()()
    for _ in range(repeats):
        for key, prepare in preparers.items():
            call = prepare()
            start = time.perf_counter()
            results[key] = call()
            times[key].append(time.perf_counter() - start)
    return {k: (times[k], results[k]) for k in preparers}


def pylinkage_drift(n, samples=300):
    """Where pylinkage's error comes from: the crank angle it actually reached.

    pylinkage advances the crank from the angle of its previous position, so rounding
    accumulates in the input angle. Returns the largest drift of that angle from 2 pi k / n,
    and pylinkage's position error measured at its own crank angle instead (relative to
    a + b + c + d): if the second is at rounding level, the drift explains the error.
    """
    linkage, ip = pylinkage_build(n)
    pos = linkage.step_fast(iterations=n, dt=1.0)
    ib = next(i for i, comp in enumerate(linkage.components) if comp.name == "B")
    actual = np.unwrap(np.angle(pos[:, ib, 0] + 1j * pos[:, ib, 1]))
    idx = sample_index(n, samples)
    P = pos[idx, ip, 0] + 1j * pos[idx, ip, 1]
    own, _, _ = coupler_reference(actual[idx], **GEOMETRY, branch=BRANCH, coupler=COUPLER)
    return {
        "n": n,
        "max_input_angle_drift_rad": float(np.max(np.abs(actual - grid(n)))),
        "err_position_at_own_crank_angle": max_error(P, own, sum(GEOMETRY.values())),
    }


# ----------------------------------------------------------------------------- driver


def run_benchmark(sizes, samples, repeats_small, repeats_large, scipy_slice, log=print):
    scale = sum(GEOMETRY.values())
    self_check(**GEOMETRY, branch=BRANCH, coupler=COUPLER)
    results, notes = [], []

    references = {}
    for n in sizes:
        idx = sample_index(n, samples)
        start = time.perf_counter()
        references[n] = (idx, coupler_reference(grid(n)[idx], **GEOMETRY, branch=BRANCH, coupler=COUPLER))
        log(f"reference N={n}: {idx.size} angles in {time.perf_counter() - start:.1f} s")

    def record(method, label, order, n, times, out, idx, ref, scaled_from=None, note=""):
        P, vP, aP = out
        entry = {
            "method": method,
            "label": label,
            "order": order,
            "n": n,
            "time_s": float(np.median(times)) * (n / scaled_from if scaled_from else 1.0),
            "time_min_s": float(np.min(times)) * (n / scaled_from if scaled_from else 1.0),
            "times_s": [float(t) for t in times],
            "timed_n": scaled_from or n,
            "scaled": bool(scaled_from),
            "err_position": max_error(None if P is None else np.asarray(P)[idx], ref[0], scale),
            "err_velocity": max_error(None if vP is None else np.asarray(vP)[idx], ref[1], scale),
            "err_acceleration": max_error(None if aP is None else np.asarray(aP)[idx], ref[2], scale),
            "note": note,
        }
        results.append(entry)
        log(
            f"  {label:<28} order={order} N={n:>8}: {entry['time_s'] * 1e3:10.2f} ms"
            f"{' (scaled)' if scaled_from else ''}  errP={entry['err_position']}"
            f"  errV={entry['err_velocity']}  errA={entry['err_acceleration']}"
        )

    have_mech = mech_available()
    naive = None
    if have_mech:
        try:
            naive = naive_modules()
        except Exception as exc:  # reported, not fatal: the other methods still run
            notes.append(f"naive code generation unavailable: {type(exc).__name__}: {exc}")
            log(notes[-1])
    else:
        notes.append("mech.planar.FourBar.solve is not available: mech and naive methods skipped")
        log(notes[-1])
    have_pylinkage = pylinkage_available()
    if have_pylinkage:
        _pylinkage_step(*pylinkage_build(64), 0, 64)  # compile the numba kernels (warm-up)
        _pylinkage_step(*pylinkage_build(64), 2, 64)
    else:
        notes.append("pylinkage or numba not installed: pylinkage skipped")
        log(notes[-1])

    for n in sizes:
        theta = grid(n)
        idx, ref = references[n]
        repeats = repeats_small if n <= 10_000 else repeats_large
        log(f"N = {n}")
        for order in (0, 2):
            # Two groups, each timed round-robin: mech with pylinkage, then the naive
            # variants. The naive code churns through gigabytes of temporaries at N = 1e6;
            # interleaved with mech it would leave mech allocating cold, unmapped memory.
            groups = [({}, {}), ({}, {})]
            if have_mech:
                run = mech_runner(order)
                run(theta[:16])
                groups[0][0]["mech"] = lambda run=run: (lambda: run(theta))
                groups[0][1]["mech"] = "mech (CSE codegen)"
            if have_pylinkage:

                def prepare_pylinkage(order=order):
                    linkage, ip = pylinkage_build(n)  # a fresh, compiled linkage: not timed
                    return lambda: _pylinkage_step(linkage, ip, order, n)

                groups[0][0]["pylinkage"] = prepare_pylinkage
                groups[0][1]["pylinkage"] = "pylinkage 1.3 (numba)"
            if naive is not None:
                for which, method, label in ((0, "naive-codegen", "codegen, cse=False"), (1, "naive-lambdify", "sympy.lambdify, cse=False")):
                    run = naive_runner(naive, which, order)
                    run(theta[:16])
                    groups[1][0][method] = lambda run=run: (lambda: run(theta))
                    groups[1][1][method] = label
            for preparers, labels in groups:
                for method, (times, out) in interleaved(preparers, repeats).items():
                    record(method, labels[method], order, n, times, out, idx, ref)
            for xtol in SCIPY_XTOL:
                run = scipy_runner(order, xtol)
                label = f"scipy root, xtol={xtol:.0e}"
                reps = min(3, repeats_small)
                if n > scipy_slice:
                    # Time a contiguous slice of the grid (same angle spacing), then scale.
                    sl = slice(0, scipy_slice)
                    times, out = timed(lambda: run(theta[sl]), reps)
                    sub = np.arange(0, scipy_slice, max(1, scipy_slice // samples))
                    sub_ref = coupler_reference(theta[sub], **GEOMETRY, branch=BRANCH, coupler=COUPLER)
                    note = f"timed on the first {scipy_slice} angles of the grid and scaled by {n // scipy_slice}; error on that slice"
                    record("scipy-root", label, order, n, times, out, sub, sub_ref, scaled_from=scipy_slice, note=note)
                else:
                    times, out = timed(lambda: run(theta), reps)
                    record("scipy-root", label, order, n, times, out, idx, ref)
    if have_pylinkage:
        for n in sizes:
            diag = pylinkage_drift(n)
            notes.append(
                f"pylinkage N={n}: its crank angle drifts up to {diag['max_input_angle_drift_rad']:.1e} rad from "
                f"2 pi k/N; measured at its own crank angle its position error is {diag['err_position_at_own_crank_angle']:.1e}"
            )
            log(notes[-1])
    return results, notes


def _find(results, method, order, n):
    for r in results:
        if r["method"] == method and r["order"] == order and r["n"] == n:
            return r
    return None


def ratios(results, sizes):
    out = []

    def add(name, num, den, goal, kind, description):
        if num is None or den is None:
            out.append({"name": name, "value": None, "value_of_minima": None, "goal": goal, "kind": kind, "pass": None, "description": description})
            return
        value = num["time_s"] / den["time_s"]
        ok = value >= goal if kind == "min" else value <= goal
        value_min = num["time_min_s"] / den["time_min_s"]
        out.append({"name": name, "value": value, "value_of_minima": value_min, "goal": goal, "kind": kind, "pass": bool(ok), "description": description})

    big = max(sizes)
    for n, key in ((10_000, "mech_vs_pylinkage_1e4"), (1_000_000, "mech_vs_pylinkage_1e6")):
        if n not in sizes:
            continue
        for order in (0, 2):
            add(
                f"{key}_order{order}",
                _find(results, "pylinkage", order, n),
                _find(results, "mech", order, n),
                GOALS[key],
                "min",
                f"pylinkage time / mech time, N={n}, order {order}",
            )
    for order in (0, 2):
        add(
            f"mech_vs_naive_order{order}",
            _find(results, "naive-codegen", order, big),
            _find(results, "mech", order, big),
            GOALS["mech_vs_naive"],
            "min",
            f"naive (cse=False codegen) time / mech time, N={big}, order {order}",
        )
        add(
            f"mech_vs_lambdify_order{order}",
            _find(results, "naive-lambdify", order, big),
            _find(results, "mech", order, big),
            GOALS["mech_vs_naive"],
            "min",
            f"plain sympy.lambdify (cse=False) time / mech time, N={big}, order {order}",
        )
    for n in sizes:
        add(
            f"order2_vs_order0_{n:.0e}".replace("+0", ""),
            _find(results, "mech", 2, n),
            _find(results, "mech", 0, n),
            GOALS["order2_vs_order0"],
            "max",
            f"mech order=2 time / order=0 time, N={n}",
        )
    return out


def table(results):
    head = f"{'method':<28} {'order':>5} {'N':>8} {'time [ms]':>11} {'err P':>9} {'err vP':>9} {'err aP':>9}"
    lines = [head, "-" * len(head)]
    fmt = lambda x: "n/a" if x is None else f"{x:9.1e}"  # noqa: E731
    for r in sorted(results, key=lambda r: (r["n"], r["order"], r["time_s"])):
        t = f"{r['time_s'] * 1e3:10.2f}{'*' if r['scaled'] else ' '}"
        lines.append(
            f"{r['label']:<28} {r['order']:>5} {r['n']:>8} {t:>11} {fmt(r['err_position']):>9}"
            f" {fmt(r['err_velocity']):>9} {fmt(r['err_acceleration']):>9}"
        )
    lines.append("* timed on a slice of the grid and scaled to N; errors relative to a+b+c+d")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="small sizes, few repeats; writes only to --output")
    parser.add_argument("--output", type=Path, default=None, help=f"default {OUTPUT.relative_to(ROOT)}")
    args = parser.parse_args(argv)
    if args.quick:
        sizes, samples, rs, rl, sl = (2_000, 20_000), 200, 3, 2, 2_000
    else:
        sizes, samples, rs, rl, sl = SIZES, SAMPLES, 15, 7, SCIPY_SLICE
    started = _dt.datetime.now(_dt.timezone.utc)
    info = {"machine": machine(), "versions": versions()}
    results, notes = run_benchmark(sizes, samples, rs, rl, sl)
    rat = ratios(results, sizes)
    print()
    print(table(results))
    print()
    for r in rat:
        verdict = "n/a " if r["pass"] is None else ("PASS" if r["pass"] else "FAIL")
        sign = ">=" if r["kind"] == "min" else "<="
        value = "n/a" if r["value"] is None else f"{r['value']:.2f}"
        vmin = "n/a" if r["value_of_minima"] is None else f"{r['value_of_minima']:.2f}"
        print(f"{verdict}  {r['name']:<28} {value:>8}  (goal {sign} {r['goal']:g}; ratio of fastest runs {vmin}): {r['description']}")
    for note in notes:
        print("note:", note)
    doc = {
        "benchmark": "coupler_curve",
        "date": started.isoformat(timespec="seconds"),
        "duration_s": round((_dt.datetime.now(_dt.timezone.utc) - started).total_seconds(), 1),
        **info,
        "linkage": {**GEOMETRY, "branch": BRANCH, "coupler": list(COUPLER), "kind": "crank-rocker"},
        "inputs": {"omega": 1.0, "alpha": 0.0, "angles": "2 pi k / N, k = 0 .. N-1"},
        "reference": {"library": "mpmath", "dps": DPS, "samples_per_size": samples, "route": "circle intersection + differentiated constraint equations (benchmarks/reference.py)"},
        "error_scale": {"position": "a+b+c+d", "velocity": "omega*(a+b+c+d)", "acceleration": "omega^2*(a+b+c+d)", "value": sum(GEOMETRY.values())},
        "sizes": list(sizes),
        "repeats": {"n<=1e4": rs, "n>1e4": rl},
        "timing": "time.perf_counter, median of the repeats; mech and pylinkage timed round-robin (interleaved) in each repeat, then the two naive variants likewise; one untimed full-size warm-up call per method; only the computation is timed (set-up, compilation and linkage construction are not)",
        "results": results,
        "ratios": rat,
        "goals": GOALS,
        "notes": notes,
    }
    output = args.output or (None if args.quick else OUTPUT)
    if output is not None:
        output.parent.mkdir(parents=True, exist_ok=True)
        output.write_text(json.dumps(doc, indent=1) + "\n")
        print(f"wrote {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
