"""Optimisation design (textbook section 4.5): the model and three ways to solve it.

`DesignModel` is the mathematical model of the text (F26-F40): design variables in a box,
an objective f(x), inequality constraints g(x) <= 0 and equality constraints h(x) = 0.
Three solvers work on it side by side:

- `grid_search`, the text's grid method (网格法) with refinement around the best point;
- `penalty_method` (module ``_optimisation_penalty``), the text's interior penalty
  (惩罚函数法, F50) with a decreasing penalty factor, each stage minimised by a Nelder-Mead
  simplex written there;
- `scipy_minimize`, SciPy's SLSQP or trust-constr (SciPy is imported only when called).

The two searches of this module can save their state to a checkpoint file (``.npz``) and
resume from it with the same result as an uninterrupted run; they show a progress bar (tqdm,
written by `mech._progress`) on request.
"""

import os
from dataclasses import dataclass, field

import numpy as np

from mech._progress import progress_bar
from mech._validate import bool_flag, finite_array, nonnegative_int, real_number

__all__ = ["DesignModel", "OptimisationResult", "grid_search", "scipy_minimize"]


def _call(func, name, x):
    """func(x) as a float array; a user function's own error is reported under its name."""
    try:
        with np.errstate(all="ignore"):
            value = func(x)
    except Exception as err:                       # a user function: report, do not mask as ours
        raise ValueError(f"Expected `{name}` to evaluate at x of shape {np.shape(x)}, "
                         f"got {type(err).__name__}: {err}") from err
    arr = np.asarray(value)
    if np.iscomplexobj(arr) or arr.dtype.kind not in "fiub":
        raise ValueError(f"Expected `{name}` to return real numbers, got {arr.dtype} values: {value!r}")
    return arr.astype(float)


@dataclass(frozen=True)
class DesignModel:
    """The mathematical model of an optimisation design: minimise f(x) subject to g(x) <= 0, h(x) = 0.

    The standard form of the textbook (F26-F40, section 4.5): n design variables x, searched
    in the box ``lower <= x <= upper``, an objective f, m inequality constraints g_i(x) <= 0
    and p equality constraints h_j(x) = 0. A maximisation is written as the minimisation of -f.

    Parameters
    ----------
    objective : callable
        ``f(X)`` for X of shape ``(..., n)``, returning shape ``(...)``. It must broadcast
        over the leading axes (the grid search evaluates a whole grid at once). A value that
        is not finite marks a design that cannot be evaluated (it cannot be assembled).
    bounds : array_like, shape (n, 2)
        Finite ``(low, high)`` per variable, ``low < high``: the search box.
    inequality : callable, optional
        ``g(X)`` of shape ``(..., m)``; feasible where every component is <= 0.
    equality : callable, optional
        ``h(X)`` of shape ``(..., p)``; feasible where every component is 0.
    names : sequence of str, optional
        Names of the variables, for printing (default ``x0, x1, ...``).

    Raises
    ------
    ValueError
        If a function is not callable or the bounds are not finite pairs with low < high.

    Notes
    -----
    The box is part of the model: the grid method lays its grid in it, the penalty method
    adds ``lower - x <= 0`` and ``x - upper <= 0`` to the inequality constraints, and SciPy
    receives it as bounds. Page ``book-synthesis-optimisation``.

    Examples
    --------
    The illustrative problem of the text (§2.4 V, Fig. 2-110) without its equality:

    >>> from mech.planar.synthesis import DesignModel
    >>> model = DesignModel(lambda x: ((x - 2.0) ** 2).sum(-1), [(0, 3), (0, 3)],
    ...                     inequality=lambda x: (x**2).sum(-1, keepdims=True) - 4.0)
    >>> float(model.f([1.0, 1.0])), model.g([1.0, 1.0]).tolist()
    (2.0, [-2.0])
    """

    objective: object
    bounds: np.ndarray
    inequality: object = None
    equality: object = None
    names: tuple = field(default=None)

    def __post_init__(self):
        for name in ("objective", "inequality", "equality"):
            value = getattr(self, name)
            if not callable(value) and not (value is None and name != "objective"):
                raise ValueError(f"Expected `{name}` to be callable, got {value!r}")
        box = finite_array("bounds", self.bounds)
        if box.ndim != 2 or box.shape[1] != 2 or box.shape[0] < 1:
            raise ValueError(f"Expected `bounds` of shape (n, 2), got shape {box.shape}: {self.bounds!r}")
        if not np.all(box[:, 0] < box[:, 1]):
            raise ValueError(f"Expected `bounds` with low < high in every row, got {box.tolist()}")
        box.setflags(write=False)
        object.__setattr__(self, "bounds", box)
        names = tuple(f"x{i}" for i in range(box.shape[0])) if self.names is None else tuple(self.names)
        if len(names) != box.shape[0] or not all(isinstance(s, str) for s in names):
            raise ValueError(f"Expected `names` as {box.shape[0]} strings, got {self.names!r}")
        object.__setattr__(self, "names", names)

    @property
    def n(self):
        """Number of design variables."""
        return self.bounds.shape[0]

    @property
    def lower(self):
        return self.bounds[:, 0]

    @property
    def upper(self):
        return self.bounds[:, 1]

    def _x(self, x, name="x"):
        arr = finite_array(name, x)
        if arr.ndim < 1 or arr.shape[-1] != self.n:
            raise ValueError(f"Expected `{name}` with last axis of length {self.n}, got shape {arr.shape}")
        return arr

    def f(self, x):
        """Objective at x of shape ``(..., n)``: shape ``(...)``."""
        x = self._x(x)
        out = _call(self.objective, "objective", x)
        if out.shape != x.shape[:-1]:
            raise ValueError(f"Expected `objective` of shape {x.shape[:-1]} for x of shape {x.shape}, "
                             f"got shape {out.shape}")
        return out

    def _constraint(self, func, name, x):
        x = self._x(x)
        if func is None:
            return np.zeros(x.shape[:-1] + (0,))
        out = _call(func, name, x)
        if out.shape[:-1] != x.shape[:-1] or out.ndim != x.ndim:
            raise ValueError(f"Expected `{name}` of shape {x.shape[:-1]} + (m,) for x of shape {x.shape}, "
                             f"got shape {out.shape}")
        return out

    def g(self, x):
        """Inequality constraints at x: shape ``(..., m)``, feasible where <= 0."""
        return self._constraint(self.inequality, "inequality", x)

    def h(self, x):
        """Equality constraints at x: shape ``(..., p)``, feasible where 0."""
        return self._constraint(self.equality, "equality", x)

    def feasible(self, x, *, tol=0.0):
        """True where x is in the box, g <= tol and ``|h|`` <= tol (and f is finite)."""
        x = self._x(x)
        tol = real_number("tol", tol)
        inside = np.all((x >= self.lower) & (x <= self.upper), axis=-1)
        with np.errstate(invalid="ignore"):
            ok = np.all(self.g(x) <= tol, axis=-1) & np.all(np.abs(self.h(x)) <= tol, axis=-1)
        return inside & ok & np.isfinite(self.f(x))


@dataclass(frozen=True)
class OptimisationResult:
    """An optimum and the record of the search that found it.

    Attributes
    ----------
    x : ndarray, shape (n,)
        The best design found. ``fun`` is f(x); ``g`` and ``h`` are the constraint values
        there (g <= 0 and h = 0 when feasible).
    evaluations : int
        Objective evaluations spent (a whole grid counts each of its points).
    history : ndarray, shape (k, 2)
        Rows ``(evaluations so far, objective at the current iterate)``: the convergence curve.
    method, message : str
    names : tuple of str
    """

    x: np.ndarray
    fun: float
    g: np.ndarray
    h: np.ndarray
    evaluations: int
    history: np.ndarray
    method: str
    message: str
    names: tuple

    def as_dict(self):
        """The optimum as ``{name: value}``."""
        return dict(zip(self.names, (float(v) for v in self.x)))


def _result(model, x, evaluations, history, method, message):
    x = np.array(x, dtype=float)
    return OptimisationResult(x, float(model.f(x)), model.g(x), model.h(x), int(evaluations),
                              np.array(history, dtype=float).reshape(-1, 2), method, message, model.names)


def _bar(progress, total, initial, desc):
    """A bar of the search's steps (`mech._progress.progress_bar`)."""
    return progress_bar(progress, total, initial, desc)


def _load(checkpoint, kind, fingerprint):
    """The saved state of `checkpoint` if the file exists and belongs to this search."""
    if checkpoint is None or not os.path.exists(checkpoint):
        return None
    with np.load(checkpoint) as data:
        state = {k: data[k] for k in data.files}
    if str(state.get("kind")) != kind or not np.array_equal(state.get("fingerprint"), fingerprint):
        raise ValueError(f"Expected `checkpoint` saved by the same {kind} on the same model and "
                         f"settings, got {checkpoint!r}")
    return state


def _save(checkpoint, kind, fingerprint, **state):
    """Write the state atomically: an interrupted write leaves the previous checkpoint intact."""
    tmp = f"{checkpoint}.tmp.npz"
    np.savez(tmp, kind=kind, fingerprint=fingerprint, **state)
    os.replace(tmp, checkpoint)


def _checkpoint_path(checkpoint):
    if checkpoint is None:
        return None
    if not isinstance(checkpoint, (str, os.PathLike)):
        raise ValueError(f"Expected `checkpoint` as a file path or None, got {checkpoint!r}")
    return os.fspath(checkpoint)


def grid_search(model, *, points=11, levels=40, shrink=0.5, max_points=1_000_000, progress=False,
                checkpoint=None, every=1):
    """Minimise a design model by the grid method with refinement (textbook section 4.5, Fig. 2-111).

    Level 0 lays a grid of ``points`` values per variable over the box and keeps the best
    feasible grid point. Each next level lays a new grid of the same size over a box
    ``shrink`` times as wide, centred on the best point so far and moved inside the bounds.

    Parameters
    ----------
    model : DesignModel
        Without equality constraints (a grid does not meet h(x) = 0).
    points : int, odd, >= 3
        Grid values per variable and level; a level costs ``points ** n`` evaluations.
    levels : int, >= 1
        Number of grids laid.
    shrink : float in (0, 1)
        Width of each box over the previous one. A small value converges fast but can lose
        a narrow curved valley; 0.5 follows one (Example 2-23's is one).
    max_points : int
        Largest allowed ``points ** n``.
    progress : bool
        Show a progress bar over the levels (`mech._progress`: standard error in a terminal,
        standard output in a Jupyter kernel).
    checkpoint : str or path, optional
        File (``.npz``) for the search state, written after every ``every`` levels. If it
        exists, the search resumes from it; the result is the same as without interruption.
    every : int, >= 1

    Returns
    -------
    OptimisationResult
        ``history`` has one row per level.

    Raises
    ------
    ValueError
        For an equality-constrained model, a grid larger than ``max_points``, no feasible
        point on the first grid, or a checkpoint of another search.

    Notes
    -----
    The grid method needs no derivatives and finds the best grid point of the whole box,
    but its cost grows as ``points ** n``: it suits two or three variables (Example 2-23),
    not nine. Refinement can miss an optimum narrower than a grid step of level 0. After
    k levels the grid step is ``shrink**k`` times that of level 0. A point
    is feasible when it lies in the box, every g_i <= 0 and f is finite.

    Examples
    --------
    >>> from mech.planar.synthesis import DesignModel, grid_search
    >>> model = DesignModel(lambda x: ((x - 0.3) ** 2).sum(-1), [(0, 1), (0, 1)])
    >>> grid_search(model, levels=60).x.round(12).tolist()
    [0.3, 0.3]
    """
    if not isinstance(model, DesignModel):
        raise ValueError(f"Expected `model` as a DesignModel, got {model!r}")
    if model.equality is not None:
        raise ValueError("Expected `model` without equality constraints for the grid method, "
                         f"got equality={model.equality!r}")
    points = nonnegative_int("points", points, 10**6)
    if points < 3 or points % 2 == 0:
        raise ValueError(f"Expected `points` odd and >= 3, got {points}")
    levels = nonnegative_int("levels", levels, 10**6)
    every = nonnegative_int("every", every, 10**9)
    for name, value in (("levels", levels), ("every", every)):
        if value < 1:
            raise ValueError(f"Expected `{name}` >= 1, got {value}")
    shrink = real_number("shrink", shrink)
    if not 0.0 < shrink < 1.0:
        raise ValueError(f"Expected `shrink` in (0, 1), got {shrink}")
    max_points = nonnegative_int("max_points", max_points, 10**12)
    if points**model.n > max_points:
        raise ValueError(f"Expected `points` ** n <= max_points = {max_points}, got {points} ** {model.n}")
    progress = bool_flag("progress", progress)
    checkpoint = _checkpoint_path(checkpoint)
    fingerprint = np.concatenate([model.bounds.ravel(), [points, model.n, shrink]])

    state = _load(checkpoint, "grid_search", fingerprint)
    if state is None:
        level, lo, hi = 0, model.lower.copy(), model.upper.copy()
        best_x, best_f, evaluations, history = np.full(model.n, np.nan), np.inf, 0, np.zeros((0, 2))
    else:
        level, lo, hi = int(state["level"]), state["lo"], state["hi"]
        best_x, best_f = state["best_x"], float(state["best_f"])
        evaluations, history = int(state["evaluations"]), state["history"]

    unit = np.linspace(0.0, 1.0, points)
    with _bar(progress, levels, min(level, levels), "grid") as bar:
        while level < levels:
            axes = [lo[i] + (hi[i] - lo[i]) * unit for i in range(model.n)]
            X = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, model.n)
            F = model.f(X)
            with np.errstate(invalid="ignore"):
                ok = np.isfinite(F) & np.all(model.g(X) <= 0.0, axis=-1)
            evaluations += X.shape[0]
            if np.any(ok):
                k = int(np.argmin(np.where(ok, F, np.inf)))
                # keep the earlier best on ties, so the sequence of iterates never gets worse
                if F[k] < best_f:
                    best_x, best_f = X[k].copy(), float(F[k])
            elif level == 0:
                raise ValueError(f"Expected a feasible point on the first grid of {X.shape[0]} points, "
                                 f"got none; widen `bounds` or add `points`")
            history = np.vstack([history, [evaluations, best_f]])
            # the next box: `shrink` times as wide, centred on the best point, moved into the bounds
            half = np.minimum(0.5 * shrink * (hi - lo), 0.5 * (model.upper - model.lower))
            centre = np.clip(best_x, model.lower + half, model.upper - half)
            lo, hi = centre - half, centre + half
            level += 1
            bar.update(1)
            if checkpoint is not None and (level % every == 0 or level == levels):
                _save(checkpoint, "grid_search", fingerprint, level=level, lo=lo, hi=hi, best_x=best_x,
                      best_f=best_f, evaluations=evaluations, history=history)
    return _result(model, best_x, evaluations, history, "grid",
                   f"{levels} levels of {points}^{model.n} points")


def scipy_minimize(model, x0, *, method="SLSQP", options=None):
    """Minimise a design model with `scipy.optimize.minimize` (SLSQP or trust-constr).

    Parameters
    ----------
    model : DesignModel
        Its objective and constraints must be smooth and finite near the path of the solver.
    x0 : array_like, shape (n,)
        Start.
    method : {"SLSQP", "trust-constr"}
    options : dict, optional
        Passed to SciPy.

    Returns
    -------
    OptimisationResult
        ``history`` has one row per solver iteration (objective at the iterate).

    Raises
    ------
    ValueError
        For an unknown method or a bad start.

    Notes
    -----
    SciPy is imported here, not with `mech`. SciPy works on the box mapped to [0, 1]^n and
    on f / ``|f(x0)|``, so its absolute tolerances (SLSQP's ``ftol``) act as relative ones. The gradient is estimated by finite
    differences, so an objective with kinks (a sum of distances) or with designs that cannot
    be assembled (f not finite) can stop SLSQP early: check ``message`` and the constraint
    values ``g``, ``h`` of the result.

    Examples
    --------
    The text's example (§2.4 V, Fig. 2-110) with all constraints: optimum C = (0.8, 1.1).

    >>> import numpy as np
    >>> from mech.planar.synthesis import DesignModel, scipy_minimize
    >>> def h(x):
    ...     x1, x2 = x[..., 0], x[..., 1]
    ...     return (73*x1**2 + 52*x2**2 + 72*x1*x2 - 356*x1 - 292*x2 + 433)[..., None]
    >>> model = DesignModel(lambda x: ((x - 2.0) ** 2).sum(-1), [(0, 3), (0, 3)],
    ...                     inequality=lambda x: (x**2).sum(-1, keepdims=True) - 4.0, equality=h)
    >>> scipy_minimize(model, [1.0, 1.0], options={"maxiter": 1000}).x.round(4).tolist()
    [0.8, 1.1]
    """
    from scipy.optimize import Bounds, NonlinearConstraint, minimize

    if not isinstance(model, DesignModel):
        raise ValueError(f"Expected `model` as a DesignModel, got {model!r}")
    if method not in ("SLSQP", "trust-constr"):
        raise ValueError(f"Expected `method` 'SLSQP' or 'trust-constr', got {method!r}")
    x0 = model._x(x0, "x0")
    if x0.shape != (model.n,):
        raise ValueError(f"Expected `x0` of shape ({model.n},), got shape {x0.shape}")
    if options is not None and not isinstance(options, dict):
        raise ValueError(f"Expected `options` as a dict or None, got {options!r}")
    count = [0]
    history = []
    lower, width = model.lower, model.upper - model.lower
    f0 = float(model.f(x0))
    scale = abs(f0) if np.isfinite(f0) and f0 != 0.0 else 1.0

    def x_of(u):
        return lower + width * u

    def fun(u):
        count[0] += 1
        return float(model.f(x_of(u))) / scale

    def record(uk, *_):
        history.append([count[0], float(model.f(x_of(uk)))])

    m = model.g(x0).shape[-1]
    p = model.h(x0).shape[-1]
    g, h = (lambda u: model.g(x_of(u))), (lambda u: model.h(x_of(u)))
    if method == "SLSQP":
        cons = ([{"type": "ineq", "fun": lambda u: -g(u)}] if m else []) + ([{"type": "eq", "fun": h}] if p else [])
    else:
        cons = ([NonlinearConstraint(g, -np.inf, 0.0)] if m else []) + ([NonlinearConstraint(h, 0.0, 0.0)] if p else [])
    res = minimize(fun, (x0 - lower) / width, method=method, bounds=Bounds(np.zeros(model.n), np.ones(model.n)),
                   constraints=cons, options=options or {}, callback=record)
    return _result(model, x_of(res.x), count[0], history, method, str(res.message))
