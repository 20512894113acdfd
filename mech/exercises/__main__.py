"""Command line: ``python -m mech.exercises {list, show, variant}``.

    python -m mech.exercises list                       # the exercises with solutions
    python -m mech.exercises show 2-3                   # the textbook's numbers, solved
    python -m mech.exercises show 2-3 --set AB=30       # your own numbers, solved
    python -m mech.exercises variant 2-3 --seed 7       # new valid numbers, solved
"""

import argparse
import sys

import numpy as np

from mech.exercises import EXERCISES, get


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
    return parser


def main(argv=None):
    """Run the command line with ``argv`` (default ``sys.argv[1:]``); return the exit code."""
    parser = _parser()
    args = parser.parse_args(argv)
    if args.command == "list":
        for ex in EXERCISES.values():
            given = ", ".join(f"{p.name}={p.default:g}" for p in ex.parameters)
            print(f"{ex.number}  [{ex.tag}]  {ex.title}  ({given})")
        return 0
    ex = args.number
    try:
        if args.command == "show":
            params = ex.params(dict(args.assign))
            heading = f"Exercise {ex.number}: {ex.title}"
        else:
            # without --seed, draw one and print it, so that the variant can be repeated
            seed = args.seed if args.seed is not None else int(np.random.default_rng().integers(2**31))
            params = ex.variant(seed)
            heading = f"Exercise {ex.number} (variant, seed {seed}): {ex.title}"
        solution = ex.solve(params)
    except ValueError as err:
        parser.exit(2, f"{parser.prog}: error: {err}\n")
    print(f"## {heading}\n\n{ex.statement_text(params)}\n")
    print(solution.as_markdown())
    return 0


if __name__ == "__main__":
    sys.exit(main())
