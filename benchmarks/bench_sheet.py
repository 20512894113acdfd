"""Time a 30-student problem sheet and key (``python -m mech.exercises sheet``) per exercise.

Run: ``PYTHONPATH=. python benchmarks/bench_sheet.py``. Issue 18 asks for under 10 s; the
simulated exercises 2-4, 2-5 and 2-7 took 5.6 s, 15.4 s and 44.8 s before the shared solve
and the multisection refinement of `_reversals`, and 1.3 s, 2.8 s and 5.0 s after (the
command, loaded machine, seed 1).
"""

import time

from mech.exercises._sheet import DEFAULT_EXERCISES, make_sheet

if __name__ == "__main__":
    for numbers in [DEFAULT_EXERCISES, ("2-4",), ("2-5",), ("2-7",), ("2-4", "2-5", "2-7")]:
        start = time.perf_counter()
        make_sheet(numbers, students=30, seed=1)
        print(f"{' '.join(numbers):24s} {time.perf_counter() - start:6.2f} s")
