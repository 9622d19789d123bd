"""The gyroscopic route's choice from the structure: about a steady state that holds a
root of the parameters (a rate pasted from steady_motion's quadratic), the exact route
would spend a minute on nested radicals, so the numeric route answers at once, with
the parameters' values put in before the linearization."""

from pathlib import Path

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.solvers.modes.exact import partial
from rbdsolve.solvers.modes.routh import RADICAL_STEADY, slow_steady_state
from rbdsolve.solvers import Options, RouteChoice, solve_question

SPIN = Path(__file__).resolve().parents[3] / "problems" / "spin"


def _question_and_model(name: str):
    model = build_model(load_file(SPIN / name))
    return model.problem.questions[0], model


def test_a_steady_rate_with_a_root_of_the_parameters_sends_the_question_to_the_numeric_route():
    question, model = _question_and_model("disk-on-tilted-axle-nutation.yaml")
    assert slow_steady_state(question, model) == RADICAL_STEADY
    assert partial(question, model) == RADICAL_STEADY


def test_a_steady_state_of_plain_parameters_keeps_the_exact_route():
    question, model = _question_and_model("sleeping-top.yaml")
    assert slow_steady_state(question, model) is None
    assert partial(question, model) is None


def test_the_numeric_route_with_the_values_put_in_first_gives_the_hand_s_nutation():
    question, model = _question_and_model("disk-on-tilted-axle-nutation.yaml")
    solution = solve_question(question, model, Options(route=RouteChoice.NUMERIC))
    # ω² = U''(θ₀)/A from Routh's effective potential, by hand (the .expected.yaml)
    assert abs(solution.answers.frequencies[0] - 19.8616958953801) < 1e-9


def test_the_numeric_route_names_its_exponent_apart_from_a_spin_named_s():
    # The sleeping top's spin is the parameter s: u = X e^(st) would read as the spin.
    question, model = _question_and_model("sleeping-top.yaml")
    solution = solve_question(question, model, Options(route=RouteChoice.NUMERIC))
    texts = [step.text for step in solution.steps]
    assert any("e^(pt) gives (p²M + pG_q + K) X = 0" in text for text in texts)
    assert not any("e^(st)" in text for text in texts)
