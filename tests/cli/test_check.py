"""``rbdsolve check``: -q says nothing of good files, only the errors."""

from __future__ import annotations

from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS

SEED = str(PROBLEMS / "sg2150-2015-10-29")


def test_quiet_check_of_good_files_prints_nothing() -> None:
    result = CliRunner().invoke(main, ["check", "-q", SEED])
    assert result.exit_code == 0
    assert result.output == ""


def test_quiet_check_still_says_each_error_and_its_exit_code(tmp_path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("title: x\nparameters: [m\n")
    result = CliRunner().invoke(main, ["check", "--quiet", SEED, str(bad)])
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr.strip().splitlines() == [
        f"{bad}:2:13: YAML syntax error: this '[' is never closed: no ']' before the end of the file "
        "(while parsing a flow sequence)"]


def test_check_without_quiet_names_every_good_file() -> None:
    result = CliRunner().invoke(main, ["check", SEED])
    assert result.exit_code == 0
    assert len(result.output.splitlines()) == len(list((PROBLEMS / "sg2150-2015-10-29").glob("*.yaml"))) - len(
        list((PROBLEMS / "sg2150-2015-10-29").glob("*.expected.yaml")))
