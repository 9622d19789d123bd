"""Conditions on the parameters: where a quantity changes sign, its critical value, and
the sign on each side — the "stable iff Ω < √(g/R)" of an exam answer.

For a quantity f whose sign the parameters' own signs do not decide, one parameter p
is chosen in which f vanishes at exactly one positive value p_c (solved exactly, every
parameter positive): a rate first (a parameter named or described as a rate, a speed
or a spin: exams ask "above which rate"), then a stiffness, otherwise the first in
the file's order.
The sign of f on each side is decided exactly by putting in

    p = p_c (1 + δ)  (above)   or   p = p_c / (1 + δ)  (below),   δ > 0,

which keeps p positive, and asking sympy for the sign of the result (factored). Where
sympy cannot tell, f is evaluated at SAMPLES random points on that side (the other
parameters and δ drawn at random); the side gets a sign only if every sample agrees.
A physical f is dimensionally homogeneous, so p_c is a formula in the others, such as
√(g/R), and a condition in one parameter is the simplest an exam would write.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from enum import Enum
from typing import Iterable

import sympy as sp

from rbdsolve.form.tidy import tidy
from rbdsolve.solvers.shared.signs import sign_of, symbolic_sign

SAMPLES = 8
RATE_WORDS = ("omega", "spin", "rate", "speed", "angular")  # exams ask "above which rate"
STIFFNESS_WORDS = ("stiff", "spring", "torsion")  # then "how stiff a spring"


class Side(Enum):
    BELOW = "below"
    ABOVE = "above"


@dataclass(frozen=True)
class Critical:
    """p_c: the value of one parameter where a sign changes."""

    parameter: sp.Symbol
    value: sp.Expr

    @property
    def name(self) -> sp.Symbol:
        """Ω_c; or, where the critical value is another parameter (R > r), that one."""
        if isinstance(self.value, sp.Symbol):
            return self.value
        return sp.Symbol(f"{self.parameter.name}_c", positive=True)

    def same_as(self, other: Critical) -> bool:
        return self.parameter == other.parameter and sp.simplify(self.value - other.value) == 0

    def when(self, side: Side, closed: bool = False) -> sp.Boolean:
        """p < p_c or p > p_c (≤, ≥ with ``closed``), in the parameters' own symbols."""
        p, c = self.parameter, self.value
        if side is Side.BELOW:
            return sp.Le(p, c) if closed else sp.Lt(p, c)
        return sp.Ge(p, c) if closed else sp.Gt(p, c)


@dataclass(frozen=True)
class CriticalValue:
    """A critical value as answers give it (docs/json.md, ``critical``)."""

    parameter: str
    value: sp.Expr


def critical_values(criticals: Iterable[Critical]) -> tuple[CriticalValue, ...]:
    """Each critical value once, in the order found."""
    out: list[CriticalValue] = []
    for c in criticals:
        if not any(o.parameter == str(c.parameter) and sp.simplify(o.value - c.value) == 0 for o in out):
            out.append(CriticalValue(str(c.parameter), c.value))
    return tuple(out)


def what_decides(f: sp.Expr) -> str:
    """What a user can give to decide the sign of f, for a message: its parameters'
    values, or an assumption."""
    names = ", ".join(sorted(str(s) for s in f.free_symbols))
    return (f"give values for {names}, or state the sign of {sp.sstr(f)} under 'assumptions:' "
            "(such as [R > r])")


def real_where(values: Iterable[sp.Expr]) -> list[sp.Expr]:
    """What must be ≥ 0 for the values to be real: radicands, 1 − c² under acos and asin."""
    needed = set()
    for value in values:
        needed |= {p.base for p in value.atoms(sp.Pow) if p.exp.is_Rational and p.exp.q == 2}
        needed |= {1 - f.args[0] ** 2 for f in value.atoms(sp.acos, sp.asin)}
    return sorted(needed, key=sp.default_sort_key)


@dataclass(frozen=True)
class Existence:
    """Where values are real: the condition solved for one parameter (true: always),
    the critical values it uses, and the sides of the first one where they are real."""

    condition: sp.Basic
    criticals: tuple[Critical, ...]
    sides: frozenset[Side]


def exists_when(values: Iterable[sp.Expr], model) -> Existence | None:
    """Where ``values`` are real (``real_where``), each condition the assumptions do not
    decide split at its critical value; None where one cannot be split, or two split at
    different critical values."""
    exists, criticals, sides = sp.true, [], set(Side)
    for condition in real_where(values):
        condition = tidy(condition)
        if isinstance(sign_of(condition, model.assumed), int):
            continue
        s = split(condition, model)
        if s is None or (criticals and not s.critical.same_as(criticals[0])):
            return None
        criticals.append(s.critical)
        held = s.sides((1,))
        sides &= set(held)
        exists = sp.And(exists, s.critical.when(held[0], closed=True)) if len(held) == 1 else exists
    return Existence(exists, tuple(criticals), frozenset(sides))


@dataclass(frozen=True)
class Split:
    """The sign of a quantity below and above a critical value."""

    critical: Critical
    below: int
    above: int

    def sides(self, wanted: Iterable[int]) -> tuple[Side, ...]:
        """The sides where the sign is one of ``wanted``."""
        wanted = set(wanted)
        return tuple(s for s, sign in ((Side.BELOW, self.below), (Side.ABOVE, self.above)) if sign in wanted)


def split(f: sp.Expr, model) -> Split | None:
    """The critical value of one parameter where f changes sign, and its sign on each
    side; None where no parameter has exactly one positive root of f, or a side's sign
    cannot be told."""
    for p in _candidates(f, model):
        critical = _critical(f, p, model)
        if critical is None:
            continue
        below, above = (_sign_on(f, critical, side, model) for side in Side)
        if below is not None and above is not None and below != above:
            return Split(critical, below, above)
    return None


def on_side(expr: sp.Expr, critical: Critical, side: Side) -> tuple[sp.Expr, sp.Symbol]:
    """expr with p = p_c (1 + δ) or p_c/(1 + δ), and δ (positive)."""
    delta = sp.Dummy("delta", positive=True)
    factor = (1 + delta) if side is Side.ABOVE else 1 / (1 + delta)
    return expr.xreplace({critical.parameter: critical.value * factor}), delta


def _candidates(f: sp.Expr, model) -> list[sp.Symbol]:
    """The parameters in f, rates first, then in the file's order."""
    order = [model.symbols.parameters[p.name] for p in model.problem.parameters]
    held = [p for p in order if p in f.free_symbols and p.is_positive]
    described = {model.symbols.parameters[p.name]: f"{p.name} {p.description}".lower()
                 for p in model.problem.parameters}
    return sorted(held, key=lambda p: (not any(w in described[p] for w in RATE_WORDS),
                                       not any(w in described[p] for w in STIFFNESS_WORDS)))


def _critical(f: sp.Expr, p: sp.Symbol, model) -> Critical | None:
    """The one positive root of f in p (the others positive), if there is exactly one."""
    numerator, denominator = sp.fraction(sp.together(f))
    try:  # f changes sign where its numerator or its denominator does (2g/(3(R − r)) at R = r)
        roots = sp.solve(numerator * denominator, p)
    except (NotImplementedError, ValueError):
        return None
    positive = []
    for r in roots:
        r = tidy(r)
        if r.is_positive or (r.is_real is not False and _positive_at_samples(r, model)):
            if not any(sp.simplify(r - x) == 0 for x in positive):
                positive.append(r)
    if len(positive) != 1:
        return None
    return Critical(p, _one_root(positive[0]))


def _one_root(value: sp.Expr) -> sp.Expr:
    """√g/√R as √(g/R), the form an exam writes (kept unevaluated: sympy would split
    the root of a quotient of positive symbols again)."""
    square = sp.factor(value**2)
    if value.has(sp.Pow) and not square.has(sp.sqrt) and not square.is_Pow:
        return sp.Pow(square, sp.Rational(1, 2), evaluate=False)
    return value


def _positive_at_samples(r: sp.Expr, model) -> bool:
    rng = random.Random(19)
    for _ in range(SAMPLES):
        point = _sample(model, rng)
        if point is None:
            return False
        z = complex(sp.N(r.xreplace(point), 20))
        if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)) or z.real <= 0:
            return False
    return True


def _sample(model, rng: random.Random, leave: tuple = ()) -> dict | None:
    """Random parameter values that satisfy the problem's assumptions (the parameter
    of the split left out: it is set by the side), or None if none is found."""
    from rbdsolve.model.assumptions import admissible_sample

    symbols = [s for s in model.symbols.parameters.values() if s not in leave]
    kept = [a for a in model.assumptions if not a.difference.free_symbols & set(leave)]
    return admissible_sample(kept, model.symbols, rng, symbols=symbols, tries=200)


def _sign_on(f: sp.Expr, critical: Critical, side: Side, model) -> int | None:
    """f's sign on one side: exactly (δ positive), else by agreeing samples."""
    value, delta = on_side(f, critical, side)
    sign = symbolic_sign(tidy(value))
    if sign:
        return sign
    rng = random.Random(20)
    signs = set()
    for _ in range(SAMPLES):
        drawn = _sample(model, rng, (critical.parameter,))
        if drawn is None:
            return None
        point = {**drawn, delta: sp.Rational(rng.randint(50, 3000), 1000)}
        z = complex(sp.N(value.xreplace(point), 30))
        if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)) or z.real == 0:
            return None
        signs.add(1 if z.real > 0 else -1)
    return signs.pop() if len(signs) == 1 else None
