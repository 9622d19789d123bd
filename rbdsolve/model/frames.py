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
from rbdsolve.model.build import Model, RigidBody
from rbdsolve.model.energy import EnergyTerm
from rbdsolve.model.state import t
from rbdsolve.model.tidy import tidy
from rbdsolve.problem.schema import Frame


@dataclass(frozen=True)
class FrameMotion:
    frame: Frame
    origin: sp.Matrix  # r_O(t), scene axes
    rotation: sp.Matrix  # R(t): F's axes -> scene axes
    omega: sp.Matrix  # ω = Ω n, constant

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
    frame: str
    kinetic: tuple[EnergyTerm, ...]  # T'-like parts: relative, gyroscopic, spin
    potential: tuple[EnergyTerm, ...]  # V' parts: gravity, springs, inertial potentials
    L: sp.Expr  # L' = Σ kinetic − Σ potential
    F: sp.Expr  # L − L' = dF/dt


def frame_motion(model: Model, frame: Frame) -> FrameMotion:
    """The frame's origin, axes and angular velocity. A frame turning about an axis
    other than z is refused when a body turns with an ``angle``: bodies turn about z
    only, so such a body's orientation cannot follow the frame."""
    names = model.symbols.with_points(model.points)
    origin = names.vector(frame.origin) if frame.origin is not None else sp.zeros(3, 1)
    if any(origin.has(q) for q in model.q):
        raise InputError(f"frame '{frame.name}' must move in a given way: its origin depends on the "
                         "coordinates", frame.origin.loc)
    if frame.axis is None:
        return FrameMotion(frame, origin, sp.eye(3), sp.zeros(3, 1))
    axis = names.vector(frame.axis)
    n = axis / sp.sqrt(axis.dot(axis))
    turning = [b.name for b in model.bodies if b.angle is not None and b.inertia != sp.zeros(3, 3)]
    if (n[0] != 0 or n[1] != 0) and turning:
        raise UnsolvedError(f"frame '{frame.name}' turns about an axis other than z, and body '{turning[0]}' "
                            "turns with an 'angle' about z: its orientation cannot follow the frame "
                            "(3D rotations come with issue 5)")
    rate = names.scalar(frame.rate)
    return FrameMotion(frame, origin, _rotation(n, rate * t), rate * n)


def _rotation(n: sp.Matrix, angle: sp.Expr) -> sp.Matrix:
    """Rodrigues: R = cos α 1 + sin α [n]× + (1 − cos α) n nᵀ."""
    cross = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    return sp.cos(angle) * sp.eye(3) + sp.sin(angle) * cross + (1 - sp.cos(angle)) * n * n.T


def frame_lagrangian(model: Model, motion: FrameMotion) -> FrameLagrangian:
    """L' and F, body by body (see the module docstring)."""
    state, omega = model.state, motion.omega
    u = motion.in_axes(motion.origin_velocity())
    a = motion.in_axes(sp.diff(motion.origin, t, 2))
    g = motion.in_axes(model.gravity) if model.gravity is not None else sp.zeros(3, 1)
    kinetic, potential = [], []
    F_bodies, time_only = sp.Integer(0), sp.Integer(0)
    v_O = motion.origin_velocity()
    for body in model.bodies:
        m, r = body.mass, motion.relative(body.position)
        v = state.d_dt(r)
        spin = _spin(body, state)
        kinetic += [EnergyTerm(f"{body.name}, relative motion", tidy(m * v.dot(v) / 2)),
                    EnergyTerm(f"{body.name}, gyroscopic", tidy(m * v.dot(omega.cross(r)))),
                    EnergyTerm(f"{body.name}, spin", spin)]
        potential += [EnergyTerm(f"centrifugal on {body.name}", tidy(-m * omega.cross(r).dot(omega.cross(r)) / 2)),
                      EnergyTerm(f"inertial force on {body.name}", tidy(m * a.dot(r))),
                      EnergyTerm(f"gravity on {body.name}", tidy(-m * g.dot(r)))]
        F_bodies += m * r.dot(u)
        gravity = model.gravity if model.gravity is not None else sp.zeros(3, 1)
        time_only += m * v_O.dot(v_O) / 2 + m * gravity.dot(motion.origin)
    potential += [EnergyTerm(f"spring {s.name}", tidy(s.stiffness * s.stretch**2 / 2)) for s in model.springs]
    kinetic = tuple(x for x in kinetic if x.value != 0)
    potential = tuple(x for x in potential if x.value != 0)
    L = sum((x.value for x in kinetic), sp.Integer(0)) - sum((x.value for x in potential), sp.Integer(0))
    time_only = tidy(time_only)
    F = tidy(F_bodies) + (sp.Integral(time_only, t) if time_only != 0 else 0)
    return FrameLagrangian(motion.frame.name, kinetic, potential, tidy(L), F)


def _spin(body: RigidBody, state) -> sp.Expr:
    """½ ω·J ω with the body's true angular velocity: the same seen from any frame."""
    omega = body.angular_velocity(state)
    if omega == sp.zeros(3, 1):
        return sp.Integer(0)
    return tidy((omega.T * body.inertia_in_scene() * omega)[0, 0] / 2)


def in_frame(model: Model, motion: FrameMotion) -> Model:
    """The model as seen in F, for relative equilibria and small oscillations:
    positions r', gravity in F's axes, and the inertial potentials (centrifugal,
    translation) added to V. A body's spin energy is kept as the scene gives it: for a
    frame turning about z its q̇-free part is ½ J_zz Ω², a constant. Valid when F's
    Lagrangian has no gyroscopic part at the configurations asked about (the modes
    solver checks it)."""
    points = {name: motion.relative(r) for name, r in model.points.items()}
    bodies = tuple(replace(b, position=motion.relative(b.position)) for b in model.bodies)
    gravity = motion.in_axes(model.gravity) if model.gravity is not None else None
    a = motion.in_axes(sp.diff(motion.origin, t, 2))
    omega = motion.omega
    extra = []
    for body, moved in zip(model.bodies, bodies):
        r = moved.position
        extra.append(EnergyTerm(f"centrifugal on {body.name}", tidy(-body.mass * omega.cross(r).dot(omega.cross(r)) / 2)))
        extra.append(EnergyTerm(f"inertial force on {body.name}", tidy(body.mass * a.dot(r))))
    extra = tuple(x for x in extra if x.value != 0)
    return replace(model, points=points, bodies=bodies, gravity=gravity, inertial=extra)
