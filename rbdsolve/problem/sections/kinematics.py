"""The options of a ``kinematics`` question: which points, at which state.

    - kinematics: {points: [B], at: {theta: pi/6, dot(theta): omega, ddot(theta): 0}, distance: [A, B]}
    - kinematics: {bodies: [coupler], at: {…}}     # a body's angular velocity and acceleration
    - kinematics: {lines: [A, B], at: {…}}         # those of the line AB (a link drawn by its ends)

``at`` gives coordinates, their rates ``dot(q)`` and accelerations ``ddot(q)``
constant values (parameters and numbers); what it leaves out stays symbolic.
``distance`` is one pair of points, or a list of pairs.
"""

from __future__ import annotations

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem.context import Reading
from rbdsolve.problem.readers import describe, expect_scalar
from rbdsolve.problem.options import KinematicsOptions
from rbdsolve.problem.instants import StateValue
from rbdsolve.problem.schema import Body, Point
from rbdsolve.problem.yamlnodes import Map, Node, Scalar, Seq

class KinematicsReader:
    def __init__(self, reading: Reading, points: tuple[Point, ...], bodies: tuple[Body, ...] = ()):
        self.reading = reading
        self.names = [p.name for p in points]
        self.bodies = [b.name for b in bodies]

    def options(self, opts: Map | None, key: Scalar) -> KinematicsOptions:
        get = opts.get if opts else (lambda _: None)
        if all(get(k) is None for k in ("points", "distance", "bodies", "lines")):
            raise InputError("'kinematics' needs 'points: [NAME, …]' (or 'distance: [A, B]'), the points whose "
                             "position, velocity and acceleration are asked, or 'bodies: [NAME, …]' or 'lines: [A, B]', "
                             "the bodies or the lines through two points whose angular velocity and acceleration are",
                             key.loc)
        points = self.point_names(get("points")) if get("points") is not None else ()
        at = self.state(get("at")) if get("at") is not None else ()
        bodies = self.body_names(get("bodies")) if get("bodies") is not None else ()
        return KinematicsOptions(points, at, self.distances(get("distance")), bodies,
                                 self.distances(get("lines"), "line"))

    def body_names(self, node: Node) -> tuple[str, ...]:
        items = node.items if isinstance(node, Seq) else [node]
        out = []
        for item in items:
            name = expect_scalar(item, "a body name").text.strip()
            if name not in self.bodies:
                raise InputError(f"no body '{name}'{did_you_mean(name, self.bodies)}", item.loc)
            out.append(name)
        return tuple(dict.fromkeys(out))

    def point_names(self, node: Node) -> tuple[str, ...]:
        items = node.items if isinstance(node, Seq) else [node]
        return tuple(self.point_name(item) for item in items)

    def point_name(self, node: Node) -> str:
        name = expect_scalar(node, "a point name").text.strip()
        if name not in self.names:
            known = did_you_mean(name, self.names) or (f" (points: {', '.join(self.names)})" if self.names
                                                       else " (declare it under 'points:')")
            raise InputError(f"no point '{name}'{known}", node.loc)
        return name

    def distances(self, node: Node | None, what: str = "distance") -> tuple[tuple[str, str], ...]:
        """[A, B] or [[A, B], [C, D]]: a distance's ends, or the points a line goes through."""
        if node is None:
            return ()
        key = "distance" if what == "distance" else "lines"
        if not isinstance(node, Seq) or not node.items:
            raise InputError(f"'{key}' takes a pair of points [A, B], or a list of pairs; found {describe(node)}",
                             node.loc)
        pairs = node.items if all(isinstance(i, Seq) for i in node.items) else [node]
        out = []
        for pair in pairs:
            if not isinstance(pair, Seq) or len(pair.items) != 2:
                raise InputError(f"a {what} is {'between' if what == 'distance' else 'through'} two points [A, B]; "
                                 f"found {describe(pair)}", pair.loc)
            a, b = (self.point_name(item) for item in pair.items)
            if a == b:
                raise InputError(f"a {what} needs two different points, found '{a}' twice", pair.loc)
            out.append((a, b))
        return tuple(out)

    def state(self, node: Node) -> tuple[StateValue, ...]:
        """coordinate, dot(coordinate) or ddot(coordinate) -> a constant value (what is left
        out stays symbolic), by the one reader of a state."""
        return self.reading.state(node, "'at'", (0, 1, 2))
