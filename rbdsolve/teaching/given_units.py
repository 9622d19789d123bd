"""A number given with its unit, as an exam's answer is written: '4.58 rad/s', '30°'.

    split_unit(text) -> (number text, unit) or None
    in_unit(value, unit, answer_unit) -> the value in the answer's SI unit, or an error

The unit is read from a short list, never parsed as an expression: a number followed by
SI symbols (rad, s, m, kg, N, J, W, Hz) joined by '/', '·', '*', '^' and powers, or an
angle in degrees (°, deg) or a rate in rpm. It must be the answer's own unit (the one the
numeric block prints beside it), up to spelling: '*' or '.' for '·', '^2' for '²', 1/s
for rad/s (a radian is a pure number); degrees are turned into radians (×π/180), rpm
into rad/s (×2π/60).
"""

from __future__ import annotations

import re

import sympy as sp

_NUMBER = r"[-+−]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_SYMBOL = r"(?:rad|kg|Hz|s|m|N|J|W)"
_UNIT = rf"{_SYMBOL}(?:\^?-?\d|[²³⁻¹])*(?:\s*[/·*.]\s*{_SYMBOL}(?:\^?-?\d|[²³⁻¹])*)*|1\s*/\s*s(?:\^?2|²)?"
_GIVEN = re.compile(rf"\s*({_NUMBER})\s*({_UNIT}|°|deg|degrees|rpm)\s*")
_POWERS = (("^-1", "⁻¹"), ("^2", "²"), ("^3", "³"), ("^4", "⁴"))

# (the unit given, the answer's) -> the factor that turns the first into the second
CONVERSIONS = {("°", "rad"): sp.pi / 180, ("deg", "rad"): sp.pi / 180, ("degrees", "rad"): sp.pi / 180,
               ("rpm", "rad/s"): 2 * sp.pi / 60, ("1/s", "rad/s"): sp.Integer(1),
               ("1/s²", "rad/s²"): sp.Integer(1)}  # fmt: skip


def split_unit(text: str) -> tuple[str, str] | None:
    """('4.58', 'rad/s') for '4.58 rad/s'; None where the text is not a number and a unit."""
    found = _GIVEN.fullmatch(text)
    return (found.group(1), found.group(2)) if found else None


def normal_unit(unit: str) -> str:
    """'kg*m^2' -> 'kg·m²': the spelling the numeric block prints."""
    out = re.sub(r"\s*[*.]\s*", "·", unit.strip()).replace(" ", "")
    for typed, printed in _POWERS:
        out = out.replace(typed, printed)
    return re.sub(r"(?<=[a-zA-Z])2\b", "²", out)


def factor_to(unit: str, answer_unit: str | None) -> sp.Expr | None:
    """The factor that turns a value in ``unit`` into one in the answer's unit; 1 where
    the answer's unit is not known (no values, nothing to hold it to); None where they
    differ."""
    given = normal_unit(unit)
    if answer_unit is None:
        return CONVERSIONS.get((given, "rad"), sp.Integer(1)) if given in ("°", "deg", "degrees") else sp.Integer(1)
    if given == answer_unit:
        return sp.Integer(1)
    return CONVERSIONS.get((given, answer_unit))
