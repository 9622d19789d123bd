"""The kinematics route chosen from the structure: a point placed by a long root of the
coordinates (a four-bar's B, where two circles meet) goes to the floating-point route,
the values put in before anything is differentiated out; short ones stay exact."""

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.solvers.kinematics.exact import partial


def _first(path):
    model = build_model(load_file(PROBLEMS / path))
    return model.problem.questions[0], model


def test_a_four_bar_s_coupler_point_goes_to_the_numeric_route():
    question, model = _first("kinematics/four-bar-coupler.yaml")
    assert "point 'B' is placed by a root of the coordinates" in partial(question, model)


def test_a_double_pendulum_s_tip_stays_exact():
    question, model = _first("kinematics/double-pendulum-tip.yaml")
    assert partial(question, model) is None
