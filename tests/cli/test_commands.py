"""The command registry (cli/app.py's ``COMMANDS``): ``rbdsolve --help`` lists the
commands from it without importing them, so it must name every command and say what
each command's own docstring says."""

from __future__ import annotations

import importlib
import pkgutil

import click
import pytest
from click.testing import CliRunner

import rbdsolve.cli
from rbdsolve.cli import main
from rbdsolve.cli.app import COMMANDS


def defined_commands() -> set[str]:
    """Every cli module that defines a click command named after itself."""
    found = set()
    for info in pkgutil.iter_modules(rbdsolve.cli.__path__):
        module = importlib.import_module(f"rbdsolve.cli.{info.name}")
        if isinstance(getattr(module, info.name, None), click.Command):
            found.add(info.name)
    return found


def test_the_registry_names_every_command() -> None:
    assert set(COMMANDS) == defined_commands()


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_the_short_help_is_the_docstrings_first_sentence(name: str) -> None:
    command = main.get_command(click.Context(main), name)
    assert command.name == name
    assert COMMANDS[name] == command.get_short_help_str(10**6)


@pytest.mark.parametrize("width", [40, 80, 120])
def test_help_lists_what_click_would(width: int) -> None:
    """The listing as click makes it from the commands themselves, at any width."""
    ctx = click.Context(main, terminal_width=width)
    formatter = ctx.make_formatter()
    click.Group.format_commands(main, ctx, formatter)
    ours = ctx.make_formatter()
    main.format_commands(ctx, ours)
    assert ours.getvalue() == formatter.getvalue()


def test_an_unknown_command_is_refused() -> None:
    done = CliRunner().invoke(main, ["solvee"])
    assert done.exit_code == 2
    assert "No such command 'solvee'" in done.output
