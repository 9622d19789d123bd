"""What a check of an answer concludes: frozen verdicts, and the common slips they name.

A student's expression is compared with rbdsolve's exact answer (teaching/check.py);
a student's number with a variant's number (teaching/grading.py). Both say what they
found in the same words: right, or wrong by a slip a teacher recognises — a sign, a
factor 2, 2π between an angular frequency ω and a frequency f = ω/(2π), degrees for
radians, a square root left out or added — or simply different.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import sympy as sp


class Slip(Enum):
    """A common slip, recognised by how the answer given relates to the right one."""

    SIGN = "sign"  # given = −right
    FACTOR_2 = "factor_2"  # given = 2·right or right/2
    TWO_PI = "two_pi"  # given = right/(2π) (f for ω) or 2π·right
    DEGREES = "degrees"  # given = right·180/π: an angle (or a rate) in degrees
    MISSING_ROOT = "missing_root"  # given = right²: λ where ω = √λ was asked
    EXTRA_ROOT = "extra_root"  # given = √right: ω where λ was asked

    @property
    def text(self) -> str:
        return SLIP_TEXT[self]


SLIP_TEXT = {
    Slip.SIGN: "the sign differs",
    Slip.FACTOR_2: "off by a factor 2",
    Slip.TWO_PI: "off by a factor 2π (ω ↔ f)",
    Slip.DEGREES: "in degrees, not radians",
    Slip.MISSING_ROOT: "a missing square root (yours is the answer squared)",
    Slip.EXTRA_ROOT: "an extra square root (yours squared is the answer)",
}

# The constant factors (given/right) that are a slip, exact: checked in this order.
FACTOR_SLIPS: tuple[tuple[sp.Expr, tuple[Slip, ...]], ...] = (
    (sp.Integer(-1), (Slip.SIGN,)),
    (sp.Integer(2), (Slip.FACTOR_2,)),
    (sp.Rational(1, 2), (Slip.FACTOR_2,)),
    (1 / (2 * sp.pi), (Slip.TWO_PI,)),
    (2 * sp.pi, (Slip.TWO_PI,)),
    (180 / sp.pi, (Slip.DEGREES,)),
    (sp.Integer(-2), (Slip.SIGN, Slip.FACTOR_2)),
    (sp.Rational(-1, 2), (Slip.SIGN, Slip.FACTOR_2)),
    (-1 / (2 * sp.pi), (Slip.SIGN, Slip.TWO_PI)),
    (-2 * sp.pi, (Slip.SIGN, Slip.TWO_PI)),
    (-180 / sp.pi, (Slip.SIGN, Slip.DEGREES)),
)


class Proof(Enum):
    """How an equivalence was established."""

    SIMPLIFIED = "simplified"  # the difference simplifies to 0 (or the same word, for a kind)
    SAMPLED = "sampled"  # equal at every admissible random point tried (30 digits)
    ANGLE = "angle"  # the same angle: they differ by whole turns, 2π k
    AT_VALUES = "at_values"  # a number, within the tolerance of the answer at the file's values


@dataclass(frozen=True)
class Equivalent:
    how: Proof

    right = True
    name = "equivalent"

    def describe(self) -> str:
        return {Proof.ANGLE: "right (the same angle, whole turns apart)",
                Proof.AT_VALUES: "right (at the file's values, within the tolerance)"}.get(self.how, "right")


@dataclass(frozen=True)
class SignDiffers:
    right = False
    name = "sign"

    @property
    def slips(self) -> tuple[Slip, ...]:
        return (Slip.SIGN,)

    def describe(self) -> str:
        return "wrong: the sign differs"


@dataclass(frozen=True)
class Factor:
    """given = factor · right, for a constant factor; ``slips`` names a known one."""

    factor: sp.Expr
    slips: tuple[Slip, ...] = ()

    right = False
    name = "factor"

    def describe(self, show: bool = False) -> str:
        """The factor itself only when the answer may be shown: with yours, it gives it."""
        if self.slips:
            return "wrong: " + "; ".join(s.text for s in self.slips)
        if not show:
            return "wrong: off by a constant factor"
        return f"wrong: off by a constant factor {_shown(self.factor)} (yours is {_shown(self.factor)} × the answer)"


@dataclass(frozen=True)
class Root:
    """given = right² (a square root missing) or given² = right (one too many)."""

    missing: bool

    right = False
    name = "root"

    @property
    def slips(self) -> tuple[Slip, ...]:
        return (Slip.MISSING_ROOT if self.missing else Slip.EXTRA_ROOT,)

    def describe(self) -> str:
        return "wrong: " + self.slips[0].text


@dataclass(frozen=True)
class Slipped:
    """A number that is the answer at the file's values after these slips."""

    slips: tuple[Slip, ...]

    right = False
    name = "slipped"

    def describe(self) -> str:
        return "wrong: " + "; ".join(s.text for s in self.slips)


@dataclass(frozen=True)
class EqualFor:
    """Equal only where ``condition`` holds (one parameter solved for), else different."""

    condition: str  # unicode: 'm = 1'

    right = False
    name = "equal_for"

    def describe(self) -> str:
        return f"wrong: equal only when {self.condition}"


@dataclass(frozen=True)
class Different:
    """Different: at ``point`` (parameter values, unicode name and number) yours is
    ``yours`` and the answer ``expected`` (said only when the answer may be shown)."""

    point: tuple[tuple[str, str], ...]
    yours: str
    expected: str

    right = False
    name = "different"

    def describe(self, show: bool = False) -> str:
        where = f" at {', '.join(f'{n} = {v}' for n, v in self.point)}" if self.point else ""
        answer = f", the answer {self.expected}" if show else ""
        return f"wrong: different{where} (yours is {self.yours}{answer})"


@dataclass(frozen=True)
class Undecided:
    """Neither proved equal nor shown different (no admissible point where both have a
    finite value): counted as not right."""

    reason: str

    right = False
    name = "undecided"

    def describe(self) -> str:
        return f"not decided: {self.reason}"


Verdict = Equivalent | SignDiffers | Factor | Root | Slipped | EqualFor | Different | Undecided


def slips_of(verdict: Verdict) -> tuple[Slip, ...]:
    return getattr(verdict, "slips", ())


def describe(verdict: Verdict, show: bool = False) -> str:
    """The verdict in words; what would give the answer away only with ``show``."""
    return verdict.describe(show) if isinstance(verdict, (Different, Factor)) else verdict.describe()


def _shown(value: sp.Expr) -> str:
    from rbdsolve.form.printers import to_unicode

    return to_unicode(value)
