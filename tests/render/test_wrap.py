"""Long math lines in the terminal (issue 27): broken before a + or − between terms at
the outermost bracket depth that fits, with a hanging indent; never inside a term;
and no line of piped output ends in spaces."""

from __future__ import annotations

import re

from click.testing import CliRunner

from conftest import PROBLEMS
from rbdsolve.cli import main
from rbdsolve.render.wrap import wrap_math

LONG = "V' = −l m [Ω² l sin(θ₁)² + 2 g cos(θ₁) + Ω² l sin(θ₁) sin(θ₂) + 1/2 Ω² l sin(θ₂)² + g cos(θ₂)]"


def test_a_long_line_breaks_before_an_operator_with_a_hanging_indent() -> None:
    lines = wrap_math(LONG, 60)
    assert all(len(line) <= 60 for line in lines)
    assert lines[0].startswith("    V' = ") and all(line.startswith("        + ") for line in lines[1:])
    assert " ".join(line.strip() for line in lines) == LONG  # nothing lost or reordered


def test_the_outermost_break_that_fits_is_taken() -> None:
    text = "⇒ l⁴ m² λ² + (2 Ω² l⁴ m² − 4 g l³ m²) λ + (Ω⁴ l⁴ m² − 4 Ω² g l³ m² + 2 g² l² m²) = 0"
    first, second = wrap_math(text, 80)
    assert first == "    ⇒ l⁴ m² λ² + (2 Ω² l⁴ m² − 4 g l³ m²) λ"  # not inside the second bracket
    assert second == "        + (Ω⁴ l⁴ m² − 4 Ω² g l³ m² + 2 g² l² m²) = 0"


def test_a_short_line_and_a_long_term_stay_whole() -> None:
    assert wrap_math("T = 3/4 m r² θ̇²", 80) == ["    T = 3/4 m r² θ̇²"]
    term = "x" * 100
    assert wrap_math(term, 80) == ["    " + term]


def test_piped_text_has_no_trailing_spaces_and_no_broken_terms() -> None:
    result = CliRunner().invoke(main, ["solve", str(PROBLEMS / "sg2150-2015-10-29")], terminal_width=80)
    assert result.exit_code == 0, result.output
    assert not [line for line in result.output.splitlines() if line != line.rstrip()]
    # a math line's continuation starts with an operator, not with the rest of a term
    continuations = [line for line in result.output.splitlines() if re.match(r" {8}\S", line)]
    assert all(re.match(r" {8}[+−=⇒<>≤≥] ", line) for line in continuations), continuations


def _row(i: int, n: int) -> str:
    return "[" + ", ".join(f"{2 * n - i - j}/2 cos(th{i} − th{j})" for j in range(1, n + 1)) + "]"


def test_a_matrix_too_long_for_a_line_is_set_a_row_per_line_under_the_first() -> None:
    text = "M(q) = l² m [" + ", ".join(_row(i, 6) for i in range(1, 7)) + "]"
    lines = wrap_math(text, 100)
    assert all(len(line) <= 100 for line in lines)
    column = len("    M(q) = l² m [")
    starts = [line for line in lines if line.lstrip().startswith("[")]
    assert lines[0].startswith("    M(q) = l² m [[") and len(starts) == 5  # rows 2 … 6 each start a line
    assert all(line.index("[") == column for line in starts)  # under the first row's "["
    # a row too long for its line breaks between entries, never inside cos(th1 − th2)
    assert all(line.rstrip().endswith(",") or line.rstrip().endswith("]") for line in lines)
    assert " ".join(line.strip() for line in lines) == text


def test_a_long_vector_breaks_after_its_commas() -> None:
    text = "a₂ = (" + ", ".join(f"−{k}.{k}2345" for k in range(1, 21)) + ")"
    lines = wrap_math(text, 60)
    assert lines[0].startswith("    a₂ = (−1.12345,") and all(len(line) <= 60 for line in lines)
    assert all(line.startswith("        −") for line in lines[1:])
    assert " ".join(line.strip() for line in lines) == text


def test_a_matrix_that_fits_a_line_stays_whole_on_it() -> None:
    text = "J_O = J_G + m (|d|² 1 − d dᵀ) = m s² [[1/2, −1/4, −1/4], [−1/4, 1/2, −1/4], [−1/4, −1/4, 1/2]]"
    assert wrap_math(text, 80) == ["    J_O = J_G + m (|d|² 1 − d dᵀ)",
                                   "        = m s² [[1/2, −1/4, −1/4], [−1/4, 1/2, −1/4], [−1/4, −1/4, 1/2]]"]


def test_a_long_matrix_after_much_else_starts_its_own_line() -> None:
    """With more than half a line before it, the matrix starts a line of its own at the
    hang, after the last operator, and its rows align there (a reviewer's case)."""
    head = "J_O = J_G + m (|d|² 1 − d dᵀ) + another long term here"
    text = head + " = m s² [" + ", ".join(_row(i, 5) for i in range(1, 6)) + "]"
    lines = wrap_math(text, 90)
    assert lines[0] == "    " + head and lines[1].startswith("        = m s² [[")
    column = len("        = m s² [")
    assert [line.index("[") for line in lines[2:] if line.lstrip().startswith("[")] == [column] * 4
    assert all(len(line) <= 90 for line in lines)
    assert " ".join(line.strip() for line in lines) == text


def test_each_line_reads_only_its_own_room(monkeypatch) -> None:
    """A long sum wraps in time linear in its length: each line's breaks are read from
    the line's room (and an operator's length past it), not from the whole rest, which
    made a four-rod chain's accelerations quadratic. The lines are those of the whole
    rest's breaks: every cut is the outermost break that fits, so each line but the last
    ends just before an operator and fits the width."""
    from rbdsolve.render import wrap

    read: list[int] = []
    real = wrap.break_points
    monkeypatch.setattr(wrap, "break_points", lambda text, entries=False: read.append(len(text)) or real(text, entries))
    text = "x = " + " + ".join(f"a{i} (b{i} − c{i})" for i in range(2000))
    lines = wrap_math(text, 80)
    assert sum(read) <= 4 * len(text)  # the whole rest each time: ~len(text)²/(2 · 80)
    assert all(len(line) <= 80 for line in lines)
    assert all(nxt.lstrip().startswith("+ ") for nxt in lines[1:])
    assert "".join(line.strip() + " " for line in lines).strip() == text
