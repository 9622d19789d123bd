"""The variants table as the CSV ``rbdsolve variants -o variants.csv`` writes, read back
as a grading key (teaching/grading.Key), so that a teacher grades from either file.

The header is ``variant, seed, PARAMETER…, ANSWER…, KIND…`` (render/variants.py): a
parameter's name has no '.', an answer's column always has one (``modes.frequencies[1]``);
a kind column (a stability, a motion) is one whose cells are words. A row is one variant:
its number, the seed, the parameter values, then the numbers (an empty cell where an
answer has no number) and the words. A spreadsheet may have saved it with ';' between
cells and decimal commas.
"""

from __future__ import annotations

import csv
import io
import math

from rbdsolve.errors import InputError, Location

VARIANT, SEED = "variant", "seed"


def looks_like_csv(text: str) -> bool:
    """A CSV variants table starts with its header's 'variant' cell."""
    return text.lstrip("\ufeff \t\r\n").lower().startswith(VARIANT)


def read_key_csv(path: str, text: str, key_type):
    """The key of a CSV variants table; an InputError naming the cell otherwise."""
    first = text.split("\n", 1)[0]
    semicolons = ";" in first and "," not in first
    rows = [r for r in csv.reader(io.StringIO(text.lstrip("\ufeff")), delimiter=";" if semicolons else ",")
            if any(c.strip() for c in r)]
    header = [c.strip() for c in rows[0]]
    if header[:2] != [VARIANT, SEED]:
        raise InputError("not a variants table: expected the header 'variant,seed,…' that rbdsolve variants "
                         "-o variants.csv writes", Location(path, 1, 1))
    answers = [i for i, name in enumerate(header) if i >= 2 and "." in name]
    body = rows[1:]
    words = {i for i in answers if any(not _is_number(r[i], semicolons) for r in body if i < len(r) and r[i].strip())}
    numeric = [i for i in answers if i not in words]
    kinds = [i for i in answers if i in words]
    numbers, named = {}, {}
    for line, row in enumerate(body, start=2):
        if len(row) != len(header):
            raise InputError(f"a row of {len(row)} cells under a header of {len(header)}", Location(path, line, 1))
        variant = _variant(row[0], Location(path, line, 1))
        numbers[variant] = tuple(_number(row[i], semicolons) for i in numeric)
        named[variant] = tuple(row[i].strip() or None for i in kinds)
    return key_type(path, "", tuple(header[i] for i in numeric), tuple(header[i] for i in kinds), numbers, named)


def _is_number(cell: str, commas: bool) -> bool:
    try:
        return math.isfinite(float(cell.strip().replace(",", ".") if commas else cell.strip()))
    except ValueError:
        return False


def _number(cell: str, commas: bool) -> float | None:
    return float(cell.strip().replace(",", ".") if commas else cell.strip()) if cell.strip() else None


def _variant(cell: str, loc: Location) -> int:
    if not cell.strip().isdigit():
        raise InputError(f"expected a variant number, found '{cell.strip()}'", loc)
    return int(cell.strip())
