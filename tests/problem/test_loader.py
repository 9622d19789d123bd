"""The loader: valid scenes load; every bad input gets one located message."""

from __future__ import annotations

import textwrap

import pytest

from rbdsolve.errors import InputError
from rbdsolve.problem import load_file, load_text
from rbdsolve.problem.schema import CoordinateKind, QuestionKind, Shape

GOOD = """\
title: Pendulum
parameters: {m: mass, l: length, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
questions:
  - modes: {about: {theta: 0}}
"""


def load(text: str):
    return load_text(textwrap.dedent(text), "p.yaml")


def error(text: str) -> InputError:
    with pytest.raises(InputError) as info:
        load(text)
    return info.value


def test_good_scene_loads() -> None:
    problem = load(GOOD)
    assert [p.name for p in problem.parameters] == ["m", "l", "g"]
    assert problem.coordinates[0].kind is CoordinateKind.AUTO
    assert problem.bodies[0].parts[0].shape is Shape.PARTICLE
    assert problem.questions[0].kind is QuestionKind.MODES
    assert problem.questions[0].options.about[0][0] == "theta"


def test_about_is_read_in_coordinate_order() -> None:
    text = GOOD.replace("coordinates: [theta]", "coordinates: [theta, x]").replace(
        "{about: {theta: 0}}", "{about: {x: 1, theta: 0}}"
    )
    assert [name for name, _ in load(text).questions[0].options.about] == ["theta", "x"]


def test_points_are_ordered_by_dependency() -> None:
    text = GOOD.replace("  P: l * [sin(theta), -cos(theta)]", "  Q: P + [0, 1]\n  P: [l, 0]")
    assert [p.name for p in load(text).points] == ["P", "Q"]


CASES = [
    # (replace this, with this, line, column, key path, words)
    ("mass: m,", "mass: M,", 8, 32, "bodies.bob.mass", "unknown symbol 'M' (did you mean 'm'?)"),
    ("at: P}", "at: Q}", 8, 39, "bodies.bob.at", "unknown point 'Q'"),
    ("shape: particle", "shape: partcle", 8, 16, "bodies.bob.shape", "unknown shape 'partcle' (did you mean 'particle'?)"),
    ("shape: particle, ", "", 8, 8, "bodies.bob", "needs a 'shape'"),
    ("mass: m, ", "", 8, 8, "bodies.bob", "missing required key 'mass'"),
    ("mass: m,", "mass: m, colour: red,", 8, 35, "bodies.bob.colour", "unknown key 'colour'"),
    ("mass: m,", "mass: -2,", 8, 32, "bodies.bob.mass", "must not be negative"),
    ("mass: m,", "mass: [1, 2],", 8, 32, "bodies.bob.mass", "expected a mass, found a list"),
    ("gravity: [0, -g]", "gravity: [0, -g, 1, 2]", 4, 10, "gravity", "2 or 3 components"),
    ("gravity: [0, -g]", "gravty: [0, -g]", 4, 1, "gravty", "unknown key 'gravty' in the problem (did you mean 'gravity'?)"),
    ("gravity: [0, -g]", "gravity: -g", 4, 10, "gravity", "expected a gravity vector"),
    ("  - modes: {about: {theta: 0}}", "  - mode", 10, 5, "questions[0]", "unknown question 'mode' (did you mean 'modes'?)"),
    ("{about: {theta: 0}}", "{about: {thta: 0}}", 10, 21, "questions[0].modes.about.thta", "'thta' is not a coordinate (did you mean 'theta'?)"),
    ("{about: {theta: 0}}", "{abut: {theta: 0}}", 10, 13, "questions[0].modes.abut", "unknown key 'abut' in question 'modes' (did you mean 'about'?)"),
    ("parameters: {m: mass, l: length, g: gravity}", "parameters: {m: mass, l: length, g: gravity, m: again}", 2, 46, "parameters.m", "duplicate key 'm'"),
    ("parameters: {m: mass,", "parameters: {sin: mass, m: mass,", 2, 14, "parameters.sin", "reserved"),
    ("coordinates: [theta]", "coordinates: [theta, m]", 3, 22, "coordinates[1]", "already declared as a parameter"),
    ("  P: l * [sin(theta), -cos(theta)]", "  P: Q + [1, 0]\n  Q: P + [0, 1]", 6, 6, "points.P", "cyclic point definitions: P -> Q -> P"),
    ("  P: l * [sin(theta), -cos(theta)]", "  P: l * [sin(theta), -cos(theta)] + 1", 6, 6, "points.P", "cannot add a vector and a scalar"),
    ("title: Pendulum", "title: Pendulum\nvalues: {m: heavy}", 2, 13, "values.m", "expected a number, found 'heavy'"),
    ("title: Pendulum", "title: Pendulum\nvalues: {M: 1}", 2, 10, "values.M", "'M' is not a parameter (did you mean 'm'?)"),
    ("title: Pendulum", "title: Pendulum\nvalues: {m: -1}", 2, 13, "values.m", "declared positive"),
    # constants stay constant; rates are not allowed in a scene
    ("mass: m,", "mass: dot(theta),", 8, 32, "bodies.bob.mass", "rates such as dot(theta) are not allowed here"),
    ("mass: m,", "mass: m*t,", 8, 34, "bodies.bob.mass", "'t' cannot appear here: a mass must be constant"),
    ("mass: m,", "mass: m*theta,", 8, 34, "bodies.bob.mass", "'theta' cannot appear here"),
    ("gravity: [0, -g]", "gravity: [0, -g*theta]", 4, 17, "gravity[1]", "'theta' cannot appear here: gravity must be constant"),
    ("  P: l * [sin(theta), -cos(theta)]", "  P: l * [dot(theta), 0]", 6, 11, "points.P", "rates such as dot(theta)"),
    ("{about: {theta: 0}}", "{about: {theta: t}}", 10, 28, "questions[0].modes.about.theta", "'t' cannot appear here"),
    # names and messages
    ("parameters: {m: mass,", "parameters: {lambda: mass, m: mass,", 2, 14, "parameters.lambda", "Python keyword"),
    ("parameters: {m: mass,", "parameters: {ℓ: mass, m: mass,", 2, 14, "parameters.ℓ", "Greek letters are spelled"),
    ("{m: mass, l: length,", "{m: 3, l: length,", 2, 17, "parameters.m", "write 'values: {m: 3}'"),
    ("  - modes: {about: {theta: 0}}", "  - eom: {about: {theta: 0}}", 10, 11, "questions[0].eom.about", "unknown key 'about' in question 'eom' (expected one of: frames, at, from_rest)"),
    ("questions:\n  - modes: {about: {theta: 0}}", "questions: []", 9, 12, "questions", "found an empty list"),
    ("shape: particle, ", "shape: rod, length: l, radius: l, ", 8, 32, "bodies.bob.radius", "a rod takes length, not 'radius'"),
    # 'for:' names the parameter the conditions are written in (issue 38)
    ("{about: {theta: 0}}", "{about: {theta: 0}, for: L}", 10, 37, "questions[0].modes.for", "no parameter 'L' (did you mean 'l'?)"),
    ("{about: {theta: 0}}", "{about: {theta: 0}, for: theta}", 10, 37, "questions[0].modes.for", "'theta' is a coordinate; conditions are written in a parameter"),
    ("{about: {theta: 0}}", "{about: {theta: 0}, for: [l]}", 10, 37, "questions[0].modes.for", "expected a parameter name, found a list"),
    ("  - modes: {about: {theta: 0}}", "  - equilibria: {for: q}", 10, 23, "questions[0].equilibria.for", "no parameter 'q' (parameters: m, l, g)"),
    ("  - modes: {about: {theta: 0}}", "  - eom: {for: l}", 10, 11, "questions[0].eom.for", "unknown key 'for' in question 'eom'"),
]


@pytest.mark.parametrize("old, new, line, column, path, words", CASES, ids=[c[-1][:40] for c in CASES])
def test_bad_input_is_located(old, new, line, column, path, words) -> None:
    assert old in GOOD
    err = error(GOOD.replace(old, new, 1))
    assert words in err.message
    assert err.location.key_path() == path
    assert (err.location.line, err.location.column) == (line, column)


@pytest.mark.parametrize(
    "text, words",
    [
        ("", "empty"),
        ("   \n", "empty"),
        ("- a\n- b\n", "expected a mapping at the top"),
        ("title: x\n", "missing required key 'questions'"),
        ("questions: [eom]\n", "needs generalized coordinates"),
        ("title: [unclosed\n", "YAML syntax error"),
        ("title: x\n\tquestions: [eom]\n", "tab"),
        ("a: &a [1, *a]\nquestions: [eom]\n", "nesting deeper than"),
    ],
)
def test_bad_documents(text: str, words: str) -> None:
    with pytest.raises(InputError) as info:
        load_text(text, "p.yaml") if text.strip() else load_file_text(text)
    assert words in info.value.message


@pytest.mark.parametrize(
    "text, at, words",
    [
        ("title: [unclosed\n", (1, 8), "this '[' is never closed: no ']' before the end of the file"),
        ("title: x\nparameters: {m: mass\n", (2, 13), "this '{' is never closed"),
        ("coordinates: [theta\ngravity: [0, -g]\nquestions: [eom]\n", (1, 14), "no ']' before 2:8"),
    ],
)
def test_an_unclosed_bracket_is_said_where_it_opens(text: str, at: tuple[int, int], words: str) -> None:
    with pytest.raises(InputError) as info:
        load_text(text, "p.yaml")
    assert words in info.value.message
    assert (info.value.location.line, info.value.location.column) == at


def test_a_bracket_closed_further_on_keeps_the_error_inside_it() -> None:
    """{a: 1,↵ c: [1, 2] + 3}: the '{' is closed; the error is the unquoted '[' on line 2."""
    with pytest.raises(InputError) as info:
        load_text("a: {b: 1,\n  c: [1, 2] + 3}\nquestions: [eom]\n", "p.yaml")
    assert "never closed" not in info.value.message
    assert info.value.location.line == 2


def load_file_text(text: str):
    from rbdsolve.problem.yamlnodes import read_text

    return load_text(read_text("p.yaml", text.encode()), "p.yaml")


def test_alias_bomb_is_refused_quickly() -> None:
    lines = ['a0: &a0 ["x", "x", "x", "x", "x", "x", "x", "x", "x"]']
    for i in range(1, 10):
        lines.append(f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]")
    with pytest.raises(InputError, match="refusing to expand"):
        load_text("\n".join(lines) + "\nquestions: [eom]\n", "bomb.yaml")


def test_binary_and_non_utf8_files(tmp_path) -> None:
    binary = tmp_path / "b.yaml"
    binary.write_bytes(b"\x00\x01\x02questions")
    with pytest.raises(InputError, match="binary"):
        load_file(binary)
    latin = tmp_path / "l.yaml"
    latin.write_bytes("title: caf\xe9\nquestions: [eom]\n".encode("latin-1"))
    with pytest.raises(InputError, match="not UTF-8") as info:
        load_file(latin)
    assert (info.value.location.line, info.value.location.column) == (1, 11)


def test_missing_file() -> None:
    with pytest.raises(InputError, match="no such file"):
        load_file("does/not/exist.yaml")


PRESCRIBED = """\
parameters: {m: mass, l: length, a: amplitude, w: frequency}
prescribed:
  y_A: unknown
  x_O: a*cos(w*t)
coordinates: [phi]
points:
  B: l * [sin(phi), -cos(phi)] + [x_O, y_A]
bodies:
  bob: {shape: particle, mass: m, at: B}
questions: [eom]
"""


def test_prescribed_functions_load() -> None:
    problem = load_text(PRESCRIBED, "p.yaml")
    assert [(p.name, p.value is None) for p in problem.prescribed] == [("y_A", True), ("x_O", False)]
    assert [c.name for c in problem.coordinates] == ["phi"]  # not degrees of freedom


@pytest.mark.parametrize(
    "old, new, where, words",
    [
        ("a*cos(w*t)", "a*cos(phi*t)", (4, 14), "unknown symbol 'phi'"),
        ("a*cos(w*t)", "a*cos(w*t) + y_A", (4, 21), "unknown symbol 'y_A'"),
        ("mass: m,", "mass: m*y_A,", (9, 34), "'y_A' cannot appear here: a mass must be constant"),
        ("  y_A: unknown", "  m: unknown", (3, 3), "'m' is already declared as a parameter"),
    ],
)
def test_bad_prescribed_functions_are_located(old, new, where, words) -> None:
    with pytest.raises(InputError) as info:
        load_text(PRESCRIBED.replace(old, new, 1), "p.yaml")
    assert words in info.value.message
    assert (info.value.location.line, info.value.location.column) == where


FRAMES = """\
parameters: {m: mass, l: length, w: rate}
prescribed: {y_A: unknown}
coordinates: [phi]
frames:
  support: {origin: A}
  turning: {axis: z, rate: w}
points:
  A: [0, y_A]
  B: A + l * [sin(phi), -cos(phi)]
bodies:
  bob: {shape: particle, mass: m, at: B}
questions:
  - eom: {frames: [support, turning]}
  - equilibria: {frame: turning}
"""


def test_frames_load() -> None:
    problem = load_text(FRAMES, "p.yaml")
    assert [f.name for f in problem.frames] == ["support", "turning"]
    assert problem.questions[0].options.frames == ("support", "turning")
    assert problem.questions[1].options.frame == "turning"


@pytest.mark.parametrize(
    "old, new, where, path, words",
    [
        ("frames: [support, turning]", "frames: [support, turnin]", (13, 29), "questions[0].eom.frames[1]",
         "no frame 'turnin' (did you mean 'turning'?)"),
        ("{frame: turning}", "{frame: hoop}", (14, 25), "questions[1].equilibria.frame",
         "no frame 'hoop' (frames: support, turning)"),
        ("{axis: z, rate: w}", "{axis: z}", (6, 12), "frames.turning", "needs both 'axis' and 'rate'"),
        ("rate: w}", "rate: w*t}", (6, 30), "frames.turning.rate", "'t' cannot appear here: a rate of turning"),
        ("{origin: A}", "{origin: Q}", (5, 21), "frames.support.origin", "unknown point 'Q'"),
        ("{origin: A}", "{orign: A}", (5, 13), "frames.support.orign", "unknown key 'orign'"),
    ],
)
def test_bad_frames_are_located(old, new, where, path, words) -> None:
    with pytest.raises(InputError) as info:
        load_text(FRAMES.replace(old, new, 1), "p.yaml")
    assert words in info.value.message
    assert info.value.location.key_path() == path
    assert (info.value.location.line, info.value.location.column) == where


def test_steady_spin_names_its_body() -> None:
    text = """\
parameters: {m: mass, a: side}
bodies:
  box: {shape: box, mass: m, width: a, depth: a, height: a, at: [0, 0, 0]}
  ball: {shape: sphere, mass: m, radius: a, at: [0, 0, 0]}
questions:
  - steady_spin: {body: bx}
"""
    with pytest.raises(InputError) as info:
        load_text(text, "p.yaml")
    assert "no body 'bx' (did you mean 'box'?)" in info.value.message
    assert (info.value.location.line, info.value.location.column) == (6, 25)
    with pytest.raises(InputError, match="'steady_spin' needs 'body: NAME' when the scene has 2 bodies"):
        load_text(text.replace("  - steady_spin: {body: bx}", "  - steady_spin"), "p.yaml")


ORIENTED = """\
parameters: {m: mass, r: radius, w: rate, theta: tilt}
unknowns: [spin]
triads:
  T: {turns: [[z, w*t], [y, -theta]], vectors: [e1, e2, e3]}
points:
  G: r*e3
bodies:
  ring: {shape: ring, mass: m, radius: r, at: G, axis: x, orientation: [T, [x, spin*t]]}
questions:
  - steady_motion: {about: G, solve_for: spin}
"""


def test_triads_and_orientations_load() -> None:
    problem = load_text(ORIENTED, "p.yaml")
    assert problem.unknowns == ("spin",)
    space = load_text(ORIENTED.replace("turns: [[z, w*t], [y, -theta]]", "space_turns: [[y, -theta], [z, w*t]]"),
                      "p.yaml")
    assert [t.axis.text for t in space.triads[0].turns] == ["z", "y"]  # stored body-fixed, reversed
    assert problem.triads[0].vectors == ("e1", "e2", "e3")
    assert problem.bodies[0].orientation[0] == "T"


@pytest.mark.parametrize(
    "old, new, where, words",
    [
        ("orientation: [T, [x, spin*t]]", "orientation: [[x, spin*t], T]", (8, 86),
         "the triad 'T' may only come first"),
        ("orientation: [T, [x, spin*t]]", "orientation: [S, [x, spin*t]]", (8, 73),
         "'S' is not a triad here (triads: T)"),
        ("[[z, w*t], [y, -theta]]", "[[z], [y, -theta]]", (4, 15), "expected a turn [axis, angle]"),
        ("vectors: [e1, e2, e3]", "vectors: [e1, e2]", (4, 48), "the three unit vectors"),
        ("{turns: [[z, w*t], [y, -theta]], ", "{", (4, 6), "give either 'turns'"),
        ("{turns: [[z, w*t], [y, -theta]], ", "{turns: [[z, w*t]], space_turns: [[y, -theta]], ", (4, 39),
         "give either 'turns'"),
        ("vectors: [e1, e2, e3]", "vectors: [e1, e2, m]", (4, 57), "'m' is already declared as a parameter"),
        ("at: G, axis: x, orientation", "at: G, angle: w*t, orientation", (8, 57),
         "give either 'orientation' (3D turns) or 'angle'"),
        ("{about: G, solve_for: spin}", "{solve_for: spin}", (10, 5), "needs 'about: POINT'"),
        ("{about: G, solve_for: spin}", "{about: G, triad: S}", (10, 38), "no triad 'S' (triads: T)"),
        ("{about: G, solve_for: spin}", "{about: G, reactions: {at: G}}", (10, 42), "expected a list of reactions"),
        ("{about: G, solve_for: spin}", "{about: G, reactions: [{at: G}]}", (10, 43), "missing required key 'force'"),
        ("{about: G, solve_for: spin}", "{about: G, reactions: [{at: H, force: m*e3}]}", (10, 48),
         "unknown point 'H'"),
        ("{about: G, solve_for: spin}", "{about: G, reactions: [{at: G, force: m}]}", (10, 58), "a force vector"),
        ("{about: G, solve_for: spin}", "{about: G, rolling_at: [G, H]}", (10, 47), "unknown point 'H'"),
        ("{about: G, solve_for: spin}", "{about: G, solve_for: [spin, t]}", (10, 49), "must be constant"),
    ],
)
def test_bad_orientations_are_located(old, new, where, words) -> None:
    with pytest.raises(InputError) as info:
        load_text(ORIENTED.replace(old, new, 1), "p.yaml")
    assert words in info.value.message
    assert (info.value.location.line, info.value.location.column) == where


def test_values_take_ranges_and_choices_kept_apart_from_numbers() -> None:
    from fractions import Fraction

    from rbdsolve.problem import load_text

    problem = load_text("""
parameters: {m: mass, l: length, g: gravity}
values: {m: 2, l: {range: [0.5, 2], step: 0.4}, g: {choices: [9.81, 10]}}
coordinates: [theta]
gravity: [0, -g]
points: {P: "l * [sin(theta), -cos(theta)]"}
bodies: {bob: {shape: particle, mass: m, at: P}}
questions: [eom]
""")
    assert [(name, v.rational) for name, v in problem.values] == [("m", Fraction(2))]
    length, gravity = problem.ranges
    assert length.size == 4 and [length.value(k).rational for k in range(4)] == [
        Fraction(1, 2), Fraction(9, 10), Fraction(13, 10), Fraction(17, 10)]
    assert gravity.size == 2 and gravity.value(0).rational == Fraction(981, 100)


# A steady motion's rate written among the parameters and as the unknown a question
# solves for (a new user's first try at a conical pendulum): the message says the mend.
def test_an_unknown_also_declared_a_parameter_says_to_take_it_out() -> None:
    text = "parameters: {m: mass, Omega: rate}\nunknowns: [Omega]\ncoordinates: [theta]\nquestions: [eom]\n"
    with pytest.raises(InputError) as caught:
        load_text(text, "cone.yaml")
    assert "unknowns[0]: 'Omega' is already declared as a parameter (an unknown is what a question solves for: " \
           "take it out of 'parameters')" in str(caught.value)
    assert (caught.value.location.line, caught.value.location.column) == (2, 12)
