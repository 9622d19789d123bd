"""Mutation testing of the core math (issue 43, item 6): a fixed set of mutants.

    python3 -m benchmarks.mutants [--only NAME,NAME] [--list] [--jobs J] [--no-baseline]

Each mutant is one small change to rbdsolve's model/ or a solver family, of the kinds a
slip of the pen makes: a flipped sign, a dropped factor, a swapped comparison or case.
The tree is copied (rbdsolve/, tests/, problems/, benchmarks/ and the project files) to
a temporary folder, once per job; for each mutant the one file is changed in a free
copy, the tests that cover that piece of the math are run (``pytest -x``, one process,
the copy first on PYTHONPATH) and the file is put back. A mutant is *killed* when a test
fails (or hangs past --timeout), *survived* when they all pass. Each selection of tests
is first run on an unchanged copy (unless --no-baseline, for when the whole suite is
known to pass): a selection that fails without a mutant kills nothing and is reported as
an error.

Each mutant's text must occur exactly once in its file (checked first): a refactoring
that moves the line makes the mutant an error, to be rewritten, never a silent pass.

The last line is ``mutants: K killed of N (score S %), U survived (names)``.
"""

from __future__ import annotations

import argparse
import os
import queue
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
COPIED = ("rbdsolve", "tests", "problems", "benchmarks", "pyproject.toml", "conftest.py", "setup.cfg", "pytest.ini")


@dataclass(frozen=True)
class Mutant:
    name: str
    path: str  # in the tree, from its root
    before: str  # exact text, once in the file
    after: str
    tests: tuple[str, ...]  # pytest arguments that cover it
    what: str  # the slip, in words


MODEL = ("tests/model", "tests/solvers/inertia/test_inertia.py", "tests/solvers/eom")
EQUILIBRIA = ("tests/solvers/equilibria", "tests/solvers/conditions/test_signs.py", "tests/edges/test_equilibria_edges.py")
MODES = ("tests/solvers/modes/test_modes.py", "tests/solvers/modes/test_modes_cases.py",
         "tests/solvers/modes/test_modes_numeric.py", "tests/edges/test_modes_edges.py")
IMPACT = ("tests/solvers/impact",)
SPIN = ("tests/solvers/steady_spin",)
STEADY = ("tests/solvers/steady_motion",)
REACTIONS = ("tests/solvers/reactions",)
ENERGY = ("tests/solvers/energy",)
KINEMATICS = ("tests/solvers/kinematics",)

MUTANTS: tuple[Mutant, ...] = (
    # model/: T, V, inertia, rotation, time derivatives
    Mutant("T-translation-half", "rbdsolve/model/energies/energy.py",
           "T_translation = body.mass * v.dot(v) / 2", "T_translation = body.mass * v.dot(v)",
           MODEL, "½ m v² without the ½"),
    Mutant("T-rotation-half", "rbdsolve/model/energies/energy.py",
           "* omega)[0, 0] / 2 if", "* omega)[0, 0] if", MODEL, "½ ωᵀJω without the ½"),
    Mutant("V-gravity-sign", "rbdsolve/model/energies/energy.py",
           "V_gravity = -body.mass * model.gravity.dot(body.position)",
           "V_gravity = body.mass * model.gravity.dot(body.position)", MODEL, "V = +m g·r"),
    Mutant("V-spring-half", "rbdsolve/model/energies/energy.py",
           "spring.stiffness * spring.stretch**2 / 2", "spring.stiffness * spring.stretch**2",
           MODEL, "½ k s² without the ½"),
    Mutant("parallel-axis-sign", "rbdsolve/model/inertia.py",
           "return m * (d.dot(d) * sp.eye(3) - d * d.T)", "return m * (d.dot(d) * sp.eye(3) + d * d.T)",
           MODEL, "Steiner's m (|d|² 1 − d dᵀ) with + d dᵀ"),
    Mutant("rod-moment", "rbdsolve/model/inertia.py",
           "return sp.Integer(0), m * L**2 / 12, m * L**2 / 12", "return sp.Integer(0), m * L**2 / 3, m * L**2 / 12",
           MODEL, "a rod's m L²/12 about G taken as m L²/3 about its end (one axis)"),
    Mutant("sphere-moment", "rbdsolve/model/inertia.py",
           "return (2 * m * r**2 / 5,) * 3", "return (2 * m * r**2 / 3,) * 3", MODEL,
           "a solid sphere's 2/5 m r² as a shell's 2/3"),
    Mutant("rodrigues-sign", "rbdsolve/model/rotation.py",
           "sp.cos(angle) * sp.eye(3) + sp.sin(angle) * cross_matrix(n)",
           "sp.cos(angle) * sp.eye(3) - sp.sin(angle) * cross_matrix(n)", MODEL, "a turn the wrong way"),
    Mutant("chain-rule-sign", "rbdsolve/model/state.py",
           "out += d(expr, q) * qd + d(expr, qd) * qdd", "out += d(expr, q) * qd - d(expr, qd) * qdd",
           MODEL, "d/dt with −∂/∂q̇ q̈"),
    # eom
    Mutant("lagrange-sign", "rbdsolve/solvers/eom/exact.py",
           "E = model.state.d_dt(derivative(L, qd)) - derivative(L, q)",
           "E = model.state.d_dt(derivative(L, qd)) + derivative(L, q)", MODEL, "d/dt ∂L/∂q̇ + ∂L/∂q"),
    # equilibria: the sign counts of the Hessian
    Mutant("inertia-count-swapped", "rbdsolve/solvers/conditions/signs.py",
           "return Inertia(positive, zero, n - positive - zero)", "return Inertia(n - positive - zero, zero, positive)",
           EQUILIBRIA, "Descartes' sign changes counted as negative eigenvalues (the reviewer's singular, "
                       "non-diagonal Hessian)"),
    Mutant("sign-of-value", "rbdsolve/solvers/conditions/signs.py",
           "return 0 if z.real == 0 else (1 if z.real > 0 else -1)",
           "return 0 if z.real == 0 else (1 if z.real < 0 else -1)", EQUILIBRIA, "a value's sign flipped"),
    Mutant("negative-diagonal", "rbdsolve/solvers/conditions/signs.py",
           "if any(sign_of(H[i, i], values) == -1 for i in range(n)):",
           "if any(sign_of(H[i, i], values) == 1 for i in range(n)):", EQUILIBRIA,
           "a positive diagonal entry taken for proof of a negative eigenvalue"),
    Mutant("neutral-count", "rbdsolve/solvers/equilibria/exact.py",
           "if len(flat) == inertia.zero:", "if len(flat) != inertia.zero:", EQUILIBRIA,
           "neutral and undetermined swapped where the Hessian is singular"),
    Mutant("numeric-unstable-test", "rbdsolve/solvers/numeric/numeric_model.py",
           "if np.any(eig < -tol):", "if np.any(eig > -tol):", EQUILIBRIA,
           "the numeric search calls a zero curvature unstable"),
    # modes
    Mutant("numeric-mode-kind", "rbdsolve/solvers/modes/numeric.py",
           "return Motion.OSCILLATION if lam > 0 else Motion.GROWTH",
           "return Motion.GROWTH if lam > 0 else Motion.OSCILLATION", MODES, "the numeric route's kinds swapped"),
    Mutant("exact-mode-kind", "rbdsolve/solvers/modes/cases.py",
           "KIND = {1: Motion.OSCILLATION, 0: Motion.NEUTRAL, -1: Motion.GROWTH}",
           "KIND = {1: Motion.GROWTH, 0: Motion.NEUTRAL, -1: Motion.OSCILLATION}", MODES,
           "the exact route's kinds of a case swapped"),
    Mutant("sylvester-sign", "rbdsolve/solvers/modes/cases.py",
           "sign = 1 if counts.positive == len(eigenvalues) else -1 if",
           "sign = -1 if counts.positive == len(eigenvalues) else 1 if", MODES,
           "K positive definite read as every λ negative"),
    Mutant("rate-sign", "rbdsolve/solvers/modes/exact.py",
           "return tidy(sp.sqrt(sign * pair.lam))", "return tidy(sp.sqrt(pair.lam))", MODES,
           "γ = √λ instead of √−λ"),
    # impact
    Mutant("restitution-sign", "rbdsolve/solvers/impact/equations.py",
           "out.append(self.normal_speed(blow, final=True) + e * approach)",
           "out.append(self.normal_speed(blow, final=True) - e * approach)", IMPACT,
           "n·(v − u)_f = +e n·(v − u)_i (the reviewer's flipped restitution)"),
    # steady spin
    Mutant("spin-stability", "rbdsolve/solvers/steady_spin/numeric.py",
           "    if product < 0:\n        return NumericSpin(axis, float(J[k]), Stability.UNSTABLE, rate)",
           "    if product > 0:\n        return NumericSpin(axis, float(J[k]), Stability.UNSTABLE, rate)", SPIN,
           "the intermediate axis stable (numeric route)"),
    Mutant("spin-frequency", "rbdsolve/solvers/steady_spin/exact.py",
           "frequency = tidy(omega * sp.sqrt(tidy_fraction(product / (J[i] * J[j]))))",
           "frequency = tidy(omega * sp.sqrt(tidy_fraction(product / J[i])))", SPIN,
           "Ω √((J_k − J_i)(J_k − J_j)/(J_i J_j)) without J_j"),
    # steady motion
    Mutant("steady-transport", "rbdsolve/solvers/steady_motion/balances.py",
           "found, a_G = [dL + v_P.cross(body.mass * v_G) - M], None",
           "found, a_G = [dL - v_P.cross(body.mass * v_G) - M], None", STEADY,
           "dL/dt about a moving point with −v_P × m v_G"),
    Mutant("steady-frame-rate", "rbdsolve/solvers/steady_motion/balances.py",
           "return (self.model.state.d_dt(r_T) + self.Omega.cross(r_T)).applyfunc(tidy)",
           "return (self.model.state.d_dt(r_T) - self.Omega.cross(r_T)).applyfunc(tidy)", STEADY,
           "a turning triad's rate with −Ω × r"),
    # reactions
    Mutant("reactions-gravity-sign", "rbdsolve/solvers/reactions/balances.py",
           "force = (b.mass * model.gravity) if", "force = (-b.mass * model.gravity) if", REACTIONS,
           "weight pointing up in Newton's law"),
    Mutant("reactions-moment-arm", "rbdsolve/solvers/reactions/balances.py",
           "moment += sign * (s.point - b.position).cross(c.symbol * c.direction)",
           "moment += sign * (b.position - s.point).cross(c.symbol * c.direction)", REACTIONS,
           "a support's moment arm from the point to G"),
    # energy and kinematics
    Mutant("energy-integral-factor", "rbdsolve/solvers/lagrange/energy_integral.py",
           "rate_squared = clean_fraction(2 * (h0 - (h - T2)) / M)",
           "rate_squared = clean_fraction((h0 - (h - T2)) / M)", ENERGY, "q̇² = (E − V)/M without the 2"),
    Mutant("speed-root", "rbdsolve/solvers/kinematics/exact.py",
           "return sp.sqrt(tidy(sp.expand(m.dot(m).xreplace(state))))",
           "return tidy(sp.expand(m.dot(m).xreplace(state)))", KINEMATICS, "a speed as v², without its root"),
)


def copy_tree(to: Path) -> None:
    for name in COPIED:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, to / name, ignore=shutil.ignore_patterns("__pycache__", "results", "*.pyc"))
        elif src.exists():
            shutil.copy2(src, to / name)


def check(mutant: Mutant) -> str | None:
    """Why the mutant cannot be applied (its text not once in the file), or None."""
    path = ROOT / mutant.path
    if not path.exists():
        return f"{mutant.path} does not exist"
    n = path.read_text().count(mutant.before)
    return None if n == 1 else f"its text occurs {n} times in {mutant.path}"


def run_tests(tree: Path, tests: tuple[str, ...], timeout: float) -> tuple[int, float, str]:
    """pytest's exit code (−1 on timeout), the wall seconds and the last line of its output."""
    env = dict(os.environ, PYTHONPATH=str(tree), PYTHONHASHSEED="0")
    cmd = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-n", "0", "-x", "-q", *tests]
    start = time.perf_counter()
    try:
        done = subprocess.run(cmd, cwd=tree, env=env, capture_output=True, text=True, timeout=timeout)
        code, out = done.returncode, done.stdout
    except subprocess.TimeoutExpired as exc:
        code, out = -1, (exc.stdout.decode() if isinstance(exc.stdout, bytes) else exc.stdout or "")
    lines = [ln for ln in out.splitlines() if ln.strip()]
    failed = next((ln for ln in lines if ln.startswith("FAILED") or ln.startswith("ERROR")), "")
    return code, time.perf_counter() - start, failed or (lines[-1] if lines else "")


def verdict(code: int) -> str:
    """pytest's exit code read: 0 all passed, 1 a test failed, −1 our timeout (the mutant
    made a test hang: killed, a hang is caught too); anything else is an error."""
    return {0: "survived", 1: "killed", -1: "killed"}.get(code, "error")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python3 -m benchmarks.mutants", description=__doc__.split("\n\n")[0])
    ap.add_argument("--only", default="", help="comma-separated mutant names")
    ap.add_argument("--list", action="store_true", help="list the mutants and check that each applies")
    ap.add_argument("--timeout", type=float, default=1800.0, help="seconds per test run (a hang counts as killed)")
    ap.add_argument("--jobs", type=int, default=1, help="mutants at once, each in its own copy of the tree")
    ap.add_argument("--no-baseline", action="store_true",
                    help="skip running each selection unmutated first (when the whole suite is known to pass)")
    args = ap.parse_args(argv)
    chosen = [m for m in MUTANTS if not args.only or m.name in args.only.split(",")]
    problems = {m.name: why for m in chosen if (why := check(m))}
    if args.list:
        for m in chosen:
            print(f"{m.name:24} {m.path:48} {problems.get(m.name, 'applies')}: {m.what}")
        return 1 if problems else 0
    with tempfile.TemporaryDirectory(prefix="mutants-") as tmp:
        trees: queue.Queue = queue.Queue()
        for k in range(max(1, args.jobs)):
            tree = Path(tmp) / str(k)
            copy_tree(tree)
            trees.put(tree)
        baseline: dict[tuple[str, ...], str] = {}
        if not args.no_baseline:
            selections = sorted({m.tests for m in chosen if m.name not in problems})
            with ThreadPoolExecutor(max(1, args.jobs)) as pool:
                for tests, why in zip(selections, pool.map(lambda t: _baseline(trees, t, args.timeout), selections)):
                    baseline[tests] = why
        with ThreadPoolExecutor(max(1, args.jobs)) as pool:
            results = list(pool.map(lambda m: _one(trees, m, problems, baseline, args.timeout), chosen))
    print(table(results))
    print(summary(results))
    return 0


def _baseline(trees: queue.Queue, tests: tuple[str, ...], timeout: float) -> str:
    tree = trees.get()
    try:
        code, _, line = run_tests(tree, tests, timeout)
    finally:
        trees.put(tree)
    return "" if code == 0 else f"the tests fail without a mutant: {line}"


def _one(trees: queue.Queue, m: Mutant, problems: dict, baseline: dict, timeout: float):
    """(mutant, verdict, seconds, first failing test) of one mutant, in a free copy."""
    if m.name in problems:
        return m, "error", 0.0, problems[m.name]
    if baseline.get(m.tests):
        return m, "error", 0.0, baseline[m.tests]
    tree = trees.get()
    target = tree / m.path
    original = target.read_text()
    try:
        target.write_text(original.replace(m.before, m.after))
        code, seconds, line = run_tests(tree, m.tests, timeout)
    finally:
        target.write_text(original)
        trees.put(tree)
    print(f"{m.name:24} {verdict(code):9} {seconds:6.0f} s  {line[:100]}", file=sys.stderr, flush=True)
    return m, verdict(code), seconds, line if code else ""


def table(results) -> str:
    rows = ["| mutant | file | the slip | verdict | s | first failing test |", "|---|---|---|---|---|---|"]
    for m, v, s, line in results:
        rows.append(f"| {m.name} | {m.path.removeprefix('rbdsolve/')} | {m.what} | {v} | {s:.0f} | "
                    f"{line.replace('|', '/')[:120]} |")
    return "\n".join(rows)


def summary(results) -> str:
    killed = sum(1 for _, v, _, _ in results if v == "killed")
    survived = [m.name for m, v, _, _ in results if v == "survived"]
    errors = [m.name for m, v, _, _ in results if v == "error"]
    scored = killed + len(survived)
    score = 100.0 * killed / scored if scored else 0.0
    tail = f", {len(errors)} errors ({', '.join(errors)})" if errors else ""
    return (f"mutants: {killed} killed of {scored} (score {score:.0f} %), {len(survived)} survived"
            f" ({', '.join(survived) or 'none'}){tail}")


if __name__ == "__main__":
    sys.exit(main())
