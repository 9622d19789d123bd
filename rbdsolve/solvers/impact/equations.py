"""The impulse equations of an impact: Lagrange's equations for impact, set up and solved.

During an impact the configuration does not change and finite forces give no impulse.
Integrating Lagrange's equations over the impact gives, for each coordinate q_a,

    ∂T/∂q̇_a |_f − ∂T/∂q̇_a |_i = I_a,      I_a = Σ_k P_k · ∂v_k/∂q̇_a

(i just before, f just after; P_k the impulse at a point with velocity v_k; e.g. the
worked solution of problem 2 in the KTH SG2150 exam of 2015-10-29, or Greenwood,
Advanced Dynamics, ch. 3). T is quadratic in q̇ with M(q) frozen during the impact, so
the left side is M (q̇_f − q̇_i): the impulse equations' matrix is the mass matrix at the
instant. Smooth ideal constraints give no generalized impulse.

A collision whose impulse is unknown, λ n along the normal n at point P (as given:
the law below is homogeneous in n, so n is never normalized and no √ enters), adds λ
as an unknown and Newton's law of restitution as its equation,

    n · (v_P − u)_f = −e n · (v_P − u)_i,

with u the velocity of what P hits: 0 for a fixed surface, and for a particle of mass
μ, u_f = u_i − λ n / μ (it gets the opposite impulse).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import InputError, UnsolvedError
from rbdsolve.form.stand_ins import stand_ins
from rbdsolve.form.tidy import tidy, tidy_fraction
from rbdsolve.model.build import Model, RigidBody
from rbdsolve.model.energies.energy import body_kinetic_energy, tidy_quadratic
from rbdsolve.model.constraints.plane_rolling import material_velocity, tangents
from rbdsolve.model.state import t
from rbdsolve.problem import expr as ex
from rbdsolve.problem.sections.impact import restitution_message
from rbdsolve.problem.options import Collision, ImpactOptions
from rbdsolve.solvers.impact.answers import ImpactAnswers
from rbdsolve.solvers.configuration.singular import exact_reason


@dataclass(frozen=True)
class Blow:
    """An impulse on the system at ``point``: known, or λ n with λ unknown."""

    point: str
    impulse: sp.Matrix
    size: sp.Symbol | None  # λ, when the impulse is unknown
    normal: sp.Matrix | None  # the normal as given, or the impulse's direction (collisions)
    collision: Collision | None
    components: tuple[sp.Symbol, ...] = ()  # a sticking particle's unknown impulse (P_x, P_y, P_z)
    partner: str | None = None  # a sticking point's partner: the other body's point (it feels −P)
    directions: tuple[sp.Matrix, ...] = ()  # a sticking point's: the directions its impulse has components in

    @property
    def sticking_point(self) -> bool:
        """A body's point that sticks (to a fixed point, or to its partner)."""
        return self.collision is not None and self.collision.sticks and self.collision.particle is None


@dataclass(frozen=True)
class Instant:
    """The kinematics at the impact instant, linear in the rates q̇."""

    model: Model
    at: Mapping[sp.Symbol, sp.Expr]
    T: sp.Expr  # ½ q̇ᵀ M q̇ + … at the instant

    def velocity(self, point: str) -> sp.Matrix:
        """A point's velocity at the instant; at a contact on a plane, the body's material
        point there (model/constraints/plane_rolling.py)."""
        contact = next((c for c in self.model.plane_contacts if c.name == point), None)
        if contact is not None:
            body = next(b for b in self.model.bodies if b.name == contact.body)
            return material_velocity(contact, body, self.model.state).xreplace(self.at)
        return self.model.point_velocity(point).xreplace(self.at)

    def body_velocity(self, body: RigidBody) -> sp.Matrix:
        return body.velocity(self.model.state).xreplace(self.at)

    def struck_velocity(self, blow: "Blow") -> sp.Matrix:
        """The velocity the blow's impulse works on: its point's, or, for a point that
        sticks to another body's point, the one relative to that point (P on one, −P on
        the other)."""
        v = self.velocity(blow.point)
        return v - self.velocity(blow.partner) if blow.partner is not None else v


def instant(model: Model, opts: ImpactOptions) -> Instant:
    """Substitute the configuration into every velocity; what is left must be known."""
    names = model.symbols
    at = {model.symbols.coordinates[name]: names.scalar(value) for name, value in opts.at}
    T = sum((body_kinetic_energy(b, model.state).xreplace(at) for b in model.bodies), sp.Integer(0))
    T = tidy_quadratic(T, model.qd)
    require_known(T, model, opts)
    return Instant(model, at, T)


def require_known(expr: sp.Expr, model: Model, opts: ImpactOptions) -> None:
    missing = [n for q, n in zip(model.q, model.coordinate_names()) if expr.has(q)]
    if missing:
        raise InputError(f"the velocities at the instant depend on {', '.join(missing)}: give "
                         f"{'its value' if len(missing) == 1 else 'their values'} with 'at:'", opts.loc)
    if expr.has(t):
        raise UnsolvedError("the scene moves by itself (its positions depend on t): an impact at a "
                            "given time is not supported yet")


def blows(model: Model, opts: ImpactOptions, now: Instant) -> list[Blow]:
    """Known impulses, impulses of particles with a given velocity after, and unknown
    collision impulses λ n (n as given)."""
    names = model.symbols
    out = [Blow(point, names.vector(vector), None, None, None) for point, vector in opts.impulses]
    for c in opts.collisions:
        normal = _nonzero(names.vector(c.normal), c) if c.normal is not None else None
        if c.particle is not None:
            _positive(names.scalar(c.particle.mass), c.particle.mass, model)
        if c.sticks and c.particle is None:  # a body's point sticks: a pivot just after
            out.append(_sticking_point(c, model, opts, now))
        elif c.sticks:  # the particle embeds: an unknown impulse, every component
            components = tuple(sp.Dummy(f"P{axis}_{c.point}") for axis in "xyz")
            out.append(Blow(c.point, sp.Matrix(components), None, None, c, components))
        elif c.restitution is None:  # a particle with a known velocity after: a known impulse
            mu = names.scalar(c.particle.mass)
            P = mu * (names.vector(c.particle.velocity) - names.vector(c.particle.after))
            if normal is None:
                normal = P if P != sp.zeros(3, 1) else None
            out.append(Blow(c.point, P, None, normal, c))
        else:
            size = sp.Dummy(f"lamda_{c.point}")
            out.append(Blow(c.point, size * normal, size, normal, c))
    return out + [_rolling(c) for c in model.plane_contacts]


def _sticking_point(c: Collision, model: Model, opts: ImpactOptions, now: Instant) -> Blow:
    """A body's point P that sticks to a fixed point (a ledge), or to point Q of another
    body, becomes a pivot at the instant: it moves with what it sticks to just after. The
    impulse there, P on P's body (and −P on Q's), is unknown in every direction P can move
    relative to what it sticks to — the span of the partial velocities ∂(v_P − v_Q)/∂q̇;
    along the others the supports the coordinates already hold take it."""
    blow = Blow(c.point, sp.zeros(3, 1), None, None, c, partner=c.to)
    velocity = now.struck_velocity(blow)
    require_known(velocity, model, opts)
    directions = _directions(velocity, model.qd)
    if not directions:
        raise UnsolvedError(f"the point {c.point} cannot move{' relative to ' + c.to if c.to else ''} at the instant "
                            "(its partial velocities are all zero): it is held already, so sticking changes nothing; "
                            "a sticking point is a point of a moving body (the end of a falling rod)")
    named = all(sum(abs(x) for x in w) == 1 for w in directions)  # the scene's axes: P_x, P_y
    components = tuple(sp.Dummy(f"P{_axis_name(w) if named else k + 1}_{c.point}") for k, w in enumerate(directions))
    impulse = sum((x * w for x, w in zip(components, directions)), sp.zeros(3, 1))
    return Blow(c.point, impulse, None, None, c, components, c.to, directions)


def _directions(velocity: sp.Matrix, rates) -> tuple[sp.Matrix, ...]:
    """A basis of the span of the partial velocities ∂v/∂q̇ₐ (the directions the point
    can move in at the instant): first the scene's axes that lie in it, then partial
    velocities themselves."""
    J = sp.Matrix.hstack(*[velocity.diff(x).applyfunc(tidy) for x in rates])
    rank = J.rank(simplify=True)
    chosen: list[sp.Matrix] = []
    for w in [*(sp.eye(3)[:, k] for k in range(3)), *(J[:, k] for k in range(J.cols))]:
        if len(chosen) == rank:
            break
        if (sp.Matrix.hstack(J, w).rank(simplify=True) == rank
                and sp.Matrix.hstack(*chosen, w).rank(simplify=True) == len(chosen) + 1):
            chosen.append(w)
    return tuple(chosen)


def _axis_name(w: sp.Matrix) -> str:
    return "xyz"[next(k for k in range(3) if w[k] != 0)]


def _rolling(contact) -> Blow:
    """A body rolling on a plane keeps rolling through the impact (a rough plane, no
    slip): the plane's impulse at C along it, F₁ t₁ + F₂ t₂, is unknown, and C's material
    point is at rest just after along the plane. The push along n does no work on the
    coordinates (they keep the body on the plane: v_C·n = 0), so it is not an unknown."""
    t1, t2 = tangents(contact.normal)
    components = (sp.Dummy(f"F1_{contact.name}"), sp.Dummy(f"F2_{contact.name}"))
    return Blow(contact.name, components[0] * t1 + components[1] * t2, None, contact.normal, None, components)


def _on_the_plane(blow: Blow, velocity: sp.Matrix) -> None:
    """The coordinates must keep a rolling body on its plane, v_C·n = 0 for any rates:
    then the plane's push does no work and only the impulse along it is unknown."""
    normal = tidy(velocity.dot(blow.normal))
    if normal != 0:
        raise UnsolvedError(f"at the contact {blow.point} the body's point moves off the plane (v·n = "
                            f"{to_unicode(normal)}): a contact on a plane needs coordinates that keep the body on "
                            "it (its height given by its turns, as in 'at: [x, y, r]' for a ball)")


def _nonzero(vector: sp.Matrix, collision: Collision) -> sp.Matrix:
    if tidy_fraction(vector.dot(vector)) == 0:
        raise InputError("a normal must not be the zero vector", collision.normal.loc)
    return vector


def _positive(value: sp.Expr, expr: ex.Expr, model: Model) -> None:
    number = _known_value(value, model)
    if value.is_nonpositive or (number is not None and number <= 0):
        raise InputError(f"a particle's mass must be positive, found {expr.text}", expr.loc)


class ImpactEquations:
    """The impulse equations of one impact, set up and solved on construction."""

    def __init__(self, model: Model, opts: ImpactOptions, now: Instant, hits: list[Blow]):
        self.model, self.opts, self.now, self.hits = model, opts, now, hits
        given = dict(opts.before)
        self.before = {qd: model.symbols.scalar(given[n]) if n in given else sp.Integer(0)
                       for n, qd in zip(model.coordinate_names(), model.qd)}
        self.final = tuple(sp.Dummy(f"{n}_f") for n in model.coordinate_names())
        self.after = dict(zip(model.qd, self.final))
        self.sizes = [b.size for b in hits if b.size is not None] + [x for b in hits for x in b.components]
        self.I = [tidy(sum((b.impulse.dot(sp.diff(now.struck_velocity(b), qd)) for b in hits), sp.Integer(0)))
                  for qd in model.qd]
        self.momenta = [sp.diff(now.T, qd) for qd in model.qd]  # ∂T/∂q̇_a
        self.solution = self._solve()

    # --- the equations -----------------------------------------------------------------

    def lagrange(self) -> list[sp.Expr]:
        """∂T/∂q̇_a|_f − ∂T/∂q̇_a|_i − I_a = 0."""
        return [p.xreplace(self.after) - p.xreplace(self.before) - I for p, I in zip(self.momenta, self.I)]

    def other_velocity(self, blow: Blow, final: bool) -> sp.Matrix:
        """u: the velocity of what the point hits (a fixed surface: 0)."""
        particle = blow.collision.particle if blow.collision else None
        if particle is None:
            return sp.zeros(3, 1)
        names = self.model.symbols
        u = names.vector(particle.velocity)
        return u - blow.impulse / names.scalar(particle.mass) if final else u

    def normal_speed(self, blow: Blow, final: bool) -> sp.Expr:
        """n · (v_P − u), before or after (after: in the unknowns ẋ_f, λ): negative
        while approaching."""
        v = self.now.velocity(blow.point).xreplace(self.after if final else self.before)
        return blow.normal.dot(v - self.other_velocity(blow, final))

    def restitution(self, collision: Collision) -> sp.Expr:
        """e, checked to lie in [0, 1] as far as its sign and the values tell."""
        e = self.model.symbols.scalar(collision.restitution)
        value = _known_value(e, self.model)
        if e.is_negative or (e - 1).is_positive or (value is not None and not 0 <= value <= 1):
            raise InputError(restitution_message(collision.restitution.text, value), collision.restitution.loc)
        return e

    def restitution_equations(self) -> list[sp.Expr]:
        """n · (v_P − u)_f + e n · (v_P − u)_i = 0, one per unknown collision impulse."""
        out = []
        for blow in self.hits:
            if blow.size is None:
                continue
            e = self.restitution(blow.collision)
            approach = tidy_fraction(self.normal_speed(blow, final=False))
            if _nonnegative(approach, self.model):
                raise UnsolvedError(f"at {blow.point} the normal velocity n·(v − u) just before is "
                                    f"{to_unicode(approach)}, so nothing approaches: no collision, or the normal "
                                    "points the wrong way (it is the direction of the impulse on the system)")
            out.append(self.normal_speed(blow, final=True) + e * approach)
        return out

    def sticking_equations(self) -> list[sp.Expr]:
        """v_P|f − u|f = 0 component by component, u_f = u_i − P/μ: a sticking particle
        moves with the point just after (the particle's own momentum balance is in u_f);
        a body's point that sticks is at rest relative to what it sticks to just after,
        w·(v_P − v_Q)|f = 0 along each direction w of its impulse."""
        out = []
        for blow in self.hits:
            if blow.sticking_point:
                v = self.now.struck_velocity(blow).xreplace(self.after)
                out += [v.dot(w) for w in blow.directions]
            elif blow.components and blow.collision is None:  # rolling on a plane: at rest along it
                _on_the_plane(blow, self.now.velocity(blow.point))
                v = self.now.velocity(blow.point).xreplace(self.after)
                out += [v.dot(t) for t in tangents(blow.normal)]
            elif blow.components:
                v = self.now.velocity(blow.point).xreplace(self.after)
                out += list(v - self.other_velocity(blow, final=True))
        return out

    def equations(self) -> list[sp.Expr]:
        return [*self.lagrange(), *self.restitution_equations(), *self.sticking_equations()]

    def _solve(self) -> dict[sp.Symbol, sp.Expr]:
        unknowns = [*self.final, *self.sizes]
        equations = self.equations()
        A, b = sp.linear_eq_to_matrix([sp.expand(x) for x in equations], unknowns)
        values = solve_linear(A, b)
        if values is None:
            raise UnsolvedError(self.singular_reason(exact_reason(self.inertia(), self.model.coordinate_names(),
                                                                  "at the instant")))
        return {u: tidy_fraction(x) for u, x in zip(unknowns, values)}

    def inertia(self) -> sp.Matrix:
        """M at the instant, ∂²T/∂q̇∂q̇: the impulse equations' matrix without collisions."""
        return sp.Matrix([[sp.diff(p, qd) for qd in self.model.qd] for p in self.momenta])

    def singular_reason(self, inertia: str | None) -> str:
        """Why the impulse equations have no unique solution: the mass matrix at the instant
        (``singular``: a coordinate or a combination that moves no mass), else the collisions'
        columns (their generalized impulses) are dependent."""
        if inertia:
            return f"the impulse equations are singular (no unique solution): {inertia}"
        return ("the impulse equations are singular (no unique solution): the mass matrix is regular, so the unknown "
                "collision impulses are not independent (two collisions push the system the same way, or a "
                "collision point moves with no coordinate along its normal)")

    # --- the results -------------------------------------------------------------------

    def results(self) -> tuple[ImpactAnswers, tuple[str, ...]]:
        """The answers, and warnings about what they imply."""
        model, sol = self.model, self.solution
        names = model.coordinate_names()
        final = {qd: sol[f] for qd, f in self.after.items()}
        impulses = [tidy_fraction(I.xreplace(sol)) for I in self.I]
        points = {p: tuple(tidy_fraction(x) for x in self.now.velocity(p).xreplace(final)) for p in self.opts.points}
        before, after = self.energy(final=False), self.energy(final=True)
        support = self.support_impulse(final)
        restitution, notes = self.equivalent_restitution()
        centre, why = self.centre_of_percussion(support)
        contacts = {b.point: tidy_fraction(sol[b.size] * sp.sqrt(tidy_fraction(b.normal.dot(b.normal))))
                    for b in self.hits if b.size is not None}
        sticking = {b.point: tuple(tidy_fraction(x) for x in b.impulse.xreplace(sol)) for b in self.hits
                    if b.components}
        notes += [f"the impulse at {p} comes out pulling ({to_unicode(v)} < 0): with several contacts at once "
                  "Newton's law can fail, and this contact probably separates" for p, v in contacts.items()
                  if v.is_negative or (_known_value(v, model) or 0) < 0]
        answers = ImpactAnswers(
            impulses=dict(zip(names, impulses)),
            velocities={n: sol[f] for n, f in zip(names, self.final)},
            points=points,
            particles=self.particle_velocities(),
            contact_impulses=contacts,
            sticking_impulses=sticking,
            restitution=restitution,
            energy_before=before,
            energy_after=after,
            energy_lost=tidy_fraction(before - after),
            support_impulse=support,
            centre_of_percussion=centre,
            energy_fraction=None if before == 0 else tidy_fraction((before - after) / before),
        )
        return answers, tuple(notes + ([why] if why else []))

    def particle_velocities(self) -> dict[str, tuple[sp.Expr, sp.Expr, sp.Expr]]:
        return {b.point: tuple(tidy_fraction(x) for x in self.other_velocity(b, final=True).xreplace(self.solution))
                for b in self.hits if b.collision and b.collision.particle}

    def energy(self, final: bool) -> sp.Expr:
        """T of the system plus ½ μ u·u of each striking particle."""
        rates = {qd: self.solution[f] for qd, f in self.after.items()} if final else self.before
        total = self.now.T.xreplace(rates)
        for blow in self.hits:
            if blow.collision and blow.collision.particle:
                u = self.other_velocity(blow, final).xreplace(self.solution)
                total += self.model.symbols.scalar(blow.collision.particle.mass) * u.dot(u) / 2
        return tidy_fraction(total)

    def equivalent_restitution(self) -> tuple[dict[str, sp.Expr], list[str]]:
        """e = −n·(v_P − u)_f / n·(v_P − u)_i where a particle's velocity after is given,
        with warnings when the given velocities do not make a collision."""
        out, notes = {}, []
        for blow in self.hits:
            if blow.size is not None or blow.collision is None or blow.normal is None:
                continue
            if blow.collision.normal is not None and _nonnegative(-blow.impulse.dot(blow.normal), self.model):
                notes.append(f"at {blow.point} the particle's impulse on the system points against the "
                             "given normal")
            approach = tidy_fraction(self.normal_speed(blow, final=False))
            if _nonnegative(approach, self.model):
                notes.append(f"at {blow.point} nothing approaches along the normal (n·(v − u) just before "
                             f"is {to_unicode(approach)}): no restitution coefficient")
                continue
            e = tidy_fraction(-self.normal_speed(blow, final=True).xreplace(self.solution) / approach)
            value = _known_value(e, self.model)
            if value is not None and not 0 <= value <= 1:
                notes.append(f"the velocities given at {blow.point} imply a restitution coefficient "
                             f"{to_unicode(e)}, outside [0, 1]")
            out[blow.point] = e
        return out, notes

    def support_impulse(self, final: dict) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """What the supports gave: the change of momentum, Σ m Δv_G, less the impulses."""
        dp = sp.zeros(3, 1)
        for body in self.model.bodies:
            v = self.now.body_velocity(body)
            dp += body.mass * (v.xreplace(final) - v.xreplace(self.before))
        applied = sum((b.impulse.xreplace(self.solution) for b in self.hits if b.partner is None),  # P − P inside
                      sp.zeros(3, 1))
        return tuple(tidy_fraction(x) for x in dp - applied)

    def centre_of_percussion(self, support: tuple[sp.Expr, ...]) -> tuple[sp.Expr | None, str | None]:
        """The parameter's value that makes every component of the support impulse
        zero, or None and why not."""
        name = self.opts.centre_of_percussion
        if name is None:
            return None, None
        p = self.model.symbols.parameters[name]
        equations = [x for x in support if x != 0]
        if not equations:
            return None, f"the supports feel no impulse whatever {name} is"
        try:
            found = sp.solve(equations, p, dict=True)
        except NotImplementedError:
            found = []
        values = [tidy_fraction(f[p]) for f in found if p in f]
        exact = [v for v in values if all(tidy_fraction(x.xreplace({p: v})) == 0 for x in equations)]
        if len(exact) != 1:
            return None, f"no single value of {name} frees the supports of impulse"
        return exact[0], None


def solve_linear(A: sp.Matrix, b: sp.Matrix) -> list[sp.Expr] | None:
    """x with A x = b, exactly, or None when A is singular.

    sin α, cos α and radicals such as √3 are taken as symbols, so A is a matrix of
    rational functions and the solve runs in a fraction field (sympy's DomainMatrix):
    no expression swell, and the √3² that appear become 3 again on the way back.
    """
    atoms = {x for x in (A.atoms(sp.Function) | b.atoms(sp.Function))}
    atoms |= {p for p in (A.atoms(sp.Pow) | b.atoms(sp.Pow)) if not p.exp.is_Integer}
    table, back = stand_ins(atoms)
    square = DomainMatrix.from_Matrix(A.xreplace(table)).to_field()
    # singular also when det A vanishes only through √3·√3 = 3 or sin² + cos² = 1
    if tidy_fraction(square.domain.to_sympy(square.det()).xreplace(back)) == 0:
        return None
    system = DomainMatrix.from_Matrix(A.xreplace(table).row_join(b.xreplace(table))).to_field()
    n = A.shape[1]
    rref, pivots = system.rref()
    if tuple(pivots) != tuple(range(n)):
        return None
    column = rref.to_Matrix()[:, n]
    return [sp.cancel(x).xreplace(back) for x in column]


def _nonnegative(value: sp.Expr, model: Model) -> bool:
    """Provably ≥ 0, from the parameters' signs or their values."""
    number = _known_value(value, model)
    return bool(value.is_nonnegative) or (number is not None and number >= 0)


def _known_value(value: sp.Expr, model: Model) -> float | None:
    """The value at the parameters' values, if every parameter in it has one."""
    number = value.xreplace(model.values)
    return float(number) if number.is_number and number.is_real else None
