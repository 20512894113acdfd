"""Draw many seeds of every exercise and prove each variant valid: the seed sweep.

A variant is valid when it assembles (the solver accepts it and checks it by analysis), has
every answer its statement asks for (the keys of :mod:`mech.exercises._answers`), and its
givens and answers print to the digits a sheet states: a given printed with six significant
digits reads back as the same number, and an answer printed so lies within the tolerance
``check`` grants it. Run it from a shell, in the background, with a progress bar::

    python -m mech.exercises._sweep --seeds 1000 --workers 2 --json sweep.json

Only the standard library is imported at module level; tqdm (for the bar) and the process pool are imported
when a sweep runs.
"""

from __future__ import annotations

import math
import time

__all__ = ["OPTIONAL_KEYS", "check_variant", "sweep"]


def _centres_at_infinity(keys, got):
    """2-8: an instant centre at infinity has no coordinates; at most four such centres."""
    return len(set(keys) - set(got)) <= 8


#: Exercises whose variants may legitimately lack some keys, with the rule that says which:
#: 2-8 (an instant centre of a translating pair lies at infinity), 2-2 (a range of AB may be
#: empty, and an empty range has no end) and 2-31 (a variant whose other limit position
#: gives no crank-rocker has one design only).
OPTIONAL_KEYS = {
    "2-8": _centres_at_infinity,
    "2-2": lambda keys, got: bool(got) and set(got) <= set(keys),
    "2-31": lambda keys, got: {"l_AB_1", "l_BC_1"} <= set(got) <= set(keys),
}


def check_variant(number, seed):
    """The faults of the variant ``seed`` of exercise ``number`` (an empty list if it is valid).

    Examples
    --------
    >>> from mech.exercises._sweep import check_variant
    >>> check_variant("2-3", 7)
    []
    """
    from mech.exercises import get
    from mech.exercises._answers import ANSWER_KEYS
    from mech.exercises._core import _fmt_number
    from mech.exercises._sheet import answer_quantities, solved_variant

    ex = get(number)
    try:
        params, solution = solved_variant(ex, seed)
    except Exception as exc:                    # noqa: BLE001 -- any failure is a finding
        return [f"does not assemble: {type(exc).__name__}: {exc}"]
    faults = []
    for name, value in params.items():
        if float(_fmt_number(value)) != value:
            faults.append(f"given {name} = {value!r} prints as {_fmt_number(value)}")
    quantities = answer_quantities(solution)
    got = {q.key: q for q in quantities}
    keys = [k for k, _, _ in ANSWER_KEYS[number]]
    rule = OPTIONAL_KEYS.get(number)
    if rule is not None:
        if not rule(keys, got):
            faults.append(f"answers {sorted(got)} break the rule for {number}")
    elif set(got) != set(keys):
        faults.append(f"missing answers {sorted(set(keys) - set(got))}")
    for q in quantities:
        printed = float(_fmt_number(q.value))
        if not (math.isfinite(q.value) and abs(printed - q.value) <= q.tolerance()):
            faults.append(f"answer {q.key} = {q.value!r} prints as {_fmt_number(q.value)}")
    if not ex.statement_text(params).strip():
        faults.append("empty statement")
    return faults


def _chunk(args):
    number, seeds = args
    t0 = time.process_time()
    found = [(seed, f) for seed in seeds for f in check_variant(number, seed)]
    return number, len(seeds), found, time.process_time() - t0


def sweep(numbers=None, seeds=1000, *, first=0, workers=1, chunk=50, progress=True):
    """Check seeds ``first .. first+seeds-1`` of each exercise in ``numbers`` (all when None).

    Returns a dict of exercise number to ``{"seeds", "failures", "cpu_s"}`` (failures a
    list of ``(seed, fault)``), plus ``"wall_s"`` under the key ``"_total"``. With
    ``workers`` > 1 the seeds run in that many processes; ``progress`` shows a tqdm bar
    counted in seeds.
    """
    from mech.exercises import EXERCISES
    from mech._validate import integer

    numbers = list(EXERCISES) if numbers is None else list(numbers)
    seeds = integer("seeds", seeds, minimum=1)
    first = integer("first", first, minimum=0)
    workers = integer("workers", workers, minimum=1)
    chunk = integer("chunk", chunk, minimum=1)
    end = first + seeds
    jobs = [(n, range(s, min(s + chunk, end))) for n in numbers for s in range(first, end, chunk)]
    out = {n: {"seeds": 0, "failures": [], "cpu_s": 0.0} for n in numbers}
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=len(numbers) * seeds, unit="seed", mininterval=5.0)
    t0 = time.perf_counter()

    def record(result):
        number, n, found, cpu = result
        row = out[number]
        row["seeds"] += n
        row["failures"] += found
        row["cpu_s"] += cpu
        if bar is not None:
            bar.update(n)
            bar.set_postfix_str(f"{number}, failures {sum(len(r['failures']) for r in out.values())}")

    if workers == 1:
        for job in jobs:
            record(_chunk(job))
    else:
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(workers) as pool:
            for result in pool.map(_chunk, jobs):
                record(result)
    if bar is not None:
        bar.close()
    out["_total"] = {"wall_s": time.perf_counter() - t0}
    return out


def _main(argv=None):
    import argparse
    import json

    parser = argparse.ArgumentParser(prog="python -m mech.exercises._sweep",
                                     description="Check that every seed of every exercise gives a valid variant.")
    parser.add_argument("numbers", nargs="*", help="exercise numbers (default: all)")
    parser.add_argument("--seeds", type=int, default=1000, help="how many seeds (default 1000)")
    parser.add_argument("--first", type=int, default=0, help="the first seed (default 0), to split a sweep")
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--json", help="write the totals to this file")
    args = parser.parse_args(argv)
    result = sweep(args.numbers or None, args.seeds, first=args.first, workers=args.workers)
    rows = {k: v for k, v in result.items() if k != "_total"}
    for number, row in rows.items():
        print(f"{number:>5}: {row['seeds']} seeds, {len(row['failures'])} failures, {row['cpu_s']:.0f} s CPU")
        for seed, fault in row["failures"][:5]:
            print(f"       seed {seed}: {fault}")
    failures = sum(len(r["failures"]) for r in rows.values())
    print(f"total: {sum(r['seeds'] for r in rows.values())} seeds, {failures} failures, "
          f"{sum(r['cpu_s'] for r in rows.values()):.0f} s CPU, {result['_total']['wall_s']:.0f} s wall")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(result, f, indent=1)
    return 1 if failures else 0


if __name__ == "__main__":
    raise SystemExit(_main())
