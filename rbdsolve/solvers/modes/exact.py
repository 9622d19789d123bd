"""Small oscillations about an equilibrium: normal modes.

With q = q₀ + u and u small, Lagrange's equations linearize to

    M ü + K u = 0,   M = ∂²T/∂q̇∂q̇ |_(q₀),   K = ∂²V/∂q∂q |_(q₀)

(e.g. Goldstein, ch. 6). M comes from the velocity Jacobians at q₀ and K from the
Hessian of V at q₀: the nonlinear equations of motion are never built. Trying
u = a cos(ωt) gives det(K − λM) = 0 with λ = ω². When M = s_M M̂ and K = s_K K̂ with
rational M̂, K̂ (the usual case: s_M = m r², s_K = m g r), the characteristic
polynomial is taken over the rationals in the dimensionless μ = λ s_M / s_K, which is
fast and exact; otherwise over the parameters.

λ > 0: oscillation at ω = √λ; λ < 0: exponential growth at rate γ = √−λ (the solutions
e^(±γt) a); λ = 0: neutral, its mode shape the direction of no restoring force.

A root of multiplicity k has a k-dimensional mode space (K and M symmetric, M > 0:
the pencil is diagonalizable, Parlett, The Symmetric Eigenvalue Problem, §15.3); its
null space basis is made M-orthogonal (Gram–Schmidt in the inner product uᵀ M v) and
each vector scaled so its first nonzero entry is 1.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import TYPE_CHECKING, Mapping

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.arrange import common_scale, configuration
from rbdsolve.form.display import Relation
from rbdsolve.form.tidy import tidy
from rbdsolve.model.assumptions import admissible_sample
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import mass_matrix, potential_energy, stiffness_matrix
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.modes import gyroscopic_terms
from rbdsolve.solvers.modes.about import exact_equilibrium
from rbdsolve.solvers.modes.cases import absent, existence, kinds
from rbdsolve.report import steps as st
from rbdsolve.solvers.equilibria.cases import necessary_where, stiffness_at
from rbdsolve.solvers.equilibria.exact import incomplete, listing
from rbdsolve.solvers.equilibria.higher_order import degenerate_minimum_note
from rbdsolve.solvers.conditions.present_conditions import condition_relations
from rbdsolve.solvers.modes.answers import (CERTIFIED_DEGREE, EachModesAnswers, Form, ModesAnswers, Motion, Skipped,
                                             none_answered, with_amplitude_check)
from rbdsolve.form.arrange import descending
from rbdsolve.solvers.modes.steps import exact_steps, mode_labels
from rbdsolve.solvers.conditions.conditions import critical_values
from rbdsolve.solvers.conditions.parameter_order import asked
from rbdsolve.solvers.conditions.polynomial import plain_linear_root
from rbdsolve.solvers.lagrange.frames import require_static
from rbdsolve.solvers.routes.needed import missing_values
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.configuration.singular import exact_reason
from rbdsolve.model.values.values import sample

if TYPE_CHECKING:
    from rbdsolve.solvers.modes.certified import CertifiedRoot

LAMBDA = sp.Symbol("lamda")  # sympy's spelling: "lambda" is a Python keyword (the JSON's characteristic)
MU = sp.Symbol("mu")


def _det(labels) -> sp.Expr:
    """det(K − λM) as it is written, in that order (non-commutative symbols keep it), in
    the labels the solution prints."""
    K, lam, M = (sp.Symbol(labels.name(k), commutative=False)
                 for k in ("stiffness_matrix", "eigenvalue", "mass_matrix"))
    return sp.Function("det")(K - lam * M)


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_static(model, "small oscillations")
    if gyroscopic_terms.applies(question, model):
        from rbdsolve.solvers.modes import gyroscopic  # that route, only for such a scene

        return gyroscopic.solve(question, model)
    first = asked(model, question)
    if question.options.each:
        return _at_each(model, first)
    at, notes = exact_equilibrium(question, model)
    notes += gyroscopic_terms.spin_notes(question, model)
    where = existence(at, model, first)
    missing = absent(at, where, model)
    if missing:
        raise UnsolvedError(missing)
    # as about each: a case outside a condition the equilibrium needs is dropped
    answers, steps = modes_at(at, model, necessary_where(at, model, first), first)
    notes += degenerate_minimum_note(model, at, stiffness_at(model, at))
    answers = replace(answers, exists_when=where)  # a script reads where it holds, as the text says
    if where is not sp.true:  # a case outside it is left out: say so
        steps = (st.note("The equilibrium exists only where the following holds; its small motions are "
                         "answered there:", *condition_relations(where)), *steps)
    return with_amplitude_check(question, model, Solution("modes", Route.EXACT, answers, steps, warnings=notes))


def partial(question: Question, model: Model) -> str | None:
    """The route choice's check (solvers/routes/routes.py), read from the structure: where the
    modes are taken about an equilibrium the exact route must find (no ``about`` point,
    ``about: each``, or ``about: {equilibrium: N}``), why its list of equilibria would be
    partial; about a given point, why its eigenvalues would take minutes (``_slow_spectrum``).
    A scene with gyroscopic terms has its own exact route and no such check."""
    if gyroscopic_terms.applies(question, model):
        # its own exact route (Routh, det(K − ω²M + iωG)), slow only about a steady state with roots in it,
        # or a long one
        from rbdsolve.solvers.modes.routh import slow_steady_state  # (loaded where the scene spins)

        return slow_steady_state(question, model)
    if question.options.about is None:
        return incomplete(model)
    given = dict(question.options.about)
    names = model.coordinate_names()
    if set(given) != set(names):
        return None
    return _slow_spectrum({q: model.symbols.scalar(given[n]) for n, q in zip(names, model.q)}, model)


SYMBOLIC_DEGREE = 3  # det(K − λM) over the parameters from this degree: Cardano's and Ferrari's forms


def _slow_spectrum(at: dict, model: Model) -> str | None:
    """Why det(K − λM) = 0 has no quick exact roots here, or None: M and K are not each
    a common scale times a rational matrix (``_spectrum``'s fast route, over QQ), so the
    polynomial's coefficients hold the parameters, and its degree is 3 or more (four
    rods with springs, symbolic: over three minutes of processor time in the roots,
    their signs and the mode shapes)."""
    n = len(model.q)
    if n < SYMBOLIC_DEGREE:
        return None
    symbols = set(model.symbols.parameters.values())
    M = sp.Matrix(mass_matrix(model, at))
    K = sp.Matrix(stiffness_matrix(potential_energy(model).total, model.q, at))
    if _rational(M / common_scale(list(M), symbols)) and _rational(K / common_scale(list(K), symbols)):
        return None
    return (f"the eigenvalues are the roots of det(K − λM), of degree {n}, whose coefficients hold the parameters "
            "(M and K have no common scale): their closed forms (Cardano's, Ferrari's) take minutes")


def _at_each(model: Model, first: sp.Symbol | None) -> Solution:
    """The modes at every listed equilibrium, each under its own heading; one that
    cannot be answered (a singular M, a sign rbdsolve cannot split) says why."""
    names = model.coordinate_names()
    found, skipped, steps = [], [], []
    for k, listed in enumerate(listing(model).equilibria, 1):
        about = {n: listed.at[q] for n, q in zip(names, model.q)}
        where = existence(listed.at, model, first)
        bounds = [] if where is sp.true else condition_relations(where)
        steps.append(st.result(f"About equilibrium {k}" + (" (it exists only where the following holds)"
                                                            if bounds else "") + ":",
                               configuration(model.state.functions(), list(about.values())), *bounds))
        try:
            # a case outside a condition the equilibrium needs is dropped, even where the
            # whole condition cannot be split (the text and the JSON say only what can)
            answers, more = modes_at(listed.at, model, necessary_where(listed.at, model, first), first)
        except UnsolvedError as exc:
            skipped.append(Skipped(about, str(exc)))
            steps.append(st.note(f"Not answered here: {exc}."))
            continue
        found.append(replace(answers, exists_when=where))  # a script reads where it holds, as the text says
        steps += more
    if not found:
        raise UnsolvedError(none_answered(skipped, "among the roots of ∂V/∂q = 0"))
    return Solution("modes", Route.EXACT, EachModesAnswers(tuple(found), tuple(skipped)), tuple(steps))


def modes_at(at: dict, model: Model, where: sp.Basic = sp.true,
             first: sp.Symbol | None = None) -> tuple[ModesAnswers, tuple]:
    """The small oscillations about the equilibrium ``at`` ({q: value}) and their steps;
    ``where``: where it exists (a case outside it is dropped); ``first``: the parameter
    the cases are written in where they can be (a question's ``for:``)."""
    chosen = {n: at[q] for n, q in zip(model.coordinate_names(), model.q)}
    M = sp.ImmutableMatrix(mass_matrix(model, at))
    # the equilibria's own K there, once per model and root (the equilibria question has
    # made it where both are asked: 0.4 s of a bead on an offset turning rod's three), its
    # Hessian not tidied before the root goes in (at θ₀ = acos(…) of six parameters that
    # made 333 operations 18 848, six seconds to factor)
    K = stiffness_at(model, at)
    singular = exact_reason(M, model.coordinate_names(), "at this configuration")
    if singular:
        raise UnsolvedError(singular)
    if K.has(sp.DiracDelta):
        raise UnsolvedError("K = ∂²V/∂q∂q does not exist at this configuration: a spring's length |…| is zero "
                            "there, where V is not twice differentiable")
    spectrum = _spectrum(K, M, set(model.symbols.parameters.values()), model)
    note = ""
    if _unreadable(spectrum) and model.values and not missing_values(model):
        values = dict(model.values)
        spectrum = _spectrum(sp.ImmutableMatrix(K.xreplace(values)), sp.ImmutableMatrix(M.xreplace(values)),
                             set(model.symbols.parameters.values()), model)
        note = (f"With every value given, the eigenvalues in the parameters run to more than {READABLE_OPS} "
                "operations each: they are solved at the values, exactly.")
    eigenvalues = [pair.lam for pair in spectrum.pairs]
    motions, cases, criticals = kinds(eigenvalues, K, model, where, first, at)
    frequencies = tuple(_rate(pair, spectrum.scale, 1) if mo in (Motion.OSCILLATION, Motion.DEPENDS) else None
                        for pair, mo in zip(spectrum.pairs, motions))
    shapes = _shapes(spectrum, model.values)
    rates = tuple(_rate(pair, spectrum.scale, -1) if mo in (Motion.GROWTH, Motion.DEPENDS) else None
                  for pair, mo in zip(spectrum.pairs, motions))
    certified = [pair.certified for pair in spectrum.pairs]
    answers = ModesAnswers(chosen, M, K, spectrum.characteristic, tuple(eigenvalues), frequencies, motions, shapes,
                           rates, tuple(eigenvalues.count(lam) for lam in eigenvalues), None,
                           cases if any(cases) else (), critical_values(criticals),
                           tuple(Form.EXACT if c is None else Form.CERTIFIED for c in certified),
                           next((c.digits for c in certified if c is not None), None))
    return answers, exact_steps(answers, model, spectrum.steps, note)


READABLE_OPS = 200  # an eigenvalue longer than this is no answer to read (a rod and a disk coupled by a spring: 676)


def _unreadable(spectrum: _Spectrum) -> bool:
    """Is any eigenvalue in the parameters too long to read (``READABLE_OPS``)? Then,
    with every value given, it is solved at the values: its shapes and kinds in the
    parameters cost seconds more for an answer nobody reads."""
    return any(sp.count_ops(pair.lam) > READABLE_OPS for pair in spectrum.pairs)


def _rate(pair: _Pair, scale: sp.Expr, sign: int) -> sp.Expr:
    """ω = √λ (sign 1) or γ = √(−λ) (sign −1); for a certified μ, √scale times its own
    certified √|μ| (rounding √ of the rounded μ would not keep every digit proven)."""
    if pair.certified is not None:
        return pair.certified.root * tidy(sp.sqrt(scale))
    return tidy(sp.sqrt(sign * pair.lam))


@dataclass(frozen=True)
class _Pair:
    """An eigenvalue λ and the root of the eigenproblem actually solved (μ, or λ
    itself), with the irreducible factor it solves and, for a factor of high degree,
    its certified decimals (certified.py)."""

    lam: sp.Expr
    root: sp.Expr
    factor: sp.Poly
    certified: CertifiedRoot | None = None


@dataclass(frozen=True)
class _Spectrum:
    """The eigenvalues λ, ascending, each with the root of the eigenproblem actually
    solved: (K̂ − μ M̂) a = 0 in the scaled form, or (K − λM) a = 0 itself."""

    K: sp.Matrix
    M: sp.Matrix
    x: sp.Symbol  # the variable of the eigenproblem solved: μ (scaled) or λ
    pairs: list[_Pair]
    steps: tuple[Relation, ...]
    characteristic: sp.Expr  # det(K − λM)
    scale: sp.Expr = sp.Integer(1)  # λ = scale · x


def _spectrum(K: sp.Matrix, M: sp.Matrix, symbols: set, model: Model) -> _Spectrum:
    s_M, s_K = common_scale(list(M), symbols), common_scale(list(K), symbols)
    scale = s_K / s_M  # λ = scale · μ
    labels = mode_labels(model)
    M_hat, K_hat = M / s_M, K / s_K
    if _rational(M_hat) and _rational(K_hat):
        poly = _charpoly_rational(K_hat, M_hat)  # det(K̂ − μ M̂) over QQ
        pairs = [_Pair(tidy(scale * mu), mu, f, c) for mu, f, c in _rational_roots(poly, K_hat, M_hat)]
        mu, lam = labels.symbol("scaled_eigenvalue"), labels.symbol("eigenvalue")
        steps = (Relation(_det(labels), sp.Integer(0)), Relation(descending(poly, mu), sp.Integer(0), lead="⇒"),
                 Relation(mu, tidy(lam / scale), lead="with"))
        # det(K − λM) = s_Kⁿ det(K̂ − μM̂) with μ = λ s_M/s_K
        characteristic = tidy(s_K ** K.rows * poly.as_expr().subs(MU, LAMBDA * s_M / s_K))
        return _Spectrum(K_hat, M_hat, MU, _ascending(pairs, model), steps, characteristic, scale)
    poly = sp.Poly((K - LAMBDA * M).det(method="berkowitz"), LAMBDA)
    pairs = [_Pair(lam, lam, poly) for lam in (sp.factor_terms(sp.together(x)) for x in _roots(poly, LAMBDA))]
    steps = (Relation(_det(labels), sp.Integer(0)),
             Relation(descending(poly, labels.symbol("eigenvalue")), sp.Integer(0), lead="⇒"))
    return _Spectrum(K, M, LAMBDA, _ascending(pairs, model), steps, tidy(poly.as_expr()))


def _rational(matrix: sp.Matrix) -> bool:
    return all(x.is_Rational for x in matrix)


def _charpoly_rational(K_hat: sp.Matrix, M_hat: sp.Matrix) -> sp.Poly:
    """det(K̂ − μ M̂) with exact rational arithmetic: with M̂ invertible,

        det(K̂ − μM̂) = det(M̂) det(M̂⁻¹K̂ − μ1) = (−1)ⁿ det(M̂) p(μ),

    p the characteristic polynomial det(μ1 − M̂⁻¹K̂), over QQ (DomainMatrix; a
    determinant over QQ[μ] costs seconds from n ≈ 30)."""
    M_q, K_q = (DomainMatrix.from_Matrix(sp.Matrix(A)).convert_to(sp.QQ) for A in (M_hat, K_hat))
    p = sp.Poly([sp.QQ.to_sympy(c) for c in (M_q.inv() * K_q).charpoly()], MU)
    return p * (sp.Integer(-1) ** K_hat.rows * sp.QQ.to_sympy(M_q.det()))


MAX_ROOT_OPS = 60  # a longer closed form (Cardano, Ferrari) reads worse than CRootOf


def _certified(factor: sp.Poly, K: sp.Matrix, M: sp.Matrix) -> list[CertifiedRoot] | None:
    """A factor's roots as certified decimals where its degree is ≥ CERTIFIED_DEGREE
    (certified.py, imported only for such a factor), else None."""
    if factor.degree() < CERTIFIED_DEGREE:
        return None
    from rbdsolve.solvers.modes.certified import certified_roots

    return certified_roots(factor, K, M)


def _rational_roots(poly: sp.Poly, K: sp.Matrix, M: sp.Matrix) -> list[tuple]:
    """Every root of det(K − μM), a polynomial over QQ, with the irreducible factor it
    belongs to and, for a factor of degree ≥ 5, its certified decimals: closed forms for
    factors of degree ≤ 2 and for cubics with a compact real (trigonometric) form, each
    checked against the isolated roots (``_agree``); certified decimals for degree ≥ 5
    (certified.py); exact CRootOf(f, k) otherwise. No Ferrari quartics."""
    out = []
    for factor, multiplicity in poly.factor_list()[1]:
        certified = _certified(factor, K, M)
        if certified is not None:
            out += [(c.value, factor, c) for c in certified for _ in range(multiplicity)]
            continue
        roots = None
        if factor.degree() <= 2 or (factor.degree() == 3 and not _near_double_root(factor)):
            found = sp.roots(factor, trig=True)
            if sum(found.values()) == factor.degree() and all(
                    not r.has(sp.I) and sp.count_ops(r) <= MAX_ROOT_OPS for r in found) \
                    and _agree(list(found), factor):
                roots = list(found)
        if roots is None:
            roots = factor.all_roots()
        out += [(r, factor, None) for r in roots for _ in range(multiplicity)]
    return out


NEAR_DOUBLE = sp.Rational(1, 10**6)  # sympy's trig formula goes wrong from 1 − x ≈ 1e-8 (failure-edges.md)


def _near_double_root(cubic: sp.Poly) -> bool:
    """Two of a cubic's three real roots nearly equal beside its spread: in the trig
    form t = 2√(−p/3) cos(acos(x)/3 − 2πk/3) of its depressed form t³ + pt + q, x² is
    within NEAR_DOUBLE of 1 (1 − x² = −(4p³ + 27q²)/(−4p³), the discriminant over −4p³,
    exact in rationals). For such a cubic sympy's roots(trig=True) returned the trig form
    in some runs and, in others, one with cos(acos(x)/3) already taken as 1 (wrong by
    2.5e-10 in 2e9, which ``_agree`` refuses): which one depended on what was solved
    before it in the same run, so the printed form did too. Such a cubic keeps CRootOf."""
    a, b, c, d = (sp.Rational(v) for v in cubic.all_coeffs())
    p = (3 * a * c - b**2) / (3 * a**2)
    q = (2 * b**3 - 9 * a * b * c + 27 * a**2 * d) / (27 * a**3)
    return p < 0 and 0 <= -(4 * p**3 + 27 * q**2) / (-4 * p**3) < NEAR_DOUBLE


CHECK_DIGITS = 50


def _agree(closed: list[sp.Expr], factor: sp.Poly) -> bool:
    """Whether closed forms are the roots of ``factor``: their values at CHECK_DIGITS
    digits match, in order, those of the isolated real roots (CRootOf, exact isolation)
    to 10^-(CHECK_DIGITS − 10) relative. A guard against sympy simplifying a closed form
    wrongly: cos(acos(x)/3) evaluates to 1 when x is within ~1e-24 of 1 (a cubic with one
    eigenvalue 1e12 times the others), which would silently drop a term of a root."""
    exact = [sp.N(r, CHECK_DIGITS) for r in factor.all_roots()]
    if len(exact) != len(closed):
        return False
    values = sorted(sp.N(r, CHECK_DIGITS) for r in closed)
    tolerance = sp.Float(10, CHECK_DIGITS) ** (10 - CHECK_DIGITS)
    return all(abs(a - b) <= tolerance * max(abs(b), 1) for a, b in zip(values, exact))


@lru_cache(maxsize=256)  # equilibria ±θ₀ share one K, and a second question asks about the same ones
def _roots(poly: sp.Poly, x: sp.Symbol) -> tuple[sp.Expr, ...]:
    """All roots with multiplicity, in closed form where one exists (else CRootOf); one
    coordinate's λ = K/M as it stands where K and M are long over sympy's EX domain
    (``plain_linear_root``: the caller tidies it)."""
    plain = plain_linear_root(poly)
    if plain is not None:
        return (plain,)
    found = sp.roots(poly, x)
    if sum(found.values()) == poly.degree():
        return tuple(r for r, k in found.items() for _ in range(k))
    if all(c.is_Rational for c in poly.all_coeffs()):
        return tuple(sp.Poly(poly, x).all_roots())  # exact CRootOf for the rest
    raise UnsolvedError(f"no closed form for the roots of the degree-{poly.degree()} "
                        "characteristic polynomial")


def _ascending(pairs: list[tuple], model: Model) -> list:
    """Sorted by λ: at the given parameter values, the others 1, or, where that point
    breaks an assumption (r = 1 > R = 1/2 under R > r), at a point that keeps them."""
    at = _ordering_point(model)

    def key(pair):
        lam = pair.lam
        number = sample(lam, at)
        if number.imag != 0:
            return (1, 0.0, sp.default_sort_key(lam))
        return (0, number.real, sp.default_sort_key(lam))

    return sorted(pairs, key=key)


def _ordering_point(model: Model) -> dict:
    """The given values, with admissible values for the others where every other
    parameter at 1 would break an assumption (``model.assumptions.admissible_sample``)."""
    ones = {**{p: sp.Integer(1) for p in model.symbols.parameters.values()}, **model.values}
    if all(a.difference.xreplace(ones) > 0 or (not a.strict and a.difference.xreplace(ones) == 0)
           for a in model.assumptions if not a.difference.xreplace(ones).free_symbols):
        return dict(model.values)
    point = admissible_sample(model.assumptions, model.symbols, random.Random(38), fixed=model.values)
    return point or dict(model.values)


def _shapes(spectrum: _Spectrum, values: Mapping[sp.Symbol, sp.Expr]) -> tuple:
    """An amplitude vector a for each λ, (K − λM) a = 0, scaled so its first nonzero
    entry is 1; a repeated λ takes the next vector of a basis of its mode space.

    For a simple irrational or symbolic root of an irreducible factor f, adj(K − xM) has
    rank one there and its nonzero columns are a (the cofactor method). The ratios
    a_k/a_first = adj_kj/adj_first,j are reduced modulo f to polynomials of degree
    < deg f before the root is put in: exact algebra, no radical simplification.
    Rational roots and repeated ones use the null space.
    """
    K, M, x = spectrum.K, spectrum.M, spectrum.x
    roots = [pair.root for pair in spectrum.pairs]
    counts = {root: roots.count(root) for root in roots}
    adjugate = None
    bases: dict[sp.Expr, list[tuple[sp.Expr, ...]]] = {}
    used: dict[sp.Expr, int] = {}
    out = []
    conjugates: dict[sp.Poly, tuple[sp.Expr, ...] | None] = {}
    for pair in spectrum.pairs:
        root, factor = pair.root, pair.factor
        if root not in bases:
            vector = None
            if pair.certified is not None:
                vector = pair.certified.shape
            elif counts[root] == 1 and not root.is_Rational and _rational(K) and _rational(M):
                if factor not in conjugates:
                    conjugates[factor] = _field_null_vector(K, M, x, factor)
                if conjugates[factor] is not None:
                    vector = tuple(_at_root(c, x, root) for c in conjugates[factor])
            elif counts[root] == 1 and not root.is_Rational:
                if adjugate is None:
                    adjugate = (K - x * M).adjugate(method="berkowitz").applyfunc(sp.expand)
                vector = _shape_mod(adjugate, x, factor.as_expr(), root, values)
            if vector is not None:
                bases[root] = [vector]
            else:
                null = (K - root * M).applyfunc(tidy).nullspace(simplify=True)
                bases[root] = [_normalize(v) for v in _m_orthogonal(null, M)]
        k = used.get(root, 0)
        used[root] = k + 1
        out.append(bases[root][k] if k < len(bases[root]) else ())
    return tuple(out)


def _at_root(p: sp.Expr, x: sp.Symbol, root: sp.Expr) -> sp.Expr:
    """A polynomial p at a root: at a CRootOf, highest power first, built without
    evaluation (an evaluated Add of CRootOf powers sorts its terms by isolating the
    root again); at a closed form (radicals), expanded and collected."""
    if not root.has(sp.CRootOf):
        return sp.factor_terms(sp.together(sp.expand(p.xreplace({x: root}))))
    terms = [c * root**k if k else c for (k,), c in sp.Poly(p, x).terms() if c != 0]
    return sp.Add(*terms, evaluate=False) if len(terms) > 1 else (terms[0] if terms else sp.Integer(0))


def _field_null_vector(K: sp.Matrix, M: sp.Matrix, x: sp.Symbol, f: sp.Poly) -> tuple[sp.Expr, ...] | None:
    """The mode shape of every root of an irreducible f over QQ at once, as polynomials
    in x of degree < deg f: the null vector of K − αM over the field QQ(α), f(α) = 0,
    by exact elimination there (DomainMatrix), scaled so its first nonzero entry is 1.
    Each root's shape is these polynomials at that root: the roots of f are conjugate,
    and conjugation maps one null vector onto the other."""
    alpha = f.all_roots()[0]
    field = sp.QQ.algebraic_field(alpha)
    a = field.from_sympy(alpha)
    rows = [[field.from_sympy(K[i, j]) - a * field.from_sympy(M[i, j]) for j in range(K.cols)]
            for i in range(K.rows)]
    null = DomainMatrix(rows, K.shape, field).nullspace()
    if null.shape[0] != 1:
        return None
    entries = null.to_list()[0]  # field elements: polynomials in alpha of degree < deg f
    first = next(e for e in entries if e)
    return tuple(sp.Poly([sp.QQ.to_sympy(c) for c in (e / first).to_list()], x).as_expr() for e in entries)


def _shape_mod(adjugate: sp.Matrix, x: sp.Symbol, f: sp.Expr, root: sp.Expr,
               values: Mapping[sp.Symbol, sp.Expr]) -> tuple[sp.Expr, ...] | None:
    """The mode shape at a simple root of f from the adjugate, reduced modulo f."""
    sample = {s: values.get(s, 1) for s in adjugate.free_symbols | root.free_symbols if s != x}
    at_root = adjugate.xreplace({x: root}).xreplace(sample).evalf()
    sizes = [sum(abs(v) for v in at_root[:, j]) for j in range(adjugate.cols)]
    if any(size.has(sp.nan, sp.zoo, sp.oo) for size in sizes):
        return None  # the sample fell on a singular point: the null space route instead
    j = max(range(adjugate.cols), key=lambda c: sizes[c])
    if sizes[j] == 0:
        return None
    first = next(i for i in range(adjugate.rows) if abs(at_root[i, j]) > 1e-9 * sizes[j])
    try:
        inverse = sp.invert(adjugate[first, j], f, x)
    except sp.polys.polyerrors.NotInvertible:
        return None
    ratios = [sp.rem(sp.expand(adjugate[k, j] * inverse), f, x) for k in range(adjugate.rows)]
    return tuple(sp.factor_terms(sp.together(sp.expand(r.xreplace({x: root})))) for r in ratios)


def _m_orthogonal(vectors: list[sp.Matrix], M: sp.Matrix) -> list[sp.Matrix]:
    """Gram–Schmidt in the inner product ⟨u, v⟩ = uᵀ M v (M symmetric positive
    definite), exact: a basis of the same space with uᵢᵀ M uⱼ = 0 for i ≠ j."""
    out: list[sp.Matrix] = []
    for v in vectors:
        w = sp.Matrix(v)
        for u in out:
            w = w - tidy((u.T * M * v)[0] / (u.T * M * u)[0]) * u
        out.append(w.applyfunc(tidy))
    return out


def _normalize(v: sp.Matrix) -> tuple[sp.Expr, ...]:
    first = next(x for x in v if x != 0)
    return tuple(tidy(x / first) for x in v)
