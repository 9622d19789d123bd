"""One in-process measurement, run in its own process so that the benchmark can put a
timeout on it:

    python3 -m benchmarks.measure FAMILY SIZE ROUTE REPEATS   # prints one JSON line

What is timed: time.perf_counter around
``solve_problem(build_model(load_text(text)), Options(route=...))`` — loading, building
and solving, in a process where rbdsolve, sympy, numpy and scipy are already imported
and one size-1 problem of the same family has been solved on the same route (a warm-up,
so that lazy imports and first-call compilation are not charged to the size measured).
Each repeat starts from the text again. Also recorded: the question's own
``solution.seconds`` (the solver alone) and "compute", load + build + the solver (the
answer from the text, without the report's model section that writes out T and V),
the route that ran, its error estimate, and the relative error of the eigenvalues (modes questions) against the 50-digit reference:
max_i |λ_i − λ_ref,i| / |λ_ref,i|, the exact route's eigenvalues evaluated to 30 digits.
The reference is computed up to REFERENCE_LIMIT degrees of freedom: mpmath's 60-digit
eigensolver is O(n³) in Python numbers (minutes at n = 200), and its time would count
against the measurement's timeout; above it the route's own error estimate stands alone.
"""

from __future__ import annotations

import json
import statistics
import sys
import time

from benchmarks.families import FAMILIES, Case

LONG = 10.0  # one sample only when a solve takes longer than this (s): the timeout bounds the whole
REFERENCE_LIMIT = 50  # largest size whose eigenvalues are checked against the 50-digit reference


def solve_once(case: Case, route: str):
    """One timed solve; returns (seconds, load + build seconds, the question's Solution,
    the model)."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers import Options, RouteChoice, solve_problem

    start = time.perf_counter()
    model = build_model(load_text(case.text))
    built = time.perf_counter()
    report = solve_problem(model, Options(route=RouteChoice(route)))
    return time.perf_counter() - start, built - start, report.solutions[0], model


def reference(case: Case, model) -> list:
    """The 50-digit eigenvalues of K a = λ M a: from the case's hand formula, else from
    rbdsolve's exact M and K at the equilibrium (values put in, no rounding)."""
    import sympy as sp

    from rbdsolve.model.energies.energy import mass_matrix, potential_energy, stiffness_matrix
    from rbdsolve.solvers.modes.numeric import reference_eigenvalues

    if case.M is not None:
        M = [[sp.Rational(x.numerator, x.denominator) for x in row] for row in case.M]
        K = [[sp.Rational(x.numerator, x.denominator) for x in row] for row in case.K]
        return reference_eigenvalues(K, M)
    at = {q: 0 for q in model.q}
    values = dict(model.values)
    M = sp.Matrix(mass_matrix(model, at)).xreplace(values)
    K = sp.Matrix(stiffness_matrix(potential_energy(model).total, model.q, at)).xreplace(values)
    return reference_eigenvalues(K.tolist(), M.tolist())


def relative_error(eigenvalues, ref, values) -> float:
    """max |λ − λ_ref| / |λ_ref| over the modes, exact answers evaluated to 30 digits."""
    import mpmath
    import sympy as sp

    with mpmath.workdps(40):
        got = [mpmath.mpf(str(sp.N(sp.sympify(x).xreplace(values), 30))) if isinstance(x, sp.Basic)
               else mpmath.mpf(x) for x in eigenvalues]
        got.sort()
        return float(max(abs(a - b) / abs(b) for a, b in zip(got, ref)))


def measure(family: str, size: int, route: str, repeats: int) -> dict:
    """Warm up, then ``repeats`` timed solves (one if a solve takes over LONG s); the
    median and every sample."""
    case = FAMILIES[family](size)
    solve_once(FAMILIES[family](1), route)
    samples, computes, solution, model = [], [], None, None
    for _ in range(repeats):
        seconds, build, solution, model = solve_once(case, route)
        samples.append(seconds)
        computes.append(build + solution.seconds)
        if solution.error or seconds > LONG:
            break
    out = {"samples": samples, "median": statistics.median(samples), "route_ran": solution.route.value,
           "solution_seconds": solution.seconds, "compute": statistics.median(computes), "error": solution.error,
           "error_estimate": solution.error_estimate, "relative_error": None}
    if case.question == "modes" and solution.answers is not None and size <= REFERENCE_LIMIT:
        out["relative_error"] = relative_error(solution.answers.eigenvalues, reference(case, model),
                                               dict(model.values))
    return out


if __name__ == "__main__":
    from rbdsolve.cli.app import process_settings

    process_settings()  # timed as the rbdsolve command runs: BLAS on one thread, the collector less often
    family, size, route, repeats = sys.argv[1], int(sys.argv[2]), sys.argv[3], int(sys.argv[4])
    print(json.dumps(measure(family, size, route, repeats)))
