"""Hostile class-grading input (issue 39): a class's answers CSV and a variants table
from outside, through ``rbdsolve grade variants.json answers.csv``.

The variants table here is written by hand (the JSON ``rbdsolve variants`` writes: its
columns, each row's variant, answers and kinds), so nothing is solved: the right answer
for each cell is the number the table holds. Every case must be exit code 0, 1 or 2
with one located line per problem, never a traceback or exit 3; a grades.csv written
from hostile names must open in a spreadsheet as text (no cell a formula, no control
character).
"""

from __future__ import annotations

import csv
import io
import json
import os
import threading

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.errors import InputError
from rbdsolve.problem import yamlnodes
from rbdsolve.render.spreadsheet import FORMULA_STARTS
from rbdsolve.teaching import grading
from rbdsolve.teaching.files import read_file

from conftest import spin

KEY = {"file": "p.yaml", "title": "t", "seed": 1, "fixed": {}, "parameters": ["m"],
       "columns": ["modes.frequencies[1]", "modes.frequencies[2]"], "kind_columns": ["modes.motions[1]"],
       "rows": [{"variant": n, "values": [n], "answers": [2.0 * n, 3.0 * n], "kinds": ["oscillation"]}
                for n in (1, 2, 3, 4)]}
HEADER = "student,variant,omega1,omega2,modes.motions[1]"
HOSTILE_NAMES = ["=cmd|' /C calc'!A0", "@SUM(1+1)", "+1+1", "-1+1", "\t=1+1", "\r=1+1", "=DDE(\"cmd\";\"/C calc\";\"x\")",
                 "a;=1+1", "x\x1b]0;PWN\x07\x1b[2J", "\u2212\u2212x", "\uff1d1+1", "\u202eevil", "x\x9b2J"]
NUMBER = __import__("re").compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?")


def write_key(folder, key=KEY, name="variants.json"):
    path = folder / name
    path.write_text(json.dumps(key), encoding="utf-8")
    return path


def a_class(folder, *rows: str, end: str = "\n"):
    """(the variants table KEY, an answers CSV of the header and ``rows``) in ``folder``."""
    answers = folder / "answers.csv"
    answers.write_text(end.join([HEADER, *rows]) + end, encoding="utf-8", newline="")
    return write_key(folder), answers


def grade(variants, answers, *options):
    return CliRunner().invoke(main, ["grade", str(variants), str(answers), *options])


def quoted(text: str) -> str:
    return '"' + text.replace('"', '""') + '"'


def assert_plain_text(path) -> list[list[str]]:
    """Every cell of a CSV reads as text in a spreadsheet: none begins as a formula
    unless it is a number, and none holds a control character; the rows, read back."""
    text = path.read_text(encoding="utf-8")
    assert not any(ch in text for ch in "\x1b\x07\x9b\u202e\r\t"), repr(text)
    rows = list(csv.reader(io.StringIO(text)))
    for row in rows:
        for cell in row:
            assert cell[:1] not in FORMULA_STARTS or NUMBER.fullmatch(cell), cell
    semicolons = list(csv.reader(io.StringIO(text), delimiter=";"))  # as a spreadsheet splitting on ';' reads it
    for row in semicolons:
        for cell in row:
            assert cell.lstrip('"')[:1] not in FORMULA_STARTS or NUMBER.fullmatch(cell), cell
    return rows


def test_hostile_student_names_land_as_text_in_grades_csv(tmp_path) -> None:
    variants = write_key(tmp_path)
    answers = tmp_path / "answers.csv"
    answers.write_text(HEADER + "\n" + "".join(f"{quoted(name)},1,2,3,oscillation\n" for name in HOSTILE_NAMES),
                       encoding="utf-8", newline="")
    grades = tmp_path / "grades.csv"
    result = grade(variants, answers, "-o", str(grades))
    assert result.exit_code == 0, result.output
    rows = assert_plain_text(grades)
    names = [row[0] for row in rows[1:]]
    assert names[:3] == ["'=cmd|' /C calc'!A0", "'@SUM(1+1)", "'+1+1"]
    assert "'=1+1" in names  # the tab and CR before it were stripped as space; the rest kept
    assert "x\\x1b]0;PWN\\x07\\x1b[2J" in names and "'\u2212\u2212x" in names
    assert all(row[2:] == ["3", "3", "right", "right", "right"] for row in rows[1:])
    graded_json = tmp_path / "grades.json"
    assert grade(variants, answers, "-o", str(graded_json)).exit_code == 0
    text = graded_json.read_text(encoding="utf-8")
    assert not any(ch in text for ch in "\x1b\x07\x9b\u202e")
    assert [s["student"] for s in json.loads(text)["students"]][8] == "x\x1b]0;PWN\x07\x1b[2J"  # escaped, not lost


def test_hostile_column_names_in_the_variants_table(tmp_path) -> None:
    key = {**KEY, "columns": ["=1+1", "x\x1b]0;PWN\x07"]}
    variants = write_key(tmp_path, key)
    answers = tmp_path / "answers.csv"
    answers.write_text(f"student,variant,=1+1,{quoted(key['columns'][1])}\nanna,1,2,3\n", encoding="utf-8")
    grades = tmp_path / "grades.csv"
    result = grade(variants, answers, "-o", str(grades))
    assert result.exit_code == 0, result.output
    assert "\x1b" not in result.output and "x\\x1b]0;PWN\\x07" in result.output  # the terminal's table
    assert assert_plain_text(grades)[0][4:] == ["'=1+1", "x\\x1b]0;PWN\\x07"]


@pytest.mark.parametrize(("cell", "message"), [
    ("²", "variant '²' is not in"),
    ("①", "variant '①' is not in"),
    ("9" * 5000, "variant '" + "9" * 60 + "… (5,000 characters)' is not in"),
    ("-1", "variant '-1' is not in"),
])
def test_a_variant_cell_that_is_no_variant(tmp_path, cell: str, message: str) -> None:
    variants, answers = a_class(tmp_path, f"anna,{cell},2,3,oscillation", "bert,2,4,6,oscillation")
    result = grade(variants, answers)
    assert result.exit_code == 2
    assert result.stderr.startswith(f"{answers}:2:6: {message}"), result.stderr
    assert len(result.stderr.splitlines()) == 1 and "4 to" not in result.stderr
    assert "2 students" not in result.output and "1 students" in result.output  # bert graded


def test_a_number_cell_of_5000_digits(tmp_path) -> None:
    variants, answers = a_class(tmp_path, f"anna,1,{'9' * 5000},3,oscillation")
    result = grade(variants, answers)
    assert result.exit_code == 2
    assert result.stderr == f"{answers}:2:8: modes.frequencies[1]: '{'9' * 60}… (5,000 characters)' is not a number\n"


def test_a_cell_past_the_csv_field_limit(tmp_path) -> None:
    variants, answers = a_class(tmp_path, f"{'x' * 140_000},1,2,3,oscillation", "bert,2,4,6,oscillation")
    result = grade(variants, answers)
    assert result.exit_code == 2
    assert result.stderr == f"{answers}:2:1: a cell is longer than 131,072 characters; the row is not graded\n"
    assert "1 students" in result.output  # the next row is graded


@pytest.mark.parametrize("end", ["\r", "\r\n", "\n"])
def test_any_line_end(tmp_path, end: str) -> None:
    variants, answers = a_class(tmp_path, "anna,1,2,3,oscillation", "bert,2,4,1,oscillation", "carl,x,1,1,", end=end)
    result = grade(variants, answers)
    assert result.exit_code == 2
    assert result.stderr == f"{answers}:4:6: variant 'x' is not in {variants} (its variants: 1 to 4); the row " \
                            "is not graded\n"
    assert "2 students" in result.output


@pytest.mark.parametrize(("number", "shown"), [
    ("1" + "0" * 400, "the number " + "1" + "0" * 59 + "… (401 characters) is out of range"),
    ("9" * 5000, "the number " + "9" * 60 + "… (5,000 characters) is out of range"),
    ("1e999", "the number 1e999 is out of range"),
    ("-1e999", "the number -1e999 is out of range"),
])
def test_a_number_out_of_range_in_the_variants_table(tmp_path, number: str, shown: str) -> None:
    text = json.dumps(KEY, indent=1)
    text = text.replace("2.0,", f"{number},", 1)
    variants = tmp_path / "variants.json"
    variants.write_text(text, encoding="utf-8")
    line = text[: text.index(number)].count("\n") + 1
    answers = tmp_path / "answers.csv"
    answers.write_text(f"{HEADER}\nanna,1,2,3,oscillation\n", encoding="utf-8")
    result = grade(variants, answers)
    assert result.exit_code == 2
    column = text.index(number) - text.rfind("\n", 0, text.index(number))
    assert result.stderr.startswith(f"{variants}:{line}:{column}: {shown}"), result.stderr


def test_too_many_students_is_refused_at_the_first_row_past_the_limit(tmp_path, monkeypatch) -> None:
    monkeypatch.setattr(grading, "MAX_STUDENTS", 3)
    variants, answers = a_class(tmp_path, *["s,1,2,3,oscillation"] * 5)
    result = grade(variants, answers)
    assert result.exit_code == 2
    assert result.stderr == f"{answers}:5:1: more than 3 students; the limit is 3: grade the class in parts\n"


def test_too_many_answers_is_refused(tmp_path, monkeypatch) -> None:
    monkeypatch.setattr(grading, "MAX_MARKS", 5)
    variants, answers = a_class(tmp_path, *["s,1,2,3,oscillation"] * 2)
    result = grade(variants, answers)
    assert result.exit_code == 2
    assert result.stderr.startswith(f"{answers}:3:1: more than 5 answers to grade (3 columns, 2 students so far)")


def test_a_header_of_too_many_columns(tmp_path) -> None:
    variants = write_key(tmp_path)
    answers = tmp_path / "answers.csv"
    answers.write_text(HEADER + ",x" * 2000 + "\n", encoding="utf-8")
    result = grade(variants, answers)
    assert result.exit_code == 2
    assert result.stderr == f"{answers}:1:1: the header has 2,005 columns; the limit is 1,000\n"


def test_a_class_past_its_budget_stops(tmp_path, monkeypatch) -> None:
    """Grading is bounded by --budget (processor time): a grader that never ends (a
    CPU-spinning stand-in for a row) is stopped, one line, exit code 1."""
    variants, answers = a_class(tmp_path, "anna,1,2,3,oscillation")
    monkeypatch.setattr(grading, "_student", lambda *args: spin(float("inf")))
    result = grade(variants, answers, "--budget", "0.5")
    assert result.exit_code == 1
    assert result.stderr == f"{answers}: grading the class ran out of its 0.5 s budget (--budget to change it)\n"


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
@pytest.mark.parametrize("which", ["answers", "variants"])
def test_a_fifo_nobody_writes_is_not_waited_for(tmp_path, monkeypatch, which: str) -> None:
    monkeypatch.setattr(yamlnodes, "READ_SECONDS", 0.3)
    variants, answers = a_class(tmp_path, "anna,1,2,3,oscillation")
    fifo = tmp_path / ("ans.csv" if which == "answers" else "v.json")
    os.mkfifo(fifo)
    result = grade(*((variants, fifo) if which == "answers" else (fifo, answers)))
    assert result.exit_code == 2
    assert result.stderr.startswith(f"{fifo}:1:1: no end of file within 0.3 s")

    def writer() -> None:
        with open(fifo, "w", encoding="utf-8") as handle:
            handle.write(HEADER + "\nanna,1,2,3,oscillation\n" if which == "answers" else json.dumps(KEY))

    monkeypatch.setattr(yamlnodes, "READ_SECONDS", 60.0)
    thread = threading.Thread(target=writer)
    thread.start()
    result = grade(*((variants, fifo) if which == "answers" else (fifo, answers)))
    thread.join()
    assert result.exit_code == 0, result.output  # a FIFO that is written is read


def test_a_path_with_a_nul_character() -> None:
    """(A command line cannot hold NUL; a script calling the library can.)"""
    with pytest.raises(InputError, match=r"^no such file: ans\\x00.csv$"):
        read_file("ans\x00.csv")


@pytest.mark.parametrize("which", ["variants", "answers"])
def test_an_output_that_is_an_input_names_which(tmp_path, which: str) -> None:
    variants, answers = a_class(tmp_path, "anna,1,2,3,oscillation")
    target, what = (variants, "the variants table") if which == "variants" else (answers, "the class's answers")
    before = target.read_bytes()
    result = grade(variants, answers, "-o", target)  # it said "one of the problem files" of either
    assert result.stderr == f"-o {target}: this is {what}; choose another output\n"
    assert result.exit_code == 2 and target.read_bytes() == before
