"""Steady motion of a rigid body: rolling conditions and angular momentum balance in a
turning triad (the seed's problem 3: a ring rolling on a horizontal circle).

In a steady motion every component in a triad T (turning at Ω_T) is constant. Then

- rolling without slipping at a contact point C: v_G + ω × (r_C − r_G) = 0, solved for
  the unknown rates (a spin rate);
- the angular momentum about a point P, L_P = J_G ω + (r_G − r_P) × m v_G, has constant
  components in T, so dL_P/dt = (dL_P/dt)_T + Ω_T × L_P = Ω_T × L_P;
- angular momentum balance about P, which may move with velocity v_P,

      dL_P/dt + v_P × m v_G = M_P = Σ (r_i − r_P) × F_i,

  with gravity at G as the force whose moment counts (a contact force at C has none
  about C), gives the relations between the parameters (each component = 0);
- with the contact forces stated as reactions R_i at points r_i (their unknowns N,
  x_N, …), they join M_P = Σ (r_i − r_P) × F_i, and Newton's law for G,

      m a_G = m g + Σ R_i,   a_G = (dv_G/dt)_T + Ω_T × v_G,

  gives three relations more: a cone rolling on its side (a line contact) has its
  normal force's resultant at an unknown distance along the line. Each rolling contact
  then needs a reaction (Newton's law counts it even where it has no moment), and the
  asked quantities are solved together with the reactions' other unknowns, so that no
  answer keeps one (docs/format.md, steady_motion).
"""

from __future__ import annotations

import random

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import NUMERIC_REMEDY, UnsolvedError
from rbdsolve.form.tidy import tidy, tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.problem.options import SteadyMotionOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.conditions.polynomial import polynomial_roots
from rbdsolve.model.values.values import parameter_sample
from rbdsolve.solvers.conditions.parameter_order import asked
from rbdsolve.solvers.steady_motion.answers import AtSolution, SteadyMotionAnswers, SupportForce
from rbdsolve.solvers.steady_motion.existence import absent_at_values, with_existence
from rbdsolve.solvers.steady_motion.balances import (
    angle_of,
    angle_unknown,
    balances,
    relation,
    rolling_velocities,
    setup,
    sin_cos,
    twin,
    unknown_symbols,
)
from rbdsolve.solvers.steady_motion.steps import balance_steps, kinematics_step, omega_label, rolling_steps


def solve(question: Question, model: Model, options: Options) -> Solution:
    opts: SteadyMotionOptions = question.options
    k, vectors = setup(opts, model)
    omega, v_G = k.omega(), k.velocity(k.body.position)
    w = omega_label(model)
    steps = [kinematics_step(vectors, k.Omega, omega, v_G, w)]
    rates, rolling_steps = _rolling(opts, model, k, rolling_velocities(opts, model, k, omega, v_G), omega, vectors)
    steps += rolling_steps
    b = balances(opts, model, k, rates, omega, v_G)
    targets = tuple(model.symbols.scalar(x) for x in opts.solve_for)
    target = targets[0] if len(targets) == 1 else None
    relations = tuple(relation(x, target) for x in b.components if tidy_fraction(x) != 0)
    names = model.symbols.with_points(model.points)
    held = _reaction_unknowns(opts, model, names)
    found = _solve_for(opts, targets, relations, model, rates, held)
    real, several, critical = _branches(found, targets, model, asked(model, question))
    solved, along = real[0] if len(real) == 1 else ({}, {})
    answers = SteadyMotionAnswers(vectors, {str(a): b for a, b in rates.items()}, tuple(b.omega), tuple(b.L),
                                  tuple(b.M), relations, solved, {str(u): v for u, v in along.items()},
                                  several, critical, _reactions(opts, k, names, targets, solved, along, held),
                                  _at_solutions(opts, targets, real, rates, tuple(b.omega)))
    loaded = any(opts.body in (x.body, x.by) for x in model.loads)
    steps += balance_steps(answers, b.dL, b.v_P, opts, targets, b.a_G, w, loaded,
                           labels_for(model, "angular_momentum").name("angular_momentum"))
    return Solution("steady_motion", Route.EXACT, answers, tuple(steps),
                    warnings=absent_at_values(several, critical, model))


def _reactions(opts: SteadyMotionOptions, k, names, targets, solved: dict, along: dict,
               unknowns: tuple[sp.Symbol, ...]) -> dict[str, SupportForce]:
    """Each reaction's force, triad components, the unknowns found put in, named by its
    point as the reactions question and impact name theirs; {} where an unknown is left
    (not asked, or several solutions)."""
    found = {t: solved[x.text] for x, t in zip(opts.solve_for, targets)
             if isinstance(t, sp.Symbol) and x.text in solved}
    found.update(along)
    out: dict[str, sp.Matrix] = {}
    for r in opts.reactions:
        at = r.at.text.strip()
        out[at] = out.get(at, sp.zeros(3, 1)) + k.components(names.vector(r.force)).xreplace(found)
    if unknowns and any(f.has(*unknowns) for f in out.values()):
        return {}
    return {at: SupportForce(tuple(tidy(x) for x in f)) for at, f in out.items()}


def _at_solutions(opts: SteadyMotionOptions, targets: tuple[sp.Expr, ...], solutions: list[tuple[dict, dict]],
                  rates: dict, omega: tuple[sp.Expr, ...]) -> tuple[AtSolution, ...]:
    """Each solution's values put back where the other answers use them: ω₀ = √(ω₀²)
    for a positive ω₀ asked as ω₀² (a square of a quantity of open sign has two roots:
    left out), a quantity asked for itself (the spin), the reactions' unknowns found
    along; then each rate the rolling condition gave in terms of them, and ω. Nothing
    where no solution fixes a quantity that ω or a rate holds."""
    out = []
    for solved, along in solutions:
        fixed = {**{q: v for x, t in zip(opts.solve_for, targets) if x.text in solved
                    for q, v in _fixes(t, solved[x.text]).items()}, **along}
        shown = {str(q): v for q, v in fixed.items() if q not in targets and q not in along}
        moved = {str(a): tidy(r.xreplace(fixed)) for a, r in rates.items() if r.has(*fixed)}
        held = fixed and any(w.has(*fixed) for w in omega)
        out.append(AtSolution(shown, moved, tuple(tidy(w.xreplace(fixed)) for w in omega) if held else ()))
    return tuple(out) if any(a.values or a.rates or a.angular_velocity for a in out) else ()


def _fixes(target: sp.Expr, value: sp.Expr) -> dict[sp.Symbol, sp.Expr]:
    """The symbol a solved target fixes: itself, or the positive base of a power (ω₀
    from ω₀² = v: ω₀ = √v); {} for anything else."""
    if isinstance(target, sp.Symbol):
        return {target: value}
    if (target.is_Pow and isinstance(target.base, sp.Symbol) and target.base.is_positive
            and target.exp.is_Integer and target.exp > 0):
        return {target.base: tidy(value ** (sp.Integer(1) / target.exp))}
    return {}


def _rolling(opts: SteadyMotionOptions, model: Model, k, v_C: list[sp.Matrix], omega, vectors):
    """v_C = v_G + ω × (r_C − r_G) = 0 at the contact, solved for the unknown rates."""
    if not opts.contacts:
        return {}, []
    named = {C.text for C in opts.contacts}
    derived = [(c.name, k.components(c.point - k.body.position).applyfunc(tidy))
               for c in model.plane_contacts if c.name in named]
    unknowns = [model.symbols.parameters[u] for u in model.problem.unknowns]
    equations = [x for v in v_C for x in v if x != 0]
    found = sp.solve(equations, unknowns, dict=True) if equations else [{}]
    if len(found) != 1:
        raise UnsolvedError("the rolling condition does not fix the unknown rates")
    rates = {a: tidy(b) for a, b in found[0].items()}
    return rates, rolling_steps(opts, v_C, rates, omega.xreplace(rates).applyfunc(tidy), vectors, derived,
                                omega_label(model))


def _solve_for(opts: SteadyMotionOptions, targets: tuple[sp.Expr, ...], relations, model: Model,
               rates: dict, reaction_unknowns: tuple[sp.Symbol, ...] = ()):
    """Every solution [(asked values, the reactions' other unknowns found)]: the asked
    quantities from the relations that hold them, solved together with the
    reactions' other unknowns (x_N alone needs N too: N x_N = … and N = m g hold them
    together), so that no answer keeps an unknown; an answer that still holds one (a
    reaction's unknown or a rate the rolling conditions leave open) is refused. Every
    other relation must then hold too (unless it holds an unknown not found), or there
    is no such steady motion. A positive quantity (ω₀²) takes only positive roots.
    """
    if not targets:
        return [({}, {})]
    if all(x in rates for x in targets):
        return [({x.text: rates[y] for x, y in zip(opts.solve_for, targets)}, {})]
    held = set().union(*(x.free_symbols for x in targets))
    along = [u for u in reaction_unknowns if u not in held]
    X = [sp.Dummy(f"X{i}") for i in range(len(targets))]
    replaced = [r.subs(dict(zip(targets, X))) for r in relations]
    holding = [r for r in replaced if r.has(*X, *along) and not r.has(*held)]
    asked = ", ".join(x.text for x in opts.solve_for)
    if not holding:
        raise UnsolvedError(f"the relations do not give {asked}: no relation holds {asked}")
    solutions, proved = _solved(holding, X + along)
    if solutions and not any(all(d in f for d in X) for f in solutions):
        raise UnsolvedError(f"the relations do not give {asked} uniquely: they leave some of them open "
                            f"({len(holding)} relation{'s' if len(holding) > 1 else ''} for {len(X)} quantities)")
    found = [f for f in solutions
             if all(d in f for d in X) and not any(x.is_positive and (f[d].is_negative or f[d].could_extract_minus_sign())
                                                   for x, d in zip(targets, X))]
    found = _once(found, holding, model)
    if not found:
        raise UnsolvedError(f"no steady motion: the relations have no real solution for {asked} (proved: they are "
                            "polynomial in the unknowns and the sines and cosines of the angles, solved completely)"
                            if proved else f"the relations could not be solved exactly for {asked}")
    back = dict(zip(X, targets))
    unsolved = [r for r, x in zip(relations, replaced) if x not in holding]  # the solved ones hold by construction
    out = []
    for f in found:
        values = {x: tidy_fraction(sin_cos(f[d].xreplace(back))) for x, d in zip(targets, X)}
        _require_known(values, unknown_symbols(model) | held)
        found_along = {u: tidy_fraction(sin_cos(f[u])) for u in along
                       if u in f and not f[u].has(*X, *unknown_symbols(model))}
        _require_rest(unsolved, {**values, **found_along}, model, targets, held, bool(opts.reactions))
        out.append(({x.text: values[y] for x, y in zip(opts.solve_for, targets)}, found_along))
    return out


def _branches(found, targets, model: Model, first=None):
    """The solutions that are real somewhere, each with where it is (solved for one
    parameter: the least spin for which a top's two precession rates exist, the tilt
    below which a coin's rate is; the value of a square, ω₀², must be ≥ 0:
    existence.py), and the critical values; no branches for one solution that is real
    everywhere."""
    squares = [k for k, t in enumerate(targets) if t.is_Pow and t.exp.is_even and t.base.is_real]
    branches, critical = with_existence([solved for solved, _ in found], squares, model, first)
    real = [(pair, b) for pair, b in zip(found, branches) if b.exists_when is not sp.false]
    if not real:
        raise UnsolvedError("no steady motion: every solution of the relations is complex for all the values the "
                            "assumptions allow")
    if len(real) == 1 and real[0][1].exists_when is sp.true:
        return [real[0][0]], (), ()
    return [pair for pair, _ in real], tuple(b for _, b in real), critical


def _solved(relations: list[sp.Expr], unknowns: list[sp.Symbol]) -> tuple[list[dict], bool]:
    """Every solution, and whether the list is complete. Unknowns that the relations
    hold only through sin and cos (a tilt β) are solved for on the unit circle: sin β =
    s, cos β = c, s² + c² = 1, which makes the relations polynomial; sympy then solves
    them completely (Gröbner bases) and β = atan2(s, c) in (−π, π], so "no solution" is
    proved. Otherwise sympy's solve, which may miss solutions (not complete)."""
    polynomial = _on_unit_circle(relations, unknowns)
    if polynomial is not None:
        system, symbols, back, determined = polynomial
        _require_low_degree(system, symbols)
        roots = polynomial_roots(system, symbols, "the relations")
        out = []
        for root in roots:
            if any(sp.sympify(v).is_real is False for v in root.values()):
                continue
            # a family (some symbols left free) keeps only the unknowns it determines
            out.append({u: back[u](root) for u in unknowns if determined[u] <= set(root)})
        return out, True
    quadratic = _one_quadratic(relations, unknowns)
    if quadratic is not None:
        return quadratic, True
    try:
        return sp.solve(relations, unknowns, dict=True), False
    except NotImplementedError:
        return [], False


def _one_quadratic(relations: list[sp.Expr], unknowns: list[sp.Symbol]) -> list[dict] | None:
    """One relation, a polynomial of degree 1 or 2 in the one unknown X (a top's
    precession rate: (I₁ − I₃) cos θ Ω² − I₃ s Ω + m g h = 0), solved by formula:
    X = −c/b, or X = (−b ± √(b² − 4ac))/(2a) once the factors common to a, b, c
    (sin θ) are divided out; complete, and without sympy's solve and its checks (a
    third of a second for a heavy top). None for anything else."""
    if len(relations) != 1 or len(unknowns) != 1:
        return None
    (X,) = unknowns
    numerator, denominator = sp.fraction(sp.together(relations[0]))
    if denominator.has(X) or not numerator.is_polynomial(X):
        return None
    coefficients = sp.Poly(numerator, X).all_coeffs()
    if len(coefficients) not in (2, 3) or any(c.has(X) for c in coefficients):
        return None
    common = sp.gcd_list(coefficients)
    coefficients = [sp.cancel(c / common) for c in coefficients]
    if coefficients[0].could_extract_minus_sign():
        coefficients = [-c for c in coefficients]
    if len(coefficients) == 2:
        b, c = coefficients
        return [{X: -c / b}]
    a, b, c = coefficients
    root = sp.sqrt(b**2 - 4 * a * c)
    return [{X: (-b - root) / (2 * a)}, {X: (-b + root) / (2 * a)}]


MAX_DEGREE = 2  # in one sine after eliminating its cosine: beyond, closed forms swell (a quartic)


def _require_low_degree(system: list[sp.Expr], symbols: list) -> None:
    """One relation in one angle (s, c on the unit circle): eliminating c leaves a
    polynomial in s; past MAX_DEGREE with symbolic coefficients its closed-form roots
    are no answer (Ferrari's formula, after minutes), so say so at once (``auto`` then
    takes the numeric route where every value is given)."""
    if len(system) != 2 or len(symbols) != 2:
        return
    relation, circle = system
    s, c = symbols
    eliminated = sp.Poly(sp.resultant(relation, circle, c), s)
    if eliminated.degree() > MAX_DEGREE and eliminated.free_symbols - {s}:
        raise UnsolvedError(f"the relation is a polynomial of degree {eliminated.degree()} in the sine of the "
                            "angle asked for, with symbolic coefficients: no compact closed form", NUMERIC_REMEDY)


def _on_unit_circle(relations, unknowns):
    """(system, symbols, {unknown: its value from a root}, {unknown: the symbols a root
    must give for it}) with each angle unknown's sin and cos as symbols on the unit
    circle; None unless the relations become polynomial."""
    angles = [u for u in unknowns if angle_unknown(u, relations)]
    if not angles:
        return None
    s = {u: sp.Dummy(f"s_{u}", real=True) for u in angles}
    c = {u: sp.Dummy(f"c_{u}", real=True) for u in angles}
    plain = [u for u in unknowns if u not in s]
    table = {sp.sin(u): s[u] for u in s} | {sp.cos(u): c[u] for u in c}
    system = [sp.numer(sp.together(sin_cos(r).xreplace(table))) for r in relations]
    symbols = [*s.values(), *c.values(), *plain]
    if any(e.has(*angles) or not e.is_polynomial(*symbols) for e in system):
        return None
    system += [s[u] ** 2 + c[u] ** 2 - 1 for u in angles]
    back = {u: (lambda root, u=u: angle_of(root[s[u]], root[c[u]])) for u in angles}
    back |= {u: (lambda root, u=u: root[u]) for u in plain}
    determined = {u: {s[u], c[u]} for u in angles} | {u: {u} for u in plain}
    return system, symbols, back, determined


def _once(found: list[dict], relations, model: Model) -> list[dict]:
    """Solutions that are the same motion listed once: angles that differ by a whole
    turn, or twins, a half turn of every angle unknown with the other unknowns' signs
    turned where that leaves the relations as they are (β + π with −φ̇: the motion
    turned over). The representative: the least in size at a sample."""
    sample = parameter_sample(model, random.Random(26))
    out: list[dict] = []
    for f in sorted(found, key=lambda f: [abs(complex(sp.N(sp.sympify(v).xreplace(sample), 15))) for v in f.values()]):
        if not any(twin(f, g, relations, sample) for g in out):
            out.append(f)
    return out


def _require_known(values: dict, unknown: set) -> None:
    """An answer must be free of the unknowns: one still holding N (not asked for, and not
    fixed by the relations) would be no answer."""
    for x, v in values.items():
        left = sorted(str(u) for u in v.free_symbols & unknown)
        if left:
            raise UnsolvedError(f"the relations leave {', '.join(left)} unknown, and {x} = {to_unicode(v)} depends "
                                f"on {'it' if len(left) == 1 else 'them'}: {x} is not fixed by this balance")


def _require_rest(relations, values: dict, model: Model, targets, held: set, reactions: bool) -> None:
    """Every other relation free of the unknowns not found must hold with the values
    found (those they were solved from hold by construction)."""
    others = unknown_symbols(model) - set(targets) - held - set(values)
    rest = [r for r in relations if not r.has(*others) and tidy_fraction(sin_cos(r.subs(values))) != 0]
    if rest:
        shown = ", ".join(f"{x} = {to_unicode(v)}" for x, v in values.items())
        hint = " (or a contact force is missing from 'reactions')" if reactions else ""
        raise UnsolvedError(f"{shown} from the relations, but then {to_unicode(rest[0])} = 0 must hold too: "
                            f"no such steady motion in general{hint}")


def _reaction_unknowns(opts: SteadyMotionOptions, model: Model, names) -> tuple[sp.Symbol, ...]:
    """The declared unknowns the reactions hold (N, x_N, F1, F2), in their declared order."""
    held = set().union(*(names.vector(r.at).free_symbols | names.vector(r.force).free_symbols
                         for r in opts.reactions))
    return tuple(s for s in (model.symbols.parameters[u] for u in model.problem.unknowns) if s in held)
