"""Which backend evaluates the generated kernels, and the reused working memory.

The code generator emits each solver's expressions twice (``derivations/_kernels.py``): as
NumPy kernels ``<name>_into`` that write into buffers the caller owns, and as numba fused
loops ``<name>_kernel`` in ``mech/_generated/<stem>_numba.py``. The NumPy kernels are always
there; the numba ones are used when numba is importable (``pip install mech[fast]``).

The backend is ``"auto"`` unless the environment variable ``MECH_BACKEND`` or
`set_backend` says otherwise: ``"auto"`` uses numba for a solve of at least
`NUMBA_MIN_SIZE` points when numba is importable (below that, importing numba and loading
its kernels would cost more than the solve), NumPy otherwise. ``"numpy"`` and ``"numba"``
force one. numba is imported only when a solve first uses it, never by ``import mech``.
"""

import importlib
import importlib.util
import os
import threading

__all__ = ["set_backend", "get_backend"]

BACKENDS = ("auto", "numpy", "numba")
#: The smallest solve that ``"auto"`` hands to numba.
NUMBA_MIN_SIZE = 4096
#: Points per block of the NumPy kernels: their temporaries (a few tens of rows of this
#: length, a few megabytes) stay in cache and are reused from block to block and call to
#: call. Each ufunc call costs about a microsecond whatever its length, and a kernel makes
#: fifty or more of them per block: blocks of 4096 points lost a quarter of the time to
#: these calls, blocks of 16384 points were faster at every size measured (10^4 to 10^6).
BLOCK = 16384
#: Points per block of the numba kernels: large enough that the per-call cost vanishes,
#: small enough that the solver's passes after the kernel (scaling, the finiteness check)
#: find the block's outputs still in cache, and that the per-block work row stays small.
NUMBA_BLOCK = 16384

_state = {"backend": None, "numba": None}
_local = threading.local()


def _check(name, value):
    if not isinstance(value, str) or value not in BACKENDS:
        raise ValueError(f"Expected `{name}` one of {', '.join(map(repr, BACKENDS))}, got {value!r}")
    return value


def get_backend():
    """The backend in force: ``"auto"``, ``"numpy"`` or ``"numba"``.

    Set by `set_backend`, else by the environment variable ``MECH_BACKEND``, else
    ``"auto"``.

    Examples
    --------
    >>> import mech
    >>> mech.get_backend() in ("auto", "numpy", "numba")
    True
    """
    if _state["backend"] is None:
        _state["backend"] = _check("MECH_BACKEND", os.environ.get("MECH_BACKEND", "auto"))
    return _state["backend"]


def set_backend(name):
    """Choose how the generated kernels are evaluated; return the previous choice.

    Parameters
    ----------
    name : {"auto", "numpy", "numba"}
        ``"numpy"``: NumPy kernels on cache-sized blocks (always available).
        ``"numba"``: numba fused loops of the same expressions (needs numba:
        ``pip install mech[fast]``). ``"auto"``: numba for solves of at least
        ``NUMBA_MIN_SIZE`` points when numba is importable, else NumPy.

    Returns
    -------
    str
        The backend in force before the call.

    Raises
    ------
    ValueError
        If `name` is not one of the three.

    Examples
    --------
    >>> import mech
    >>> previous = mech.set_backend("numpy")
    >>> mech.get_backend()
    'numpy'
    >>> _ = mech.set_backend(previous)
    """
    name = _check("name", name)
    previous = get_backend()
    _state["backend"] = name
    return previous


def numba_available():
    if _state["numba"] is None:
        _state["numba"] = importlib.util.find_spec("numba") is not None
    return _state["numba"]


def use_numba(size, minimum=None):
    """True if a solve of `size` points should run the numba kernels.

    ``minimum`` replaces `NUMBA_MIN_SIZE` for ``"auto"`` (a solver whose NumPy path costs
    far more per point than a fused kernel's pays back numba's loading sooner).
    """
    backend = get_backend()
    if backend == "numpy":
        return False
    if backend == "numba":
        if not numba_available():
            raise ImportError("The numba backend needs numba: `pip install mech[fast]`, "
                              "or mech.set_backend('numpy')")
        return True
    return size >= (NUMBA_MIN_SIZE if minimum is None else minimum) and numba_available()


def numba_kernels(stem):
    """The generated numba module ``mech._generated.<stem>_numba`` (imported on first use)."""
    module = _kernel_modules.get(stem)
    if module is None:
        module = _kernel_modules[stem] = importlib.import_module(f"mech._generated.{stem}_numba")
    return module


_kernel_modules = {}


def workspace(key, rows, n):
    """A float array of shape ``(rows, n)`` reused by every call with this `key` on this thread.

    Its contents are garbage; a caller must not keep it beyond the call that asked for it,
    and one key belongs to one solver (a solver that calls another uses another key).
    """
    buffers = getattr(_local, "buffers", None)
    if buffers is None:
        buffers = _local.buffers = {}
    buf = buffers.get(key)
    if buf is None or buf.size < rows * n:
        # NumPy is imported here, not at the top: `mech.index` imports `mech` and must stay free of it.
        import numpy as np

        buf = buffers[key] = np.empty(max(rows * n, 16 * BLOCK))
    return buf[: rows * n].reshape(rows, n)
