"""A teacher's grading: a class's numeric answers against their variants' answers.

    grade(read_key(variants.json), answers.csv, Rule()) -> ClassGrades

The key is the table ``rbdsolve variants -o variants.json`` (or ``-o variants.csv``,
teaching/key_csv.py) writes (one row per variant: its parameter values and its numeric
answers). The answers are a CSV with a
header ``student, variant, ANSWER, ANSWER, …`` (or separated by ';', with decimal commas,
as spreadsheets in much of Europe write it) — each ANSWER a column of the key or an
alias (teaching/addresses.py: ``omega1`` for ``modes.frequencies[1]``) — and one row per
student. Each number is right when it is within the Rule's tolerance of the key; a
wrong one is said to be a slip (verdicts.Slip) when it is within that tolerance of the
key after the slip (−k, 2k, k/2π, 180k/π, k², √k, with or without the sign). A kind
column (a stability) is right when it is the same word.

Malformed input (an unknown column, a row with the wrong number of cells, a variant the
table does not have, a cell that is not a number or past the csv module's 131,072
characters) is one located message each; the rest is still graded. Lines may end with
LF, CRLF or CR. A class past MAX_STUDENTS rows, MAX_COLUMNS columns or MAX_MARKS answers
is refused where it passes the limit, and grading runs within the run's budget
(docs/grading.md, Limits).
"""

from __future__ import annotations

import csv
import io
import math
import re
from collections import Counter
from dataclasses import dataclass
from enum import Enum

from rbdsolve.errors import InputError, Location, UnsolvedError, clipped
from rbdsolve.teaching.addresses import resolve
from rbdsolve.teaching.files import read_file
from rbdsolve.teaching.variants_key import Key, read_key  # noqa: F401 - read_key: grade(read_key(…), …)
from rbdsolve.teaching.verdicts import FACTOR_SLIPS, Slip

STUDENT, VARIANT = "student", "variant"


@dataclass(frozen=True)
class Rule:
    """When a number is right: within max(rtol·|key|, atol) of the key, or, with
    ``sig_figs`` N, within one unit of the key's N-th significant figure (N = 3:
    4.37 to 4.39 for 4.3816). A slip earns ``slip_credit`` of a mark."""

    rtol: float = 0.01
    atol: float = 1e-9
    sig_figs: int | None = None
    slip_credit: float = 0.0

    def tolerance(self, key: float) -> float:
        if self.sig_figs is not None and key != 0:
            return 10.0 ** (math.floor(math.log10(abs(key))) - self.sig_figs + 1)
        return max(self.rtol * abs(key), self.atol)

    def agrees(self, given: float, key: float) -> bool:
        """Within the tolerance of ``key``; never for a key past a float's range (a slip
        of 10³⁰⁰ turned into degrees is infinite, and so would be its tolerance)."""
        return math.isfinite(key) and abs(given - key) <= self.tolerance(key)


class Outcome(Enum):
    RIGHT = "right"
    SLIP = "slip"  # wrong, by a named slip
    WRONG = "wrong"
    BLANK = "blank"  # no answer given
    UNGRADED = "ungraded"  # the cell is malformed, or the key has no number for this variant


@dataclass(frozen=True)
class Mark:
    answer: str  # the key's column
    given: str  # as written
    key: float | str | None
    outcome: Outcome
    slips: tuple[Slip, ...] = ()

    @property
    def word(self) -> str:
        """'right', 'wrong', 'blank', 'ungraded', or the slips: 'sign', 'sign+two_pi'."""
        return "+".join(s.value for s in self.slips) if self.outcome is Outcome.SLIP else self.outcome.value


@dataclass(frozen=True)
class StudentGrade:
    student: str
    variant: int
    line: int
    marks: tuple[Mark, ...]


@dataclass(frozen=True)
class ClassGrades:
    key: Key
    answers_file: str
    rule: Rule
    answers: tuple[str, ...]  # the graded columns, in the CSV's order
    students: tuple[StudentGrade, ...]
    errors: tuple[InputError, ...]

    def score(self, student: StudentGrade) -> float:
        credit = {Outcome.RIGHT: 1.0, Outcome.SLIP: self.rule.slip_credit}
        return sum(credit.get(m.outcome, 0.0) for m in student.marks)

    @property
    def all_right(self) -> bool:
        return all(m.outcome is Outcome.RIGHT for s in self.students for m in s.marks)


# --- the class's answers -------------------------------------------------------------

MAX_STUDENTS = 100_000  # as rbdsolve variants' --count: a class is hundreds
MAX_COLUMNS = 1_000  # cells in the header: the largest exam's table has a few hundred answers
MAX_MARKS = 1_000_000  # answers graded in one run (students × answer columns): ~0.2 GB of marks
_LINE_END = re.compile(r"\r\n|\r|\n")  # a spreadsheet may end lines with CR alone (old Macs)
_VARIANT = re.compile(r"[0-9]{1,9}")  # ASCII digits only: '²' and '①' are digits to str.isdigit


def grade(key: Key, answers_file: str, rule: Rule = Rule(), budget: float | None = None) -> ClassGrades:
    """Every student's row graded against their variant (see the module docstring),
    within ``budget`` seconds of processor time (None: no limit; past it an
    UnsolvedError). More than MAX_STUDENTS rows, MAX_COLUMNS columns or MAX_MARKS
    answers is refused (an InputError) as soon as it is seen."""
    from rbdsolve.solvers.routes.budget import OutOfTime, within

    text = read_file(answers_file)
    try:
        with within(budget, "grading the class"):
            return _graded(key, answers_file, text, rule)
    except OutOfTime as exc:
        raise UnsolvedError(f"{answers_file}: {exc}") from None


def _graded(key: Key, answers_file: str, text: str, rule: Rule) -> ClassGrades:
    first = _LINE_END.split(text, 1)[0]
    semicolons = ";" in first and "," not in first  # a spreadsheet's CSV where the decimal mark is a comma
    errors: list[InputError] = []
    records = _records(text, ";" if semicolons else ",", answers_file, errors)
    line, cells = next(records, (1, None))
    if errors:  # the header itself could not be read
        raise errors[0]
    if cells is None:
        raise InputError("the answers file is empty: expected a header 'student,variant,ANSWER,…'",
                         Location(answers_file, 1, 1))
    header = _header(cells, key, answers_file, errors)
    answers = tuple(a for a in header.columns if a is not None)
    students = []
    for line, row in records:
        if not any(cell.strip() for cell in row):
            continue
        _within_limits(len(students) + 1, len(answers), Location(answers_file, line, 1))
        try:
            students.append(_student(row, line, header, key, rule, answers_file, errors, semicolons))
        except InputError as exc:
            errors.append(exc)
    return ClassGrades(key, answers_file, rule, answers, tuple(students), tuple(errors))


def _records(text: str, delimiter: str, file: str, errors: list[InputError]):
    """(the line a record starts on, its cells) for each record of the CSV, lines ended
    by LF, CRLF or CR alike; a record the csv module cannot read (a cell past its
    131,072-character limit) is one located error, and reading goes on after it."""
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter)
    start = 1
    while True:
        try:
            cells = next(reader)
        except StopIteration:
            return
        except csv.Error as exc:
            errors.append(InputError(_unreadable(exc), Location(file, start, 1)))
        else:
            yield start, cells
        start = reader.line_num + 1


def _unreadable(exc: csv.Error) -> str:
    if "field limit" in str(exc):
        return f"a cell is longer than {csv.field_size_limit():,} characters; the row is not graded"
    return f"this row cannot be read as CSV ({exc}); the row is not graded"


def _within_limits(students: int, columns: int, where: Location) -> None:
    if students > MAX_STUDENTS:
        raise InputError(f"more than {MAX_STUDENTS:,} students; the limit is {MAX_STUDENTS:,}: grade the class "
                         "in parts", where)
    if students * columns > MAX_MARKS:
        raise InputError(f"more than {MAX_MARKS:,} answers to grade ({columns:,} columns, {students:,} students "
                         "so far); grade the class in parts", where)


@dataclass(frozen=True)
class _Header:
    student: int
    variant: int
    columns: tuple[str | None, ...]  # per cell, the key's column it answers (None: not graded)


def _header(cells: list[str], key: Key, file: str, errors: list[InputError]) -> _Header:
    if len(cells) > MAX_COLUMNS:
        raise InputError(f"the header has {len(cells):,} columns; the limit is {MAX_COLUMNS:,}", Location(file, 1, 1))
    names = [c.strip() for c in cells]
    lower = [n.lower() for n in names]
    for needed in (STUDENT, VARIANT):
        if needed not in lower:
            raise InputError(f"the header has no '{needed}' column; it starts 'student,variant,' and then names "
                             f"the answers (e.g. {key.columns[0] if key.columns else 'omega1'})", Location(file, 1, 1))
    columns: list[str | None] = []
    known = [*key.columns, *key.kind_columns]
    for i, name in enumerate(names):
        if lower[i] in (STUDENT, VARIANT):
            columns.append(None)
            continue
        try:
            column = resolve(name, known, Location(file, 1, _column(cells, i)))
            if column in columns:
                raise InputError(f"'{clipped(name)}' is the same answer as an earlier column ({column})",
                                 Location(file, 1, _column(cells, i)))
            columns.append(column)
        except InputError as exc:
            errors.append(exc)
            columns.append(None)
    return _Header(lower.index(STUDENT), lower.index(VARIANT), tuple(columns))


def _column(cells: list[str], i: int) -> int:
    """The 1-based character column where cell ``i`` starts (for an unquoted header)."""
    return sum(len(c) + 1 for c in cells[:i]) + 1


def _student(row: list[str], line: int, header: _Header, key: Key, rule: Rule, file: str,
             errors: list[InputError], decimal_comma: bool) -> StudentGrade:
    where = Location(file, line, 1)
    if len(row) != len(header.columns):
        raise InputError(f"this row has {len(row)} cells, the header {len(header.columns)}; the row is not graded",
                         where)
    text = row[header.variant].strip()
    if not _VARIANT.fullmatch(text) or int(text) not in key.numbers:
        span = f"{min(key.numbers)} to {max(key.numbers)}" if key.numbers else "none"
        raise InputError(f"variant '{clipped(text)}' is not in {key.file} (its variants: {span}); the row is not "
                         "graded", Location(file, line, _column(row, header.variant)))
    variant = int(text)
    marks = []
    for i, column in enumerate(header.columns):
        if column is None:
            continue
        cell = row[i].strip().replace(",", ".") if decimal_comma else row[i].strip()
        try:
            marks.append(_mark(cell, column, variant, key, rule, Location(file, line, _column(row, i))))
        except InputError as exc:
            errors.append(exc)
            marks.append(Mark(column, row[i].strip(), None, Outcome.UNGRADED))
    return StudentGrade(row[header.student].strip(), variant, line, tuple(marks))


def _mark(given: str, column: str, variant: int, key: Key, rule: Rule, loc: Location) -> Mark:
    if column in key.kind_columns:
        return _word(given, column, key.kinds[variant][key.kind_columns.index(column)], loc)
    right = key.numbers[variant][key.columns.index(column)]
    if not given:
        return Mark(column, given, right, Outcome.BLANK)
    number = _number(given, column, loc)
    if right is None:
        return Mark(column, given, right, Outcome.UNGRADED)
    if rule.agrees(number, right):
        return Mark(column, given, right, Outcome.RIGHT)
    slips = slip_of(number, right, rule)
    return Mark(column, given, right, Outcome.SLIP if slips else Outcome.WRONG, slips)


def _number(text: str, column: str, loc: Location) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or text.lower().lstrip("+-") in ("inf", "infinity", "nan"):
        raise InputError(f"{column}: '{clipped(text)}' is not a number", loc)
    return value


def _word(given: str, column: str, right: str | None, loc: Location) -> Mark:
    if not given:
        return Mark(column, given, right, Outcome.BLANK)
    if right is None:
        return Mark(column, given, right, Outcome.UNGRADED)
    return Mark(column, given, right, Outcome.RIGHT if given.lower() == right else Outcome.WRONG)


# Each slip as the number it turns the key into (FACTOR_SLIPS: given = factor · key), the
# factors as floats once: float() of a sympy 2π is an evalf, ~0.1 ms, 11 of them per
# wrong answer made a class of 100,000 take minutes.
_FACTORS = tuple((float(factor), slips) for factor, slips in FACTOR_SLIPS)
_ROOTS = ((Slip.MISSING_ROOT, lambda k: k * k), (Slip.EXTRA_ROOT, lambda k: math.sqrt(k) if k >= 0 else math.nan))


def slip_of(given: float, right: float, rule: Rule) -> tuple[Slip, ...]:
    """The slips that turn ``right`` into ``given`` within the rule's tolerance, or ()."""
    for factor, slips in _FACTORS:
        if rule.agrees(given, factor * right):
            return slips
    for slip, turn in _ROOTS:
        for sign, signs in ((1.0, ()), (-1.0, (Slip.SIGN,))):
            wrong = sign * turn(right)
            if math.isfinite(wrong) and rule.agrees(given, wrong):
                return (*signs, slip)
    return ()


# --- what the class did, per answer --------------------------------------------------


@dataclass(frozen=True)
class Tally:
    """One answer across the class: how many of each outcome, and of each slip."""

    answer: str
    counts: dict[Outcome, int]
    slips: dict[str, int]  # 'sign', 'sign+two_pi' -> how many


def tallies(grades: ClassGrades) -> list[Tally]:
    out = []
    for answer in grades.answers:
        marks = [m for s in grades.students for m in s.marks if m.answer == answer]
        counts = Counter(m.outcome for m in marks)
        slips = Counter(m.word for m in marks if m.outcome is Outcome.SLIP)
        out.append(Tally(answer, {o: counts.get(o, 0) for o in Outcome}, dict(slips.most_common())))
    return out


def score_counts(grades: ClassGrades) -> list[tuple[float, int]]:
    """(score, how many students), best score first."""
    counts = Counter(grades.score(s) for s in grades.students)
    return sorted(counts.items(), reverse=True)
