"""How far the linear modes hold: each oscillating mode simulated at finite amplitude.

A ``modes`` question with ``check_amplitudes: [A₁, A₂, …]`` also integrates the full
nonlinear Lagrange equations (Goldstein, ch. 1; with T = ½ q̇ᵀ M(q) q̇ for a scene that
does not move by itself)

    M(q) q̈ = −∂V/∂q − (∂(M q̇)/∂q) q̇ + ½ ∂(q̇ᵀ M q̇)/∂q

from rest at q(0) = q₀ + A a, a the mode shape scaled so its largest entry is 1 (A is
the amplitude of the mode's largest coordinate: radians or lengths), by scipy's
solve_ivp (DOP853, rtol 1e-11). M, ∂V/∂q and the velocity terms come from the symbolic
model (``mass_matrix``, ``potential_energy``) with the parameter values put in,
compiled by sympy's lambdify. The measured angular frequency is

    ω = 2π k / (t_{2k+1} − t₁)

over the first zero crossings t₁ < t₂ < … of the modal coordinate p = aᵀ M₀ (q − q₀)
(M₀ = M(q₀); each crossing located by solve_ivp's event root finding), k = CYCLES
full periods; the drift is ω/ω_lin − 1. At small A the drift is O(A²) (a pendulum:
ω/ω_lin = π / (2 K(sin²(A/2))) = 1 − A²/16 + …). ``spread`` is (max − min)/mean of
the full periods t_{i+2} − t_i: 0 for a periodic motion; a large spread means energy
moves into other modes at this amplitude, and ω is then an average. ``energy_error``
is |E(t_end) − E(0)| / max(|E(0) − V(q₀)|, tiny), the integration's accuracy gauge.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, Mapping, Sequence

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.model.numeric.compiled import numpy_function
from rbdsolve.model.energies.energy import mass_matrix, potential_energy
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Solution
from rbdsolve.model.values.values import numeric
from rbdsolve.solvers.routes.needed import missing_values

if TYPE_CHECKING:  # numpy is imported where a check runs: a modes question without one needs none
    import numpy as np

CYCLES = 4  # full periods measured
SLOWEST = 4.0  # integrate up to SLOWEST × the linear time for CYCLES periods
DRIFT_WARN = 0.01  # |ω/ω_lin − 1| past this: the linearization is not a good model there
RTOL, ATOL = 1e-11, 1e-13


@dataclass(frozen=True)
class AmplitudeRun:
    mode: int  # 1-based, in the order of the eigenvalues
    amplitude: float  # of the mode's largest coordinate
    coordinate: str  # that coordinate
    linear_frequency: float
    measured_frequency: float | None  # None: no oscillation about q₀ at this amplitude
    drift: float | None  # measured / linear − 1
    spread: float | None  # (max − min)/mean of the full periods
    energy_error: float | None  # relative change of T + V over the run


@dataclass(frozen=True)
class AmplitudeCheck:
    runs: tuple[AmplitudeRun, ...]
    tolerance: float  # the drift past which a warning is given


@dataclass(frozen=True)
class Dynamics:
    """The nonlinear equations, compiled: M(q), the right side f(q, q̇) and E(q, q̇)."""

    mass: Callable
    force: Callable
    energy: Callable


def with_check(question, model: Model, solution: Solution) -> Solution:
    """The modes solution with ``amplitude_check`` filled in when the question asks
    (the hook both modes routes call); unchanged otherwise."""
    wanted = getattr(question.options, "check_amplitudes", ())
    if not wanted or solution.answers is None:
        return solution
    from dataclasses import replace

    missing = missing_values(model)
    if missing:
        note = (f"check_amplitudes: not run: simulating the nonlinear equations needs a value for every "
                f"parameter; give {', '.join(missing)} ('values:' in the file, or --set NAME=VALUE)")
        return replace(solution, warnings=(*solution.warnings, note))
    a = solution.answers
    about = {k: _float(v, model) for k, v in a.about.items()}
    modes = [(i, _float(w, model), [_float(x, model) for x in shape])
             for i, (w, shape) in enumerate(zip(a.frequencies, a.shapes), 1) if w is not None and shape]
    result = check(model, about, modes, [float(x) for x in wanted])
    warnings = tuple(_warning(r) for r in result.runs if _warning(r))
    return replace(solution, answers=replace(a, amplitude_check=result),
                   steps=(*solution.steps, _step(result)), warnings=(*solution.warnings, *warnings))


def _float(value, model: Model) -> float:
    return float(numeric(value, model.values)) if not isinstance(value, float) else value


def check(model: Model, about: Mapping[str, float], modes: Sequence[tuple[int, float, Sequence[float]]],
          amplitudes: Sequence[float]) -> AmplitudeCheck:
    """Every (mode, amplitude) run: ``modes`` holds (index, ω_lin, shape) of the
    oscillating modes, ``about`` the equilibrium q₀."""
    import numpy as np

    dyn = compile_dynamics(model)
    q0 = np.array([about[n] for n in model.coordinate_names()], dtype=float)
    runs = []
    for index, omega, shape in modes:
        a = np.asarray(shape, dtype=float)
        big = int(np.argmax(np.abs(a)))
        a = a / a[big]
        for amplitude in amplitudes:
            runs.append(simulate(dyn, q0, a, omega, amplitude, index, model.coordinate_names()[big]))
    return AmplitudeCheck(tuple(runs), DRIFT_WARN)


def compile_dynamics(model: Model) -> Dynamics:
    """M(q), f(q, q̇) = −∂V/∂q − (∂(M q̇)/∂q) q̇ + ½ ∂(q̇ᵀ M q̇)/∂q and E = ½ q̇ᵀ M q̇ + V,
    with the parameter values in, lambdified for numpy."""
    values = dict(model.values)
    q, qd = sp.Matrix(model.q), sp.Matrix(model.qd)
    M = mass_matrix(model).xreplace(values)
    V = potential_energy(model).total.xreplace(values)
    p = M * qd
    T2 = (qd.T * p)[0, 0]
    f = -sp.Matrix([V]).jacobian(q).T - p.jacobian(q) * qd + sp.Matrix([T2]).jacobian(q).T / 2
    args = (list(model.q), list(model.qd))
    return Dynamics(numpy_function([args[0]], M), numpy_function(args, f),
                    numpy_function(args, T2 / 2 + V))


def simulate(dyn: Dynamics, q0: np.ndarray, a: np.ndarray, omega: float, amplitude: float,
             index: int, coordinate: str) -> AmplitudeRun:
    """One run from rest at q₀ + A a; the frequency from the modal coordinate's crossings."""
    import numpy as np
    from scipy.integrate import solve_ivp

    n = len(q0)
    M0 = np.asarray(dyn.mass(q0), dtype=float)
    weight = M0 @ a

    def rhs(_, y):
        M = np.asarray(dyn.mass(y[:n]), dtype=float)
        f = np.asarray(dyn.force(y[:n], y[n:]), dtype=float).ravel()
        return np.concatenate([y[n:], np.linalg.solve(M, f)])

    def crossing(_, y):
        return float(weight @ (y[:n] - q0))

    y0 = np.concatenate([q0 + amplitude * a, np.zeros(n)])
    span = SLOWEST * 2 * math.pi * CYCLES / omega
    with np.errstate(all="ignore"):
        sol = solve_ivp(rhs, (0.0, span), y0, method="DOP853", rtol=RTOL, atol=ATOL * max(1.0, amplitude),
                        events=_terminal(crossing, 2 * CYCLES + 1))
    times = np.asarray(sol.t_events[0]) if sol.t_events else np.array([])
    blank = AmplitudeRun(index, amplitude, coordinate, omega, None, None, None, None)
    if sol.status == -1 or len(times) < 2 * CYCLES + 1:
        return blank
    measured = 2 * math.pi * CYCLES / (times[2 * CYCLES] - times[0])
    periods = times[2:] - times[:-2]
    E0, E1 = (float(dyn.energy(y[:n], y[n:])) for y in (y0, sol.y[:, -1]))
    swing = max(abs(E0 - float(dyn.energy(q0, np.zeros(n)))), np.finfo(float).tiny)
    values = (measured, measured / omega - 1, float((periods.max() - periods.min()) / periods.mean()),
              abs(E1 - E0) / swing)
    if not all(math.isfinite(v) for v in values):
        return blank
    return AmplitudeRun(index, amplitude, coordinate, omega, *values)


def _terminal(event, count: int):
    event.terminal = count  # stop at the count-th crossing (scipy ≥ 1.12)
    return event


def _warning(run: AmplitudeRun) -> str | None:
    where = f"mode {run.mode} at amplitude {run.amplitude:g} of {run.coordinate}"
    if run.measured_frequency is None:
        return (f"check_amplitudes: {where} does not oscillate about the equilibrium (fewer than {CYCLES} periods "
                f"within {SLOWEST:g}× the linear time): the linear modes do not describe this motion")
    if abs(run.drift) > DRIFT_WARN:
        return (f"check_amplitudes: {where}: the simulated ω = {run.measured_frequency:.6g} differs from the "
                f"linear ω = {run.linear_frequency:.6g} by {run.drift:+.2%}: the linearization is not a good model "
                "at this amplitude")
    return None


def _step(result: AmplitudeCheck) -> st.Step:
    lines = []
    for r in result.runs:
        head = f"mode {r.mode}, {r.coordinate} amplitude {r.amplitude:g}: "
        if r.measured_frequency is None:
            lines.append(head + "no oscillation about the equilibrium")
        else:
            lines.append(head + f"ω = {r.measured_frequency:.10g} (linear {r.linear_frequency:.10g}), "
                                f"drift {r.drift:+.3e}, period spread {r.spread:.1e}, energy error {r.energy_error:.1e}")
    return st.note("Check at finite amplitude: the full nonlinear equations simulated from rest in each "
                   "oscillating mode's shape (scipy solve_ivp, DOP853, rtol 1e-11), ω from the zero crossings "
                   "of the modal coordinate; " + "; ".join(lines) + ".")
