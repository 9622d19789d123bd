"""Reading 'forces:', 'couples:', a body's own points and a body hanging straight from a
drum: what each key gives, the defaults (the body a load acts on), and every refusal
located at its key with the message the format's manual quotes (docs/format.md)."""

from __future__ import annotations

import pytest

from rbdsolve.errors import InputError
from rbdsolve.problem import load_text
from rbdsolve.problem.expr import Kind

BASE = """\
title: Pendulum
parameters: {m: mass, l: length, g: gravity, F: force}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
forces:
  push: {on: bob, force: [F, 0]}
questions:
  - eom
"""


def _with(line: str, section: str = "forces:") -> str:
    lines = BASE.splitlines()
    lines[8], lines[9] = section, line
    return "\n".join(lines) + "\n"


def _refused(text: str) -> str:
    with pytest.raises(InputError) as caught:
        load_text(text, "p.yaml")
    return str(caught.value)


def test_a_force_and_its_defaults() -> None:
    problem = load_text(BASE, "p.yaml")
    (force,) = problem.forces
    assert (force.name, force.on, force.at, force.towards, force.wound) == ("push", "bob", None, None, None)
    assert force.force.kind is Kind.VECTOR
    assert problem.dimension_map()["F"].unit == "N"  # a parameter alone in a force is a force


def test_the_body_follows_from_the_point_and_a_couple_may_be_a_vector() -> None:
    text = BASE.replace("  bob: {shape: particle, mass: m, at: P}",
                        "  bob: {shape: particle, mass: m, at: P}\n"
                        "  rod: {shape: rod, mass: m, length: l, at: [0, 0], angle: theta, points: {B: [l/2, 0]}}")
    text = text.replace("  push: {on: bob, force: [F, 0]}", "  push: {at: B, force: [F, 0]}\n"
                        "  tow: {at: rod, force: F, towards: P}\ncouples:\n  twist: {on: rod, by: bob, moment: "
                        "\"F*l*[0, 0, 1]\"}\n  turn: {on: rod, moment: F*l}")
    problem = load_text(text, "p.yaml")
    assert [(f.name, f.on) for f in problem.forces] == [("push", "rod"), ("tow", "rod")]
    assert problem.forces[1].force.kind is Kind.SCALAR
    twist, turn = problem.couples
    assert (twist.on, twist.by, twist.moment.kind) == ("rod", "bob", Kind.VECTOR)
    assert (turn.by, turn.moment.kind) == (None, Kind.SCALAR)


@pytest.mark.parametrize("line, message", [
    ("  push: {on: bob, force: F}", "p.yaml:10:26: forces.push.force: expected a force vector such as [F, 0] (or its "
                                    "size with 'towards: POINT'), found a scalar 'F'"),
    ("  push: {on: bb, force: [F, 0]}", "p.yaml:10:14: forces.push.on: no body 'bb' (did you mean 'bob'?)"),
    ("  push: {on: bob, forse: [F, 0]}", "p.yaml:10:19: forces.push.forse: unknown key 'forse' in force 'push' "
                                         "(did you mean 'force'?)"),
    ("  push: {on: bob, force: [F, 0], at: Q}", "p.yaml:10:38: forces.push.at: unknown point 'Q'"),
    ("  push: {on: bob, force: [F, 0], wound: {radius: l, side: under}}",
     "p.yaml:10:59: forces.push.wound.side: expected side below, above, left, right (where the string leaves the "
     "body, as drawn), found 'under'"),
    ("  push: {on: bob, force: F, towards: P, wound: {radius: l, side: below}}",
     "p.yaml:10:48: forces.push.wound: a wound string's force has its own direction"),
    ("  push: {on: bob, force: [F, dot(theta)]}",
     "p.yaml:10:30: forces.push.force[1]: rates such as dot(theta) are not allowed here: a load may hold the "
     "parameters, the coordinates, the points and t, not the velocities: a damper or a drag (c*dot(x)) is not in "
     "the format yet"),
])
def test_a_bad_force_is_refused_where_it_is(line: str, message: str) -> None:
    assert _refused(_with(line)).startswith(message)


@pytest.mark.parametrize("line, message", [
    ("  push: {on: bob, by: bob, moment: F}", "p.yaml:10:23: couples.push.by: a couple at a joint acts between two "
                                             "bodies: 'by' names 'bob' as 'on' does"),
    ("  push: {on: bob}", "p.yaml:10:9: couples.push: missing required key 'moment' in couple 'push'"),
    ("  push: {on: bob, moment: M0}", "p.yaml:10:27: couples.push.moment: unknown symbol 'M0'"),
    ("  push: {on: bob, moment: -F*l*dot(theta)}", "p.yaml:10:32: couples.push.moment: rates such as dot(theta) are "
     "not allowed here: a load may hold the parameters, the coordinates, the points and t, not the velocities: a "
     "damper or a drag (c*dot(x)) is not in the format yet"),
])
def test_a_bad_couple_is_refused_where_it_is(line: str, message: str) -> None:
    assert _refused(_with(line, "couples:")) == message


@pytest.mark.parametrize("key, section", [("torques", "couples"), ("loads", "forces"), ("moments", "couples")])
def test_a_section_under_another_name_names_the_format_s(key: str, section: str) -> None:
    message = _refused(BASE.replace("forces:", f"{key}:"))
    assert message.startswith(f"p.yaml:9:1: {key}: unknown key '{key}' in the problem: applied loads go under "
                              f"'{section}:'")


def test_a_body_s_points_only_after_the_body() -> None:
    rod = "  rod: {shape: rod, mass: m, length: l, at: [0, 0], angle: theta, points: {B: [l/2, 0]}}\n"
    text = BASE.replace("bodies:\n", "bodies:\n" + rod).replace("  push: {on: bob, force: [F, 0]}",
                                                                 "  push: {at: B, force: [F, 0]}")
    assert load_text(text, "p.yaml").bodies[0].points[0][0] == "B"
    early = text.replace("  P: l * [sin(theta), -cos(theta)]", "  P: B + l * [sin(theta), -cos(theta)]")
    assert _refused(early).startswith("p.yaml:6:6: points.P: 'B' cannot appear here: it is a point of body 'rod' "
                                      "(under its 'points:'), placed with the body")
    named = text.replace("  P: l * [sin(theta), -cos(theta)]", "  P: rod + l * [sin(theta), -cos(theta)]")
    assert "'rod' cannot appear here: it names body 'rod'" in _refused(named)
    after = text.replace("at: P}", "at: B}")  # bob is listed after rod: it may sit at rod's point
    assert load_text(after, "p.yaml").bodies[1].at.text == "B"
    before = BASE.replace("bodies:\n", "bodies:\n").replace(
        "  bob: {shape: particle, mass: m, at: P}", "  bob: {shape: particle, mass: m, at: B}\n" + rod.rstrip())
    assert "'B' cannot appear here" in _refused(before)


def test_a_body_point_is_a_constant_offset() -> None:
    text = BASE.replace("at: P}", "at: P, points: {B: [theta, 0]}}")
    assert "'theta' cannot appear here: a point of body 'bob' is fixed in it" in _refused(text)


ATWOOD = """\
parameters: {M: mass, R: radius, m: mass, g: gravity}
coordinates: [theta]
points: {O: [0, 0], P: [2*R, 0]}
bodies:
  pulley: {shape: disk, mass: M, radius: R, at: O, angle: theta}
  block: {shape: particle, mass: m}
contacts:
  S: {body: block, hangs_from: {drum: pulley, side: left}}
questions: [eom]
"""


def test_a_body_hanging_straight_from_a_drum() -> None:
    (contact,) = load_text(ATWOOD, "p.yaml").contacts
    assert (contact.pulley.over, contact.pulley.side, contact.pulley.direction.text) == (None, "left", "[0, -1]")


@pytest.mark.parametrize("hang, message", [
    ("{drum: pulley}", "p.yaml:8:32: contacts.S.hangs_from: a body hanging from the drum says on which side of it "
                       "the string comes down: 'side: left' or 'side: right'"),
    ("{drum: pulley, side: lft}", "p.yaml:8:53: contacts.S.hangs_from.side: expected side left, right, above, "
                                  "below (where the string leaves the drum, as drawn), found 'lft' (did you mean "
                                  "'left'?)"),
    ("{drum: pulley, side: left, over: P, direction: [1, 0]}", "p.yaml:8:53: contacts.S.hangs_from.side: the "
                                                               "string runs over the pulley at 'over'"),
    ("{drum: pulley, over: P}", "p.yaml:8:32: contacts.S.hangs_from: a string over a pulley needs 'direction'"),
    ("{drum: pulley, side: left, down: [0, -1]}", "p.yaml:8:65: contacts.S.hangs_from.down: 'down' is the way the "
                                                  "string runs after a pulley"),
])
def test_a_hanging_string_s_keys_are_checked(hang: str, message: str) -> None:
    assert _refused(ATWOOD.replace("{drum: pulley, side: left}", hang)).startswith(message)


def test_a_couple_on_a_particle_is_refused_and_on_a_particle_that_turns_with_an_angle_is_not() -> None:
    """A point has no orientation: a couple on it does no work, and the motion would
    ignore it without a word (a new user's plate written as a particle at its centroid:
    ∂V/∂θ lost the couple). The same particle on an arm that turns ('angle') is a body a
    couple works on."""
    refused = _refused(_with("  push: {on: bob, moment: F*l}", "couples:"))
    assert refused.startswith("p.yaml:10:14: couples.push.on: couple 'push' acts on 'bob', a particle: a point has no "
                              "orientation, so a couple on it does no work")
    turning = _with("  push: {on: bob, moment: F*l}", "couples:").replace(
        "  bob: {shape: particle, mass: m, at: P}",
        "  bob: {at: [0, 0], angle: theta, parts: {b: {shape: particle, mass: m, at: [0, -l]}}}")
    assert [c.on for c in load_text(turning, "p.yaml").couples] == ["bob"]
