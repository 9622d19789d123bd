"""Where a steady motion exists: a solution of the balances is a motion only where it
is real (issue 38). A heavy top's precession rates are the roots of

    (I₁ − I₃) cos θ Ω² − I₃ s Ω + m g h = 0,

real only where the discriminant I₃² s² − 4 (I₁ − I₃) m g h cos θ is ≥ 0; solved for
the spin, s ≥ s_c, the least spin of every such exercise.

Each condition a solution needs (its radicands ≥ 0, 1 − c² under acos and asin, the
value of a square asked for ≥ 0: ``real_where``) is

- a discriminant A p² + C in a rate p, A > 0 (``least_rate``): p ≥ p_c = √(−C/A) where
  C < 0, true where C ≥ 0, p² ≥ −C/A where C's sign is open;
- dropped where the assumptions make it hold for every value (its sign is ≥ 0);
- false where they make it fail for every value: the solution is never real, and is
  not listed;
- else solved for one parameter (``exists_when`` of solvers/conditions/conditions.py: rates first;
  at the given values of the others, where the problem gives some);
- else stated as it is, ``D ≥ 0``: never dropped as if it always held.

At the given values a solution whose condition fails is no motion: its numbers are
not printed (a complex rate is no rate), and a warning names what it needs, "no
steady motion at s = 50: every solution needs s ≥ s_c = 159.647".
"""

from __future__ import annotations

import random
from typing import Sequence

import sympy as sp
from sympy.logic.boolalg import BooleanAtom

from rbdsolve.form.printers import float_text, to_unicode
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.solvers.conditions.condition_roots import admissible, angle_parameters
from rbdsolve.solvers.conditions.conditions import (Critical, CriticalValue, critical_values, divided_radicands,
                                                exists_when, real_where)
from rbdsolve.solvers.conditions.parameter_order import RATE_WORDS
from rbdsolve.solvers.conditions.present_conditions import critical_names
from rbdsolve.solvers.conditions.signs import sign_of
from rbdsolve.solvers.steady_motion.answers import Branch
from rbdsolve.form.zero import simplifies_to_zero


def with_existence(found: Sequence[dict], squares: Sequence[int], model: Model, first: sp.Symbol | None = None
                   ) -> tuple[tuple[Branch, ...], tuple[CriticalValue, ...]]:
    """Each solution ({asked quantity: value}) with where it is real (false: nowhere
    the assumptions allow; ``squares``: the positions of the asked quantities that are
    squares, ω₀², so ≥ 0), and the critical values those conditions use, solved for
    ``first`` (the question's ``for:``) where it names a parameter."""
    out, criticals = [], []
    known: dict[tuple[sp.Expr, bool], tuple[sp.Basic, tuple[Critical, ...]]] = {}  # ±√D share D: split once
    for solved in found:
        values = list(solved.values())
        needed = [*real_where(values), *(values[k] for k in squares)]
        divided = divided_radicands(values)  # 1/√c: c > 0
        condition = sp.true
        for c in needed:
            key = (c, c in divided)
            if key not in known:
                known[key] = _where_nonnegative(c, model, first, strict=c in divided)
            part, found_criticals = known[key]
            condition = sp.And(condition, part)
            criticals += found_criticals
        out.append(Branch(solved, condition))
    return tuple(out), critical_values(criticals)


def _where_nonnegative(c: sp.Expr, model: Model, first: sp.Symbol | None = None, strict: bool = False
                       ) -> tuple[sp.Basic, tuple[Critical, ...]]:
    """Where c ≥ 0 (c > 0 where ``strict``: c under a root in a denominator): a top's
    discriminant in its spin (``least_rate``); else solved for one parameter where one
    splits it (``exists_when``, which passes over a c whose sign the assumptions decide:
    then true where c ≥ 0, false where it is negative), else c ≥ 0 as it is."""
    c = tidy(c)
    found = None if strict else least_rate(c, model, first)
    if found is not None:
        return found
    split = exists_when((), model, [], first, positive=[c]) if strict else exists_when((), model, [c], first)
    if split is None:
        return (sp.StrictGreaterThan if strict else sp.GreaterThan)(c, 0), ()
    if split.condition is sp.true and _sign(c, model) == -1:
        return sp.false, ()
    return split.condition, split.criticals


def least_rate(c: sp.Expr, model: Model, first: sp.Symbol | None = None
               ) -> tuple[sp.Basic, tuple[Critical, ...]] | None:
    """c = A p² + C in a rate p ≥ 0 (a spin, a speed: parameter_order.RATE_WORDS), A > 0: the
    discriminant of a top's precession rates, I₃² s² − 4 (I₁ − I₃) m g h cos θ. Then

        c ≥ 0  ⟺  p ≥ p_c = √(−C/A)   where C < 0 (the least spin),
               always                  where C ≥ 0,
               p² ≥ −C/A               where C's sign is not decided (a disk top with
                                       h ≷ R/2 open: I₁ − I₃ = m (h² − R²/4)),

    signs decided as ``_sign`` decides them. None where c is not of this form, or where
    ``first`` (a question's ``for:``) names another parameter than the rate."""
    for p in _rates(c, model):
        if first is not None and p != first:
            continue
        polynomial = sp.Poly(c, p) if c.is_polynomial(p) else None
        if polynomial is None or polynomial.degree() != 2 or polynomial.coeff_monomial(p) != 0:
            continue
        A, C = polynomial.coeff_monomial(p**2), polynomial.coeff_monomial(1)
        if _sign(A, model) != 1:
            continue
        sign = _sign(C, model)
        if sign is not None and sign >= 0:
            return sp.true, ()
        square = sp.factor(-C / A)
        if sign is None:
            return sp.GreaterThan(p**2, square), ()
        least = _root(square)
        return sp.GreaterThan(p, least), (Critical(p, least),)
    return None


def _rates(c: sp.Expr, model: Model) -> list[sp.Symbol]:
    """The positive parameters of c named or described as rates, in the file's order."""
    out = []
    for parameter in model.problem.parameters:
        p = model.symbols.parameters[parameter.name]
        words = f"{parameter.name} {parameter.description}".lower()
        if p in c.free_symbols and p.is_positive and any(w in words for w in RATE_WORDS):
            out.append(p)
    return out


def _root(square: sp.Expr) -> sp.Expr:
    """√(g h m (…)/J₃²) kept as one root, the form an exam writes (sympy would split the
    root of a product of positive symbols)."""
    if square.has(sp.sqrt) or square.is_Pow:
        return tidy(sp.sqrt(square))
    return sp.Pow(square, sp.Rational(1, 2), evaluate=False)


SAMPLES = 8  # admissible points that decide a sign sympy does not


def _sign(x: sp.Expr, model: Model) -> int | None:
    """1, 0 or −1: by the parameters' signs, the assumptions and the values (exactly),
    else where every one of SAMPLES admissible points (the given values kept, angles in
    their ranges) agrees, as conditions.py decides a piece's sign; None otherwise."""
    sign = sign_of(x, model.decided_by)
    if isinstance(sign, int):
        return sign
    angles = angle_parameters(x)
    seen = set()
    for k in range(SAMPLES):
        point = admissible(model, random.Random(38 + k), (), angles)
        if point is None:
            return None
        z = complex(sp.N(x.xreplace(point), 20))
        if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)) or z.real == 0:
            return None
        seen.add(1 if z.real > 0 else -1)
    return seen.pop() if len(seen) == 1 else None


def absent_at_values(branches: Sequence[Branch], critical: Sequence[CriticalValue], model: Model,
                     motion: str = "steady motion") -> tuple[str, ...]:
    """A warning for each solution whose condition fails at the given values (one for
    all of them where every one fails): "no steady motion at s = 50: it needs
    s ≥ s_c = 83.02"; () where the values leave each condition undecided or every one
    holds."""
    values = dict(model.values)
    failing = [(k, b) for k, b in enumerate(branches, 1) if _at(b.exists_when, values) is sp.false]
    if not failing:
        return ()
    said = [_needs(b.exists_when, critical, values) for _, b in failing]
    if len(failing) == len(branches):
        at = sorted({a for _, a in said}) if all(a for _, a in said) else []
        needs = " or ".join(dict.fromkeys(n for n, _ in said))
        return (f"no {motion} at {', '.join(at) if at else 'the given values'}: "
                f"{'it needs' if len(branches) == 1 else 'every solution needs'} {needs}",)
    return tuple(f"solution {k} is no {motion} at {a or 'the given values'}: it needs {n}"
                 for (k, _), (n, a) in zip(failing, said))


def _at(condition: sp.Basic, values: dict) -> sp.Basic | None:
    """The condition at the values: true, false, or None where they do not decide it."""
    try:
        decided = condition.xreplace(values)
        if not isinstance(decided, BooleanAtom) and not decided.free_symbols:
            decided = decided.simplify()
    except TypeError:  # a side that is not real there: sympy will not compare it
        return None
    return decided if isinstance(decided, BooleanAtom) else None


OPS = {sp.StrictLessThan: "<", sp.LessThan: "≤", sp.StrictGreaterThan: ">", sp.GreaterThan: "≥"}


def _needs(condition: sp.Basic, critical: Sequence[CriticalValue], values: dict) -> tuple[str, str]:
    """('s ≥ s_c = 83.02', 's = 50'): the parts of the condition that fail at the
    values, each critical value by its name and number; and the value of the parameter
    they are solved for ('' where a part is not solved for a parameter with a value)."""
    parts = condition.args if isinstance(condition, sp.And) else (condition,)
    failing = [p for p in parts if _at(p, values) is sp.false] or [condition]
    texts = [_part_text(p, critical, values) for p in failing]
    at = ", ".join(dict.fromkeys(a for _, a in texts)) if all(a for _, a in texts) else ""
    return "; ".join(t for t, _ in texts), at


def _part_text(part: sp.Basic, critical: Sequence[CriticalValue], values: dict) -> tuple[str, str]:
    """One part: 's ≥ s_c = 83.02' and 's = 50'; 'D ≥ 0, which is −1.5 there' and ''."""
    if type(part) not in OPS:
        return to_unicode(part), ""
    lhs, rhs, op = part.lhs, part.rhs, OPS[type(part)]
    if not (isinstance(lhs, sp.Symbol) and lhs in values):
        return f"{to_unicode(lhs)} {op} {to_unicode(rhs)}, which is {_number(lhs, values)} there", ""
    named = [name for c, name in critical_names(critical)
             if c.parameter == lhs.name and simplifies_to_zero(c.value - rhs)]
    name = to_unicode(named[0]) if named else to_unicode(rhs)
    bound = f"{name} = {_number(rhs, values)}" if rhs.free_symbols else name
    return f"{to_unicode(lhs)} {op} {bound}", f"{to_unicode(lhs)} = {_number(lhs, values)}"


def _number(value: sp.Expr, values: dict) -> str:
    z = complex(sp.N(value.xreplace(values), 17))
    return float_text(z.real) if abs(z.imag) <= 1e-14 * max(1.0, abs(z.real)) else f"{z:.6g}"
