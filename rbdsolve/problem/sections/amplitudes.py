"""The ``check_amplitudes`` option of a ``modes`` question, validated at load time.

``modes: {about: {...}, check_amplitudes: [0.01, 0.5]}``: a list of positive numbers,
each the amplitude of the mode's largest coordinate (radians for an angle, the length
unit for a length) at which rbdsolve simulates the full nonlinear equations
(:mod:`rbdsolve.solvers.modes.amplitude`).
"""

from __future__ import annotations

from fractions import Fraction

from rbdsolve.errors import InputError
from rbdsolve.problem import expr as ex
from rbdsolve.problem.readers import describe, expect_scalar
from rbdsolve.problem.yamlnodes import Node, Scalar, Seq

MAX_AMPLITUDES = 8  # each is a simulation of several periods per mode


def amplitudes(node: Node | None, frame: Node | None) -> tuple[Fraction, ...]:
    """The amplitudes, in the order given; () without the option."""
    if node is None or (isinstance(node, Scalar) and node.null):
        return ()
    if frame is not None:
        raise InputError("'check_amplitudes' simulates the scene's own equations; it is not available with "
                         "'frame'", node.loc)
    if not isinstance(node, Seq) or not node.items:
        found = "an empty list" if isinstance(node, Seq) else describe(node)
        raise InputError(f"expected a list of amplitudes such as [0.01, 0.5] (of the mode's largest "
                         f"coordinate: radians or lengths), found {found}", node.loc)
    if len(node.items) > MAX_AMPLITUDES:
        raise InputError(f"{len(node.items)} amplitudes; the limit is {MAX_AMPLITUDES}", node.loc)
    out = []
    for item in node.items:
        scalar = expect_scalar(item, "an amplitude (a number)")
        value = ex.parse_number(scalar.text, scalar.loc, scalar.plain)
        if value <= 0:
            raise InputError(f"an amplitude must be positive, found {scalar.text.strip()}", scalar.loc)
        if value > 1000:
            raise InputError(f"an amplitude must be at most 1000, found {scalar.text.strip()}", scalar.loc)
        out.append(value)
    return tuple(out)
