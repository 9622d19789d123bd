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

An angle parameter (one that f holds only through sines and cosines of whole
multiples of it: a tilt, an incline, a half-angle) has no positive scale; its sign is
studied over one range, (0, π) for a positive one and (−π, π) otherwise
(``angle_parameters``): the roots of f's numerator and denominator there, in the same
order at every sample, cut it into intervals, f's sign on each is sampled, and a single
change of sign is the critical value (θ < π/2 for a coin's tilt). A side of it is then
the part of the range up to the critical value or beyond it.
"""

from __future__ import annotations

import math
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
    span: tuple[sp.Expr, sp.Expr] | None = None  # an angle's range; None: every positive value

    @property
    def name(self) -> sp.Expr:
        """Ω_c; or, where the critical value is another parameter (R > r) or a number
        (θ < π/2), that itself."""
        if isinstance(self.value, sp.Symbol) or not self.value.free_symbols:
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


def exists_when(values: Iterable[sp.Expr], model, nonnegative: Iterable[sp.Expr] = ()) -> Existence | None:
    """Where ``values`` are real (``real_where``) and ``nonnegative`` ones are ≥ 0 (the
    value of a square, ω₀²), each condition the assumptions do not decide split at its
    critical value; None where one cannot be split, or two split at different critical
    values."""
    exists, criticals, sides = sp.true, [], set(Side)
    for condition in [*real_where(values), *nonnegative]:
        condition = tidy(condition)
        if isinstance(sign_of(condition, model.assumed), int):
            continue
        s = split(condition, model)
        if s is None or (criticals and not s.critical.same_as(criticals[0])):
            return None
        criticals.append(s.critical)
        held = s.sides((1,))
        sides &= set(held)
        closed = _finite_at(condition, s.critical)  # ω² ≥ g/R, but R > r where 1/(R − r) is
        exists = sp.And(exists, s.critical.when(held[0], closed=closed)) if len(held) == 1 else exists
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
    side; None where no parameter has exactly one positive root of f (one change of
    sign in an angle's range), or a side's sign cannot be told."""
    angles = angle_parameters(f)
    for p in _candidates(f, model, angles):
        critical = _angle_critical(f, p, angles, model) if p in angles else _critical(f, p, model, angles)
        if critical is None:
            continue
        below, above = (_sign_on(f, critical, side, model, angles) for side in Side)
        if below is not None and above is not None and below != above:
            return Split(critical, below, above)
    return None


def on_side(expr: sp.Expr, critical: Critical, side: Side) -> tuple[sp.Expr, sp.Symbol]:
    """expr with p = p_c (1 + δ) or p_c/(1 + δ), δ positive; for an angle in its range
    (a, b), p = p_c + (b − p_c) δ/(1 + δ) or p_c − (p_c − a) δ/(1 + δ)."""
    delta = sp.Dummy("delta", positive=True)
    p, c = critical.parameter, critical.value
    if critical.span is not None:
        low, high = critical.span
        step = delta / (1 + delta)
        return expr.xreplace({p: c + (high - c) * step if side is Side.ABOVE else c - (c - low) * step}), delta
    factor = (1 + delta) if side is Side.ABOVE else 1 / (1 + delta)
    return expr.xreplace({p: c * factor}), delta


TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


def angle_parameters(f: sp.Expr) -> dict[sp.Symbol, tuple[sp.Expr, sp.Expr]]:
    """{p: its range} for the parameters f holds only through sines and cosines of
    whole multiples of them: (0, π) for a positive one, (−π, π) otherwise."""
    out = {}
    for p in sorted(f.free_symbols, key=str):
        trig = [t for t in f.atoms(*TRIG) if t.has(p)]
        if not trig or not all((t.args[0] / p).is_Integer for t in trig):
            continue
        if not f.xreplace({t: sp.Dummy() for t in trig}).has(p):
            out[p] = (sp.Integer(0), sp.pi) if p.is_positive else (-sp.pi, sp.pi)
    return out


def _finite_at(f: sp.Expr, critical: Critical) -> bool:
    """Whether f is finite at the critical value (its numerator vanishes there, not its
    denominator): a boundary where the condition holds with equality."""
    _, denominator = sp.fraction(sp.together(f))
    return sp.simplify(denominator.xreplace({critical.parameter: critical.value})) != 0


def _candidates(f: sp.Expr, model, angles: dict) -> list[sp.Symbol]:
    """The positive parameters and the angles in f, rates first, then in the file's order."""
    order = [model.symbols.parameters[p.name] for p in model.problem.parameters]
    held = [p for p in order if p in f.free_symbols and (p.is_positive or p in angles)]
    described = {model.symbols.parameters[p.name]: f"{p.name} {p.description}".lower()
                 for p in model.problem.parameters}
    return sorted(held, key=lambda p: (not any(w in described[p] for w in RATE_WORDS),
                                       not any(w in described[p] for w in STIFFNESS_WORDS)))


def _critical(f: sp.Expr, p: sp.Symbol, model, angles: dict) -> Critical | None:
    """The one positive root of f in p (the others positive), if there is exactly one."""
    numerator, denominator = sp.fraction(sp.together(f))
    try:  # f changes sign where its numerator or its denominator does (2g/(3(R − r)) at R = r)
        roots = sp.solve(numerator * denominator, p)
    except (NotImplementedError, ValueError):
        return None
    positive = []
    for r in roots:
        r = tidy(r)
        if r.is_positive or (r.is_real is not False and _positive_at_samples(r, model, angles)):
            if not any(sp.simplify(r - x) == 0 for x in positive):
                positive.append(r)
    if len(positive) != 1:
        return None
    return Critical(p, _one_root(positive[0]))


def _angle_critical(f: sp.Expr, p: sp.Symbol, angles: dict, model) -> Critical | None:
    """The one value in p's range where f changes sign: the roots of f's numerator and
    denominator inside the range (each inside, or outside, at every sample, in the
    same order), and f's sign sampled between them; None unless exactly one of them
    changes it."""
    low, high = angles[p]
    roots = _roots_inside(f, p, angles, model)
    if roots is None:
        return None
    cuts = [low, *roots, high]
    signs = [_sign_between(f, p, a, b, angles, model) for a, b in zip(cuts, cuts[1:])]
    if None in signs:
        return None
    changes = [r for r, before, after in zip(roots, signs, signs[1:]) if before != after]
    return Critical(p, changes[0], (low, high)) if len(changes) == 1 else None


def _roots_inside(f: sp.Expr, p: sp.Symbol, angles: dict, model) -> list[sp.Expr] | None:
    """f's numerator's and denominator's roots in p strictly inside p's range, turned
    into it by whole turns, in increasing order; None where a root is inside at some
    samples and not at others, or the order changes."""
    low, high = angles[p]
    numerator, denominator = sp.fraction(sp.together(f))
    try:
        found = {tidy(r) for factor in (numerator, denominator) if factor.has(p) for r in sp.solve(factor, p)}
    except (NotImplementedError, ValueError):
        return None
    points = [_sample(model, random.Random(21 + k), (p,), angles) for k in range(SAMPLES)]
    if None in points:
        return None
    inside = {}
    for r in found:
        turns = {_turns_into(complex(sp.N(r.xreplace(point), 20)), low, high) for point in points}
        if turns == {None}:
            continue  # never real inside the range
        if len(turns) != 1:
            return None
        turned = tidy(r + 2 * sp.pi * turns.pop())
        if not any(sp.simplify(turned - x) == 0 for x in inside):
            inside[turned] = [float(sp.N(turned.xreplace(point), 20)) for point in points]
    order = sorted(inside, key=lambda r: inside[r][0])
    if any(sorted(inside, key=lambda r: inside[r][k]) != order for k in range(len(points))):
        return None
    return order


def _turns_into(z: complex, low, high) -> int | None:
    """The whole turns k that put the real value z + 2πk strictly inside (low, high);
    None if z is not real or no turn does."""
    if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)):
        return None
    a, b = float(low), float(high)
    k = math.floor((a - z.real) / (2 * math.pi)) + 1
    value = z.real + 2 * math.pi * k
    return k if a + 1e-12 < value < b - 1e-12 else None


def _sign_between(f: sp.Expr, p: sp.Symbol, a, b, angles: dict, model) -> int | None:
    """f's sign for p between a and b (themselves in the parameters), sampled: every
    sample must agree."""
    rng = random.Random(22)
    signs = set()
    for _ in range(SAMPLES):
        point = _sample(model, rng, (p,), angles)
        if point is None:
            return None
        at = a + (b - a) * sp.Rational(rng.randint(1, 999), 1000)
        z = complex(sp.N(f.xreplace({**point, p: at.xreplace(point)}), 30))
        if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)) or z.real == 0:
            return None
        signs.add(1 if z.real > 0 else -1)
    return signs.pop() if len(signs) == 1 else None


def _one_root(value: sp.Expr) -> sp.Expr:
    """√g/√R as √(g/R), the form an exam writes (kept unevaluated: sympy would split
    the root of a quotient of positive symbols again)."""
    square = sp.factor(value**2)
    if square.could_extract_minus_sign():  # −g (−2 + √2)/l: a sign taken into the sum, (2 − √2) g/l
        square = sp.factor_terms(sp.expand(value**2))
    if value.has(sp.Pow) and not square.has(sp.sqrt) and not square.is_Pow:
        return sp.Pow(square, sp.Rational(1, 2), evaluate=False)
    return value


def _positive_at_samples(r: sp.Expr, model, angles: dict) -> bool:
    rng = random.Random(19)
    for _ in range(SAMPLES):
        point = _sample(model, rng, angles=angles)
        if point is None:
            return False
        z = complex(sp.N(r.xreplace(point), 20))
        if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)) or z.real <= 0:
            return False
    return True


def _sample(model, rng: random.Random, leave: tuple = (), angles: dict = {}) -> dict | None:
    """Random parameter values that satisfy the problem's assumptions (the parameter
    of the split left out: it is set by the side), angles in their ranges, or None if
    none is found."""
    from rbdsolve.model.assumptions import admissible_sample

    symbols = [s for s in model.symbols.parameters.values() if s not in leave]
    kept = [a for a in model.assumptions if not a.difference.free_symbols & set(leave)]
    return admissible_sample(kept, model.symbols, rng, symbols=symbols, tries=200, ranges=angles)


def _sign_on(f: sp.Expr, critical: Critical, side: Side, model, angles: dict) -> int | None:
    """f's sign on one side: exactly (δ positive), else by agreeing samples."""
    value, delta = on_side(f, critical, side)
    sign = symbolic_sign(tidy(value))
    if sign:
        return sign
    rng = random.Random(20)
    signs = set()
    for _ in range(SAMPLES):
        drawn = _sample(model, rng, (critical.parameter,), angles)
        if drawn is None:
            return None
        point = {**drawn, delta: sp.Rational(rng.randint(50, 3000), 1000)}
        z = complex(sp.N(value.xreplace(point), 30))
        if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)) or z.real == 0:
            return None
        signs.add(1 if z.real > 0 else -1)
    return signs.pop() if len(signs) == 1 else None
