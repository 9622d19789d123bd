"""The Python API (rbdsolve/api/, docs/api.md): the CLI's pipeline from Python, its
answers sympy objects, its errors the CLI's located exceptions."""

from __future__ import annotations

import json
import subprocess
import sys
import xml.etree.ElementTree as ET
from fractions import Fraction

import pytest
import sympy as sp
import yaml
from click.testing import CliRunner

import rbdsolve
from rbdsolve.cli import main

from conftest import ROOT, SEED

P1 = SEED / "p1-two-rods.yaml"
PENDULUM = ROOT / "problems" / "examples" / "pendulum.yaml"


@pytest.fixture(scope="module")
def p1() -> rbdsolve.Result:
    return rbdsolve.solve(P1)


def _without_times(data):
    """A report's JSON object without the seconds each route took (they differ run to run)."""
    if isinstance(data, dict):
        return {k: _without_times(v) for k, v in data.items() if k != "seconds"}
    if isinstance(data, list):
        return [_without_times(x) for x in data]
    return data


def test_the_api_gives_what_the_cli_prints(p1) -> None:
    """One pipeline: the API's JSON is the CLI's, to the letter (times aside)."""
    cli = CliRunner().invoke(main, ["solve", str(P1), "--format", "json"])
    assert cli.exit_code == 0, cli.output
    assert _without_times(json.loads(p1.to_json())) == _without_times(json.loads(cli.stdout))


def test_answers_are_sympy_objects_with_the_problems_symbols(p1) -> None:
    """p1's eigenvalues, by hand in the exam's solution: 24g/(25r) and 2g/r."""
    g, r = p1.symbols["g"], p1.symbols["r"]
    assert g.is_positive and r.is_positive
    eigenvalues = p1["modes"]["eigenvalues"]
    assert all(isinstance(x, sp.Expr) for x in eigenvalues)
    assert sp.simplify(eigenvalues[0] - 24 * g / (25 * r)) == 0 and sp.simplify(eigenvalues[1] - 2 * g / r) == 0
    assert p1.subs(eigenvalues[1], g=10, r=4) == 5
    assert isinstance(p1["modes"].answers.M, sp.MatrixBase)
    theta = p1.symbols["theta"]
    assert theta.args == (p1.symbols["t"],) and p1["eom"].answers.equations[0].has(theta)


def test_a_result_is_a_sequence_of_answers(p1) -> None:
    assert [a.question for a in p1] == ["eom", "equilibria", "modes"] and len(p1) == 3
    assert p1[2] is not p1["modes"] and p1[2].solution is p1["modes"].solution
    assert p1.solved and p1.exit_code == 0 and p1.errors == ()
    assert p1["modes"].number == 3 and p1["modes"].route == "exact" and p1["modes"].results
    with pytest.raises(KeyError, match="no question 'impact'"):
        p1["impact"]
    with pytest.raises(KeyError, match="no answer 'omega'"):
        p1["modes"]["omega"]
    with pytest.raises(rbdsolve.InputError, match="no name 'k'"):
        p1.subs(sp.Integer(1), k=2)


def test_every_format_renders(p1) -> None:
    assert p1.render("text") == p1.to_text() and "Two rods in a circle" in p1.to_text()
    assert p1.to_markdown().startswith("# Two rods in a circle")
    assert "\\boxed{" in p1.to_latex() and p1.to_latex(document=True).rstrip().endswith("\\end{document}")
    assert p1.to_dict()["title"] == "Two rods in a circle"
    assert p1._repr_markdown_() == p1.to_markdown() and p1._repr_html_() == p1.to_html()
    for html in (p1.to_html(), p1["modes"]._repr_html_()):
        fragment = ET.fromstring(html)  # well-formed XML, its mathematics MathML
        assert fragment.get("class") == "rbdsolve" and fragment.find(".//math//mfrac") is not None
    assert ".rbdsolve .math" in p1.to_html() and "body {" not in p1.to_html()  # styles nothing of the notebook
    latex = p1._repr_latex_()
    assert latex.startswith("$$") and latex.endswith("$$") and "\\frac{24 g}{25 r}" in latex
    with pytest.raises(rbdsolve.InputError, match="format: expected one of"):
        p1.render("docx")


def test_a_path_text_and_dict_load_the_same_problem() -> None:
    text = PENDULUM.read_text(encoding="utf-8")
    answers = [rbdsolve.solve(source)["modes"].answers.eigenvalues
               for source in (str(PENDULUM), PENDULUM, rbdsolve.loads(text), yaml.safe_load(text))]
    l, g = sp.symbols("l g", positive=True)
    assert all(a == (sp.Rational(3, 2) * g / l,) for a in answers)  # a rod pivoted at its end: ω² = 3g/(2l)


def test_values_route_and_budget_are_the_clis() -> None:
    """ω² = 3g/(2l) at g = 9.81, l = 0.5 m (given as '50 cm'), on the numeric route."""
    result = rbdsolve.solve(PENDULUM, route="numeric", budget=30,
                            values={"m": Fraction(1, 2), "l": "50 cm", "g": 9.81})
    assert result["modes"].route == "numeric"
    assert result["modes"].values["eigenvalues"] == pytest.approx([3 * 9.81 / (2 * 0.5)], rel=1e-12)


@pytest.mark.parametrize("kwargs, message", [
    ({"values": {"k": 1}}, "values['k']: problems/examples/pendulum.yaml has no parameter 'k'"),
    ({"values": {"m": -1}}, "values['m']: the parameter is positive, found -1"),
    ({"values": {"m": True}}, "values['m']: expected a number, found True"),
    ({"values": {"m": float("nan")}}, "values['m']: expected a finite number"),
    ({"values": {"l": "2 kg"}}, "values['l']: 'l' is"),
    ({"route": "fast"}, "route: expected one of auto, exact, numeric, found 'fast'"),
    ({"budget": 0}, "budget: expected seconds"),
    ({"budget": float("inf")}, "budget: expected seconds"),
])
def test_bad_options_are_input_errors(kwargs, message, monkeypatch) -> None:
    monkeypatch.chdir(ROOT)
    with pytest.raises(rbdsolve.InputError) as caught:
        rbdsolve.solve("problems/examples/pendulum.yaml", **kwargs)
    assert message in str(caught.value) and caught.value.exit_code == 2


def test_bad_input_is_located() -> None:
    with pytest.raises(rbdsolve.InputError) as caught:
        rbdsolve.load_dict({"title": "t", "parameters": {"m": "mass"}, "coordinates": ["x"],
                            "bodies": {"b": {"shape": "particle", "mass": sp.Symbol("m"), "at": "[x, 0]"}},
                            "questions": ["eom"]})
    assert caught.value.location.key_path() == "bodies.b.mass" and "found Symbol" in str(caught.value)
    with pytest.raises(rbdsolve.InputError, match="no such file: nowhere.yaml"):
        rbdsolve.load("nowhere.yaml")
    with pytest.raises(rbdsolve.InputError, match="loads\\(\\) reads YAML text"):
        rbdsolve.load(42)
    with pytest.raises(rbdsolve.InputError, match="rbdsolve.loads\\(text\\) reads"):
        rbdsolve.solve("title: t\nquestions: [eom]\n")
    with pytest.raises(rbdsolve.InputError, match="the limit is"):
        rbdsolve.loads("title: t\n" + "#" * 300_000)


def test_an_unanswered_question_is_in_the_result_not_raised() -> None:
    """The numeric route without values cannot answer: exit code 1, as the CLI's."""
    result = rbdsolve.solve(PENDULUM, route="numeric")
    assert not result.solved and result.exit_code == 1 and len(result.errors) == 3
    assert result[0].answers is None and result[0].error


def test_import_rbdsolve_loads_nothing_of_the_pipeline() -> None:
    code = ("import sys, rbdsolve\n"
            "print(sorted(m for m in sys.modules if m.startswith('rbdsolve.') or m in ('sympy', 'yaml', 'rich')))\n"
            "rbdsolve.load\n"
            "print('sympy' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=60,
                          env={"PYTHONPATH": str(ROOT)})
    assert done.stdout.split("\n")[:2] == ["[]", "False"], done.stdout + done.stderr
    assert set(rbdsolve.__all__) <= set(dir(rbdsolve))
    with pytest.raises(AttributeError):
        rbdsolve.no_such_name
