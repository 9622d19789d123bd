"""``rbdsolve key``: the seed exam's answer key in each format, and what a key does with
a bad file, a bad suffix and a missing TeX engine."""

from __future__ import annotations

import shutil
import subprocess

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.problem import load_file
from rbdsolve.report.key import default_title

from conftest import SEED, needs_tex

BAD = SEED.parents[1] / "tests" / "problem" / "bad" / "001-yaml-unclosed-flow-mapping.yaml"
SEED_FILES = sorted(p for p in SEED.glob("*.yaml") if not p.name.endswith(".expected.yaml"))


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


@pytest.fixture(scope="module")
def seed_keys(tmp_path_factory) -> dict[str, str]:
    """The seed exam's key as .md, .tex and .html (figures on), written once."""
    folder = tmp_path_factory.mktemp("key")
    out = {}
    for suffix in ("md", "tex", "html"):
        result = run("key", SEED, "-o", folder / f"key.{suffix}", "--quiet")
        assert result.exit_code == 0, result.output
        out[suffix] = (folder / f"key.{suffix}").read_text(encoding="utf-8")
    out["folder"] = str(folder)
    return out


@pytest.mark.parametrize("suffix", ["md", "tex", "html"])
def test_every_problem_is_in_the_key_with_its_statement(seed_keys, suffix) -> None:
    text = seed_keys[suffix]
    for path in SEED_FILES:
        problem = load_file(path)
        assert problem.title in text
        first_words = " ".join(problem.statement.split()[:4])  # before any symbol LaTeX would escape
        assert first_words in text, (path.name, first_words)
    assert "SG2150 exam 2015-10-29" in text


def test_final_answers_are_boxed(seed_keys) -> None:
    # p1's eigenvalues λ₁ = 24g/(25r), λ₂ = 2g/r (the exam's solution), boxed in LaTeX and Markdown
    assert "\\boxed{\\lambda_{1} = \\frac{24 g}{25 r}}" in seed_keys["tex"]
    assert "\\boxed{\\lambda_{2} = \\frac{2 g}{r}}" in seed_keys["md"]
    assert ('<span class="result"><math displaystyle="true"><mrow><msub><mi>λ</mi><mn>1</mn></msub><mo>=</mo>'
            '<mrow><mfrac><mrow><mn>24</mn><mo>\u2062</mo><mi>g</mi></mrow><mrow><mn>25</mn><mo>\u2062</mo><mi>r</mi></mrow>'
            '</mfrac></mrow></mrow></math></span>') in seed_keys["html"]  # MathML: λ₁ = 24g/(25r) typeset


def test_pictures_of_the_planar_problems(seed_keys) -> None:
    from pathlib import Path

    figures = sorted(p.name for p in (Path(seed_keys["folder"]) / "key-figures").iterdir())
    assert any(name.startswith("01-p1-two-rods") for name in figures)  # the scene and its modes
    assert not any(name.startswith("03-p3") for name in figures)  # a 3-D scene is not drawn
    for name in figures:
        assert f"key-figures/{name}" in seed_keys["md"] and f"key-figures/{name}" in seed_keys["tex"]


def test_html_is_one_file_with_nothing_from_the_network(seed_keys) -> None:
    html = seed_keys["html"]
    assert "<script" not in html and "http://" not in html and "https://" not in html.replace(
        "http://www.w3.org/2000/svg", "")  # an embedded SVG names its namespace, fetches nothing
    assert "data:image/svg+xml;base64," in html


def test_the_seed_key_compiles_to_pdf(tmp_path) -> None:
    needs_tex()
    result = run("key", SEED, "-o", tmp_path / "key.pdf", "--quiet")
    assert result.exit_code == 0, result.output
    pdf = (tmp_path / "key.pdf").read_bytes()
    assert pdf.startswith(b"%PDF") and len(pdf) > 50_000
    if shutil.which("pdftotext"):
        text = subprocess.run(["pdftotext", str(tmp_path / "key.pdf"), "-"], capture_output=True,
                              text=True, check=True).stdout
        for path in SEED_FILES:
            assert load_file(path).title in text
    assert not list(tmp_path.glob("*.tex"))  # a PDF key leaves no LaTeX behind


def test_a_bad_file_is_said_in_the_key_and_in_the_exit_code(tmp_path) -> None:
    result = run("key", SEED_FILES[0], BAD, "-o", tmp_path / "key.md", "--no-figures")
    assert result.exit_code == 2
    text = (tmp_path / "key.md").read_text(encoding="utf-8")
    assert "Two rods in a circle" in text and "Not solved" in text and "YAML syntax error" in text


def test_a_key_is_pdf_tex_md_or_html(tmp_path) -> None:
    result = run("key", SEED, "-o", tmp_path / "key.docx")
    assert result.exit_code == 2 and "the key is written as .pdf, .tex, .md, .html" in result.output


def test_a_pdf_without_a_tex_engine_says_how_to_get_one(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("RBDSOLVE_LATEX", "no-such-tex-engine")
    result = run("key", SEED_FILES[3], "-o", tmp_path / "key.pdf", "--no-figures")
    assert result.exit_code == 2 and "needs a LaTeX engine" in result.output
    assert "RBDSOLVE_LATEX=no-such-tex-engine names none on PATH" in result.output


def test_default_title() -> None:
    assert default_title(["exam/"], ["SG2150 exam 2015-10-29, problem 1", "SG2150 exam 2015-10-29, problem 2"]) \
        == "Answer key: SG2150 exam 2015-10-29"
    assert default_title(["exams/final"], ["", "Textbook 3.2"]) == "Answer key: final"
    assert default_title(["a.yaml", "b.yaml"], ["x", "y"]) == "Answer key"


def test_a_missing_output_folder_is_said_before_any_solving(tmp_path) -> None:
    for suffix in ("pdf", "md"):
        result = run("key", SEED_FILES[0], "-o", tmp_path / "missing" / f"key.{suffix}")
        assert result.exit_code == 2 and "there is no folder" in result.output and "Summary" not in result.output


def test_file_names_and_titles_that_tex_and_matplotlib_would_read_as_code(tmp_path) -> None:
    # '%' and '#' in file names, '$' and a TeX command in the title: all plain text in the key
    odd = tmp_path / "50% rod#1.yaml"
    scene = (SEED.parent / "examples" / "pendulum.yaml").read_text(encoding="utf-8")
    odd.write_text("title: 'Cost $5 and $x^$ \\input{/etc/passwd} 100%'\n" + scene.split("\n", 1)[1],
                   encoding="utf-8")
    result = run("key", odd, "-o", tmp_path / "my key%.md", "--quiet")
    assert result.exit_code == 0, result.output
    text = (tmp_path / "my key%.md").read_text(encoding="utf-8")
    assert "(my-key-figures/01-50-rod-1.png)" in text
    tex = run("key", odd, "-o", tmp_path / "k.tex", "--quiet")
    assert tex.exit_code == 0 and "\\textbackslash{}input\\{/etc/passwd\\}" in (tmp_path / "k.tex").read_text()
    if shutil.which("pdflatex"):
        pdf = run("key", odd, "-o", tmp_path / "k%.pdf", "--quiet")
        assert pdf.exit_code == 0, pdf.output
