"""Independent oracle for 3D orientations with generalized coordinates: a body with
three different moments, pinned at a fixed point O off its centre of mass, oriented by
z-x-z Euler angles (body-fixed ``turns``) or by space-fixed x-y-z turns
(``space_turns``), as the coordinates.

rbdsolve's kinetic energy and Lagrange's equations are compared exactly with those of
``sympy.physics.mechanics`` (ReferenceFrame.orient_body_fixed / orient_space_fixed,
RigidBody, LagrangesMethod), built here from scratch: nothing of rbdsolve's model is
used. The triad's unit vectors are compared with the frame's, and the space-fixed
sequence with the body-fixed one in reverse order.
"""

from __future__ import annotations

import pytest
import sympy as sp
import sympy.physics.mechanics as me

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

SCENE = """\
parameters: {{m: mass, a: offset, b: offset, J1: moment, J2: moment, J3: moment, g: gravity}}
coordinates: [q1, q2, q3]
gravity: [0, 0, -g]
triads:
  B: {{{turns}, vectors: [e1, e2, e3]}}
points:
  G: a*e1 + b*e3
bodies:
  body: {{mass: m, inertia: [J1, J2, J3], at: G, orientation: [B]}}
questions:
  - eom
"""

SEQUENCES = {
    "body-fixed z-x-z": ("turns: [[z, q1], [x, q2], [z, q3]]", "body", "ZXZ"),
    "space-fixed x-y-z": ("space_turns: [[x, q1], [y, q2], [z, q3]]", "space", "XYZ"),
}

m, a, b, J1, J2, J3, g = sp.symbols("m a b J1 J2 J3 g", positive=True)


def _mechanics(kind: str, order: str):
    """T and Lagrange's equations (d/dt ∂L/∂q̇ − ∂L/∂q) from sympy.physics.mechanics."""
    q = me.dynamicsymbols("q1 q2 q3")
    N, B = me.ReferenceFrame("N"), me.ReferenceFrame("B")
    if kind == "body":
        B.orient_body_fixed(N, q, order)
    else:
        B.orient_space_fixed(N, q, order)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", a * B.x + b * B.z)
    G.v2pt_theory(O, N, B)
    body = me.RigidBody("body", G, B, m, (me.inertia(B, J1, J2, J3), G))
    body.potential_energy = m * g * G.pos_from(O).dot(N.z)
    L = me.Lagrangian(N, body)
    equations = me.LagrangesMethod(L, q).form_lagranges_equations()
    return q, N, B, body.kinetic_energy(N), list(equations)


def _t_form(expr, q):
    """rbdsolve's JSON writes q1(t); mechanics uses the same functions of t."""
    return sp.sympify(expr, locals={"m": m, "a": a, "b": b, "J1": J1, "J2": J2, "J3": J3, "g": g,
                                    **{str(x.func): x.func for x in q}})


def _is_zero(expr, q) -> bool:
    """Exactly zero as a function of q, q̇, q̈: with the rates as plain symbols and
    s_i = sin q_i, c_i = cos q_i (multiple angles expanded), the numerator is a polynomial
    that vanishes iff its remainder modulo s_i² + c_i² − 1 does (those polynomials, in
    distinct variables, are their own Gröbner basis). Far cheaper than simplify's search."""
    t = q[0].args[0]
    rates = {}
    for i, qi in enumerate(q):
        rates[qi.diff(t, 2)] = sp.Symbol(f"qdd{i}")
        rates[qi.diff(t)] = sp.Symbol(f"qd{i}")
    x = sp.symbols(f"x0:{len(q)}")
    s, c = sp.symbols(f"s0:{len(q)}"), sp.symbols(f"c0:{len(q)}")
    e = expr.doit().subs(rates).subs(dict(zip(q, x)))
    e = sp.expand_trig(e).xreplace({**{sp.sin(xi): si for xi, si in zip(x, s)},
                                     **{sp.cos(xi): ci for xi, ci in zip(x, c)}})
    numerator = sp.expand(sp.together(e).as_numer_denom()[0])
    assert not numerator.free_symbols & set(x), "an angle outside sin and cos"
    if numerator == 0:
        return True
    unit = [si**2 + ci**2 - 1 for si, ci in zip(s, c)]
    return sp.reduced(numerator, unit, *s, *c, *sorted(numerator.free_symbols - set(s) - set(c), key=str))[1] == 0


@pytest.mark.parametrize("name", SEQUENCES)
def test_energy_and_equations_match_lagranges_method(name) -> None:
    turns, kind, order = SEQUENCES[name]
    report = solve_problem(build_model(load_text(SCENE.format(turns=turns), "scene.yaml")))
    got = report_object(report)
    q, _, _, T, equations = _mechanics(kind, order)
    assert _is_zero(_t_form(got["model"]["T"], q) - T, q)
    (result,) = got["results"]
    assert len(result["answers"]["equations"]) == len(equations)
    for mine, theirs in zip(result["answers"]["equations"], equations):
        assert _is_zero(_t_form(mine, q) - theirs, q)


@pytest.mark.parametrize("name", SEQUENCES)
def test_triad_vectors_are_the_frame_s(name) -> None:
    turns, kind, order = SEQUENCES[name]
    model = build_model(load_text(SCENE.format(turns=turns), "scene.yaml"))
    q, N, B, _, _ = _mechanics(kind, order)
    R = model.to_time(model.triads["B"])  # columns: e1, e2, e3 in scene axes (its own t: via text)
    for column, axis in enumerate((B.x, B.y, B.z)):
        want = [axis.dot(e) for e in (N.x, N.y, N.z)]
        assert all(sp.simplify(_t_form(str(R[i, column]), q) - want[i]) == 0 for i in range(3))
