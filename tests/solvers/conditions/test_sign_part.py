"""A condition is split once for K and for λ = K/M: ``partition`` takes f without its
positive factors (conditions.sign_part), so the modes about an equilibrium reuse the
pieces its stability was split into.

The scene (tests/conftest.py's TURNING_ROD, worked there by hand): a bead on a rod
turning at Ω, held by a spring of natural length a from the axis, has K = k − m Ω² and
M = m at its one equilibrium, so λ = K/M = (k − m Ω²)/m; both change sign once, at
Ω_c = √(k/m) (the equilibrium exists and is stable below it).
"""

from __future__ import annotations

import random

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.conditions import conditions
from rbdsolve.solvers.conditions.conditions import partition, sign_part
from tests.conftest import TURNING_ROD, counted_calls


def _symbols(model):
    return tuple(model.symbols.parameters[n] for n in ("m", "k", "a", "Omega"))


def test_positive_numbers_and_powers_of_positive_parameters_are_left_out() -> None:
    m, d = sp.symbols("m d", positive=True)
    x = sp.Symbol("x", real=True)
    K = 3 * x - m
    assert sign_part(K / (2 * d * m**2)) == K
    assert sign_part(-K / (d * sp.sqrt(m))) == -K
    assert sign_part(x * K / m) == x * K  # x may be negative: kept
    assert sign_part(K) == K


def test_k_and_k_over_m_are_split_once_with_the_same_pieces() -> None:
    model = build_model(load_text(TURNING_ROD))
    m, k, _, Omega = _symbols(model)
    K = k - m * Omega**2
    by_stiffness = partition(K, model)
    assert partition(K / m, model) is by_stiffness
    assert by_stiffness.parameter == Omega
    (critical,) = by_stiffness.criticals
    assert sp.simplify(critical.value - sp.sqrt(k / m)) == 0
    # the sign on each side, sampled: λ = (k − m Ω²)/m at Ω below and above Ω_c
    rng = random.Random(5)
    for _ in range(200):
        mv, kv = rng.uniform(0.1, 10), rng.uniform(0.1, 10)
        for piece, factor in ((by_stiffness.pieces[0], 0.9), (by_stiffness.pieces[1], 1.1)):
            omega = factor * (kv / mv) ** 0.5
            assert piece.sign == (1 if (kv - mv * omega**2) / mv > 0 else -1)


def test_the_modes_reuse_the_equilibrias_split(monkeypatch) -> None:
    model = build_model(load_text(TURNING_ROD))
    splits = counted_calls(monkeypatch, conditions, "candidates")  # once per f split
    report = solve_problem(model)
    assert all(s.solved for s in report.solutions)
    Omega = _symbols(model)[3]
    split = [sign_part(f) for f, *_ in splits if f.has(Omega)]
    # K (the equilibria's stability) and λ = K/m (the modes) have one sign part: split once
    assert split and len(set(split)) == len(split)
