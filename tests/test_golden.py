"""Golden cases: every problem file with a NAME.expected.yaml beside it is solved and its
JSON output compared with the expected answers, exactly (simplify(a − b) == 0), and
with the expected numeric values, if given, to a relative tolerance of 1e-10.

Expected answers come from independent derivations (the exam's worked solutions, or by
hand), noted in each file's ``derivation``. Only the keys an expected file gives are
checked; equilibria are matched by their coordinates, in any order.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
import yaml

from rbdsolve.cli.writing import Look, rendered_text
from rbdsolve.render.json import report_object
from rbdsolve.render.numbers import number_text

from conftest import PROBLEMS, same, solved_file

CASES = sorted(PROBLEMS.rglob("*.expected.yaml"))


def _problem_for(expected: Path) -> Path:
    return expected.with_name(expected.name.replace(".expected.yaml", ".yaml"))


@pytest.mark.parametrize("expected_file", CASES, ids=lambda p: str(p.relative_to(PROBLEMS)))
def test_golden(expected_file: Path) -> None:
    expected = yaml.safe_load(expected_file.read_text(encoding="utf-8"))
    _, report = solved_file(_problem_for(expected_file))
    got = json.loads(json.dumps(report_object(report)))  # exactly what scripts see
    for key, value in expected.get("model", {}).items():
        assert same(got["model"][key], value), f"model.{key}: {got['model'][key]} != {value}"
    results = got["results"]
    assert [r["question"] for r in results] == [e["question"] for e in expected["results"]]
    for result, want in zip(results, expected["results"]):
        assert result["ok"], f"{result['question']}: {result['error']}"
        compare(result["answers"], want["answers"], result["question"])
        compare_numbers(result["values"], want.get("values", {}), result["question"])
    assert_reads_clean(rendered_text(report, Look(width=80)))
    for solution in report.solutions:
        assert_units_right([(re.split(" = | ≥ ", number_text(n))[0], n.unit) for n in solution.numbers if not n.accuracy])


def compare(got, want, where: str) -> None:
    if isinstance(want, dict):
        for key, value in want.items():
            assert key in got, f"{where}: missing key {key}"
            if key == "equilibria":
                compare_equilibria(got[key], value, f"{where}.{key}")
            else:
                compare(got[key], value, f"{where}.{key}")
    elif isinstance(want, list):
        assert isinstance(got, list) and len(got) == len(want), f"{where}: {got} != {want}"
        for i, (g, w) in enumerate(zip(got, want)):
            compare(g, w, f"{where}[{i}]")
    elif want is None:
        assert got is None, f"{where}: {got} != None"
    elif isinstance(want, bool) or want in ("stable", "unstable", "neutral", "undetermined",
                                            "oscillation", "growth", "conditional"):
        assert got == want, f"{where}: {got} != {want}"
    else:
        assert same(str(got), str(want)), f"{where}: {got} != {want}"


SCANS = {
    # what the printed text of a solution must never have (issue 27)
    "sympy syntax in prose": re.compile(r"\*\*|[A-Za-z0-9)]\*[A-Za-z(]|sqrt\(|Derivative\(|Integral\(|Abs\(|lamda"),
    "a zero term": re.compile(r"[+−] 0(?![\d.])"),
    "a binomial with a leading minus": re.compile(r"\(−[^(),\[\]]* [+−] [^(),\[\]]*\)"),
    "a float that is zero within rounding": re.compile(r"= −?\d(\.\d+)?e-(1[2-9]|[2-9]\d)"),
    "trailing spaces": re.compile(r"[ \t]+$", re.MULTILINE),
    # the numeric block names each value as the solution prints it (issue 41, item 5)
    "a JSON path as a value's name": re.compile(r"^ +([A-Za-z_]\w*(\[\d+\])*[.\[]\S* = |[a-z]{2,}_[a-z]{2,} = )",
                                               re.MULTILINE),
    "a dash for a value": re.compile(r"= \[[^\]\n]*—"),
    # warnings and notes in the solution's notation, not sympy's (issue 41, item 6)
    "sympy's relation or constant": re.compile(r"<=|>=|!=|(?<![A-Za-z_])pi(?![A-Za-z_(])"),
}


def assert_reads_clean(text: str) -> None:
    """The scan of issue 27 over one printed solution; an error bound may be tiny, and so
    may the machine's ε (named so, on whichever line the sentence wraps it to)."""
    for what, pattern in SCANS.items():
        found = [m for m in pattern.finditer(text)
                 if "bound" not in _line(text, m.start()) and "error" not in _line(text, m.start())
                 and not text[:m.start()].endswith("ε ")]
        assert not found, f"{what}: {_line(text, found[0].start())!r}"


def _line(text: str, at: int) -> str:
    return text[text.rfind("\n", 0, at) + 1:text.find("\n", at) if text.find("\n", at) >= 0 else None]


def test_the_scan_finds_what_it_looks_for() -> None:
    """Each pattern catches the instance the issue listed (so the scan can fail)."""
    for bad in ["T = 3*m*r**2/4", "1/2 m r² ω̇₃ + 0 ω₁ ω₂ = 0", "λ₁ = −2g/(3 (−R + r))",
                "θ = −3.08148791102e-32", "T = m ẋ² ", "    there.rate_squared.theta = 42.0429 1/s²",
                "    M[1] = [0.0466667] kg·m²", "    branches[1].solved.Omega**2 = 3.4748",
                "    angular_velocity = [0, —, 120]", "warning: -pi/2 <= theta <= pi/2"]:
        with pytest.raises(AssertionError):
            assert_reads_clean(bad)
    assert_reads_clean("(exact, relative error ≤ 3.8e-16)\nθ ∈ (−π, π]\n    λ = 2 g/(3 (R − r))")
    assert_reads_clean("(relative error about ε κ,\nε = 2.2e-16).")


# A number of the numeric block that is a pure number by what it is: a mode's amplitude
# (a₁, X₁), a friction coefficient (μ_C), a restitution (e), a unit vector (e₁), a ratio.
PURE = re.compile(r"^(a[₀-₉]+|X[₀-₉]+|μ\S*|e[₀-₉]*)$|/")
ENERGIES = re.compile(r"^(T|V|h|E|W)")  # T, V, Tᵢ, T_f, Tᵢ − T_f, h = T + V, the work W
DOUBLE_DOT, DOT = "\u0308", "\u0307"


def assert_units_right(lines: list[tuple[str, str]]) -> None:
    """The units of a numeric block (issue 41, item 5), read from each line's printed name,
    not from how rbdsolve works them out: every number has a unit unless it is a pure
    number by what it is; J only for an energy (a torque is N·m, a torsional stiffness
    N·m/rad: a radian is no dimension, so only the name tells them apart); a name with
    two dots (θ̈, ẍ) is per s², with one dot (θ̇, ẋ_f, not squared) per s; an eigenvalue λ
    in 1/s², a frequency ω₁ in rad/s; an angle in rad is never a rate."""
    for name, unit in lines:
        where = f"{name} in {unit or 'no unit'}"
        assert unit or PURE.search(name), f"{where}: no unit"
        assert unit != "J" or ENERGIES.match(name), f"{where}: J is for an energy"
        if DOUBLE_DOT in name:
            assert unit.endswith("/s²"), f"{where}: an acceleration is per s²"
        elif DOT in name and "²" not in name and not name.startswith("("):
            assert unit.endswith("/s"), f"{where}: a rate is per s"
        if re.fullmatch(r"λ[₀-₉]+", name):
            assert unit == "1/s²", f"{where}: λ = ω² is in 1/s²"
        if re.fullmatch(r"ω[₀-₉]+", name):
            assert unit == "rad/s", f"{where}: a frequency is in rad/s"


def test_the_unit_scan_finds_what_it_looks_for() -> None:
    """The wrong units the issue listed, each caught (so the scan can fail)."""
    for bad in [("M_C", "J"), ("K", "J"), ("θ̈", "rad"), ("λ₁", ""), ("R_Ox", ""), ("θ̇_f", "rad"), ("ω₁", "1/s"),
                ("ẋ_f", "")]:
        with pytest.raises(AssertionError):
            assert_units_right([bad])
    assert_units_right([("Tᵢ − T_f", "J"), ("(Tᵢ − T_f)/Tᵢ", ""), ("a₁", ""), ("μ_C", ""), ("θ̈", "rad/s²"),
                        ("ẋ²", "m²/s²"), ("K", "N·m/rad"), ("ω₁", "rad/s"), ("θ", "rad")])


def compare_numbers(got, want, where: str) -> None:
    """Numeric values: relative tolerance 1e-10 (the expected ones are hand-computed)."""
    if isinstance(want, dict):
        for key, value in want.items():
            compare_numbers(got[key], value, f"{where}.{key}")
    elif isinstance(want, list):
        assert len(got) == len(want), f"{where}: {got} != {want}"
        for i, (g, w) in enumerate(zip(got, want)):
            compare_numbers(g, w, f"{where}[{i}]")
    elif want is None:  # no number there (a push that never reaches zero)
        assert got is None, f"{where}: {got} != None"
    else:
        assert got == pytest.approx(want, rel=1e-10), f"{where}: {got} != {want}"


def compare_equilibria(got: list, want: list, where: str) -> None:
    assert len(got) == len(want), f"{where}: {len(got)} equilibria, expected {len(want)}"
    for w in want:
        match = [g for g in got if all(same(g["at"][k], str(v)) for k, v in w["at"].items())]
        assert match, f"{where}: no equilibrium at {w['at']}"
        compare(match[0], {k: v for k, v in w.items() if k != "at"}, f"{where}{w['at']}")


def test_every_example_has_expected_answers() -> None:
    """A problem file without golden answers is untested: keep the corpus complete."""
    problems = [p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml")]
    missing = [str(p.relative_to(PROBLEMS)) for p in problems
               if not (p.parent / p.name.replace(".yaml", ".expected.yaml")).exists()]
    assert not missing, f"problem files without expected answers: {missing}"
