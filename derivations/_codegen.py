"""The project's code generator: SymPy expressions in, a plain NumPy module out.

Three steps; NumPy source with common subexpressions eliminated, and for functions that
declare per-point (``vector``) arguments two more backends of the same expressions
(``derivations/_kernels.py``): a NumPy kernel writing into caller-owned buffers and a numba
fused loop in ``mech/_generated/<stem>_numba.py``:

- ``render(...)`` returns the module text;
- ``write(...)`` rewrites ``mech/_generated/<stem>.py`` only when the input hash changed,
  then checks the module numerically against mpmath;
- ``check_fresh(...)`` checks the committed module without writing it.

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
from pathlib import Path

import mpmath
import numpy as np
import sympy as sm
from sympy.printing.numpy import NumPyPrinter

from derivations import _kernels

__all__ = ["Function", "render", "write", "check_fresh", "input_hash", "GENERATED_DIR"]

#: Bump when the template changes, so every module is regenerated.
GENERATOR_VERSION = "1"
#: Bump when the kernel templates change (only modules that declare `vector` arguments).
KERNEL_VERSION = "6"
GENERATED_DIR = Path(__file__).resolve().parent.parent / "mech" / "_generated"


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
    """

    name: str
    summary: str
    args: tuple
    outputs: tuple
    domain: dict = field(default_factory=dict)
    vector: tuple = ()
    mask: str = None
    finite: tuple = None

    def symbols(self):
        return [s for s, _ in self.args]

    def exprs(self):
        return [sm.sympify(e) for _, e, _ in self.outputs]


def _canonical_text(functions, equations):
    parts = [f"generator={GENERATOR_VERSION}", f"equations={equations}"]
    for f in functions:
        parts.append(f"def {f.name}(" + ",".join(sm.srepr(s) for s in f.symbols()) + ")")
        if f.vector:
            # only modules with kernels carry the kernel template's version in their hash
            parts.append(f"kernels={KERNEL_VERSION} vector(" + ",".join(s.name for s in f.vector) + ")"
                         + (f" mask={f.mask}" if f.mask else "")
                         + (f" finite={','.join(f.finite)}" if f.finite else ""))
        for out_name, expr, _ in f.outputs:
            parts.append(f"{out_name}={sm.srepr(sm.sympify(expr))}")
    return "\n".join(parts)


def input_hash(functions, equations=""):
    """SHA-256 of the ``srepr`` of every argument and output expression."""
    return "sha256:" + hashlib.sha256(_canonical_text(functions, equations).encode()).hexdigest()


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


def _print(expr):
    return NumPyPrinter({"fully_qualified_modules": True}).doprint(expr).replace("numpy.", "np.")


def _render_body(f, cse=True, common=None):
    exprs = f.exprs()
    lines = []
    if common is not None:
        replacements, reduced = common
    elif cse:
        symbols = sm.numbered_symbols("x")
        replacements, reduced = sm.cse(exprs, symbols=symbols, order="none")
    else:
        replacements, reduced = [], exprs
    for sym, sub in replacements:
        lines.append(f"    {sym} = {_print(sub)}")
    outs = [_print(e) for e in reduced]
    if len(outs) == 1:
        lines.append(f"    return {outs[0]}")
    else:
        lines.append("    return (")
        lines.extend(f"        {o}," for o in outs)
        lines.append("    )")
    return lines


def _render_doc(f, notebook, equations):
    lines = [f'    """{f.summary}', "", f"    Generated from ``{notebook}``, equations {equations}.", ""]
    lines += ["    Parameters", "    ----------"]
    for sym, desc in f.args:
        lines += [f"    {sym.name} : array_like", f"        {desc}"]
    lines += ["", "    Returns", "    -------"]
    for out_name, _, desc in f.outputs:
        lines += [f"    {out_name} : ndarray", f"        {desc}"]
    lines += ["", "    Arguments broadcast against each other like a NumPy ufunc.", '    """']
    return lines


def render(stem, notebook, equations, functions, *, cse=True):
    """Return the text of ``mech/_generated/<stem>.py`` for ``functions``."""
    return _render_all(stem, notebook, equations, functions, cse=cse)[0]


def _render_all(stem, notebook, equations, functions, *, cse=True):
    """The NumPy module's text, and the numba module's text (None without kernels)."""
    for f in functions:
        _validate(f)
    # kernels always work on the CSE'd expressions; the plain functions only with cse=True
    # a complex output is two real outputs of the kernels, so their CSE is its own
    plain = {f.name: _kernels.cse_of(f) for f in functions
             if cse or (f.vector and not _kernels.has_complex(f))}
    commons = {f.name: (plain[f.name] if cse else None) for f in functions}
    kernels = [f for f in functions if f.vector]
    kernel_cse = {f.name: (_kernels.cse_of(f, split=True) if _kernels.has_complex(f) else plain[f.name])
                  for f in kernels}
    names = [f.name for f in functions] + [f"{f.name}_into" for f in kernels]
    out = [
        f"# GENERATED by {notebook} — do not edit",
        f"# Equations: {equations}",
        f"# SymPy {sm.__version__}; regenerate with `python -m derivations`",
        f'"""Generated NumPy functions for {notebook} ({equations})."""',
        "",
        "import numpy as np",
        "",
        f'INPUT_HASH = "{input_hash(functions, equations)}"',
        "",
        "__all__ = [" + ", ".join(repr(n) for n in names) + "]",
    ]
    rows = {}
    for f in functions:
        args = ", ".join(s.name for s in f.symbols())
        out += ["", "", f"def {f.name}({args}):"]
        out += _render_doc(f, notebook, equations)
        out += _render_body(f, cse=cse, common=commons[f.name])
        if f.vector:
            lines, rows[f.name] = _kernels.numpy_kernel(f, *kernel_cse[f.name])
            out += ["", ""] + lines
    if kernels:
        out += ["", "", "#: Rows of the ``work`` array each ``*_into`` kernel needs.",
                "WORK_ROWS = {" + ", ".join(f"{k!r}: {v}" for k, v in rows.items()) + "}"]
    numpy_text = "\n".join(out) + "\n"
    if not kernels:
        return numpy_text, None
    nb = [
        f"# GENERATED by {notebook} — do not edit",
        f"# Equations: {equations}",
        f"# SymPy {sm.__version__}; regenerate with `python -m derivations`",
        f'"""Generated numba kernels (fused loops) for {notebook} ({equations}).',
        "",
        f"The same expressions as ``mech._generated.{stem}``; imported only by the numba backend.",
        '"""',
        "",
        "import math",
        "",
        "import numba",
        "",
        f'INPUT_HASH = "{input_hash(functions, equations)}"',
        "",
        "__all__ = [" + ", ".join(repr(f"{f.name}{kind}") for f in kernels for kind in ("_kernel", "_fused_kernel")) + "]",
        "",
        "",
        "@numba.njit(cache=True, nogil=True)",
        "def _sign(x):",
        "    if x > 0.0:",
        "        return 1.0",
        "    if x < 0.0:",
        "        return -1.0",
        "    return x  # 0.0, -0.0 or NaN, as numpy.sign",
    ]
    for f in kernels:
        nb += ["", ""] + _kernels.numba_kernel(f, *kernel_cse[f.name])
    return numpy_text, "\n".join(nb) + "\n"


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


def _numeric_check(module, functions, samples, rtol, numba_module=None):
    """Compare every generated function (and its kernels) with mpmath at 50 digits."""
    rng = np.random.default_rng(20261121)
    for f in functions:
        syms = f.symbols()
        values = {}
        for s in syms:
            low, high = f.domain.get(s, (-2.0, 2.0))
            values[s] = rng.uniform(low, high, samples)
        got = getattr(module, f.name)(*(values[s] for s in syms))
        candidates = {f.name: [got] if len(f.outputs) == 1 else list(got)}
        if f.vector:
            into, rows = getattr(module, f"{f.name}_into"), module.WORK_ROWS[f.name]
            with np.errstate(all="ignore"):
                candidates[f"{f.name}_into"] = _kernel_outputs(
                    lambda args, outs: into(*args, outs, np.empty((rows, 1))), f, values, samples)
            if numba_module is not None:
                kernel = getattr(numba_module, f"{f.name}_kernel")
                candidates[f"{f.name}_kernel"] = _kernel_outputs(
                    lambda args, outs: kernel(*args, *outs), f, values, samples)
                fused = getattr(numba_module, f"{f.name}_fused_kernel")
                ones = (1.0,) * len(_kernels.real_parts(f)[1])
                valid = (np.empty(1, dtype=bool),) if f.mask else ()
                candidates[f"{f.name}_fused_kernel"] = _kernel_outputs(
                    lambda args, outs: fused(*args, ones, *outs, *valid), f, values, samples)
        reference = sm.lambdify(syms, f.exprs(), modules="mpmath")
        with mpmath.workdps(50):
            for i in range(samples):
                ref = reference(*(mpmath.mpf(float(values[s][i])) for s in syms))
                for label, outputs in candidates.items():
                    for (out_name, _, _), g, r in zip(f.outputs, outputs, ref):
                        g_i = complex(np.broadcast_to(g, (samples,))[i])
                        r_i = complex(r)
                        if not np.isfinite(r_i) and not np.isfinite(g_i):
                            continue
                        if abs(g_i - r_i) > rtol * max(1.0, abs(r_i)):
                            point = {s.name: float(values[s][i]) for s in syms}
                            raise AssertionError(
                                f"{label}.{out_name} disagrees with mpmath at {point}: "
                                f"{g_i!r} vs {r_i!r}"
                            )


def _hash_of(path):
    committed = re.search(r'^INPUT_HASH = "([^"]+)"', path.read_text(), re.M) if path.exists() else None
    return committed.group(1) if committed else None


def check_fresh(stem, notebook, equations, functions, *, samples=25, rtol=1e-11):
    """Raise ``AssertionError`` unless the committed module matches these inputs.

    With kernels (a function declares ``vector`` arguments), the numba module must match
    too; its kernels are checked numerically when numba is importable.
    """
    path = GENERATED_DIR / f"{stem}.py"
    if not path.exists():
        raise AssertionError(f"{path} is missing: run `python -m derivations`")
    expected = input_hash(functions, equations)
    if _hash_of(path) != expected:
        raise AssertionError(f"{path.name} is stale (hash differs): run `python -m derivations`")
    numba_module = None
    if any(f.vector for f in functions):
        numba_path = GENERATED_DIR / f"{stem}_numba.py"
        if _hash_of(numba_path) != expected:
            raise AssertionError(f"{numba_path.name} is missing or stale: run `python -m derivations`")
        if importlib.util.find_spec("numba") is not None:
            # under its package name: numba's cache records the module of `_sign`, which a
            # later solve must be able to import
            numba_module = _load(numba_path, f"mech._generated.{stem}_numba")
    _numeric_check(_load(path, f"_fresh_{stem}"), functions, samples, rtol, numba_module)
    return path


def write(stem, notebook, equations, functions, *, samples=25, rtol=1e-11):
    """Write ``mech/_generated/<stem>.py`` (and ``<stem>_numba.py`` for kernels) if its
    inputs changed, then check it.

    Returns the path. With ``MECH_CODEGEN=check`` in the environment, nothing is written.
    """
    path = GENERATED_DIR / f"{stem}.py"
    if os.environ.get("MECH_CODEGEN") != "check":
        expected = input_hash(functions, equations)
        numba_path = GENERATED_DIR / f"{stem}_numba.py"
        kernels = any(f.vector for f in functions)
        if _hash_of(path) != expected or (kernels and _hash_of(numba_path) != expected):
            numpy_text, numba_text = _render_all(stem, notebook, equations, functions)
            path.write_text(numpy_text)
            if numba_text is not None:
                numba_path.write_text(numba_text)
    return check_fresh(stem, notebook, equations, functions, samples=samples, rtol=rtol)
