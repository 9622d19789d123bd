"""The report's text without colour, laid out without rich (render/text.py), is the text
rich writes for the same lines: compared here character for character, on reports and on
lines made to reach each case of the layout (a word that just fits, one that must fold,
wide and zero-width characters, blank lines, tabs), at many widths."""

from __future__ import annotations

import io

import pytest
from rich.console import Console, Group

from rbdsolve.api import solve
from rbdsolve.render.lines import MATH, PROSE, RULE, Line, line, report_lines
from rbdsolve.render.terminal import shown
from rbdsolve.render.text import no_trailing_spaces, plain_text, rich_text, terminal_text

from conftest import PROBLEMS, SEED

WIDTHS = (12, 19, 20, 33, 40, 57, 80, 100, 131)


def by_rich(lines: list[Line], width: int) -> str:
    console = Console(file=io.StringIO(), width=width, highlight=False)
    console.print(Group(*[shown(x) for x in lines]))
    return no_trailing_spaces(console.file.getvalue())


def compared(lines: list[Line], width: int) -> bool:
    """The plain layout equals rich's; False where it leaves the lines to rich."""
    plain = plain_text(lines, width)
    if plain is None:
        return False
    assert no_trailing_spaces(plain) == by_rich(lines, width), width
    return True


PROSE_CASES = [
    "A rod of mass 3m and length √3·r moves with both ends on a smooth fixed circle of radius r.",
    "exactly twenty chars",  # fits a 20-column line to the last cell
    "exactly twenty chars and then some more words after it",
    "  two spaces first, then words that run past the line's end more than once or twice",
    "words   with   runs   of   spaces   between   them   that   wrap   somewhere   along",
    "first paragraph\n\nthird, after a blank line\n",
    "",
    "θ̈ φ̇ and q̇ carry combining dots: zero cells each, so a line holds more characters",
    "全角の文字は二つのセルを使う wide characters take two cells each 全角の文字",
    "ends with spaces    ",
    "a-very-long-word-without-any-space-that-cannot-fit-a-narrow-line and after",
    "tab\there",
]


@pytest.mark.parametrize("text", PROSE_CASES)
def test_prose_is_wrapped_as_rich_wraps_it(text: str) -> None:
    laid_out = [compared([line(text), line(text, gap=True)], w) for w in WIDTHS]
    assert any(laid_out) or "\t" in text  # each case is laid out here at some width (a tab: never)


@pytest.mark.parametrize("text", [
    "m r² [7/4 θ̈ + 1/4 cos(φ − θ) φ̈ − 1/4 sin(φ − θ) φ̇²] + 2 g m r sin(θ) = 0",
    "K = g m r [[2, 0], [0, 1/2]]",
    "θ̈ = (6 g sin(φ) cos(φ − θ) − 32 g sin(θ) + 3 r sin(φ − θ) cos(φ − θ) θ̇² + 4 r sin(φ − θ) φ̇²)/(r (28 − 3 cos(φ − θ)²))",
])
def test_relations_are_broken_as_rich_breaks_them(text: str) -> None:
    assert any([compared([line(text, kind=MATH)], w) for w in WIDTHS])


@pytest.mark.parametrize("title", ["Two rods in a circle", "x" * 18, "x" * 19, "全角 title", "θ̈ title"])
def test_the_title_rule_is_richs(title: str) -> None:
    laid_out = [compared([line(title, "bold", RULE)], w) for w in WIDTHS]
    assert any(laid_out)
    assert not compared([line("x" * 30, "bold", RULE)], 20)  # cut short with an ellipsis: rich's


def test_a_line_of_two_styles_is_its_text() -> None:
    head = Line((("Question 1: eom", "bold underline"), ("   (exact, 0.11 s)", "dim")), PROSE, gap=True)
    assert all(compared([head], w) for w in (20, 80))


@pytest.mark.parametrize("name", ["p1-two-rods.yaml", "p3-rolling-ring.yaml"])
def test_a_report_is_richs_text_at_every_width(name: str) -> None:
    report = solve(SEED / name).report
    for width in WIDTHS:
        plain = plain_text(report_lines(report), width)
        if plain is not None:
            assert no_trailing_spaces(plain) == rich_text(report, width), width
    assert terminal_text(report, 80) == rich_text(report, 80)


def test_numeric_values_and_accuracy_are_richs_text() -> None:
    report = solve(PROBLEMS / "examples" / "pendulum.yaml", route="numeric", values={"g": 9.81, "l": 1, "m": 1}).report
    assert any("Accuracy" in x.text for x in report_lines(report))
    for width in (40, 80, 100):
        assert terminal_text(report, width) == rich_text(report, width)


def test_colour_goes_through_rich() -> None:
    report = solve(SEED / "p1-two-rods.yaml").report
    coloured = terminal_text(report, 80, "truecolor", True)
    assert "\x1b[" in coloured and coloured == rich_text(report, 80, "truecolor", True)
