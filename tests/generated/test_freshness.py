"""Every generated module is fresh: its input hash matches the notebook, and its numbers
agree with mpmath at 50 digits (``_codegen.check_fresh``, run by each notebook's
``write`` call under ``MECH_CODEGEN=check``). Text is never compared: SymPy's CSE output
differs between machines.

Re-running the notebooks takes minutes, so it is marked ``slow``, and a notebook that
``make book`` already ran in check mode on the same inputs (its check record) is not run
twice; the fast run checks the manifest instead (``derivations/_manifest.py``): the notebooks' code cells, the generator's
source and the generated files must hash to what ``python -m derivations`` recorded when it
last ran them."""

import importlib
import json
import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest

from derivations import __main__ as runner
from derivations import _codegen, _manifest

NOTEBOOKS = runner.notebooks()
# written by `make book`, which executes every derivation notebook in check mode
BOOK_CHECK_RECORD = runner.HERE.parent / "book" / "_build" / "codegen-checks.jsonl"


def _written_stems(path):
    return re.findall(r"_codegen\.write\(\s*\"([a-z0-9_]+)\"", path.read_text())


@pytest.fixture(autouse=True)
def check_mode(monkeypatch):
    monkeypatch.setenv("MECH_CODEGEN", "check")


@pytest.mark.slow
@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_generated_module_is_fresh(notebook):
    stems = _written_stems(notebook)
    if not stems:
        pytest.skip(f"{notebook.name} generates no code")
    if _manifest.checked(notebook, BOOK_CHECK_RECORD):
        # the book build of this very tree ran the notebook in check mode on the same code,
        # generator and modules (numbers against mpmath included); running it again
        # would repeat the same work
        return
    before = {s: (_codegen.GENERATED_DIR / f"{s}.py").read_bytes() for s in stems if (_codegen.GENERATED_DIR / f"{s}.py").exists()}
    runner.run(notebook)
    after = {s: (_codegen.GENERATED_DIR / f"{s}.py").read_bytes() for s in stems}
    assert before == after, "check mode must not write"
    # the re-run passed, so the manifest that the fast run trusts must describe these files
    assert not _manifest.stale(notebook), _manifest.stale(notebook)


WRITERS = [nb for nb in NOTEBOOKS if _written_stems(nb)]


@pytest.mark.parametrize("notebook", WRITERS, ids=lambda p: p.stem)
def test_generated_module_matches_manifest(notebook):
    """The fast freshness check: hashes only, no notebook is run."""
    assert not _manifest.stale(notebook), _manifest.stale(notebook)


def test_manifest_names_only_existing_notebooks():
    keys = {nb.relative_to(runner.HERE).as_posix() for nb in WRITERS}
    assert set(_manifest.read()) == keys


def test_manifest_detects_changes(tmp_path, monkeypatch):
    """A changed code cell, generator file or generated module each make the entry stale;
    a changed prose line does not."""
    notebook = tmp_path / "nb" / "probe.md"
    notebook.parent.mkdir()
    notebook.write_text("""---
jupytext:
  text_representation:
    extension: .md
    format_name: myst
kernelspec:
  display_name: Python 3
  language: python
  name: python3
---
# A probe

Some prose.

```{code-cell} ipython3
x = 1
_codegen.write("probe", "derivations/nb/probe.md", "(0-0)", [])
```
""")
    generated = tmp_path / "generated"
    generated.mkdir()
    (generated / "probe.py").write_text("VALUE = 1\n")
    generator = tmp_path / "_codegen.py"
    generator.write_text("# template 1\n")
    monkeypatch.setattr(_manifest, "HERE", tmp_path)
    monkeypatch.setattr(_manifest, "MANIFEST", tmp_path / "manifest.json")
    monkeypatch.setattr(_manifest, "GENERATED_DIR", generated)
    _manifest.record([notebook])
    assert _manifest.stale(notebook) == ""
    assert runner.code_cells(notebook)[0].startswith("x = 1")
    notebook.write_text(notebook.read_text().replace("Some prose.", "Other prose."))
    assert _manifest.stale(notebook) == ""
    notebook.write_text(notebook.read_text().replace("x = 1", "x = 2"))
    assert "code cells changed" in _manifest.stale(notebook)
    _manifest.record([notebook])
    generator.write_text("# template 2\n")
    assert "generator" in _manifest.stale(notebook)
    _manifest.record([notebook])
    (generated / "probe.py").write_text("VALUE = 2\n")
    assert "probe.py differs" in _manifest.stale(notebook)


def test_every_generated_module_has_a_notebook():
    stems = {s for nb in NOTEBOOKS for s in _written_stems(nb)}
    modules = {p.stem for p in _codegen.GENERATED_DIR.glob("*.py") if p.stem != "__init__"}
    # the numba kernels of a module with kernels: <stem>_numba.py beside <stem>.py
    kernels = {m for m in modules if m.endswith("_numba") and m[: -len("_numba")] in stems}
    modules -= kernels
    assert modules <= stems, f"generated modules without a notebook: {sorted(modules - stems)}"
    for stem in modules:
        text = (_codegen.GENERATED_DIR / f"{stem}.py").read_text()
        assert text.startswith("# GENERATED by derivations/")
        assert re.search(r'^INPUT_HASH = "sha256:[0-9a-f]{64}"', text, re.M)


def test_every_module_has_a_javascript_module():
    """The JavaScript backend emits one ES module per generated NumPy module, with the
    same provenance header and a freshness hash, and none without a notebook."""
    python = {p.stem for p in _codegen.GENERATED_DIR.glob("*.py")
              if p.stem != "__init__" and not p.stem.endswith("_numba")}
    js = {p.stem for p in _codegen.JS_DIR.glob("*.js")}
    assert js == python, f"missing: {sorted(python - js)}, without a module: {sorted(js - python)}"
    for stem in js:
        text = (_codegen.JS_DIR / f"{stem}.js").read_text()
        assert text.startswith("// GENERATED by derivations/")
        assert re.search(r'^export const INPUT_HASH = "sha256:[0-9a-f]{64}";', text, re.M)


def test_stale_module_is_detected(tmp_path, monkeypatch):
    """A changed expression changes the hash, and check_fresh refuses the old module."""
    import sympy as sm

    x = sm.symbols("x", real=True)
    f = _codegen.Function("square", "x squared.", ((x, "x"),), (("y", x**2, "x^2"),), {x: (-1, 1)})
    monkeypatch.setattr(_codegen, "GENERATED_DIR", tmp_path)
    monkeypatch.setattr(_codegen, "JS_DIR", tmp_path)
    monkeypatch.delenv("MECH_CODEGEN")
    _codegen.write("probe", "derivations/probe.md", "(0-0)", [f])
    g = _codegen.Function("square", "x squared.", ((x, "x"),), (("y", x**2 + 1, "x^2"),), {x: (-1, 1)})
    with pytest.raises(AssertionError, match="stale"):
        _codegen.check_fresh("probe", "derivations/probe.md", "(0-0)", [g])
    # a module whose hash matches but whose numbers are wrong is caught numerically
    text = (tmp_path / "probe.py").read_text().replace("return x**2", "return x**2 + 1e-6")
    (tmp_path / "probe.py").write_text(text)
    with pytest.raises(AssertionError, match="disagrees with mpmath"):
        _codegen.check_fresh("probe", "derivations/probe.md", "(0-0)", [f])


def test_kernels_of_vector_functions(tmp_path, monkeypatch):
    """A function with `vector` arguments gets a NumPy out= kernel and a numba loop; both are
    checked against mpmath, a wrong kernel is caught, and a stale numba module is refused."""
    import sympy as sm

    x, a = sm.symbols("x a", real=True)
    expr = (a * sm.sin(x) ** 2 - sm.sqrt(a + x**2)) / (1 + x**2)
    f = _codegen.Function("probe", "A probe.", ((a, "scalar"), (x, "per point")),
                          (("y", expr, "value"), ("z", -x * a + 2, "second")),
                          {a: (1, 2), x: (-1, 1)}, vector=(x,))
    monkeypatch.setattr(_codegen, "GENERATED_DIR", tmp_path)
    monkeypatch.setattr(_codegen, "JS_DIR", tmp_path)
    monkeypatch.delenv("MECH_CODEGEN")
    _codegen.write("probe", "derivations/probe.md", "(0-0)", [f])
    assert (tmp_path / "probe_numba.py").exists()
    spec = importlib.util.spec_from_file_location("_probe_kernels", tmp_path / "probe.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    xs = np.linspace(-1, 1, 7)
    out, work = (np.empty(7), np.empty(7)), np.empty((module.WORK_ROWS["probe"], 7))
    module.probe_into(1.5, xs, out, work)
    want = module.probe(1.5, xs)
    np.testing.assert_allclose(out[0], want[0], rtol=1e-15, atol=1e-15)
    np.testing.assert_allclose(out[1], want[1], rtol=1e-15, atol=1e-15)
    # a wrong NumPy kernel is caught numerically
    good = (tmp_path / "probe.py").read_text()
    (tmp_path / "probe.py").write_text(good.replace("np.sin(x, out=", "np.cos(x, out=", 1))
    with pytest.raises(AssertionError, match="probe_into.y disagrees with mpmath"):
        _codegen.check_fresh("probe", "derivations/probe.md", "(0-0)", [f])
    (tmp_path / "probe.py").write_text(good)
    # a numba module of other inputs is stale
    numba_text = (tmp_path / "probe_numba.py").read_text()
    (tmp_path / "probe_numba.py").write_text(numba_text.replace("INPUT_HASH = \"sha256:", "INPUT_HASH = \"sha256:0"))
    with pytest.raises(AssertionError, match="probe_numba.py is missing or stale"):
        _codegen.check_fresh("probe", "derivations/probe.md", "(0-0)", [f])


def test_codegen_rejects_unknown_free_symbols():
    import sympy as sm

    x, y = sm.symbols("x y")
    f = _codegen.Function("f", "f.", ((x, "x"),), (("out", x + y, "x + y"),))
    with pytest.raises(ValueError, match="free symbol\\(s\\) y"):
        _codegen.render("f", "derivations/f.md", "", [f])


@pytest.mark.slow  # runs the four-bar notebook (about a minute and a half under load)
def test_cse_same_numerical_results():
    """The CSE module and a plain rendering of the same expressions agree (PyDy's test)."""
    nb = Path(runner.HERE / "planar" / "fourbar_position.md")
    functions = runner.run(nb)["FUNCTIONS"]
    plain = _codegen.render("fourbar_position", "x", "(2-11), (2-12)", functions, cse=False)
    namespace = {}
    exec(compile(plain, "plain", "exec"), namespace)
    generated = importlib.import_module("mech._generated.fourbar_position")
    rng = np.random.default_rng(1)
    for f in functions:
        args = [rng.uniform(*f.domain.get(s, (-2, 2)), 50) for s in f.symbols()]
        with np.errstate(all="ignore"):
            got = np.array(getattr(generated, f.name)(*args), dtype=float)
            ref = np.array(namespace[f.name](*args), dtype=float)
        np.testing.assert_allclose(got, ref, rtol=1e-12, atol=1e-12)


def test_kernels_of_complex_outputs(tmp_path, monkeypatch):
    """A complex output is two real kernel outputs (real, imaginary part); a root of a
    negative number stays NaN in both backends, as in the plain NumPy function, and a
    kernel that swapped the parts is caught against mpmath."""
    import sympy as sm

    x, a = sm.symbols("x a", real=True)
    root = sm.sqrt(a - x**2)                  # NaN for |x| > sqrt(a)
    expr = a * sm.exp(sm.I * x) + root * (x + 2 * sm.I)
    f = _codegen.Function("cprobe", "A complex probe.", ((a, "scalar"), (x, "per point")),
                          (("w", expr, "complex value"), ("r", root, "real value")),
                          {a: (1, 2), x: (-0.9, 0.9)}, vector=(x,))
    monkeypatch.setattr(_codegen, "GENERATED_DIR", tmp_path)
    monkeypatch.setattr(_codegen, "JS_DIR", tmp_path)
    monkeypatch.delenv("MECH_CODEGEN")
    _codegen.write("cprobe", "derivations/cprobe.md", "(0-0)", [f])
    spec = importlib.util.spec_from_file_location("_cprobe_kernels", tmp_path / "cprobe.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    xs = np.array([-0.5, 0.0, 0.7, 1.5])     # the last one has no real root at a = 1.2
    w, r = np.empty(4, complex), np.empty(4)
    with np.errstate(invalid="ignore"):
        module.cprobe_into(1.2, xs, (w.real, w.imag, r), np.empty((module.WORK_ROWS["cprobe"], 4)))
    # independent route: the formula by hand, in complex arithmetic
    want = 1.2 * np.exp(1j * xs[:3]) + np.sqrt(1.2 - xs[:3] ** 2) * (xs[:3] + 2j)
    np.testing.assert_allclose(w[:3], want, rtol=1e-14)
    assert np.isnan(w[3].real) and np.isnan(w[3].imag) and np.isnan(r[3])
    good = (tmp_path / "cprobe.py").read_text()
    (tmp_path / "cprobe.py").write_text(good.replace("out[0]", "out[9]").replace("out[1]", "out[0]")
                                        .replace("out[9]", "out[1]"))
    with pytest.raises(AssertionError, match="cprobe_into.w disagrees with mpmath"):
        _codegen.check_fresh("cprobe", "derivations/cprobe.md", "(0-0)", [f])


def test_check_record_names_exact_inputs(tmp_path, monkeypatch):
    """A check recorded by the book build counts only for the very entry it recorded: a
    record of other code (or no record at all) sends the notebook to be run again."""
    notebook = WRITERS[0]
    record = tmp_path / "checks.jsonl"
    assert not _manifest.checked(notebook, record)
    monkeypatch.setenv(_manifest.RECORD_ENV, str(record))
    _manifest.note_checked(notebook.relative_to(runner.HERE.parent).as_posix())
    assert _manifest.checked(notebook, record)
    assert not _manifest.checked(WRITERS[1], record)
    line = json.loads(record.read_text())
    line["entry"]["code"] = "sha256:" + "0" * 64
    record.write_text(json.dumps(line) + "\n")
    assert not _manifest.checked(notebook, record)


def test_check_runs_only_notebooks_not_checked_on_these_inputs(tmp_path, monkeypatch, capsys):
    """`python -m derivations --check` runs a notebook once; a second check of the same
    inputs skips it, `--all` runs it again, and a changed imported module sends it back."""
    notebook = runner.HERE / "planar" / "grashof.md"
    record = tmp_path / "checked.jsonl"
    monkeypatch.setattr(runner, "notebooks", lambda: [notebook])
    monkeypatch.setenv(_manifest.RECORD_ENV, str(record))
    runner.main(["--check"])
    assert "grashof.md: ok" in capsys.readouterr().out
    runner.main(["--check"])
    assert "grashof.md: unchanged since its last check" in capsys.readouterr().out
    runner.main(["--check", "--all"])
    assert "grashof.md: ok" in capsys.readouterr().out
    imported = _manifest.imported_files(notebook)
    assert any(f.name == "_codegen.py" for f in imported)
    real = _manifest.check_entry(notebook)
    monkeypatch.setattr(_manifest, "check_entry", lambda path: {**real, "imports": "sha256:changed"})
    runner.main(["--check"])
    assert "grashof.md: ok" in capsys.readouterr().out


def test_imported_files_follow_the_project_imports():
    """The import walk reaches the package modules a notebook's checks call."""
    files = {f.relative_to(runner.HERE.parent).as_posix()
             for f in _manifest.imported_files(runner.HERE / "spherical" / "fourbar.md")}
    assert "mech/__init__.py" in files
    assert "mech/planar/__init__.py" in files
    assert "derivations/_codegen.py" in files
