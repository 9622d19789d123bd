"""The steps of an impact solution, in the order of the seed's problem 2: velocities at
the instant, T, partial velocities, generalized impulses, Lagrange's equations for
impact, their solution, then what follows from it."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import along_axes, configuration, ordered_sum, scaled_sum
from rbdsolve.form.display import Label, Math, Relation
from rbdsolve.form.printers import float_text, to_unicode, within_rounding
from rbdsolve.form.tidy import collect_in, tidy, tidy_fraction
from rbdsolve.model.state import t
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Step
from rbdsolve.solvers.impact.answers import ImpactAnswers
from rbdsolve.solvers.impact.equations import ImpactEquations
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.conditions.signs import sign_of



class _Show:
    """Display forms: q̇ as ẋ, the unknown velocities after as ẋ_f."""

    def __init__(self, work: ImpactEquations):
        model = work.model
        self.model = model
        self.params = set(model.symbols.parameters.values())
        self.final = {f: sp.Derivative(sp.Function(f"{n}_f", real=True)(t), t)
                      for n, f in zip(model.coordinate_names(), work.final)}
        self.rates = [*model.qd, *work.final, *work.sizes]

    def scalar(self, expr: sp.Expr) -> Math:
        """Collected in the rates, in exam order, with a common scale pulled out; a value
        free of them as one tidy fraction."""
        model = self.model
        if not expr.has(*self.rates):
            return model.to_time(tidy_fraction(expr))
        parts = collect_in(sp.expand(expr), self.rates)
        terms = [(model.to_time(tidy(c)), tuple(self.time(f) for f in factors))
                 for c, factors in ordered_sum(parts, self.rates, list(model.q))]
        return scaled_sum(terms, self.params)

    def time(self, expr):
        return self.model.to_time(expr.xreplace(self.final))

    def vector(self, v: sp.Matrix) -> Math:
        """(ẋ − 1/2 l φ̇) eₓ + …"""
        return along_axes(v, self.scalar)

    def angular(self, omega: sp.Matrix) -> Math:
        """A planar ω (about z) as a scalar, else a vector."""
        if sp.expand(omega[0]) == 0 and sp.expand(omega[1]) == 0:
            return self.scalar(omega[2])
        return self.vector(omega)


def exact_steps(work: ImpactEquations, answers: ImpactAnswers) -> tuple[Step, ...]:
    show = _Show(work)
    out = equation_steps(work)
    out.append(st.result("Solving these linear equations:",
                         *[Relation(show.time(u), show.scalar(work.solution[u])) for u in work.solution]))
    out += _after(work, show, answers)
    return tuple(out)


def equation_steps(work: ImpactEquations) -> list[Step]:
    """From the velocities at the instant to the impulse equations, before solving."""
    show = _Show(work)
    out = [*_given(work, show), _velocities(work, show),
           st.definition("Kinetic energy at the instant:", Relation(sp.Symbol("T"), show.scalar(work.now.T))),
           _partial_velocities(work, show), _impulses(work, show), _lagrange(work, show)]
    restitution = _restitution(work, show)
    if restitution.math:
        out.append(restitution)
    if work.sticking_equations():
        out += _sticking(work, show)
    return out


def _sticking(work: ImpactEquations, show: _Show) -> list[Step]:
    """v_P|f = u|f = u|i − P/μ for each particle that embeds; v_P|f = 0 (or v_Q|f) for a
    body's point that sticks; v_C|f·t = 0 along the plane for each body that rolls on one."""
    after = lambda point: show.vector(work.now.velocity(point).xreplace(work.after))  # noqa: E731
    rows = [Relation(after(b.point), show.vector(work.other_velocity(b, final=True)))
            for b in work.hits if b.components and b.collision is not None and not b.sticking_point]
    points = [Relation(after(b.point), after(b.partner) if b.partner else sp.Integer(0))
              for b in work.hits if b.sticking_point]
    rolling = [Relation(after(b.point), sp.Integer(0)) for b in work.hits if b.components and b.collision is None]
    mu = labels_for(work.model, "particle_mass").text("particle_mass")
    out = [st.equation(f"A particle that sticks moves with the point just after: v_P|f = u|f = u|i − P/{mu} "
                       f"(P: its impulse on the system, every component unknown; {mu}: the particle's mass):",
                       *rows)] if rows else []
    if points:
        out.append(st.equation("A point that sticks becomes a pivot: just after, it moves with what it sticks to "
                               "(at rest on a fixed point), v_P|f = 0 or v_Q|f, Q the other body's point there "
                               "(P: the impulse on the body there, unknown in every direction the point can move; "
                               "the other body feels −P):", *points))
    if rolling:
        out.append(st.equation("Rolling without slipping on the plane goes on: the body's point at the contact "
                               "is at rest just after, v_C|f = 0 (the plane's impulse along it, F₁ t₁ + F₂ t₂, "
                               "unknown; its push along n does no work on the coordinates):", *rolling))
    return out


def unknown_name(work: ImpactEquations, unknown: sp.Symbol) -> sp.Expr:
    return _Show(work).time(unknown)


def _given(work: ImpactEquations, show: _Show) -> list[Step]:
    model = work.model
    out = []
    if work.now.at:
        q = [model.to_time(q) for q in model.q if q in work.now.at]
        out.append(st.given("The configuration at the instant of the impact:",
                            configuration(tuple(q), [work.now.at[x] for x in model.q if x in work.now.at])))
    moving = [(qd, v) for qd, v in work.before.items() if v != 0]
    if moving:
        out.append(st.given("Generalized velocities just before the impact:",
                            *[Relation(model.to_time(qd), v) for qd, v in moving]))
    return out


def _velocities(work: ImpactEquations, show: _Show) -> Step:
    model, at = work.model, work.now.at
    rows, shown = [], set()
    for body in model.bodies:
        shown.add(centre_name(body, model))
        rows.append(Relation(sp.Symbol(f"v_{centre_name(body, model)}"),
                             show.vector(body.velocity(model.state).xreplace(at))))
        omega = body.angular_velocity(model.state).xreplace(at)
        if omega != sp.zeros(3, 1) or body.given_angular_velocity is not None:
            rows.append(Relation(sp.Symbol(f"omega_{body.name}"), show.angular(omega)))
    for point in dict.fromkeys(p for b in work.hits for p in (b.point, b.partner) if p and p not in shown):
        rows.append(Relation(sp.Symbol(f"v_{point}"), show.vector(work.now.velocity(point))))
    return st.definition("Velocities at the instant (of each body's centre of mass, and of the struck "
                         "points), linear in the generalized velocities:", *rows)


def centre_name(body, model) -> str:
    """The name of the point a body's centre of mass is at (G1 for a rod placed at G1),
    so that its velocity reads v_G1 in every step; the body's name where no point is."""
    named = body.source.at or body.source.velocity
    preferred = sorted(named.names()) if named is not None else []
    given = [(model.points, body.position), (model.velocities, body.given_velocity)]
    for points, r in given:
        if r is None:
            continue
        same = [n for n, p in points.items() if p == r]
        if same:
            return next((n for n in preferred if n in same), same[0])
    return body.name


def _partial_velocities(work: ImpactEquations, show: _Show) -> Step:
    model = work.model
    rows = [Relation(sp.Derivative(sp.Symbol(f"v_{p}"), model.to_time(qd)),
                     show.vector(sp.diff(work.now.velocity(p), qd)))
            for p in dict.fromkeys(p for b in work.hits for p in (b.point, b.partner) if p) for qd in model.qd]
    return st.definition("Partial velocities ∂v/∂q̇ of the struck points:", *rows)


def _impulses(work: ImpactEquations, show: _Show) -> Step:
    rows = [Relation(sp.Symbol(f"P_{b.point}"), show.vector(b.impulse)) for b in work.hits]
    rows += [Relation(sp.Symbol(f"P_{b.partner}"), show.vector(-b.impulse)) for b in work.hits if b.partner]
    rows += [Relation(sp.Symbol(f"I_{n}"), show.scalar(I)) for n, I in zip(work.model.coordinate_names(), work.I)]
    unknown = "; λ n is a collision's unknown impulse, n its normal as given" if any(b.size for b in work.hits) else ""
    a = _index(work)
    return st.equation(f"Impulses on the system and the generalized impulses I{a} = Σ P · ∂v/∂q̇{a}{unknown}:",
                       *rows)


def _index(work: ImpactEquations) -> str:
    """_a, or _j where the scene has a name a (a parameter, a point)."""
    return "_" + labels_for(work.model, "coordinate_index").name("coordinate_index")


def _lagrange(work: ImpactEquations, show: _Show) -> Step:
    rows = [Relation(show.scalar(p.xreplace(work.after) - p.xreplace(work.before)), show.scalar(I))
            for p, I in zip(work.momenta, work.I)]
    a = _index(work)
    return st.equation(f"Lagrange's equations for impact, ∂T/∂q̇{a}|f − ∂T/∂q̇{a}|i = I{a} (f: just after, "
                       "i: just before):", *rows)


def _restitution(work: ImpactEquations, show: _Show) -> Step:
    rows = []
    for blow in work.hits:
        if blow.size is None:
            continue
        e = work.model.symbols.scalar(blow.collision.restitution)
        rows.append(Relation(show.scalar(work.normal_speed(blow, final=True)),
                             show.scalar(-e * work.normal_speed(blow, final=False))))
    return st.equation("Newton's law of restitution at each collision, n·(v − u)|f = −e n·(v − u)|i "
                       "(u: the velocity of what is hit, n: the normal):", *rows)


def _after(work: ImpactEquations, show: _Show, answers: ImpactAnswers) -> list[Step]:
    out = []
    rows = [Relation(sp.Symbol(f"v_{p}"), show.vector(sp.Matrix(v))) for p, v in answers.points.items()]
    rows += [Relation(sp.Symbol(f"u_{p}"), show.vector(sp.Matrix(v))) for p, v in answers.particles.items()]
    if rows:
        particles = " (u: the particle that struck there)" if answers.particles else ""
        out.append(st.result(f"Velocities just after the impact{particles}:", *rows))
    out.append(_energy_step(work, show, answers))
    if answers.sticking_impulses:
        kinds = {_kind(b) for b in work.hits if b.components}
        whose = " and ".join(text for kind, text in (("particle", "of each sticking particle on the system"),
                                                     ("point", "on the body at each point that sticks"),
                                                     ("rolling", "of the plane, along it, at each rolling contact"))
                             if kind in kinds)
        out.append(st.result(f"The impulse {whose}:",
                             *[Relation(sp.Symbol(f"P_{p}"), show.vector(sp.Matrix(v)))
                               for p, v in answers.sticking_impulses.items()]))
    if answers.restitution:
        out.append(st.result("The coefficient of restitution this impact amounts to, "
                             "e = −n·(v − u)|f / n·(v − u)|i:",
                             *[Relation(sp.Symbol(f"e_{p}"), e) for p, e in answers.restitution.items()]))
    out.append(st.result("Impulse from the supports, the change of momentum Σ m Δv_G less the impulses "
                         "applied:", Relation(sp.Symbol("P_supports"), show.vector(sp.Matrix(answers.support_impulse)))))
    if answers.centre_of_percussion is not None:
        p = sp.Symbol(work.opts.centre_of_percussion)
        out.append(st.result("The supports feel no impulse (the centre of percussion) when",
                             Relation(p, answers.centre_of_percussion)))
    return out


def _kind(blow) -> str:
    """What an impulse with unknown components is: a sticking particle's, a sticking
    point's, or a plane's at a rolling contact."""
    return "point" if blow.sticking_point else "rolling" if blow.collision is None else "particle"


def _energy_step(work: ImpactEquations, show: _Show, answers: ImpactAnswers) -> Step:
    """Tᵢ, T_f and the energy lost, Tᵢ − T_f; "gained", T_f − Tᵢ, where the impulses add
    energy (the sign decided by the parameters or their values); and the fraction lost,
    (Tᵢ − T_f)/Tᵢ, where it is a ratio of parameters alone (1 − e², M/(M + 3m)), the
    form an exam asks for."""
    lost = answers.energy_lost
    gained = sign_of(lost, work.model.decided_by) == -1
    rows = [Relation(sp.Symbol("T_i"), show.scalar(answers.energy_before)),
            Relation(sp.Symbol("T_f"), show.scalar(answers.energy_after))]
    if gained:
        rows.append(Relation(Label("T_f − Tᵢ", "T_f - T_i"), show.scalar(tidy_fraction(-lost))))
    else:
        rows.append(Relation(Label("Tᵢ − T_f", "T_i - T_f"), show.scalar(lost)))
    fraction = tidy_fraction(lost / answers.energy_before) if answers.energy_before != 0 else None
    if fraction is not None and lost != 0 and fraction.free_symbols < lost.free_symbols:  # the speeds cancel
        label = Label("(T_f − Tᵢ)/Tᵢ", "(T_f - T_i)/T_i") if gained else Label("(Tᵢ − T_f)/Tᵢ", "(T_i - T_f)/T_i")
        rows.append(Relation(label, show.scalar(tidy_fraction(-fraction) if gained else fraction)))
    word = "gained" if gained else "lost"
    return st.result("Kinetic energy of the system and the striking particles, just before (i) and "
                     f"after (f), and the energy {word}:", *rows)


def numeric_steps(work: ImpactEquations, condition: float) -> tuple[Step, ...]:
    """The impulse equations, then their solution in floats at the parameter values."""
    values = ", ".join(f"{to_unicode(k)} = {float_text(float(v))}" for k, v in work.model.values.items())
    found = [sp.Float(float(v), 15) for v in work.solution.values()]
    noise = within_rounding(found)  # a component that cancelled to 1e-17 beside the others is 0
    solved = st.result(f"With {values}, solved in floating point (numpy.linalg.solve):",
                       *[Relation(unknown_name(work, u), sp.Integer(0) if i in noise else v)
                         for i, (u, v) in enumerate(zip(work.solution, found))])
    return (*equation_steps(work), solved, st.accuracy(f"The condition number of the impulse equations: "
                                                       f"{condition:.3g}."))
