"""The corpus of bad problem files: each one gets exactly one located, actionable line.

Every file under ``tests/problem/bad/`` states what ``rbdsolve`` must say about it. A
file whose first line is UTF-8 text carries its expectation in its first line::

    # expect: 2 "duplicate key 'mass'" "first defined at line 9" at 9:35

(exit code, then the quoted words the message must contain, then ``at LINE:COLUMN``
when the message is located in the file; lines count this comment). Files that cannot
carry a comment (empty, binary, UTF-16) have the same fields in ``EXPECTATIONS.toml``.

To add a case: write the file with its ``# expect:`` line (or a table entry), run this
test, and make sure the message is what a user needs, not what the code happens to say.
"""

from __future__ import annotations

import re
import shlex
from dataclasses import dataclass
from pathlib import Path

import pytest
import tomllib
from click.testing import CliRunner

from rbdsolve.cli import main

BAD = Path(__file__).parent / "bad"
TABLE = tomllib.loads((BAD / "EXPECTATIONS.toml").read_text(encoding="utf-8"))
FILES = sorted(BAD.glob("*.yaml"))
ALGEBRA_ONLY = ("is not a real number", "must not be zero or negative", "break the assumption",
                "cannot hold with the others", "does not touch", "cannot roll inside", "does not roll",
                "does not pass through the pulley", "does not move", "which also moves",
                "a line out of the xy-plane", "not in the plane of the scene", "lies flat on the plane")


@dataclass(frozen=True)
class Expect:
    exit: int
    words: tuple[str, ...]
    at: str | None  # "line:column", or None for a message that is not located


def expectation(path: Path) -> Expect:
    if path.name in TABLE:
        entry = TABLE[path.name]
        return Expect(entry["exit"], tuple(entry["words"]), entry.get("at"))
    first = path.read_bytes().split(b"\n", 1)[0].decode("utf-8")
    assert first.startswith("# expect: "), f"{path.name}: no '# expect:' line and no table entry"
    parts = shlex.split(first.removeprefix("# expect: "))
    at = parts[-1] if len(parts) > 2 and parts[-2] == "at" else None
    words = parts[1:-2] if at else parts[1:]
    return Expect(int(parts[0]), tuple(words), at)


def test_the_corpus_is_large_and_fully_described() -> None:
    assert len(FILES) >= 60
    assert set(TABLE) <= {f.name for f in FILES}, "EXPECTATIONS.toml names a missing file"


@pytest.mark.parametrize("command", ["check", "solve"])
@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_bad_file_gets_one_located_actionable_line(path: Path, command: str) -> None:
    expect = expectation(path)
    result = CliRunner().invoke(main, [command, str(path)])
    if command == "check" and result.exit_code == 0:
        # check does no algebra: a negative length -l or sqrt(-1) shows only when solving.
        assert any(w in " ".join(expect.words) for w in ALGEBRA_ONLY), result.output
        return
    assert result.exit_code == expect.exit, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    message = lines[0]
    assert "Traceback" not in result.output and "internal error" not in message
    if expect.at:
        assert message.startswith(f"{path}:{expect.at}: "), message
    else:
        assert not re.match(rf"{re.escape(str(path))}:\d+:\d+:", message), message
    for words in expect.words:
        assert words in message, f"{words!r} not in {message!r}"
