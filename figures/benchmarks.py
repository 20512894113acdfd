"""Figures and tables of the benchmark page, drawn from the committed results JSON.

Nothing here runs a benchmark: ``benchmarks/bench_coupler_curve.py`` writes
``benchmarks/results/coupler_curve.json`` and these functions only read it. Every function
tolerates a missing method, a missing size or a missing error (``None``).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

__all__ = [
    "RESULTS_PATH", "load_results", "results_markdown", "ratios_markdown", "notes_markdown", "measured_on",
    "work_precision",
]

RESULTS_PATH = Path(__file__).resolve().parent.parent / "benchmarks" / "results" / "coupler_curve.json"

#: Plot style per method; unknown methods get the default colour cycle.
_STYLE = {
    "mech": {"color": "C0", "marker": "o"},
    "naive-codegen": {"color": "C1", "marker": "s"},
    "naive-lambdify": {"color": "C4", "marker": "D"},
    "pylinkage": {"color": "C2", "marker": "^"},
    "scipy-root": {"color": "C3", "marker": "v"},
}
#: Errors below this are drawn at this value (a log axis cannot show 0).
ERROR_FLOOR = 1e-17


def load_results(path=None):
    """Return the results document, or ``None`` when the file does not exist."""
    path = Path(path) if path is not None else RESULTS_PATH
    if not path.exists():
        return None
    return json.loads(path.read_text())


def _results(doc):
    return list(doc.get("results", [])) if doc else []


def total_error(entry):
    """Largest of the relative errors the entry has (position; at order 2 also vP, aP)."""
    keys = ["err_position"] + (["err_velocity", "err_acceleration"] if entry.get("order", 0) >= 2 else [])
    values = [entry.get(k) for k in keys]
    if any(v is None for v in values):
        return None
    return max(values)


def measured_on(doc):
    """One sentence naming when and where the numbers were measured."""
    if not doc:
        return "No benchmark results have been committed yet."
    m, v = doc.get("machine", {}), doc.get("versions", {})
    cpus = m.get("usable_cpus") or m.get("logical_cpus")
    load = m.get("load_average_at_start")
    parts = [
        f"Measured on {doc.get('date', 'an unrecorded date')} (UTC) on {m.get('cpu', 'an unrecorded CPU')}",
        f"({cpus or 'an unrecorded number of'} usable cores, {m.get('system', 'unknown system')}",
    ]
    if load:
        parts[-1] += f", load average {load[0]:.2f} at the start"
    parts[-1] += ")"
    soft = ", ".join(f"{k} {val}" for k, val in v.items() if val)
    return " ".join(parts) + f", with {soft}."


def _fmt_err(x):
    return "n/a" if x is None else f"{x:.1e}"


def _fmt_time(entry):
    t = entry.get("time_s")
    if t is None:
        return "n/a"
    text = f"{t * 1e3:.3g}" if t < 1 else f"{t * 1e3:,.0f}"
    return text + ("\\*" if entry.get("scaled") else "")


def results_markdown(doc):
    """A Markdown table: one row per method, order and N."""
    rows = sorted(_results(doc), key=lambda r: (r.get("n", 0), r.get("order", 0), r.get("time_s") or math.inf))
    if not rows:
        return "*No results to show.*"
    lines = [
        "| method | order | N | time (ms) | error P | error vP | error aP |",
        "|:--|--:|--:|--:|--:|--:|--:|",
    ]
    for r in rows:
        lines.append(
            f"| {r.get('label', r.get('method'))} | {r.get('order')} | {r.get('n', 0):,} | {_fmt_time(r)} "
            f"| {_fmt_err(r.get('err_position'))} | {_fmt_err(r.get('err_velocity'))} "
            f"| {_fmt_err(r.get('err_acceleration'))} |"
        )
    if any(r.get("scaled") for r in rows):
        lines.append("")
        lines.append("\\* Timed on a slice of the grid with the same angle spacing and scaled to N.")
    return "\n".join(lines)


def ratios_markdown(doc):
    """A Markdown table of the speed ratios against the project's goals."""
    rat = list(doc.get("ratios", [])) if doc else []
    if not rat:
        return "*No ratios to show.*"
    lines = ["| ratio | medians | fastest runs | goal | verdict |", "|:--|--:|--:|--:|:--|"]
    for r in rat:
        sign = "≥" if r.get("kind") == "min" else "≤"
        value = "n/a" if r.get("value") is None else f"{r['value']:.2f}"
        fastest = "n/a" if r.get("value_of_minima") is None else f"{r['value_of_minima']:.2f}"
        verdict = {True: "met", False: "missed", None: "not measured"}[r.get("pass")]
        lines.append(f"| {r.get('description', r.get('name'))} | {value} | {fastest} | {sign} {r.get('goal')} | {verdict} |")
    return "\n".join(lines)


def notes_markdown(doc):
    """The run's notes (skipped methods, diagnostics) as a Markdown list."""
    notes = list(doc.get("notes", [])) if doc else []
    if not notes:
        return "*The run recorded no notes.*"
    return "\n".join(f"- {n}" for n in notes)


def work_precision(doc, axes=None):
    """Work-precision diagram: run time against the largest relative error, log-log.

    Left panel positions only (order 0), right panel positions, velocities and
    accelerations (order 2, the largest of the three errors). Hollow markers N = 10^4 (the
    smaller size), filled markers the larger size.

    Parameters
    ----------
    doc : dict or None
        The results document from :func:`load_results`.
    axes : sequence of two matplotlib Axes, optional
        Created in a new figure when omitted.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt

    if axes is None:
        fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), sharey=True, layout="constrained")
    else:
        fig = axes[0].figure
    results = _results(doc)
    sizes = sorted({r["n"] for r in results if "n" in r})
    variants = {}
    for r in results:  # one method run several ways (e.g. two tolerances): vary the marker
        labels = variants.setdefault(r.get("method"), [])
        if r.get("label") not in labels:
            labels.append(r.get("label"))
    for ax, order, title in zip(axes, (0, 2), ("positions only", "positions, velocities, accelerations")):
        seen = set()
        for r in results:
            if r.get("order") != order or r.get("time_s") is None:
                continue
            err = total_error(r)
            if err is None:
                continue
            method = r.get("method", "?")
            style = dict(_STYLE.get(method, {"marker": "o"}))
            k = variants[method].index(r.get("label"))
            if k:
                style["marker"] = ("v", ">", "<", "p", "h")[k % 5]
            filled = bool(sizes) and r["n"] == sizes[-1]
            key = (method, r.get("label"))
            label = r.get("label", method) if key not in seen else None
            seen.add(key)
            ax.loglog(
                max(err, ERROR_FLOOR),
                r["time_s"],
                linestyle="none",
                markersize=8,
                markerfacecolor=style.get("color") if filled else "none",
                label=label,
                **style,
            )
        ax.set_title(f"order {order}: {title}")
        ax.set_xlabel("largest error / (a+b+c+d)")
        ax.grid(True, which="major", alpha=0.3)
        if seen:
            ax.legend(fontsize=8, loc="best")
        else:
            ax.text(0.5, 0.5, "no results", transform=ax.transAxes, ha="center")
    axes[0].set_ylabel("median run time (s)")
    if len(sizes) >= 2:
        fig.suptitle(f"hollow: N = {sizes[0]:,}   filled: N = {sizes[-1]:,}", fontsize=9)
    return fig
