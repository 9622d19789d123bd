"""sympy#28621 (sympy 1.14): sqrt of some large integers raised ``ValueError: … is not a
prime factor of …`` from the factor cache; a problem file reaches such integers with
numbers near 1e±300. With rbdsolve.form imported, they are computed."""

from __future__ import annotations

import math

import sympy as sp
from click.testing import CliRunner

import rbdsolve.form  # noqa: F401 - applies the work-around
from rbdsolve.cli import main

from conftest import PROBLEMS


def test_the_upstream_example_is_computed() -> None:
    a, b = 989034254522489566, 989034254830458946
    value = (sp.sqrt(a) / 10**9) * (sp.sqrt(b) / 10**9)
    assert math.isclose(float(value), math.sqrt(a) * math.sqrt(b) / 1e18, rel_tol=1e-15)
    factors = sp.factorint(978188756923448938700236182276357436, limit=2**15, use_rho=False, use_pm1=False)
    assert math.prod(p**k for p, k in factors.items()) == 978188756923448938700236182276357436


def test_a_file_with_a_length_over_1e_minus_300_is_solved(tmp_path) -> None:
    """The rod in a bowl with its radius R written R/1e-300: found by the mutation fuzzer."""
    text = (PROBLEMS / "examples" / "rod-in-bowl.yaml").read_text(encoding="utf-8")
    path = tmp_path / "p.yaml"
    assert "G: O + R/2 * [sin(theta), -cos(theta)]" in text
    path.write_text(text.replace("R/2 * [sin", "R/1e-300 * [sin"), encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--budget", "20", "-f", "json"])
    assert result.exit_code in (0, 1) and "internal error" not in result.output, result.output
