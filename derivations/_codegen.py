"""The project's code generator: SymPy expressions in, NumPy, numba and JavaScript out.

One generator, three backends (``derivations/_backends.py``) that share each function's
common-subexpression elimination and differ only in their printer and template:

- NumPy, ``mech/_generated/<stem>.py``: every function, broadcasting like a ufunc, and for
  functions that declare per-point (``vector``) arguments a kernel writing into buffers the
  caller owns (``derivations/_kernels.py``);
- numba, ``mech/_generated/<stem>_numba.py``: fused loops of the ``vector`` functions;
- JavaScript, ``book/_static/kernels/<stem>.js``: an ES module of scalar functions for
  the book's pages.

Square roots of sums of squares are printed as ``hypot`` in every backend
(``derivations/_printers.py``), so no intermediate square overflows.

- ``render(...)`` returns the NumPy module's text;
- ``write(...)`` rewrites each backend's file only when its hash changed and its text
  differs, then checks the modules numerically against mpmath (the JavaScript one under
  Node when ``node`` is on the PATH);
- ``check_fresh(...)`` checks the committed files without writing them.

A derivation notebook ends with one ``write`` call. With the environment variable
``MECH_CODEGEN=check`` (set by ``python -m derivations --check`` and by the freshness
test), ``write`` only checks. SymPy's CSE output is not deterministic across machines, so
freshness is the hash of the ``srepr`` of the inputs plus numeric agreement, never the text.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import re
from dataclasses import dataclass, field

import mpmath
import numpy as np
import sympy as sm

from derivations import _backends, _kernels, _node

__all__ = ["Function", "render", "write", "check_fresh", "input_hash", "GENERATED_DIR", "JS_DIR"]

#: Bump when the template or the printer changes, so every module is regenerated
#: (2: square roots of sums of squares printed as hypot).
GENERATOR_VERSION = "2"
KERNEL_VERSION = _kernels.KERNEL_VERSION
GENERATED_DIR = _backends.GENERATED_DIR
JS_DIR = _backends.JS_DIR


@dataclass(frozen=True)
class Function:
    """One generated function: named arguments in, named expressions out.

    Parameters
    ----------
    name : str
        Python name of the function, after the quantity it computes (``fourbar_psi``).
    summary : str
        One-line docstring summary.
    args : sequence of (Symbol, str)
        Arguments in call order, each with a short description (shape, unit).
    outputs : sequence of (str, Expr, str)
        Returned quantities: name, expression and description. One output is returned
        bare, several as a tuple in this order.
    domain : dict Symbol -> (low, high)
        Where the numeric check samples each argument (uniformly).
    vector : sequence of Symbol, optional
        The per-point arguments (one value per input angle). When given, the generator also
        emits two kernels of the same common-subexpression-eliminated expressions: a NumPy
        kernel ``<name>_into(..., out, work)`` that writes every output and temporary into
        buffers the caller owns (no allocation per call), and a numba fused loop
        ``<name>_kernel`` in ``mech/_generated/<stem>_numba.py``. The other arguments are
        scalars there, and subexpressions of scalars alone are computed once per call.
        The numba module also has ``<name>_fused_kernel``, the same loop with a scale per
        output, returning whether every output is finite.
    mask : str, optional
        With kernels: the output that is NaN exactly where a point does not exist (the
        linkage cannot be assembled). ``<name>_fused_kernel`` then also writes the mask
        ``valid`` (True where that output is not NaN) in its one pass.
    finite : sequence of str, optional
        With kernels: the outputs whose sum ``<name>_fused_kernel`` checks for its returned
        flag (default every output). Name fewer only where the derivation shows that, for
        finite scalar arguments, these are finite at a point only if every output is (a
        NaN or an infinity in any output reaches one of them): fewer additions per point.
    equations : str, optional
        The textbook equations this function implements (``"(2-11), (2-12)"``), cited in
        its docstring; default the equations of the whole module (``write``'s argument).
    """

    name: str
    summary: str
    args: tuple
    outputs: tuple
    domain: dict = field(default_factory=dict)
    vector: tuple = ()
    mask: str = None
    finite: tuple = None
    equations: str = None

    def symbols(self):
        return [s for s, _ in self.args]

    def exprs(self):
        return [sm.sympify(e) for _, e, _ in self.outputs]


def _canonical_text(functions, equations, extra=""):
    parts = [f"generator={GENERATOR_VERSION}", f"equations={equations}"] + ([extra] if extra else [])
    for f in functions:
        parts.append(f"def {f.name}(" + ",".join(sm.srepr(s) for s in f.symbols()) + ")")
        if f.equations:
            parts.append(f"equations {f.name}={f.equations}")
        if f.vector:
            # only modules with kernels carry the kernel template's version in their hash
            parts.append(f"kernels={KERNEL_VERSION} vector(" + ",".join(s.name for s in f.vector) + ")"
                         + (f" mask={f.mask}" if f.mask else "")
                         + (f" finite={','.join(f.finite)}" if f.finite else ""))
        for out_name, expr, _ in f.outputs:
            parts.append(f"{out_name}={sm.srepr(sm.sympify(expr))}")
    return "\n".join(parts)


def input_hash(functions, equations="", extra=""):
    """SHA-256 of the ``srepr`` of every argument and output expression (and ``extra``,
    a backend's template version)."""
    return "sha256:" + hashlib.sha256(_canonical_text(functions, equations, extra).encode()).hexdigest()


def _validate(f):
    names = [s.name for s in f.symbols()]
    if len(set(names)) != len(names):
        raise ValueError(f"Expected distinct argument names for `{f.name}`, got {names}")
    allowed = set(f.symbols())
    for out_name, expr, _ in f.outputs:
        extra = sm.sympify(expr).free_symbols - allowed
        if extra:
            bad = ", ".join(sorted(s.name for s in extra))
            raise ValueError(
                f"Expected only the arguments of `{f.name}` in output `{out_name}`, "
                f"got free symbol(s) {bad}"
            )


def render(stem, notebook, equations, functions, *, cse=True):
    """Return the text of ``mech/_generated/<stem>.py`` for ``functions``."""
    for f in functions:
        _validate(f)
    rendering = _backends.Rendering(functions, cse=cse)
    return _backends.NumPyBackend().render(stem, notebook, equations, rendering, input_hash(functions, equations))


def backend_hash(backend, functions, equations=""):
    """The hash a backend's file carries: of the functions it emits and its template."""
    emitted = backend.emitted(functions)
    extra = f"{type(backend).__name__}={backend.version}" if backend.version else ""
    return input_hash(emitted, equations, extra) if emitted else None


def backend_path(backend, stem):
    """Where a backend's file of ``stem`` is (`GENERATED_DIR` or `JS_DIR`, read at call time)."""
    return (JS_DIR if backend.folder == "js" else GENERATED_DIR) / f"{stem}{backend.suffix}"


def _load(path, module_name):
    spec = importlib.util.spec_from_file_location(module_name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _kernel_outputs(call, f, values, samples):
    """Outputs of a kernel called once per sample (its scalar arguments are scalars); the
    real and imaginary parts of a complex output are put back together."""
    slots = _kernels.real_parts(f)[1]
    outs = [np.empty(samples) for _ in slots]
    vector = set(f.vector)
    for i in range(samples):
        args = [values[s][i:i + 1] if s in vector else float(values[s][i]) for s in f.symbols()]
        call(args, [o[i:i + 1] for o in outs])
    joined = [np.zeros(samples, dtype=complex if _kernels.has_complex(f) else float) for _ in f.outputs]
    for (k, part), o in zip(slots, outs):
        if part == "imag":
            joined[k] = joined[k] + 1j * o
        else:
            joined[k] = joined[k] + o
    return joined


def _js_outputs(path, functions, values, samples):
    """Each function of the JavaScript module at ``path`` on the sampled points, its
    outputs put back together as the NumPy function returns them (complex from two parts)."""
    calls = [(path, f.name, [np.broadcast_to(values[f.name][s], (samples,)) for s in f.symbols()],
              len(_kernels.real_parts(f)[1])) for f in functions]
    results = {}
    for f, got in zip(functions, _node.evaluate(calls)):
        joined = [np.zeros(samples, dtype=complex if _kernels.has_complex(f) else float) for _ in f.outputs]
        for (k, part), o in zip(_kernels.real_parts(f)[1], got):
            joined[k] = joined[k] + (1j * o if part == "imag" else o)
        results[f.name] = joined
    return results


def _numeric_check(module, functions, samples, rtol, numba_module=None, js_path=None):
    """Compare every generated function (and its kernels) with mpmath at 50 digits."""
    rng = np.random.default_rng(20261121)
    values = {}
    for f in functions:
        values[f.name] = {}
        for s in f.symbols():
            low, high = f.domain.get(s, (-2.0, 2.0))
            values[f.name][s] = rng.uniform(low, high, samples)
    js = _js_outputs(js_path, functions, values, samples) if js_path is not None else {}
    for f in functions:
        syms = f.symbols()
        points = values[f.name]
        got = getattr(module, f.name)(*(points[s] for s in syms))
        candidates = {f.name: [got] if len(f.outputs) == 1 else list(got)}
        if f.name in js:
            candidates[f"{js_path.name}:{f.name}"] = js[f.name]
        if f.vector:
            into, rows = getattr(module, f"{f.name}_into"), module.WORK_ROWS[f.name]
            with np.errstate(all="ignore"):
                candidates[f"{f.name}_into"] = _kernel_outputs(
                    lambda args, outs: into(*args, outs, np.empty((rows, 1))), f, points, samples)
            if numba_module is not None:
                kernel = getattr(numba_module, f"{f.name}_kernel")
                candidates[f"{f.name}_kernel"] = _kernel_outputs(
                    lambda args, outs: kernel(*args, *outs), f, points, samples)
                fused = getattr(numba_module, f"{f.name}_fused_kernel")
                ones = (1.0,) * len(_kernels.real_parts(f)[1])
                valid = (np.empty(1, dtype=bool),) if f.mask else ()
                candidates[f"{f.name}_fused_kernel"] = _kernel_outputs(
                    lambda args, outs: fused(*args, ones, *outs, *valid), f, points, samples)
        reference = sm.lambdify(syms, f.exprs(), modules="mpmath")
        with mpmath.workdps(50):
            for i in range(samples):
                ref = reference(*(mpmath.mpf(float(points[s][i])) for s in syms))
                for label, outputs in candidates.items():
                    for (out_name, _, _), g, r in zip(f.outputs, outputs, ref):
                        g_i = complex(np.broadcast_to(g, (samples,))[i])
                        r_i = complex(r)
                        if not np.isfinite(r_i) and not np.isfinite(g_i):
                            continue
                        if abs(g_i - r_i) > rtol * max(1.0, abs(r_i)):
                            point = {s.name: float(points[s][i]) for s in syms}
                            raise AssertionError(
                                f"{label}.{out_name} disagrees with mpmath at {point}: "
                                f"{g_i!r} vs {r_i!r}"
                            )


def _hash_of(path):
    text = path.read_text() if path.exists() else ""
    committed = re.search(r'^(?:export const )?INPUT_HASH = "([^"]+)"', text, re.M)
    return committed.group(1) if committed else None


def check_fresh(stem, notebook, equations, functions, *, samples=25, rtol=1e-11):
    """Raise ``AssertionError`` unless every backend's committed file matches these inputs.

    With kernels (a function declares ``vector`` arguments), the numba module must match
    too; its kernels are checked numerically when numba is importable, and the
    JavaScript module when Node is installed.
    """
    path = GENERATED_DIR / f"{stem}.py"
    if not path.exists():
        raise AssertionError(f"{path} is missing: run `python -m derivations`")
    numba_module, js_path = None, None
    for backend in _backends.BACKENDS:
        expected = backend_hash(backend, functions, equations)
        if expected is None:
            continue
        target = backend_path(backend, stem)
        if _hash_of(target) != expected:
            state = "missing" if not target.exists() else "stale (hash differs)"
            if isinstance(backend, _backends.NumbaBackend):
                state = "missing or stale"
            raise AssertionError(f"{target.name} is {state}: run `python -m derivations`")
        if isinstance(backend, _backends.NumbaBackend) and importlib.util.find_spec("numba") is not None:
            # under its package name: numba's cache records the module of `_sign`, which a
            # later solve must be able to import
            numba_module = _load(target, f"mech._generated.{stem}_numba")
        if isinstance(backend, _backends.JSBackend) and _node.node() is not None:
            js_path = target
    _numeric_check(_load(path, f"_fresh_{stem}"), functions, samples, rtol, numba_module, js_path)
    return path


def write(stem, notebook, equations, functions, *, samples=25, rtol=1e-11):
    """Write each backend's file (``mech/_generated/<stem>.py``, ``<stem>_numba.py`` for
    kernels, ``book/_static/kernels/<stem>.js``) whose hash changed, then check them.

    A file is written only when its text differs from what is there, so an unchanged
    kernel keeps its file. Returns the path of the NumPy module. With
    ``MECH_CODEGEN=check`` in the environment, nothing is written.
    """
    for f in functions:
        _validate(f)
    if os.environ.get("MECH_CODEGEN") != "check":
        rendering = None
        for backend in _backends.BACKENDS:
            expected = backend_hash(backend, functions, equations)
            target = backend_path(backend, stem)
            if expected is None or _hash_of(target) == expected:
                continue
            rendering = rendering or _backends.Rendering(functions)
            text = backend.render(stem, notebook, equations, rendering, expected)
            if not target.exists() or target.read_text() != text:
                target.parent.mkdir(parents=True, exist_ok=True)
                target.write_text(text)
    path = check_fresh(stem, notebook, equations, functions, samples=samples, rtol=rtol)
    if os.environ.get("MECH_CODEGEN") == "check":
        # the book build runs every notebook in check mode; the slow freshness test then
        # reads this record instead of running the same notebooks a second time
        from derivations import _manifest

        _manifest.note_checked(notebook)
    return path
