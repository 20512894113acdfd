"""Command line: ``python -m mech.exercises {list, show, variant, sheet, check}``.

    python -m mech.exercises list                       # the exercises, and what [N]/[A]/[G] mean
    python -m mech.exercises show 2-3                   # the textbook's numbers, solved
    python -m mech.exercises show 2-3 --set AB=30       # your own numbers, solved
    python -m mech.exercises variant 2-3 --seed 7       # new valid numbers, solved
    python -m mech.exercises sheet 2-3 2-6 --students 30 --seed 2026 --out sheet/ \\
        --format md html pdf moodle qti                 # a sheet and a key per student, quizzes
    python -m mech.exercises check 2-3 --seed 7 --answer K=1.23 theta=0.35rad
                                                        # which of a student's numbers are right
    python -m mech.exercises check --answers class.csv --gradebook grades.csv
                                                        # a whole class in one call

Every bad command line ends with a one-line error on stderr and exit status 2.
"""

import argparse
import re
import sys
import time
from pathlib import Path

import numpy as np

from mech.exercises import EXAMPLES, EXERCISES, get
from mech.exercises._sheet import DEFAULT_EXERCISES, check_answers, solved_variant, tolerances

FORMATS = ("md", "html", "pdf", "moodle", "qti")

TAGS = {"N": "the textbook's text states every given (its numbers are used as they are)",
        "A": "the figure with some dimensions is lost: a layout is assumed and stated in the solution",
        "G": "the figure is lost: a common mechanism is assumed and stated in the statement"}


class _Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line on stderr, with exit status 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message}\n")


def _exercise(text):
    if text.strip().lower() in ("all", "examples"):
        return text.strip().lower()
    try:
        return get(text)
    except ValueError as err:
        raise argparse.ArgumentTypeError(str(err)) from None


_VALUE = re.compile(r"\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*[^\d\s=][^=]*|\s*[-+]?(?:\d+\.?\d*|\.\d+)"
                    r"(?:[eE][-+]?\d+)?\s*")


def _assignment(text):
    if text.startswith("@") and len(text) > 1:
        return "@", text[1:]                     # an answer file
    name, sep, value = text.partition("=")
    if not sep or not name.strip() or not _VALUE.fullmatch(value):
        raise argparse.ArgumentTypeError(f"Expected NAME=NUMBER with an optional unit (K=1.2, theta=0.35rad), "
                                         f"got {text!r}")
    return name.strip(), value.strip()


def _setting(text):
    name, sep, value = text.partition("=")
    try:
        if not sep:
            raise ValueError
        return name.strip(), float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"Expected NAME=NUMBER, got {text!r}") from None


def _count(text):
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"Expected a whole number, got {text!r}") from None


def _parser():
    parser = _Parser(prog="python -m mech.exercises",
                     description="Textbook exercises with generated solutions and random variants.")
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list the exercises that have generated solutions, with their tags")
    show = sub.add_parser("show", help="state and solve an exercise (textbook numbers)")
    show.add_argument("number", type=_exercise, help="exercise number, e.g. 2-3")
    show.add_argument("--set", dest="assign", type=_setting, action="append", default=[],
                      metavar="NAME=VALUE", help="replace a given value (repeatable)")
    show.add_argument("--markdown", action="store_true", help="print Markdown instead of plain text")
    variant = sub.add_parser("variant", help="draw new valid numbers, state and solve")
    variant.add_argument("number", type=_exercise, help="exercise number, e.g. 2-3")
    variant.add_argument("--seed", type=_count, default=None, help="random seed (default: a new one, printed)")
    variant.add_argument("--markdown", action="store_true", help="print Markdown instead of plain text")
    sheet = sub.add_parser("sheet", help="write a sheet and a key per student, and quizzes")
    sheet.add_argument("numbers", nargs="*", type=_exercise, metavar="NUMBER",
                       help=f"exercise numbers, worked examples (E2-1 ...), 'all' exercises or 'examples' "
                            f"(default: {' '.join(DEFAULT_EXERCISES)})")
    sheet.add_argument("--students", type=_count, default=30, help="number of students (default 30)")
    sheet.add_argument("--seed", type=_count, default=None, help="class seed (default: a new one, printed)")
    sheet.add_argument("--out", type=Path, required=True, metavar="DIR", help="folder for the files")
    sheet.add_argument("--title", default="Problem sheet", help="heading of the sheets and the keys")
    sheet.add_argument("--format", dest="formats", nargs="+", choices=FORMATS, default=["md", "html"],
                       help="md and html: a sheet and a key per student; pdf: the same through Typst, and a "
                            "class list; moodle: quiz.xml; qti: quiz_qti.zip for Canvas (default: md html)")
    sheet.add_argument("--rtol", type=float, default=0.01, help="relative tolerance of quiz answers (default 0.01)")
    sheet.add_argument("--atol", type=float, default=0.01, help="absolute tolerance of quiz answers (default 0.01)")
    check = sub.add_parser("check", help="check a student's answers, or a whole class's from files")
    check.add_argument("number", nargs="?", type=_exercise, default=None,
                       help="exercise number, e.g. 2-3 (needed unless every answer is named NUMBER:KEY)")
    check.add_argument("--seed", type=_count, default=None, help="the student's seed (from the sheet)")
    check.add_argument("--answer", dest="answers", type=_assignment, action="extend", nargs="+", default=[],
                       metavar="KEY=VALUE", help="an answer with an optional unit, e.g. phi=32.07deg; "
                                                 "@FILE reads an answer file")
    check.add_argument("--answers", dest="files", type=Path, action="extend", nargs="+", default=[],
                       metavar="FILE", help="answer files: a CSV with a row per student, or text files, "
                                            "one per student")
    check.add_argument("--gradebook", type=Path, default=None, metavar="CSV",
                       help="write the gradebook (a row per student and answer) to this CSV")
    check.add_argument("--rtol", type=float, default=0.01, help="relative tolerance (default 0.01, i.e. 1 %%)")
    check.add_argument("--atol", type=float, default=0.01,
                       help="absolute tolerance in the quantity's unit (default 0.01)")
    return parser


def _numbers(args):
    out = []
    for x in args.numbers:
        group = list(EXERCISES) if x == "all" else list(EXAMPLES) if x == "examples" else [x.number]
        out += [n for n in group if n not in out]
    return out or list(DEFAULT_EXERCISES)


def _sheet(args):
    from mech.exercises import _export

    numbers = _numbers(args)
    seed = args.seed if args.seed is not None else int(np.random.default_rng().integers(2**31))
    rtol, atol = tolerances(args.rtol, args.atol)
    start = time.perf_counter()
    out = args.out
    try:
        out.mkdir(parents=True, exist_ok=True)
        probe = out / ".write_test"
        probe.write_text("")
        probe.unlink()
    except OSError as err:
        raise ValueError(f"Expected `--out` to be a folder that can be written, got {str(out)!r} "
                         f"({err.strerror})") from None
    students = _export.build_class(numbers, students=args.students, seed=seed)
    files = []
    if {"md", "html"} & set(args.formats):
        files += [p for p in _export.write_markdown(students, out, title=args.title, html_too="html" in args.formats)
                  if p.suffix[1:] in args.formats]
    if "pdf" in args.formats:
        files += _export.write_pdf(students, out, title=args.title)
    if "moodle" in args.formats:
        _export.write_moodle(students, out / "quiz.xml", rtol=rtol, atol=atol)
        files.append(out / "quiz.xml")
    if "qti" in args.formats:
        files.append(_export.write_qti(students, out / "quiz_qti.zip", rtol=rtol, atol=atol))
    took = time.perf_counter() - start
    print(f"Exercises {', '.join(numbers)} for {args.students} students, class seed {seed}, "
          f"{len(files)} files in {took:.1f} s, in {out}:")
    for f in files[:6]:
        print(f"  {f}")
    if len(files) > 6:
        print(f"  ... and {len(files) - 6} more; the class list (student, seed) is {out / 'class_list.csv'}")
    return 0


def _check_class(args, entries):
    from mech.exercises._gradebook import grade_class, write_gradebook

    rtol, atol = tolerances(args.rtol, args.atol)
    graded = grade_class(entries, rtol=rtol, atol=atol)
    counts = {}
    for e, v in graded:
        counts[v.status] = counts.get(v.status, 0) + 1
        if v.status == "malformed":
            print(f"  malformed: student {e.student}, {e.exercise or '?'}:{e.key or '?'} = {e.text!r}: {v.why}")
    if args.gradebook is not None:
        write_gradebook(args.gradebook, graded)
    students = len({e.student for e, _ in graded})
    print(f"{students} students, {len(graded)} answers: " + ", ".join(f"{counts.get(k, 0)} {k}" for k in
                                                                     ("right", "wrong", "missing", "malformed"))
          + (f"; gradebook {args.gradebook}" if args.gradebook else ""))
    return 0 if counts.get("right", 0) == len(graded) else 1


def _check(args):
    from mech.exercises._grade import Entry, read_answers

    default = args.number.number if args.number else None
    files = list(args.files) + [Path(v) for n, v in args.answers if n == "@"]
    inline = [(n, v) for n, v in args.answers if n != "@"]
    if files or args.gradebook is not None:
        entries = [e for f in files for e in read_answers(f, exercise=default)]
        if args.seed is not None:                 # a file without a seed line: the --seed given
            entries = [Entry(e.student, args.seed, e.exercise, e.key, e.text) if e.seed in (None, "") else e
                       for e in entries]
        if inline:
            if args.seed is None:
                raise ValueError("Expected `--seed` with `--answer` KEY=VALUE, got none")
            entries += [Entry("command line", args.seed, default, n, v) for n, v in inline]
        if not entries:
            raise ValueError("Expected `--answers` files that hold answers, got none")
        return _check_class(args, entries)
    if args.number is None or args.seed is None or not inline:
        raise ValueError("Expected NUMBER, --seed and --answer KEY=VALUE, or --answers FILE ..., got "
                         + ("no exercise number" if args.number is None else
                            "no --seed" if args.seed is None else "no answers"))
    ex = args.number
    verdicts = check_answers(ex, args.seed, inline, rtol=args.rtol, atol=args.atol)
    print(f"Exercise {ex.number}, seed {args.seed}: right within {args.rtol:g} relative "
          f"plus {args.atol:g} absolute (in each quantity's unit; angles in degrees)")
    for v in verdicts:
        print(f"  {v.line()}")
    wrong = [v.quantity.key for v in verdicts if not v.right]
    print(f"{len(verdicts) - len(wrong)} of {len(verdicts)} right"
          + (f"; check {', '.join(wrong)}" if wrong else ""))
    return 1 if wrong else 0


def _list():
    print("Tags:")
    for k, v in TAGS.items():
        print(f"  [{k}] {v}")
    for ex in (*EXERCISES.values(), *EXAMPLES.values()):
        given = ", ".join(f"{p.name}={p.default:g}" for p in ex.parameters)
        print(f"{ex.number}  [{ex.tag}]  {ex.title}  ({given})")
    return 0


def main(argv=None):
    """Run the command line with ``argv`` (default ``sys.argv[1:]``); return the exit code."""
    from mech.exercises._text import markdown_to_text

    parser = _parser()
    args = parser.parse_args(argv)
    if args.command == "list":
        return _list()
    try:
        if args.command == "sheet":
            return _sheet(args)
        if args.command == "check":
            return _check(args)
        ex = args.number
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
    except (ValueError, TypeError, OverflowError) as err:
        parser.exit(2, f"{parser.prog}: error: {err}\n")
    except OSError as err:
        parser.exit(2, f"{parser.prog}: error: could not write or read a file: {err}\n")
    except ImportError as err:
        parser.exit(2, f"{parser.prog}: error: {err.name} is needed for this format (pip install "
                       f"'mech[teach]')\n")
    text = f"## {heading}\n\n{ex.statement_text(params)}\n\n{solution.as_markdown()}"
    print(text if args.markdown else markdown_to_text(text), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
