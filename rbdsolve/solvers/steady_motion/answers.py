"""The answers of a steady motion question, both routes (docs/json.md, steady_motion)."""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from rbdsolve.solvers.conditions.conditions import CriticalValue


@dataclass(frozen=True)
class Branch:
    """One solution of the relations for the asked quantities, and where it is real."""

    solved: dict[str, sp.Expr]
    exists_when: sp.Basic = sp.true


@dataclass(frozen=True)
class AtSolution:
    """What the other answers hold of a solution, put back in (exact route): the value
    of each quantity the solution fixes that is not asked as itself (ω₀ from ω₀² where
    ω₀ is positive), each rate the rolling condition wrote in terms of them, and ω with
    those values in."""

    values: dict[str, sp.Expr]
    rates: dict[str, sp.Expr] = field(default_factory=dict)
    angular_velocity: tuple[sp.Expr, ...] = ()  # () where ω holds none of them


@dataclass(frozen=True)
class SupportForce:
    """A reaction's force on the body, in the triad's components."""

    force: tuple[sp.Expr, sp.Expr, sp.Expr]


@dataclass(frozen=True)
class SteadyMotionAnswers:
    triad: tuple[str, str, str]  # the names of the triad's unit vectors
    rates: dict[str, sp.Expr]  # unknown rates found from the rolling conditions
    angular_velocity: tuple[sp.Expr, sp.Expr, sp.Expr]  # ω in the triad's components
    angular_momentum: tuple[sp.Expr, sp.Expr, sp.Expr]  # L_P, triad components
    moment: tuple[sp.Expr, sp.Expr, sp.Expr]  # M_P, triad components
    relations: tuple[sp.Expr, ...]  # each = 0
    solved: dict[str, sp.Expr]  # the asked quantities, from the relations
    # the reactions' other unknowns (not asked for), solved together with the asked ones
    found_along: dict[str, sp.Expr] = field(default_factory=dict)
    # every solution when there are several (``solved`` is then {}), or the one solution
    # where it is real only under a condition
    branches: tuple[Branch, ...] = ()
    critical: tuple[CriticalValue, ...] = ()  # where a branch stops being real
    # each reaction's force with its unknowns found, by its point ('at' as written), as the
    # reactions question names a reaction; {} where an unknown is left open
    reactions: dict[str, SupportForce] = field(default_factory=dict)
    # one per solution (in the order of ``branches``, or the one of ``solved``), where a
    # solved quantity stands in ω or the rates; () where none does
    at_solutions: tuple[AtSolution, ...] = ()


@dataclass(frozen=True)
class NumericSteadyMotion:
    """One solution of the relations."""

    unknowns: dict[str, float | None]  # every unknown solved for (None: the relations leave it open)
    angular_velocity: tuple[float, float, float]  # ω in the triad's components
    solved: dict[str, float]  # each solve_for expression (as written) -> its value
    residuals: tuple[float, ...]  # each relation's value there, in the order of ``relations``
    absolute_errors: dict[str, float]  # a bound on each value's error: unknowns, solved, omega1..3


@dataclass(frozen=True)
class NumericSteadyMotionAnswers:
    triad: tuple[str, str, str]
    relations: tuple[sp.Expr, ...]  # the rolling conditions, then the balances, each = 0
    angular_velocity: tuple  # one 3-vector, or one per solution when they differ
    solved: dict[str, float | list[float]]  # a value, or one per solution when they differ
    solutions: tuple[NumericSteadyMotion, ...]
    starts: int
