"""Issue 28, findings 6-8, 10 and 12: text from a file made safe for where it goes
(terminal, messages, Markdown, LaTeX), YAML tags, limits on standard input and FIFOs,
zero axes by arithmetic, line numbers past U+0085 and U+2028, a missing coordinates
list, and a combining dot over a LaTeX special character."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.errors import InputError
from rbdsolve.problem import load_file, yamlnodes

from conftest import ROOT, SIMPLE_PENDULUM

CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e]")
PROBLEM = SIMPLE_PENDULUM + "questions: [eom]\n"


def run(*args, input=None):
    return CliRunner().invoke(main, [str(a) for a in args], input=input)


def write(tmp_path: Path, text: str, name: str = "p.yaml") -> Path:
    path = tmp_path / name
    path.write_bytes(text.encode("utf-8"))
    return path


@pytest.mark.parametrize("command", ["check", "solve"])
@pytest.mark.parametrize("line, at", [
    ('title: "\\e]0;PWNED\\a\\e[2J"\n', "1:8"),
    ('statement: "clear \\x1b[2J now"\n', "1:12"),
    ('source: "back\\rspace \\x85 \\u202e"\n', "1:9"),
    ('"\\e[8mhidden": 1\n', "1:1"),  # an unknown key: its own message must not hide itself
])
def test_control_characters_from_yaml_escapes_are_refused(tmp_path, command, line, at) -> None:
    path = write(tmp_path, line + PROBLEM)
    result = run(command, path)
    assert result.exit_code == 2, result.output
    assert not CONTROL.search(result.output), repr(result.output)
    assert result.stderr.startswith(f"{path}:{at}: ") and "a control character (\\x" in result.stderr


def test_a_file_name_with_control_characters_is_shown_escaped(tmp_path) -> None:
    path = write(tmp_path, "title: [unclosed\n", name="\x1b]0;X\x07.yaml")
    result = run("solve", path, "-f", "json")
    assert result.exit_code == 2 and not CONTROL.search(result.stderr), repr(result.stderr)
    assert "\\x1b]0;X\\x07.yaml:" in result.stderr


def test_markdown_escapes_html_and_links(tmp_path) -> None:
    text = ('title: "<script>alert(1)</script>"\n'
            'source: "[click](http://evil.example) ![x](http://evil.example/a.png)"\n'
            'statement: "<img src=x onerror=alert(1)> & $x$ # heading"\n') + PROBLEM
    result = run("solve", write(tmp_path, text), "-f", "markdown")
    assert result.exit_code == 0, result.output
    out = result.stdout
    for raw in ("<script>", "<img", "![x]", " $x$"):
        assert raw not in out, raw
    assert not re.search(r"(?<!\\)\]\(", out)  # no ']' that closes a link text: each is backslashed
    assert "\\[click\\](http://evil.example)" in out  # parentheses as they are: \( opens MathJax's math
    assert "&lt;script&gt;" in out and "&lt;img src=x onerror=alert(1)&gt; &amp; \\$x\\$ \\# heading" in out


def test_latex_escapes_a_combining_dot_over_a_special_character(tmp_path) -> None:
    text = 'statement: "A %\u0307 B, and x\u0307"\n' + PROBLEM
    result = run("solve", write(tmp_path, text), "-f", "latex")
    assert result.exit_code == 0, result.output
    assert "\\dot{%}" not in result.stdout and "A \\%[U+0307] B, and \\ensuremath{\\dot{x}}" in result.stdout


@pytest.mark.parametrize("tagged, shown", [
    ("statement: !!python/name:os.system\n", "!!python/name:os.system"),
    ("statement: !include /etc/passwd\n", "!include"),
    ("title: !!binary aGk=\n", "!!binary"),
])
def test_unknown_yaml_tags_are_bad_input(tmp_path, tagged, shown) -> None:
    path = write(tmp_path, tagged + PROBLEM)
    result = run("check", path)
    assert result.exit_code == 2
    assert result.stderr.startswith(f"{path}:1:") and f"the YAML tag '{shown}' is not supported" in result.stderr


def test_standard_input_is_limited_while_it_is_read() -> None:
    """50 MB on standard input: refused after reading one byte past the limit."""
    command = [sys.executable, "-m", "rbdsolve", "solve", "-"]
    done = subprocess.run(command, input=b"#" * (50 * 1024 * 1024), capture_output=True, timeout=60,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert done.returncode == 2 and b"<stdin>:1:1: file is more than 262144 bytes" in done.stderr


def test_a_pipe_that_never_ends_is_not_waited_for() -> None:
    read_end, write_end = os.pipe()  # the write end stays open: no end of file ever
    try:
        with open(read_end, "rb", buffering=0) as stream:
            with pytest.raises(InputError, match="no end of file within 0.3 s"):
                yamlnodes.read_stream(stream, "<stdin>", seconds=0.3)
    finally:
        os.close(write_end)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_fifo_as_a_problem_file_does_not_block(tmp_path, monkeypatch) -> None:
    monkeypatch.setattr(yamlnodes, "READ_SECONDS", 0.3)
    fifo = tmp_path / "p.yaml"
    os.mkfifo(fifo)
    with pytest.raises(InputError, match="no end of file"):
        load_file(fifo)  # nobody writes: it used to block in open() forever

    def writer() -> None:
        with open(fifo, "w") as handle:
            handle.write(PROBLEM)

    thread = threading.Thread(target=writer)
    monkeypatch.setattr(yamlnodes, "READ_SECONDS", 10.0)
    thread.start()
    assert load_file(fifo).coordinates[0].name == "theta"  # a FIFO that is written is read
    thread.join()


def test_an_axis_that_is_zero_by_arithmetic_is_refused(tmp_path) -> None:
    text = PROBLEM.replace("bob: {shape: particle, mass: m, at: P}",
                           "bob: {shape: rod, length: l, mass: m, at: P, axis: '[m - m, 0, 0]', angle: theta}")
    result = run("solve", write(tmp_path, text))
    zero = run("solve", write(tmp_path, text.replace("[m - m, 0, 0]", "[0, 0, 0]"), name="zero.yaml"))
    assert zero.exit_code == 2 and "zero vector" in zero.stderr
    assert result.exit_code == 2 and "an axis direction must not be the zero vector" in result.stderr
    assert ":7:" in result.stderr and "Traceback" not in result.output


def test_line_numbers_are_an_editors_past_a_next_line_character(tmp_path) -> None:
    """YAML breaks a line at U+0085 (NEL), an editor does not: after a statement holding
    one, an unknown key is reported on the line an editor shows."""
    text = 'statement: "one\u0085two"\ntitle: x\n' + PROBLEM.replace("gravity:", "gravty:", 1)
    result = run("check", write(tmp_path, text))
    wanted = 2 + PROBLEM.splitlines().index("gravity: [0, -g]") + 1
    assert result.exit_code == 2 and f":{wanted}:1: gravty: unknown key" in result.stderr, result.stderr


@pytest.mark.parametrize("separator, escaped", [("\u2028", "\\u2028"), ("\u2029", "\\u2029")])
def test_a_line_separator_in_a_string_is_refused_where_it_is(tmp_path, separator, escaped) -> None:
    text = 'title: x\nstatement: "one' + separator + 'two"\n' + PROBLEM
    result = run("check", write(tmp_path, text))
    assert result.exit_code == 2 and f":2:12: statement: a control character ({escaped})" in result.stderr, \
        result.stderr


def test_a_file_without_coordinates_is_told_so(tmp_path) -> None:
    text = PROBLEM.replace("coordinates: [theta]\n", "")
    result = run("check", write(tmp_path, text))
    assert result.exit_code == 2 and "unknown symbol 'theta'" in result.stderr
    assert "the file declares no coordinates: list them as 'coordinates: [...]'" in result.stderr
