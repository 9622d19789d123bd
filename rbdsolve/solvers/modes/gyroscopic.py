"""Small oscillations with gyroscopic terms, exact: a sleeping top, a rotor in gimbals,
a body seen from a turning frame.

About a steady state (solvers/modes/routh.py) the motion is M ü + G u̇ + K u = 0, M and
K symmetric, G skew. u = X e^(iωt) gives

    (K − ω² M + i ω G) X = 0,   P(ω) = det(K − ω² M + i ω G) = 0,

the form an exam writes, with real ω for an oscillation. iG is Hermitian, so P is
real, and P(−ω) = det((K − ω²M + iωG)ᵀ) = P(ω): P is a polynomial p(λ) in λ = ω²
(Meirovitch, Methods of Analytical Dynamics, ch. 6.6; Merkin, Gyroscopic Systems).
Every small motion stays bounded — the motion is stable to first order — when every
root λ of p is real, positive and simple (ω = √λ real; a root λ = 0 is a neutral
direction, set apart). For a polynomial whose roots are all real, the number of its
positive roots is the number of sign changes of its coefficients (Descartes' rule,
exact when every root is real), so for p of degree n ≤ 3 (aₙ λⁿ + … + a₀, a₀ ≠ 0),
stability is each of

    n = 1:  −a₀/a₁ > 0
    n = 2:  Δ = a₁² − 4a₂a₀ > 0,  −a₁/a₂ > 0,  a₀/a₂ > 0
    n = 3:  Δ > 0 (three distinct real roots),  −a₂/a₃ > 0,  a₁/a₃ > 0,  −a₀/a₃ > 0

and the case analysis of these conditions on one parameter goes through the shared
machinery (solvers/conditions/conditions.py): the sleeping top, p(λ) = A²λ² + (2 A m g h −
C² s²) λ + m²g²h², is stable when Δ = C² s² (C² s² − 4 A m g h) > 0, s > s_c = 2√(A m g h)/C.

The frequencies are written as an exam writes them: P factored over the parameters;
a factor with odd powers of ω pairs with its mirror image f(−ω), and the roots of the
one whose roots sum to a positive value are the frequencies (A ω² − C s ω + m g h = 0:
ω = (C s ± √(C² s² − 4 A m g h))/(2A)); a factor in ω² gives ω = √λ. Below s_c that
factor's roots are complex: the motion grows at γ = √(4ac − b²)/(2|a|) for a ω² + b ω + c.
"""

from __future__ import annotations

import random
from dataclasses import replace

import sympy as sp

from rbdsolve.errors import NUMERIC_REMEDY, UnsolvedError
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.equilibria.answers import Stability
from rbdsolve.solvers.modes.about import exact_equilibrium
from rbdsolve.solvers.modes.answers import GyroscopicCase, GyroscopicModesAnswers
from rbdsolve.solvers.modes.gyroscopic_steps import gyroscopic_steps
from rbdsolve.solvers.modes.routh import Linear, linearize, slow_steady_state
from rbdsolve.solvers.routes.needed import missing_for
from rbdsolve.solvers.conditions.condition_roots import SAMPLES, admissible, angle_parameters
from rbdsolve.solvers.conditions.conditions import Piece, changes, critical_values, partition, sign_on
from rbdsolve.solvers.conditions.signs import Undecided, sign_of, symbolic_sign
from rbdsolve.model.values.values import sample
from rbdsolve.form.zero import simplifies_to_zero

OMEGA = sp.Symbol("omega")  # the variable of det(K − ω²M + iωG) (the JSON's characteristic)
LAMBDA = sp.Symbol("lamda")


def solve(question: Question, model: Model) -> Solution:
    """The exact route's answer about the steady state the question names. About one whose
    closed forms would take minutes in the parameters (``slow_steady_state``: a root of
    them, or a long expression), the values are put in first, so the answers are exact
    numbers; without a value for each, that is said at once rather than after the
    budget."""
    refuse_options(question)
    at, notes = _steady_state(question, model)
    slow = slow_steady_state(question, model)
    if slow and missing_for(model, question):
        raise UnsolvedError(slow, NUMERIC_REMEDY)
    linear = linearize(question, model, at, model.values if slow else None)
    answers = gyroscopic_modes(linear, model)
    return Solution("modes", Route.EXACT, answers, gyroscopic_steps(answers, linear, model), warnings=notes)


def refuse_options(question: Question) -> None:
    """What the gyroscopic route does not answer, said rather than ignored (both routes)."""
    if question.options.each:
        raise UnsolvedError("'about: each' is not available where the scene has gyroscopic terms: name the steady "
                            "state, about: {…}")
    if question.options.check_amplitudes:
        raise UnsolvedError("'check_amplitudes' simulates normal modes, and the scene has gyroscopic terms (its "
                            "modes are not normal modes): ask without it")


def _steady_state(question: Question, model: Model) -> tuple[dict, tuple[str, ...]]:
    """{q: value} of the coordinates kept: given (every one but the cyclic ones), or the
    equilibrium 'about: {equilibrium: N}' or the first stable one (by K alone) names."""
    options = question.options
    if options.about is not None:
        values = dict(options.about)
        return {q: model.symbols.scalar(values[n]) for q, n in zip(model.q, model.coordinate_names())
                if n in values}, ()
    try:
        return exact_equilibrium(question, model)
    except UnsolvedError as exc:
        raise UnsolvedError(f"{exc.reason} (stable by K alone: with gyroscopic terms an equilibrium unstable by K "
                            "may be held by the spin: name it, about: {…})", exc.remedy) from None


def gyroscopic_modes(linear: Linear, model: Model) -> GyroscopicModesAnswers:
    """The characteristic polynomial, the frequencies, the stability and its cases."""
    P = characteristic(linear)
    lam_poly, zeros = _in_lambda(P, len(linear.names))
    frequencies, growth = frequency_forms(P, model)
    conditions = stability_conditions(lam_poly)
    stability, cases, critical = _stability(conditions, lam_poly, model, growth)
    return GyroscopicModesAnswers(dict(linear.about), dict(linear.steady), dict(linear.momenta), linear.M, linear.G,
                                  linear.K, P, tuple(frequencies), stability, tuple(conditions), tuple(cases),
                                  critical_values(critical), zeros)


def characteristic(linear: Linear) -> sp.Expr:
    """P(ω) = det(K − ω²M + iωG), expanded: real and even in ω."""
    pencil = linear.K - OMEGA**2 * linear.M + sp.I * OMEGA * linear.G
    P = sp.expand(sp.Matrix(pencil).det(method="berkowitz"))
    if P.has(sp.I):
        P = sp.expand(sp.re(P)) if simplifies_to_zero(sp.im(P)) else P
    return tidy(P) if not P.has(sp.I) else P


def _in_lambda(P: sp.Expr, n: int) -> tuple[sp.Poly, int]:
    """p(λ) with P(ω) = p(ω²), its zero roots λ = 0 (neutral directions) divided out,
    and how many there were."""
    poly = sp.Poly(P, OMEGA)
    terms = {k: c for (k,), c in poly.terms()}
    if any(k % 2 for k in terms):
        raise UnsolvedError("det(K − ω²M + iωG) is not even in ω: G is not skew (an internal inconsistency)")
    lam = sp.Poly({(k // 2,): c for k, c in terms.items()}, LAMBDA)
    zeros = 0
    while lam.degree() > 0 and lam.eval(0) == 0:
        lam = sp.Poly(sp.cancel(lam.as_expr() / LAMBDA), LAMBDA)
        zeros += 1
    return lam, zeros


def stability_conditions(lam: sp.Poly) -> list[sp.Expr]:
    """What must be > 0 for every root of p(λ) to be real, positive and simple (degree ≤ 3;
    see the module docstring); [] for a constant p (every direction neutral)."""
    a = [tidy(c) for c in reversed(lam.all_coeffs())]  # a₀, a₁, …
    n = lam.degree()
    if n <= 0:
        return []
    if n > 3:
        raise UnsolvedError(f"the characteristic polynomial in ω² has degree {n}: stability is given for degree "
                            "≤ 3 (three coordinates) on the exact route; the numeric route answers with values")
    signs = [(-1) ** (n - k) for k in range(n)]  # −a₀/a₁ for n = 1; a₀/a₂, −a₁/a₂ for n = 2 …
    ratios = [essential(s * a[k] / a[n]) for k, s in enumerate(signs)]
    found = ratios if n == 1 else [essential(sp.discriminant(lam.as_expr(), LAMBDA)), *reversed(ratios)]
    return [f for f in found if f != 1]


def essential(expr: sp.Expr) -> sp.Expr:
    """The factor of ``expr`` that carries its sign: the factored form with each factor
    that the parameters' signs make positive left out (C² s² (C² s² − 4 A m g h)/A² > 0
    is C² s² − 4 A m g h > 0), a negative one turning the sign; 1 where none is left."""
    kept, sign = [], 1
    for factor in sp.Mul.make_args(sp.factor(tidy(expr))):
        decided = symbolic_sign(factor)
        base, exp = factor.as_base_exp()
        if decided == 1 or (exp.is_Integer and exp % 2 == 0 and base.is_real is not False):
            continue  # an even power is positive but where its base vanishes: a neutral root, not a loss
        if decided == -1:
            sign = -sign
            continue
        kept.append(factor)
    return sign * sp.Mul(*kept)


def frequency_forms(P: sp.Expr, model: Model) -> tuple[list[sp.Expr], list[sp.Expr]]:
    """The frequencies ω > 0 as an exam writes them (the module docstring), ascending at
    the values (or a sample), and the quadratic factors a ω² + b ω + c they come from
    (for the growth rate where their roots are complex)."""
    factors = [f for f, k in sp.factor_list(P, OMEGA)[1] for _ in range(k) if sp.Poly(f, OMEGA).degree() > 0]
    out, quadratics, used = [], [], set()
    for i, f in enumerate(factors):
        if i in used:
            continue
        poly = sp.Poly(f, OMEGA)
        if poly.as_expr() == OMEGA:  # ω = 0 twice over (P is even): a neutral direction
            used.add(i)
            continue
        if all(k % 2 == 0 for (k,), _ in poly.terms()):
            used.add(i)
            out += [_root(tidy(x)) for x in _all_roots(sp.Poly({(k // 2,): c for (k,), c in poly.terms()}, LAMBDA))]
            continue
        mirror = next((j for j, g in enumerate(factors) if j != i and j not in used
                       and sp.expand(g + f.subs(OMEGA, -OMEGA)) == 0 or j != i and j not in used
                       and sp.expand(g - f.subs(OMEGA, -OMEGA)) == 0), None)
        if mirror is None:
            raise UnsolvedError("det(K − ω²M + iωG) has a factor without its mirror image in ω")
        used |= {i, mirror}
        chosen = _positive_of(poly, sp.Poly(factors[mirror], OMEGA), model)
        if chosen.degree() == 2:
            out += _quadratic_frequencies(chosen, model)
            quadratics.append(chosen.as_expr())
        else:
            out += [_positive(tidy(x), model) for x in _all_roots(chosen)]
    return sorted(out, key=lambda w: sample(w, model.values).real), quadratics


def _quadratic_frequencies(f: sp.Poly, model: Model) -> list[sp.Expr]:
    """The roots of a ω² + b ω + c (its roots summing to a positive value) by the
    quadratic formula, ω = (−b ± √(b² − 4ac))/(2a), as an exam writes them; where
    c/a < 0 the roots have opposite signs and the smaller one is taken with its sign
    turned: the gimbals' (√(C² s² + 4 A k) ∓ C s)/(2A)."""
    a, b, c = f.all_coeffs()
    if sign_of(a, model.decided_by) == -1:
        a, b, c = -a, -b, -c
    root = squares_out(sp.sqrt(sp.factor(tidy(b**2 - 4 * a * c))))
    low, high = tidy((-b - root) / (2 * a)), tidy((-b + root) / (2 * a))
    if sign_of(c / a, model.decided_by) == -1:
        return [high, tidy((b + root) / (2 * a))]
    return [low, high]


def _positive_of(f: sp.Poly, mirror: sp.Poly, model: Model) -> sp.Poly:
    """Of a factor and its mirror image, the one whose roots sum to a positive value."""
    a = f.all_coeffs()
    total = -a[1] / a[0]
    sign = sign_of(total, model.decided_by)
    if isinstance(sign, Undecided) or sign == 0:
        raise UnsolvedError(f"which of ±ω are the frequencies depends on the sign of {sp.sstr(total)}: "
                            "state it under 'assumptions:'")
    return f if sign > 0 else mirror


def _positive(root: sp.Expr, model: Model) -> sp.Expr:
    """A root ω of the chosen factor, turned positive where the parameters (or values)
    make it negative: Ω − √(k/m) is √(k/m) − Ω where √(k/m) > Ω."""
    sign = sign_of(root, model.decided_by)
    return tidy(-root) if sign == -1 else root


def _all_roots(poly: sp.Poly) -> list[sp.Expr]:
    found = sp.roots(poly)
    if sum(found.values()) != poly.degree():
        raise UnsolvedError(f"no closed form for the roots of a factor of degree {poly.degree()} of "
                            "det(K − ω²M + iωG); the numeric route answers with values")
    return [r for r, k in found.items() for _ in range(k)]


def _root(lam: sp.Expr) -> sp.Expr:
    """ω = √λ."""
    return tidy(sp.sqrt(lam))


def _stability(conditions: list[sp.Expr], lam: sp.Poly, model: Model, quadratics: list[sp.Expr]):
    """The stability at the values or for every value, its cases on one parameter where
    that changes it, and the critical values."""
    if lam.degree() <= 0:
        return Stability.NEUTRAL, [], []
    if not conditions:
        return Stability.STABLE, [], []
    signs = [sign_of(f, model.decided_by) for f in conditions]
    found = _cases(conditions, model, quadratics)
    if any(s == -1 or s == 0 for s in signs):
        stability = Stability.UNSTABLE
    elif all(s == 1 for s in signs):
        stability = Stability.STABLE
    else:
        stability = Stability.DEPENDS if found else Stability.UNDETERMINED
    if found is None:
        return stability, [], []
    cases, critical = found
    return stability, cases, critical


def _cases(conditions: list[sp.Expr], model: Model, quadratics: list[sp.Expr]):
    """(cases, critical values) where the assumptions alone leave the stability open and
    one parameter's values split it: each condition's own partition of that parameter's
    range (solvers/conditions/conditions.py), the pieces between all their critical values
    taken together, stable where every condition is positive; None where they do not
    split alike."""
    assumed = [sign_of(f, model.assumed) for f in conditions]
    if any(s == -1 or s == 0 for s in assumed):
        return None
    open_ = sorted((f for f, s in zip(conditions, assumed) if not isinstance(s, int)), key=sp.count_ops)
    parts = [partition(f, model) for f in open_]
    if not parts or None in parts or len({x.parameter for x in parts}) != 1:
        return None
    p, span = parts[0].parameter, parts[0].pieces[0].span
    angles = {k: v for f in open_ for k, v in angle_parameters(f).items()}
    bounds = _in_order([x.value for part in parts for x in part.criticals], p, model, angles)
    if bounds is None:
        return None
    parts = [replace(part, pieces=tuple(replace(x, low=_out(x.low), high=_out(x.high)) for x in part.pieces))
             for part in parts]
    bounds = [squares_out(b) for b in bounds]
    merged: list[Piece] = []
    for low, high in zip([None, *bounds], [*bounds, None]):
        stable = all(_sign_within(part, low, bounds) > 0 for part in parts)
        sign = 1 if stable else -1
        if merged and merged[-1].sign == sign:
            merged[-1] = Piece(p, merged[-1].low, high, sign, span)
        else:
            merged.append(Piece(p, low, high, sign, span))
    if len(merged) < 2:
        return None
    cases = [GyroscopicCase(piece.when(), Stability.STABLE if piece.sign > 0 else Stability.UNSTABLE,
                            None if piece.sign > 0 else _growth(piece, quadratics, model, angles))
             for piece in merged]
    return cases, list(changes(merged))


def _out(value: sp.Expr | None) -> sp.Expr | None:
    return None if value is None else squares_out(value)


def _in_order(values: list[sp.Expr], p: sp.Symbol, model: Model, angles: dict) -> list[sp.Expr] | None:
    """The critical values, each once, in increasing order at every sample of the other
    parameters (None where the order changes between samples)."""
    distinct: list[sp.Expr] = []
    for v in values:
        if not any(simplifies_to_zero(v - d) for d in distinct):
            distinct.append(v)
    orders = set()
    for k in range(SAMPLES):
        point = admissible(model, random.Random(41 + k), (p,), angles)
        if point is None:
            return None
        numbers = [complex(sp.N(v.xreplace(point), 20)).real for v in distinct]
        orders.add(tuple(sorted(range(len(distinct)), key=numbers.__getitem__)))
    if len(orders) != 1:
        return None
    return [distinct[i] for i in orders.pop()]


def _sign_within(part, low, bounds: list[sp.Expr]) -> int:
    """A partition's sign on the merged piece that starts at ``low``: that of its own
    piece whose ends bracket it."""
    def position(value, default: int) -> int:
        return default if value is None else next(i for i, b in enumerate(bounds) if simplifies_to_zero(value - b))

    start = position(low, -1)
    for piece in part.pieces:
        if position(piece.low, -1) <= start < position(piece.high, len(bounds)):
            return piece.sign
    raise AssertionError("a partition does not cover its parameter's range")


def squares_out(value: sp.Expr) -> sp.Expr:
    """√(4 A m g h/C²) as 2 √(A m g h)/C: the square factors of a root taken out, the
    rest left under one root (√(g/R) stays)."""
    if not (isinstance(value, sp.Pow) and value.exp == sp.S.Half):
        return value
    outside, inside = sp.Integer(1), sp.Integer(1)
    for part, power in ((sp.fraction(sp.factor(value.base))[0], 1), (sp.fraction(sp.factor(value.base))[1], -1)):
        for factor in sp.Mul.make_args(part):
            base, exp = factor.as_base_exp()
            if factor.is_Rational:
                root = sp.sqrt(factor)
                square = sp.Integer(sp.fraction(root)[0].as_coeff_Mul()[0]) ** 2  # 12 -> 4
                outside *= sp.sqrt(square) ** power
                inside *= (factor / square) ** power
            elif exp.is_Integer and exp > 1 and (base.is_positive or exp % 2 == 0):
                outside *= base ** (power * (exp // 2))
                inside *= base ** (power * (exp % 2))
            else:
                inside *= factor ** power
    if outside == 1:
        return value
    if inside == 1:
        return outside
    top, bottom = sp.fraction(outside)  # kept apart, so that the root of a product stays one root
    return sp.Mul(*[x for x in sp.Mul.make_args(top) if x != 1], sp.Pow(inside, sp.S.Half, evaluate=False),
                  *[sp.Pow(x, -1) for x in sp.Mul.make_args(bottom) if x != 1], evaluate=False)


def _growth(piece: Piece, quadratics: list[sp.Expr], model: Model, angles: dict) -> sp.Expr | None:
    """Where a frequency factor a ω² + b ω + c has complex roots on the whole piece,
    the growth rate γ = √(4ac − b²)/(2|a|) of its motion; None otherwise."""
    rates = []
    for f in quadratics:
        a, b, c = sp.Poly(f, OMEGA).all_coeffs()
        inside = tidy(4 * a * c - b**2)
        if sign_on(inside, piece, model, angles, seed=31) == 1:
            rates.append(tidy(sp.sqrt(inside) / (2 * abs(a))))
    return rates[0] if len(rates) == 1 else None
