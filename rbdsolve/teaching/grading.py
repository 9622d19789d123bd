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
table does not have, a cell that is not a number) is one message each; the rest is
still graded.
"""

from __future__ import annotations

import csv
import io
import json
import math
from collections import Counter
from dataclasses import dataclass
from enum import Enum

from rbdsolve.errors import InputError, Location
from rbdsolve.teaching.addresses import resolve
from rbdsolve.teaching.files import read_file
from rbdsolve.teaching.key_csv import looks_like_csv, read_key_csv
from rbdsolve.teaching.verdicts import FACTOR_SLIPS, Slip

STUDENT, VARIANT = "student", "variant"


@dataclass(frozen=True)
class Key:
    """The variants table as read back: per variant number, its numbers and kinds."""

    file: str
    problem: str
    columns: tuple[str, ...]
    kind_columns: tuple[str, ...]
    numbers: dict[int, tuple[float | None, ...]]
    kinds: dict[int, tuple[str | None, ...]]


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
        return abs(given - key) <= self.tolerance(key)


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


# --- the key -------------------------------------------------------------------------


def read_key(path: str) -> Key:
    """The table of ``rbdsolve variants``, its JSON or its CSV (teaching/key_csv.py); an
    InputError that says which file to give for anything else."""
    text = read_file(path)
    if looks_like_csv(text):
        return read_key_csv(path, text, Key)
    if text.lstrip("\ufeff \t\r\n").lower().startswith(STUDENT):
        raise InputError("this is a class's answers ('student,variant,…'); give the variants table first: "
                         f"rbdsolve grade variants.csv {path}", Location(path, 1, 1))
    try:
        body = json.loads(text, parse_constant=_refuse_constant)
    except json.JSONDecodeError as exc:
        raise InputError(f"not JSON: {exc.msg}", Location(path, exc.lineno, exc.colno)) from None
    except ValueError as exc:  # NaN or Infinity, refused by _refuse_constant
        raise InputError(f"not strict JSON: {exc}", Location(path, 1, 1)) from None
    except RecursionError:
        raise InputError("the JSON is nested too deeply", Location(path, 1, 1)) from None
    if not isinstance(body, dict) or not isinstance(body.get("rows"), list) or "columns" not in body:
        raise InputError("not a variants table (write one with: rbdsolve variants PROBLEM -o variants.csv, "
                         "or -o variants.json)",
                         Location(path, 1, 1))
    columns = _strings(body, "columns", path)
    kind_columns = _strings(body, "kind_columns", path)
    numbers, kinds = {}, {}
    for i, row in enumerate(body["rows"]):
        variant, values, words = _row(row, i, len(columns), len(kind_columns), path)
        numbers[variant], kinds[variant] = values, words
    return Key(path, str(body.get("file", "")), columns, kind_columns, numbers, kinds)


def _refuse_constant(name: str) -> float:
    raise ValueError(f"{name} is not a number in strict JSON")


def _strings(body: dict, key: str, path: str) -> tuple[str, ...]:
    value = body.get(key, [])
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise InputError(f"'{key}' must be a list of names", Location(path, 1, 1, (key,)))
    return tuple(value)


def _row(row: object, i: int, width: int, kind_width: int, path: str):
    where = Location(path, 1, 1, ("rows", i))
    if not isinstance(row, dict) or not isinstance(row.get("variant"), int) or isinstance(row.get("variant"), bool):
        raise InputError("expected {\"variant\": N, \"answers\": [...]}", where)
    values, words = row.get("answers"), row.get("kinds", [None] * kind_width)
    if not isinstance(values, list) or len(values) != width or not all(
            v is None or (isinstance(v, (int, float)) and not isinstance(v, bool)) for v in values):
        raise InputError(f"'answers' must be {width} numbers (or null), one per column", where)
    if not isinstance(words, list) or len(words) != kind_width or not all(w is None or isinstance(w, str) for w in words):
        raise InputError(f"'kinds' must be {kind_width} words (or null), one per kind column", where)
    return row["variant"], tuple(None if v is None else float(v) for v in values), tuple(words)


# --- the class's answers -------------------------------------------------------------


def grade(key: Key, answers_file: str, rule: Rule = Rule()) -> ClassGrades:
    """Every student's row graded against their variant (see the module docstring)."""
    text = read_file(answers_file)
    first = text.split("\n", 1)[0]
    semicolons = ";" in first and "," not in first  # a spreadsheet's CSV where the decimal mark is a comma
    rows = list(csv.reader(io.StringIO(text), delimiter=";" if semicolons else ","))
    if not rows:
        raise InputError("the answers file is empty: expected a header 'student,variant,ANSWER,…'",
                         Location(answers_file, 1, 1))
    errors: list[InputError] = []
    header = _header(rows[0], key, answers_file, errors)
    students = []
    for line, row in enumerate(rows[1:], start=2):
        if not any(cell.strip() for cell in row):
            continue
        try:
            students.append(_student(row, line, header, key, rule, answers_file, errors, semicolons))
        except InputError as exc:
            errors.append(exc)
    answers = tuple(a for a in header.columns if a is not None)
    return ClassGrades(key, answers_file, rule, answers, tuple(students), tuple(errors))


@dataclass(frozen=True)
class _Header:
    student: int
    variant: int
    columns: tuple[str | None, ...]  # per cell, the key's column it answers (None: not graded)


def _header(cells: list[str], key: Key, file: str, errors: list[InputError]) -> _Header:
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
                raise InputError(f"'{name}' is the same answer as an earlier column ({column})",
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
    if not text.isdigit() or int(text) not in key.numbers:
        span = f"{min(key.numbers)} to {max(key.numbers)}" if key.numbers else "none"
        raise InputError(f"variant '{text}' is not in {key.file} (its variants: {span}); the row is not graded",
                         Location(file, line, _column(row, header.variant)))
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
        raise InputError(f"{column}: '{text}' is not a number", loc)
    return value


def _word(given: str, column: str, right: str | None, loc: Location) -> Mark:
    if not given:
        return Mark(column, given, right, Outcome.BLANK)
    if right is None:
        return Mark(column, given, right, Outcome.UNGRADED)
    return Mark(column, given, right, Outcome.RIGHT if given.lower() == right else Outcome.WRONG)


# Each slip as the number it turns the key into (FACTOR_SLIPS: given = factor · key).
_ROOTS = ((Slip.MISSING_ROOT, lambda k: k * k), (Slip.EXTRA_ROOT, lambda k: math.sqrt(k) if k >= 0 else math.nan))


def slip_of(given: float, right: float, rule: Rule) -> tuple[Slip, ...]:
    """The slips that turn ``right`` into ``given`` within the rule's tolerance, or ()."""
    for factor, slips in FACTOR_SLIPS:
        if rule.agrees(given, float(factor) * right):
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
