"""The evident roots of ∂V/∂q = 0: the configurations where every equation vanishes
exactly at simple values, found without solving anything.

Where the equations are transcendental (a slab rocking on a drum,
∂V/∂θ = m g (R θ cos θ − ½ a sin θ); a half-disk on a drum, sin θ beside sin(r θ/(R + r)))
no closed form lists every root, but the equilibrium an exam asks about is nearly
always one where each term vanishes by itself: θ = 0, where sin θ = 0 and θ cos θ = 0,
or θ = π. A coordinate q that enters the equations inside sin or cos, as c q with c a
rational number, is tried at 0 and where c q is ±π/2 or ±π (θ/2: 0, ±π, ±2π); every
other coordinate at 0; in every combination (at most COMBINATIONS; past that, only
where c q is 0 or ±π, then 0 alone). A combination is a root when each
equation, the values put in, is exactly zero for every value of the parameters: first
screened at one sample of the parameters to 30 digits (a value far from zero rejects
it at once), then proved by sympy's simplification; an equation undefined there (0/0)
is no root, nor one that holds sign(u) where u = 0: a spring's length |u| is zero there
and V has a kink, ½ k (|u| − l₀)² ≈ −k l₀ |u| (a bead on a turning rod, its distance r
from the axis the coordinate, on a spring of natural length l₀ from the axis: sympy's
sign(0) = 0 made r = 0 look like a root). The list is not complete: other roots may exist, and the report says so.
"""

from __future__ import annotations

import itertools
import random

import sympy as sp

from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.model.values.values import parameter_sample
from rbdsolve.form.zero import simplifies_to_zero

COMBINATIONS = 256
SCREEN = 1e-12  # |value| at the sample above this (relative to the equation's scale) rejects at once
SIMPLIFY_OPS = 400  # past this many operations a leftover is not simplified: not proved, not a root


def evident_roots(equations, unknowns, model: Model) -> list[dict]:
    """Every combination of simple values at which all ``equations`` vanish exactly."""
    arguments = [f.args[0] for e in equations for f in e.atoms(sp.sin, sp.cos, sp.tan)]
    choices = _choices([_candidates(q, arguments) for q in unknowns])
    point = parameter_sample(model, random.Random(17))
    return [dict(zip(unknowns, combo)) for combo in itertools.product(*choices)
            if all(_vanishes(e, dict(zip(unknowns, combo)), point) for e in equations)]


def _candidates(q: sp.Symbol, arguments) -> tuple[tuple, tuple]:
    """(where each c q is 0 or ±π, where it is ±π/2) for the rational c of q in the
    trigonometric arguments; a coordinate in none is tried at 0 only."""
    scales = {sp.diff(a, q) for a in arguments if a.has(q)}
    scales = sorted((c for c in scales if c.is_Rational and c != 0), key=lambda c: (abs(c), c))
    whole = [sp.Integer(0)] + [v / c for c in scales for v in (sp.pi, -sp.pi)]
    half = [v / c for c in scales for v in (sp.pi / 2, -sp.pi / 2)]
    return tuple(dict.fromkeys(whole)), tuple(x for x in dict.fromkeys(half) if x not in whole)


def _choices(candidates: list[tuple[tuple, tuple]]) -> list[tuple]:
    """Each coordinate's values, as many as COMBINATIONS allows in all."""
    for pick in (lambda w, h: w + h, lambda w, h: w, lambda w, h: w[:1]):
        choices = [pick(w, h) for w, h in candidates]
        count = 1
        for c in choices:
            count *= len(c)
        if count <= COMBINATIONS:
            return choices
    return [(sp.Integer(0),)] * len(candidates)


def _vanishes(equation: sp.Expr, at: dict, point: dict) -> bool:
    if any(sp.expand(f.args[0].xreplace(at)) == 0 for f in equation.atoms(sp.sign)):
        return False  # sign(u) at u = 0: |u| has a kink there (a spring through zero length), no derivative
    value = equation.xreplace(at)
    if value == 0:
        return True
    if value.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        return False
    if not _small_at(value, point):
        return False
    if sp.expand(value) == 0 or tidy(value) == 0:
        return True
    return sp.count_ops(value) <= SIMPLIFY_OPS and simplifies_to_zero(value)


def _small_at(value: sp.Expr, point: dict) -> bool:
    """Is the value zero to 30 digits at the sample, relative to its terms' size?"""
    terms = sp.Add.make_args(sp.expand(value))
    try:
        numbers = [complex(sp.N(t.xreplace(point), 30)) for t in terms]
    except (TypeError, ValueError):
        return True  # not a number at the sample: leave it to the exact test
    total, scale = abs(sum(numbers)), sum(abs(n) for n in numbers)
    if total != total or scale != scale:  # NaN: undefined at the sample
        return False
    return total <= SCREEN * max(scale, 1e-300)
