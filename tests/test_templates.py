"""``rbdsolve new KIND`` and its templates: one per question kind, each a working
problem whose answers agree with a derivation by hand (written out below, never taken
from rbdsolve's output), plus the command's own behaviour and shell completion."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from functools import cache
from importlib import resources

import pytest
import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.cli.new import KINDS
from rbdsolve.problem.schema import QuestionKind

from conftest import ROOT, same


def run(*args: str, env: dict[str, str] | None = None):
    return CliRunner().invoke(main, list(args), prog_name="rbdsolve", env=env)


def template_path(kind: str) -> str:
    return str(resources.files("rbdsolve") / "templates" / f"{kind}.yaml")


@cache
def solved(kind: str) -> dict:
    """The JSON report of a template, solved once for all the tests that read it."""
    result = run("solve", template_path(kind), "--format", "json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def answers(kind: str) -> dict:
    (only,) = solved(kind)["results"]
    return only["answers"]


def same_all(got: list, expected: list) -> bool:
    """Element by element, at any depth of nesting (vectors, matrices)."""
    if isinstance(expected, list):
        return len(got) == len(expected) and all(same_all(g, e) for g, e in zip(got, expected))
    return same(got, expected)


# --- the command ---------------------------------------------------------------------


def test_there_is_one_template_per_question_kind() -> None:
    assert list(KINDS) == [k.value for k in QuestionKind]
    for kind in KINDS:
        assert resources.files("rbdsolve").joinpath("templates", f"{kind}.yaml").is_file()


@pytest.mark.parametrize("kind", list(KINDS))
def test_template_passes_check_and_solves(kind: str, tmp_path) -> None:
    path = tmp_path / f"{kind}.yaml"
    written = run("new", kind, "-o", str(path))
    assert written.exit_code == 0, written.output
    checked = run("check", str(path))
    assert checked.exit_code == 0 and f"ok ({kind})" in checked.output, checked.output
    report = solved(kind)
    assert report["ok"] and report["results"][0]["question"] == kind
    text = path.read_text(encoding="utf-8")
    assert "title:" in text and "statement:" in text and text.count("\n#") >= 5  # commented


@pytest.mark.parametrize("kind", list(KINDS))
def test_stdout_is_the_text_of_the_file(kind: str, tmp_path) -> None:
    path = tmp_path / "p.yaml"
    assert run("new", kind, "-o", str(path)).exit_code == 0
    printed = run("new", kind)
    assert printed.exit_code == 0
    assert printed.stdout == path.read_text(encoding="utf-8")


def test_new_refuses_to_overwrite_without_force(tmp_path) -> None:
    path = tmp_path / "mine.yaml"
    path.write_text("my own problem\n", encoding="utf-8")
    refused = run("new", "modes", "-o", str(path))
    assert refused.exit_code == 2
    assert f"{path} already exists; use --force to overwrite it" in refused.stderr
    assert path.read_text(encoding="utf-8") == "my own problem\n"
    forced = run("new", "modes", "-o", str(path), "--force")
    assert forced.exit_code == 0
    assert path.read_text(encoding="utf-8") == run("new", "modes").stdout


def test_list_and_help_name_every_kind() -> None:
    listing = run("new", "--list")
    assert listing.exit_code == 0
    from rbdsolve.cli.new import SCENES

    assert [line.split()[0] for line in listing.stdout.splitlines()] == [*KINDS, *SCENES]
    helped = run("new", "--help")
    assert all(kind in helped.stdout for kind in KINDS)
    assert "rbdsolve new modes -o my-problem.yaml && rbdsolve solve my-problem.yaml" in helped.stdout


def test_a_missing_or_unknown_kind_is_a_usage_error() -> None:
    assert run("new").exit_code == 2
    unknown = run("new", "mode")
    assert unknown.exit_code == 2 and "'mode' is not one of" in unknown.output


def test_new_loads_no_sympy() -> None:
    """A fresh interpreter: the command must stay instant (no algebra, no YAML)."""
    code = ("import sys; from rbdsolve.cli import main\n"
            "try: main(['new', 'eom'], standalone_mode=False)\n"
            "finally: print('sympy' in sys.modules, 'yaml' in sys.modules, file=sys.stderr)")
    done = subprocess.run([sys.executable, "-c", code], check=False, capture_output=True,
                          text=True, cwd=ROOT, env={"PYTHONPATH": str(ROOT)}, timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stderr.strip() == "False False"


@pytest.mark.parametrize(("words", "cword", "expected"), [
    ("rbdsolve ne", "1", "plain,new"),
    ("rbdsolve new steady_", "2", "plain,steady_spin\nplain,steady_motion"),
])
def test_bash_completion(words: str, cword: str, expected: str) -> None:
    env = {"_RBDSOLVE_COMPLETE": "bash_complete", "COMP_WORDS": words, "COMP_CWORD": cword}
    assert run(env=env).stdout.strip() == expected


@pytest.mark.parametrize("shell", ["bash", "zsh", "fish"])
def test_completion_scripts(shell: str) -> None:
    script = run(env={"_RBDSOLVE_COMPLETE": f"{shell}_source"}).stdout
    assert "_RBDSOLVE_COMPLETE" in script and "rbdsolve" in script


# --- the answers, against derivations by hand ----------------------------------------


def test_eom_rolling_wheel_with_pendulum() -> None:
    """C = (x, r), the disk turns at -x'/r: T_disk = M x'^2/2 + (M r^2/2)(x'/r)^2/2 = 3/4 M x'^2.
    P = C + l (sin θ, -cos θ): v_P = (x' + l cos θ θ', l sin θ θ').
    V = M g r + m g (r - l cos θ) + k x^2/2. Lagrange:
      x: d/dt[(3M/2 + m) x' + m l cos θ θ'] + k x
      θ: d/dt[m l cos θ x' + m l^2 θ'] + m l sin θ x' θ' + m g l sin θ."""
    xd, xdd = "Derivative(x(t), t)", "Derivative(x(t), (t, 2))"
    td, tdd = "Derivative(theta(t), t)", "Derivative(theta(t), (t, 2))"
    model = solved("eom")["model"]
    assert same(model["T"], f"3*M*{xd}**2/4 + m*({xd}**2 + 2*l*cos(theta(t))*{xd}*{td} + l**2*{td}**2)/2")
    assert same(model["V"], "M*g*r + m*g*(r - l*cos(theta(t))) + k*x(t)**2/2")
    assert same_all(answers("eom")["equations"], [
        f"(3*M/2 + m)*{xdd} + m*l*cos(theta(t))*{tdd} - m*l*sin(theta(t))*{td}**2 + k*x(t)",
        f"m*l*cos(theta(t))*{xdd} + m*l**2*{tdd} + m*g*l*sin(theta(t))",
    ])


def test_equilibria_sliding_ladder() -> None:
    """A = (2a sin θ, 0), G = a (sin θ, cos θ): V = m g a cos θ + 2 k a^2 sin^2 θ,
    V' = a sin θ (4 k a cos θ - m g) = 0: θ = 0, π, ±acos(m g/(4 k a)) (4 k a > m g at the
    values). V'' = -m g a cos θ + 4 k a^2 cos 2θ: a (4ka - mg) > 0 at 0, a (4ka + mg) > 0 at π,
    4 k a^2 (c^2 - 1) < 0 at cos θ = c."""
    theta, m, a, k, g = sp.symbols("theta m a k g", positive=True)
    hessian = -m * g * a * sp.cos(theta) + 4 * k * a**2 * sp.cos(2 * theta)
    root = sp.acos(m * g / (4 * k * a))
    expected = {sp.S(0): "stable", sp.pi: "stable", root: "unstable", -root: "unstable"}
    found = answers("equilibria")["equilibria"]
    assert len(found) == len(expected)
    for equilibrium in found:
        (at,) = [e for e in expected if same(equilibrium["at"]["theta"], str(e))]
        assert equilibrium["stability"] == expected[at]
        assert same(equilibrium["hessian"][0][0], str(hessian.subs(theta, at)))


def test_modes_rod_with_bob_on_string() -> None:
    """About (0, 0): T = (m l^2/3) θ'^2/2 + m (l^2 θ'^2 + 2 l^2 θ' φ' + l^2 φ'^2)/2, so
    M = m l^2 [[4/3, 1], [1, 1]]; V = -m g l cos θ/2 - m g l (cos θ + cos φ), so
    K = m g l [[3/2, 0], [0, 1]]. With μ = λ l/g, det = 2μ^2 - 17μ + 9 (times 1/6),
    μ = (17 ∓ √217)/4, and the first row gives a = (1, (3/2 - 4μ/3)/μ)."""
    got = answers("modes")
    assert same_all(got["M"], [["4*m*l**2/3", "m*l**2"], ["m*l**2", "m*l**2"]])
    assert same_all(got["K"], [["3*m*g*l/2", "0"], ["0", "m*g*l"]])
    mus = [(17 - sp.sqrt(217)) / 4, (17 + sp.sqrt(217)) / 4]
    assert same_all(got["eigenvalues"], [f"g/l*({mu})" for mu in mus])
    assert same_all(got["frequencies"], [f"sqrt(g/l*({mu}))" for mu in mus])
    assert same_all(got["shapes"], [["1", str((sp.Rational(3, 2) - 4 * mu / 3) / mu)] for mu in mus])
    lam = [9.81 / 0.5 * float(mu) for mu in mus]  # the template's values: l = 0.5, g = 9.81
    assert solved("modes")["results"][0]["values"]["eigenvalues"] == pytest.approx(lam, rel=1e-10)


def test_inertia_plate_about_its_corner() -> None:
    """J_G = m diag(a^2, 4a^2, 5a^2)/12; d = (a, a/2, 0), |d|^2 = 5a^2/4, so J_O = m a^2
    [[1/3, -1/2, 0], [-1/2, 4/3, 0], [0, 0, 5/3]] (J_xy = -∫ x y dm = -m a (a/2)). The xy
    block has trace 5/3 and determinant 7/36: moments m a^2 (5/6 ∓ √2/2), and 5/3 m a^2 about
    z; the smallest one's axis has y/x = 2 (1/3 - λ) = √2 - 1, i.e. 22.5° from x."""
    got = answers("inertia")
    assert same_all(got["J_G"], [["m*a**2/12", "0", "0"], ["0", "m*a**2/3", "0"], ["0", "0", "5*m*a**2/12"]])
    assert same_all(got["J"], [["m*a**2/3", "-m*a**2/2", "0"], ["-m*a**2/2", "4*m*a**2/3", "0"],
                               ["0", "0", "5*m*a**2/3"]])
    assert same_all(got["principal_moments"],
                    ["m*a**2*(5/6 - sqrt(2)/2)", "m*a**2*(5/6 + sqrt(2)/2)", "5*m*a**2/3"])
    assert same_all(got["principal_axes"][0], ["cos(pi/8)", "sin(pi/8)", "0"])
    assert same_all(got["principal_axes"][2], ["0", "0", "1"])


def test_impact_cart_and_rod_struck() -> None:
    """At θ = 0, v_G = (x' + l θ'/2, 0): T = (M + m) x'^2/2 + m l x' θ'/2 + m l^2 θ'^2/6.
    The impulse at C gives I_x = P, I_θ = 0: p_θ = m l x'/2 + m l^2 θ'/3 = 0 so θ' = -3x'/(2l),
    and (M + m) x' - 3m x'/4 = P: x' = 4P/(4M + m), θ' = -6P/(l (4M + m)),
    v_G = P/(4M + m). From rest T_f = P x'/2 = 2P^2/(4M + m); the rail gives no impulse."""
    got = answers("impact")
    assert same(got["velocities"]["x"], "4*P/(4*M + m)")
    assert same(got["velocities"]["theta"], "-6*P/(l*(4*M + m))")
    assert same_all(got["points"]["G"], ["P/(4*M + m)", "0", "0"])
    assert same(got["energy_after"], "2*P**2/(4*M + m)")
    assert same_all(got["support_impulse"], ["0", "0", "0"])


def test_steady_spin_of_a_thrown_phone() -> None:
    """Plate a × 2a: J = m a^2 (1/3, 1/12, 5/12) about x, y, z (J_z = J_x + J_y). About x
    (the intermediate moment): unstable, γ = Ω √((1/3-1/12)(5/12-1/3)/((1/12)(5/12))) = Ω √(3/5);
    about y (smallest): ν = Ω √((1/12-1/3)(1/12-5/12)/((1/3)(5/12))) = Ω √(3/5); about z
    (largest): ν = Ω √((1/12)(1/3)/((1/3)(1/12))) = Ω."""
    got = answers("steady_spin")
    assert same_all(got["moments"], ["m*a**2/3", "m*a**2/12", "5*m*a**2/12"])
    (case,) = got["cases"]
    expected = {("Omega", "0", "0"): ("unstable", "sqrt(3/5)*Omega"),
                ("0", "Omega", "0"): ("stable", "sqrt(3/5)*Omega"),
                ("0", "0", "Omega"): ("stable", "Omega")}
    assert len(case["stability"]) == len(expected)
    for spin in case["stability"]:
        stability, rate = expected[tuple(spin["spin"])]
        assert spin["stability"] == stability and same(spin["rate"], rate)


def test_steady_motion_conical_pendulum_of_a_rod() -> None:
    """ω = Ω ẑ, and ẑ = -sin θ e1 - cos θ e3 in the triad (e3 along the rod). J_O is m l^2/3
    across the rod, 0 along it: L_O = -m l^2 Ω sin θ/3 e1; dL/dt = Ω ẑ × L = m l^2 Ω^2 sin θ
    cos θ/3 e2; gravity's moment (l/2) e3 × (-m g ẑ) = m g l sin θ/2 e2. Balance:
    Ω^2 = 3 g/(2 l cos θ)."""
    got = answers("steady_motion")
    assert same_all(got["angular_velocity"], ["-Omega*sin(theta)", "0", "-Omega*cos(theta)"])
    assert same_all(got["angular_momentum"], ["-m*l**2*Omega*sin(theta)/3", "0", "0"])
    assert same_all(got["moment"], ["0", "m*g*l*sin(theta)/2", "0"])
    assert same(got["solved"]["Omega**2"], "3*g/(2*l*cos(theta))")


def test_reactions_bar_swinging_on_a_pivot() -> None:
    """By hand: J_O = m l²/3, so θ̈ = −3 g sin θ/(2 l); energy (m l²/6) θ̇² = (m g l/2)(cos θ − cos θ₀).
    At the lowest point the pivot pulls up m g + m (l/2) θ̇² = m g (5 − 3 cos θ₀)/2, sideways
    nothing. Just after release (θ̇ = 0), R = m a_G − m g with a_G = (l/2) θ̈ (cos θ₀, sin θ₀)."""
    got = answers("reactions")
    theta, theta0, g, l, m = sp.symbols("theta theta0 g l m", positive=True)
    names = {"theta": theta, "theta0": theta0, "g": g, "l": l, "m": m}
    along = {k: sp.sympify(v.replace("theta(t)", "theta"), locals=names) for k, v in got["along"]["O"].items()}
    assert sp.simplify(along["R_Oy"].subs(theta, 0) - m * g * (5 - 3 * sp.cos(theta0)) / 2) == 0
    assert sp.simplify(along["R_Ox"].subs(theta, 0)) == 0
    # just after release: a_G = (l/2) θ̈ (cos θ₀, sin θ₀), θ̈ = −3 g sin θ₀/(2 l), R = m a_G + m g ŷ
    acc = -3 * g * sp.sin(theta0) / (2 * l)
    at = got["at"]["O"]["components"]
    assert sp.simplify(sp.sympify(at["R_Ox"], locals=names) - m * l / 2 * acc * sp.cos(theta0)) == 0
    assert sp.simplify(sp.sympify(at["R_Oy"], locals=names) - (m * g + m * l / 2 * acc * sp.sin(theta0))) == 0
    assert same(got["rate_squared"]["theta"], "3*g*(cos(theta(t)) - cos(theta0))/l")


def test_energy_bar_falling_from_upright() -> None:
    """By hand: J_O = m l²/3, G at height (l/2) cos θ; T + V constant from rest upright,
    (m l²/6) θ̇² = (m g l/2)(1 − cos θ), so θ̇² = 3 g (1 − cos θ)/l; the tip B at distance
    l moves at v = l θ̇: v_B² = 3 g l (1 − cos θ), √(3 g l) at the horizontal."""
    got = answers("energy")
    assert got["integral"] == "T + V"
    assert same(got["rate_squared"]["theta"], "3*g*(1 - cos(theta(t)))/l")
    assert same(got["speed_squared"]["B"], "3*g*l*(1 - cos(theta(t)))")
    assert same(got["there"]["rate"]["theta"], "sqrt(3*g/l)") and same(got["there"]["speed"]["B"], "sqrt(3*g*l)")
    assert got["there"]["reached"] is True


# The scene templates (rolling, rocking), against the textbook answers by hand:
# a solid cylinder inside a cylinder, ω² = 2g/(3(R − r)); a half-disk rocking on the
# floor, ω² = 8g/((9π − 16) R) (problems/contacts/*.expected.yaml derive both).
SCENE_ANSWERS = {"rolling": "2*g/(3*(R - r))", "rocking": "8*g/((9*pi - 16)*R)"}


@pytest.mark.parametrize("scene", list(SCENE_ANSWERS))
def test_scene_templates_solve_to_the_textbook_answers(scene: str) -> None:
    from rbdsolve.cli.new import SCENES

    assert set(SCENES) == set(SCENE_ANSWERS)
    report = solved(scene)
    modes = next(r for r in report["results"] if r["question"] == "modes")
    (eigenvalue,) = modes["answers"]["eigenvalues"]
    assert same(eigenvalue, SCENE_ANSWERS[scene])
    listing = run("new", "--list").stdout
    assert scene in listing and run("new", scene).stdout.startswith("# rbdsolve template")


def test_kinematics_slider_crank_at_a_quarter_turn() -> None:
    """By hand, θ = π/2, θ̇ = ω, θ̈ = 0: A = r(cos θ, sin θ) = (0, r), v_A = r ω (−sin θ,
    cos θ) = (−r ω, 0), a_A = −r ω² (cos θ, sin θ) = (0, −r ω²). x_B = r cos θ + √(l² −
    r² sin² θ): ẋ_B = −r sin θ ω − r² sin θ cos θ ω/√(…) = −r ω; ẍ_B = ω² d²x_B/dθ², and
    d²x_B/dθ² = −r cos θ − r² cos 2θ/√(…) − r⁴ sin²θ cos²θ/(…)^(3/2) = r²/√(l² − r²)."""
    got = answers("kinematics")
    a, b = got["points"]
    assert same_all(a["position"], ["0", "r", "0"]) and same_all(a["velocity"], ["-r*omega", "0", "0"])
    assert same_all(a["acceleration"], ["0", "-r*omega**2", "0"])
    assert same_all(b["velocity"], ["-r*omega", "0", "0"])
    assert same_all(b["acceleration"], ["r**2*omega**2/sqrt(l**2 - r**2)", "0", "0"])
    assert same(got["distances"][0]["distance"], "sqrt(l**2 - r**2)")
    values = solved("kinematics")["results"][0]["values"]
    # r = 0.1 m, l = 0.3 m, ω = 1200·2π/60 = 40π rad/s
    assert values["points"][1]["acceleration"][0] == pytest.approx(0.01 * (40 * math.pi) ** 2 / math.sqrt(0.08))
    assert solved("kinematics")["results"][0]["units"]["points"][1]["acceleration"][0] == "m/s²"


def test_the_main_help_and_the_readme_name_every_question_kind_and_template() -> None:
    """Issue 41, item 6: `rbdsolve --help` lists every question kind; the README's
    tables list every kind (what it solves) and every template `rbdsolve new` offers."""
    from rbdsolve.cli.new import SCENES

    helped = " ".join(run("--help").stdout.split())
    assert all(f"{kind.value} (" in helped or f"{kind.value}," in helped for kind in QuestionKind)
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    rows = [line.split("|")[1].strip() for line in readme.splitlines() if line.startswith("| `")]
    for name in [*KINDS, *SCENES]:
        assert rows.count(f"`{name}`") >= (2 if name in KINDS else 1), name  # a template row, and what it solves


def test_the_ladder_template_turns_its_rod_the_way_its_ends_move() -> None:
    """The equilibria template's rod AB has A = 2a (sin θ, 0) and B = (0, 2a cos θ): the
    body's own axis (y, for axis: y) must lie along B − A = 2a (−sin θ, cos θ) at every θ,
    which a rod turned by −θ does not (its T is the same, its moments would not be)."""
    import sympy as sp

    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_file

    model = build_model(load_file(template_path("equilibria")))
    (rod,) = model.bodies
    theta, a = model.q[0], model.symbols.parameters["a"]
    along = rod.rotation * sp.Matrix([0, 1, 0])
    ends = sp.Matrix([-2 * a * sp.sin(theta), 2 * a * sp.cos(theta), 0]) / (2 * a)
    assert sp.simplify(along - ends) == sp.zeros(3, 1)
