"""CSV that a spreadsheet opens as plain text: a class's grades, a variants table.

Names in these files come from outside (a student's name in the answers CSV, a column
of a hand-edited variants.json), and a spreadsheet runs a cell as a formula when it
begins with ``=``, ``+``, ``-`` or ``@`` — or with a tab or a carriage return before one
— (``=cmd|' /C calc'!A0``, ``=DDE(…)``, ``@SUM(1+1)``). Each such cell that is not a
number is written with a leading apostrophe, the mark Excel, LibreOffice and Google
Sheets read as "this cell is text" (OWASP, CSV Injection). The full-width forms
(＝ ＋ － ＠) and the minus sign − are treated alike.

Control characters are written escaped (``\\x1b``: errors.printable), so a cell is one
line of plain text. A cell holding a comma, a semicolon or a double quote is quoted
(the quotes inside doubled): a spreadsheet that splits on semicolons (where the decimal
mark is a comma) then reads it as one cell too, and no formula starts inside it.
"""

from __future__ import annotations

import re
from typing import Iterable

from rbdsolve.errors import printable

FORMULA_STARTS = frozenset("=+-@\t\r\u2212\uff1d\uff0b\uff0d\uff20")
_NUMBER = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?")
_QUOTED = frozenset(',;"')


def cell(value: object) -> str:
    """One cell's text: a number as it is, text escaped and neutralised (module docstring)."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return str(value)
    raw = str(value)
    text = printable(raw)
    if (raw[:1] in FORMULA_STARTS or text[:1] in FORMULA_STARTS) and not _NUMBER.fullmatch(raw):
        text = "'" + text
    if _QUOTED.intersection(text):
        text = '"' + text.replace('"', '""') + '"'
    return text


def row(values: Iterable[object]) -> str:
    """One line of comma-separated cells."""
    return ",".join(cell(v) for v in values) + "\n"


def table(rows: Iterable[Iterable[object]]) -> str:
    """Rows of cells as CSV text (the first row the header)."""
    return "".join(row(r) for r in rows)
