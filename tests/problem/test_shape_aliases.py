"""The names a student writes for a shape (a new user's solid_sphere suggested
'solid_hemisphere' by spelling): each alias reads as the library's shape, checked by
the moment of inertia about the centre, by hand — a solid sphere 2/5 m r², a solid
cylinder and a solid disk m r²/2 about the axis, a hollow sphere 2/3 m r², a hollow
cylinder m r² about the axis."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text


@pytest.mark.parametrize("alias, size, moment", [
    ("solid_sphere", "radius: r", sp.Rational(2, 5)),
    ("solid_cylinder", "radius: r, height: h", sp.Rational(1, 2)),
    ("solid_disk", "radius: r", sp.Rational(1, 2)),
    ("hollow_sphere", "radius: r", sp.Rational(2, 3)),
    ("hollow_cylinder", "radius: r, height: h", sp.Integer(1)),
])
def test_a_shape_written_as_a_student_would_is_the_librarys(alias, size, moment) -> None:
    model = build_model(load_text(f"parameters: [m, r, h]\ncoordinates: [x]\n"
                                  f"bodies:\n  b: {{shape: {alias}, mass: m, {size}, at: [x, 0, 0]}}\n"
                                  "questions: [eom]\n"))
    (body,) = model.bodies
    m, r = sp.symbols("m r", positive=True)
    assert sp.simplify(body.inertia_in_scene()[2, 2] - moment * m * r**2) == 0
