"""Conditions on the parameters: where a quantity changes sign, its critical values, and
the sign between them — the "stable iff Ω < √(g/R)" of an exam answer.

For a quantity f whose sign the parameters' own signs do not decide, one parameter p
is chosen (``partition``), the one the question is about (``candidates``): the one a
question's ``for:`` names; else the problem's only parameter without a value (every
value given but k: "how stiff must the springs be"); else a rate or a spin (exams ask
"above which rate"), then a stiffness, then a length, then a mass, then the others,
each group in the file's order. The first of these that f holds and whose roots split
its range is taken. The roots of f's numerator and denominator in p, solved exactly,
that lie inside p's range at every sample (``parameter_roots``) cut the range into
pieces; f's sign on each piece is decided exactly by putting in a point of it,

    p = p₁/(1 + δ)  (below the first),  p = pₙ (1 + δ)  (above the last),
    p = pₖ + (pₖ₊₁ − pₖ) δ/(1 + δ)  (between),   δ > 0,

and asking sympy for the sign of the result (factored). Where sympy cannot tell, f is
evaluated at SAMPLES random points of the piece (the other parameters and δ drawn at
random); the piece gets a sign only if every sample agrees. Neighbouring pieces of one
sign are one (a double root changes nothing); the roots left are the critical values.
A physical f is dimensionally homogeneous, so each is a formula in the others, such as
√(g/R), and a condition in one parameter is the simplest an exam would write.

An angle parameter (one that f holds only through sines and cosines of whole
multiples of it: a tilt, an incline, a half-angle) has no positive scale; its range is
(0, π) for a positive one and (−π, π) otherwise (``angle_parameters``), and its roots
are turned into it by whole turns (θ < π/2 for a coin's tilt).
"""

from __future__ import annotations

import cmath
import random
from dataclasses import dataclass, replace
from typing import Iterable, Mapping

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.form.quotient import quotient
from rbdsolve.form.tidy import square_root, tidy, tidy_fraction
from rbdsolve.form.zero import simplifies_to_zero
from rbdsolve.model.assumptions import implies
from rbdsolve.model.energies.energy import memoized
from rbdsolve.solvers.conditions.condition_roots import SAMPLES, admissible, angle_parameters, parameter_roots
from rbdsolve.solvers.conditions.parameter_order import candidates
from rbdsolve.solvers.conditions.angle_signs import angle_sign
from rbdsolve.solvers.conditions.bounds import tightest_bounds
from rbdsolve.solvers.conditions.signs import sign_of, symbolic_sign


@dataclass(frozen=True)
class Critical:
    """p_c: a value of one parameter where a sign changes."""

    parameter: sp.Symbol
    value: sp.Expr

    def same_as(self, other: Critical) -> bool:
        return self.parameter == other.parameter and simplifies_to_zero(self.value - other.value)


@dataclass(frozen=True)
class CriticalValue:
    """A critical value as answers give it (docs/json.md, ``critical``)."""

    parameter: str
    value: sp.Expr


def critical_values(criticals: Iterable[Critical]) -> tuple[CriticalValue, ...]:
    """Each critical value once, in the order found."""
    out: list[CriticalValue] = []
    for c in criticals:
        if not any(o.parameter == str(c.parameter) and simplifies_to_zero(o.value - c.value) for o in out):
            out.append(CriticalValue(str(c.parameter), c.value))
    return tuple(out)


@dataclass(frozen=True)
class Piece:
    """The values of one parameter between two critical values (None: an end of its
    range), and the sign of the quantity there."""

    parameter: sp.Symbol
    low: sp.Expr | None
    high: sp.Expr | None
    sign: int
    span: tuple[sp.Expr, sp.Expr]  # the parameter's range: (0, ∞), or an angle's

    def when(self, closed_low: bool = False, closed_high: bool = False) -> sp.Boolean:
        """Ω < Ω_c, Ω_c1 < Ω < Ω_c2 or Ω > Ω_c (≤, ≥ where closed), in the parameters' symbols."""
        p, parts = self.parameter, []
        if self.low is not None:
            parts.append(sp.Ge(p, self.low) if closed_low else sp.Gt(p, self.low))
        if self.high is not None:
            parts.append(sp.Le(p, self.high) if closed_high else sp.Lt(p, self.high))
        return sp.And(*parts)

    def inside(self, expr: sp.Expr) -> tuple[sp.Expr, sp.Symbol]:
        """expr at a point of the piece, and δ > 0 that moves the point across it."""
        delta = sp.Dummy("delta", positive=True)
        low = self.span[0] if self.low is None else self.low
        high = self.span[1] if self.high is None else self.high
        if high is sp.oo:
            at = low * (1 + delta) if low != 0 else delta  # the whole of (0, ∞): any δ
        elif low == 0:
            at = high / (1 + delta)
        else:
            at = low + (high - low) * delta / (1 + delta)
        return expr.xreplace({self.parameter: at}), delta

    def joined(self, other: Piece) -> Piece:
        """This piece and the next one, as one."""
        return Piece(self.parameter, self.low, other.high, self.sign, self.span)


@dataclass(frozen=True)
class Partition:
    """The range of one parameter in pieces, in increasing order; neighbours differ."""

    parameter: sp.Symbol
    pieces: tuple[Piece, ...]

    @property
    def criticals(self) -> tuple[Critical, ...]:
        return changes(self.pieces)


def partition(f: sp.Expr, model, first: sp.Symbol | None = None) -> Partition | None:
    """f's sign piece by piece in the first parameter (``candidates``: ``first``, the one
    a question names, before all) whose roots cut its range into pieces of known sign,
    at least one change of sign among them; None where no parameter does. Found once
    per model (its samples are seeded: the same f gives the same pieces): the equilibria
    and the modes about them ask for one stability condition each: f is taken without
    its positive factors (``sign_part``), so det K = k − m Ω² and λ = (k − m Ω²)/m are
    split once)."""
    return _partition(model, sign_part(f), first)


def sign_part(f: sp.Expr) -> sp.Expr:
    """f without the factors that are positive wherever f is defined: positive numbers
    and powers of positive parameters (λ = K/m has K's roots and sign). A negative
    coefficient is kept as −1."""
    if not isinstance(f, sp.Mul):
        return f
    kept = [x for x in f.args if not (x.is_Number or _positive_power(x))]
    coefficient = f.as_coeff_Mul()[0]
    return sp.Mul(*([-1] if coefficient.is_negative else []), *kept)


def _positive_power(x: sp.Expr) -> bool:
    """A positive parameter, or a real power of one: m, 1/d, k²."""
    base, exponent = x.as_base_exp()
    return isinstance(base, sp.Symbol) and base.is_positive is True and exponent.is_real is True


@memoized
def _partition(model, f: sp.Expr, first: sp.Symbol | None) -> Partition | None:
    """The first candidate that splits f's sign where the assumptions allow it (a shell
    inside a pipe, R > r: its condition in θ₀, not "r > R"), else the first that splits
    it at all (a coin whose contact implies cos θ > 0 keeps "θ < π/2"); each candidate's
    roots and signs found once."""
    angles = angle_parameters(f)
    anywhere = None
    for p in candidates(f, model, angles, first):
        found, split = _split_in(model, f, p, angles)
        if found is not None:
            return found
        anywhere = anywhere or split
    return anywhere


def _split_in(model, f: sp.Expr, p: sp.Symbol, angles: dict) -> tuple[Partition | None, Partition | None]:
    """f's sign piece by piece in p: where the assumptions allow it, and anywhere (None,
    None: p's roots do not split it, or a piece's sign is not known)."""
    roots = parameter_roots(f, p, angles, model)
    if not roots:
        return None, None
    span = angles.get(p, (sp.Integer(0), sp.oo))
    ends = [None, *roots, None]
    pieces = [Piece(p, a, b, 0, span) for a, b in zip(ends, ends[1:])]
    signs = [sign_on(f, piece, model, angles) for piece in pieces]
    if None in signs:
        return None, None
    # a piece the assumptions rule out (r > R under R > r) splits nothing
    allowed_ones = [(piece, sign) for piece, sign in zip(pieces, signs) if allowed(piece, model)]
    return _merged(p, allowed_ones), _merged(p, list(zip(pieces, signs)))


def _split(condition: sp.Expr, model, first: sp.Symbol | None) -> tuple[Partition | None, dict, sp.Expr]:
    """The condition's pieces, the size they are in ({|C|'s symbol: Abs(C)}, or {} for a
    positive parameter) and the condition in that symbol (C as its size): a parameter of
    either sign the question is about first (``_signed_first``), then the positive ones
    (``partition``), then any of either sign (``by_size``)."""
    preferred = _signed_first(condition, model, first)
    sized = by_size(condition, model, preferred) if preferred is not None else None
    if sized is None:
        found = partition(condition, model, first)
        if found is not None:
            return found, {}, condition
        sized = by_size(condition, model)
    if sized is None:
        return None, {}, condition
    found, size = sized
    return found, size, condition.xreplace({magnitude.args[0]: k for k, magnitude in size.items()})


def _signed_first(f: sp.Expr, model, first: sp.Symbol | None) -> sp.Symbol | None:
    """The parameter of either sign a condition is to be written in before the positive
    ones (``candidates``' first two rules): the one a question's ``for:`` names, else
    the problem's only parameter without a value — a bead on a hoop turning at Ω of
    either sense, every other value given: |Ω| ≥ Ω_c, not R ≥ R_c in the radius given."""
    open_ = [model.symbols.parameters[p.name] for p in model.problem.parameters
             if model.symbols.parameters[p.name] not in model.values]
    chosen = first if first is not None else open_[0] if len(open_) == 1 else None
    if chosen is None or chosen.is_positive or chosen not in f.free_symbols:
        return None
    return chosen


def by_size(f: sp.Expr, model, only: sp.Symbol | None = None) -> tuple[Partition, dict[sp.Symbol, sp.Expr]] | None:
    """f's sign piece by piece in the size |p| of a parameter of either sign that f
    holds only in even powers (a couple C of either sign on a plate hung from a corner:
    1 − 2 C²/(a² g² m²) ≥ 0 is |C| ≤ C_c, C_c = √2 a g m/2), where no positive parameter
    splits it (an angle of either sign is not one: ``partition`` splits it over its turn):
    f(p) = f(|p|), so |p| is split as a positive parameter of p's name, and the pieces'
    conditions read |p| once that name is put back as Abs(p) (the second value
    returned); ``only`` tries that parameter alone. None where no such parameter splits f."""
    order = [only] if only is not None else [model.symbols.parameters[x.name] for x in model.problem.parameters]
    angles = angle_parameters(f)  # an angle of either sign is split in (−π, π) by ``partition`` already
    for p in order:
        if p not in f.free_symbols or p.is_positive or p.is_negative or p in angles or not _even_in(f, p):
            continue
        size = sp.Symbol(p.name, positive=True)
        found, _ = _split_in(model, f.xreplace({p: size}), size, {})
        if found is not None:
            return found, {size: sp.Abs(p)}
    return None


def _even_in(f: sp.Expr, p: sp.Symbol) -> bool:
    """f(−p) = f(p), term by term: p only in even powers."""
    return simplifies_to_zero(f.xreplace({p: -p}) - f)


def _merged(p: sp.Symbol, signed: list) -> Partition | None:
    """Neighbouring pieces of one sign joined; a partition where at least two are left."""
    if not signed:
        return None
    merged = [replace(signed[0][0], sign=signed[0][1])]
    for piece, sign in signed[1:]:
        if sign == merged[-1].sign:
            merged[-1] = merged[-1].joined(piece)
        else:
            merged.append(replace(piece, sign=sign))
    return Partition(p, tuple(merged)) if len(merged) > 1 else None


def allowed(piece: Piece, model) -> bool:
    """Whether the assumptions that hold the piece's parameter hold somewhere on it:
    False only where they fail at every sampled point of it (R < r under R > r)."""
    mine = [a.relation for a in model.assumptions if piece.parameter in a.difference.free_symbols]
    return not mine or within(piece, sp.And(*mine), model) is not False


def at_samples(piece: Piece, expr, model, seed: int, angles: dict) -> list | None:
    """expr at SAMPLES random points of the piece (the other parameters admissible
    rationals, angles in their ranges); None where no admissible point is found."""
    value, delta = piece.inside(expr)
    rng = random.Random(seed)
    out = []
    for _ in range(SAMPLES):
        point = admissible(model, rng, (piece.parameter,), angles)
        if point is None:
            return None
        out.append(value.xreplace({**point, delta: sp.Rational(rng.randint(50, 3000), 1000)}))
    return out


def within(piece: Piece, condition: sp.Basic, model) -> bool | None:
    """Whether ``condition`` holds on the piece: True if at every sampled point of it,
    False if at none, None if at some (the pieces do not line up)."""
    if condition is sp.true:
        return True
    held = [x for x in (condition, piece.low, piece.high) if x is not None]
    angles = {p: span for x in held for p, span in angle_parameters(x).items()}
    try:
        values = at_samples(piece, condition, model, 23, angles)
        seen = {bool(v) for v in values} if values is not None else set()
    except TypeError:  # not decided at some point (a value that is not real: sympy refuses
        return None    # to build the comparison itself, or to say whether it holds)
    return seen.pop() if len(seen) == 1 else None


def existing(pieces, where: sp.Basic, model) -> list[Piece] | None:
    """The pieces on which ``where`` (an equilibrium's existence) holds and the
    assumptions allow (``allowed``: R < r is no case under R > r); None where one lies
    partly inside ``where`` (the pieces do not line up with it)."""
    kept = []
    for piece in pieces:
        inside = within(piece, where, model)
        if inside is None:
            return None
        if inside and allowed(piece, model):
            kept.append(piece)
    return kept


def existing_within_bounds(pieces, where: sp.Basic, model) -> list[Piece] | None:
    """``existing``, or, where a piece lies partly inside ``where`` (an And of conditions
    each needed for an equilibrium to exist), the pieces inside its bounds on the pieces'
    own parameter: a piece outside one of them has no equilibrium; the other bounds
    (another parameter's range) are the existence's to say, beside the cases."""
    kept = existing(pieces, where, model)
    if kept is None and pieces:
        p = pieces[0].parameter
        bounds = [c for c in sp.And.make_args(where) if isinstance(c, sp.Rel) and c.lhs == p]
        kept = existing(pieces, sp.And(*bounds), model)
    return kept


def changes(pieces) -> tuple[Critical, ...]:
    """The critical values between neighbouring pieces (where one ends and the next
    begins): where what the pieces carry changes."""
    return tuple(Critical(a.parameter, a.high) for a, b in zip(pieces, pieces[1:])
                 if a.high is not None and a.high == b.low)


def what_decides(f: sp.Expr, values: Mapping = {}) -> str:
    """What a user can give to decide the sign of f, for a message: the values of its
    parameters that have none (``values``: those given), or an assumption."""
    names = ", ".join(sorted(str(s) for s in f.free_symbols if s not in values) or
                      sorted(str(s) for s in f.free_symbols))
    return (f"give values for {names}, or state the sign of {to_unicode(f)} under 'assumptions:'"
            + _assumption_example(f))


def _assumption_example(f: sp.Expr) -> str:
    """An assumption that decides f's sign, in the file's own names: one linear in one
    of f's parameters is solved for it (model/assumptions.py), so where f is such a
    parameter's multiple its own sign serves ([k < 0]); otherwise what kind of
    assumption does."""
    linear = [p for p in sorted(f.free_symbols, key=str)
              if not isinstance(p, sp.Dummy) and (f / p).free_symbols.isdisjoint({p}) and not p.is_positive]
    if linear:
        return f" (such as [{linear[0]} > 0] or [{linear[0]} < 0])"
    return " (an inequality between its parameters that is linear in one of them)"


def real_where(values: Iterable[sp.Expr]) -> list[sp.Expr]:
    """What must be ≥ 0 for the values to be real: radicands, 1 − c² under acos and asin."""
    needed = set()
    for value in values:
        needed |= {p.base for p in value.atoms(sp.Pow) if square_root(p)}
        needed |= {1 - f.args[0] ** 2 for f in value.atoms(sp.acos, sp.asin)}
    return sorted(needed, key=sp.default_sort_key)


def divided_radicands(values: Iterable[sp.Expr]) -> list[sp.Expr]:
    """The radicands that stand under a square root in a denominator, 1/√c: a value is
    infinite where c = 0, so it is real only where c > 0, not c ≥ 0 (a rod as a conical
    pendulum: Ω = √(3 g/(2 l cos α)) needs α < π/2)."""
    found = {p.base for value in values for p in value.atoms(sp.Pow)
             if square_root(p) and p.exp < 0}
    return sorted(found, key=sp.default_sort_key)


@dataclass(frozen=True)
class Existence:
    """Where values are real: the condition, solved for one parameter each (true:
    always), and the critical values it uses."""

    condition: sp.Basic
    criticals: tuple[Critical, ...]


def exists_when(values: Iterable[sp.Expr], model, nonnegative: Iterable[sp.Expr] = (),
                first: sp.Symbol | None = None, positive: Iterable[sp.Expr] = ()) -> Existence | None:
    """Where ``values`` are real (``real_where``), ``nonnegative`` ones are ≥ 0 (the
    value of a square, ω₀²) and ``positive`` ones > 0: each condition the assumptions do
    not decide, piece by piece, holds on its positive pieces, a boundary included where
    the condition is finite there and may be zero (ω² ≥ g/R, but R > r where 1/(R − r)
    is, and k > m g/L where a spring would be at zero length); None where one cannot be
    split. A radicand under a root in a denominator (``divided_radicands``) is positive."""
    values = list(values)
    exists, criticals = sp.true, []
    strict = [tidy(x) for x in (*positive, *divided_radicands(values))]
    for condition in dict.fromkeys([*real_where(values), *nonnegative, *positive]):
        condition = tidy(condition)
        if isinstance(sign_of(condition, model.assumed), int):
            continue
        found, size, split = _split(condition, model, first)
        if found is None:
            # no change of sign in any parameter: where it keeps one, proved with each angle
            # parameter in (0, π) (an incline's g m sin α + 6 k r), that sign decides
            sign = angle_sign(condition, model)
            if sign is None:
                return None
            if sign < 0 or (sign == 0 and condition in strict):
                return Existence(sp.false, ())
            continue
        closed = {c.value: condition not in strict and _finite_at(split, c) for c in found.criticals}
        held = [piece.when(closed.get(piece.low, False), closed.get(piece.high, False)).xreplace(size)
                for piece in found.pieces if piece.sign > 0]
        exists = sp.And(exists, sp.Or(*held))
        criticals += found.criticals
    exists, implied = tightest_bounds(exists, model)
    return Existence(exists, tuple(c for c in criticals if c.value not in implied))


def constant_sign(f: sp.Expr, model, first: sp.Symbol | None = None) -> int | None:
    """f's sign where it keeps one throughout: the first parameter (``candidates``) in
    whose range f has no root at any sample, f's sign on the whole range (``sign_on``:
    exactly, else agreeing samples). An inverted plate held by a spring, released from
    rest at θ₀ in (0, π), has θ̇² ∝ g m (cos θ₀ − 1) − 2 h k sin θ₀ < 0 at θ = 0: it
    never gets there. None where no parameter shows it."""
    angles = angle_parameters(f)
    for p in candidates(f, model, angles, first):
        if parameter_roots(f, p, angles, model) == []:
            sign = sign_on(f, Piece(p, None, None, 0, angles.get(p, (sp.Integer(0), sp.oo))), model, angles)
            if sign is not None:
                return sign
    return None


def nonnegative_where(value: sp.Expr, model, first: sp.Symbol | None = None) -> Existence:
    """Where value ≥ 0: true or false where the parameters' signs and the assumptions
    decide it, or where it keeps one sign throughout (``constant_sign``); else solved
    for one parameter (``exists_when``, ``first`` before all), true where the
    assumptions imply what it gives (α ≤ π/2 under 0 < α < π/2); else value ≥ 0 as it
    is. A support that holds at a state, a configuration the motion reaches (q̇² ≥ 0
    there)."""
    sign = sign_of(tidy_fraction(value), model.assumed)
    if isinstance(sign, int):
        return Existence(sp.true if sign >= 0 else sp.false, ())
    found = exists_when((), model, [value], first)
    if found is None:
        sign = constant_sign(tidy_fraction(value), model, first)
        return Existence(sp.Ge(value, 0) if sign is None else sp.true if sign > 0 else sp.false, ())
    if implies(model.assumptions, found.condition):
        return Existence(sp.true, ())
    return found


def _finite_at(f: sp.Expr, critical: Critical) -> bool:
    """Whether f is finite at the critical value (its numerator vanishes there, not its
    denominator): a boundary where the condition holds with equality."""
    _, denominator = quotient(f)
    return not simplifies_to_zero(denominator.xreplace({critical.parameter: critical.value}))


def sign_on(f: sp.Expr, piece: Piece, model, angles: dict, seed: int = 20) -> int | None:
    """f's sign on a piece: exactly (δ positive), else by agreeing samples (drawn from
    ``seed``).

    The samples are asked first: where sympy's assumptions decide the sign at the
    δ-point, it holds at every point of the piece, so samples that all agree give the
    same sign, and one that decides nothing (a long sum of nested radicals: a tenth of a
    second per query) is never asked. Where they do not all agree, it is as above —
    except where f is not real at a sample: then it has no sign on the piece, and
    sympy's assumptions, asked at the δ-point, could not give one (a rod in a bowl, λ =
    3 g √(4R² − l²)/(6R² − l²) past l = 2R: two such queries took 0.8 s to say nothing)."""
    numbers = [_number(v) for v in at_samples(piece, f, model, seed, angles) or [sp.nan]]
    if any(z is not None and _off_the_reals(z) for z in numbers):
        return None
    sampled = _one_sign(numbers)
    if sampled is not None:
        return sampled
    value, _ = piece.inside(f)
    return symbolic_sign(tidy(value)) or None  # 0 there (f vanishes at the δ-point): no sign


def _number(v: sp.Expr) -> complex | None:
    """v to 30 digits, as a complex number; None where it is not a number."""
    try:
        z = complex(sp.N(v, 30))
    except TypeError:
        return None
    return None if cmath.isnan(z) else z


def _off_the_reals(z: complex) -> bool:
    """An imaginary part beyond the rounding of 30 digits, relative to the size."""
    return abs(z.imag) > 1e-12 * max(1.0, abs(z.real))


def _one_sign(numbers: list[complex | None]) -> int | None:
    """The one sign of the real numbers at the samples; None where they differ, or one
    is zero or not a number."""
    if any(z is None or z.real == 0 for z in numbers):
        return None
    signs = {1 if z.real > 0 else -1 for z in numbers}
    return signs.pop() if len(signs) == 1 else None
