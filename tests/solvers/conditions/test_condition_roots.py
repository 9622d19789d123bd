"""solvers/conditions/condition_roots.py: the roots of a quantity in a parameter come out
the same whatever the hash seed of the run.

The roots of the numerator and of the denominator are gathered in a set; they were
once walked in its iteration order, which decided which of two forms of one value came
first: for (c − a − b)/(c − √(a² + 2ab + b²)), PYTHONHASHSEED 0 listed a + b first and
2 listed the square root first."""

from __future__ import annotations

import os
import subprocess
import sys

ROOTS = """
import sympy as sp
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers.conditions.condition_roots import parameter_roots
model = build_model(load_text('''
parameters: {m: mass, a: length, b: length, c: length}
coordinates: [x]
points: {P: [x, 0]}
bodies: {bob: {shape: particle, mass: m, at: P}}
questions: [eom]
'''))
a, b, c = (model.symbols.parameters[n] for n in "abc")
print(parameter_roots((c - a - b) / (c - sp.sqrt(a**2 + 2*a*b + b**2)), c, {}, model))
"""


def _roots_with_seed(seed: int) -> str:
    env = {**os.environ, "PYTHONHASHSEED": str(seed)}
    return subprocess.run([sys.executable, "-c", ROOTS], env=env, capture_output=True, text=True,
                          check=True).stdout


def test_the_roots_are_the_same_whatever_the_hash_seed() -> None:
    first = _roots_with_seed(0)
    assert "a + b" in first
    assert first == _roots_with_seed(2)
