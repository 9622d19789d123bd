"""The numeric modes route against the condition of the problem: three masses on a
line, wall–k₁–m₁–k₂–m₂–k₃–m₃, one mass or one spring made small or stiff by a ratio r
from 1 down to 1e-12. Each case is solved on both routes; the numeric eigenvalues are
compared with the 50-digit reference of the exact M and K (hand formula:
M = diag(m), K tridiagonal with Kᵢᵢ = kᵢ + kᵢ₊₁, Kᵢ,ᵢ₊₁ = −kᵢ₊₁).

    python3 -m benchmarks.conditioning        # prints one JSON list (a few seconds)

Per case and eigenvalue: the actual relative error |λ̂ − λ|/|λ|, the stated bound
(relative_errors), the relative condition number κ(λ) and κ₂(M) (modes_spaces), and
per case the exact route's time, whether its eigenvalues are exact (no floats) and
their relative error against the reference (at 60 digits: a wrong closed form shows).
"""

from __future__ import annotations

import json
import time
from dataclasses import asdict, dataclass
from fractions import Fraction

RATIOS = tuple(Fraction(1, 10**p) for p in range(0, 13, 2))


@dataclass(frozen=True)
class ChainCase:
    """Masses and spring stiffnesses (rational) of the three-mass chain and its label."""

    kind: str  # "mass" (m₃ = r) or "stiffness" (k₂ = 1/r)
    ratio: Fraction
    masses: tuple[Fraction, ...]
    stiffnesses: tuple[Fraction, ...]


def cases() -> list[ChainCase]:
    out = []
    for r in RATIOS:
        out.append(ChainCase("mass", r, (Fraction(1), Fraction(1), r), (Fraction(1),) * 3))
        out.append(ChainCase("stiffness", r, (Fraction(1),) * 3, (Fraction(1), 1 / r, Fraction(1))))
    return out


def chain_text(masses, stiffnesses) -> str:
    """Masses on parallel rails 1 apart, zero-length springs: V = ½ Σ kᵢ ((xᵢ − xᵢ₋₁)² + 1).
    The masses and stiffnesses are written as rational numbers, not parameters: the
    exact route then works over QQ (with six symbolic parameters its cubic runs out of
    the budget; docs/failure-edges.md)."""
    n = len(masses)
    return (f"coordinates: [{', '.join(f'x{i}' for i in range(1, n + 1))}]\n"
            + "points:\n  P0: [0, 0]\n" + "".join(f"  P{i}: [x{i}, {i}]\n" for i in range(1, n + 1))
            + "bodies:\n" + "".join(f"  b{i}: {{shape: particle, mass: {m}, at: P{i}}}\n"
                                    for i, m in enumerate(masses, 1))
            + "springs:\n" + "".join(f"  s{i}: {{stiffness: {k}, between: [P{i - 1}, P{i}]}}\n"
                                     for i, k in enumerate(stiffnesses, 1))
            + "questions:\n  - modes: {about: {" + ", ".join(f"x{i}: 0" for i in range(1, n + 1)) + "}}\n")


def chain_matrices(masses, stiffnesses):
    """M = diag(m), K tridiagonal (the module docstring), as Fractions."""
    n = len(masses)
    k = list(stiffnesses) + [Fraction(0)]
    M = [[masses[i] if i == j else Fraction(0) for j in range(n)] for i in range(n)]
    K = [[k[i] + k[i + 1] if i == j else -k[max(i, j)] if abs(i - j) == 1 else Fraction(0) for j in range(n)]
         for i in range(n)]
    return M, K


@dataclass(frozen=True)
class ConditioningPoint:
    """One eigenvalue of one case on the numeric route, and the case's exact route."""

    kind: str
    ratio: float
    mode: int
    condition_M: float
    condition: float | None
    actual: float
    bound: float | None
    exact_seconds: float
    exact_exact: bool  # no floats in the exact route's eigenvalues
    exact_error: float  # their relative error against the reference, evaluated at 60 digits


def measure_case(case: ChainCase) -> list[ConditioningPoint]:
    import mpmath
    import sympy as sp

    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers import Options, RouteChoice, solve_problem
    from rbdsolve.solvers.modes.numeric import reference_eigenvalues

    model = build_model(load_text(chain_text(case.masses, case.stiffnesses)))
    numeric = solve_problem(model, Options(route=RouteChoice.NUMERIC)).solutions[0].answers
    start = time.perf_counter()
    exact = solve_problem(model, Options(route=RouteChoice.EXACT)).solutions[0].answers
    seconds = time.perf_counter() - start
    M, K = chain_matrices(case.masses, case.stiffnesses)
    ref = reference_eigenvalues([[sp.Rational(x.numerator, x.denominator) for x in r] for r in K],
                                [[sp.Rational(x.numerator, x.denominator) for x in r] for r in M])
    exact_ok = all(not x.has(sp.Float) for x in exact.eigenvalues)
    with mpmath.workdps(50):
        actual = [float(abs(mpmath.mpf(x) - r) / abs(r)) for x, r in zip(numeric.eigenvalues, ref)]
        exact_error = [float(abs(mpmath.mpf(str(sp.N(x, 60))) - r) / abs(r)) for x, r in zip(exact.eigenvalues, ref)]
    return [ConditioningPoint(case.kind, float(case.ratio), i + 1, numeric.condition_M, numeric.conditions[i],
                              actual[i], numeric.relative_errors[i], seconds, exact_ok, exact_error[i])
            for i in range(len(actual))]


def measure() -> list[dict]:
    return [asdict(p) for case in cases() for p in measure_case(case)]


if __name__ == "__main__":
    print(json.dumps(measure()))
