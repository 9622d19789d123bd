"""Shared helpers for the test suite."""

from __future__ import annotations

import functools
import os
import re
import shutil
import subprocess
import sys
import time
from fractions import Fraction
from pathlib import Path

import pytest
import sympy as sp

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = ROOT / "problems"
SEED = PROBLEMS / "sg2150-2015-10-29"


@functools.lru_cache(maxsize=None)
def solved_file(path: Path):
    """(model, report) of a problem file, solved once per test process: the golden
    answers, the JSON read-back, the audit and the LaTeX compile each check every file
    in problems/, and a
    process that runs two of them for one file solves it once (they are collected side
    by side, ``pytest_collection_modifyitems``, and pytest-xdist's worksteal hands each
    process a run of neighbouring tests). The report is read, never changed (frozen
    dataclasses)."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_file
    from rbdsolve.solvers import solve_problem

    model = build_model(load_file(path))
    return model, solve_problem(model)


def solved_scene(folder: Path, text: str, name: str = "scene.yaml"):
    """The one question's answer of a scene written to ``folder`` as a user's file, through
    the Python API, with a budget far from the work (no test depends on the clock)."""
    import rbdsolve

    path = folder / name
    path.write_text(text, encoding="utf-8")
    (solution,) = rbdsolve.solve(path, budget=1200.0)
    return solution


def counted_calls(monkeypatch, owner, name: str) -> list[tuple]:
    """The arguments of every call of ``owner.name`` from here on (it still does its
    work): a test that some work is done once counts its calls."""
    calls: list[tuple] = []
    real = getattr(owner, name)

    def counted(*args, **kwargs):
        calls.append(args)
        return real(*args, **kwargs)

    monkeypatch.setattr(owner, name, counted)
    return calls


def fresh_process(code: str) -> list[str]:
    """The lines a Python program printed, run in a process of its own with this
    checkout on its path: what a run imports (``sys.modules``) is seen only there."""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                          env={"PYTHONPATH": str(ROOT)}, timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip().splitlines()


def needs_tex() -> None:
    """Skip without a TeX engine, except in CI, which installs TeX Live (.ci/run): there
    a missing pdflatex is a failure, so the key's LaTeX is compiled on every change."""
    if shutil.which("pdflatex") is None:
        if os.environ.get("CI"):
            pytest.fail("CI installs TeX Live (.ci/run), but pdflatex is not on PATH")
        pytest.skip("no TeX engine installed")


def spin(seconds: float) -> None:
    """Spend ``seconds`` of processor time, the clock of rbdsolve's budgets (forever for
    inf): work a budget must stop, where time.sleep would spend none."""
    end = time.process_time() + seconds
    while time.process_time() < end:
        sum(range(1000))


def read_back(text: str, names: dict[str, sp.Symbol] | None = None) -> sp.Expr:
    """Read an exact answer string the way a script would: sympify, with parameters as
    positive symbols (as declared in the problem files) so that sqrt(g/r) = sqrt(g)/sqrt(r)."""
    expr = sp.sympify(text, locals=names or {})
    return expr


_NAMES = re.compile(r"\b([A-Za-z_]\w*)\b(?!\s*\()")  # a name not called as a function


def positive_names(*texts: str) -> dict[str, sp.Symbol]:
    """Positive symbols for every free name in these strings, except t; a parameter
    named as one of sympy's functions (beta, gamma: the angle of a slope) is a symbol."""
    out: dict[str, sp.Symbol] = {name: sp.Symbol(name, positive=True) for text in texts
                                 for name in _NAMES.findall(text)
                                 if isinstance(getattr(sp, name, None), sp.FunctionClass)}
    for text in texts:
        for s in getattr(sp.sympify(text, locals=dict(out)), "free_symbols", set()):
            if s.name != "t":
                out[s.name] = sp.Symbol(s.name, positive=True)
    out["t"] = sp.Symbol("t", real=True)
    return out


def same(a: str, b: str) -> bool:
    """Exact equality of two answer strings: simplify(a − b) == 0, after writing every
    radicand in factored form (so √((m1+m2)(…)) and √(m1+m2)·√(expanded …) meet)."""
    names = positive_names(a, b)
    x, y = sp.sympify(a, locals=names), sp.sympify(b, locals=names)
    if isinstance(x, (bool, sp.logic.boolalg.BooleanAtom)) or isinstance(y, (bool, sp.logic.boolalg.BooleanAtom)):
        return bool(x) == bool(y)  # a condition that always holds: "True"
    if isinstance(x, sp.core.relational.Relational) or isinstance(y, sp.core.relational.Relational):
        return _same_condition(x, y)
    if isinstance(x, (sp.And, sp.Or)) or isinstance(y, (sp.And, sp.Or)):
        return _same_compound(x, y)
    return sp.simplify(_canonical_radicands(x - y)) == 0


def _same_compound(x, y) -> bool:
    """Two conditions joined by & (or by |) the same: each part of one the same as a part
    of the other (in any order), part for part."""
    if type(x) is not type(y) or len(x.args) != len(y.args):
        return False
    left = list(y.args)
    for a in x.args:
        match = next((b for b in left if _same_part(a, b)), None)
        if match is None:
            return False
        left.remove(match)
    return True


def _same_part(a, b) -> bool:
    if isinstance(a, (sp.And, sp.Or)) or isinstance(b, (sp.And, sp.Or)):
        return _same_compound(a, b)
    return _same_condition(a, b)


def _same_condition(x, y) -> bool:
    """One inequality written two ways: the same direction after moving everything to
    one side (p < c as c > p), and the sides equal."""
    def normal(r):
        if r.rel_op in ("<", "<="):
            return r.rel_op.replace("<", ">"), r.rhs - r.lhs
        return r.rel_op, r.lhs - r.rhs
    if not (isinstance(x, sp.core.relational.Relational) and isinstance(y, sp.core.relational.Relational)):
        return False
    (op_x, dx), (op_y, dy) = normal(x), normal(y)
    return op_x == op_y and sp.simplify(_canonical_radicands(dx - dy)) == 0


def _canonical_radicands(expr: sp.Expr) -> sp.Expr:
    return expr.replace(
        lambda e: e.is_Pow and e.exp.is_Rational and not e.exp.is_Integer,
        lambda e: sp.Pow(sp.factor(sp.expand(e.base)), e.exp),
    )


@pytest.fixture
def problems_dir() -> Path:
    return PROBLEMS


# A particle pendulum (θ from the downward vertical); tests add values and questions.
SIMPLE_PENDULUM = """\
parameters: {m: mass, l: length, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
"""

# A cart (x) carrying a pendulum (θ) on a massless link; tests add values and questions.
CART_PENDULUM = """\
parameters: {m: mass, M: cart mass, l: length, g: gravity}
coordinates: [x, theta]
gravity: [0, -g]
points:
  C: [x, 0]
  P: C + l * [sin(theta), -cos(theta)]
bodies:
  cart: {shape: particle, mass: M, at: C}
  bob: {shape: particle, mass: m, at: P}
"""

# A uniform rod pivoted at one end (θ from the downward vertical), with a stiffness c for
# tests that add a torsional spring; tests add springs and questions.
ROD_PENDULUM = """\
parameters: {m: mass, l: length, g: gravity, c: stiffness}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2 * [sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta}
"""


# --- an n-link chain (tests/model/numeric/test_numeric.py, tests/solvers/modes/test_numeric_chains.py)


def chain(n: int, rods: bool) -> str:
    """Links of length l hanging from O: P_i = P_(i−1) + l [sin θ_i, −cos θ_i]; a particle
    at each P_i, or a rod along each link (its centre at the midpoint)."""
    lines = ["parameters: {m: mass, l: length, g: gravity}",
             f"coordinates: [{', '.join(f'th{i}' for i in range(1, n + 1))}]",
             "gravity: [0, -g]", "points:", "  P0: [0, 0]"]
    bodies = ["bodies:"]
    for i in range(1, n + 1):
        lines.append(f"  P{i}: P{i - 1} + l*[sin(th{i}), -cos(th{i})]")
        if rods:
            lines.append(f"  G{i}: P{i - 1} + l/2*[sin(th{i}), -cos(th{i})]")
            bodies.append(f"  rod{i}: {{shape: rod, mass: m, length: l, at: G{i}, angle: th{i} - pi/2}}")
        else:
            bodies.append(f"  bob{i}: {{shape: particle, mass: m, at: P{i}}}")
    return "\n".join(lines + bodies + ["questions: [modes]", ""])


def hand_matrices(n: int, rods: bool, m, l, g) -> tuple[list, list]:
    """M and K at q = 0 (1-based i, j). At q = 0 each point moves horizontally by
    Σ_(j below) l θ̇_j, and V = −m g Σ y has ∂²V/∂θ_j² = m g l × (the mass below joint j).

    Particles: M_ij = m l² (n − max(i, j) + 1),  K_ii = m g l (n − i + 1).
    Rods (centre at the link's half, J = m l²/12): M_ij = m l² (n − j + 1/2) for i < j,
    M_ii = m l² (n − i + 1/3) (= n − i + 1/4 + 1/12), K_ii = m g l (n − i + 1/2)."""
    half = Fraction(1, 2) if rods else 0
    M = [[0] * n for _ in range(n)]
    K = [[0] * n for _ in range(n)]
    for i in range(1, n + 1):
        for j in range(1, n + 1):
            below = n - max(i, j) + 1
            if i == j:
                M[i - 1][j - 1] = m * l**2 * (below - (Fraction(2, 3) if rods else 0))
                K[i - 1][j - 1] = m * g * l * (below - half)
            else:
                M[i - 1][j - 1] = m * l**2 * (below - half)
    return M, K


# A bead on a rod turning at Ω about z, held by a spring of natural length a from the
# axis, x measured from the natural length. By hand, in the rod's frame: the spring's
# length is |a + x|, a + x on the side it is drawn (x = 0), so while a + x > 0
# V' = ½ k x² − ½ m Ω² (a + x)², ∂V'/∂x = k x − m Ω² (a + x) = 0 at
# x₀ = m Ω² a/(k − m Ω²), where a + x₀ = k a/(k − m Ω²): positive only for k > m Ω²,
# that is Ω < √(k/m). Past it the bead would sit beyond the axis, where the true
# V'(x) = ½ k (|a + x| − a)² − ½ m Ω² (a + x)² has a slope at x₀: no equilibrium.
# K = k − m Ω² > 0 wherever it exists: stable, λ = (k − m Ω²)/m an oscillation.
TURNING_ROD = """
parameters: {m: mass, k: stiffness, a: natural length, Omega: rate}
coordinates: [x]
frames:
  rod: {axis: z, rate: Omega}
points:
  O: "[0, 0, 0]"
  P: (a + x)*[cos(Omega*t), sin(Omega*t), 0]
bodies:
  bead: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [P, O], natural_length: a}
questions:
  - equilibria: {frame: rod}
  - modes: {frame: rod, about: each}
"""


# A bob of mass m at P = (l φ, y(φ)) in gravity: V = m g y, so ∂V/∂φ and its higher
# derivatives are y's, times m g (equilibria tests write y; ``.replace("{HEIGHT}", …)``).
BOB_AT_HEIGHT = """\
parameters: [m, l, g]
coordinates: [phi]
gravity: [0, -g]
points:
  P: "[l*phi, {HEIGHT}]"
bodies:
  bob: {shape: particle, mass: m, at: P}
questions:
  - equilibria
"""


# A hoop (m, r) rolling on an incline at α, x up the slope, its centre tied by a spring
# (k, natural length l₀) to W, l₀ straight above its start, released from rest at x = 0
# (a new user's trial). Tests add values (``+ "values: …"``).
HOOP_ON_INCLINE = """\
title: a hoop on an incline held by a spring
parameters: {m: mass, r: radius, k: stiffness, l0: natural length, alpha: angle, g: gravity}
coordinates: [x]
gravity: [0, -g]
points:
  W: "r*[-sin(alpha), cos(alpha)] + [0, l0]"
bodies:
  hoop: {shape: ring, mass: m, radius: r}
contacts:
  C: {body: hoop, rolls_on: {line: {through: [0, 0], angle: alpha}}, along: x}
springs:
  s: {stiffness: k, between: [hoop, W], natural_length: l0}
questions:
  - reactions: {forces: [C], from_rest: {x: 0}}
"""


# A disk (radius r) rolling inside a circular track (radius R) in a vertical plane, θ
# from the downward vertical: N = m (R − r) θ̇² + m g cos θ, F = −m g sin θ/3. Values and
# the question are the test's own.
DISK_IN_TRACK = """\
parameters: [m, r, R, g]
coordinates: [theta]
gravity: [0, -g]
bodies:
  disk: {shape: disk, mass: m, radius: r}
contacts:
  C: {body: disk, rolls_on: {circle: {centre: [0, 0], radius: R, side: inside}}, along: theta}
"""


# A square plate (m, side a) hung from a corner O, its centre a/√2 from it, turned by a
# couple C: V = −(m g a/√2) cos θ − C θ (a new user's trial).
PLATE_ON_A_CORNER = """title: a square plate hung from a corner, turned by a couple
parameters: {m: mass, a: side, g: acceleration of gravity, C: moment}
coordinates: [theta]
gravity: [0, -g]
points:
  G: "a/sqrt(2)*[sin(theta), -cos(theta)]"
bodies:
  plate: {shape: plate, mass: m, width: a, height: a, at: G, angle: theta}
couples:
  turn: {on: plate, moment: C}
questions:
  - equilibria
"""


# A rod OA (m, L) pinned at O on a plane inclined at α (gravity's part in it g sin α), θ
# from up the slope, its end A held by a horizontal spring (k, zero length) to a slider
# level with it on the up-slope line: stretch L sin θ, V = m g sin α (L/2) cos θ + ½ k L²
# sin²θ. Tests add a load at A and the questions (``+ "questions: …"``).
ROD_ON_INCLINE = """\
parameters: {m: mass of the rod, L: length, k: stiffness, g: gravity, alpha: incline}
coordinates: [theta]
gravity: [0, -g*sin(alpha)]
points:
  A: L*[sin(theta), cos(theta)]
  S: [0, L*cos(theta)]
  G: L/2*[sin(theta), cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: L, at: G, angle: -theta, axis: y}
springs:
  s: {stiffness: k, between: [A, S]}
"""


def pytest_collection_modifyitems(config, items) -> None:
    """Each problem file's checks side by side (its golden answers, JSON read-back, audit
    and LaTeX compile, each in its own module), at the place of the first: pytest-xdist's worksteal
    (pyproject.toml) gives each process a contiguous run of tests and takes from the end
    of one only when another runs dry, so a file is solved once in the suite, not once
    in each process its checks happen to reach (``solved_file``: 2 × 110 processor
    seconds on 2 cores, with tests dealt one by one). Grouping them with --dist loadgroup
    instead made the suite slower (17 min against 13): whole groups balance worse."""
    anchor: dict[Path, int] = {}
    keys = []
    for index, item in enumerate(items):
        problem = _problem_file(item)
        keys.append((anchor.setdefault(problem, index) if problem else index, index))
    items[:] = [item for _, item in sorted(zip(keys, items), key=lambda pair: pair[0])]


def _problem_file(item) -> Path | None:
    """The problem file a parametrized test checks, if it checks one of problems/."""
    params = getattr(getattr(item, "callspec", None), "params", {})
    for name in ("path", "expected_file"):
        value = params.get(name)
        if isinstance(value, Path) and PROBLEMS in value.parents:
            return value.with_name(value.name.replace(".expected.yaml", ".yaml"))
    return None
