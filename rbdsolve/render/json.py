"""JSON Lines: one object per problem file (the contract in docs/json.md).

Exact answers are ``str()`` of sympy objects, which ``sympy.sympify`` reads back;
coordinates appear as ``theta(t)``; matrices are nested lists of strings. The
conversion is generic over the answers dataclasses, so a new solver family needs no
code here.

The output is strict JSON (``allow_nan=False``): a number that is not finite is a bug
where the answers were built (they give None, JSON null, where a value is undefined,
and say what null means in docs/json.md), so it is an InternalError here, not a
``NaN`` or ``Infinity`` token that strict JSON readers refuse.
"""

from __future__ import annotations

from enum import Enum
from functools import lru_cache

import sympy as sp
from sympy.printing.str import StrPrinter

from rbdsolve.errors import InputError, InternalError, UnsolvedError
from rbdsolve.render.json_text import strict_json
from rbdsolve.form.printers import relation_latex
from rbdsolve.form.display import Math, plain
from rbdsolve.model.values.tree import map_leaves
from rbdsolve.report.steps import ProblemReport, Solution, Step
from rbdsolve.form.display import Relation

SCHEMA_VERSION = 1


def exact(value: object) -> object:
    """An answers tree as JSON data: sympy -> str, enums -> their value."""
    return map_leaves(value, _exact_leaf)


def _exact_leaf(value: object) -> object:
    if isinstance(value, Enum):
        return value.value
    if isinstance(value, sp.Basic):
        return str(value) if isinstance(value, sp.MatrixBase) or value.has(sp.Float) else _printed(value)
    return value


@lru_cache(maxsize=4096)
def _printed(value: sp.Basic) -> str:
    """``str`` of an exact expression, which a report prints several times (an answer,
    then in its step; the zeros of every matrix): sympy orders a sum's terms each time.
    (Not for floats: 0.5 at 15 and at 30 digits are equal keys that print differently.)
    An object whose class writes its own ``str`` (a matrix, on one line) is left to it."""
    return _SHARED.doprint(value) if type(value).__str__ is sp.Basic.__str__ else str(value)


class SharedStr(StrPrinter):
    """``str`` of exact expressions with each subexpression printed once, whichever
    expression it stands in: a chain's T and M(q) hold each cos(θⱼ(t) − θᵢ(t)) and θ̇ᵢ
    n times over, and sympy's printer orders a sum's terms again each time. The text is
    ``str``'s: the same printer with the settings ``str`` uses (sympy's ``sstr`` with
    order None), and it prints a subexpression the same wherever it stands (the brackets
    round it are its parent's). Only for expressions without a Float (``_printed``): a
    Float prints by its precision, which equal keys do not share. Past ``LIMIT``
    subexpressions (a long batch) the memory starts again."""

    LIMIT = 100_000

    def __init__(self) -> None:
        super().__init__({"order": None})
        self._texts: dict[sp.Basic, str] = {}

    def _print(self, expr, **kwargs) -> str:
        if kwargs or not isinstance(expr, sp.Basic):
            return super()._print(expr, **kwargs)
        text = self._texts.get(expr)
        if text is None:
            text = super()._print(expr)
            if len(self._texts) >= self.LIMIT:
                self._texts.clear()
            self._texts[expr] = text
        return text


_SHARED = SharedStr()


def _math(value: Math) -> object:
    return exact(plain(value))


def relation(rel: Relation) -> dict:
    out = {"lhs": _math(rel.lhs), "op": rel.op, "rhs": _math(rel.rhs)}
    if rel.more:
        out["more"] = [_math(m) for m in rel.more]
    if rel.more_op != "=":
        out["more_op"] = rel.more_op
    if rel.lead:
        out["lead"] = rel.lead
    out["latex"] = relation_latex(rel)
    return out


def step(s: Step) -> dict:
    out = {"kind": s.kind.value, "text": s.text, "math": [relation(r) for r in s.math]}
    return out | {"accuracy": True} if s.accuracy else out


def solution(s: Solution) -> dict:
    return {
        "question": s.question,
        "ok": s.solved,
        "route": s.route.value,
        "seconds": round(s.seconds, 6),
        "error_estimate": s.error_estimate,
        "answers": exact(s.answers) if s.answers is not None else None,
        "values": s.values,
        "units": s.units,
        "warnings": list(s.warnings),
        "error": s.error,
        "steps": [step(x) for x in s.steps],
    }


def report_object(report: ProblemReport) -> dict:
    model = report.model
    return {
        "schema": SCHEMA_VERSION,
        "file": report.file,
        "title": report.title,
        "source": report.source,
        "ok": report.solved,
        "symbols": list(report.symbols),
        "parameters": report.values,
        "parameter_units": dict(report.units),
        "model": {
            "coordinates": [str(q) for q in model.coordinates],
            "T": exact(model.T) if model.T is not None else None,
            "V": exact(model.V) if model.V is not None else None,
            "steps": [step(x) for x in model.steps],
        },
        "results": [solution(s) for s in report.solutions],
    }


def render_report(report: ProblemReport) -> str:
    return _dumps(report_object(report), report.file)


def render_error(file: str, error: InputError | InternalError | UnsolvedError) -> str:
    """The JSON line for a file that could not be read: scripts still get one line."""
    loc = error.location
    where = {"line": loc.line, "column": loc.column, "path": loc.key_path()} if loc else {}
    body = {"schema": SCHEMA_VERSION, "file": file, "ok": False,
            "error": {"message": error.message, **where}, "exit_code": int(error.exit_code)}
    return _dumps(body, file)


def _dumps(body: dict, file: str) -> str:
    """One line of strict JSON (no NaN or Infinity)."""
    try:
        return strict_json(body)
    except ValueError as exc:
        raise InternalError(f"{file}: a number that is not finite reached the JSON output ({exc})") from None

