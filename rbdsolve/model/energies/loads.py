"""Applied forces and couples: where they act, their generalized forces, and their
potential where they have one.

A force F on body B acts on B's material point at P (a point of the body, its origin,
or where a string wound on it leaves it); a couple M turns B (and −M turns ``by``, at a
joint: a motor). Their virtual work gives the generalized forces (e.g. Goldstein, ch. 1)

    Q_i = F · ∂v_P/∂q̇_i + M · (∂ω_B/∂q̇_i − ∂ω_by/∂q̇_i),    v_P = v_G + ω_B × (r_P − r_G),

the material point's velocity (a string leaving a turning drum moves with the drum's
point there, not with the tangent point, which stays put). Lagrange's equations are then
d/dt(∂L/∂q̇_i) − ∂L/∂q_i = Q_i.

A load has a potential V_F, with Q_i = −∂V_F/∂q_i, where it is conservative; it then
enters V (the equilibria, the modes and the energy integral take it from there). The
forms tried, each checked against Q at generic states before it is taken:

    V_F = −F·r_P              a constant force at a point of the body;
    V_F = −F·r_G − τ α_B      a constant force whose lever τ = ((r_P − r_G) × F)·e_z is
                              constant (a string wound on a rolling spool), α_B the body's angle;
    V_F = F |r_A − r_P|       a constant pull along the line to a fixed point A;
    V_F = −M (α_B − α_by)     a constant couple (planar);
    V_F = −∫ Q dq             one coordinate, Q free of t.

A load with none (a force that changes with t) stays a generalized force.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.tidy import tidy
from rbdsolve.form.zero import settled
from rbdsolve.model.state import t
from rbdsolve.model.symbols import Symbols
from rbdsolve.problem.expr import Kind
from rbdsolve.problem.schema import Problem

if TYPE_CHECKING:
    from rbdsolve.problem.scene import Couple, Force

_Z = sp.Matrix([0, 0, 1])


@dataclass(frozen=True)
class Load:
    """A force or a couple as sympy objects: on body ``body`` (and −moment on ``by``),
    acting at ``point`` (a couple: the body's centre), its generalized forces Q and its
    potential (None: it has none)."""

    name: str
    body: str
    by: str | None
    point: sp.Matrix  # scene axes
    force: sp.Matrix  # zero for a couple
    moment: sp.Matrix  # zero for a force
    generalized: tuple[sp.Expr, ...]  # Q_i, one per coordinate
    potential: sp.Expr | None
    source: Force | Couple

    @property
    def kind(self) -> str:
        return self.source.kind


def build_loads(problem: Problem, names: Symbols, bodies, decide) -> tuple[Load, ...]:
    """Every applied force and couple; ``bodies`` the model's RigidBody's, ``decide`` the
    sign of an expression in the parameters (1, −1, or None: undecided), by the values
    and the assumptions."""
    table = {b.name: b for b in bodies}
    for load in (*problem.forces, *problem.couples):
        if not table[load.on].placed or (getattr(load, "by", None) and not table[load.by].placed):
            raise InputError(f"{load.kind} '{load.name}': body '{load.on}' "
                             "is given by its velocities at one instant; a finite load does nothing in an impact "
                             "(give an impulse instead: 'impulses:' of the impact question)", load.loc)
    out = [_force(f, names, table[f.on], decide) for f in problem.forces]
    out += [_couple(c, names, table) for c in problem.couples]
    return tuple(out)


def _force(f: Force, names: Symbols, body, decide) -> Load:
    state = names.state
    at = names.vector(f.at) if f.at is not None else names.vector(body.source.at)
    if f.towards is not None:
        d = names.vector(f.towards) - at
        force = names.scalar(f.force) * d / sp.sqrt(d.dot(d))
    else:
        force = names.vector(f.force)
    point = at if f.wound is None else _leaves(f, names, at, force, decide)
    v = body.velocity(state) + body.angular_velocity(state).cross(point - body.position)
    Q = tuple(tidy(sp.expand(v.diff(qd).dot(force))) for qd in state.qd)
    base = Load(f.name, f.on, None, point, force, sp.zeros(3, 1), Q, None, f)
    candidates = [lambda: -force.dot(point), lambda: _levered(force, point, body, state),
                  lambda: _pulled(f, names, at, force), lambda: _integral(Q, state)]
    return _with_potential(base, candidates, force, names)


def _couple(c: Couple, names: Symbols, table) -> Load:
    state = names.state
    moment = names.vector(c.moment) if c.moment.kind is Kind.VECTOR else sp.Matrix([0, 0, names.scalar(c.moment)])
    on = table[c.on]
    omega = on.angular_velocity(state) - (table[c.by].angular_velocity(state) if c.by else sp.zeros(3, 1))
    Q = tuple(tidy(sp.expand(omega.diff(qd).dot(moment))) for qd in state.qd)
    base = Load(c.name, c.on, c.by, on.position, sp.zeros(3, 1), moment, Q, None, c)

    def turned() -> sp.Expr | None:
        angles = [table[n].angle if table[n].angle is not None else sp.Integer(0) for n in (c.on, c.by) if n]
        if any(table[n].turns_3d for n in (c.on, c.by) if n):
            return None
        return -moment[2] * (angles[0] - (angles[1] if len(angles) > 1 else 0))

    return _with_potential(base, [turned, lambda: _integral(Q, state)], moment, names)


def _with_potential(base: Load, candidates, value: sp.Matrix, names: Symbols) -> Load:
    """The load with the first candidate potential that gives its Q (none where the load
    changes with time)."""
    if value.has(t) or any(q.has(t) for q in base.generalized):
        return base
    for make in candidates:
        V = make()
        if V is not None and not V.has(t) and _gives(V, base.generalized, names):
            return Load(base.name, base.body, base.by, base.point, base.force, base.moment, base.generalized,
                        tidy(sp.expand(V)), base.source)
    return base


def _levered(force: sp.Matrix, point: sp.Matrix, body, state) -> sp.Expr | None:
    """−F·r_G − τ α for a planar body whose lever τ = ((r_P − r_G) × F)·e_z holds no q."""
    if body.angle is None or body.turns_3d:
        return None
    lever = settled(tidy((point - body.position).cross(force)[2]), state.q)
    if lever.has(*state.q):
        return None
    return -force.dot(body.position) - lever * body.angle


def _pulled(f: Force, names: Symbols, at: sp.Matrix, force: sp.Matrix) -> sp.Expr | None:
    """F |r_A − r_P| for a pull of constant size towards a point A."""
    if f.towards is None:
        return None
    d = names.vector(f.towards) - at
    return names.scalar(f.force) * sp.sqrt(d.dot(d))


def _integral(Q: tuple[sp.Expr, ...], state) -> sp.Expr | None:
    """−∫₀^q Q dq with one coordinate (a closed form only)."""
    if len(Q) != 1:
        return None
    q = state.q[0]
    s = sp.Dummy("s", real=True)
    found = sp.integrate(Q[0].xreplace({q: s}), (s, 0, q))
    return None if found.has(sp.Integral) else -found


def _gives(V: sp.Expr, Q: tuple[sp.Expr, ...], names: Symbols) -> bool:
    """Q_i = −∂V/∂q_i at two generic states (parameters and coordinates pseudo-random)."""
    residuals = [sp.diff(V, q) + Qi for q, Qi in zip(names.state.q, Q)]
    symbols = set().union(*(r.free_symbols for r in residuals)) if residuals else set()
    for seed in (5, 13):
        rng = random.Random(seed)
        point = {s: sp.Rational(rng.randint(11, 97), 37) for s in sorted(symbols, key=str)}
        for r in residuals:
            value = r.xreplace(point).evalf(30)
            size = sum(abs(sp.N(x.xreplace(point), 30)) for x in sp.Add.make_args(sp.expand(r))) or 1
            if not value.is_number or abs(value) > 1e-20 * (1 + size):
                return False
    return True


def _leaves(f: Force, names: Symbols, centre: sp.Matrix, force: sp.Matrix, decide) -> sp.Matrix:
    """Where a string wound at radius ρ about the centre leaves it along the force:
    C = centre + ρ n, n the unit normal to the force on the side asked (below, above,
    left or right of the centre as drawn: n·e > 0 for that side's e, a sign the
    parameters, their values or the assumptions decide)."""
    w = f.wound
    rho = names.scalar(w.radius)
    size = sp.sqrt(force.dot(force))
    unit = (force / size).applyfunc(lambda x: settled(tidy(sp.factor_terms(x)), (t, *names.state.q)))
    if unit.has(t, *names.state.q):
        raise InputError(f"force '{f.name}': a string wound on the body leaves it along the force, whose direction "
                         f"({to_unicode(unit.T)}) changes as the scene moves; a wound string's pull keeps one "
                         "direction (give the point where it acts with 'at:' instead)", w.loc)
    left = _Z.cross(unit)
    reference = {"below": sp.Matrix([0, -1, 0]), "above": sp.Matrix([0, 1, 0]),
                 "left": sp.Matrix([-1, 0, 0]), "right": sp.Matrix([1, 0, 0])}[w.side]
    along = sp.simplify(left.dot(reference))
    if along == 0:
        raise InputError(f"force '{f.name}': the string is pulled along the {w.side} direction itself, so it "
                         f"does not leave the body on its {w.side}: give the side across the pull", w.loc)
    sign = decide(along)
    if sign is None:
        deciding = -along if along.could_extract_minus_sign() else along
        raise InputError(f"force '{f.name}': whether the string leaves the body {w.side} its centre on the "
                         f"left or on the right of the pull depends on the sign of {to_unicode(deciding)}; give an "
                         f"assumption that decides it (such as 'assumptions: {_deciding(deciding)}'), or a value, "
                         "or the point where it leaves with 'at:'", w.loc)
    return centre + rho * sign * left


def _deciding(value: sp.Expr) -> str:
    """An assumption, as a file writes it, that fixes the sign of ``value``: [alpha < pi/2]
    for cos α (the angle of a slope or a pull), else [value > 0]."""
    if isinstance(value, sp.cos) and value.args[0].is_Symbol:
        return f"[{value.args[0]} < pi/2]"
    return f"[{value} > 0]"


def free_forces(model) -> tuple[sp.Expr, ...] | None:
    """Σ Q_i of the loads without a potential, one per coordinate (None: there are none):
    what Lagrange's equations d/dt(∂L/∂q̇_i) − ∂L/∂q_i = Q_i keep on their right."""
    free = [x for x in model.loads if x.potential is None]
    if not free:
        return None
    return tuple(tidy(sp.Add(*(x.generalized[i] for x in free))) for i in range(len(model.q)))
