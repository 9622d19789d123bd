"""Values as exams write them, through the command line: --set takes pi/6 and 30 cm,
answers print their SI unit in text and JSON (``units`` beside ``values``)."""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner

from conftest import ROD_PENDULUM
from rbdsolve.cli import main

ROD = ("title: Rod pendulum\nvalues: {m: 200 g, l: 30 cm, g: 9.81 m/s^2}\n" + ROD_PENDULUM
       + "questions:\n  - modes: {about: {theta: 0}}\n  - inertia: {body: rod, about: [0, 0]}\n")


@pytest.fixture()
def rod(tmp_path):
    path = tmp_path / "rod.yaml"
    path.write_text(ROD)
    return path


def test_answers_carry_their_si_units(rod) -> None:
    result = CliRunner().invoke(main, ["solve", "-f", "json", str(rod)])
    assert result.exit_code == 0, result.output
    report = json.loads(result.output)
    modes, inertia = report["results"]
    # By hand: M = m l²/3, K = m g l/2, λ = 3g/(2l) = 3·9.81/0.6 = 49.05 1/s², ω = √λ.
    assert modes["values"]["eigenvalues"] == pytest.approx([49.05], rel=1e-12)
    assert modes["units"]["eigenvalues"] == ["1/s²"] and modes["units"]["frequencies"] == ["rad/s"]
    assert modes["units"]["M"] == [["kg·m²"]] and modes["units"]["K"] == [["J"]]
    # J about the pivot = m l²/3 = 0.2·0.09/3 = 0.006 kg·m², about z.
    assert inertia["values"]["J"][2][2] == pytest.approx(0.006, rel=1e-12)
    assert inertia["units"]["J"][2][2] == "kg·m²" and inertia["units"]["mass"] == "kg"
    assert report["parameter_units"] == {"m": "kg", "l": "m", "g": "m/s²"}
    text = CliRunner().invoke(main, ["solve", str(rod)]).output
    assert f"frequencies = [{math.sqrt(49.05):.6g}] rad/s" in text and "m = 0.2 kg" in text


def test_set_takes_exact_values_and_units(rod) -> None:
    result = CliRunner().invoke(main, ["solve", "-f", "json", str(rod), "--set", "l=60 cm", "--set", "g=pi**2"])
    assert result.exit_code == 0, result.output
    (modes, _) = json.loads(result.output)["results"]
    assert modes["values"]["eigenvalues"] == pytest.approx([3 * math.pi**2 / 1.2], rel=1e-12)


@pytest.mark.parametrize("setting, message", [
    ("m=2 m", "--set m: 'm' is a mass (in "),
    ("l=30 cmm", "--set l: unknown unit 'cmm'"),
    ("m=-1 kg", "--set m: the parameter is positive, found -1 kg"),
])
def test_set_refuses_a_unit_that_does_not_fit(rod, setting, message) -> None:
    result = CliRunner().invoke(main, ["solve", str(rod), "--set", setting])
    assert result.exit_code == 2 and message in result.output, result.output


def test_pint_is_loaded_only_for_a_file_with_units(tmp_path) -> None:
    import subprocess
    import sys

    plain = tmp_path / "plain.yaml"
    plain.write_text(ROD.replace("{m: 200 g, l: 30 cm, g: 9.81 m/s^2}", "{m: 1/5, l: 3/10, g: 9.81}"))
    code = ("import sys; from click.testing import CliRunner; from rbdsolve.cli import main; "
            f"r = CliRunner().invoke(main, ['check', {str(plain)!r}]); print(r.exit_code, 'pint' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["0", "False"]
