"""tests/slow_tests.txt: what `make test-fast` leaves out (tests/slow_list.py writes it, the
root conftest.py marks its functions `slow`)."""

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
import slow_list  # noqa: E402

REPORT = """\
============================= slowest durations ==============================
12.50s call     tests/a/test_x.py::test_big[1-2]
10.00s call     tests/a/test_x.py::test_big[3-4]
3.00s setup    tests/a/test_x.py::test_fixture_heavy
0.20s call     tests/a/test_x.py::test_fixture_heavy
1.00s call     mech/planar/_x.py::mech.planar._x.f
0.01s teardown tests/a/test_x.py::test_small
"""


def test_durations_summed_per_function():
    got = slow_list.parse_durations(REPORT)
    assert got == pytest.approx({"tests/a/test_x.py::test_big": 22.5, "tests/a/test_x.py::test_fixture_heavy": 3.2,
                                 "mech/planar/_x.py::mech.planar._x.f": 1.0, "tests/a/test_x.py::test_small": 0.01})


def test_slowest_listed_until_the_rest_fits(monkeypatch):
    monkeypatch.setattr(slow_list, "exists", lambda f: True)
    measured = slow_list.parse_durations(REPORT)
    chosen, rest = slow_list.choose(measured, {}, budget=2.0)
    assert set(chosen) == {"tests/a/test_x.py::test_big", "tests/a/test_x.py::test_fixture_heavy"}
    assert rest == pytest.approx(1.01)
    # an entry already listed stays, and a vanished one goes
    monkeypatch.setattr(slow_list, "exists", lambda f: f != "tests/gone.py::test_gone")
    chosen, _ = slow_list.choose({}, {"tests/a/test_x.py::test_small": 0.5, "tests/gone.py::test_gone": 9.0}, 100)
    assert chosen == {"tests/a/test_x.py::test_small": 0.5}


def test_every_listed_function_exists():
    listed = slow_list.read_list()
    missing = sorted(f for f in listed if not slow_list.exists(f))
    assert not missing, f"tests/slow_tests.txt names functions that no longer exist: {missing}"


def test_round_trip(tmp_path):
    chosen = {"tests/a/test_x.py::test_big": 22.5, "tests/b/test_y.py::test_z": 1.25}
    slow_list.write_list(chosen, tmp_path / "slow.txt")
    assert slow_list.read_list(tmp_path / "slow.txt") == chosen


def test_listed_functions_are_marked_slow():
    """The root conftest.py marks a listed function: `-m slow` selects it, `-m "not slow"` not."""
    listed = [f for f in slow_list.read_list() if f.startswith("tests/") and "::" in f]
    if not listed:
        pytest.skip("no test function is listed")
    function = sorted(listed, key=lambda f: (len(f), f))[0]
    path = function.split("::")[0]

    def collect(marker):
        out = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider",
                              "-m", marker, path], cwd=ROOT, capture_output=True, text=True).stdout
        return {line.split("[")[0] for line in out.splitlines() if "::" in line}

    assert function in collect("slow")
    assert function not in collect("not slow")
