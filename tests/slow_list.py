"""Write tests/slow_tests.txt, the test functions that `make test-fast` leaves out.

    .venv/bin/python -m pytest -m "not slow" --durations=0 -q -p no:cacheprovider > durations.txt
    .venv/bin/python tests/slow_list.py durations.txt [--budget 60]

pytest's ``--durations=0`` report gives the time of every setup, call and teardown. They are
summed per test function (all its parameters together), and the slowest functions are added
to the list until what stays in the fast run takes at most ``--budget`` seconds (the time of
collection and of the imports comes on top). Functions already listed stay listed, with
their recorded time, unless they no longer exist; the root ``conftest.py`` marks every listed
function ``slow``. Time a quiet machine: the budget is in seconds of that machine.
"""

import argparse
import re
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
LIST = ROOT / "tests" / "slow_tests.txt"
HEADER = """\
# Test functions marked `slow` by the root conftest.py (all parameters of each), so that
# `make test-fast` stays short; `make test` runs them. Written by tests/slow_list.py from a
# `--durations=0` report: seconds (all parameters, setup to teardown), then the function.
"""
_LINE = re.compile(r"^\s*(\d+(?:\.\d+)?)s\s+(setup|call|teardown)\s+(\S.*?)\s*$")


def function_of(nodeid):
    """The test function of a node id: parameters dropped."""
    return nodeid.split("[", 1)[0]


def parse_durations(text):
    """``{function: seconds}`` from pytest's ``--durations`` report."""
    totals = defaultdict(float)
    for line in text.splitlines():
        m = _LINE.match(line)
        if m:
            totals[function_of(m.group(3))] += float(m.group(1))
    return dict(totals)


def read_list(path=LIST):
    """``{function: seconds}`` of the current list."""
    listed = {}
    if path.exists():
        for line in path.read_text().splitlines():
            if line.strip() and not line.startswith("#"):
                seconds, function = line.split("\t")
                listed[function.strip()] = float(seconds)
    return listed


def exists(function, root=ROOT):
    """Whether a listed function still exists (a test function, or a doctest of a module)."""
    path, _, name = function.partition("::")
    file = root / path
    if not file.exists():
        return False
    if path.startswith("mech/"):
        return True                            # a doctest: the module is enough
    last = name.split("::")[-1]
    return re.search(rf"^\s*(async\s+)?def {re.escape(last)}\(", file.read_text(), re.M) is not None


def choose(measured, listed, budget):
    """The new list: the listed functions that exist, and the slowest measured ones until the
    rest fits in ``budget`` seconds."""
    keep = {f: s for f, s in listed.items() if exists(f)}
    keep.update({f: s for f, s in measured.items() if f in keep})
    fast = {f: s for f, s in measured.items() if f not in keep}
    rest = sum(fast.values())
    for function, seconds in sorted(fast.items(), key=lambda fs: -fs[1]):
        if rest <= budget:
            break
        keep[function] = seconds
        rest -= seconds
    return keep, rest


def write_list(chosen, path=LIST):
    lines = [f"{seconds:.2f}\t{function}" for function, seconds in
             sorted(chosen.items(), key=lambda fs: (-round(fs[1], 2), fs[0]))]
    path.write_text(HEADER + "\n".join(lines) + "\n")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("report", help="a file with pytest's --durations=0 report")
    parser.add_argument("--budget", type=float, default=60.0,
                        help="seconds of tests left in the fast run (default 60)")
    args = parser.parse_args(argv)
    measured = parse_durations(Path(args.report).read_text())
    chosen, rest = choose(measured, read_list(), args.budget)
    write_list(chosen)
    print(f"{len(chosen)} functions listed as slow; {rest:.1f} s of measured tests stay in the fast run")
    return 0


if __name__ == "__main__":
    sys.exit(main())
