"""The stored targets of benchmarks/bench_synthesis.py (issue 28, item 3): each one loads, names
its source, and is closed or open as its file name says; the benchmark's written-out error
measure agrees with `Match.relative_error`."""

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

from mech.atlas import build_atlas, query, read_target

pytest.importorskip("svgelements")

ROOT = Path(__file__).resolve().parents[2]
TARGETS = ROOT / "benchmarks" / "targets"
FILES = sorted(TARGETS.glob("*.csv")) + sorted(TARGETS.glob("*/*.csv")) + sorted(TARGETS.glob("*/*.svg"))


def _bench():
    sys.path.insert(0, str(ROOT / "benchmarks"))
    spec = importlib.util.spec_from_file_location("bench_synthesis", ROOT / "benchmarks" / "bench_synthesis.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_there_are_targets_of_every_kind():
    names = {p.name.split(".")[0] for p in FILES}
    assert {"yu1", "yu2", "mcgarva", "ullah", "O", "C", "closed-0", "open-noisy-0"} <= names
    assert len(FILES) >= 24


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_target_loads_and_names_its_source(path):
    z, closed = read_target(path)
    kind = path.name.split(".")[1]
    assert kind in ("closed", "open")
    if closed is not None:                         # an SVG says it itself
        assert closed == (kind == "closed")
    assert len(z) >= 10 and np.all(np.isfinite(z))
    head = path.read_text(encoding="utf-8")[:600]
    assert any(word in head for word in ("four-bar-rs", "drawn for", "Coupler curve of"))


def test_bench_error_measure_is_the_match_error():
    bench = _bench()
    atlas = build_atlas(1500, seed=5)
    for name in ("yu1.closed.csv", "mkh1.closed.csv"):
        target, _ = read_target(TARGETS / name)
        m = query(atlas, target, k=1)[0]
        assert bench.shape_error(target, m.curve) == pytest.approx(m.relative_error, rel=5e-3)
