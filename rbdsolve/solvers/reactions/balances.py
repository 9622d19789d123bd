"""Newton–Euler per body, and the forces solved from it.

For each body B held by the supports asked about (a free body diagram),

    m a_G = m g + Σ R            (linear momentum)
    dL_G/dt = Σ (r_P − r_G) × R + Σ M     (angular momentum about G, L_G = J_G ω)

where R is a support's force on B at P (a body named ``by`` feels −R and −M there), and
a_G, dL_G/dt carry q̈, replaced by the accelerations from Lagrange's equations. What is
left is linear in the unknown components x: A x = b. As many independent rows as
unknowns are solved exactly (chosen at a generic sample); the other rows must then hold
too — where they do not, a support on that body is missing from the question.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from rbdsolve.errors import InputError, Location, UnsolvedError
from rbdsolve.form.tidy import collect_in, tidy, tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import memoized
from rbdsolve.solvers.lagrange.accelerations import clean_fraction
from rbdsolve.solvers.reactions.applied import applied
from rbdsolve.problem.options import Support, SupportKind
from rbdsolve.solvers.reactions.supports import Held, body, contact_support, generic_point, planar
from rbdsolve.solvers.reactions.supports import held as held_support

_Z = sp.Matrix([0, 0, 1])


@dataclass(frozen=True)
class Balance:
    """One component of one body's balance: ``lhs = rhs`` (m a_G·e_k = Σ F·e_k, or the
    moment about G), exact, with q̈ still in it."""

    body: str
    label: str  # x, y, z or "moment about G (z)"
    lhs: sp.Expr
    rhs: sp.Expr


def with_strings(model: Model, supports: tuple[Held, ...], loc) -> tuple[Held, ...]:
    """The supports asked, and every string that pulls a body among them (a drum's or a
    pulley's tension, the string of a hanging body, the strings over a pulley with mass
    whose axle is asked): a string is inside the system, so
    its tension is found with the others, from the balance of the body at its other end
    (that body joins the free body diagrams). Added until no held body has a string left."""
    out = list(supports)
    while True:
        held, named = set(bodies_held(tuple(out))), {s.name for s in out}
        more = [c for c in model.contacts if c.source.string and c.name not in named
                and (c.body in held or (c.source.pulley is not None and held & {c.source.pulley.drum,
                                                                               c.source.pulley.wheel}))]
        if not more:
            return tuple(out) + _axles(model, tuple(out), loc)
        out += [replace(contact_support(model, c), loc=loc, added=True) for c in more]


def _axles(model: Model, supports: tuple[Held, ...], loc) -> tuple[Held, ...]:
    """The axle of each pulley with mass that a string among the supports runs over,
    where no support asked holds that pulley: its balance gives the tension off the drum
    (its moment: R (T₁ − T₂) = J ψ̈), so it joins the free body diagrams."""
    held, out = set(bodies_held(supports)), []
    for s in supports:
        contact = next((c for c in model.contacts if c.name == s.name and c.source.pulley is not None), None)
        wheel = contact.source.pulley.wheel if contact is not None else None
        if wheel is not None and wheel not in held:
            axle = Support(SupportKind.POINT, wheel, wheel, None, None, loc or contact.source.pulley.wheel_loc)
            out.append(replace(held_support(model, axle), added=True))
            held.add(wheel)
    return tuple(out)


def bodies_held(supports: tuple[Held, ...]) -> list[str]:
    """The bodies on which the supports act, in the order they are first named."""
    names: list[str] = []
    for s in supports:
        for name in (s.on, s.by):
            if name is not None and name not in names:
                names.append(name)
    return names


def balances(model: Model, supports: tuple[Held, ...], dims: int) -> list[Balance]:
    """The free body diagram of every held body, component by component."""
    out = []
    pulls = applied(model, bodies_held(supports))
    for name in bodies_held(supports):
        b = body(model, name)
        acceleration = model.state.d_dt(model.state.d_dt(b.position))
        force = (b.mass * model.gravity) if model.gravity is not None else sp.zeros(3, 1)
        moment = sp.zeros(3, 1)
        for s in supports:
            sign = 1 if s.on == name else -1 if s.by == name else 0
            for c in s.components:
                if c.moment:
                    moment += sign * c.symbol * c.direction
                else:
                    force += sign * c.symbol * c.direction
                    moment += sign * (s.point - b.position).cross(c.symbol * c.direction)
                for other, point, direction in c.also:  # a string's other end, on its drum
                    if other == name:
                        force += c.symbol * direction
                        moment += (point - b.position).cross(c.symbol * direction)
        for a in pulls:
            if a.body == name:
                force += a.force
                moment += (a.point - b.position).cross(a.force) + a.moment
        L_dot = model.state.d_dt(b.inertia_in_scene() * b.angular_velocity(model.state))
        for k in range(dims):
            lhs = _tidied(b.mass * acceleration[k], model)
            if lhs != 0 or sp.expand(force[k]) != 0:  # 0 = 0: a direction nothing acts along
                out.append(Balance(name, "xyz"[k], lhs, force[k]))
        for k in ((2,) if dims == 2 else range(3)):
            lhs = _tidied(L_dot[k], model)
            if lhs != 0 or sp.expand(moment[k]) != 0:
                out.append(Balance(name, f"moment about G ({'xyz'[k]})", lhs, _moment(moment[k])))
    return out


def _tidied(expr: sp.Expr, model: Model) -> sp.Expr:
    """m a_G·e_k or dL_G/dt·e_k collected in q̈ and q̇, each coefficient tidied."""
    parts = collect_in(sp.expand(expr), [*model.qdd, *model.qd])
    return sp.Add(*[c * m for m, c in parts.items()])


def _moment(expr: sp.Expr) -> sp.Expr:
    return sp.collect(tidy(sp.expand(expr)), sorted(expr.free_symbols, key=str))


def solve_forces(model: Model, rows: list[Balance], supports: tuple[Held, ...],
                 qdd: dict[sp.Symbol, sp.Expr]) -> dict[sp.Symbol, sp.Expr]:
    """x from A x = b, the accelerations put in; the rows not used must hold too. Where
    one does not, the question lists a point that holds nothing or leaves a support out:
    bad input, located at the first force asked for on that body."""
    unknowns = tuple(c.symbol for s in supports for c in s.components)
    exprs = tuple(sp.expand((r.lhs - r.rhs).xreplace(qdd)) for r in rows)
    solution, unused = _solution(model, exprs, unknowns)
    solution = dict(solution)
    for i in unused:
        if not _holds(exprs[i].xreplace(solution), model):
            row = rows[i]
            raise InputError(unheld(row.body, f"its {row.label} balance") + _on_strings(row.body, supports)
                             + _on_drum(row.body, supports),
                             located(supports, row.body))
    return solution


@memoized  # a reactions question and the energy question's check on the way (on_the_way.py) solve the same rows
def _solution(model: Model, exprs: tuple[sp.Expr, ...], unknowns: tuple[sp.Symbol, ...]
              ) -> tuple[tuple[tuple[sp.Symbol, sp.Expr], ...], tuple[int, ...]]:
    """x from A x = b (Cramer's rule on independent rows), and the rows not used."""
    A = sp.Matrix([[sp.diff(e, x) for x in unknowns] for e in exprs])
    b = sp.Matrix([-e.xreplace({x: 0 for x in unknowns}) for e in exprs])
    chosen = _independent_rows(A, model, len(unknowns))
    if len(chosen) < len(unknowns):
        raise UnsolvedError("the balances do not fix every force asked for (statically indeterminate: more "
                            f"unknowns than independent balances among {', '.join(map(str, unknowns))})")
    A_s, b_s = A.extract(chosen, list(range(len(unknowns)))), b.extract(chosen, [0])
    det = tidy_fraction(A_s.det(method="berkowitz"))
    solution = []
    for j, x in enumerate(unknowns):
        Aj = A_s.copy()
        Aj[:, j] = b_s
        solution.append((x, clean_fraction(sp.expand(Aj.det(method="berkowitz")) / det)))
    return tuple(solution), tuple(i for i in range(len(exprs)) if i not in chosen)


def unheld(name: str, what: str) -> str:
    return (f"the forces asked for cannot keep body '{name}' in its motion ({what} is left unsatisfied): a "
            "point listed does not hold it, or a support on it is missing from 'forces' (a pivot, a joint with "
            "another body, a contact; strings, springs and the applied loads are counted by themselves)")


def _on_strings(name: str, supports: tuple[Held, ...]) -> str:
    """For a body held only by strings: what the format needs to hold it across them."""
    mine = [s for s in supports if name in (s.on, s.by)]
    if not mine or any(s.how.value != "string" for s in mine):
        return ""
    strings = ", ".join(s.name for s in mine)
    return (f". Body '{name}' is held only by string {strings}, which pulls it along the string: what carries it "
            f"across (a table it slides on, a guide) is a support to list, such as {{at: {name}, on: {name}, "
            "normal: y} (a smooth surface's push, counted positive upwards)")


def _on_drum(name: str, supports: tuple[Held, ...]) -> str:
    """For a drum whose strings are all counted and still cannot keep it: the string the
    format cannot name (one between two bodies with mass), and what does hold."""
    strings = [s.name for s in supports for c in s.components if any(other == name for other, _, _ in c.also)]
    if not strings:
        return ""
    return (f". The strings on body '{name}' that the scene names ({', '.join(strings)}) are counted on it; a "
            "string from it to another body with mass (over a second pulley with mass, a belt between two drums) "
            "is not in the format yet, which names strings from a drum to a hanging body only: the eom and the "
            "tensions at the hanging bodies hold, the axle forces of such pulleys are not answered")


def located(supports: tuple[Held, ...], name: str) -> Location | None:
    """Where the question asks for the first force on body ``name``."""
    return next((s.loc for s in supports if name in (s.on, s.by)), None)


def _independent_rows(A: sp.Matrix, model: Model, wanted: int) -> list[int]:
    """Rows of A independent at a generic sample, greedily, up to ``wanted``; rows whose
    coefficients hold no coordinate first (a body's force balances before a moment
    balance), so that the determinant Cramer's rule divides by holds none where it can:
    one that does (sin θ) would make a force 0/0 at θ = 0 though the force is finite."""
    numeric = A.xreplace(generic_point(model, 5)).evalf(30)
    chosen: list[int] = []
    moving = [sum(1 for x in A.row(i) if x.has(*model.q)) for i in range(A.rows)]
    for i in sorted(range(A.rows), key=lambda i: moving[i]):
        trial = numeric.extract(chosen + [i], list(range(A.cols)))
        if trial.rank(iszerofunc=lambda x: abs(x) < 1e-20) == len(chosen) + 1:
            chosen.append(i)
        if len(chosen) == wanted:
            break
    return chosen


def _holds(residual: sp.Expr, model: Model) -> bool:
    """Zero at two generic samples, relative to the size of its terms."""
    for seed in (3, 17):
        # the point as 30-digit floats: the residual is then evaluated as it is built (exact
        # rationals put in built the whole expression first, radicals and all: 4 times slower)
        point = {s: sp.N(v, 30) for s, v in generic_point(model, seed).items()}
        value = abs(sp.N(residual.xreplace(point), 30))
        size = sum(abs(sp.N(t.xreplace(point), 30)) for t in sp.Add.make_args(sp.expand(residual))) or 1
        if value > 1e-15 * size:
            return False
    return True


def contact_forces(model: Model, table) -> tuple[tuple[Held, ...], dict[sp.Symbol, sp.Expr]] | None:
    """Newton–Euler with the scene's contacts and strings (a body hanging over a pulley
    aside) as the only supports, ``table`` put in (q̈ from Lagrange's equations, or the
    state at rest): the supports and their forces; None where the scene has none, is
    not planar, or they do not hold its bodies by themselves (a pivot too). Where a
    contact would have to pull at an equilibrium (equilibria/contact_push.py), where one
    is lost on the way to a configuration (on_the_way.py)."""
    contacts = [c for c in model.contacts if c.source.pulley is None]
    if not contacts or not planar(model):
        return None
    try:
        supports = with_strings(model, tuple(contact_support(model, c) for c in contacts), None)
        return supports, solve_forces(model, balances(model, supports, 2), supports, dict(table))
    except (InputError, UnsolvedError, ValueError, TypeError, ZeroDivisionError):
        return None
