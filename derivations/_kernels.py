"""Kernels of the code generator: the same CSE'd expressions, written for two more backends.

For a `Function` that declares its per-point (``vector``) arguments, ``_codegen`` emits

- a NumPy kernel ``<name>_into(args..., out, work)``: every operation is one ufunc call
  writing into ``out`` (the caller's output arrays, which may be strided views such as the
  real part of a complex array) or into a row of ``work`` (a float array of shape
  ``(WORK_ROWS[name], n)`` that the caller keeps and reuses). Rows are reused as soon as a
  temporary is dead, so a block of a few thousand points stays in cache and a solve makes
  no allocation per block. Subexpressions of the scalar arguments alone are computed once.
- a numba kernel ``<name>_kernel(args..., out...)``: one fused loop over the points, the
  same expressions written with ``math`` on scalars, in ``mech/_generated/<stem>_numba.py``;
- beside it ``<name>_fused_kernel(args..., scales, out..., [valid])``, the solvers' variant of
  that loop: each output times a power of two (the solver's scaling of lengths, undone in
  the same pass), the mask ``valid`` where the function declares a ``mask`` output, and a
  returned flag that every output is finite (from the sum of the outputs the function
  declares in ``finite``, by default all), so no second pass over the outputs is needed.

Both come from one call of ``sympy.cse``, so the two backends evaluate the same
expression tree and agree to a few units in the last place.
"""

from __future__ import annotations

import sympy as sm

from derivations._printers import MathPrinter, hypot, numpy_operand, overflow_safe

#: Bump when the kernel templates change (only modules that declare `vector` arguments).
KERNEL_VERSION = "6"

__all__ = ["numpy_kernel", "numba_kernel", "cse_of", "real_parts", "has_complex"]

_UFUNCS = {
    sm.sin: "sin", sm.cos: "cos", sm.tan: "tan", sm.asin: "arcsin", sm.acos: "arccos",
    sm.atan: "arctan", sm.exp: "exp", sm.log: "log", sm.Abs: "absolute", sm.sign: "sign",
    sm.sinh: "sinh", sm.cosh: "cosh", sm.tanh: "tanh", sm.atan2: "arctan2", sm.floor: "floor",
    hypot: "hypot",
}


def real_parts(f):
    """The kernels' outputs: each real output as it is, a complex one as its real and
    imaginary parts (the caller passes ``z.real, z.imag`` of its complex array).

    Returns ``(exprs, slots)``, ``slots[j] = (k, part)``: output ``k`` of `f`, part
    ``None`` (real), ``"real"`` or ``"imag"``.
    """
    exprs, slots = [], []
    for k, expr in enumerate(f.exprs()):
        if expr.has(sm.I):
            exprs += list(_split(expr))
            slots += [(k, "real"), (k, "imag")]
        else:
            exprs.append(expr)
            slots.append((k, None))
    return exprs, slots


def _split(expr):
    """``(re, im)`` of `expr`, taking every subexpression free of ``I`` as real.

    That is the generated code's convention: a square root of a negative number is NaN
    (the pose does not exist), not imaginary, so ``sqrt(u)`` stays ``sqrt(u)`` in the real
    part rather than becoming ``|u|**(1/2) cos(arg(u)/2)`` as SymPy's ``as_real_imag``
    would write it for a symbol of unknown sign.
    """
    if not expr.has(sm.I):
        return expr, sm.S.Zero
    if expr == sm.I:
        return sm.S.Zero, sm.S.One
    if expr.is_Add:
        parts = [_split(t) for t in expr.args]
        return sm.Add(*[r for r, _ in parts]), sm.Add(*[i for _, i in parts])
    if expr.is_Mul:
        re, im = sm.S.One, sm.S.Zero
        for factor in expr.args:
            r, i = _split(factor)
            re, im = re * r - im * i, re * i + im * r
        return re, im
    if expr.func is sm.exp:
        r, i = _split(expr.args[0])
        scale = sm.exp(r) if r != 0 else sm.S.One
        return scale * sm.cos(i), scale * sm.sin(i)
    if expr.is_Pow and expr.exp.is_Integer and expr.exp > 0:
        return _split(sm.Mul(*([expr.base] * int(expr.exp)), evaluate=False))
    raise NotImplementedError(f"no real and imaginary parts for {expr.func.__name__}: {expr}")


def has_complex(f):
    return any(e.has(sm.I) for e in f.exprs())


def cse_of(f, split=False):
    """``(replacements, reduced)`` of one function's outputs, as the NumPy module uses them;
    with ``split=True`` of the kernels' real outputs (`real_parts`)."""
    exprs = [overflow_safe(e) for e in (real_parts(f)[0] if split else f.exprs())]
    return sm.cse(exprs, symbols=sm.numbered_symbols("x"), order="none")


_scalar = numpy_operand


class _Emitter:
    """Turns vector expressions into ufunc calls with ``out=``, reusing work rows."""

    def __init__(self):
        self.lines = []
        self.free = []
        self.rows = 0
        self.where = {}  # vector Symbol -> the name of the array holding it

    # -- rows ------------------------------------------------------------------------
    def row(self):
        if self.free:
            return self.free.pop()
        self.rows += 1
        return f"w{self.rows - 1}"

    def release(self, owned):
        if owned is not None and owned not in self.free:
            self.free.append(owned)

    def is_vec(self, expr):
        return any(s in self.where for s in expr.free_symbols)

    # -- emission --------------------------------------------------------------------
    def call(self, ufunc, operands, dst):
        """``np.<ufunc>(*operands, out=target)``; operands are ``(text, owned_row_or_None)``."""
        owned = [o for _, o in operands if o is not None]
        if dst is not None:
            target = dst
        elif owned:
            target = owned[0]
        else:
            target = self.row()
        args = ", ".join(text for text, _ in operands)
        self.lines.append(f"np.{ufunc}({args}, out={target})")
        for o in owned:
            if o != target:
                self.release(o)
        return target, (None if dst is not None else target)

    def value(self, expr, dst=None):
        """Emit code for a vector ``expr``; return ``(text, owned)`` of where it is."""
        if expr in self.where:
            if dst is None:
                return self.where[expr], None
            self.lines.append(f"np.copyto({dst}, {self.where[expr]})")
            return dst, None
        if not self.is_vec(expr):
            raise ValueError("scalar expression given to the vector emitter")
        if expr.is_Add:
            return self._add(expr, dst)
        if expr.is_Mul:
            return self._mul(expr, dst)
        if expr.is_Pow:
            return self._pow(expr, dst)
        if expr.func in _UFUNCS:
            operands = [self.operand(arg) for arg in expr.args]
            return self.call(_UFUNCS[expr.func], operands, dst)
        if expr.func in (sm.Min, sm.Max):
            name = "minimum" if expr.func is sm.Min else "maximum"
            return self._chain([(name, arg) for arg in expr.args[1:]], self.operand(expr.args[0]), dst)
        raise NotImplementedError(f"no vector kernel for {expr.func.__name__}: {expr}")

    def operand(self, expr):
        if self.is_vec(expr):
            return self.value(expr)
        return _scalar(expr), None

    def _chain(self, steps, acc, dst):
        """``acc`` (text, owned), then each ``(ufunc, expr)`` in turn; the last writes into dst."""
        if not steps:
            return acc if dst is None else self.call("positive", [acc], dst)
        for k, (ufunc, expr) in enumerate(steps):
            last = k == len(steps) - 1
            acc = self.call(ufunc, [acc, self.operand(expr)], dst if last else None)
        return acc

    def _add(self, expr, dst):
        vec = [t for t in expr.args if self.is_vec(t)]
        rest = sm.Add(*[t for t in expr.args if not self.is_vec(t)])
        positive = [t for t in vec if not t.could_extract_minus_sign()]
        negative = [-t for t in vec if t.could_extract_minus_sign()]
        if positive:
            acc = self.value(positive[0])
            steps = [("add", t) for t in positive[1:]]
        elif rest != 0:
            # rest - t: one subtraction, not a negation and an addition
            last = not negative[1:]
            acc = self.call("subtract", [(_scalar(rest), None), self.value(negative[0])], dst if last else None)
            if last:
                return acc
            negative, steps, rest = negative[1:], [], sm.S.Zero
        else:
            acc = self.call("negative", [self.value(negative[0])], None)
            negative, steps = negative[1:], []
        steps += [("subtract", t) for t in negative]
        if rest != 0:
            steps.append(("add", rest))
        return self._chain(steps, acc, dst)

    def _mul(self, expr, dst):
        num, den, scal = [], [], []
        for f in expr.args:
            if not self.is_vec(f):
                scal.append(f)
            elif f.is_Pow and f.exp.is_Number and f.exp < 0:
                den.append(f.base if f.exp == -1 else sm.Pow(f.base, -f.exp))
            else:
                num.append(f)
        s = sm.Mul(*scal)
        steps = []
        if den:
            d = den[0] if len(den) == 1 else sm.Mul(*den)
        if not num:
            # scalar / vector
            dval = self.value(d)
            return self.call("divide", [(_scalar(s), None), dval], dst)
        steps = [("multiply", f) for f in num[1:]]
        if s == -1 and not den and not steps:
            return self.call("negative", [self.value(num[0])], dst)
        if s != 1:
            steps.append(("multiply", s))
        if den:
            steps.append(("divide", d))
        return self._chain(steps, self.value(num[0]), dst)

    def _pow(self, expr, dst):
        base, exp = expr.args
        if not self.is_vec(base):
            return self.call("power", [(_scalar(base), None), self.value(exp)], dst)
        if exp == 2:
            return self.call("square", [self.value(base)], dst)
        if exp == sm.S.Half:
            return self.call("sqrt", [self.value(base)], dst)
        if exp.is_Number and exp < 0:
            inner = self.value(base if exp == -1 else sm.Pow(base, -exp))
            return self.call("divide", [("1.0", None), inner], dst)
        if exp.is_Number:
            return self.call("power", [self.value(base), (repr(float(exp)), None)], dst)
        return self.call("power", [self.value(base), self.operand(exp)], dst)


def _uses(symbol, exprs):
    return any(symbol in e.free_symbols for e in exprs)


def numpy_kernel(f, replacements, reduced):
    """Lines of ``def <name>_into(...)`` and the number of work rows it needs."""
    em = _Emitter()
    vector = set(f.vector)
    for s in f.vector:
        em.where[s] = s.name
    scalar_lines = []
    # the last step (replacement index, or len(replacements) for the outputs) reading each symbol
    steps = [sub for _, sub in replacements] + [sm.Tuple(*reduced)]
    last_use = {}
    for k, e in enumerate(steps):
        for sym in e.free_symbols:
            last_use[sym] = k
    holders = {}  # work row -> CSE symbols held there
    # an output that is a CSE symbol is computed straight into its output array (no copy)
    direct = {}
    for k, expr in enumerate(reduced):
        if expr.is_Symbol and expr not in vector:
            direct.setdefault(expr, k)
    for k, (sym, sub) in enumerate(replacements):
        if not em.is_vec(sub):
            scalar_lines.append(f"{sym} = {_scalar(sub)}")
            continue
        if sym in direct and not sub.is_Symbol:
            em.where[sym] = em.value(sub, f"out[{direct[sym]}]")[0]
            continue
        text, owned = em.value(sub)
        em.where[sym] = owned if owned is not None else text
        if em.where[sym].startswith("w"):
            holders.setdefault(em.where[sym], set()).add(sym)
        # free the rows whose every symbol is read for the last time by step k (or never)
        for row, syms in list(holders.items()):
            if all(last_use.get(x, -1) <= k for x in syms):
                del holders[row]
                em.release(row)
    for k, expr in enumerate(reduced):
        dst = f"out[{k}]"
        if em.where.get(expr) == dst:
            continue
        if em.is_vec(expr):
            em.value(expr, dst)
        else:
            em.lines.append(f"{dst}[...] = {_scalar(expr)}")
    args = ", ".join(s.name for s in f.symbols())
    rows = max(em.rows, 1)
    body = [f"def {f.name}_into({args}, out, work):"]
    body += [
        f'    """`{f.name}` written into ``out`` (one array per output, in order), using the',
        f"    rows of ``work`` (shape ({rows}, n)) for temporaries; per-point arguments: "
        + ", ".join(f"``{s.name}``" for s in f.vector) + ' (length n)."""',
    ]
    body += [f"    {ln}" for ln in scalar_lines]
    names = ", ".join(f"w{i}" for i in range(rows))
    body.append(f"    {names}{',' if rows == 1 else ''} = work[:{rows}]")
    body += [f"    {ln}" for ln in em.lines]
    return body, rows


def _tree_sum(terms):
    """``terms`` added pairwise, ``((y0 + y1) + (y2 + y3)) + ...``: a short chain of additions."""
    while len(terms) > 1:
        terms = [f"({terms[k]} + {terms[k + 1]})" if k + 1 < len(terms) else terms[k]
                 for k in range(0, len(terms), 2)]
    return terms[0]


def numba_kernel(f, replacements, reduced):
    """Lines of the numba fused loop ``<name>_kernel(args..., out0, out1, ...)``."""
    printer = MathPrinter({"fully_qualified_modules": True, "standard": "python3"})
    vector = list(f.vector)
    per_point = {s: sm.Symbol(f"{s.name}_i", **s.assumptions0) for s in vector}
    vec_syms = set(vector)
    hoisted, loop = [], []
    for sym, sub in replacements:
        if sub.free_symbols & vec_syms:
            loop.append(f"{sym} = {printer.doprint(sub.xreplace(per_point))}")
            vec_syms.add(sym)
        else:
            hoisted.append(f"{sym} = {printer.doprint(sub)}")
    outs = [f"out{k}" for k in range(len(reduced))]
    args = ", ".join([s.name for s in f.symbols()] + outs)
    body = ["@numba.njit(cache=True, nogil=True, error_model='numpy')", f"def {f.name}_kernel({args}):"]
    body.append(f'    """`{f.name}` as one loop over the points, written into out0, out1, ..."""')
    body += [f"    {ln}" for ln in hoisted]
    body.append(f"    for i in range({outs[0]}.shape[0]):")
    body += [f"        {s.name}_i = {s.name}[i]" for s in vector]
    body += [f"        {ln}" for ln in loop]
    for name, expr in zip(outs, reduced):
        body.append(f"        {name}[i] = {printer.doprint(expr.xreplace(per_point))}")
    # the solvers' variant: the same loop, each output times its power-of-two scale (exact,
    # so the same bits as scaling afterwards), the validity mask and a finiteness check in
    # the same pass
    slots = real_parts(f)[1]
    names = [name for name, _, _ in f.outputs]
    mark = None
    if f.mask is not None:
        mark = next(j for j, (k, part) in enumerate(slots) if names[k] == f.mask and part != "imag")
    args = ", ".join([s.name for s in f.symbols()] + ["scales"] + outs + (["valid"] if f.mask else []))
    body += ["", "", "@numba.njit(cache=True, nogil=True, error_model='numpy')",
             f"def {f.name}_fused_kernel({args}):"]
    doc = [f'    """`{f.name}_kernel`, each output k times ``scales[k]``.', ""]
    if f.mask:
        doc += [f"    ``valid[i]`` is True where output ``{f.mask}`` at point i is not NaN (the point exists)."]
    checked = list(range(len(outs)))
    if f.finite:
        unknown = set(f.finite) - set(names)
        if unknown:
            raise ValueError(f"{f.name}: finite names outputs it does not have: {sorted(unknown)}")
        checked = [j for j, (k, _) in enumerate(slots) if names[k] in f.finite]
    if len(checked) == len(outs):
        doc += ["    Returns True if the sum of every output at every point is finite (so each is);",
                '    False if one is NaN or infinite, or the sum overflows."""']
    else:
        doc += ["    Returns True if the sum of " + ", ".join(f"out{j}" for j in checked) + " at every point is finite",
                "    (so each is, and by the derivation every output is, for finite scalar arguments);",
                '    False if one is NaN or infinite, or the sum overflows."""']
    body += doc
    body += [f"    {ln}" for ln in hoisted]
    body += [f"    scale{k} = scales[{k}]" for k in range(len(outs))]
    body.append("    acc = 0.0")
    body.append(f"    for i in range({outs[0]}.shape[0]):")
    body += [f"        {s.name}_i = {s.name}[i]" for s in vector]
    body += [f"        {ln}" for ln in loop]
    for k, expr in enumerate(reduced):
        body.append(f"        y{k} = ({printer.doprint(expr.xreplace(per_point))})*scale{k}")
    for k, name in enumerate(outs):
        body.append(f"        {name}[i] = y{k}")
    if mark is not None:
        body.append(f"        valid[i] = y{mark} == y{mark}")
    # the sum is finite only if every output it adds is (a NaN or an infinity stays in it);
    # a finite sum that overflows answers False, and the caller checks more closely
    body.append("        acc += " + _tree_sum([f"y{k}" for k in checked]))
    body.append("    return math.isfinite(acc)")
    return body
