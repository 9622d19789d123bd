"""A seeded mutation fuzzer over problems/ (issue 28): each case takes a golden problem
file, applies one to three hostile mutations (sympy's class names as coordinates, YAML
escapes and tags, overflowing and complex values, zero axes, line separators, broken
syntax…) and runs ``rbdsolve solve`` on it in-process, in one of the four formats.

Invariants of every case: exit code 0, 1 or 2 (never 3); no traceback and no
"internal error"; no control character in what is printed; a refusal (2) is one line
naming the file; JSON is strict (no NaN, no Infinity), and a numeric value left null
where the exact answer is a plain number comes with a warning that says so.

The normal run is 90 cases (RBDSOLVE_MUTATION_CASES), about 25 s on a two-core machine
twice as slow as a laptop; the cases are the same on every machine, quiet or loaded, for a seed
(RBDSOLVE_MUTATION_SEED, default 28). A long run, before a release or after touching
the loader (about two minutes per 1000 cases):

    RBDSOLVE_MUTATION_CASES=1000 python3 -m pytest -q tests/problem/test_mutation_fuzz.py

and with other seeds: RBDSOLVE_MUTATION_SEED=1, 2, … A case that hangs is caught by a
watchdog (faulthandler, 120 s) that prints every thread's stack and ends the run; the
case being run is always in ``current-case.yaml`` of the test's temporary folder. A
failing case is shown in full with its seed and number; its smallest form joins the
corpus in tests/problem/bad/ (or a test beside the module that owns the bug).
"""

from __future__ import annotations

import faulthandler
import json
import os
import random
import re
import time
from pathlib import Path

import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS

SEED = int(os.environ.get("RBDSOLVE_MUTATION_SEED", "28"))
CASES = int(os.environ.get("RBDSOLVE_MUTATION_CASES", "90"))
BUDGET = "1"  # seconds per question and for the model: a case costs a few seconds at most
HANG = 120  # seconds: a case still running then is a hang

GOLDEN = sorted(p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml"))
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e]")
FORMATS = ("json", "json", "terminal", "markdown", "latex")

NAMES = ["Integer", "Float", "Rational", "PolyElement", "FracElement", "UnevaluatedExpr", "Symbol",
         "Function", "Add", "Mul", "Pow", "S", "N", "O", "Q", "beta", "gamma", "zeta", "x0", "theta_dot",
         "numpy", "array", "select", "float", "Matrix", "Dummy", "Derivative", "nan", "oo", "zoo"]
REFUSED_NAMES = ["E", "I", "t", "pi", "lambda", "__class__", "sin", "dot"]
VALUES = ["1e300", "-1e300", "1e-300", "0", "-0", "1/0", "0/0", "acos(2)", "sqrt(-1)", "log(0)", "9**9**9",
          "1e999", ".nan", ".inf", "-.inf", "nan", "m - m", "2**1000", "10**40", "1/3", "-1"]
YAML = ['"\\e]0;PWNED\\a\\e[2J"', '"\\x85"', '"\\u202e"', '"\\u2028"', "!!python/name:os.system",
        "!include /etc/passwd", "!!binary aGk=", "&a", "*a", "<<: *a", "~", "null", "[", "{", "'", '"', "|",
        ">", "? ", "- ", "#", ":", ","]
EXPRESSIONS = ["[m - m, 0, 0]", "[0, 0, 0]", "dot(theta)", "ddot(x)", "cross(A, B)", "theta**2**3",
               "__import__('os').system('true')", "[1, 2, 3, 4]", "norm([0, 0])", "atan2(0, 0)"]
CHARACTERS = ["\u2028", "\u0085", "\u200b", "\t", "\r", "\x1b", "\x07", "θ", "%\u0307", "\ufeff", "\u202e"]
TOKENS = NAMES + REFUSED_NAMES + VALUES + YAML + EXPRESSIONS + CHARACTERS
# Mostly mutations that keep the file readable, so that most cases reach the model, the
# solvers and the renderers; some that break it, so that the refusals are tried too.
OPERATIONS = {"rename": 6, "value": 5, "values": 3, "token": 2, "insert": 1, "delete": 1, "duplicate": 1,
              "swap": 0.5, "truncate": 0.3}


def mutate(text: str, rng: random.Random) -> str:
    """One mutation of ``text``, drawn by ``rng``."""
    lines = text.splitlines(keepends=True) or [""]
    i = rng.randrange(len(lines))
    j = rng.randrange(len(text) + 1)
    op = rng.choices(list(OPERATIONS), weights=list(OPERATIONS.values()))[0]
    if op == "rename":  # a declared name renamed everywhere: reaches the model and the printers
        declared = _declared(text)
        if declared:
            new = rng.choice(NAMES) if rng.random() < 0.9 else rng.choice(REFUSED_NAMES)
            return re.sub(rf"\b{re.escape(rng.choice(declared))}\b", new, text)
    if op == "value":  # a number replaced by a hostile value
        numbers = list(re.finditer(r"(?<![\w.])\d+(\.\d+)?(e-?\d+)?", text))
        if numbers:
            found = rng.choice(numbers)
            return text[:found.start()] + rng.choice(VALUES) + text[found.end():]
    if op == "token":
        tokens = list(re.finditer(r"\w+|[^\w\s]", text))
        if tokens:
            found = rng.choice(tokens)
            return text[:found.start()] + rng.choice(TOKENS) + text[found.end():]
    if op == "delete":
        return "".join(lines[:i] + lines[i + 1:])
    if op == "duplicate":
        return "".join(lines[:i + 1] + lines[i:])
    if op == "swap":
        k = rng.randrange(len(lines))
        lines[i], lines[k] = lines[k], lines[i]
        return "".join(lines)
    if op == "truncate":
        return text[:j]
    if op == "values":  # every parameter given one hostile value
        names = re.findall(r"^parameters:\s*\{(.*)\}", text, re.M)
        params = [p.split(":")[0].strip() for p in names[0].split(",")] if names else ["m"]
        value = rng.choice(VALUES)
        return re.sub(r"^values:.*\n", "", text, flags=re.M) + \
            "values: {" + ", ".join(f"{p}: {value}" for p in params if p) + "}\n"
    return text[:j] + rng.choice(TOKENS) + text[j:]


def _declared(text: str) -> list[str]:
    """The parameters and coordinates a file declares (flow style, as problems/ writes them)."""
    names = []
    for section in re.findall(r"^(?:parameters|coordinates):\s*[\[{](.*)[\]}]", text, re.M):
        names += [part.split(":")[0].strip() for part in section.split(",")]
    return sorted(n for n in set(names) if n.isidentifier())


def case(seed: int, number: int) -> tuple[str, str, str]:
    """Case ``number`` of a seed: (golden file's name, mutated text, format)."""
    rng = random.Random(f"{seed}:{number}")
    path = rng.choice(GOLDEN)
    text = path.read_text(encoding="utf-8")
    for _ in range(rng.randint(1, 3)):
        text = mutate(text, rng)
    return path.name, text, rng.choice(FORMATS)


def check(path: Path, text: str, fmt: str) -> None:
    path.write_bytes(text.encode("utf-8", "surrogatepass"))
    result = CliRunner().invoke(main, ["solve", str(path), "--budget", BUDGET, "-f", fmt])
    said = f"exit {result.exit_code}\n{result.output}"
    assert result.exit_code in (0, 1, 2), said
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    assert "Traceback" not in result.output and "internal error" not in result.output, said
    assert not CONTROL.search(result.stdout) and not CONTROL.search(result.stderr), repr(result.output)
    if result.exit_code == 2 and not result.stdout.strip():
        lines = result.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"{path}:"), result.stderr
    if fmt == "json":
        for line in result.stdout.splitlines():
            _check_numbers(json.loads(line, parse_constant=_not_finite))


def _not_finite(name: str):
    raise AssertionError(f"{name} in the JSON output")


def _check_numbers(body: dict) -> None:
    """A null numeric value beside an exact answer that is a plain number is said in a warning."""
    for result in body.get("results", []):
        nulls = [a for a, v in _pairs(result.get("answers"), result.get("values")) if v is None and _is_number(a)]
        if nulls:
            assert any("no numeric value" in w for w in result["warnings"]), (nulls, result["warnings"])


def _pairs(answer, value):
    if isinstance(answer, dict) and isinstance(value, dict):
        for key in answer.keys() & value.keys():
            yield from _pairs(answer[key], value[key])
    elif isinstance(answer, list) and isinstance(value, list) and len(answer) == len(value):
        for a, v in zip(answer, value):
            yield from _pairs(a, v)
    elif isinstance(answer, str):
        yield answer, value


def _is_number(text: str) -> bool:
    """An exact answer that is a plain number (no parameter, no coordinate, no word)."""
    try:
        value = sp.sympify(text)
    except Exception:  # noqa: BLE001 - a word or a user's name that sympy reads otherwise
        return False
    return isinstance(value, sp.Basic) and not value.free_symbols and not value.atoms(sp.Function)


def test_seeded_mutations_of_the_golden_files(tmp_path: Path) -> None:
    current = tmp_path / "current-case.yaml"
    faulthandler.dump_traceback_later(HANG, exit=True)  # a hang ends the run, with every stack
    start, done = time.monotonic(), 0
    try:
        for number in range(CASES):
            name, text, fmt = case(SEED, number)
            current.write_bytes(text.encode("utf-8", "surrogatepass"))
            faulthandler.dump_traceback_later(HANG, exit=True)  # re-armed for each case
            try:
                check(tmp_path / name, text, fmt)
            except AssertionError as exc:
                raise AssertionError(f"seed {SEED}, case {number} ({name}, -f {fmt}):\n{text}\n---\n{exc}") from None
            done += 1
    finally:
        faulthandler.cancel_dump_traceback_later()
    print(f"{done} mutation cases (seed {SEED}) in {time.monotonic() - start:.1f} s")  # measured, not asserted
    assert done == CASES
