"""The ``forces:`` and ``couples:`` sections: loads applied to the bodies, besides gravity
and the springs.

    forces:
      pull: {on: cylinder, force: [F, 0]}                  # at the body's origin (its centre)
      push: {on: rod, at: B, force: P*[0, -1]}             # at a point (B may be a point of the rod)
      tow: {on: rod, at: B, force: F, towards: A}          # size F along the line from B to A
      reel: {on: spool, force: F*[cos(alpha), sin(alpha)], wound: {radius: r, side: below}}
    couples:
      motor: {on: wheel, moment: M0}                       # a couple on a body (about z)
      drive: {on: arm, by: base, moment: M0}               # at a joint: M0 on arm, −M0 on base

A force may hold the parameters, the coordinates, the points and t (a given function of
time); a couple likewise. Whether a load has a potential (a constant force at a point of
a body: V = −F·r_P) is decided with sympy (model/energies/loads.py).
"""

from __future__ import annotations

from dataclasses import replace

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.sections.bodies import refuse_negative
from rbdsolve.problem.context import Reading
from rbdsolve.problem.readers import check_keys, describe, expect_mapping, expect_scalar
from rbdsolve.problem.scene import Couple, Force, Wound
from rbdsolve.problem.schema import Body, Shape
from rbdsolve.problem.yamlnodes import Node, Scalar

SIDES = ("below", "above", "left", "right")


class LoadReader:
    def __init__(self, reading: Reading, bodies: tuple[Body, ...]):
        self.reading = reading
        self.bodies = {b.name: b for b in bodies}
        self.owner = {p: b.name for b in bodies for p, _ in b.points}  # a body's point -> the body

    def forces(self, node: Node | None) -> tuple[Force, ...]:
        if node is None or (isinstance(node, Scalar) and node.null):
            return ()
        table = expect_mapping(node, "forces: name -> {on: BODY, at: POINT, force: VECTOR}")
        return tuple(self.force(self.reading.declare(key, "force"), value) for key, value in table.entries)

    def couples(self, node: Node | None) -> tuple[Couple, ...]:
        if node is None or (isinstance(node, Scalar) and node.null):
            return ()
        table = expect_mapping(node, "couples: name -> {on: BODY, moment: M}")
        return tuple(self.couple(self.reading.declare(key, "couple"), value) for key, value in table.entries)

    def force(self, name: str, node: Node) -> Force:
        what = f"force '{name}'"
        spec = expect_mapping(node, f"{what}: {{on: BODY, at: POINT, force: VECTOR}}")
        check_keys(spec, ("force",), ("on", "at", "towards", "wound"), what)
        at = spec.get("at")
        point = self.reading.expr(at, ex.Kind.VECTOR, "a point name or position vector",
                                  self.reading.positions) if at is not None else None
        on = self.body(spec.get("on"), spec, what, point)
        towards = spec.get("towards")
        kind = ex.Kind.SCALAR if towards is not None else ex.Kind.VECTOR
        expected = ("the force's size (a scalar: it acts along the line to 'towards')" if towards is not None
                    else "a force vector such as [F, 0] (or its size with 'towards: POINT')")
        force = self.reading.expr(spec.get("force"), kind, expected, _without_rates(self.reading.positions))
        target = self.reading.expr(towards, ex.Kind.VECTOR, "the point the force pulls towards",
                                   self.reading.positions) if towards is not None else None
        wound = self.wound(spec.get("wound"), towards)
        return Force(name, on, point, force, target, wound, spec.loc)

    def couple(self, name: str, node: Node) -> Couple:
        what = f"couple '{name}'"
        spec = expect_mapping(node, f"{what}: {{on: BODY, moment: M}}")
        check_keys(spec, ("moment",), ("on", "by"), what)
        on = self.body(spec.get("on"), spec, what, None)
        by = self.named_body(spec.get("by")) if spec.get("by") is not None else None
        if by == on:
            raise InputError(f"a couple at a joint acts between two bodies: 'by' names '{on}' as 'on' does",
                             spec.get("by").loc)
        moment = spec.get("moment")
        if isinstance(moment, Scalar):  # a scalar about z, or a vector expression
            value = ex.parse(expect_scalar(moment, "a moment").text, moment.loc,
                             _without_rates(self.reading.positions), moment.plain)
        else:
            value = self.reading.expr(moment, ex.Kind.VECTOR, "a moment: a scalar about z, or a vector",
                                      _without_rates(self.reading.positions))
        if _a_point(self.bodies[on]):  # ('by' a particle: its half does no work, the other half does)
            raise InputError(f"{what} acts on '{on}', a particle: a point has no orientation, so a couple on it "
                             "does no work and the motion would ignore it; put it on a body that turns (a rod, a "
                             "disk, a plate… with an angle)", (spec.get("on") or spec).loc)
        return Couple(name, on, by, value, spec.loc)

    def wound(self, node: Node | None, towards: Node | None):
        """``wound: {radius: r, side: below}``: the force pulls a string wound on the body."""
        if node is None:
            return None
        if towards is not None:
            raise InputError("a wound string's force has its own direction: give 'force' as a vector, without "
                             "'towards'", node.loc)
        spec = expect_mapping(node, "a wound string: {radius: r, side: below}")
        check_keys(spec, ("radius", "side"), (), "a wound string")
        radius = self.reading.constant(spec.get("radius"), "the radius the string is wound at")
        refuse_negative(radius, "radius")
        word = expect_scalar(spec.get("side"), " or ".join(SIDES)).text.strip()
        if word not in SIDES:
            raise InputError(f"expected side {', '.join(SIDES)} (where the string leaves the body, as drawn), "
                             f"found {describe(spec.get('side'))}{did_you_mean(word, list(SIDES))}",
                             spec.get("side").loc)
        return Wound(radius, word, spec.loc)

    def body(self, node: Node | None, spec, what: str, point: ex.Expr | None) -> str:
        """The body the load acts on: named, or the one whose point (or name) ``at`` is,
        or the only body."""
        if node is not None:
            return self.named_body(node)
        if point is not None and isinstance(point.tree, ex.Name):
            name = point.tree.id
            if name in self.bodies:
                return name
            if name in self.owner:
                return self.owner[name]
        if len(self.bodies) == 1:
            return next(iter(self.bodies))
        raise InputError(f"say which body {what} acts on: 'on: BODY' (bodies: {', '.join(self.bodies) or 'none'})",
                         spec.loc)

    def named_body(self, node: Node) -> str:
        word = expect_scalar(node, "a body name").text.strip()
        if word not in self.bodies:
            raise InputError(f"no body '{word}'{did_you_mean(word, list(self.bodies))}", node.loc)
        return word


RATES = ("a load may hold the parameters, the coordinates, the points and t, not the velocities: a damper or "
         "a drag (c*dot(x)) is not in the format yet")


def _a_point(body: Body) -> bool:
    """A body that is one particle, given no angle or orientation: nothing of it turns
    (a particle on an arm that turns with 'angle' is a body a couple works on)."""
    return (len(body.parts) == 1 and body.parts[0].shape is Shape.PARTICLE and body.angle is None
            and not body.orientation and body.angular_velocity is None)


def _without_rates(scope: ex.Scope) -> ex.Scope:
    """The scope of a load's expression, with the reason rates are refused there."""
    return replace(scope, no_rates=RATES)
