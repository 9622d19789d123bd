"""Every answer checked before it is printed (issue 38, item 2): the residuals each
family registers, the sampling inside the assumptions and the existence condition, and
a wrong answer refused (the question unanswered, exit code 1, rbdsolve's fault) rather
than printed.

A wrong answer is made by hand here: the exact route's answer with one value moved
(an equilibrium by 1/10 rad, an eigenvalue by 1 %, a precession rate, a velocity after
an impact, a reaction's component); each must be caught by its family's check."""

from __future__ import annotations

import dataclasses
import importlib

import pytest
import sympy as sp
from click.testing import CliRunner

from conftest import PROBLEMS, SEED
from rbdsolve.cli import main
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.routes.checks import CheckFailed, Pencil, Vanishes, verify

BARE = """\
title: Parameters only
parameters: {a: length, b: length, phi: angle of a slope}
assumptions: [a > b]
coordinates: [x]
points: {P: "[x, 0]"}
bodies: {bead: {shape: particle, mass: a, at: P}}
questions: [eom]
"""


def _model(text: str = BARE):
    return build_model(load_text(text, "bare.yaml"))


def test_a_residual_that_cancels_passes_and_one_that_does_not_is_refused() -> None:
    model = _model()
    a, b, phi = (model.symbols.parameters[n] for n in ("a", "b", "phi"))
    verify([Vanishes("identity", a * sp.sin(phi) ** 2 + a * sp.cos(phi) ** 2 - a)], model)
    K, M = sp.ImmutableMatrix([[3 * a, b], [b, a]]), sp.ImmutableMatrix([[1, 0], [0, 1]])
    lam = 2 * a - sp.sqrt(a**2 + b**2)  # by hand: (3a − λ)(a − λ) = b², λ = 2a ∓ √(a² + b²)
    shape = (sp.Integer(1), (lam - 3 * a) / b)  # the first row of (K − λ) a = 0
    verify([Pencil("", K, M, (lam,), (shape,))], model)
    verify([Pencil("", K, M, (lam,), (None,))], model)
    with pytest.raises(CheckFailed, match="off by = .*not 0"):
        verify([Vanishes("off by", a * sp.sin(phi) ** 2 + a * sp.cos(phi) ** 2 - a + b / 10**6)], model)
    with pytest.raises(CheckFailed, match="bug in rbdsolve"):
        verify([Pencil("", K, M, (lam * sp.Rational(1000001, 1000000),), (None,))], model)
    with pytest.raises(CheckFailed, match=r"row 1 of \(K − λ₁ M\) a₁ = "):
        verify([Pencil("", K, M, (lam,), ((sp.Integer(1), -(lam - 3 * a) / b),))], model)


def test_the_samples_keep_the_assumptions_and_the_existence_condition() -> None:
    """|a − b| − (a − b) vanishes only where a ≥ b, which the assumption a > b gives;
    |c − b| − (c − b) only where c ≥ b: with that as the answer's condition it passes
    (c < 2b leaves room on both sides), and without it, where every sample has c < b,
    it is caught."""
    model = _model()
    a, b = (model.symbols.parameters[n] for n in ("a", "b"))
    verify([Vanishes("a > b", sp.Abs(a - b) - (a - b))], model)
    inside = (BARE.replace("phi: angle of a slope", "phi: angle of a slope, c: length")
              .replace("assumptions: [a > b]", "assumptions: [a > b, c < 2*b]"))
    model = _model(inside)
    a, b, c = (model.symbols.parameters[n] for n in ("a", "b", "c"))
    verify([Vanishes("c ≥ b only", sp.Abs(c - b) - (c - b), sp.GreaterThan(c, b))], model)
    model = _model(inside.replace("c < 2*b", "c < b"))  # every sample outside c ≥ b
    a, b, c = (model.symbols.parameters[n] for n in ("a", "b", "c"))
    with pytest.raises(CheckFailed):
        verify([Vanishes("c ≥ b only", sp.Abs(c - b) - (c - b))], model)


def _wrong(monkeypatch, family: str, move) -> None:
    """The family's exact route with its answer moved by ``move``."""
    module = importlib.import_module(f"rbdsolve.solvers.{family}.exact")
    right = module.solve

    def solve(question, model, options):
        solution = right(question, model, options)
        return dataclasses.replace(solution, answers=move(solution.answers))

    monkeypatch.setattr(module, "solve", solve)


def _moved_equilibrium(answers):
    first = answers.equilibria[0]
    moved = dataclasses.replace(first, at={k: v + sp.Rational(1, 10) for k, v in first.at.items()})
    return dataclasses.replace(answers, equilibria=(moved, *answers.equilibria[1:]))


def _moved_eigenvalue(answers):
    return dataclasses.replace(answers, eigenvalues=(answers.eigenvalues[0] * sp.Rational(101, 100),
                                                     *answers.eigenvalues[1:]))


def _moved_rate(answers):
    first = answers.branches[0]
    moved = dataclasses.replace(first, solved={k: v * sp.Rational(11, 10) for k, v in first.solved.items()})
    return dataclasses.replace(answers, branches=(moved, *answers.branches[1:]))


def _moved_velocity(answers):
    name, value = next(iter(answers.velocities.items()))
    return dataclasses.replace(answers, velocities={**answers.velocities, name: value + 1})


def _moved_reaction(answers):
    name, reaction = next(iter(answers.reactions.items()))
    key, value = next(iter(reaction.components.items()))
    moved = dataclasses.replace(reaction, components={**reaction.components, key: value * 2})
    return dataclasses.replace(answers, reactions={**answers.reactions, name: moved})


WRONG = [
    ("equilibria", SEED / "p1-two-rods.yaml", "equilibria", _moved_equilibrium, "∂V/∂θ at equilibrium 1"),
    ("modes", SEED / "p1-two-rods.yaml", "modes", _moved_eigenvalue, "of (K − λ₁ M) a₁"),
    ("steady_motion", PROBLEMS / "conditions" / "heavy-top-precession-rates.yaml", "steady_motion", _moved_rate,
     "balance 1 at solution 1"),
    ("impact", SEED / "p2-rod-impact.yaml", "impact", _moved_velocity, "the impulse equation of"),
    ("reactions", PROBLEMS / "forces" / "rod-pivot-released.yaml", "reactions", _moved_reaction, "balance"),
]


@pytest.mark.parametrize(("family", "path", "question", "move", "what"), WRONG, ids=[w[0] for w in WRONG])
def test_a_wrong_answer_is_refused_not_printed(monkeypatch, family, path, question, move, what) -> None:
    report = solve_problem(build_model(load_file(path)))
    assert all(s.solved for s in report.solutions)  # the right answers pass their checks
    _wrong(monkeypatch, family, move)
    report = solve_problem(build_model(load_file(path)))
    (wrong,) = [s for s in report.solutions if s.question == question]
    assert wrong.answers is None and not wrong.values
    assert "rbdsolve's own check of this answer failed" in wrong.error and what in wrong.error, wrong.error
    assert "bug in rbdsolve" in wrong.error


def test_a_refused_answer_exits_1_and_says_whose_fault_it_is(monkeypatch) -> None:
    """No other route is tried: the numeric route would hide the bug."""
    _wrong(monkeypatch, "equilibria", _moved_equilibrium)
    result = CliRunner().invoke(main, ["solve", str(SEED / "p1-two-rods.yaml"), "--format", "json"])
    assert result.exit_code == 1
    import json

    (equilibria,) = [r for r in json.loads(result.stdout)["results"] if r["question"] == "equilibria"]
    assert equilibria["ok"] is False and equilibria["route"] == "exact" and equilibria["answers"] is None
    assert "bug in rbdsolve" in equilibria["error"]


def test_a_balance_whose_every_term_is_a_rounding_of_zero_passes() -> None:
    """A ring on a drum at θ = π with R/r in sin(π R/r): each term of the x balance is
    sin(3π) in 30 digits, ~1e-30, and their sum as large as they are (a trial's 'bug in
    rbdsolve', exit 1); a term of ordinary size off by as much still fails."""
    from rbdsolve.solvers.routes.checks import Point, _failure

    model = _model()
    a, b = (model.symbols.parameters[n] for n in ("a", "b"))
    point = Point.of({a: sp.Integer(3), b: sp.Integer(1)})
    rounding = a * sp.sin(sp.pi * a * b) + b * sp.sin(sp.pi * a) ** 2 + 2 * b * sp.sin(sp.pi * (a + b) / 2)
    assert _failure(Vanishes("x balance", rounding), point) is None
    assert "not 0" in _failure(Vanishes("x balance", a * b + sp.Rational(1, 10**6) - 3), point)
