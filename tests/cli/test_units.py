"""Values as exams write them, through the command line: --set takes pi/6 and 30 cm,
answers print their SI unit in text and JSON (``units`` beside ``values``)."""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner

from conftest import PROBLEMS, ROD_PENDULUM
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
    assert modes["units"]["M"] == [["kg·m²"]] and modes["units"]["K"] == [["N·m/rad"]]
    # J about the pivot = m l²/3 = 0.2·0.09/3 = 0.006 kg·m², about z.
    assert inertia["values"]["J"][2][2] == pytest.approx(0.006, rel=1e-12)
    assert inertia["units"]["J"][2][2] == "kg·m²" and inertia["units"]["mass"] == "kg"
    assert report["parameter_units"] == {"m": "kg", "l": "m", "g": "m/s²"}
    text = CliRunner().invoke(main, ["solve", str(rod)]).output
    assert f"ω₁ = {math.sqrt(49.05):.6g} rad/s" in text and "m = 0.2 kg" in text


def test_set_takes_exact_values_and_units(rod) -> None:
    result = CliRunner().invoke(main, ["solve", "-f", "json", str(rod), "--set", "l=60 cm", "--set", "g=pi**2"])
    assert result.exit_code == 0, result.output
    (modes, _) = json.loads(result.output)["results"]
    assert modes["values"]["eigenvalues"] == pytest.approx([3 * math.pi**2 / 1.2], rel=1e-12)


@pytest.mark.parametrize("setting, message", [
    ("m=2 m", "--set m: 'm' is a mass (in "),
    ("l=30 cmm", "--set l: unknown unit 'cmm'"),
    ("m=-1 kg", "--set m: the parameter is positive, found -1 kg"),
    # issue 39: an overflow, not "not a real number"; a number out of range, not "unknown unit 'e999'"
    ("l=1e300 ly", "--set l: the number 1e300 ly is too large (the limit is 1e300)"),
    ("l=1e999 m", "--set l: the number 1e999 is out of range (the limit is 1e±300)"),
    ("l=1 m**0.5", "--set l: the power 0.5 of a unit is refused: a unit's power is a whole number"),
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


def test_the_numeric_route_carries_units_too(tmp_path) -> None:
    """Floats have no expression to read: a coordinate's value takes the coordinate's
    unit, λ 1/s², ω rad/s, M_ij J·s²/(q_i q_j) and K_ij J/(q_i q_j) (θ an angle: kg·m², J)."""
    path = tmp_path / "rod.yaml"
    path.write_text(ROD.replace("  - inertia: {body: rod, about: [0, 0]}\n", ""))
    result = CliRunner().invoke(main, ["solve", "-f", "json", "--route", "numeric", str(path)])
    assert result.exit_code == 0, result.output
    (modes,) = json.loads(result.output)["results"]
    assert modes["route"] == "numeric" and modes["values"]["eigenvalues"] == pytest.approx([49.05], rel=1e-10)
    assert modes["units"]["about"] == {"theta": "rad"}
    assert modes["units"]["eigenvalues"] == ["1/s²"] and modes["units"]["frequencies"] == ["rad/s"]
    assert modes["units"]["M"] == [["kg·m²"]] and modes["units"]["K"] == [["N·m/rad"]]


def test_a_coordinate_at_zero_keeps_its_unit(tmp_path) -> None:
    """θ = 0 is an angle too (it had no unit: 0 has no dimension of its own)."""
    path = tmp_path / "rod.yaml"
    path.write_text(ROD.replace("  - modes: {about: {theta: 0}}\n", "  - equilibria\n"))
    equilibria, _ = json.loads(CliRunner().invoke(main, ["solve", "-f", "json", str(path)]).output)["results"]
    by_place = {round(eq["at"]["theta"], 9): unit["at"]["theta"]
                for eq, unit in zip(equilibria["values"]["equilibria"], equilibria["units"]["equilibria"])}
    assert by_place == {0.0: "rad", round(math.pi, 9): "rad"}


def test_an_answer_key_prints_si_units(tmp_path) -> None:
    """A Markdown key of two problems with values in units (problems/impact/bullet-…,
    problems/units/hoop-…); the numbers by hand: ω = 3 m v0/((M + 3m) l), the pivot's
    impulse (m M v0/(2(M + 3m)), m v1), T_i = m (v0² + v1²)/2; the hoop's bead about
    cos θ = g/(Ω² R): ω² = (Ω⁴ R² − g²)/(Ω² R²) at Ω = 60 rev/min = 2π rad/s, R = 0.5 m."""
    key = tmp_path / "key.md"
    files = [PROBLEMS / "impact" / "bullet-embeds-in-hanging-rod.yaml", PROBLEMS / "units" / "hoop-rev-per-min.yaml"]
    result = CliRunner().invoke(main, ["key", *map(str, files), "-o", str(key), "--no-figures"])
    assert result.exit_code == 0, result.output
    text = key.read_text(encoding="utf-8")
    M, l, m, v0, v1, g, R, W = 4, 1.2, 0.02, 300, 40, 9.81, 0.5, 2 * math.pi
    assert f"$\\dot{{\\theta}}_{{f}} = {3 * m * v0 / ((M + 3 * m) * l):.6g}$ rad/s" in text
    assert (f"$P_{{\\mathrm{{supports}}}} = \\begin{{pmatrix}} {m * M * v0 / (2 * (M + 3 * m)):.6g} \\\\ "
            f"{m * v1:.6g} \\\\ 0 \\end{{pmatrix}}$ N·s") in text
    assert f"$T_{{i}} = {m * (v0**2 + v1**2) / 2:.6g}$ J" in text
    assert f"$\\omega_{{1}} = {math.sqrt((W**4 * R**2 - g**2) / (W**2 * R**2)):.6g}$ rad/s" in text
    assert "  - $\\theta = 0$ rad" in text


@pytest.mark.parametrize("route", ["exact", "numeric"])
def test_a_state_and_a_point_carry_units_on_both_routes(route) -> None:
    """problems/kinematics/double-pendulum-tip.yaml: θ, φ angles (rad, rad/s, rad/s²), B's
    position, velocity, acceleration in m, m/s, m/s², a distance in m; values by hand."""
    path = PROBLEMS / "kinematics" / "double-pendulum-tip.yaml"
    result = CliRunner().invoke(main, ["solve", "-f", "json", "--route", route, str(path)])
    assert result.exit_code == 0, result.output
    (kinematics,) = json.loads(result.output)["results"]
    units, values = kinematics["units"], kinematics["values"]
    assert units["at"] == {"theta": "rad", "phi": "rad", "dot(theta)": "rad/s", "dot(phi)": "rad/s",
                           "ddot(theta)": "rad/s²", "ddot(phi)": "rad/s²"}
    (point,) = units["points"]
    assert (point["position"], point["velocity"], point["acceleration"]) == (["m"] * 3, ["m/s"] * 3, ["m/s²"] * 3)
    assert units["distances"][0]["distance"] == "m"
    assert values["points"][0]["velocity"][:2] == pytest.approx([0.8, -0.3], rel=1e-12)  # (a p, b s)


def test_inertia_numbers_carry_units_on_the_numeric_route() -> None:
    """problems/inertia/door-at-configuration.yaml: J and J_axis in kg·m², the mass in kg."""
    path = PROBLEMS / "inertia" / "door-at-configuration.yaml"
    result = CliRunner().invoke(main, ["solve", "-f", "json", "--route", "numeric", str(path)])
    (inertia,) = json.loads(result.output)["results"]
    assert inertia["units"]["J"] == [["kg·m²"] * 3] * 3 and inertia["units"]["J_axis"] == "kg·m²"
    assert inertia["units"]["mass"] == "kg"
    assert inertia["values"]["J_axis"] == pytest.approx(12 * 0.64 * 4 / (6 * 4.64), rel=1e-12)  # m b²h²/(6(b² + h²))


@pytest.mark.parametrize("name, where", [
    ("edges/inverted-rod-stiff-spring.yaml", 0),  # declared {kind: angle, periodic: false}
    ("examples/pendulum-torsion-spring.yaml", 1),  # undeclared: the rod turns by θ (modes, question 2)
])
def test_an_angle_a_spring_winds_up_is_in_radians(name, where) -> None:
    """θ held bare by a torsional spring is not periodic, but it is an angle all the same."""
    result = CliRunner().invoke(main, ["solve", "-f", "json", str(PROBLEMS / name)])
    units = json.loads(result.output)["results"][where]["units"]
    assert (units["equilibria"][0]["at"] if "equilibria" in units else units["about"]) == {"theta": "rad"}


def test_a_value_given_with_set_decides_what_the_same_value_in_the_file_would(tmp_path) -> None:
    """Which side of the axle the string leaves from depends on the sign of cos α: a value
    decides it, under ``values:`` or given with --set alike (the model is built from them)."""
    text = (PROBLEMS / "forces" / "spool-pulled-off-top.yaml").read_text()
    line = next(x for x in text.splitlines() if x.startswith("values:"))
    path = tmp_path / "spool.yaml"
    path.write_text(text.replace(line + "\n", ""))
    unset = CliRunner().invoke(main, ["solve", "-f", "json", str(path)])
    assert unset.exit_code == 2 and "sign of cos(α)" in unset.output
    sets = [x for pair in (("--set", v) for v in ("m=2 kg", "R=10 cm", "r=5 cm", "k=8 cm", "F=10 N",
                                                   "alpha=30 deg", "g=9.81 m/s^2")) for x in pair]
    result = CliRunner().invoke(main, ["solve", "-f", "json", str(path), *sets])
    assert result.exit_code == 0, result.output
    eom, reactions = json.loads(result.output)["results"]
    # By hand, moments about the contact: m (k² + R²) a/R = F (r + R cos α); N = m g − F sin α.
    m, R, r, k, F, alpha, g = 2, 0.1, 0.05, 0.08, 10, math.pi / 6, 9.81
    a = F * R * (r + R * math.cos(alpha)) / (m * (k**2 + R**2))
    assert eom["values"]["accelerations"]["x"] == pytest.approx(a, rel=1e-12)
    components = reactions["values"]["reactions"]["C"]["components"]
    assert components["N_C"] == pytest.approx(m * g - F * math.sin(alpha), rel=1e-12)
    assert components["F_C"] == pytest.approx(F * math.cos(alpha) - m * a, rel=1e-12)



GYROSCOPE = """title: a gyroscope on a horizontal axle with a counterweight
parameters: {m: mass, r: radius, L: length, M: mass, b: distance, g: gravity, s: spin}
values: {m: 2 kg, r: 6 cm, L: 12 cm, M: 0.5 kg, g: 9.81 m/s^2, s: 3000 rev/min}
unknowns: [Omega]
gravity: [0, 0, -g]
triads:
  T: {turns: [[z, Omega*t], [x, pi/2]], vectors: [e1, e2, e3]}
bodies:
  gyro:
    at: [0, 0, 0]
    orientation: [T, [z, s*t]]
    parts:
      disk: {shape: disk, mass: m, radius: r, at: [0, 0, L]}
      weight: {shape: particle, mass: M, at: [0, 0, -b]}
questions:
  - steady_motion: {about: [0, 0, 0], solve_for: Omega}
"""


def test_a_unit_given_with_set_makes_the_answer_s_unit_known(tmp_path) -> None:
    """b, the counterweight's distance, has a dimension only from its value: --set
    b="10 cm" gives it one as 'values: {b: 10 cm}' does, so the steady precession
    Ω = 2 g (L m − M b)/(m r² s) (the moment balance about O, by hand) = 2·9.81·(0.24 −
    0.05)/(2·0.0036·100π) = 1.64805 prints in rad/s (it printed a bare number)."""
    path = tmp_path / "gyro.yaml"
    path.write_text(GYROSCOPE)
    out = CliRunner().invoke(main, ["solve", str(path), "--set", "b=10 cm"])
    assert out.exit_code == 0, out.output
    omega = 2 * 9.81 * (0.24 - 0.05) / (2 * 0.0036 * 100 * math.pi)
    assert f"Ω = {omega:.6g} rad/s" in out.output
