"""The teacher's toolkit in one place: a class's variants, exported and graded.

>>> from mech.exercises import teaching
>>> [k for k, _, _ in teaching.ANSWER_KEYS["2-3"]]
['theta', 'K', 'phi', 'gamma_min']
>>> round(teaching.parse_answer("0.5 rad", "deg"), 3)
28.648

- ``build_class`` draws and solves every student's variant (with its figure);
  ``write_markdown``, ``write_pdf``, ``write_moodle`` and ``write_qti``
  write sheets, keys and quizzes; ``write_class_list`` the students' seeds;
- ``read_answers``, ``grade_class`` and ``write_gradebook`` grade a class;
  ``parse_answer`` reads one answer with its unit;
- ``ANSWER_KEYS`` is the vocabulary of answer names, ``key_table`` its rows.

The command line ``python -m mech.exercises sheet ... --format md html pdf moodle qti`` and
``python -m mech.exercises check --answers class.csv --gradebook grades.csv`` call these.
Matplotlib, Typst and the XML writer are imported only when a file is written.
"""

from mech.exercises._answers import ANSWER_KEYS, key_table
from mech.exercises._export import (build_class, write_class_list, write_markdown, write_moodle, write_pdf,
                                    write_qti)
from mech.exercises._grade import UNITS, parse_answer, read_answers
from mech.exercises._gradebook import grade_class, write_gradebook
from mech.exercises._sheet import answer_quantities, check_answers, student_seeds

__all__ = ["ANSWER_KEYS", "UNITS", "answer_quantities", "build_class", "check_answers", "grade_class", "key_table",
           "parse_answer", "read_answers", "student_seeds", "write_class_list", "write_gradebook", "write_markdown",
           "write_moodle", "write_pdf", "write_qti"]
