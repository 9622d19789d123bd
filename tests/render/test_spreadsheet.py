"""CSV cells a spreadsheet shows as text (render/spreadsheet.py) and JSON text with no
raw control character (render/json_text.py): issue 39, formula injection."""

from __future__ import annotations

import csv
import io
import json

import pytest

from rbdsolve.render.json_text import strict_json
from rbdsolve.render.spreadsheet import cell, row


@pytest.mark.parametrize(("value", "written"), [
    ("=cmd|' /C calc'!A0", "'=cmd|' /C calc'!A0"),
    ("@SUM(1+1)", "'@SUM(1+1)"),
    ("+1+1", "'+1+1"),
    ("-1+1", "'-1+1"),
    ("\t=1+1", "'\\x09=1+1"),
    ("\r=1+1", "'\\x0d=1+1"),
    ("\u22121", "'\u22121"),
    ("\uff1d1+1", "'\uff1d1+1"),
    ("=DDE(\"cmd\";\"/C calc\";\"A\")", "\"'=DDE(\"\"cmd\"\";\"\"/C calc\"\";\"\"A\"\")\""),
    ("a;=1+1", "\"a;=1+1\""),  # quoted: a spreadsheet that splits on ';' keeps it one cell
    ("a,b", "\"a,b\""),
    ("x\x1b]0;PWN\x07\x1b[2J", "\"x\\x1b]0;PWN\\x07\\x1b[2J\""),
    ("line\nbreak", "line\\x0abreak"),
    ("-2.376", "-2.376"),  # a number stays a number
    ("+1e-5", "+1e-5"),
    ("anna", "anna"),
    ("", ""),
    (-3, "-3"),
    (0.5, "0.5"),
])
def test_a_cell(value, written: str) -> None:
    assert cell(value) == written


def test_a_row_reads_back_as_the_cells_written() -> None:
    values = ["=1+1", "a;b", 'say "hi"', "plain", 4]
    assert next(csv.reader(io.StringIO(row(values)))) == ["'=1+1", "a;b", 'say "hi"', "plain", "4"]


def test_json_text_escapes_what_a_terminal_acts_on_and_reads_back_the_same() -> None:
    body = {"name": "x\x1b]0;PWN\x07\x9b2J\u202eevil\u2028\x7f\ud800", "n": 1.5}
    text = strict_json(body)
    assert text.endswith("\n") and "é" in strict_json({"x": "é"})  # UTF-8, not \\u00e9
    assert not any(ch in text for ch in "\x1b\x07\x9b\u202e\u2028\x7f\ud800")
    assert json.loads(text) == body
    text.encode("utf-8")  # a lone surrogate no longer stops the write
    with pytest.raises(ValueError):
        strict_json({"x": float("nan")})
