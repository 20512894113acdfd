"""Command line: ``python -m mech.exercises {list, show, variant, sheet, check}``.

    python -m mech.exercises list                       # the exercises with solutions
    python -m mech.exercises show 2-3                   # the textbook's numbers, solved
    python -m mech.exercises show 2-3 --set AB=30       # your own numbers, solved
    python -m mech.exercises variant 2-3 --seed 7       # new valid numbers, solved
    python -m mech.exercises sheet 2-3 2-6 --students 30 --seed 2026 --out sheet/
                                                        # a sheet per student, and the key
    python -m mech.exercises check 2-3 --seed 7 --answer K=1.23 theta=20
                                                        # which of a student's numbers are right
"""

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from mech.exercises import EXERCISES, get
from mech.exercises._sheet import DEFAULT_EXERCISES, check_answers, make_sheet, markdown_to_html, solved_variant


def _exercise(text):
    try:
        return get(text)
    except ValueError as err:
        raise argparse.ArgumentTypeError(str(err)) from None


def _assignment(text):
    name, sep, value = text.partition("=")
    try:
        if not sep:
            raise ValueError
        return name.strip(), float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"Expected NAME=NUMBER, got {text!r}") from None


def _parser():
    parser = argparse.ArgumentParser(
        prog="python -m mech.exercises",
        description="Textbook exercises with generated solutions and random variants.",
    )
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list the exercises that have generated solutions")
    show = sub.add_parser("show", help="state and solve an exercise (textbook numbers)")
    show.add_argument("number", type=_exercise, help="exercise number, e.g. 2-3")
    show.add_argument("--set", dest="assign", type=_assignment, action="append", default=[],
                      metavar="NAME=VALUE", help="replace a given value (repeatable)")
    variant = sub.add_parser("variant", help="draw new valid numbers, state and solve")
    variant.add_argument("number", type=_exercise, help="exercise number, e.g. 2-3")
    variant.add_argument("--seed", type=int, default=None, help="random seed (default: a new one, printed)")
    sheet = sub.add_parser("sheet", help="write a problem sheet with one variant per student, and its key")
    sheet.add_argument("numbers", nargs="*", type=_exercise, metavar="NUMBER",
                       help=f"exercise numbers (default: {' '.join(DEFAULT_EXERCISES)})")
    sheet.add_argument("--students", type=int, default=30, help="number of students (default 30)")
    sheet.add_argument("--seed", type=int, default=None, help="class seed (default: a new one, printed)")
    sheet.add_argument("--out", type=Path, required=True, metavar="DIR",
                       help="folder for sheet.md, sheet.html, key.md and key.html")
    sheet.add_argument("--title", default="Problem sheet", help="heading of the sheet and the key")
    check = sub.add_parser("check", help="check a student's numbers for one variant")
    check.add_argument("number", type=_exercise, help="exercise number, e.g. 2-3")
    check.add_argument("--seed", type=int, required=True, help="the student's seed (from the sheet)")
    check.add_argument("--answer", dest="answers", type=_assignment, action="extend", nargs="+",
                       required=True, metavar="KEY=VALUE", help="an answer, angles in degrees (repeatable)")
    check.add_argument("--rtol", type=float, default=0.01, help="relative tolerance (default 0.01, i.e. 1 %%)")
    check.add_argument("--atol", type=float, default=0.01,
                       help="absolute tolerance in the quantity's unit (default 0.01)")
    return parser


def _sheet(args):
    numbers = [ex.number for ex in args.numbers] or list(DEFAULT_EXERCISES)
    seed = args.seed if args.seed is not None else int(np.random.default_rng().integers(2**31))
    start = time.perf_counter()
    sheet_md, key_md = make_sheet(numbers, students=args.students, seed=seed, title=args.title)
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    files = {"sheet.md": sheet_md, "key.md": key_md,
             "sheet.html": markdown_to_html(sheet_md, title=args.title),
             "key.html": markdown_to_html(key_md, title=f"{args.title}: answer key")}
    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8")
    took = time.perf_counter() - start
    print(f"Sheet of exercises {', '.join(numbers)} for {args.students} students, class seed {seed}, "
          f"in {took:.2f} s:")
    for name in files:
        print(f"  {out / name}")
    return 0


def _check(args):
    ex = args.number
    verdicts = check_answers(ex, args.seed, args.answers, rtol=args.rtol, atol=args.atol)
    print(f"Exercise {ex.number}, seed {args.seed}: right within {args.rtol:g} relative "
          f"plus {args.atol:g} absolute (in each quantity's unit; angles in degrees)")
    for v in verdicts:
        print(f"  {v.line()}")
    wrong = [v.quantity.key for v in verdicts if not v.right]
    print(f"{len(verdicts) - len(wrong)} of {len(verdicts)} right"
          + (f"; check {', '.join(wrong)}" if wrong else ""))
    return 1 if wrong else 0


def main(argv=None):
    """Run the command line with ``argv`` (default ``sys.argv[1:]``); return the exit code."""
    parser = _parser()
    args = parser.parse_args(argv)
    if args.command == "list":
        for ex in EXERCISES.values():
            given = ", ".join(f"{p.name}={p.default:g}" for p in ex.parameters)
            print(f"{ex.number}  [{ex.tag}]  {ex.title}  ({given})")
        return 0
    try:
        if args.command == "sheet":
            return _sheet(args)
        if args.command == "check":
            return _check(args)
    except ValueError as err:
        parser.exit(2, f"{parser.prog}: error: {err}\n")
    ex = args.number
    try:
        if args.command == "show":
            params = ex.params(dict(args.assign))
            heading = f"Exercise {ex.number}: {ex.title}"
            solution = ex.solve(params)
        else:
            # without --seed, draw one and print it, so that the variant can be repeated;
            # a variant is printed only once it is solved, with every number finite
            seed = args.seed if args.seed is not None else int(np.random.default_rng().integers(2**31))
            params, solution = solved_variant(ex, seed)
            heading = f"Exercise {ex.number} (variant, seed {seed}): {ex.title}"
    except ValueError as err:
        parser.exit(2, f"{parser.prog}: error: {err}\n")
    print(f"## {heading}\n\n{ex.statement_text(params)}\n")
    print(solution.as_markdown())
    return 0


if __name__ == "__main__":
    sys.exit(main())
