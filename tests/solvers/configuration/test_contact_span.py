"""Where a contact holds, checked by its definition rather than by the span formula of
model/constraints/contacts.py: at sampled values of the coordinate, the contact point C, carried
back into the body's axes (Rᵀ (C − O)), lies on the edge — on the arc (d·a ≥ 0 for the
arc's limits, by hand for each shape) or within the flat side's half length, all the
way from the reference configuration — exactly when solvers/configuration/contact_span.py says
the configuration is inside the span."""

from __future__ import annotations

import pytest
import sympy as sp

import rbdsolve
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers.configuration import contact_span

HEAD = "parameters: {m: mass, r: radius, R: radius, b: width, a: height, g: gravity}\n" \
       "values: {m: 1, r: 1, R: 3, b: 2, a: 1/5, g: 10}\ncoordinates: [q]\ngravity: [0, -g]\n" \
       "questions: [equilibria]\n"

# (body, contact, on-edge test in body axes d = Rᵀ(C − O), by hand)
SCENES = {
    "half disk on the floor": (
        "half: {shape: half_disk, mass: m, radius: r, axis: -y}",
        "{body: half, edge: curved, rolls_on: floor, angle: q}",
        lambda d: -d[1] >= 0),  # the arc is the half below the diameter (axis −y)
    "quarter disk on the floor": (
        "quarter: {shape: quarter_disk, mass: m, radius: r, axis: -y}",
        "{body: quarter, edge: curved, rolls_on: floor, angle: q}",
        lambda d: -d[1] >= abs(d[0])),  # the quarter arc within 45° of straight down
    "half disk on top of a drum": (
        "half: {shape: half_disk, mass: m, radius: r, axis: -y}",
        "{body: half, edge: curved, rolls_on: {circle: {centre: [0, 0], radius: R, side: outside}}, along: q}",
        lambda d: -d[1] >= 0),
    "half disk in a bowl": (
        "half: {shape: half_disk, mass: m, radius: r, axis: -y}",
        "{body: half, edge: curved, rolls_on: {circle: {centre: [0, 0], radius: R, side: inside}}, along: q}",
        lambda d: -d[1] >= 0),
    "cylinder segment on the floor": (
        "trunk: {shape: cylinder_segment, mass: m, radius: r, height: b, half_angle: 1, axis: -y}",
        "{body: trunk, edge: curved, rolls_on: floor, angle: q}",
        lambda d: -d[1] >= 0.5403023058681398 * (d[0] ** 2 + d[1] ** 2) ** 0.5),  # within 1 rad of down
    "slab on a drum": (
        "slab: {shape: plate, mass: m, width: b, height: a}",
        "{body: slab, edge: bottom, rolls_on: {circle: {centre: [0, 0], radius: R, side: outside}}, angle: q}",
        lambda d: abs(d[0]) <= 1),  # the underside spans |x| ≤ b/2 = 1
}


def _model(body: str, contact: str):
    return build_model(load_text(HEAD + f"bodies:\n  {body}\ncontacts:\n  C: {contact}\n"))


@pytest.mark.parametrize("name", list(SCENES))
def test_the_span_is_where_the_contact_point_is_on_the_edge(name: str) -> None:
    body_text, contact_text, on_edge = SCENES[name]
    model = _model(body_text, contact_text)
    (contact,) = model.contacts
    body = model.bodies[0]
    origin = model.symbols.vector(model.problem.bodies[0].at)
    q = model.q[0]
    inside = outside = 0
    for side in (1, -1):  # walking away from the reference: once C leaves the edge, the contact is gone
        left = False
        for k in range(0, 121):
            value = side * sp.Rational(k, 40)  # q out to ±3, one turn of the coordinate and a bit
            at = {q: value, **model.values}
            d = (body.rotation.T * (contact.point - origin)).xreplace(at).evalf(30)
            ends = (abs(d[0]) - 1, d[1], abs(d[0]) - abs(d[1]), -d[1] - 0.5403023058681398 * abs(d.norm()))
            if min(abs(x) for x in ends) < 1e-9:
                continue  # at an end of the edge: either answer is right
            left = left or not on_edge(d)
            got = contact_span.outside(model, {q: value}) is None
            assert got == (not left), (name, value, d.T)
            inside, outside = inside + (not left), outside + left
    assert inside and outside  # the samples saw both sides of the span


def test_the_half_disk_upside_down_is_not_listed_and_the_reason_is_given() -> None:
    from rbdsolve.solvers.equilibria.exact import listing

    model = _model(*SCENES["half disk on the floor"][:2])
    listed = listing(model)
    assert [x.at[model.q[0]] for x in listed.equilibria] == [0]
    assert any("q = π is a solution of ∂V/∂q = 0 but not an equilibrium" in w
               and "−π/2 ≤ q ≤ π/2" in w for w in listed.warnings)


def test_modes_about_a_point_off_the_edge_are_refused_on_both_routes() -> None:
    from rbdsolve.solvers import Options, RouteChoice, solve_problem

    text = HEAD.replace("questions: [equilibria]", "questions: [{modes: {about: {q: pi}}}]")
    body, contact, _ = SCENES["half disk on the floor"]
    model = build_model(load_text(text + f"bodies:\n  {body}\ncontacts:\n  C: {contact}\n"))
    for route in (RouteChoice.EXACT, RouteChoice.NUMERIC):
        report = solve_problem(model, Options(route=route))
        (result,) = report.solutions
        assert result.error is not None and "off half's curved edge" in result.error, route


def test_where_the_parameters_leave_the_span_open_the_equilibrium_is_kept_with_its_condition() -> None:
    """A cylinder segment of symbolic half angle α rocking on the floor: its arc spans
    |θ| ≤ α (by hand: the arc is the directions within α of straight down, and turning by θ
    moves the contact's direction by θ), so θ = π is on the arc only for α = π (a whole
    cylinder): kept, with that condition said."""
    from rbdsolve.solvers.equilibria.exact import listing

    text = ("parameters: {m: mass, r: radius, h: length, alpha: angle, g: gravity}\ncoordinates: [q]\n"
            "gravity: [0, -g]\nquestions: [equilibria]\nbodies:\n  trunk: {shape: cylinder_segment, mass: m, "
            "radius: r, height: h, half_angle: alpha, axis: -y}\n"
            "contacts:\n  C: {body: trunk, edge: curved, rolls_on: floor, angle: q}\n")
    model = build_model(load_text(text))
    listed = listing(model)
    assert sorted(x.at[model.q[0]] for x in listed.equilibria) == [0, sp.pi]
    assert any("q = π is an equilibrium only while" in w and "−α ≤ q ≤ α" in w for w in listed.warnings)


def test_the_ranges_of_inverse_functions_decide_a_side_where_sampling_agrees() -> None:
    """π − atan(u) − π/2 > 0 and −atan(u) + π/2 > 0 for every u > 0 (the half ring with a
    particle: its second root of ∂V/∂θ = 0 is off the arc); asin and acos by their
    ranges; an expression whose range meets 0 stays undecided. Each decided sign is
    checked at random positive values of the parameters."""
    import random

    from rbdsolve.solvers.configuration.contact_span import _bounded_sign

    m, M = sp.symbols("m M", positive=True)
    u = sp.pi * m / (2 * M)
    cases = {sp.pi - sp.atan(u) - sp.pi / 2: 1, sp.pi / 2 - sp.atan(u): 1, -sp.atan(u) - sp.pi / 2: -1,
             sp.acos(u / (1 + u)) - sp.pi / 2: -1, sp.asin(-u / (1 + u)) + sp.pi: 1,
             sp.atan(u) - sp.pi / 4: None, sp.atan(m - M): None}
    rng = random.Random(40)
    for expr, sign in cases.items():
        assert _bounded_sign(expr) == sign, expr
        if sign is None:
            continue
        for _ in range(20):
            at = {m: rng.uniform(1e-3, 1e3), M: rng.uniform(1e-3, 1e3)}
            assert sign * float(expr.xreplace(at)) > 0, (expr, at)


HALF_DISK_TURNED = """\
parameters:
  m: mass
  R: radius
  g: gravity
  C: {description: couple, positive: false}
coordinates: [theta]
gravity: [0, -g]
bodies:
  half: {shape: half_disk, mass: m, radius: R, axis: -y}
contacts:
  C1: {body: half, edge: curved, rolls_on: floor, angle: theta}
couples:
  turn: {on: half, moment: C}
questions: [equilibria]
"""


def test_a_half_disk_turned_by_a_couple_rests_only_where_its_curved_edge_is_down(tmp_path) -> None:
    """A new user's: by hand ∂V/∂θ = m g d sin θ − C (d = 4R/(3π) from the flat side's
    middle to G), so sin θ₀ = C/(m g d): θ₀ = asin(…), in [−π/2, π/2], always on the curved
    edge, and π − θ₀ (written atan2(…, −√(…))), with cos θ ≤ 0: off the edge but at its
    ends, where it is the first one. It listed both, each 'the parameters leave that open'."""
    path = tmp_path / "half.yaml"
    path.write_text(HALF_DISK_TURNED)
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    (only,) = solution.answers.equilibria
    R, g, m = sp.symbols("R g m", positive=True)
    C = sp.Symbol("C", real=True)
    assert sp.simplify(only.at["theta"] - sp.asin(3 * sp.pi * C / (4 * R * g * m))) == 0
    assert not any("leave that open" in w for w in solution.warnings)
    assert any("not an equilibrium of the scene" in w and "atan2" in w for w in solution.warnings)
