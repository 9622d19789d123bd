"""Solutions print their own labels apart from the problem's names (solvers/routes/labels.py,
form/labels.py); the JSON keys stay as documented."""

from __future__ import annotations

import json
import re

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

CLASH = """\
title: Names that clash
parameters: {m: mass, M: cart mass, a: length, K: stiffness, omega: a rate, g: gravity}
coordinates: [x, theta]
gravity: [0, -g]
points:
  O: [0, 0]
  C: [x, 0]
  P: C + a * [sin(theta), -cos(theta)]
bodies:
  cart: {shape: particle, mass: M, at: C}
  bob: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: K, between: [O, C], natural_length: 0}
questions:
  - equilibria
  - modes: {about: {x: 0, theta: 0}}
"""

DUMBBELL = """\
title: A dumbbell
parameters: {m: mass of a ball, m_a: mass of the bar, l: length, r: radius}
points:
  O: [0, 0, 0]
bodies:
  dumbbell:
    at: O
    parts:
      bar: {shape: rod, mass: m_a, length: l}
      left: {shape: sphere, mass: m, radius: r, at: [-l/2, 0, 0]}
      right: {shape: sphere, mass: m, radius: r, at: [l/2, 0, 0]}
questions:
  - inertia: {body: dumbbell, about: O}
"""


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("labels")
    (folder / "clash.yaml").write_text(CLASH, encoding="utf-8")
    (folder / "dumbbell.yaml").write_text(DUMBBELL, encoding="utf-8")
    text = CliRunner().invoke(main, ["solve", str(folder / "clash.yaml"), str(folder / "dumbbell.yaml"), "-q"])
    data = CliRunner().invoke(main, ["solve", str(folder / "clash.yaml"), "-f", "json"])
    assert text.exit_code == 0 and data.exit_code == 0, text.output
    return text.stdout, json.loads(data.stdout)


def test_the_mass_and_stiffness_matrices_beside_parameters_m_and_k(outputs) -> None:
    text, _ = outputs
    assert "M_q u\u0308 + K_q u = 0" in text and "\n    M_q = [[M + m, a m], [a m, a² m]]" in text
    assert "\n    K_q = [[K, 0], [0, a g m]]" in text
    assert "the Hessian K_q = ∂²V/∂q∂q" in text and "Hessian K =" not in text


def test_the_amplitudes_beside_a_length_a_and_the_frequency_beside_a_rate(outputs) -> None:
    text, _ = outputs
    assert "u = X cos(ωₖ t)" in text and "\n    X₁ = (1, " in text and "\n    a₁" not in text
    assert "an oscillation at ωₖ = √λₖ with amplitudes X:" in text and "\n    ω₁ = " in text


def test_a_composite_mass_is_not_labelled_like_its_parts(outputs) -> None:
    text, _ = outputs
    assert "\n    M = 2 m + mₐ" in text and "\n    m = 2 m" not in text


def test_json_keys_stay_as_documented(outputs) -> None:
    _, data = outputs
    modes = data["results"][1]["answers"]
    assert {"M", "K", "characteristic", "eigenvalues", "frequencies", "shapes"} <= set(modes)
    assert "lamda" in modes["characteristic"]


def test_a_bodys_angular_velocity_beside_an_unknown_rate_named_omega() -> None:
    """The rolling coin with its spin called omega: the body's angular velocity is ω_b."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.render.terminal import step_lines
    from rbdsolve.solvers import solve_problem

    from conftest import PROBLEMS

    text = (PROBLEMS / "steady" / "rolling-coin.yaml").read_text(encoding="utf-8")
    text = re.sub(r"\bspin\b", "omega", text)
    (solution,) = solve_problem(build_model(load_text(text, "coin.yaml"))).solutions
    lines = [line.plain if hasattr(line, "plain") else line.text for s in solution.steps for line in step_lines(s)]
    assert any(line.startswith("ω_b = ") for line in lines) and not any(line.startswith("ω = (") for line in lines)
    assert any("v_G + ω_b × (r_C − r_G) = 0" in line for line in lines)


def test_the_angular_momentum_moves_off_a_parameter_named_l() -> None:
    from rbdsolve.form.labels import Labels

    assert Labels.of(("m", "r"), ("angular_momentum",)).name("angular_momentum") == "L"
    assert Labels.of(("m", "L", "r"), ("angular_momentum",)).name("angular_momentum") == "H"
