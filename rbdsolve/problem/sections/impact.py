"""Options of the ``impact`` question: the instant, the velocities before, the blows.

    - impact:
        at: {theta: 0}              # the configuration at the instant (when it matters)
        before: {theta: 0}          # generalized velocities just before (default 0)
        impulses: {P: [F, 0]}       # known impulses at points
        collisions:                 # unknown impulses along a normal, closed by e
          A: {normal: y, restitution: e}                          # A hits a fixed surface
          B: {normal: x, restitution: e, particle: {mass: m, velocity: [v0, 0]}}
          C: {particle: {mass: m, velocity: [v0, 0], after: [0, 0]}}   # e follows
          D: {particle: {mass: m, velocity: [v0, -v1]}, sticks: true}  # it embeds at D
          E: {sticks: true}          # the body's point E sticks to a fixed point (a ledge): a pivot after
          F: {sticks: true, to: H}   # the body's point F sticks to point H of another body
        points: [A, B]              # velocities after (default: the struck points)
        centre_of_percussion: d     # the value of d for which the supports feel no impulse
"""

from __future__ import annotations

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.context import Reading
from rbdsolve.problem.readers import check_keys, describe, expect_mapping, expect_scalar, read_bool
from rbdsolve.problem.options import Collision, ImpactOptions, Particle
from rbdsolve.problem.schema import Point
from rbdsolve.problem.yamlnodes import Map, Node, Scalar, Seq


class ImpactReader:
    def __init__(self, reading: Reading, points: tuple[Point, ...]):
        self.reading = reading
        self.point_names = [p.name for p in points]

    def options(self, opts: Map | None, key: Scalar) -> ImpactOptions:
        get = opts.get if opts else (lambda _: None)
        at = self.reading.coordinate_values(get("at"), "the configuration 'at'", complete=False) \
            if get("at") is not None else ()
        before = self.reading.coordinate_values(get("before"), "the velocities 'before'", complete=False) \
            if get("before") is not None else ()
        impulses = self.impulses(get("impulses")) if get("impulses") is not None else ()
        collisions = self.collisions(get("collisions")) if get("collisions") is not None else ()
        if not impulses and not collisions:
            raise InputError("'impact' needs 'impulses' (known impulses at points) or 'collisions'", key.loc)
        struck = [name for name, _ in impulses] + [c.point for c in collisions]
        points = self.point_list(get("points")) if get("points") is not None else tuple(dict.fromkeys(struck))
        centre = self.parameter(get("centre_of_percussion")) if get("centre_of_percussion") is not None else None
        return ImpactOptions(at, before, impulses, collisions, points, centre, key.loc)

    def point(self, node: Node) -> str:
        name = expect_scalar(node, "a point name").text.strip()
        if name not in self.point_names:
            known = f" (points: {', '.join(self.point_names)})" if self.point_names else " (no points are declared)"
            raise InputError(f"unknown point '{name}'{did_you_mean(name, self.point_names) or known}", node.loc)
        return name

    def point_list(self, node: Node) -> tuple[str, ...]:
        if not isinstance(node, Seq):
            raise InputError(f"expected a list of point names, found {describe(node)}", node.loc)
        return tuple(self.point(item) for item in node.items)

    def constant_vector(self, node: Node, what: str) -> ex.Expr:
        scope = self.reading.scope.constants(f"{what} must be constant (parameters and numbers only)")
        return self.reading.expr(node, ex.Kind.VECTOR, what, scope)

    def impulses(self, node: Node) -> tuple[tuple[str, ex.Expr], ...]:
        table = expect_mapping(node, "impulses: point -> impulse vector")
        return tuple((self.point(k), self.constant_vector(v, "an impulse (a vector)")) for k, v in table.entries)

    def collisions(self, node: Node) -> tuple[Collision, ...]:
        table = expect_mapping(node, "collisions: point -> {normal, restitution, particle}")
        return tuple(self.collision(self.point(k), expect_mapping(v, f"collision at '{k.text}'"))
                     for k, v in table.entries)

    def collision(self, point: str, spec: Map) -> Collision:
        what = f"collision at '{point}'"
        check_keys(spec, (), ("normal", "restitution", "particle", "sticks", "to"), what)
        particle = self.particle(spec.get("particle")) if spec.get("particle") is not None else None
        if spec.get("sticks") is not None and read_bool(spec.get("sticks"), "true or false"):
            return self.sticking(point, spec, particle)
        if spec.get("to") is not None:
            raise InputError(f"'to' names what the point '{point}' sticks to: add 'sticks: true'", spec.get("to").loc)
        restitution = spec.get("restitution")
        known_after = particle is not None and particle.after is not None
        if restitution is not None and known_after:
            raise InputError("give either 'restitution' (the velocities after follow) or the particle's "
                             "'after' velocity (the restitution follows), not both", restitution.loc)
        if restitution is None and not known_after:
            hint = "" if particle else " (a point hitting a fixed surface)"
            raise InputError(f"{what}{hint} needs 'restitution: e' (0 ≤ e ≤ 1)", spec.loc)
        if spec.get("normal") is None and not known_after:
            raise InputError(f"{what} needs 'normal': the direction of the impulse on the system "
                             "(x, -y, … or a vector)", spec.loc)
        normal = self.normal(spec.get("normal")) if spec.get("normal") is not None else None
        e = self.restitution(restitution) if restitution is not None else None
        return Collision(point, normal, e, particle, spec.loc)

    def sticking(self, point: str, spec: Map, particle: Particle | None) -> Collision:
        """A particle that embeds at the point, or (no particle) the body's point that
        sticks to a fixed point, or to point ``to`` of another body: no normal, no
        restitution, no velocity after (it moves with what it sticks to); the impulse is
        unknown in every component the point can move in."""
        what = "a sticking particle" if particle is not None else "a sticking point"
        for key, why in (("restitution", "it moves with what it sticks to after (e = 0 in every direction)"),
                         ("normal", "the impulse has every component, not only a normal one")):
            if spec.get(key) is not None:
                raise InputError(f"{what} takes no '{key}': {why}", spec.get(key).loc)
        if particle is not None and particle.after is not None:
            raise InputError("a sticking particle takes no 'after': it moves with the point after the impact",
                             particle.after.loc)
        to = spec.get("to")
        if to is None:
            return Collision(point, None, None, particle, spec.loc, sticks=True)
        if particle is not None:
            raise InputError(f"a particle sticks at '{point}', where it hits; 'to' is for a point of a body that "
                             "sticks to a point of another body", to.loc)
        partner = self.point(to)
        if partner == point:
            raise InputError(f"point '{point}' cannot stick to itself: 'to' names the point of the other body it "
                             "sticks to", to.loc)
        return Collision(point, None, None, None, spec.loc, sticks=True, to=partner)

    def normal(self, node: Node) -> ex.Expr:
        value = self.reading.axis(node) if _is_axis_name(node) else self.constant_vector(node, "a normal (a vector)")
        if isinstance(value.tree, ex.Vec) and all(ex.constant_value(c) == 0 for c in value.tree.items):
            raise InputError("a normal must not be the zero vector", value.loc)
        return value

    def restitution(self, node: Node) -> ex.Expr:
        value = self.reading.constant(node, "a coefficient of restitution")
        number = ex.constant_value(value.tree)
        if number is not None and not 0 <= number <= 1:
            raise InputError(restitution_message(value.text), value.loc)
        return value

    def particle(self, node: Node) -> Particle:
        spec = expect_mapping(node, "a particle: {mass, velocity, after}")
        check_keys(spec, ("mass", "velocity"), ("after",), "the particle")
        mass = self.reading.constant(spec.get("mass"), "a mass")
        number = ex.constant_value(mass.tree)
        if number is not None and number <= 0:
            raise InputError(f"a particle's mass must be positive, found {mass.text}", mass.loc)
        velocity = self.constant_vector(spec.get("velocity"), "the particle's velocity just before")
        after = self.constant_vector(spec.get("after"), "the particle's velocity just after") \
            if spec.get("after") is not None else None
        return Particle(mass, velocity, after, spec.loc)

    def parameter(self, node: Node) -> str:
        name = expect_scalar(node, "a parameter name").text.strip()
        params = sorted(self.reading.scope.scalars - self.reading.scope.functions_of_time - {"t"})
        if name not in params:
            raise InputError(f"'{name}' is not a parameter{did_you_mean(name, params)}", node.loc)
        return name


def _is_axis_name(node: Node) -> bool:
    return isinstance(node, Scalar) and node.text.strip() in {"x", "y", "z", "-x", "-y", "-z"}


def restitution_message(text: str, value: object = None) -> str:
    """One message for e outside [0, 1], whether the file or the values put it there."""
    shown = text if value is None or str(value) == text.replace(" ", "") else f"{text} = {value}"
    return f"a coefficient of restitution is between 0 and 1, found {shown}"
