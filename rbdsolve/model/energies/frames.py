"""Moving frames: the Lagrangian as an observer in an accelerated or turning frame sees it.

A frame F has its origin O at r_O(t) and turns at the constant rate Ω about the fixed
unit axis n through O: its axes are R(t) = rotation about n by Ω t, and ω = Ω n (the
same in both axes, since R n = n). A position r in the scene is r' = Rᵀ (r − r_O) in F.
Writing u = Rᵀ v_O and a' = Rᵀ a_O for the origin's velocity and acceleration in F's
axes, the kinetic energy of a body splits as (e.g. Goldstein, ch. 4.10; the seed's
problem 5 for the translating case)

    T = ½ m |v_O|² + m u · (v' + ω × r') + ½ m |v' + ω × r'|² + T_spin,

and since m u · (v' + ω × r') = d/dt(m r' · u) − m a' · r', the Lagrangian in F,

    L' = ½ m |v'|² + m v' · (ω × r') + ½ m |ω × r'|² + T_spin
         − m a' · r' + m (Rᵀ g) · r' − V_springs,

differs from L by a total time derivative, L − L' = dF/dt with

    F = Σ m r' · u + ∫ Σ (½ m |v_O|² + m g · r_O) dt.

The pieces of L' are, in order: the relative kinetic energy, the gyroscopic (Coriolis)
term, the centrifugal potential −½ m |ω × r'|² (counted in V'), the body's own spin
energy (the same in every frame), the potential of the inertial force of translation
m a' · r', gravity in F's axes and the springs.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from rbdsolve.errors import InputError, UnsolvedError
from rbdsolve.model.build import Model, RigidBody, SpringModel, signed_springs
from rbdsolve.model.rotation import axis_rotation
from rbdsolve.model.energies.energy import EnergyTerm
from rbdsolve.model.state import t
from rbdsolve.form.tidy import tidy
from rbdsolve.problem.scene import Frame


@dataclass(frozen=True)
class FrameMotion:
    """A frame's motion in the scene: the position of its origin, its rotation (frame
    axes to scene axes) and its angular velocity."""

    frame: Frame
    origin: sp.Matrix  # r_O(t), scene axes
    rotation: sp.Matrix  # R(t): F's axes -> scene axes
    omega: sp.Matrix  # ω = Ω n, constant
    rate: sp.Expr = sp.Integer(0)  # Ω, as the file gives it (0: the frame does not turn)

    def relative(self, r: sp.Matrix) -> sp.Matrix:
        """r' = Rᵀ (r − r_O), each component tidied (cos²Ωt + sin²Ωt = 1)."""
        return (self.rotation.T * (r - self.origin)).applyfunc(tidy)

    def origin_velocity(self) -> sp.Matrix:
        return sp.diff(self.origin, t)

    def in_axes(self, v: sp.Matrix) -> sp.Matrix:
        """A scene vector's components in F's axes: Rᵀ v."""
        return (self.rotation.T * v).applyfunc(tidy)


@dataclass(frozen=True)
class FrameLagrangian:
    """The motion seen from a frame: T' and V' measured in it, L' = T' − V', and F
    with L − L' = dF/dt."""

    frame: str
    kinetic: tuple[EnergyTerm, ...]  # T'-like parts: relative, gyroscopic, spin
    potential: tuple[EnergyTerm, ...]  # V' parts: gravity, springs, inertial potentials
    L: sp.Expr  # L' = Σ kinetic − Σ potential
    F: sp.Expr  # L − L' = dF/dt


def frame_motion(model: Model, frame: Frame) -> FrameMotion:
    """The frame's origin, axes and angular velocity."""
    names = model.symbols.with_points(model.points)
    origin = names.vector(frame.origin) if frame.origin is not None else sp.zeros(3, 1)
    if frame.axis is None:
        return FrameMotion(frame, origin, sp.eye(3), sp.zeros(3, 1))
    axis = names.vector(frame.axis)
    length = tidy(axis.dot(axis))
    if length == 0:
        raise InputError(f"frame '{frame.name}' turns about the zero vector", frame.axis.loc)
    n = axis / sp.sqrt(length)
    rate = names.scalar(frame.rate)
    return FrameMotion(frame, origin, axis_rotation(n, rate * t), rate * n, rate)


def inertial_potentials(name: str, m: sp.Expr, r: sp.Expr, motion: FrameMotion) -> list[EnergyTerm]:
    """−½ m |ω × r'|² (centrifugal) and m a' · r' (the origin's acceleration), tidied."""
    centrifugal, translation = _inertial(m, r, motion.omega, motion.in_axes(sp.diff(motion.origin, t, 2)))
    return [EnergyTerm(f"centrifugal on {name}", tidy(centrifugal)),
            EnergyTerm(f"inertial force on {name}", tidy(translation))]


def _inertial(m: sp.Expr, r: sp.Matrix, omega: sp.Matrix, a: sp.Matrix) -> tuple[sp.Expr, sp.Expr]:
    """(−½ m |ω × r'|², m a' · r') as built, a' = Rᵀ a_O the origin's acceleration in F."""
    return -m * omega.cross(r).dot(omega.cross(r)) / 2, m * a.dot(r)


def frame_lagrangian(model: Model, motion: FrameMotion) -> FrameLagrangian:
    """L' and F, body by body (see the module docstring)."""
    state, omega = model.state, motion.omega
    v_O = motion.origin_velocity()
    u = motion.in_axes(v_O)
    gravity = model.gravity if model.gravity is not None else sp.zeros(3, 1)
    g = motion.in_axes(gravity)
    kinetic, potential = [], []
    F_bodies, time_only = sp.Integer(0), sp.Integer(0)
    for body in model.bodies:
        m, r = body.mass, motion.relative(body.position)
        v = state.d_dt(r)
        kinetic += [EnergyTerm(f"{body.name}, relative motion", tidy(m * v.dot(v) / 2)),
                    EnergyTerm(f"{body.name}, gyroscopic", tidy(m * v.dot(omega.cross(r)))),
                    EnergyTerm(f"{body.name}, spin", _spin(body, state))]
        potential += [*inertial_potentials(body.name, m, r, motion),
                      EnergyTerm(f"gravity on {body.name}", tidy(-m * g.dot(r)))]
        F_bodies += m * r.dot(u)
        time_only += m * v_O.dot(v_O) / 2 + m * gravity.dot(motion.origin)
    potential += [EnergyTerm(f"spring {s.name}", tidy(s.stiffness * s.stretch**2 / 2)) for s in model.springs]
    kinetic = tuple(x for x in kinetic if x.value != 0)
    potential = tuple(x for x in potential if x.value != 0)
    L = sum((x.value for x in kinetic), sp.Integer(0)) - sum((x.value for x in potential), sp.Integer(0))
    time_only = tidy(time_only)
    F = tidy(F_bodies) + _time_integral(time_only)
    return FrameLagrangian(motion.frame.name, kinetic, potential, tidy(L), F)


def _time_integral(f: sp.Expr) -> sp.Expr:
    """∫ f dt for the part of F that depends on time alone, evaluated where sympy finds a
    closed form no more than twice as long as f (∫ ½ a² m t² dt = 1/6 a² m t³), else
    left as the integral: any antiderivative will do, L − L' = dF/dt either way."""
    if f == 0:
        return sp.Integer(0)
    found = sp.integrate(sp.expand(f), t)
    if found.has(sp.Integral) or sp.count_ops(found) > 2 * sp.count_ops(f) + 4:
        return sp.Integral(f, t)
    return tidy(found)


def _spin(body: RigidBody, state) -> sp.Expr:
    """½ ω·J ω with the body's true angular velocity: the same seen from any frame."""
    omega = body.angular_velocity(state)
    if omega == sp.zeros(3, 1):
        return sp.Integer(0)
    return tidy((omega.T * body.inertia_in_scene() * omega)[0, 0] / 2)


def in_frame(model: Model, motion: FrameMotion) -> Model:
    """The model as seen in F, for relative equilibria and small oscillations:
    positions r', bodies turned relative to F, spring stretches from the relative
    positions, gravity in F's axes, the inertial potentials added to V, and L's terms
    linear in the relative rates kept as the model's gyroscopic terms.

    With ω' a body's angular velocity relative to F and J' its inertia in F's axes, its
    true rotational energy is ½ (ω' + ω_F)ᵀ J' (ω' + ω_F) = ½ ω'ᵀ J' ω' + ω_Fᵀ J' ω'
    + ½ ω_Fᵀ J' ω_F: the relative energy (the seen model's T), a gyroscopic term, and
    the centrifugal potential of the body's turning, −½ ω_Fᵀ J' ω_F, which holds the
    inertia tensor, not just the centre: a rod hinged to a turning shaft at θ from it has
    −½ Ω² (m l²/3) sin²θ in all, a third more than its centre alone would give (kept
    where it depends on q). Likewise ½ m |v' + ω_F × r'|² adds m v'·(ω_F × r') (Coriolis).
    The part of the gyroscopic terms without rates (a body spun relative to F about an
    axis ω_F does not hold: ω_Fᵀ J' ω'_t) is a potential too.

    A planar body turns with its angle α less Ω t in a frame turning about z (J_zz about
    z is constant: its turning changes no equation). In a frame turning about another
    axis a body that turns with a planar ``angle`` is refused: its orientation is given
    as turns, the frame's turn first."""
    n = motion.omega
    turning = [b.name for b in model.bodies if b.angle is not None and b.inertia != sp.zeros(3, 3)]
    if (n[0] != 0 or n[1] != 0) and turning:
        raise UnsolvedError(f"frame '{motion.frame.name}' turns about {motion.frame.axis.text}, and body "
                            f"'{turning[0]}' turns with a planar 'angle' (about z), which cannot follow it: give its "
                            f"orientation as turns, the frame's turn first, such as orientation: "
                            f"[[{motion.frame.axis.text}, {motion.frame.rate.text}*t], [z, theta]] "
                            "(docs/format.md, frames)")
    bodies = tuple(_relative_body(b, motion) for b in model.bodies)
    springs = tuple(_relative_spring(s, model, motion) for s in model.springs)
    gravity = motion.in_axes(model.gravity) if model.gravity is not None else None
    points = {name: motion.relative(r) for name, r in model.points.items()}
    origin = motion.in_axes(sp.diff(motion.origin, t, 2))
    settled = [_raw_terms(moved, model, motion, origin).settled(model.q, model.qd) for moved in bodies]
    extra = [x for terms in settled for x in terms.inertial]
    extra += [x for terms in settled for x in (terms.turning, terms.still)]
    return replace(model, points=points, bodies=bodies, springs=springs, gravity=gravity,
                   inertial=tuple(x for x in extra if x.value != 0),
                   gyroscopic=tuple(terms.gyroscopic for terms in settled if terms.gyroscopic.value != 0))


@dataclass(frozen=True)
class _Settled:
    """A body's terms in F, tidied: its inertial potentials (centrifugal, the origin's
    acceleration), the centrifugal potential of its turning, the gyroscopic term and the
    gyroscopic term's part without rates (as a potential)."""

    inertial: tuple[EnergyTerm, EnergyTerm]
    turning: EnergyTerm
    gyroscopic: EnergyTerm
    still: EnergyTerm


@dataclass(frozen=True)
class _RawTerms:
    """A body's terms in F as built, before tidying (``in_frame`` first builds them from
    the tidied positions r', then tidies them all): −½ m |ω × r'|², m a' · r',
    m v'·(ω_F × r'), and (ω_Fᵀ J' ω', ½ ω_Fᵀ J' ω_F), J' the inertia in F's axes."""

    name: str
    centrifugal: sp.Expr
    translation: sp.Expr
    coriolis: sp.Expr
    turning: sp.Expr
    turning_energy: sp.Expr

    def settled(self, q, qd) -> _Settled:
        """L's terms linear in the relative rates, m v'·(ω_F × r') + ω_Fᵀ J' ω', are the
        model's gyroscopic term, their part without rates a potential (negated);
        −½ ω_Fᵀ J' ω_F is kept where it depends on the coordinates (a constant changes
        nothing)."""
        inertial = (EnergyTerm(f"centrifugal on {self.name}", tidy(self.centrifugal)),
                    EnergyTerm(f"inertial force on {self.name}", tidy(self.translation)))
        linear = tidy(self.coriolis + tidy(self.turning))
        still = tidy(linear.xreplace({x: 0 for x in qd}))
        held = still if still.free_symbols & set(q) else sp.Integer(0)
        energy = tidy(self.turning_energy)
        turning = energy if energy.free_symbols & set(q) else sp.Integer(0)
        return _Settled(inertial, EnergyTerm(f"centrifugal on {self.name}, turning", tidy(-turning)),
                        EnergyTerm(f"{self.name}, gyroscopic", tidy(linear - still)),
                        EnergyTerm(f"gyroscopic potential on {self.name}", tidy(-held)))


def _raw_terms(body: RigidBody, model: Model, motion: FrameMotion, origin: sp.Matrix) -> _RawTerms:
    """A body's terms in F, built from its relative position r' (``_RawTerms``), where
    ``origin`` is a' = Rᵀ a_O."""
    m, r, omega = body.mass, body.position, motion.omega
    v = model.state.d_dt(r)
    turning, energy = _relative_rotational_energy(body, motion, model)
    return _RawTerms(body.name, *_inertial(m, r, omega, origin), m * v.dot(omega.cross(r)), turning, energy)


def _relative_body(body: RigidBody, motion: FrameMotion) -> RigidBody:
    position = motion.relative(body.position)
    if body.turns:
        return replace(body, position=position, rotation=motion.in_axes(body.rotation),
                       turns=_relative_turns(body.turns, motion))
    if body.angle is None:
        return replace(body, position=position)
    angle = tidy(body.angle - motion.omega[2] * t)
    return replace(body, position=position, angle=angle, rotation=sp.rot_axis3(-angle))


def _relative_turns(turns, motion: FrameMotion):
    """R_Fᵀ R as turns: the frame's turn back, by −Ω t about n, first, joined to the
    body's first turn where that is about n too ([[z, Ω t], [y, θ]] in a frame turning
    at Ω about z is [[z, 0], [y, θ]])."""
    if motion.omega == sp.zeros(3, 1):
        return turns
    rate = sp.sqrt(tidy(motion.omega.dot(motion.omega)))
    n = (motion.omega / rate).applyfunc(tidy)
    (axis, angle), rest = turns[0], turns[1:]
    if (axis - n).applyfunc(tidy) == sp.zeros(3, 1):
        return ((axis, tidy(angle - rate * t)), *rest)
    return ((n, -rate * t), *turns)


def _relative_rotational_energy(body: RigidBody, motion: FrameMotion, model: Model) -> tuple[sp.Expr, sp.Expr]:
    """(ω_Fᵀ J' ω', ½ ω_Fᵀ J' ω_F) of a body seen in F, J' its inertia in F's axes, as built."""
    if body.inertia == sp.zeros(3, 3) or motion.omega == sp.zeros(3, 1):
        return sp.Integer(0), sp.Integer(0)
    J, w = body.inertia_in_scene(), motion.omega
    return (w.T * J * body.angular_velocity(model.state))[0, 0], (w.T * J * w)[0, 0] / 2


def _relative_spring(spring: SpringModel, model: Model, motion: FrameMotion) -> SpringModel:
    """A linear spring's stretch from the ends' relative positions (the same length,
    written so that a spring still in the frame shows no t), its |u| written ±u by u's
    sign at the reference configuration as the scene's own stretch is
    (model/energies/spring_length.py): a bead on a turning rod held by a spring from the axis has
    the stretch x, not √((a + x)²) − a."""
    if spring.source.ends is None:
        return spring
    names = model.symbols.with_points(model.points)
    a, b = (motion.relative(names.vector(e)) for e in spring.source.ends)
    rest = names.scalar(spring.source.natural_length) if spring.source.natural_length else sp.Integer(0)
    relative = replace(spring, stretch=sp.sqrt(tidy((a - b).dot(a - b))) - rest, lengths=())
    return signed_springs((relative,), model.symbols, model.assumptions, model.problem.coordinates,
                          dict(model.values))[0]
