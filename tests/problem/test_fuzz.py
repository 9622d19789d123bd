"""Fuzzing the whole tool (hypothesis): random valid scenes, and random mutations of
the golden problem files, go through the command line in-process.

Invariants: the exit code is 0, 1 or 2 (never 3, an internal error); no traceback;
a file that is refused (exit 2) gets one line, located ``file:line:column:``; and the
run stays within its budget (``--budget`` per question and for the model).

The default run is bounded (FUZZ_EXAMPLES examples per test, well under a minute on
two cores). A longer run, before a release or after touching the loader:

    RBDSOLVE_FUZZ_EXAMPLES=5000 python3 -m pytest tests/problem/test_fuzz.py

A crash found here is fixed in the module that owns it, and its smallest failing
file joins the corpus in tests/problem/bad/.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from rbdsolve.cli import main

from conftest import PROBLEMS

FUZZ_EXAMPLES = int(os.environ.get("RBDSOLVE_FUZZ_EXAMPLES", "30"))  # more on demand: RBDSOLVE_FUZZ_EXAMPLES=500
BUDGET = 2.0
# On CI the examples are derandomized (the same every run): a merge is not blocked by a
# crash drawn by chance in code it did not touch; local runs keep exploring new ones.
FUZZ = settings(max_examples=FUZZ_EXAMPLES, deadline=None, derandomize=bool(os.environ.get("CI")),
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("fuzz")


def run_file(path: Path, text: str | bytes, questions: int) -> tuple[int, str]:
    """Solve one file through the CLI; check the invariants every run shares."""
    path.write_bytes(text if isinstance(text, bytes) else text.encode("utf-8", "surrogatepass"))
    result = CliRunner().invoke(main, ["solve", str(path), "--budget", str(BUDGET), "-f", "json"])
    assert result.exit_code in (0, 1, 2), f"{result.exit_code}: {result.output}\n{text}"
    assert "Traceback" not in result.output and "internal error" not in result.output, result.output
    # a runaway (a budget not enforced) is no longer timed here: the budget counts processor
    # time, so it stops the same work on a quiet machine and a loaded one, and test_budget
    # shows that it stops work; a run that never ends hangs the suite, which CI reports
    return result.exit_code, result.stderr


# --- random valid scenes --------------------------------------------------------------

@st.composite
def scenes(draw) -> tuple[str, int]:
    coordinates = draw(st.sampled_from([["theta"], ["x"], ["theta", "phi"], ["theta", "x"]]))
    lines = ["title: fuzzed scene", "parameters: {m: mass, l: length, k: stiffness, g: gravity, a: offset}",
             f"coordinates: [{', '.join(coordinates)}]"]
    gravity = draw(st.sampled_from([None, "[0, -g]", "[0, g]", "[g, 0]", "[0, 0, -g]"]))
    if gravity:
        lines.append(f"gravity: {gravity}")
    if draw(st.booleans()):
        lines.append("values: {m: 2, l: 1/2, k: 3, g: 9.81, a: 1}")
    lines += ["points:", "  A: [a, 0]"]
    for i, q in enumerate(coordinates):
        base = f"P{i - 1} + " if i and draw(st.booleans()) else ""
        scale = draw(st.sampled_from(["l", "l/2", "2*l", "a"]))
        if q == "x":
            vec = draw(st.sampled_from(["[x, 0]", "[0, x]", "[x, l]"]))
        else:
            vec = draw(st.sampled_from([f"{scale} * [sin({q}), -cos({q})]", f"{scale} * [cos({q}), sin({q})]"]))
        lines.append(f"  P{i}: {base}{vec}")
    lines.append("bodies:")
    for i, q in enumerate(coordinates):
        angle = q if q != "x" else "0"
        shape = draw(st.sampled_from([
            "shape: particle", f"shape: rod, length: l, angle: {angle}", f"shape: disk, radius: l, angle: {angle}"]))
        lines.append(f"  b{i}: {{{shape}, mass: {draw(st.sampled_from(['m', '2*m', 'm/3']))}, at: P{i}}}")
    spring = draw(st.sampled_from([None, "between: [P0, A]", "between: [P0, A], natural_length: l",
                                   f"angle: {coordinates[0]}"]))
    if spring:
        lines += ["springs:", f"  s: {{stiffness: k, {spring}}}"]
    about = ", ".join(f"{q}: 0" for q in coordinates)
    kinds = draw(st.lists(st.sampled_from(
        ["eom", "equilibria", "modes", f"modes: {{about: {{{about}}}}}", "inertia: {body: b0}"]),
        min_size=1, max_size=2, unique=True))
    lines += ["questions:"] + [f"  - {kind}" for kind in kinds]
    return "\n".join(lines) + "\n", len(kinds)


# Found by the fuzzer: the spring's natural length equals its length at the values given,
# so the sampled adjugate in modes was NaN and max() compared NaN (exit code 3).
ZERO_LENGTH_SPRING = """\
title: fuzzed scene
parameters: {m: mass, l: length, k: stiffness, g: gravity, a: offset}
coordinates: [theta, x]
values: {m: 2, l: 1/2, k: 3, g: 9.81, a: 1}
points:
  A: [a, 0]
  P0: 2*l * [cos(theta), sin(theta)]
  P1: P0 + [x, l]
bodies:
  b0: {shape: particle, mass: m, at: P0}
  b1: {shape: disk, radius: l, angle: 0, mass: m, at: P1}
springs:
  s: {stiffness: k, between: [P0, A], natural_length: l}
questions:
  - modes: {about: {theta: 0, x: 0}}
"""


# Found by the fuzzer: a spring of natural length 0 whose ends meet at the equilibrium θ = 0,
# so the placement's derivative there is 0/0 and the singular-point test read NaN (exit 3).
SPRING_ENDS_MEET = """\
title: fuzzed scene
parameters: {m: mass, l: length, k: stiffness, g: gravity, a: offset}
coordinates: [theta, phi]
points:
  A: [a, 0]
  P0: a * [cos(theta), sin(theta)]
  P1: l * [sin(phi), -cos(phi)]
bodies:
  b0: {shape: particle, mass: m, at: P0}
  b1: {shape: particle, mass: m, at: P1}
springs:
  s: {stiffness: k, between: [P0, A]}
questions:
  - equilibria
"""


@FUZZ
@example(scene=(ZERO_LENGTH_SPRING, 1))
@example(scene=(SPRING_ENDS_MEET, 1))
@given(scene=scenes())
def test_random_valid_scenes_never_crash(folder: Path, scene: tuple[str, int]) -> None:
    text, questions = scene
    run_file(folder / "scene.yaml", text, questions)


# --- random mutations of the golden files ---------------------------------------------

GOLDEN = sorted(p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml"))
TOKENS = ["", "-", "[", "]", "{", "}", ":", ",", "*", "**", "&a", "*a", "<<", "!!python/object:os.system",
          "~", "null", "0", "-1", "1e999", "9**9**9", "theta", "__import__", "'", '"', "#", "|", ">", "?",
          "\t", "λ", "θ", "\u200b", "\x00", "\r", "\ufeff", "yes", "[[[[", "dot(theta)", "t"]


@st.composite
def mutated(draw) -> tuple[str, str]:
    path = draw(st.sampled_from(GOLDEN))
    text = path.read_text(encoding="utf-8")
    for _ in range(draw(st.integers(1, 3))):
        text = draw(mutation(text))
    return path.name, text


@st.composite
def mutation(draw, text: str) -> str:
    lines = text.splitlines(keepends=True) or [""]
    i = draw(st.integers(0, len(lines) - 1))
    j = draw(st.integers(0, max(len(text) - 2, 0)))
    op = draw(st.sampled_from(["delete", "duplicate", "swap", "token", "truncate", "tab", "unicode"]))
    if op == "delete":
        return "".join(lines[:i] + lines[i + 1:])
    if op == "duplicate":
        return "".join(lines[:i + 1] + lines[i:])
    if op == "swap":
        return text[:j] + text[j + 1:j + 2] + text[j:j + 1] + text[j + 2:]
    if op == "truncate":
        return text[:j]
    if op == "token":
        tokens = list(re.finditer(r"\w+|[^\w\s]", text)) or [re.match("", text)]
        found = draw(st.sampled_from(tokens))
        new = draw(st.sampled_from(TOKENS) | st.text(max_size=4))
        return text[:found.start()] + new + text[found.end():]
    insert = "\t" if op == "tab" else draw(st.text(min_size=1, max_size=3))
    return text[:j] + insert + text[j:]


@FUZZ
@given(case=mutated())
def test_mutated_golden_files_get_one_located_line(folder: Path, case: tuple[str, str]) -> None:
    name, text = case
    path = folder / name
    code, stderr = run_file(path, text, questions=text.count("\n  - ") + 1)
    if code == 2:
        lines = stderr.splitlines()
        assert len(lines) == 1, stderr
        assert re.match(rf"{re.escape(str(path))}:\d+:\d+: ", lines[0]), lines[0]
