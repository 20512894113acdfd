"""Where does ``FourBar.solve`` spend its time? A line-by-line profile of the generated code.

Each generated function used by ``mech.planar.kinematics._fourbar`` is executed statement by statement
(the assignments of its body, then each returned expression) on the benchmark's linkage, and
each statement is timed; the wrapper's own work (input checks, packing complex arrays, the
validity mask) is timed beside it. A second table times the same solve in blocks, to show
how much of the large-N cost is memory traffic rather than arithmetic.

    python benchmarks/profile_mech.py [N]          # default N = 1_000_000
"""

from __future__ import annotations

import ast
import inspect
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_coupler_curve import BRANCH, COUPLER, GEOMETRY, grid  # noqa: E402


def _best(fn, repeats=5):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def profile_function(func, args, repeats=5):
    """Time every top-level statement of ``func``'s body; return [(seconds, source)], outputs."""
    source = inspect.getsource(func)
    tree = ast.parse(source)
    fdef = tree.body[0]
    names = [a.arg for a in fdef.args.args]
    env = dict(func.__globals__)
    env.update(zip(names, args))
    rows = []
    outputs = None
    for stmt in fdef.body:
        if isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant):
            continue  # docstring
        if isinstance(stmt, ast.Return):
            elts = stmt.value.elts if isinstance(stmt.value, ast.Tuple) else [stmt.value]
            outputs = []
            for k, e in enumerate(elts):
                code = compile(ast.Expression(e), "<ret>", "eval")
                rows.append((_best(lambda: eval(code, env), repeats), f"return[{k}] = {ast.unparse(e)}"))
                outputs.append(eval(code, env))
            continue
        code = compile(ast.Module([stmt], []), "<stmt>", "exec")
        rows.append((_best(lambda: exec(code, env), repeats), ast.unparse(stmt)))
    return rows, outputs


def main(n=1_000_000):
    import mech.planar.kinematics._fourbar as fb
    from mech._validate import finite_array
    from mech.planar import FourBar

    gen = fb._gen
    linkage = FourBar(**GEOMETRY, branch=BRANCH, coupler=COUPLER)
    theta = grid(n)
    a, b, c, d = (GEOMETRY[k] for k in "abcd")
    p, q = COUPLER
    report = []
    with np.errstate(invalid="ignore", divide="ignore"):
        rows, out = profile_function(
            gen.fourbar_position, (a, b, c, d, p, q, theta, BRANCH, *linkage._gaps, linkage._m23, linkage._m4)
        )
        report.append(("fourbar_position", rows))
        Bx, By, Cx, Cy, Px, Py, S = out
        rows, out = profile_function(gen.fourbar_velocity, (b, d, p, q, Bx, By, Cx, Cy, S, BRANCH, 1.0))
        report.append(("fourbar_velocity", rows))
        w2, w3 = out[0], out[1]
        rows, out = profile_function(
            gen.fourbar_acceleration, (b, d, p, q, Bx, By, Cx, Cy, S, BRANCH, 1.0, 0.0, w2, w3)
        )
        report.append(("fourbar_acceleration", rows))
    wrapper = [
        (_best(lambda: finite_array("theta", theta)), "finite_array('theta', theta)"),
        (_best(lambda: ~np.isnan(S)), "valid = ~np.isnan(S)"),
        (_best(lambda: fb._complex(Bx, By)), "_complex(Bx, By)  (x3 at order 0, x9 at order 2)"),
    ]
    report.append(("FourBar.solve wrapper", wrapper))

    print(f"N = {n:,}; best of 5 per statement\n")
    for name, rows in report:
        total = sum(t for t, _ in rows)
        print(f"{name}: {len(rows)} statements, {total * 1e3:.1f} ms in all")
        for t, src in sorted(rows, reverse=True)[:12]:
            print(f"  {t * 1e3:7.2f} ms  {100 * t / total:4.0f}%  {src[:100]}")
        print()
    print("whole solve, one call vs. in blocks (same results):")
    for order in (0, 2):
        whole = _best(lambda: linkage.solve(theta, order=order), 3)
        line = f"  order={order}: one call {whole * 1e3:7.1f} ms"
        for block in (4096, 16384, 65536):
            chunks = [theta[i : i + block] for i in range(0, n, block)]
            t = _best(lambda: [linkage.solve(ch, order=order) for ch in chunks], 3)
            line += f" | blocks of {block}: {t * 1e3:6.1f} ms"
        print(line)


if __name__ == "__main__":
    main(int(float(sys.argv[1])) if len(sys.argv) > 1 else 1_000_000)
