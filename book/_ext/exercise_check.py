"""A form on each exercise page that checks a reader's answers, in the page.

The directive ::

    ```{exercise-check} 2-1 2-2 2-3 2-6
    ```

writes a form: choose an exercise and a variant (seed 0 to 99), read its givens, type the
answers (with a unit if you like: ``0.5 rad``, ``1.2 m``), and the page says right, wrong,
missing or malformed per quantity, with the tolerance and the unit table of
``python -m mech.exercises check`` (1 % of the value plus 0.01 in the quantity's unit).

Solving the exercises in the browser is out of reach, so the answers are computed when the
book is built: for each page one small JSON file, ``_static/exercise-answers/PAGE.json``,
holds every listed exercise's answers for seeds 0 to 99 (by `mech.exercises.solved_variant`
and `answer_quantities`, the functions ``check`` uses), its statement template and givens,
and the unit table of `mech.exercises._grade`. The page reads it when the reader first uses
the form; the comparison and the unit conversion run in ``_static/mech/exercise_check.js``.
The tables are cached in the doctree folder, keyed by a hash of the package's source.
"""

import hashlib
import json
import os
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import Directive

SEEDS = range(100)
RTOL = ATOL = 0.01  # the defaults of `python -m mech.exercises check`
OUT_DIR = "_static/exercise-answers"
ROOT = Path(__file__).resolve().parents[2]


def _source_hash():
    digest = hashlib.sha256(Path(__file__).read_bytes())     # this file's table format too
    for path in sorted((ROOT / "mech").rglob("*.py")):
        digest.update(path.relative_to(ROOT).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def exercise_table(number):
    """One exercise's answers for every seed of `SEEDS` (a JSON-ready dict)."""
    from mech.exercises import get
    from mech.exercises._core import _fmt_number
    from mech.exercises._sheet import answer_quantities, solved_variant

    ex = get(number)
    names = [p.name for p in ex.parameters]
    quantities, solved, units = {}, [], {}
    for seed in SEEDS:
        try:
            params, solution = solved_variant(ex, seed)
        except ValueError:
            solved.append(None)        # no valid variant for this seed: the page says so
            continue
        answers = {}
        for q in answer_quantities(solution):
            quantities.setdefault(q.key, {"key": q.key, "name": q.name, "unit": q.unit, "what": q.what})
            answers[q.key] = float(q.value)
        units.update({k: solution.units.get(k, "") for k in params})
        solved.append(([_fmt_number(params[k]) for k in names], answers))
    keys = list(quantities)
    # per seed: the givens in the order of `givens`, the answers in the order of `quantities`
    seeds = [None if s is None else [s[0], [s[1].get(k) for k in keys]] for s in solved]
    return {"number": ex.number, "title": ex.title, "statement": ex.statement, "givens": names,
            "units": {k: units.get(k, "") for k in names}, "quantities": list(quantities.values()), "seeds": seeds}


def _cached_tables(app, numbers):
    cache_file = Path(app.doctreedir) / "exercise-answers-cache.json"
    key = _source_hash()
    try:
        cache = json.loads(cache_file.read_text())
        if cache.get("key") != key:
            cache = {"key": key, "tables": {}}
    except (OSError, ValueError):
        cache = {"key": key, "tables": {}}
    missing = [n for n in numbers if n not in cache["tables"]]
    if len(missing) > 1:
        # about 0.02 to 0.8 s per variant: the page's exercises side by side on every core
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(max_workers=min(len(missing), os.cpu_count() or 1)) as pool:
            cache["tables"].update(zip(missing, pool.map(exercise_table, missing)))
    elif missing:
        cache["tables"][missing[0]] = exercise_table(missing[0])
    if missing:
        cache_file.parent.mkdir(parents=True, exist_ok=True)
        cache_file.write_text(json.dumps(cache))
    return {n: cache["tables"][n] for n in numbers}


def page_data(tables):
    """The JSON of one page: its exercises' tables and the unit rules of ``check``."""
    from mech.exercises import _grade

    return {"rtol": RTOL, "atol": ATOL, "seeds": [SEEDS.start, SEEDS.stop - 1],
            "units": _grade.UNITS, "kinds": _grade._KIND_OF_QUANTITY, "shown": _grade._SHOWN,
            "exercises": tables}


def _slug(docname):
    return docname.replace("/", "-")


def _form(docname, tables):
    from html import escape

    depth = docname.count("/")
    up = "../" * depth
    first = next(iter(tables.values()))
    options = "".join(f'<option value="{escape(n)}">Exercise {escape(n)}: {escape(t["title"])}</option>'
                      for n, t in tables.items())
    rows = "".join(
        f'<tr><td><label for="ans-{escape(first["number"])}-{escape(q["key"])}"><code>{escape(q["key"])}</code></label></td>'
        f'<td>{escape(q["name"])}</td><td><input type="text" id="ans-{escape(first["number"])}-{escape(q["key"])}" '
        f'data-key="{escape(q["key"])}" size="12"> {escape(q["unit"])}</td><td class="verdict" data-key="{escape(q["key"])}"></td></tr>'
        for q in first["quantities"])
    seed0 = first["seeds"][0]
    givens = ("" if seed0 is None else
              "Variant 0: " + first["statement"].format(**dict(zip(first["givens"], seed0[0]))))
    return (
        f'<div class="mech-exercise-check" data-table="{up}{OUT_DIR}/{_slug(docname)}.json">'
        "<p>Check your own answers here. Choose an exercise and a variant (seed 0 to 99; "
        "<code>python -m mech.exercises variant NUMBER --seed SEED</code> prints the same one), solve it, "
        "type your numbers (in the unit shown, or with a unit such as <code>0.5 rad</code>, <code>1.2 m</code>, "
        "<code>15 N*m</code>) and press Check. Each answer is right when it is within 1 % of the value plus "
        "0.01 in the quantity's unit, as <code>python -m mech.exercises check</code> decides. The answers were "
        "computed when the book was built, for seeds 0 to 99 only, and are read from a small file of this page; "
        "the comparison and the unit conversion run in your browser (with scripts off, use the command line).</p>"
        f'<p><label>Exercise <select data-control="exercise" style="max-width:19em">{options}</select></label> '
        f'<label>Seed <input type="number" min="{SEEDS.start}" max="{SEEDS.stop - 1}" step="1" value="0" '
        'data-control="seed"></label> <button type="button" data-control="check">Check</button></p>'
        f'<p class="givens" data-part="givens">{escape(givens)}</p>'
        # the table scrolls in its own box on a phone, so the page itself never pans sideways
        '<div style="overflow-x:auto;max-width:100%">'
        f'<table><thead><tr><th>key</th><th>quantity</th><th>your answer</th><th>verdict</th></tr></thead>'
        f'<tbody data-part="answers">{rows}</tbody></table></div><p data-part="summary" aria-live="polite"></p></div>'
        f'<script type="module" src="{up}_static/mech/exercise_check.js"></script>'
    )


class ExerciseCheck(Directive):
    """``{exercise-check} NUMBER ...``: the answer-check form for these exercises."""

    required_arguments = 1
    optional_arguments = 40

    def run(self):
        env = self.state.document.settings.env
        numbers = list(self.arguments)
        tables = _cached_tables(env.app, numbers)
        store = env.__dict__.setdefault("mech_exercise_tables", {})
        store[env.docname] = tables
        return [nodes.raw("", _form(env.docname, tables), format="html")]


def _purge(app, env, docname):
    getattr(env, "mech_exercise_tables", {}).pop(docname, None)


def _merge(app, env, docnames, other):
    store = env.__dict__.setdefault("mech_exercise_tables", {})
    for name, tables in getattr(other, "mech_exercise_tables", {}).items():
        if name in docnames:
            store[name] = tables


def _write(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    out = Path(app.outdir) / OUT_DIR
    out.mkdir(parents=True, exist_ok=True)
    for docname, tables in getattr(app.env, "mech_exercise_tables", {}).items():
        text = json.dumps(page_data(tables), separators=(",", ":"), allow_nan=False)
        (out / f"{_slug(docname)}.json").write_text(text, encoding="utf-8")


def setup(app):
    app.add_directive("exercise-check", ExerciseCheck)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    app.connect("build-finished", _write)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "env_version": 1}

