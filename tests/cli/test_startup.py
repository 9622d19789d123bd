"""Start-up: the commands that do no algebra load none (docs/architecture.md, rule 5),
and a command loads no other command's module, nor machinery its problem does not use.
Each runs in a fresh interpreter, which then reports what it imported."""

from __future__ import annotations

import subprocess
import sys

import pytest

from conftest import ROOT, SEED
from rbdsolve.cli.app import COMMANDS

HEAVY = ("sympy", "numpy", "scipy", "matplotlib")
COMMAND_MODULES = tuple(f"rbdsolve.cli.{name}" for name in COMMANDS)  # each imported when its command runs
# imported only for a scene or question that uses them: seed problem 1 has none
FEATURES = ("rbdsolve.model.constraints.contacts", "rbdsolve.model.constraints.plane_rolling", "rbdsolve.solvers.modes.amplitude",
            "rbdsolve.solvers.conditions.monotone", "rbdsolve.model.energies.frames", "rbdsolve.model.summary.frame",
            "rbdsolve.solvers.modes.gyroscopic", "rbdsolve.solvers.modes.routh", "rbdsolve.model.energies.gyroscopic",
            # a scene's contacts, springs, loads, frames (and their readers), the other questions' options
            "rbdsolve.problem.scene", "rbdsolve.problem.options", "rbdsolve.problem.sections.contacts",
            "rbdsolve.problem.sections.loads", "rbdsolve.problem.sections.impact",
            # roots of degree ≥ 5 as certified decimals; where the numeric route would search
            "rbdsolve.solvers.modes.certified", "rbdsolve.solvers.numeric.search_box",
            # the units and the numeric block of answers with values (seed problem 1 has none)
            "rbdsolve.model.values.units", "rbdsolve.model.values.numbers")
TERMINAL = ("rich.console",)  # a solution written to a pipe or a file is laid out without it (render/text.py)
WATCHED = HEAVY + COMMAND_MODULES + FEATURES + TERMINAL


def loaded_after(*args: str) -> set[str]:
    """Which of WATCHED the command ``args`` imported."""
    code = ("import sys; from rbdsolve.cli import main\n"
            f"try: main({list(args)!r}, standalone_mode=False)\n"
            f"finally: print(','.join(m for m in {WATCHED!r} if m in sys.modules), file=sys.stderr)")
    done = subprocess.run([sys.executable, "-c", code], check=False, capture_output=True,
                          text=True, cwd=ROOT, env={"PYTHONPATH": str(ROOT)}, timeout=60)
    assert done.returncode == 0, done.stderr
    last = done.stderr.rstrip("\n").rpartition("\n")[2]
    return {m for m in last.split(",") if m}


@pytest.mark.parametrize("args", [["--help"], ["solve", "--help"], ["key", "--help"],
                                  ["check", str(SEED / "p1-two-rods.yaml")]])
def test_commands_without_algebra_load_no_sympy(args: list[str]) -> None:
    assert loaded_after(*args) - set(COMMAND_MODULES) == set()


def test_help_imports_no_command() -> None:
    assert loaded_after("--help") == set()


def test_the_probe_sees_an_import() -> None:
    """The check itself: solving loads sympy, and the probe says so."""
    loaded = loaded_after("solve", "--quiet", "--format", "json", str(SEED / "p1-two-rods.yaml"))
    assert "sympy" in loaded
    assert loaded & set(COMMAND_MODULES) == {"rbdsolve.cli.solve"}  # no other command's module
    assert not loaded & set(FEATURES)  # no contacts, loads, check_amplitudes, θ = k sin θ, frame, spin


def test_a_solution_to_a_pipe_loads_no_rich_console() -> None:
    """Text without colour (standard output a pipe here) is laid out without rich's console."""
    loaded = loaded_after("solve", "--quiet", str(SEED / "p1-two-rods.yaml"))
    assert "sympy" in loaded and not loaded & set(TERMINAL)


def ground_types_after(env: dict[str, str], settings: bool = True) -> str:
    """sympy's ground types in a fresh interpreter that first makes the rbdsolve
    process's settings (or, not ``settings``, none: sympy's own choice)."""
    code = ("import sys; from rbdsolve.cli.app import process_settings\n"
            + ("process_settings()\n" if settings else "")
            + "from sympy.external.gmpy import GROUND_TYPES\nprint(GROUND_TYPES)")
    done = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True, cwd=ROOT,
                          env={"PYTHONPATH": str(ROOT), **env}, timeout=60)
    return done.stdout.strip()


def test_the_process_leaves_sympy_its_own_integers() -> None:
    """sympy takes python-flint's integers where it is installed (it is: the certified
    roots use it), which factor several times faster; the rbdsolve process does not
    override that choice, and a user's SYMPY_GROUND_TYPES still decides."""
    assert ground_types_after({}) == ground_types_after({}, settings=False)
    assert ground_types_after({"SYMPY_GROUND_TYPES": "python"}) == "python"
