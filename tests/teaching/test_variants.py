"""Exam variants (teaching/variants.py, render/variants.py, ``rbdsolve variants``).

Expected values come from independent derivations: p1's eigenvalues are the exam's
λ₁ = 24g/(25r), λ₂ = 2g/r; a simple pendulum has ω² = g/l; two uncoupled
oscillators have λ = g/l and k/m, in whichever order their sizes give; a bead on a
hoop turning at Ω has equilibria θ = ±acos(g/(Ω²R)) only where Ω²R ≥ g.
"""

from __future__ import annotations

import csv
import io
import json
import math
from fractions import Fraction

from rbdsolve.problem.quantities.quantity import Value

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.errors import InputError, UnsolvedError
from rbdsolve.problem import load_file, load_text
from rbdsolve.render.variants import render_csv, render_json, render_latex
from rbdsolve.teaching.variants import variants

from conftest import PROBLEMS, SIMPLE_PENDULUM

P1 = PROBLEMS / "sg2150-2015-10-29" / "p1-two-rods.yaml"

PENDULUM = "title: Pendulum\n" + SIMPLE_PENDULUM + """\
values: {m: 2, l: {range: [0.5, 2], step: 0.25}, g: {choices: [9.81, 10]}}
questions:
  - modes: {about: {theta: 0}}
"""

TWO_OSCILLATORS = """
title: A pendulum beside a mass on a spring
parameters: {m: mass, l: length, g: gravity, k: stiffness}
values: {m: 1, g: 10, l: {range: [0.5, 2], step: 0.5}, k: {range: [%s], step: 2}}
coordinates: [theta, x]
gravity: [0, -g]
points:
  P: l * [sin(theta), -cos(theta)]
  Q: [x, 5]
  A: [0, 5]
bodies:
  bob: {shape: particle, mass: m, at: P}
  block: {shape: particle, mass: m, at: Q}
springs:
  s: {stiffness: k, between: [A, Q], natural_length: 0}
questions:
  - modes: {about: {theta: 0, x: 0}}
"""


def hoop(omega: str) -> str:
    text = (PROBLEMS / "edges" / "rotating-hoop-critical.yaml").read_text(encoding="utf-8")
    return text.replace("values: {m: 1, R: 1, g: 9, Omega: 3}", f"values: {{m: 1, R: 1, g: 9, Omega: {omega}}}")


@pytest.fixture(scope="module")
def p1_table():
    return variants(load_file(P1), 30, 1, verify=2)


def column(table, name: str) -> list:
    i = table.columns.index(name)
    return [row[i] for row in table.answers]


def params(table, name: str) -> list[float]:
    i = table.parameters.index(name)
    return [float(d[i]) for d in table.draws]


def test_p1_eigenvalues_follow_the_exam_formulas(p1_table) -> None:
    r, g = params(p1_table, "r"), params(p1_table, "g")
    for lam1, lam2, ri, gi in zip(column(p1_table, "modes.eigenvalues[1]"),
                                  column(p1_table, "modes.eigenvalues[2]"), r, g):
        assert lam1 == pytest.approx(24 * gi / (25 * ri), rel=1e-12)
        assert lam2 == pytest.approx(2 * gi / ri, rel=1e-12)
    assert p1_table.verified == (1, 30)
    assert not p1_table.warnings


def test_values_are_on_the_declared_grid(p1_table) -> None:
    for m in params(p1_table, "m"):
        assert 1 <= m <= 5 and (m - 1) / 0.5 == pytest.approx(round((m - 1) / 0.5))
    for r in params(p1_table, "r"):
        assert 0.2 - 1e-12 <= r <= 2 + 1e-12 and (r - 0.2) / 0.1 == pytest.approx(round((r - 0.2) / 0.1))
    assert set(params(p1_table, "g")) <= {9.81, 10.0}
    assert all(isinstance(v, Value) and v.rational is not None for d in p1_table.draws for v in d)


def test_pendulum_frequency_squared_is_g_over_l() -> None:
    table = variants(load_text(PENDULUM, "pendulum.yaml"), 40, 3, verify=1)
    assert table.parameters == ("l", "g") and [(n, v.rational) for n, v in table.fixed] == [("m", Fraction(2))]
    for omega, l, g in zip(column(table, "modes.frequencies[1]"), params(table, "l"), params(table, "g")):
        assert omega**2 == pytest.approx(g / l, rel=1e-12)


def test_the_same_seed_gives_the_same_variants_and_another_seed_others() -> None:
    problem = load_text(PENDULUM, "pendulum.yaml")
    a, b = variants(problem, 20, 5, verify=0), variants(problem, 20, 5, verify=0)
    c = variants(problem, 20, 6, verify=0)
    assert a.draws == b.draws and a.answers == b.answers
    assert a.draws != c.draws


def test_eigenvalues_are_ordered_per_variant_with_their_shapes() -> None:
    table = variants(load_text(TWO_OSCILLATORS % "3, 31", "two.yaml"), 40, 5, verify=4)
    l, k = params(table, "l"), params(table, "k")
    lam1, lam2 = column(table, "modes.eigenvalues[1]"), column(table, "modes.eigenvalues[2]")
    shape = column(table, "modes.shapes[1][1]")  # 1: the first mode is the pendulum's
    assert {10 / li < ki for li, ki in zip(l, k)} == {True, False}  # the order does change
    for li, ki, a, b, s in zip(l, k, lam1, lam2, shape):
        assert (a, b) == pytest.approx(sorted([10 / li, ki]), rel=1e-12)
        assert s == (1.0 if 10 / li < ki else 0.0)


def test_a_double_eigenvalue_the_table_cannot_know_is_an_error_naming_the_variant() -> None:
    # At k = g/l λ is double: the full solve picks another basis of its modes than the
    # table's formulas (exact for k ≠ g/l) give.
    text = (TWO_OSCILLATORS % "2, 30").replace("l: {range: [0.5, 2], step: 0.5}", "l: 1")
    text = text.replace("{range: [2, 30], step: 2}", "{choices: [10]}")
    with pytest.raises(UnsolvedError, match=r"variant 1 \(k = 10\): modes.shapes\[1\]\[1\] is 0 in the table, "
                                            r"but a full solve at these values gives 1"):
        variants(load_text(text, "two.yaml"), 3, 5, verify=1)


def test_equilibria_that_exist_only_above_the_critical_rate_are_empty_below_it() -> None:
    table = variants(load_text(hoop("{range: [1, 5], step: 0.5}"), "hoop.yaml"), 30, 2, verify=8)
    omega = params(table, "Omega")
    assert any(w.startswith("equilibria.equilibria[2]: does not exist") for w in table.warnings)
    for o, lower, upper in zip(omega, column(table, "equilibria.equilibria[2].at.theta"),
                               column(table, "equilibria.equilibria[3].at.theta")):
        if o**2 <= 9:  # at Ω²R = g, ±acos(1) is θ = 0, already the first equilibrium
            assert lower is None and upper is None
        else:
            assert upper == pytest.approx(math.acos(9 / o**2), rel=1e-12, abs=1e-12)
            assert lower == pytest.approx(-upper, abs=1e-12)


def test_each_student_gets_the_stability_of_their_case() -> None:
    """Issue 19: the exact solve gives θ = 0 stable when Ω² < g/R and unstable above (by
    hand: V'' = m R (g − Ω² R), here g = 9, R = 1), ±acos(g/(R Ω²)) stable where they
    exist, π unstable; each variant's kinds are read off its own Ω, and 8 variants are
    checked against a full solve at their values."""
    table = variants(load_text(hoop("{range: [1, 5], step: 0.5}"), "hoop.yaml"), 30, 2, verify=8)
    kinds = {c: [row[i] for row in table.kinds] for i, c in enumerate(table.kind_columns)}
    for o, bottom, side, top in zip(params(table, "Omega"), kinds["equilibria.equilibria[1].stability"],
                                    kinds["equilibria.equilibria[3].stability"],
                                    kinds["equilibria.equilibria[4].stability"]):
        if o**2 == 9:
            assert bottom is None  # on the boundary: the cases do not say
        else:
            assert bottom == ("stable" if o**2 < 9 else "unstable")
        assert side == (None if o**2 <= 9 else "stable")
        assert top == "unstable"


def test_at_the_critical_rate_the_meeting_branches_are_one_equilibrium() -> None:
    # sin θ (g − Ω²R cos θ) = 0 at Ω²R = g: θ = 0 and θ = π only (cos θ = 1 is θ = 0 again)
    table = variants(load_text(hoop("{choices: [3, 2]}"), "hoop.yaml"), 12, 0, verify=12)
    for o, row in zip(params(table, "Omega"), table.answers):
        thetas = [row[table.columns.index(f"equilibria.equilibria[{k}].at.theta")] for k in range(1, 5)]
        assert sorted(t for t in thetas if t is not None) == pytest.approx([0, math.pi])
    assert 3 in params(table, "Omega") and len(table.verified) == 12
    assert any("is equilibria.equilibria[1]" in w and "listed once there" in w for w in table.warnings)


def test_a_file_without_ranges_is_refused() -> None:
    text = PENDULUM.replace("{range: [0.5, 2], step: 0.25}", "1").replace("{choices: [9.81, 10]}", "9.81")
    with pytest.raises(InputError, match="no parameter has a range"):
        variants(load_text(text, "pendulum.yaml"), 5, 1)


def test_solve_keeps_ranged_parameters_symbolic() -> None:
    problem = load_file(P1)
    assert problem.values == () and [r.name for r in problem.ranges] == ["m", "r", "g"]


def test_writers(p1_table) -> None:
    rows = list(csv.reader(io.StringIO(render_csv(p1_table))))
    assert rows[0][:5] == ["variant", "seed", "m", "r", "g"] and len(rows) == 31
    assert "modes.eigenvalues[1]" in rows[0]
    data = json.loads(render_json(p1_table))
    assert data["seed"] == 1 and len(data["rows"]) == 30 and data["columns"] == list(p1_table.columns)
    tex = render_latex(p1_table)
    assert tex.count("\\newpage") == 30 and "Variant 30" in tex and tex.rstrip().endswith("\\end{document}")


def test_cli_writes_a_csv_of_30_variants(tmp_path) -> None:
    out = tmp_path / "variants.csv"
    result = CliRunner().invoke(main, ["variants", str(P1), "--count", "30", "--seed", "1", "-o", str(out),
                                       "--verify", "1"])
    assert result.exit_code == 0, result.output
    assert len(out.read_text(encoding="utf-8").splitlines()) == 31


def test_cli_errors() -> None:
    runner = CliRunner()
    no_range = runner.invoke(main, ["variants", str(PROBLEMS / "edges" / "rotating-hoop-critical.yaml")])
    assert no_range.exit_code == 2 and "no parameter has a range" in no_range.stderr
    bad_suffix = runner.invoke(main, ["variants", str(P1), "-o", "out.xlsx"])
    assert bad_suffix.exit_code == 2 and "cannot tell the format" in bad_suffix.stderr
    missing = runner.invoke(main, ["variants", "nope.yaml"])
    assert missing.exit_code == 2 and missing.stderr.strip() == "no such file: nope.yaml"
    assert "--count 30 --seed 1 -o variants.csv" in runner.invoke(main, ["variants", "--help"]).output


def test_parameters_without_value_or_range_are_named() -> None:
    text = (PROBLEMS / "examples" / "pendulum.yaml").read_text(encoding="utf-8")
    table = variants(load_text(text.replace("questions:", "values: {m: {range: [1, 5], step: 1}}\nquestions:"),
                               "pendulum.yaml"), 3, 0, verify=1)
    assert any(w.startswith("l, g have neither a value nor a range") for w in table.warnings)
    assert not any("eigenvalues" in c for c in table.columns)  # λ = 3g/(2l) holds l and g: no number


def test_a_students_values_do_not_move_when_the_count_changes() -> None:
    """Issue 41: with one seed, student i gets the same values for --count 4 and 30 (a
    teacher adding students keeps the first ones), on a small grid (shuffled whole) and
    a large one (drawn set by set)."""
    from rbdsolve.teaching.variants import WHOLE_GRID, draw

    small = _ranges({"r": (1, 9, 1), "m": (1, 9, 1)})
    large = _ranges({"a": (1, 1000, 1), "b": (1, 1000, 1)})
    assert math.prod(r.size for r in large) > WHOLE_GRID >= math.prod(r.size for r in small)
    for ranges in (small, large):
        four, thirty = draw(ranges, 4, seed=1), draw(ranges, 30, seed=1)
        assert thirty[:4] == four
        assert draw(ranges, 30, seed=2) != thirty  # the seed does matter


def test_no_two_students_share_values_while_the_grid_allows_and_a_warning_when_it_cannot() -> None:
    from rbdsolve.teaching.variants import draw, repeated

    ranges = _ranges({"r": (1, 9, 1), "m": (1, 9, 1)})  # 81 sets of values
    thirty = draw(ranges, 30, seed=1)
    assert len(set(thirty)) == 30 and repeated(ranges, 30) == 0
    every = draw(ranges, 81, seed=1)
    assert len(set(every)) == 81  # the whole grid, each set once
    assert repeated(ranges, 100) == 19 and len(set(draw(ranges, 100, seed=1))) == 81


def _ranges(grid: dict[str, tuple[int, int, int]]):
    """Ranged parameters as a file declares them: {name: (low, high, step)}."""
    lines = "\n".join(f"  {n}: {{range: [{lo}, {hi}], step: {st}}}" for n, (lo, hi, st) in grid.items())
    text = (f"parameters: [{', '.join(grid)}]\nvalues:\n{lines}\n"
            f"bodies: {{ball: {{shape: particle, mass: {next(iter(grid))}, at: [0, 0]}}}}\nquestions: [inertia]\n")
    return load_text(text, "ranges.yaml").ranges


def test_a_student_sheet_gives_each_value_with_its_unit_and_an_angle_in_degrees() -> None:
    """An incline drawn from 20 deg and 45 deg: the sheet says β = 20° (or 45°), not
    0.3490658504; a mass drawn in kg says kg."""
    scene = """
title: A block on an incline
parameters: {m: mass, g: gravity, beta: angle of the incline}
values: {m: {range: [1, 2], step: 1}, g: 9.81 m/s^2, beta: {choices: [20 deg, 45 deg]}}
coordinates: [x]
gravity: [0, -g]
points:
  P: x * [cos(beta), -sin(beta)]
bodies:
  block: {shape: particle, mass: m, at: P}
questions:
  - eom
"""
    table = variants(load_text(scene), count=4, seed=3)
    tex = render_latex(table)
    pages = [line for line in tex.splitlines() if line.startswith("\\textbf{Your values:}")]
    assert len(pages) == 4
    for page, draw in zip(pages, table.draws):
        m, beta = (float(v) for v in draw)
        assert f"$m = {m:.10g}$ kg" in page and "$g = 9.81$ m/s" in page
        assert f"$\\beta = {math.degrees(beta):.10g}^\\circ$" in page
    assert "0.349" not in tex and "0.785" not in tex
