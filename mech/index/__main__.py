"""``python -m mech.index 2-19``: where a textbook number is derived, computed, shown and tested.

Usage::

    python -m mech.index 2-19            # every kind numbered 2-19
    python -m mech.index eq 2-19         # also: fig 2-86, ex 2-15 (example), exercise 2-27,
                                         # table 2-3, chapter 5, §1.3.1
    python -m mech.index --summary       # how many numbers of each kind are covered
    python -m mech.index --missing       # catalogued numbers not covered, with reasons
    python -m mech.index --root PATH ... # index another clone
"""

import argparse
import sys

from mech.index import RepositoryNotFound, build_index, parse_query
from mech.index._refs import KINDS
from mech.index._render import entry_text


class _Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line on stderr (status 2), not a usage block."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def main(argv=None):
    parser = _Parser(
        prog="python -m mech.index",
        description="Find a textbook number: its derivation, functions, book page and tests.")
    parser.add_argument("query", nargs="*", help="e.g. 2-19, eq 2-19, fig 2-86, ex 2-15, "
                        "exercise 2-27, table 2-3, chapter 5, §1.3.1")
    parser.add_argument("--root", help="the clone to index (default: the one holding mech)")
    parser.add_argument("--summary", action="store_true", help="count covered numbers")
    parser.add_argument("--missing", action="store_true",
                        help="list the catalogued numbers not covered")
    args = parser.parse_args(argv)
    if not (args.query or args.summary or args.missing):
        parser.print_help()
        return 2
    query = " ".join(args.query)
    if args.query:                            # an empty or blank query is refused, not ignored
        try:
            parse_query(query)
        except ValueError as exc:
            print(exc, file=sys.stderr)
            return 2
    try:
        index = build_index(args.root)
    except RepositoryNotFound as exc:
        print(exc, file=sys.stderr)
        return 2
    if args.summary:
        for kind, (total, covered, gaps) in index.summary().items():
            print(f"{KINDS[kind] + 's':20s} {total:4d} catalogued, {covered:4d} covered, "
                  f"{gaps:4d} not yet covered")
        print("\nThe monograph, chapter by chapter and section by section:")
        for e in index:
            if e.key[0] in ("chapter", "section") and e.catalogued:
                label = f"chapter {e.key[1]}" if e.key[0] == "chapter" else f"  §{e.key[1]}"
                page = f"p. {e.item['page']}" if e.item and "page" in e.item else ""
                print(f"{label:12s} {page:7s} {e.name or '':58s} "
                      f"{'covered' if e.covered else 'not yet covered'}")
    if args.missing:
        for e in index:
            if e.catalogued and not e.covered:
                name = f" ({e.name})" if e.name else ""
                print(f"{e.title}{name}: {e.not_covered or 'NO REASON GIVEN'}")
        for e in index.stale():
            print(f"{e.title}: covered now; delete its entry in mech/index/_not_covered.py")
    if args.query:
        entries = index.lookup(query)
        if not entries:
            print(f"No entry for {query!r}: nothing declares it and the textbook data does not list it.",
                  file=sys.stderr)
            return 1
        if len(entries) > 1:
            print(f"{query} matches {len(entries)} kinds: "
                  + ", ".join(e.title for e in entries) + "\n")
        print("\n\n".join(entry_text(e) for e in entries))
    return 0


if __name__ == "__main__":
    sys.exit(main())
