"""The interior penalty method of the textbook (F50), with a Nelder-Mead simplex per stage.

Part of the optimisation design of ``_optimisation`` (the model, the result, checkpoints and
the progress bar live there).
"""

import numpy as np

from mech._validate import bool_flag, nonnegative_int, real_number
from mech.planar.synthesis._optimisation import DesignModel, _bar, _checkpoint_path, _load, _result, _save

__all__ = ["penalty_method"]


def _barrier(model, X, r):
    """Interior penalty phi = f - r sum 1/g_i (F50) plus sum h_j^2 / r; inf outside the region."""
    F = model.f(X)
    G = np.concatenate([model.g(X), model.lower - X, X - model.upper], axis=-1)
    H = model.h(X)
    with np.errstate(all="ignore"):
        inside = np.all(G < 0.0, axis=-1) & np.isfinite(F)
        phi = F - r * np.sum(1.0 / G, axis=-1) + np.sum(H * H, axis=-1) / r
    return np.where(inside & np.isfinite(phi), phi, np.inf), F


def _nelder_mead_step(model, r, S, Phi, Fv):
    """One Nelder-Mead iteration on a sorted simplex, in place; returns the evaluations spent.

    The expansion, contraction and shrink coefficients adapt to the dimension n (Gao and Han,
    2012: 1 + 2/n, 3/4 - 1/(2n), 1 - 1/n); for n = 2 they are the classic 2, 1/2, 1/2, and
    for larger n they keep the simplex from collapsing early.
    """
    n = S.shape[1]
    expand, contract, shrink = 1.0 + 2.0 / n, 0.75 - 0.5 / n, 1.0 - 1.0 / max(n, 2)
    c = S[:-1].mean(axis=0)
    xr = c + (c - S[-1])
    (pr,), (fr,) = _barrier(model, xr[None], r)
    if pr < Phi[0]:
        xe = c + expand * (c - S[-1])
        (pe,), (fe,) = _barrier(model, xe[None], r)
        S[-1], Phi[-1], Fv[-1] = (xe, pe, fe) if pe < pr else (xr, pr, fr)
        return 2
    if pr < Phi[-2]:
        S[-1], Phi[-1], Fv[-1] = xr, pr, fr
        return 1
    outside = pr < Phi[-1]
    xc = c + contract * (xr - c) if outside else c + contract * (S[-1] - c)
    (pc,), (fc,) = _barrier(model, xc[None], r)
    if (pc <= pr) if outside else (pc < Phi[-1]):
        S[-1], Phi[-1], Fv[-1] = xc, pc, fc
        return 2
    S[1:] = S[0] + shrink * (S[1:] - S[0])
    Phi[1:], Fv[1:] = _barrier(model, S[1:], r)
    return 2 + S.shape[0] - 1


def penalty_method(model, x0, *, r0=None, factor=0.3, stages=12, iterations=2000, step=0.05,
                   ftol=1e-13, xtol=1e-11, progress=False, checkpoint=None, every=200):
    """Minimise a design model by the interior penalty (barrier) method of the textbook (F50).

    Stage k minimises phi(x, r_k) = f(x) - r_k sum_i 1/g_i(x) + sum_j h_j(x)^2 / r_k over the
    strict interior g < 0 (box included), with r_k = r0 * factor**k, by a Nelder-Mead simplex
    started at the previous stage's optimum. As r_k -> 0 the minimisers approach the
    constrained optimum (the text's example: x - r/(1 - x) is least at 1 + sqrt(r)).

    Parameters
    ----------
    model : DesignModel
    x0 : array_like, shape (n,)
        A strictly feasible start: in the open box, every g_i < 0, f finite.
    r0 : float, optional
        First penalty factor; by default the barrier is 10 % of ``|f(x0)|`` at x0.
    factor : float in (0, 1)
        Reduction of r per stage.
    stages : int
        Number of penalty factors r_0 .. r_{stages-1}.
    iterations : int
        Largest number of simplex iterations per stage.
    step : float
        Initial simplex edge of stage k: ``step * sqrt(factor)**k`` times the box width per
        variable (the barrier keeps the optimum about sqrt(r) from an active boundary).
    ftol, xtol : float
        A stage ends when the simplex values differ by at most ``ftol * (1 + |phi|)`` and its
        vertices by at most ``xtol`` times the box width (the text's stopping tests, F41).
    progress : bool
        Progress bar over the iterations (`mech._progress`: standard error in a terminal,
        standard output in a Jupyter kernel).
    checkpoint : str or path, optional
        File (``.npz``) for the search state, written every ``every`` iterations and at the
        end of every stage; an existing file is resumed, with the same result as an
        uninterrupted run.
    every : int

    Returns
    -------
    OptimisationResult
        ``history`` has one row per simplex iteration: the objective f at the best vertex.

    Raises
    ------
    ValueError
        If ``x0`` is not strictly feasible, or for a bad keyword or a foreign checkpoint.

    Notes
    -----
    Equality constraints get the exterior term sum h_j^2 / r (a barrier cannot hold an
    equality); the result then meets them to about r_last. An inequality active at the
    optimum is met from inside, at a distance that falls as sqrt(r). A design the objective
    cannot evaluate (f not finite) counts as outside the region. Nelder-Mead needs no
    derivatives, so objectives with kinks (sums of distances) are fine; it converges to a
    local optimum near the start.

    Examples
    --------
    The text's example (§2.4 V): minimise x subject to 1 - x <= 0.

    >>> from mech.planar.synthesis import DesignModel, penalty_method
    >>> model = DesignModel(lambda x: x[..., 0], [(-5, 5)], inequality=lambda x: 1.0 - x)
    >>> round(float(penalty_method(model, [3.0], r0=1.0, factor=0.1, stages=10).x[0]), 4)
    1.0
    """
    if not isinstance(model, DesignModel):
        raise ValueError(f"Expected `model` as a DesignModel, got {model!r}")
    x0 = model._x(x0, "x0")
    if x0.shape != (model.n,):
        raise ValueError(f"Expected `x0` of shape ({model.n},), got shape {x0.shape}")
    (phi0,), (f0,) = _barrier(model, x0[None], 1.0)
    if not np.isfinite(phi0):
        raise ValueError(f"Expected `x0` strictly inside the box and g < 0 with f finite, got x0 = "
                         f"{x0.tolist()} (g = {model.g(x0).tolist()}, f = {float(f0)})")
    factor = real_number("factor", factor)
    if not 0.0 < factor < 1.0:
        raise ValueError(f"Expected `factor` in (0, 1), got {factor}")
    step = real_number("step", step)
    if not step > 0.0:
        raise ValueError(f"Expected `step` > 0, got {step}")
    ftol, xtol = real_number("ftol", ftol), real_number("xtol", xtol)
    for name, value in (("ftol", ftol), ("xtol", xtol)):
        if not value >= 0.0:
            raise ValueError(f"Expected `{name}` >= 0, got {value}")
    stages = nonnegative_int("stages", stages, 10**4)
    iterations = nonnegative_int("iterations", iterations, 10**9)
    every = nonnegative_int("every", every, 10**9)
    for name, value in (("stages", stages), ("iterations", iterations), ("every", every)):
        if value < 1:
            raise ValueError(f"Expected `{name}` >= 1, got {value}")
    if r0 is None:
        with np.errstate(all="ignore"):
            barrier = phi0 - f0 - np.sum(model.h(x0) ** 2)
        r0 = 0.1 * max(abs(float(f0)), 1e-300) / barrier if barrier > 0 else 1.0
    r0 = real_number("r0", r0)
    if not r0 > 0.0:
        raise ValueError(f"Expected `r0` > 0, got {r0}")
    progress = bool_flag("progress", progress)
    checkpoint = _checkpoint_path(checkpoint)
    width = model.upper - model.lower
    fingerprint = np.concatenate([model.bounds.ravel(), x0, [r0, factor, stages, iterations, step, ftol, xtol]])

    state = _load(checkpoint, "penalty_method", fingerprint)
    if state is None:
        stage, it, S, Phi, Fv = 0, 0, None, None, None
        evaluations, history, best = 1, np.zeros((0, 2)), x0.copy()
    else:
        stage, it, best = int(state["stage"]), int(state["it"]), state["best"]
        S, Phi, Fv = (state["S"], state["Phi"], state["Fv"]) if it > 0 else (None, None, None)
        evaluations, history = int(state["evaluations"]), state["history"]

    def save(**extra):
        if checkpoint is not None:
            _save(checkpoint, "penalty_method", fingerprint, stage=stage, it=it, best=best,
                  evaluations=evaluations, history=history, **extra)

    message = "iteration limit in the last stage"
    with _bar(progress, stages * iterations, stage * iterations + it, "penalty") as bar:
        while stage < stages:
            r = r0 * factor**stage
            if S is None:
                edge = step * np.sqrt(factor) ** stage * width
                # step away from the nearer bound so the vertices start inside the box
                sign = np.where(best + edge < model.upper, 1.0, -1.0)
                S = np.vstack([best, best + np.diag(sign * edge)])
                Phi, Fv = _barrier(model, S, r)
                evaluations += S.shape[0]
            done = False
            while it < iterations and not done:
                order = np.argsort(Phi, kind="stable")
                S, Phi, Fv = S[order], Phi[order], Fv[order]
                with np.errstate(invalid="ignore"):
                    done = bool(np.max(np.abs(Phi[1:] - Phi[0])) <= ftol * (1.0 + abs(Phi[0]))
                                and np.max(np.abs(S[1:] - S[0]) / width) <= xtol)
                if not done:
                    evaluations += _nelder_mead_step(model, r, S, Phi, Fv)
                    k = int(np.argmin(Phi))
                    history = np.vstack([history, [evaluations, Fv[k]]])
                    it += 1
                    bar.update(1)
                    if it % every == 0:
                        save(S=S, Phi=Phi, Fv=Fv)
            best = S[int(np.argmin(Phi))].copy()
            if done:
                message = "converged (F41 tests) in the last stage"
                bar.update(iterations - it)
            stage, it, S = stage + 1, 0, None
            save()
    return _result(model, best, evaluations, history, "penalty", message)
