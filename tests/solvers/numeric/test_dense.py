"""The numeric routes' dense linear algebra on numpy alone (solvers/numeric/dense.py),
against scipy.linalg's LAPACK drivers as the independent oracle (dsygv for K a = λ M a,
the SVD's null space, QZ for a pencil), on random matrices of an exam's sizes and on
ill-conditioned ones; and the routes themselves import no scipy."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg

from rbdsolve.solvers.numeric import dense

ROOT = Path(__file__).resolve().parents[3]


def _symmetric_pair(rng: np.random.Generator, n: int, spread: float = 1.0):
    """K symmetric (indefinite), M symmetric positive definite with eigenvalues spread
    over ``spread`` decades."""
    K = rng.normal(size=(n, n))
    Q, _ = np.linalg.qr(rng.normal(size=(n, n)))
    M = Q @ np.diag(10.0 ** np.linspace(0, -spread, n)) @ Q.T
    return (K + K.T) / 2, (M + M.T) / 2


@pytest.mark.parametrize("n", [1, 2, 3, 6])
@pytest.mark.parametrize("spread", [0.0, 6.0])
def test_the_symmetric_pencil_is_lapack_s(n: int, spread: float) -> None:
    rng = np.random.default_rng(100 * n + int(spread))
    K, M = _symmetric_pair(rng, n, spread)
    lam, vectors = dense.symmetric_pencil(K, dense.cholesky_lower(M))
    oracle = scipy.linalg.eigh(K, M, eigvals_only=True)
    scale = np.max(np.abs(oracle)) * 10.0**spread
    assert np.all(np.diff(lam) >= 0)
    np.testing.assert_allclose(lam, oracle, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(dense.symmetric_pencil_values(K, M), oracle, rtol=0, atol=1e-12 * scale)
    # each column a pair of the pencil: K a = λ M a
    residual = K @ vectors - M @ vectors * lam
    assert np.max(np.abs(residual)) <= 1e-10 * scale * np.max(np.abs(vectors))


def test_a_mass_matrix_that_is_not_positive_definite_is_refused() -> None:
    with pytest.raises(dense.LinAlgError):
        dense.cholesky_lower(np.array([[1.0, 2.0], [2.0, 1.0]]))


@pytest.mark.parametrize("shape, rank", [((1, 3), 1), ((2, 4), 2), ((3, 3), 2), ((2, 2), 0)])
def test_the_null_space_spans_scipy_s(shape, rank: int) -> None:
    rng = np.random.default_rng(sum(shape) + rank)
    A = rng.normal(size=(shape[0], rank)) @ rng.normal(size=(rank, shape[1]))
    mine, oracle = dense.null_space(A), scipy.linalg.null_space(A)
    assert mine.shape == oracle.shape == (shape[1], shape[1] - rank)
    # the same space: equal orthogonal projectors, and A kills it
    np.testing.assert_allclose(mine @ mine.T, oracle @ oracle.T, atol=1e-12)
    np.testing.assert_allclose(mine.T @ mine, np.eye(mine.shape[1]), atol=1e-12)
    assert np.max(np.abs(A @ mine), initial=0.0) <= 1e-12 * max(1.0, np.max(np.abs(A)))


@pytest.mark.parametrize("n", [1, 2, 3])
def test_a_gyroscopic_pencil_s_eigenvalues_are_qz_s(n: int) -> None:
    """[[0, 1], [−K, −G]] z = s [[1, 0], [0, M]] z, G skew: the first-order form of
    M ü + G u̇ + K u = 0 (solvers/modes/gyroscopic_numeric.py)."""
    rng = np.random.default_rng(7 + n)
    K, M = _symmetric_pair(rng, n, 2.0)
    G = rng.normal(size=(n, n))
    G = G - G.T
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-K, -G]])
    B = np.block([[np.eye(n), np.zeros((n, n))], [np.zeros((n, n)), M]])
    mine, oracle = dense.pencil_eigenvalues(A, B), scipy.linalg.eig(A, B, right=False)
    # paired by nearness, not by sort_complex: a real part of rounding size (1e-14 against
    # 2e-15 on another LAPACK) would order a conjugate pair either way
    assert len(mine) == len(oracle)
    left = list(oracle)
    for z in mine:
        nearest = min(range(len(left)), key=lambda k: abs(left[k] - z))
        assert abs(left.pop(nearest) - z) <= 1e-12 + 1e-10 * abs(z)


def test_a_singular_mass_matrix_has_no_pencil_eigenvalues() -> None:
    B = np.diag([1.0, 0.0])
    with pytest.raises(dense.LinAlgError):
        dense.pencil_eigenvalues(np.eye(2), B)


SCENE = """\
title: A double pendulum on the numeric route
parameters: {m: mass, l: length, g: gravity}
values: {m: 1, l: 1, g: 9.81}
coordinates: [a, b]
gravity: [0, -g]
points:
  P: l*[sin(a), -cos(a)]
  Q: P + l*[sin(b), -cos(b)]
bodies:
  p: {shape: particle, mass: m, at: P}
  q: {shape: particle, mass: m, at: Q}
questions:
  - equilibria
  - modes: {about: {a: 0, b: 0}}
"""


def test_the_numeric_route_imports_no_scipy(tmp_path: Path) -> None:
    """Equilibria (Newton from a grid) and modes on the numeric route, in a process of
    their own: importing scipy.optimize and scipy.linalg would be ~0.4 s of it."""
    scene = tmp_path / "double.yaml"
    scene.write_text(SCENE, encoding="utf-8")
    code = ("import sys; from rbdsolve.cli.app import main\n"
            f"sys.argv = ['rbdsolve', 'solve', '--route', 'numeric', '--format', 'json', {str(scene)!r}]\n"
            "try:\n    main()\nexcept SystemExit as e:\n    code = e.code\n"
            "print('EXIT', code, sorted(m for m in sys.modules if m.split('.')[0] == 'scipy'))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                          env={"PYTHONPATH": str(ROOT)}, timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    last = done.stdout.strip().splitlines()[-1]
    assert last == "EXIT 0 []", last
    assert '"route": "numeric"' in done.stdout
