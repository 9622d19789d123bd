"""Impact scenes: velocities at an instant, and the options of the ``impact`` question.
Every bad description gets one located message."""

from __future__ import annotations

import pytest

from rbdsolve.errors import InputError
from rbdsolve.problem import load_text
from rbdsolve.problem.schema import QuestionKind

GOOD = """\
parameters: {m: mass, l: length, v0: speed, e: restitution}
coordinates: [x, phi]
points:
  G: {velocity: [dot(x) - l/2*dot(phi), 0]}
  B: {velocity: [dot(x) - l*dot(phi), 0]}
bodies:
  AB: {shape: rod, mass: m, length: l, velocity: G, angular_velocity: dot(phi)}
  BC: {mass: m, velocity: B, angular_velocity: 0}
questions:
  - impact:
      impulses: {G: [m*v0, 0]}
      collisions:
        B: {normal: x, restitution: 1/2, particle: {mass: m, velocity: [-v0, 0]}}
      points: [G, B]
"""


def test_good_scene_loads() -> None:
    problem = load_text(GOOD, "p.yaml")
    question = problem.questions[0]
    assert question.kind is QuestionKind.IMPACT
    assert question.options.points == ("G", "B")
    assert [p.name for p in problem.points if p.velocity is not None] == ["G", "B"]
    assert problem.bodies[1].parts[0].shape.value == "particle"  # translating: mass only


def test_struck_points_are_the_default_points() -> None:
    problem = load_text(GOOD.replace("      points: [G, B]\n", ""), "p.yaml")
    assert problem.questions[0].options.points == ("G", "B")


CASES = [
    # (replace this, with this, line, column, key path, words)
    ("impulses: {G:", "impulses: {Q:", 11, 18, "questions[0].impact.impulses.Q",
     "unknown point 'Q' (points: G, B)"),
    ("normal: x", "normal: [0, 0]", 13, 21, "questions[0].impact.collisions.B.normal",
     "a normal must not be the zero vector"),
    ("restitution: 1/2", "restitution: 3/2", 13, 37, "questions[0].impact.collisions.B.restitution",
     "between 0 and 1, found 3/2"),
    ("restitution: 1/2, ", "", 13, 12, "questions[0].impact.collisions.B", "needs 'restitution: e'"),
    ("normal: x, ", "", 13, 12, "questions[0].impact.collisions.B", "needs 'normal'"),
    ("velocity: [-v0, 0]}", "velocity: [-v0, 0], after: [0, 0]}", 13, 37,
     "questions[0].impact.collisions.B.restitution", "not both"),
    ("velocity: [-v0, 0]", "velocity: [-v0, x]", 13, 78,
     "questions[0].impact.collisions.B.particle.velocity[1]", "must be constant"),
    ("impulses: {G: [m*v0, 0]}", "impulses: {G: [m*v0, dot(x)]}", 11, 28,
     "questions[0].impact.impulses.G[1]", "rates such as dot(x) are not allowed here"),
    ("angular_velocity: dot(phi)}", "angular_velocity: dot(psi)}", 7, 75,
     "bodies.AB.angular_velocity", "dot() needs a coordinate, found 'psi' (did you mean 'phi'?)"),
    ("[dot(x) - l/2*dot(phi), 0]", "[dot(x) - l/2*phi, 0]", 4, 31, "points.G.velocity[0]",
     "'phi' cannot appear here: a velocity at the instant uses parameters"),
    ("velocity: G,", "velocity: Q,", 7, 50, "bodies.AB.velocity", "unknown point 'Q'"),
    ("angular_velocity: 0}", "angular_velocity: dot(x)}", 8, 7, "bodies.BC",
     "needs a 'shape' (or an explicit 'inertia') since it turns at this instant"),
    (", angular_velocity: dot(phi)}", "}", 7, 7, "bodies.AB", "not 'angular_velocity' (0 if it does not turn"),
    ("velocity: G, angular", "velocity: G, at: [0, 0], angular", 7, 57, "bodies.AB.at", "not both"),
    ("[dot(x) - l/2*dot(phi), 0]", "[dot(x) - l/2*ddot(phi), 0]", 4, 31, "points.G.velocity[0]",
     "only rates such as dot(phi) are allowed here, not ddot(phi)"),
    ("angular_velocity: dot(phi)}", "angular_velocity: G}", 7, 71, "bodies.AB.angular_velocity",
     "'G' is a point; an angular velocity is a scalar (about z) or a vector"),
    ("  - impact:", "  - eom\n  - impact:", 10, 5, "questions[0]", "'eom' needs positions, but body 'AB'"),
    ("      points: [G, B]", "      points: [G, C]", 14, 19, "questions[0].impact.points[1]", "unknown point 'C'"),
    ("      impulses: {G: [m*v0, 0]}\n      collisions:\n"
     "        B: {normal: x, restitution: 1/2, particle: {mass: m, velocity: [-v0, 0]}}\n",
     "      at: {x: 0}\n", 10, 5, "questions[0].impact", "'impact' needs 'impulses'"),
]


@pytest.mark.parametrize("old, new, line, column, path, words", CASES, ids=[c[-1][:40] for c in CASES])
def test_bad_impact_input_is_located(old, new, line, column, path, words) -> None:
    assert old in GOOD
    with pytest.raises(InputError) as info:
        load_text(GOOD.replace(old, new, 1), "p.yaml")
    err = info.value
    assert words in err.message
    assert err.location.key_path() == path
    assert (err.location.line, err.location.column) == (line, column)


def test_a_velocity_must_be_linear_in_the_rates() -> None:
    from rbdsolve.model.build import build_model

    problem = load_text(GOOD.replace("[dot(x) - l/2*dot(phi), 0]", "[dot(x)*dot(phi), 0]"), "p.yaml")
    with pytest.raises(InputError) as info:
        build_model(problem)
    assert "a velocity must be linear in the rates dot(q)" in info.value.message
    assert (info.value.location.line, info.value.location.key_path()) == (4, "points.G.velocity")


STUCK = "{particle: {mass: m, velocity: [-v0, 0]}, sticks: true}"


def test_a_sticking_point_is_read() -> None:
    """Without a particle, the body's point sticks: to a fixed point, or to another point."""
    for collision, to in (("{sticks: true}", None), ("{sticks: true, to: G}", "G")):
        problem = load_text(GOOD.replace("{normal: x, restitution: 1/2, particle: {mass: m, velocity: [-v0, 0]}}",
                                         collision), "p.yaml")
        (c,) = problem.questions[0].options.collisions
        assert c.sticks and c.particle is None and c.normal is None and c.to == to


def test_a_sticking_particle_is_read() -> None:
    problem = load_text(GOOD.replace("{normal: x, restitution: 1/2, particle: {mass: m, velocity: [-v0, 0]}}", STUCK),
                        "p.yaml")
    (c,) = problem.questions[0].options.collisions
    assert c.sticks and c.normal is None and c.restitution is None and c.particle is not None


@pytest.mark.parametrize("collision, words", [
    ("{sticks: true, normal: x}", "p.yaml:13:35: questions[0].impact.collisions.B.normal: a sticking point takes "
                                  "no 'normal'"),
    ("{sticks: true, restitution: 0}", "collisions.B.restitution: a sticking point takes no 'restitution'"),
    ("{sticks: true, to: B}", "collisions.B.to: point 'B' cannot stick to itself"),
    ("{sticks: true, to: Q}", "collisions.B.to: unknown point 'Q'"),
    ("{to: G}", "collisions.B.to: 'to' names what the point 'B' sticks to: add 'sticks: true'"),
    ("{particle: {mass: m, velocity: [-v0, 0]}, sticks: true, to: G}",
     "collisions.B.to: a particle sticks at 'B', where it hits; 'to' is for a point of a body"),
    ("{particle: {mass: m, velocity: [-v0, 0]}, sticks: true, restitution: 0}",
     "collisions.B.restitution: a sticking particle takes no 'restitution'"),
    ("{particle: {mass: m, velocity: [-v0, 0]}, sticks: true, normal: x}",
     "collisions.B.normal: a sticking particle takes no 'normal': the impulse has every component"),
    ("{particle: {mass: m, velocity: [-v0, 0], after: [0, 0]}, sticks: true}",
     "collisions.B.particle.after: a sticking particle takes no 'after'"),
    ("{particle: {mass: m, velocity: [-v0, 0]}, sticks: maybe}", "collisions.B.sticks: expected true or false"),
    ("{particle: {mass: m, velocity: [-v0, 0]}, stick: true}", "unknown key 'stick' in collision at 'B' (did you mean"),
])
def test_bad_sticking(collision: str, words: str) -> None:
    text = GOOD.replace("{normal: x, restitution: 1/2, particle: {mass: m, velocity: [-v0, 0]}}", collision)
    with pytest.raises(InputError) as caught:
        load_text(text, "p.yaml")
    assert words in str(caught.value)
