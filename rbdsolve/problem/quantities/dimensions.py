"""Which parameters are masses, lengths, accelerations: read off the scene.

A value with a unit is checked against its parameter's dimension where the file makes
that dimension known, and an answer's SI unit is worked out from the parameters'
dimensions (``model/values/units.py``). A parameter's dimension is known from

- its declared ``unit:`` (``parameters: {r: {unit: cm}}``);
- the place it stands alone (times numbers) in the scene: a body's ``mass: 3*m`` (a
  mass), a shape's dimension ``length: sqrt(3)*r`` or a spring's natural length (a
  length), ``gravity: [0, -g]`` (an acceleration), a linear spring's ``stiffness: k``
  (N/m), a term ``l*sin(theta)`` of a point's position (a length), a term
  ``F*cos(alpha)`` of an applied force (N) and a couple's moment (N·m), a contact's
  circle ``radius: R``, the radius it rolls or a string winds at, a string's length,
  the terms of a surface's point (lengths); an impact's coefficient of restitution ``e``
  (a pure number), a striking particle's mass and the terms of its velocity (m/s);
- otherwise, the unit of its value (``values: {c: 2 N*m/rad}``).

A parameter found with two different dimensions in the scene (``mass: l``, with l a
length elsewhere) is left unknown: the scene, not this reading, is then the thing to
check, and no unit is printed for the answers that hold it.
"""

from __future__ import annotations

from fractions import Fraction
from typing import TYPE_CHECKING

from rbdsolve.problem import expr as ex
from rbdsolve.problem.quantities.quantity import ACCELERATION, LENGTH, MASS, NUMBER, Dimension
from rbdsolve.problem.schema import Body

if TYPE_CHECKING:
    from rbdsolve.problem.options import Collision
    from rbdsolve.problem.scene import Contact, Couple, Force, Spring

FORCE = Dimension(Fraction(1), Fraction(1), Fraction(-2))  # N = kg m/s²
STIFFNESS = Dimension(Fraction(1), Fraction(0), Fraction(-2))  # N/m = kg/s²
TORQUE = Dimension(Fraction(1), Fraction(2), Fraction(-2))  # a torsional stiffness, N·m per radian
VELOCITY = Dimension(Fraction(0), Fraction(1), Fraction(-1))  # m/s


def scene_dimensions(parameters: frozenset[str], bodies: tuple[Body, ...], springs: tuple[Spring, ...],
                     gravity: ex.Expr | None, positions: tuple[ex.Expr, ...], forces: tuple[Force, ...] = (),
                     couples: tuple[Couple, ...] = (), contacts: tuple[Contact, ...] = (),
                     collisions: tuple[Collision, ...] = ()) -> dict[str, tuple[Dimension, str]]:
    """Each parameter whose dimension the scene fixes: (dimension, where it was seen)."""
    found: dict[str, set[tuple[Dimension, str]]] = {}

    def see(tree: ex.Tree, dimension: Dimension, where: str, calls: bool = False) -> None:
        name = lone_parameter(tree, parameters, calls)
        if name is not None:
            found.setdefault(name, set()).add((dimension, where))

    for body in bodies:
        for part in body.parts:
            see(part.mass.tree, MASS, f"bodies.{body.name}.mass")
            for key, value in part.dimensions:  # a shape's sizes are lengths, its half_angle an angle
                see(value.tree, NUMBER if key == "half_angle" else LENGTH, f"bodies.{body.name}.{key}")
    for spring in springs:
        if spring.natural_length is not None:
            see(spring.natural_length.tree, LENGTH, f"springs.{spring.name}.natural_length")
        stiffness = STIFFNESS if spring.ends is not None else TORQUE
        see(spring.stiffness.tree, stiffness, f"springs.{spring.name}.stiffness")
    if gravity is not None:
        for term in _vector_terms(gravity.tree):
            see(term, ACCELERATION, "gravity")
    for position in positions:
        for term in _vector_terms(position.tree):
            see(term, LENGTH, "points", calls=True)
    for f in forces:
        terms = _vector_terms(f.force.tree) if f.towards is None else [f.force.tree]
        for term in terms:
            see(term, FORCE, f"forces.{f.name}.force", calls=True)
        if f.wound is not None:
            see(f.wound.radius.tree, LENGTH, f"forces.{f.name}.wound.radius")
    for c in couples:
        for term in (_vector_terms(c.moment.tree) if c.moment.kind is ex.Kind.VECTOR else [c.moment.tree]):
            see(term, TORQUE, f"couples.{c.name}.moment", calls=True)
    for c in contacts:
        lengths = [(c.surface.radius, "rolls_on.radius"), (c.radius, "radius")]
        if c.pulley is not None:
            lengths += [(c.pulley.radius, "radius"), (c.pulley.length, "length")]
        for value, key in lengths:
            if value is not None:
                see(value.tree, LENGTH, f"contacts.{c.name}.{key}")
        if c.surface.point is not None and c.surface.point.kind is ex.Kind.VECTOR:
            for term in _vector_terms(c.surface.point.tree):
                see(term, LENGTH, f"contacts.{c.name}.rolls_on", calls=True)
    for c in collisions:
        where = f"questions.impact.collisions.{c.point}"
        if c.restitution is not None:
            see(c.restitution.tree, NUMBER, f"{where}.restitution")
        if c.particle is not None:
            see(c.particle.mass.tree, MASS, f"{where}.particle.mass")
            for velocity in (c.particle.velocity, c.particle.after):
                for term in _vector_terms(velocity.tree) if velocity is not None else ():
                    see(term, VELOCITY, f"{where}.particle.velocity", calls=True)
    return {name: min(seen, key=lambda s: s[1]) for name, seen in found.items()
            if len({d for d, _ in seen}) == 1}


def lone_parameter(tree: ex.Tree, parameters: frozenset[str], calls: bool) -> str | None:
    """The one parameter of a product such as 3*m, m/2, sqrt(3)*r (or l*sin(theta)
    with ``calls``: a function's value is a pure number), else None."""
    names = _factors(tree, calls)
    if names is None or len(names) != 1 or names[0] not in parameters:
        return None
    return names[0]


def product_names(tree: ex.Tree) -> list[str] | None:
    """The names multiplied in a product such as 2*Omega*t (each to the first power, in
    the numerator), or None where ``tree`` is not such a product."""
    return _factors(tree, False)


def _factors(tree: ex.Tree, calls: bool) -> list[str] | None:
    """The names multiplied in ``tree`` (each to the first power, in the numerator), or
    None when it is not such a product."""
    if isinstance(tree, ex.Name):
        return [tree.id]
    if isinstance(tree, (ex.Num, ex.Const)):
        return []
    if isinstance(tree, ex.Neg):
        return _factors(tree.operand, calls)
    if isinstance(tree, ex.Call):
        return [] if calls or not set(ex.tree_names(tree)) else None
    if isinstance(tree, ex.BinOp) and tree.op == "*":
        left, right = _factors(tree.left, calls), _factors(tree.right, calls)
        return None if left is None or right is None else left + right
    if isinstance(tree, ex.BinOp) and tree.op == "/":
        left, right = _factors(tree.left, calls), _factors(tree.right, calls)
        return left if left is not None and right == [] else None
    return None


def _vector_terms(tree: ex.Tree):
    """The additive terms of each component of a vector expression: l*[sin(q), -cos(q)]
    gives l*sin(q) and l*cos(q); a point's name or a bare coordinate gives nothing
    that :func:`lone_parameter` accepts."""
    if isinstance(tree, ex.Vec):
        for item in tree.items:
            yield from sum_terms(item)
    elif isinstance(tree, ex.BinOp) and tree.op in "+-":
        yield from _vector_terms(tree.left)
        yield from _vector_terms(tree.right)
    elif isinstance(tree, ex.Neg):
        yield from _vector_terms(tree.operand)
    elif isinstance(tree, ex.BinOp) and tree.op == "*" and isinstance(tree.right, ex.Vec):
        for item in tree.right.items:
            for term in sum_terms(item):
                yield ex.BinOp("*", tree.left, term)
    elif isinstance(tree, ex.BinOp) and tree.op in "*/" and isinstance(tree.left, ex.Vec):
        for item in tree.left.items:
            for term in sum_terms(item):
                yield ex.BinOp(tree.op, term, tree.right)


def sum_terms(tree: ex.Tree):
    """The additive terms of a scalar expression: a + b − c gives a, b and c."""
    if isinstance(tree, ex.BinOp) and tree.op in "+-":
        yield from sum_terms(tree.left)
        yield from sum_terms(tree.right)
    elif isinstance(tree, ex.Neg):
        yield from sum_terms(tree.operand)
    else:
        yield tree
