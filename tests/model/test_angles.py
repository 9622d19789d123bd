"""Which parameters are angles (model/angles.py), for how an open one is noted beside an
answer that holds it: in rad, as every angle is read (a new user's trial: "θ₀ in SI
units"). Another parameter whose own unit is not known stays "in SI units"."""

from __future__ import annotations

from click.testing import CliRunner

from conftest import DISK_IN_TRACK, PROBLEMS
from rbdsolve.cli import main
from rbdsolve.model.angles import angle_parameters
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text

RELEASED = DISK_IN_TRACK.replace("[m, r, R, g]", "[m, r, R, g, theta0, v]") + """\
values: {m: 1, r: 0.08, R: 0.5, g: 9.81}
questions:
  - reactions: {forces: [C], from_rest: {theta: theta0}}
"""


def _text(tmp_path, text: str) -> str:
    path = tmp_path / "scene.yaml"
    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(main, ["solve", str(path)]).stdout


def test_a_release_angle_and_an_incline_s_angle_are_angles_and_a_speed_is_not() -> None:
    model = build_model(load_text(RELEASED, "scene.yaml"))
    assert angle_parameters(model, frozenset({"theta0", "v", "m"})) == {"theta0"}
    incline = (PROBLEMS / "contacts" / "half-disk-on-incline.yaml").read_text(encoding="utf-8")
    assert angle_parameters(build_model(load_text(incline, "p.yaml")), frozenset({"beta", "R"})) == {"beta"}


def test_an_open_release_angle_is_noted_in_rad(tmp_path) -> None:
    text = _text(tmp_path, RELEASED)
    assert "N_C = 9.81 cos(θ₀) (in N, θ₀ in rad)" in text and "in SI units" not in text


def test_an_open_incline_angle_is_noted_in_rad_and_a_state_s_speed_in_m_per_s(tmp_path) -> None:
    """The disk's speed v is the state's dot(x), x a length: m/s (it read "SI units" before
    a state's rate took its coordinate's rate's unit)."""
    half = (PROBLEMS / "contacts" / "half-disk-on-incline.yaml").read_text(encoding="utf-8")
    assert "(in 1/s², β in rad)" in _text(tmp_path, half)
    spring = (PROBLEMS / "forces" / "disk-on-incline-spring.yaml").read_text(encoding="utf-8")
    text = _text(tmp_path, spring)
    assert "(in m/s, v in m/s)" in text and "in SI units" not in text
