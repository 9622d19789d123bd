"""Equilibria of a conservative system and their stability.

Equilibria: ∂V/∂q = 0. Angles enter V through sin and cos, so each angle q is replaced
by s = sin q, c = cos q with s² + c² = 1, which turns a trigonometric system into a
polynomial one that sympy solves completely (Gröbner bases); q = atan2(s, c) recovers
every branch in (−π, π], so no root is missed (plain ``solve`` misses some).

Stability (Lagrange–Dirichlet): with T positive definite, a strict minimum of V is
stable. The Hessian H = ∂²V/∂q∂q is symmetric, so its characteristic polynomial has
real roots only, and Descartes' rule of signs then counts its positive, zero and
negative eigenvalues exactly from the signs of the coefficients, even when the
entries are symbolic:

* all eigenvalues positive → stable;
* one negative → unstable (the linearized motion grows exponentially);
* zero eigenvalues only along coordinates V does not contain → neutral;
* other zero eigenvalues → undetermined: higher-order terms decide.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Mapping

import sympy as sp

from rbdsolve.form.zero import simplifies_to_zero
from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.errors import UnsolvedError
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import memoized, potential_energy
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.equilibria.answers import EquilibriaAnswers, Equilibrium, SingularPoint, Stability
from rbdsolve.solvers.equilibria.angles import angle_of
from rbdsolve.solvers.equilibria.cases import existing_where, gradient, stiffness_at, with_cases
from rbdsolve.solvers.equilibria.evident import evident_roots
from rbdsolve.solvers.equilibria.higher_order import higher_order
from rbdsolve.solvers.equilibria.structure import PolySystem, Shape, Structure, decide, shape_of
from rbdsolve.solvers.conditions.polynomial import polynomial_roots, trig_mixed
from rbdsolve.solvers.equilibria.uniform import never_balanced, uniform_equilibrium
from rbdsolve.solvers.equilibria import declared_range, zero_length
from rbdsolve.solvers.conditions.conditions import CriticalValue, critical_values, what_decides
from rbdsolve.solvers.conditions.parameter_order import asked
from rbdsolve.solvers.equilibria.steps import exact_steps
from rbdsolve.solvers.configuration import contact_span
from rbdsolve.solvers.lagrange.frames import require_static, spin_warnings
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.configuration.placement import SUGGESTION, Singularity, Verdict, exact_kernel, same_placement, singularity
from rbdsolve.solvers.conditions.signs import (Inertia, Undecided, matrix_inertia, nonzero_where_defined,
                                              roots_where_defined, sign_of, symbolic_sign)
from rbdsolve.model.values.values import sample


@memoized
def equations_and_unknowns(model: Model) -> tuple[list, list, frozenset]:
    """The equations ∂V/∂q = 0 that are not 0 = 0, the coordinates they hold (the
    others are free: every value is an equilibrium), and the coordinates solved as
    angles over (−π, π]."""
    equations = [e for e in gradient(model) if e != 0]
    unknowns = [q for q in model.q if any(e.has(q) for e in equations)]
    return equations, unknowns, periodic_angles(model) | repeating(model)


def find_equilibria(model: Model) -> tuple[list[dict[sp.Expr, sp.Expr]], list[str]]:
    """Every solution of ∂V/∂q = 0, angles in (−π, π], where the equations' structure
    lets the exact route list them all (``structure``); else the evident roots, with a
    warning that others may exist. And warnings, if any."""
    equations, unknowns, angles = equations_and_unknowns(model)
    if any(not e.has(*model.q) for e in equations):  # e.g. ∂V/∂x = m g sin α ≠ 0
        return [], []
    free = [q for q in model.q if q not in unknowns]
    if free:
        warnings = [f"V does not depend on {', '.join(unicode_name(q.name) for q in free)}: "
                    "every value is an equilibrium; it is shown as 0"]
    else:
        warnings = []
    warnings += [f"V is not 2π-periodic in {unicode_name(q.name)} (it enters V outside sin and cos, e.g. in a torsional "
                 "spring): its equilibria are not reduced to (−π, π]" for q in model.q if q in model.angles - angles]
    warnings += [_repeats(model, q) for q in unknowns if q in repeating(model)]
    solutions, notes = _roots(model, equations, unknowns, angles)
    warnings += notes
    out = []
    for sol in solutions:
        full = {q: _turn(sol.get(q, sp.Integer(0))) if q in angles else sol.get(q, sp.Integer(0))
                for q in model.q}
        if full not in out and existence(full, model) is not None:
            out.append(full)
    return sorted(out, key=lambda sol: [_order(v) for v in sol.values()]), warnings


SHOWN_CHARACTERS = 240  # a longer ∂V/∂q = 0 is not repeated in the warning


@memoized
def structure(model: Model) -> Structure:
    """What ∂V/∂q = 0 is (structure.py), read from its form: polynomial, algebraic or
    transcendental, and whether the exact route can list every root."""
    equations, unknowns, angles = equations_and_unknowns(model)
    shape, system = shape_of(equations, unknowns, angles)
    return decide(shape, system, equations, unknowns, shape is Shape.TRANSCENDENTAL and proved_monotone(model) is not None)


def incomplete(model: Model) -> str | None:
    """Why the exact route's list of equilibria would be partial (only its evident
    roots), or None: decided from the structure, before any solving."""
    return structure(model).why_partial


def partial(question: Question, model: Model) -> str | None:
    """The route choice's check (solvers/routes/routes.py): ``incomplete``."""
    return incomplete(model)


def _roots(model: Model, equations, unknowns, angles) -> tuple[list[dict], list[str]]:
    """The roots by the route the structure allows: a Gröbner basis (polynomial),
    sympy's solve (small algebraic), a monotone bound (one transcendental equation), or
    the evident roots with the reason the list is partial."""
    found = structure(model)
    if found.shape is Shape.NONE:
        return [{}], []
    if found.why_partial is None:
        if found.shape is Shape.POLYNOMIAL:
            return _solve_polynomial(found.system, model.assumed), []
        if found.shape is Shape.ALGEBRAIC:
            return _solve_general(equations, unknowns), [
                "the equilibrium equations are not polynomial in sin, cos and the coordinates; sympy's solve "
                "was used and may miss solutions"]
        proved = proved_monotone(model)
        return [proved[0]], [proved[1]]
    evident = evident_roots(equations, unknowns, model)
    shown = "; ".join(f"{to_unicode(model.readable(e))} = 0" for e in equations)
    if len(shown) > SHOWN_CHARACTERS:  # written out in the steps already
        shown = "∂V/∂q = 0, as written above"
    from rbdsolve.solvers.numeric.search_box import search_rule  # for this message only

    where = search_rule(model, angles)
    if not evident:
        raise UnsolvedError(f"{found.why_partial} ({shown}), and no evident root (0, π or ±π/2 in the angles, 0 in "
                            "the lengths) solves them: the exact route cannot solve them",
                            f"with a value for {_lacking(model)} the numeric route searches {where}; for modes, "
                            "give the equilibrium with 'modes: {about: {...}}'")
    return evident, [f"{found.why_partial}: {shown}. The exact route lists only the evident roots, where every "
                     f"term vanishes: {_shown_roots(model, unknowns, evident)}. Other equilibria may exist; the "
                     f"numeric route (a value for every parameter, or --route numeric) searches for them {where}"]


def _lacking(model: Model) -> str:
    """The parameters the numeric route would need a value for, named (a rod on a turning
    arm with only m open: "with a value for m"), or "every parameter" where all have one
    (--route exact)."""
    from rbdsolve.solvers.routes.needed import missing_values

    return ", ".join(missing_values(model)) or "every parameter"


def _shown_roots(model: Model, unknowns, roots: list[dict]) -> str:
    """θ = 0, π; or (ψ, θ) = (0, 0), (π, π): each angle in (−π, π], so −π is not said
    beside π."""
    names = dict(zip(model.q, model.coordinate_names()))
    angles = periodic_angles(model) | repeating(model)
    values = list(dict.fromkeys(", ".join(to_unicode(_turn(r[q]) if q in angles else r[q]) for q in unknowns)
                                for r in roots))
    if len(unknowns) == 1:
        return f"{unicode_name(names[unknowns[0]])} = {', '.join(values)}"
    return f"({', '.join(unicode_name(names[q]) for q in unknowns)}) = " + ", ".join(f"({v})" for v in values)


@memoized
def periodic_angles(model: Model) -> frozenset:
    """The angle coordinates along which ∂V/∂q is 2π-periodic: ∂V/∂q at q + 2π equals it
    (sympy reduces sin and cos of q + 2π). An angle that also enters V bare, as in a
    torsional spring ½ c (θ − θ₀)², is not: turning its equilibria into (−π, π] would
    move them off ∂V/∂q = 0, so they are kept as solved."""
    grad = gradient(model)
    return frozenset(q for q in model.angles
                     if all(_vanishes(e.xreplace({q: q + 2 * sp.pi}) - e) for e in grad))


@memoized
def repeating(model: Model) -> frozenset:
    """The coordinates that are not angles of the scene (they enter a position bare, as
    a rocking body's θ does in s_C = −R θ) but along which ∂V/∂q is 2π-periodic and
    depends on q: solved as angles over (−π, π], each root standing for q₀ + 2kπ."""
    grad = gradient(model)
    return frozenset(q for q in model.q if q not in model.angles and any(e.has(q) for e in grad)
                     and all(_vanishes(e.xreplace({q: q + 2 * sp.pi}) - e) for e in grad))


def _repeats(model: Model, q: sp.Symbol) -> str:
    """The warning that equilibria in q repeat every 2π, and where a contact allows them."""
    name, zero = unicode_name(q.name), unicode_name(f"{q.name}_0")
    why = f"∂V/∂{name} is 2π-periodic in {name} though the scene is not ({_not_repeating(model, q, name)}): "
    held = contact_span.held_for(model, q)
    if held:
        return why + (f"each equilibrium {zero} would repeat at {zero} + 2kπ, but the contact holds only for "
                      f"{held}; those in (−π, π] where it holds are listed")
    return why + (f"each equilibrium {zero} repeats at {zero} + 2kπ, k an integer, the body moved on by whole "
                  "turns; those in (−π, π] are listed")


def _not_repeating(model: Model, q: sp.Symbol, name: str) -> str:
    """Why a coordinate along which ∂V/∂q repeats is no angle of the scene: declared so,
    or q bare in the positions (a rolling body's travel)."""
    declared = next(c for c in model.problem.coordinates if c.name == q.name)
    if declared.periodic is False:
        return f"{name} is declared 'periodic: false'"
    return f"{name} also enters the positions outside sin and cos, as a rolling body's travel does"


def _vanishes(expr: sp.Expr) -> bool:
    return sp.expand(expr) == 0 or sp.expand(sp.expand_trig(expr)) == 0


def _turn(angle: sp.Expr) -> sp.Expr:
    """An angle brought into (−π, π]: numbers exactly; c + 2πk by dropping the turns."""
    if not angle.is_number:
        turns = [t for t in sp.Add.make_args(angle) if (t / (2 * sp.pi)).is_integer]
        return angle - sp.Add(*turns)
    turned = angle - 2 * sp.pi * sp.ceiling((angle - sp.pi) / (2 * sp.pi))
    return sp.nsimplify(turned) if turned.is_rational else turned


def _order(value: sp.Expr) -> tuple:
    """Sort key: by numeric value (parameters set to 1), a number before an expression
    that ties with it (θ = 0 before acos(g/(Ω² R))), then at the parameters set apart (a
    wheel held by a couple, sin θ₀ = C/(m g R), has both its equilibria at π/2 where every
    parameter is 1: asin(…) before π − asin(…)), then by the expression."""
    apart = {s: 1 + sp.Rational(i + 1, 7) for i, s in enumerate(sorted(value.free_symbols, key=str))}
    return (_real(sample(value, {})), not value.is_number, _real(sample(value, apart)), sp.default_sort_key(value))


def _real(number: complex) -> float:
    return number.real if number.imag == 0 else 0.0


def _solve_polynomial(system: PolySystem, assumed: Mapping) -> list[dict]:
    """Every root of the polynomial form, angles recovered as atan2(s, c) (``assumed``:
    the assumptions' substitutions, which may decide the signs of s and c)."""
    symbols = system.symbols
    if not symbols:
        return [{}]
    roots = polynomial_roots(list(system.polynomials), symbols, "the equilibrium equations")
    out = []
    for root in roots:
        if any(sp.sympify(v).is_real is False for v in root.values()):
            continue
        if len(root) < len(symbols):  # a family of solutions: not isolated points
            raise _continuum()
        if any(simplifies_to_zero(d.xreplace(root)) for d in system.denominators):
            continue  # the equation is not defined there (a spring of zero length: ∂V/∂q has √B = 0 below)
        sol = {q: angle_of(root[system.sines[q]], root[system.cosines[q]], assumed) for q in system.sines}
        sol |= {q: tidy(root[q]) for q in system.plain}
        out.append(sol)
    return out


def existence(at: Mapping, model: Model) -> tuple[sp.Expr, ...] | None:
    """Where an equilibrium exists: None if it is not at the given parameter values
    (not real, or a spring past its zero length), else the conditions (each ≥ 0) left
    undecided (``existing_where``)."""
    conditions = []
    for condition in existing_where(at, model):
        sign = sign_of(tidy(condition), model.decided_by)
        if sign == -1 or (isinstance(sign, Undecided) and model.values and _numeric(condition, model)):
            return None  # not real for these parameter values
        if isinstance(sign, Undecided):
            conditions.append(tidy(condition))
    return tuple(conditions)


def _numeric(expr: sp.Expr, model: Model) -> bool:
    """Does the expression become a number once the given values are put in?"""
    return not expr.xreplace(model.values).free_symbols


def _solve_general(equations, unknowns) -> list[dict]:
    """sympy's solve, for a small system with radicals of the coordinates (structure.py)."""
    try:
        roots = sp.solve(equations, unknowns, dict=True)
    except NotImplementedError:
        raise UnsolvedError("the equilibrium equations hold radicals of the coordinates and sympy's solve cannot "
                            "solve them") from None
    if any(len(r) < len(unknowns) or any(sp.sympify(v).has(*unknowns) for v in r.values()) for r in roots):
        raise _continuum()  # x = √(L² − y²) for every y: a spring's natural length all round
    return [r for r in roots if all(sp.sympify(v).is_real is not False for v in r.values())]


def _continuum() -> UnsolvedError:
    return UnsolvedError("the equilibria form a continuum (V is flat along a curve); "
                         "rbdsolve reports isolated equilibria only")


@memoized
def proved_monotone(model: Model) -> tuple[dict, str] | None:
    """One equation mixing q with sin and cos of it (θ = k sin θ) whose left side is
    proved strictly monotone (``monotone``): its one simple root, and the proof in words."""
    equations, unknowns, _ = equations_and_unknowns(model)
    if len(equations) != 1 or len(unknowns) != 1 or not trig_mixed(equations[0], unknowns[0]):
        return None
    from rbdsolve.solvers.conditions.monotone import monotone_root  # only for such an equation: ~0.5 ms of start-up

    (e,), (q,) = equations, unknowns
    found = monotone_root(e, q, model.decided_by)
    if found is None:
        return None
    where = ("" if symbolic_sign(found.bound) is not None
             else " at the parameter values" if found.bound.xreplace(model.values).is_number
             else " by the assumptions")
    relation = "≥" if found.increasing else "≤"
    name = to_unicode(model.readable(q))
    text = (f"∂V/∂{name} = {to_unicode(model.readable(e))} is strictly "
            f"{'in' if found.increasing else 'de'}creasing: "
            f"its derivative {to_unicode(model.readable(found.derivative))} {relation} "
            f"{to_unicode(model.readable(found.bound))}, which is {'positive' if found.increasing else 'negative'}"
            f"{where} (|sin|, |cos| ≤ 1); so {name} = {to_unicode(found.root)} is its only root")
    return {q: found.root}, text


def classify(model: Model, at: dict[sp.Expr, sp.Expr]) -> Equilibrium:
    """The equilibrium's stability from the Hessian of V, and where it exists."""
    found = _classify(model, at)
    return replace(found, conditions=existence(at, model) or ())


def _classify(model: Model, at: dict[sp.Expr, sp.Expr]) -> Equilibrium:
    H = stiffness_at(model, at)
    names = {q: n for q, n in zip(model.q, model.coordinate_names())}
    where = {names[q]: v for q, v in at.items()}
    inertia = decided_inertia(H, model, at)
    if isinstance(inertia, Undecided):
        return Equilibrium(where, Stability.UNDETERMINED, H,
                           f"the sign of {to_unicode(inertia.expr)} depends on the parameters ({what_decides(inertia.expr, model.values)})")
    if inertia.negative:
        return Equilibrium(where, Stability.UNSTABLE, H, "the Hessian of V has a negative eigenvalue")
    if inertia.zero:
        flat = [q for q in model.q if not potential_energy(model).total.has(q)]
        if len(flat) == inertia.zero:
            return Equilibrium(where, Stability.NEUTRAL, H,
                               "V does not depend on " + ", ".join(unicode_name(names[q]) for q in flat))
        decided = higher_order(model, at)
        if decided is not None:
            return Equilibrium(where, decided[0], H, decided[1])
        return Equilibrium(where, Stability.UNDETERMINED, H,
                           "the Hessian of V is singular: higher-order terms decide")
    return Equilibrium(where, Stability.STABLE, H, "the Hessian of V is positive definite")


def decided_inertia(H: sp.Matrix, model: Model, at: Mapping[sp.Expr, sp.Expr] | None = None) -> Inertia | Undecided:
    """H's inertia decided by the values and the assumptions' substitutions, else by the
    assumptions alone: a value given for R drops the substitution R = r + δ (R is a
    number there), which still decides that g m (R − r) > 0 under R > r. At an
    equilibrium ``at``, each factor of its coordinates' denominators is ≠ 0 where it is
    defined (``nonzero_where_defined``): K = −m Ω² sin² α < 0 at s = g cos α/(Ω² sin² α);
    and each root in H is real, so positive, where the equilibrium exists
    (``roots_where_defined``)."""
    found = _inertia(H, model)
    defined_there = ({**nonzero_where_defined(at.values()), **roots_where_defined(H)}) if at else {}
    if isinstance(found, Undecided) and defined_there:
        defined = _inertia(H.xreplace(defined_there), model)
        return found if isinstance(defined, Undecided) else defined
    return found


def _inertia(H: sp.Matrix, model: Model) -> Inertia | Undecided:
    found = matrix_inertia(H, model.decided_by)
    if isinstance(found, Undecided) and model.assumed:
        alone = matrix_inertia(H, model.assumed)
        return found if isinstance(alone, Undecided) else alone
    return found


def _coinciding(solutions: list[dict], model: Model) -> list[str]:
    """Equilibria that are distinct expressions but one configuration at the given
    values (branches meeting at a bifurcation, e.g. ±acos(g/(R Ω²)) = 0 when R Ω² = g):
    a warning names them, so that the count is not read as distinct configurations."""
    if not model.values:
        return []
    points = []
    for sol in solutions:
        try:
            points.append(tuple(complex(sp.N(v.xreplace(model.values), 20)) for v in sol.values()))
        except TypeError:  # a parameter without a value: not a number
            return []
    lines = []
    for i, p in enumerate(points):
        same = [j + 1 for j, r in enumerate(points) if max(abs(a - b) for a, b in zip(p, r)) <= 1e-12 * (1 + max(map(abs, p)))]
        if len(same) > 1 and same[0] == i + 1:
            lines.append(f"equilibria {', '.join(map(str, same))} coincide at the given parameter values (one "
                         "configuration where solution branches meet, a bifurcation), listed once per branch")
    return lines


@dataclass(frozen=True)
class Listed:
    """A solution of ∂V/∂q = 0 kept as an equilibrium, with the other solutions that
    describe the same configuration, and its singular point if the coordinates are
    singular there (and the fibre test found it an equilibrium)."""

    at: dict
    equivalent: tuple[dict, ...]
    singular: Singularity | None


@dataclass(frozen=True)
class Listing:
    """The equilibria of a model, each classified, with the singular configurations among
    them and the warnings of the search."""

    equilibria: tuple[Listed, ...]
    singular_points: tuple[tuple[dict, Singularity], ...]  # not equilibria, or undecided
    warnings: tuple[str, ...]


@memoized
def listing(model: Model) -> Listing:
    """The equilibria as the report lists them: solutions of ∂V/∂q = 0 at singular
    points of the coordinates set apart unless the fibre test shows an equilibrium
    (solvers/configuration/placement.py), and solutions that are one configuration (the same
    orientation, or the same up to a coordinate V does not depend on) merged into the
    first, the others named as equivalent. Solutions where a contact point would be off
    its edge (solvers/configuration/contact_span.py), where a spring with a natural
    length would be at zero length (zero_length.py), or outside a coordinate's declared
    range (declared_range.py), are dropped, a warning saying why."""
    solutions, warnings = find_equilibria(model)
    solutions, off = contact_span.split(model, solutions)
    solutions, crushed = zero_length.split(model, solutions)
    solutions, outside = declared_range.split(model, solutions)
    warnings = [*warnings, *contact_span.warnings(off), *crushed, *outside,
                *contact_span.undecided(model, solutions)]
    free = tuple(q for q in model.q if all(not e.has(q) for e in gradient(model)))
    kept: list[Listed] = []
    apart: list[tuple[dict, Singularity]] = []
    for sol in solutions:
        singular = singularity(model, sol)
        if singular is not None and singular.verdict is not Verdict.EQUILIBRIUM:
            apart.append((sol, singular))
            continue
        same = next((i for i, k in enumerate(kept) if same_placement(model, k.at, sol, free)), None)
        if same is None:
            kept.append(Listed(sol, (), singular))
        else:
            kept[same] = replace(kept[same], equivalent=(*kept[same].equivalent, sol))
    return Listing(tuple(_plain_first(model, k) for k in kept), tuple(apart), tuple(warnings))


def _plain_first(model: Model, listed: Listed) -> Listed:
    """One configuration written with the fewest negative coordinates first ((π, π), the
    double pendulum upright, and (−π, −π) as the same configuration), where that one is
    a regular point of the coordinates as the first found is."""
    if listed.singular is not None or not listed.equivalent:
        return listed
    plain = min(listed.equivalent, key=_negatives)
    if _negatives(plain) >= _negatives(listed.at) or singularity(model, plain) is not None:
        return listed
    others = tuple(e for e in (listed.at, *listed.equivalent) if e is not plain)
    return replace(listed, at=plain, equivalent=others)


def _negatives(at: Mapping) -> int:
    """How many coordinates of a root are written with a minus sign."""
    return sum(sp.sympify(v).could_extract_minus_sign() for v in at.values())


def classify_listed(model: Model, listed: Listed) -> Equilibrium:
    """``classify``, with the equivalents named; at a singular point that is an
    equilibrium, on the Hessian across the directions that move the scene."""
    names = dict(zip(model.q, model.coordinate_names()))
    found = classify(model, listed.at) if listed.singular is None else _classify_singular(model, listed.at)
    return replace(found, equivalent=tuple({names[q]: v for q, v in e.items()} for e in listed.equivalent))


def _classify_singular(model: Model, at: dict) -> Equilibrium:
    """Bᵀ K B, B a basis of the directions the kernel of ∂φ/∂q leaves (the coordinates
    see only these at a singular point)."""
    found = classify(model, at)
    kernel = exact_kernel(model, at)
    if not kernel:
        return found
    B = sp.Matrix.hstack(*sp.Matrix.hstack(*kernel).T.nullspace())
    reduced = (B.T * found.hessian * B).applyfunc(tidy)
    inertia = decided_inertia(sp.ImmutableMatrix(reduced), model, at)
    how = "at a singular point of the coordinates, the Hessian across the directions that move the scene"
    if isinstance(inertia, Undecided):
        return replace(found, stability=Stability.UNDETERMINED, reason=f"{how} has a sign that depends on the "
                       f"parameters ({to_unicode(inertia.expr)})")
    if inertia.negative:
        return replace(found, stability=Stability.UNSTABLE, reason=f"{how} has a negative eigenvalue")
    if inertia.zero:
        return replace(found, stability=Stability.UNDETERMINED, reason=f"{how} is singular: higher-order terms decide")
    return replace(found, stability=Stability.STABLE, reason=f"{how} is positive definite")


def singular_answers(model: Model, points) -> tuple[SingularPoint, ...]:
    names = dict(zip(model.q, model.coordinate_names()))
    return tuple(SingularPoint({names[q]: v for q, v in at.items()}, sing.verdict.value, sing.reason, sing.kernel)
                 for at, sing in points)


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_static(model, "the equilibria")
    grad = gradient(model)
    listed = listing(model)
    if not listed.equilibria and not listed.singular_points:
        if find_equilibria(model)[0]:  # roots, each set aside for a reason its warning gives (outside a range)
            answers = EquilibriaAnswers(())
            return Solution("equilibria", Route.EXACT, answers, exact_steps(answers, grad, model, False),
                            warnings=listed.warnings)
        return _uniform(model, grad, asked(model, question))
    first = asked(model, question)
    classified = [with_cases(classify_listed(model, x), model, x.at, first) for x in listed.equilibria]
    equilibria = tuple(eq for eq, _ in classified)
    critical = critical_values([c for _, cs in classified for c in cs])
    warnings = [*listed.warnings, *_coinciding([x.at for x in listed.equilibria], model), *spin_warnings(model),
                *_pulling(model, [x.at for x in listed.equilibria]), *_continuum_at_values(model, grad)]
    if listed.singular_points:
        warnings.append(f"{len(listed.singular_points)} solution(s) of ∂V/∂q = 0 lie at singular points of the "
                        "coordinates and are not equilibria of the scene (listed apart); " + SUGGESTION)
    answers = EquilibriaAnswers(equilibria, singular_answers(model, listed.singular_points), critical)
    return Solution("equilibria", Route.EXACT, answers, exact_steps(answers, grad, model,
                                                                bool(periodic_angles(model) | repeating(model))),
                    warnings=tuple(warnings))


def _continuum_at_values(model: Model, grad: tuple[sp.Expr, ...]) -> list[str]:
    """Where ∂V/∂q vanishes identically at the values given (springs that balance a rod's
    weight at any angle: (2 a² k − ½ m g l) sin θ with k = m g l/(4 a²)), every
    configuration is an equilibrium there: the listing, made in the parameters, does not
    say so by itself (its equilibria are 'undetermined' at these values)."""
    if not model.values or all(g == 0 for g in grad):
        return []  # V holds no coordinate whatever the values: said already
    valued = [g.xreplace(dict(model.values)) for g in grad]
    if any(g.free_symbols - set(model.q) for g in valued) or not all(tidy(g) == 0 for g in valued):
        return []  # a parameter without a value, or ∂V/∂q not identically 0 at the values
    return ["at the values given ∂V/∂q = 0 for every configuration: every configuration is an equilibrium "
            "(a continuum), neutral; the equilibria above and their cases hold in the parameters, off these values"]


def _pulling(model: Model, places: list[Mapping]) -> list[str]:
    """``contact_push.pulling`` at each equilibrium, for a scene with contacts (loaded
    only there: it brings the reactions' balances, not needed for the seed's rods)."""
    if not model.contacts:
        return []
    from rbdsolve.solvers.equilibria.contact_push import pulling

    return [w for at in places for w in pulling(model, at)]


def _uniform(model: Model, grad: tuple[sp.Expr, ...], first: sp.Symbol | None) -> Solution:
    """No isolated equilibrium: where ∂V/∂q holds no coordinate, every configuration is
    one under a condition on the parameters (uniform.py); else there is none."""
    found = uniform_equilibrium(model, grad, first)
    if found is None:
        never = never_balanced(model, grad, first) or _no_real_root(model)
        if never is None:
            raise UnsolvedError("∂V/∂q = 0 has no real solution: the system has no equilibrium")
        answers = EquilibriaAnswers(())  # an answer, not a failure: the loads never balance here
        return Solution("equilibria", Route.EXACT, answers, (*exact_steps(answers, grad, model, False), never))
    equilibrium, warning = found
    answers = EquilibriaAnswers((equilibrium,), critical=_balancing(equilibrium.exists_when, model))
    return Solution("equilibria", Route.EXACT, answers, exact_steps(answers, grad, model, False), warnings=(warning,))


def _no_real_root(model: Model):
    """The step that says there is no equilibrium at the parameter values, where ∂V/∂q =
    0 is polynomial in the coordinates, their sines and cosines, so that its roots are
    all found (a Gröbner basis), and none is real there (a disk held by a couple past
    m g R: sin θ = C₀/(m g R) > 1); None otherwise (a list that may be partial proves
    nothing)."""
    found = structure(model)
    if not model.values or found.shape is not Shape.POLYNOMIAL or found.why_partial is not None:
        return None
    if find_equilibria(model)[0]:  # roots there, set aside for another reason (a contact off its edge)
        return None
    return st.note("At the parameter values, ∂V/∂q = 0 (polynomial in the coordinates, their sines and cosines, "
                   "so every root is found) has no real root: the loads never balance, so there is no "
                   "equilibrium (with other values, or one left open, the roots and where they exist are given).")


def _balancing(where: sp.Basic, model: Model) -> tuple[CriticalValue, ...]:
    """The parameter values where the loads balance (F = g m₂: the only F with an
    equilibrium), as critical values where the other values make them numbers, so that
    those are printed (F_c = 14.715 N); symbolic, the relation says it in place."""
    relations = where.args if isinstance(where, sp.And) else (where,)
    return tuple(CriticalValue(str(r.lhs), r.rhs) for r in relations
                 if isinstance(r, sp.Eq) and isinstance(r.lhs, sp.Symbol) and model.values
                 and r.rhs.xreplace(dict(model.values)).is_number)
