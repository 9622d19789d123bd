"""A teacher's grading (teaching/grading.py, ``rbdsolve grade variants.json answers.csv``).

A class of 120 is built here from ``rbdsolve variants`` on the seed exam's problem 1:
each student's right answers come from the exam's worked solution at their variant's
values (λ₁ = 24g/(25r), λ₂ = 2g/r, ω = √λ, M₁₁ = 7/4 m r², K₂₂ = m g r/2, the first
mode's shape (1, 4/3), both modes oscillations), written to 4 significant figures as a
student would; then errors are seeded — a sign, a factor 2, f for ω, degrees, a
missing or an extra square root, a plainly wrong number, a blank — and each must be
found as seeded, and no right answer marked wrong. A seeded value that the test's own
table of slips finds ambiguous (within 1.5 % of another slip's value) is drawn again.
"""

from __future__ import annotations

import csv
import io
import json
import math
import random
import time

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import SEED

P1 = SEED / "p1-two-rods.yaml"
STUDENTS = 120
COLUMNS = ("omega1", "omega2", "modes.eigenvalues[1]", "modes.M[1][1]", "modes.K[2][2]", "modes.shapes[1][2]",
           "modes.motions[1]")
PATHS = ("modes.frequencies[1]", "modes.frequencies[2]", *COLUMNS[2:])  # omega1, omega2 as the key names them

# The test's own table of slips: the value each turns the right one k into.
SLIPS = {
    "sign": lambda k: -k,
    "factor_2": lambda k: 2 * k,
    "two_pi": lambda k: k / (2 * math.pi),
    "degrees": lambda k: k * 180 / math.pi,
    "missing_root": lambda k: k * k,
    "extra_root": lambda k: math.sqrt(k),
}
OTHERS = (lambda k: k, lambda k: k / 2, lambda k: 2 * math.pi * k, lambda k: -2 * k, lambda k: -k / 2,
          lambda k: -k / (2 * math.pi), lambda k: -k * 180 / math.pi, lambda k: -k * k, lambda k: -math.sqrt(k))
ERRORS = (*SLIPS, "wrong", "blank")


def exam_answers(m: float, r: float, g: float) -> dict[str, float | str]:
    """The exam's answers at these values (shared/seeds/000_…txt, problem 1)."""
    lam1, lam2 = 24 * g / (25 * r), 2 * g / r
    return {"omega1": math.sqrt(lam1), "omega2": math.sqrt(lam2), "modes.eigenvalues[1]": lam1,
            "modes.M[1][1]": 7 / 4 * m * r**2, "modes.K[2][2]": m * g * r / 2, "modes.shapes[1][2]": 4 / 3,
            "modes.motions[1]": "oscillation"}


def _unambiguous(value: float, right: float, meant) -> bool:
    turns = [f for f in (*SLIPS.values(), *OTHERS) if f is not meant]
    return all(abs(value - f(right)) > 0.015 * abs(f(right)) for f in turns)


def seeded(right: float | str, rng: random.Random) -> tuple[str, str]:
    """(the cell, the outcome the grader must give): an error drawn until unambiguous."""
    if isinstance(right, str):
        return rng.choice([("growth", "wrong"), ("", "blank")])
    while True:
        error = rng.choice(ERRORS)
        if error == "blank":
            return "", "blank"
        turn = SLIPS.get(error, lambda k: k * rng.choice((1.37, 0.61, 3.3)))
        value = turn(right)
        if _unambiguous(value, right, SLIPS.get(error)):
            return f"{value:.4g}", error


@pytest.fixture(scope="module")
def table(tmp_path_factory):
    folder = tmp_path_factory.mktemp("class")
    path = folder / "variants.json"
    result = CliRunner().invoke(main, ["variants", str(P1), "--count", str(STUDENTS), "--seed", "11",
                                       "--verify", "1", "-o", str(path)])
    assert result.exit_code == 0, result.output
    return folder, path, json.loads(path.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def seeded_class(table):
    """The answers CSV and what each cell must be graded as."""
    folder, _, body = table
    rng = random.Random(25)
    m_, r_, g_ = (body["parameters"].index(p) for p in ("m", "r", "g"))
    lines, expected = [",".join(("student", "variant", *COLUMNS))], {}
    for n, row in enumerate(body["rows"], start=1):
        values = row["values"]
        right = exam_answers(values[m_], values[r_], values[g_])
        cells, outcomes = [], []
        for column in COLUMNS:
            if rng.random() < 0.2:
                cell, outcome = seeded(right[column], rng)
            else:
                cell = right[column] if isinstance(right[column], str) else f"{right[column]:.4g}"
                outcome = "right"
            cells.append(cell)
            outcomes.append(outcome)
        student = f"s{n:03d}"
        lines.append(",".join((student, str(row["variant"]), *cells)))
        expected[student] = outcomes
    path = folder / "answers.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path, expected


def graded(table, answers, *options: str):
    folder, variants, _ = table
    out = folder / "grades.csv"
    start = time.perf_counter()
    result = CliRunner().invoke(main, ["grade", str(variants), str(answers), "-o", str(out), *options])
    seconds = time.perf_counter() - start
    rows = list(csv.DictReader(io.StringIO(out.read_text(encoding="utf-8")))) if out.exists() else []
    out.unlink(missing_ok=True)
    return result, rows, seconds


def test_every_seeded_error_is_found_and_no_right_answer_is_marked_wrong(table, seeded_class) -> None:
    answers, expected = seeded_class
    result, rows, seconds = graded(table, answers)
    print(f"\ngraded {STUDENTS} students in {seconds:.3f} s")  # measured, not asserted
    assert result.exit_code == 1, result.output
    assert len(rows) == STUDENTS
    for row in rows:
        assert [row[p] for p in PATHS] == expected[row["student"]], row["student"]
        assert float(row["score"]) == expected[row["student"]].count("right")
    seeded_kinds = {o for outcomes in expected.values() for o in outcomes} - {"right"}
    assert seeded_kinds == {*ERRORS}  # every kind of error was seeded at least once


def test_the_summary_counts_the_class_per_answer(table, seeded_class) -> None:
    answers, expected = seeded_class
    folder, variants, _ = table
    result = CliRunner().invoke(main, ["grade", str(variants), str(answers), "--format", "json"])
    body = json.loads(result.stdout)
    for i, tally in enumerate(body["summary"]):
        outcomes = [o[i] for o in expected.values()]
        assert tally["answer"] == PATHS[i]
        assert tally["right"] == outcomes.count("right")
        assert tally["blank"] == outcomes.count("blank")
        assert tally["wrong"] == outcomes.count("wrong")
        assert sum(tally["slips"].values()) == tally["slip"] == sum(o in SLIPS for o in outcomes)
    text = CliRunner().invoke(main, ["grade", str(variants), str(answers)]).stdout
    assert "modes.frequencies[1]" in text and "scores (students):" in text


def test_a_slip_may_earn_part_of_a_mark(table, seeded_class) -> None:
    answers, expected = seeded_class
    result, rows, _ = graded(table, answers, "--slip-credit", "0.5")
    for row in rows:
        outcomes = expected[row["student"]]
        assert float(row["score"]) == outcomes.count("right") + 0.5 * sum(o in SLIPS for o in outcomes)


def test_significant_figures(table) -> None:
    """Three significant figures, right to one unit in the third: every exam answer
    written to 3 figures is right; with 5 figures asked, most of them are not."""
    folder, variants, body = table
    m_, r_, g_ = (body["parameters"].index(p) for p in ("m", "r", "g"))
    lines = ["student,variant," + ",".join(COLUMNS[:-1])]
    for row in body["rows"]:
        right = exam_answers(*(row["values"][i] for i in (m_, r_, g_)))
        lines.append(f"s{row['variant']},{row['variant']}," + ",".join(f"{right[c]:.3g}" for c in COLUMNS[:-1]))
    path = folder / "three-figures.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    assert graded(table, path, "--sig-figs", "3")[0].exit_code == 0
    result, rows, _ = graded(table, path, "--sig-figs", "5")
    assert result.exit_code == 1
    assert sum(row[p] == "wrong" for row in rows for p in PATHS[:-1]) > STUDENTS


def test_malformed_rows_are_one_message_each_and_the_rest_is_graded(table, seeded_class) -> None:
    answers, expected = seeded_class
    folder, variants, _ = table
    bad = folder / "bad.csv"
    text = answers.read_text(encoding="utf-8")
    bad.write_text(text + "late,3,1,2\n" + "ghost,999,1,2,3,4,5,6,stable\n" + "typo,4,four,1,2,3,4,5,oscillation\n",
                   encoding="utf-8")
    result, rows, _ = graded(table, bad)
    assert result.exit_code == 2
    messages = result.stderr.strip().splitlines()
    assert len(messages) == 3, messages
    assert messages[0].startswith(f"{bad}:{STUDENTS + 2}:1: this row has 4 cells, the header 9")
    assert f"{bad}:{STUDENTS + 3}:7: variant '999' is not in" in messages[1]
    assert messages[2] == f"{bad}:{STUDENTS + 4}:8: modes.frequencies[1]: 'four' is not a number"
    assert len(rows) == STUDENTS + 1  # the row with a bad cell is graded but for that cell
    assert rows[-1]["modes.frequencies[1]"] == "ungraded"
    assert "Traceback" not in result.output


@pytest.mark.parametrize(("header", "message"), [
    ("student,variant,omega9", "no answer is called 'omega9'"),
    ("student,variant,modes.frequencies[0]", "indices count from 1"),
    ("name,variant,omega1", "the header has no 'student' column"),
])
def test_a_bad_header(table, header: str, message: str) -> None:
    folder, variants, _ = table
    path = folder / "header.csv"
    path.write_text(header + "\ns1,1,2.5\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["grade", str(variants), str(path)])
    assert result.exit_code == 2
    assert message in result.stderr


def test_not_a_variants_table(tmp_path) -> None:
    path = tmp_path / "x.json"
    path.write_text('{"schema": 1, "results": []}', encoding="utf-8")
    answers = tmp_path / "a.csv"
    answers.write_text("student,variant,omega1\ns,1,1\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["grade", str(path), str(answers)])
    assert result.exit_code == 2
    assert "not a variants table (write one with: rbdsolve variants" in result.stderr
    path.write_text('{"columns": [], "rows": [NaN]}', encoding="utf-8")
    result = CliRunner().invoke(main, ["grade", str(path), str(answers)])
    assert result.exit_code == 2 and "NaN is not a number in strict JSON" in result.stderr


def test_a_spreadsheets_csv_with_semicolons_and_decimal_commas(table) -> None:
    folder, variants, body = table
    m_, r_, g_ = (body["parameters"].index(p) for p in ("m", "r", "g"))
    row = body["rows"][0]
    right = exam_answers(*(row["values"][i] for i in (m_, r_, g_)))
    path = folder / "semicolons.csv"
    path.write_text(f"student;variant;omega1;omega2\nanna;1;{right['omega1']:.4f};{-right['omega2']:.4f}\n"
                    .replace(".", ","), encoding="utf-8")
    result, rows, _ = graded(table, path)
    assert result.exit_code == 1, result.output
    assert [rows[0][p] for p in PATHS[:2]] == ["right", "sign"]


def test_the_output_never_overwrites_an_input(table, seeded_class) -> None:
    answers, _ = seeded_class
    folder, variants, _ = table
    before = answers.read_text(encoding="utf-8")
    result = CliRunner().invoke(main, ["grade", str(variants), str(answers), "-o", str(answers)])
    assert result.exit_code == 2 and "choose another output" in result.stderr
    assert answers.read_text(encoding="utf-8") == before


def test_an_answers_file_that_is_not_text(table) -> None:
    folder, variants, _ = table
    path = folder / "binary.csv"
    path.write_bytes(b"student,variant\x00\xff\n")
    result = CliRunner().invoke(main, ["grade", str(variants), str(path)])
    assert result.exit_code == 2 and f"{path}:1:1: this is a binary file, not text" in result.stderr


@pytest.mark.parametrize("cell", ["nan", "inf", "-Infinity", "1e999", "4.3.8", "0x10"])
def test_a_cell_that_is_not_a_number(table, cell: str) -> None:
    folder, variants, _ = table
    path = folder / "cell.csv"
    path.write_text(f"student,variant,omega1\ns1,1,{cell}\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["grade", str(variants), str(path)])
    assert result.exit_code == 2
    assert result.stderr == f"{path}:2:6: modes.frequencies[1]: '{cell}' is not a number\n"


def test_the_variants_csv_grades_the_class_as_the_json_does(table, seeded_class) -> None:
    """The same draw written as CSV (issue 41, item 3): every seeded error found and no
    right answer marked wrong, as with the JSON; the answers CSV given first is one
    message that says which file to give."""
    answers, expected = seeded_class
    folder, _, _ = table
    variants_csv = folder / "variants.csv"
    result = CliRunner().invoke(main, ["variants", str(P1), "--count", str(STUDENTS), "--seed", "11",
                                       "-o", str(variants_csv)])
    assert result.exit_code == 0, result.output
    out = folder / "grades-from-csv.csv"
    result = CliRunner().invoke(main, ["grade", str(variants_csv), str(answers), "-o", str(out)])
    assert result.exit_code == 1, result.output
    rows = list(csv.DictReader(io.StringIO(out.read_text(encoding="utf-8"))))
    assert len(rows) == STUDENTS
    for row in rows:
        assert [row[p] for p in PATHS] == expected[row["student"]], row["student"]
    result = CliRunner().invoke(main, ["grade", str(answers), str(answers)])
    assert result.exit_code == 2
    assert "this is a class's answers ('student,variant,…'); give the variants table first" in result.stderr
