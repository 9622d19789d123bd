"""The balances of a steady motion, shared by both routes: the body's kinematics in a
turning triad (ω, v_G, and dL/dt = Ω_T × L for constant components), the rolling
velocities v_C = v_G + ω × (r_C − r_G), the moment about the point, and the balance
components, each = 0, with the rates found so far put in."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.errors import InputError, UnsolvedError
from rbdsolve.form.tidy import tidy, tidy_fraction
from rbdsolve.model.build import Model, RigidBody
from rbdsolve.model.rotation import sequence_rotation, vee
from rbdsolve.model.state import t
from rbdsolve.problem.options import SteadyMotionOptions


@dataclass(frozen=True)
class Balances:
    """A steady motion's balances in the triad, with the rates found so far put in: ω,
    v_G, L_P, dL_P/dt = Ω_T × L_P, v_P, M_P, a_G (with reactions, else None) and the
    balances' components, each = 0 (Newton's law for G first, with reactions)."""

    omega: sp.ImmutableMatrix
    v_G: sp.ImmutableMatrix
    L: sp.ImmutableMatrix
    dL: sp.ImmutableMatrix
    v_P: sp.ImmutableMatrix
    M: sp.ImmutableMatrix
    a_G: sp.ImmutableMatrix | None
    components: tuple[sp.Expr, ...]


def setup(opts: SteadyMotionOptions, model: Model) -> tuple[Kinematics, tuple[str, str, str]]:
    """The kinematics of the asked body in the asked triad, and the triad's vector names."""
    body = next(b for b in model.bodies if b.name == opts.body)
    triad = next(tr for tr in model.problem.triads if tr.name == opts.triad)
    return Kinematics(model, triad.name, body), triad.vectors


def rolling_velocities(opts: SteadyMotionOptions, model: Model, k: Kinematics, omega, v_G) -> list[sp.Matrix]:
    """v_C = v_G + ω × (r_C − r_G) at each rolling contact C, in triad components: each = 0."""
    names = model.symbols.with_points(model.points)
    r_G = k.components(k.body.position)
    return [(v_G + omega.cross(k.components(names.vector(C)) - r_G)).applyfunc(tidy) for C in opts.contacts]


def balances(opts: SteadyMotionOptions, model: Model, k: Kinematics, rates: dict, omega, v_G) -> Balances:
    """The angular momentum balance about P (and, with reactions, Newton's law for G),
    with the rates found put in (none: the rates stay unknowns, as on the numeric
    route). Refuses what is not a steady motion, and moments or reactions that would
    leave out an unknown contact force."""
    body = k.body

    def fix(v: sp.Matrix) -> sp.Matrix:  # the unknown rates found, each component tidied
        return sp.Matrix([tidy(x.xreplace(rates)) for x in v])

    names = model.symbols.with_points(model.points)
    omega, v_G = fix(omega), fix(v_G)
    P = names.vector(opts.about)
    if not opts.reactions:
        _require_moments_about_contact(opts, names, P)
    _require_reactions_at_contacts(opts, model, k, names)
    L = fix(k.inertia().applyfunc(sin_cos) * omega + fix(k.components(body.position) - k.components(P)).cross(body.mass * v_G))
    if any(tidy(x) != 0 for x in k.rate_in_triad(L)) or any(x.has(t) for x in L):
        raise UnsolvedError("not a steady motion: the angular momentum's components in the triad change")
    dL, v_P = fix(k.Omega.cross(L)), fix(k.velocity(P))
    forces = _forces(model, k, body, opts, names)
    M = fix(sum(((r - k.components(P)).cross(F) for r, F in forces), _couples(model, k, body)))
    found, a_G = [dL + v_P.cross(body.mass * v_G) - M], None
    if opts.reactions:  # the reactions' unknowns need Newton's law for G as well
        a_G = fix(k.rate_in_triad(v_G) + k.Omega.cross(v_G))
        found.insert(0, body.mass * a_G - sum((F for _, F in forces), sp.zeros(3, 1)))
    if any(tidy(x).has(t) for balance in found for x in balance):
        raise UnsolvedError("not a steady motion: the balance's components in the triad change with time "
                            "(is gravity along the triad's axis of turning?)")
    frozen = [sp.ImmutableMatrix(x) if x is not None else None for x in (omega, v_G, L, dL, v_P, M, a_G)]
    return Balances(*frozen, tuple(x for balance in found for x in balance))


def _require_moments_about_contact(opts: SteadyMotionOptions, names, P: sp.Matrix) -> None:
    """Without stated reactions the contact force is unknown; only moments about the
    rolling contact are free of it."""
    if not opts.contacts:
        return
    if len(opts.contacts) > 1:
        raise UnsolvedError("the body rolls at more than one point: state the contact forces as 'reactions' "
                            "(each {at: POINT, force: VECTOR} with unknowns) so both balances can use them")
    contact = opts.contacts[0]
    offset = P - names.vector(contact)
    if tidy_fraction(offset.dot(offset)) != 0:
        raise UnsolvedError(f"the body rolls at {contact.text}: take moments about that point (about: "
                            f"{contact.text}), where the unknown contact force has no moment, or state the "
                            "contact forces as 'reactions'")


def _require_reactions_at_contacts(opts: SteadyMotionOptions, model: Model, k: Kinematics, names) -> None:
    """With reactions, Newton's law for G, m a_G = m g + Σ R, joins the balance, so the
    reactions must be all the contact forces: a missing one is a wrong answer, also at
    the point P the moments are taken about (its force has no moment about P, but it
    still counts in Σ R). A rolling contact C is stated by a reaction applied at C, or
    by one at an unknown place on the line through C and another rolling contact: the
    resultant of a line contact's distributed push (the cone's N at Q = x_N e1, on OB)."""
    if not opts.reactions:
        return
    unknown = unknown_symbols(model)
    contacts = [k.components(names.vector(C)) for C in opts.contacts]
    at = [k.components(names.vector(r.at)) for r in opts.reactions]
    for C, r_C in zip(opts.contacts, contacts):
        lines = [d for d in (r - r_C for r in contacts) if not _is_zero(d)]
        if any(_is_zero(a - r_C) or (a.free_symbols & unknown and any(_is_zero((a - r_C).cross(d)) for d in lines))
               for a in at):
            continue
        raise InputError(f"no reaction at the rolling contact '{C.text}': with 'reactions' given they must be all "
                         "the contact forces, as Newton's law for G counts each one (even at the point the moments "
                         f"are taken about); add one such as {{at: {C.text}, force: ...}} with unknowns (or, for a "
                         f"line contact, one at an unknown distance along the line through {C.text} and another "
                         "rolling point)", opts.reactions_loc)


def _is_zero(v: sp.Matrix) -> bool:
    return all(tidy_fraction(sin_cos(x)) == 0 for x in v)


def _forces(model: Model, k: Kinematics, body: RigidBody, opts: SteadyMotionOptions, names):
    """(point of application, force) in triad components: gravity at G, the applied
    forces on the body (``forces:``), then the reactions."""
    g = k.components(model.gravity) if model.gravity is not None else sp.zeros(3, 1)
    gravity = (k.components(body.position), body.mass * g)
    applied = [(k.components(x.point), k.components(x.force)) for x in model.loads
               if x.body == body.name and x.kind == "force"]
    return [gravity, *applied] + [(k.components(names.vector(r.at)), k.components(names.vector(r.force)))
                                  for r in opts.reactions]


def _couples(model: Model, k: Kinematics, body: RigidBody) -> sp.Matrix:
    """The applied couples on the body (``couples:``; −M where it is the 'by' of a motor),
    in triad components: a couple has the same moment about every point."""
    total = sp.zeros(3, 1)
    for x in model.loads:
        if x.kind == "couple" and body.name in (x.body, x.by):
            total += (1 if x.body == body.name else -1) * k.components(x.moment)
    return total


class Kinematics:
    """Vectors in a turning triad's components, by the transport theorem, so that a
    steady motion's components come out free of t:

        Ω_T = vee(Tᵀ Ṫ),  v = d r_T/dt + Ω_T × r_T,  ω = Ω_T + vee(Ṙ_rel R_relᵀ),
        J_G = R_rel J R_relᵀ,  with R_rel = Tᵀ R the body's turns relative to T."""

    def __init__(self, model: Model, triad: str, body: RigidBody):
        T = model.triads[triad]
        self.model, self.T, self.body = model, T, body
        self.Omega = vee((T.T * model.state.d_dt(T)).applyfunc(tidy))
        orientation = body.source.orientation
        if orientation and orientation[0] == triad:  # the body's own turns after the triad's
            names = model.symbols.with_points(model.points)
            self.R_rel = sequence_rotation([(names.vector(x.axis), names.scalar(x.angle)) for x in orientation[1:]])
        else:
            self.R_rel = (T.T * body.rotation).applyfunc(tidy)

    def components(self, v: sp.Matrix) -> sp.Matrix:
        return (self.T.T * v).applyfunc(tidy)

    def velocity(self, r: sp.Matrix) -> sp.Matrix:
        r_T = self.components(r)
        return (self.model.state.d_dt(r_T) + self.Omega.cross(r_T)).applyfunc(tidy)

    def rate_in_triad(self, v: sp.Matrix) -> sp.Matrix:
        return self.model.state.d_dt(v).applyfunc(tidy)

    def omega(self) -> sp.Matrix:
        relative = vee((self.model.state.d_dt(self.R_rel) * self.R_rel.T).applyfunc(tidy))
        return (self.Omega + relative).applyfunc(tidy)

    def inertia(self) -> sp.Matrix:
        return (self.R_rel * self.body.inertia * self.R_rel.T).applyfunc(tidy)


def relation(x: sp.Expr, target: sp.Expr | None) -> sp.Expr:
    """A balance component as a relation = 0: its numerator, without the positive
    parameter factors (m r/2 …) that do not change it, and, with a quantity to solve
    for, as a X + b with a factored and not negative: ω₀² cos θ (4R + r sin θ) − 2g sin θ."""
    numerator = sp.fraction(sp.together(tidy_fraction(sin_cos(x))))[0]
    kept = [f for f in sp.Mul.make_args(sp.factor_terms(sp.expand(numerator)))
            if not (f.is_number or f.is_positive)]
    relation = tidy(sp.Mul(*kept))
    if target is None:
        return relation
    X = sp.Dummy("X")
    linear = sp.expand(relation).subs(target, X)
    a, b = sp.diff(linear, X), linear.subs(X, 0)
    if a == 0 or sp.diff(a, X) != 0 or any(linear.has(s) for s in target.free_symbols):
        return relation
    a, b = sp.factor(a), tidy(b)
    if a.could_extract_minus_sign():
        a, b = -a, -b
    return sp.Add(a * target, b, evaluate=False) if b != 0 else a * target


def sin_cos(x: sp.Expr) -> sp.Expr:
    """tan as sin/cos and sin 2α as 2 sin α cos α, so that the sin² + cos² = 1
    reduction can see them."""
    return sp.expand_trig(x.replace(sp.tan, lambda y: sp.sin(y) / sp.cos(y)))


def unknown_symbols(model: Model) -> set[sp.Symbol]:
    return {model.symbols.parameters[u] for u in model.problem.unknowns}


def angle_unknown(u: sp.Symbol, relations) -> bool:
    """Do the relations hold u only through sin u and cos u (and tan u), as an angle?"""
    held = False
    for r in relations:
        r = sin_cos(r)
        if not r.has(u):
            continue
        held = True
        if r.xreplace({sp.sin(u): sp.Dummy(), sp.cos(u): sp.Dummy()}).has(u):
            return False
    return held


def angle_of(sin_value: sp.Expr, cos_value: sp.Expr) -> sp.Expr:
    """The angle in (−π, π] with this sine and cosine."""
    if sin_value.is_zero:
        return sp.Integer(0) if cos_value.is_positive else sp.pi
    y, x = sp.factor_terms(sin_value), sp.factor_terms(cos_value)
    common = [f for f in sp.Mul.make_args(y) if f in sp.Mul.make_args(x) and f.is_positive]
    # atan2(k y, k x) = atan2(y, x) for k > 0: √(…) common to both is dropped
    y, x = y / sp.Mul(*common), x / sp.Mul(*common)
    if not common:
        positive = [f for f in sp.Mul.make_args(y) if f.is_Pow and f.exp == sp.Rational(1, 2)
                    and f in sp.Mul.make_args(x)]
        y, x = y / sp.Mul(*positive), x / sp.Mul(*positive)  # a real root's √ is positive
    angle = sp.atan2(y, x)
    return sp.simplify(angle) if sp.count_ops(angle) < 40 else angle


def twin(a: dict, b: dict, relations, sample: dict, tol: float = 1e-20) -> bool:
    """Are two solutions one motion: each angle unknown the same or turned by π (at
    least one turned, unless all are the same), every other unknown the same or of the
    opposite sign (compared at ``sample``, parameter values, to 30 digits), and the
    change (u → u + π on the turned angles, v → −v on the others) a symmetry of the
    relations, mapping each to ± itself — the motion turned over (β + π with −φ̇)? ``tol``: relative, for values known to it only."""
    if set(a) != set(b):
        return False
    change = {}
    for u in a:
        kind = _compare(a[u], b[u], angle_unknown(u, relations), sample, tol)
        if kind is None:
            return False
        if kind != "same":
            change[u] = u + sp.pi if kind == "half turn" else -u
    if change and not any(v == u + sp.pi for u, v in change.items()):
        return False  # signs turned alone (±ω₀): the motion reversed, not turned over
    for r in relations:
        turned, plain = tidy_fraction(sin_cos(r.xreplace(change))), tidy_fraction(sin_cos(r))
        if tidy_fraction(turned - plain) != 0 and tidy_fraction(turned + plain) != 0:
            return False
    return True


def _compare(x: sp.Expr, y: sp.Expr, angle: bool, sample: dict, tol: float) -> str | None:
    """"same", "half turn" (an angle: sin and cos both turned), "opposite" (−x), or None."""
    def number(v):
        return complex(sp.N(sp.sympify(v).xreplace(sample), 30))

    if angle:
        (sx, cx), (sy, cy) = (number(sp.sin(x)), number(sp.cos(x))), (number(sp.sin(y)), number(sp.cos(y)))
        if abs(sx - sy) + abs(cx - cy) <= tol:
            return "same"
        return "half turn" if abs(sx + sy) + abs(cx + cy) <= tol else None
    vx, vy = number(x), number(y)
    scale = max(1.0, abs(vx))
    if abs(vx - vy) <= tol * scale:
        return "same"
    return "opposite" if abs(vx + vy) <= tol * scale else None
