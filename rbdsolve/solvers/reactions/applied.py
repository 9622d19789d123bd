"""The known forces on the bodies: springs and the applied loads (``forces:``,
``couples:``). Neither is a support: each enters the free body diagram of the body it
acts on with a known value.

A linear spring between ends a and b, stretch s = |a − b| − l₀, V = ½ k s², pulls the
body that carries end a with

    F_a = −∂V/∂r_a = −k s (a − b)/|a − b|   at a,      and that of end b with −F_a at b;

with no natural length (s = |a − b|) that is F_a = −k (a − b), written so: no length,
no |…| (a disk's centre tied to the axis of the cylinder it rolls in).

An end whose position is constant is fixed to the ground; a moving end is carried by
the body whose material point it is (its velocity is v_G + ω × (end − r_G) at every
state). A torsional spring on an angle α = Σ c_B α_B + const (α_B body B's turning
angle about e_z) turns body B by M_B = −k s c_B e_z; what is left acts on the ground.
One on the direction of a body's centre G seen from a fixed point O (a particle on a
light rod pivoted at O) acts on G through the rod: F = −k s κ (e_z × d)/|d|², d = r_G − O.

An applied force F acts on its body at its point P; a couple M turns its body, and a
motor's couple at a joint turns the other body by −M (model/energies/loads.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.tidy import tidied_roots, tidy
from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import to_unicode
from rbdsolve.model.build import Model, SpringModel
from rbdsolve.model.state import t
from rbdsolve.solvers.reactions.supports import body, generic_point, material_velocity, planar

_Z = sp.Matrix([0, 0, 1])


@dataclass(frozen=True)
class Applied:
    """A spring's or a load's force (and moment) on one body, at a point of it."""

    name: str
    body: str
    point: sp.Matrix  # where the force acts (a torsional spring, a couple: the body's G, no force)
    force: sp.Matrix  # scene axes
    moment: sp.Matrix  # scene axes (a planar one along e_z)
    kind: str = "spring"  # spring, force or couple


def applied(model: Model, held: list[str]) -> list[Applied]:
    """Every spring's pull and every applied load on the held bodies (those in a free
    body diagram)."""
    out: list[Applied] = []
    for s in model.springs:
        found = _linear(model, s, held) if s.source.ends is not None else _torsional(model, s)
        out += [a for a in found if a.body in held]
    for x in model.loads:
        if x.body in held:
            out.append(Applied(x.name, x.body, x.point, x.force, x.moment, x.kind))
        if x.by is not None and x.by in held:  # a motor at a joint: the other body feels −M
            out.append(Applied(x.name, x.by, body(model, x.by).position, sp.zeros(3, 1), -x.moment, x.kind))
    return out


def _linear(model: Model, s: SpringModel, held: list[str]) -> list[Applied]:
    a, b = (model.symbols.vector(e) for e in s.source.ends)
    d = a - b
    pull = -s.stiffness * d if not s.source.natural_length else -s.stiffness * s.stretch * _unit(s, d)
    pull = pull.applyfunc(tidied_roots)  # |d| as V writes it (tidied), so that the two cancel
    out = []
    for end, force in ((a, pull), (b, -pull)):
        carrier = _carrier(model, s, end, held)
        if carrier is not None:
            out.append(Applied(s.name, carrier, end, force, sp.zeros(3, 1)))
    return out


def _unit(s: SpringModel, d: sp.Matrix) -> sp.Matrix:
    """d/|d|, |d| written as the stretch writes it."""
    unit = d / s.signed(sp.sqrt(d.dot(d)))
    return unit.applyfunc(sp.cancel) if s.lengths else unit  # along one axis: ±(d + x)/(d + x), cancelled to ±1


def _carrier(model: Model, s: SpringModel, end: sp.Matrix, held: list[str]) -> str | None:
    """The body whose material point the end is; None: the ground (a constant end)."""
    if not (end.free_symbols & {*model.q, t}):
        return None
    v = model.state.d_dt(end)
    found = [b.name for b in model.bodies if b.position is not None
             and _zero(v - material_velocity(model, b, end), model)]
    if not found:
        raise UnsolvedError(f"spring '{s.name}': its end {to_unicode(model.readable(end.T))} moves with no body, "
                            "so which body it pulls "
                            "is not known (fix each end to a body's point, or to the ground)")
    if len(found) > 1 and set(found) & set(held):
        raise UnsolvedError(f"spring '{s.name}': its end is a point of bodies {', '.join(found)} (a joint), so "
                            "which one it pulls is not said; attach it beside the joint")
    return found[0]


def _torsional(model: Model, s: SpringModel) -> list[Applied]:
    """M_B = −k s c_B e_z, with α = Σ c_B α_B + const found at generic states."""
    turning = [b for b in model.bodies if b.angle is not None and b.angle.free_symbols & set(model.q)]
    angle = s.stretch
    c = sp.symbols(f"c0:{len(turning)}")
    rows = []
    for seed in (2, 5, 9):
        point = generic_point(model, seed)
        rows += [(sp.diff(angle, q) - sum(ci * sp.diff(b.angle, q) for ci, b in zip(c, turning))).xreplace(point)
                 for q in model.q]
    solved = sp.solve(rows, c, dict=True) if turning else []
    if not planar(model) or len(solved) != 1 or any(ci not in solved[0] for ci in c):
        rod = _light_rod(model, s) if planar(model) else None
        if rod is None:
            raise UnsolvedError(f"spring '{s.name}': its angle is neither a sum of the bodies' turning angles nor the "
                                "direction of a body's centre seen from a fixed point (a light rod's), so which "
                                "bodies it turns is not known")
        return [rod]
    return [Applied(s.name, b.name, b.position, sp.zeros(3, 1), -s.stiffness * s.stretch * solved[0][ci] * _Z)
            for ci, b in zip(c, turning) if solved[0][ci] != 0]


def _light_rod(model: Model, s: SpringModel) -> Applied | None:
    """A torsional spring on the direction φ of d = r_G − O, O a fixed point and G a
    body's centre (a particle on a light rod pivoted at O, the spring at the pivot):
    α = κ φ + const, κ = ±1. The light rod carries the couple −k s κ e_z to G as the force
    F = −k s κ (e_z × d)/|d|², whose moment about O is d × F = −k s κ e_z and whose
    virtual work F·δr_G = −k s κ δφ = −k s δα is the spring's. None where no such pair."""
    fixed = [p for p in model.points.values() if not (p.free_symbols & {*model.q, t})]
    for b in model.bodies:
        if b.position is None or not (b.position.free_symbols & set(model.q)):
            continue
        for origin in fixed:
            d = b.position - origin
            turn = sp.atan2(d[1], d[0])
            for kappa in (1, -1):
                if all(abs(sp.diff(s.stretch - kappa * turn, q).xreplace(generic_point(model, seed)).evalf(30)) < 1e-20
                       for seed in (2, 5) for q in model.q):
                    force = -s.stiffness * s.stretch * kappa * _Z.cross(d) / (d[0] ** 2 + d[1] ** 2)
                    return Applied(s.name, b.name, b.position, force.applyfunc(tidy), sp.zeros(3, 1))
    return None


def _zero(v: sp.Matrix, model: Model) -> bool:
    """Zero at two generic states."""
    for seed in (3, 17):
        value = v.xreplace(generic_point(model, seed)).evalf(30)
        if any(abs(x) > 1e-20 for x in value):
            return False
    return True
