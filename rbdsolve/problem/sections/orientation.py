"""3D orientation in the format: triads and body orientations as sequences of turns.

    unknowns: [spin]                      # constant unknowns (a steady spin rate)
    triads:
      T: {turns: [[z, omega0*t], [y, -theta]], vectors: [e1, e2, e3]}
    bodies:
      ring: {shape: ring, …, orientation: [T, [x, spin*t]]}

Each turn is [axis, angle], about an axis of the frame turned so far (body-fixed), so
[[z, psi], [x, theta], [z, phi]] are z-x-z Euler angles. A triad may instead give
``space_turns``, each about a scene axis (space-fixed): turning about fixed axes a₁,
then a₂, … is R = R_n ⋯ R₂ R₁, the same as the body-fixed turns in reverse order, which
is how they are stored. An orientation may start from a triad's name. The triad's unit
vectors (e1, e2, e3) are vectors in positions.
"""

from __future__ import annotations

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.context import Reading
from rbdsolve.problem.readers import check_keys, describe, expect_mapping, expect_scalar
from rbdsolve.problem.schema import Triad, Turn
from rbdsolve.problem.yamlnodes import Map, Node, Scalar, Seq


class OrientationReader:
    def __init__(self, reading: Reading):
        self.reading = reading

    def triads(self, node: Node | None) -> tuple[Triad, ...]:
        if node is None:
            return ()
        table = expect_mapping(node, "triads: name -> {turns, vectors}")
        out = []
        for key, value in table.entries:
            name = self.reading.declare(key, "triad")
            spec = expect_mapping(value, f"triad '{name}'")
            check_keys(spec, ("vectors",), ("turns", "space_turns"), f"triad '{name}'")
            vectors = spec.get("vectors")
            if not isinstance(vectors, Seq) or len(vectors.items) != 3:
                raise InputError("expected the names of the three unit vectors, as in [e1, e2, e3]",
                                 vectors.loc)
            names = tuple(self.reading.declare(expect_scalar(v, "a vector name"), "unit vector")
                          for v in vectors.items)
            out.append(Triad(name, self.triad_turns(spec), names, spec.loc))
        return tuple(out)

    def triad_turns(self, spec: Map) -> tuple[Turn, ...]:
        """Body-fixed ``turns``, or ``space_turns`` stored as body-fixed turns reversed."""
        body, space = spec.get("turns"), spec.get("space_turns")
        if (body is None) == (space is None):
            raise InputError("give either 'turns' (each about the turned frame's axes) or 'space_turns' "
                             "(each about the scene's fixed axes)", (space or spec).loc)
        return self.turns(body) if body is not None else self.turns(space)[::-1]

    def turns(self, node: Node) -> tuple[Turn, ...]:
        if not isinstance(node, Seq) or not node.items:
            raise InputError(f"expected a list of turns [axis, angle], found {describe(node)}", node.loc)
        return tuple(self.turn(item) for item in node.items)

    def turn(self, node: Node) -> Turn:
        if not isinstance(node, Seq) or len(node.items) != 2:
            raise InputError(f"expected a turn [axis, angle], such as [z, psi], found {describe(node)}", node.loc)
        axis = self.reading.axis(node.items[0])
        angle = self.reading.expr(node.items[1], ex.Kind.SCALAR, "an angle (a scalar expression)",
                                 self.reading.positions)
        return Turn(axis, angle)

    def orientation(self, node: Node, triads: tuple[str, ...]) -> tuple[str | Turn, ...]:
        """[T, [x, spin*t]]: a triad's name (first only), then turns."""
        if not isinstance(node, Seq) or not node.items:
            raise InputError(f"expected a list of turns [axis, angle], found {describe(node)}", node.loc)
        out: list[str | Turn] = []
        for i, item in enumerate(node.items):
            if isinstance(item, Scalar):
                name = item.text.strip()
                if i > 0 and name in triads:
                    raise InputError(f"the triad '{name}' may only come first in an orientation", item.loc)
                if name not in triads:
                    hint = did_you_mean(name, list(triads)) or (f" (triads: {', '.join(triads)})" if triads else "")
                    raise InputError(f"'{name}' is not a triad here{hint}: an orientation is a triad's name, "
                                     "first, and turns [axis, angle]", item.loc)
                out.append(name)
            else:
                out.append(self.turn(item))
        return tuple(out)
