"""Every limit on a problem file, each refused quickly with one located message.

The limits are documented in docs/format.md (section Limits); each test here runs in
well under a second, because a limit is checked before the work it guards.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from rbdsolve.errors import InputError, Location
from rbdsolve.problem import expr as ex
from rbdsolve.problem import load_file, load_text, yamlnodes

HERE = Location("p.yaml", 3, 9, ("bodies", "bob", "mass"))
SCOPE = ex.Scope(frozenset({"m", "x"}))


def refused(text: str, words: str) -> InputError:
    with pytest.raises(InputError) as info:
        ex.parse(text, HERE, SCOPE)
    assert words in info.value.message, info.value.message
    assert str(info.value).startswith("p.yaml:3:")
    return info.value


@pytest.mark.parametrize("text, words", [
    ("9**9**9", f"exponent 387420489 is too large (the limit is {ex.MAX_EXPONENT})"),
    ("9**9**9**9", "is too large"),
    ("x**(10**10)", "exponent 10000000000 is too large"),
    ("2**m**2", "a number raised to a power tower is refused"),
    ("factorial(10**9)", "unknown function 'factorial'"),
    ("(10**100)**100", f"the numbers in this expression grow past {ex.MAX_NUMBER_DIGITS} digits"),
    ("(((10**100)**100)**100)**100", "grow past"),
    ("(m*10**50)**100", "grow past"),
    ("1e99999999", f"the number 1e99999999 is out of range (the limit is 1e±{ex.MAX_TEN_POWER})"),
    ("1" * 41, f"number with 41 digits; the limit is {ex.MAX_DIGITS}"),
    ("x" + " + x" * 600, f"the limit is {ex.MAX_TEXT}"),
    ("+".join(["x"] * 300), f"expression has more than {ex.MAX_NODES} parts"),
    ("(" * 10_000 + "x" + ")" * 10_000, "the limit is 2000"),
    ("(" * 900 + "x" + ")" * 900, "too many nested parentheses"),
    ("-" * 1999 + "x", "more than 400 parts"),
], ids=lambda v: v[:24] if isinstance(v, str) else v)
def test_expression_limits(text: str, words: str) -> None:
    refused(text, words)


def test_numbers_at_the_limits_are_fine() -> None:
    for text in ("10**100 * 10**100 * m", "(1/3)**100", "1e300", "1e-300", "x**100", "1" * 40):
        ex.parse(text, HERE, SCOPE)


def test_deep_nesting_without_parentheses_is_no_recursion_error() -> None:
    # ast.parse of a long unary chain can exhaust the C stack's recursion limit: it must be
    # one message, not a RecursionError traceback.
    for text in ("-" * 1999 + "x", "not " * 499 + "x", "~" * 1999 + "x"):
        with pytest.raises(InputError):
            ex.parse(text, HERE, SCOPE)


def test_file_size_is_refused_before_reading(tmp_path: Path, monkeypatch) -> None:
    big = tmp_path / "big.yaml"
    with open(big, "wb") as handle:  # a sparse 100 MB file: its size is known without reading it
        handle.truncate(100 * 1024 * 1024)
    with pytest.raises(InputError, match=f"file is 104857600 bytes; the limit is {yamlnodes.MAX_FILE_BYTES} bytes"):
        load_file(big)


def test_a_stream_of_unknown_size_is_read_no_further_than_the_limit() -> None:
    with pytest.raises(InputError, match="file is more than 262144 bytes"):
        load_file("/dev/zero")  # endless: reading it all would never end


def billion_laughs(levels: int = 9) -> str:
    lines = ["a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    for i in range(1, levels):
        lines.append(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 10) + "]")
    return "\n".join(lines) + f"\nquestions: [*a{levels - 1}]\n"


def test_billion_laughs_is_refused_without_expanding() -> None:
    with pytest.raises(InputError, match=f"more than {yamlnodes.MAX_NODES} nodes"):
        load_text(billion_laughs(), "laughs.yaml")


@pytest.mark.parametrize("depth", [yamlnodes.MAX_DEPTH + 5, 10_000])
def test_deep_yaml_nesting_is_refused(depth: int) -> None:
    with pytest.raises(InputError, match="nest"):
        load_text("title: " + "[" * depth + "]" * depth + "\nquestions: [eom]\n", "deep.yaml")
