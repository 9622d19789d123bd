"""Hostile expressions are refused by the parser, never evaluated.

Each payload would create the file CANARY if anything evaluated it (through eval,
sympify, parse_expr, an f-string, a lambda...). It is put in every place a problem
file holds an expression, and on the command line with ``--set``; each time rbdsolve
must exit 2 with one located line, and the canary must never appear.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

PAYLOADS = [
    "__import__('os').system('touch {c}')",
    "open('{c}', 'w')",
    "(lambda: open('{c}', 'w'))()",
    "[open('{c}', 'w') for _ in [1]]",
    "{{open('{c}', 'w') for _ in [1]}}",
    "f\"{{open('{c}', 'w')}}\"",
    "(x := open('{c}', 'w'))",
    "().__class__.__bases__[0].__subclasses__()",
    "getattr(__builtins__, 'open')('{c}', 'w')",
    "exec(\"open('{c}', 'w')\")",
    "eval(\"open('{c}', 'w')\")",
    "compile(\"open('{c}', 'w')\", 'f', 'eval')",
    "__builtins__",
    "__import__",
    "sin(*[open('{c}', 'w')])",
    "sin(**{{'x': open('{c}', 'w')}})",
    "sin(x=open('{c}', 'w'))",
    "sympy.sympify(\"open('{c}', 'w')\")",
    "os.system('touch {c}')",
    "m.__class__",
    "sin.__call__(m)",
    "m[0]",
    "'touch {c}'",
    "b'touch'",
    "m if open('{c}', 'w') else m",
    "open('{c}', 'w') and m",
    "m < open('{c}', 'w')",
    "globals()",
    "breakpoint()",
    "import os",
    "(yield open('{c}', 'w'))",
    "m @ m",
    "m % 2",
    "{{'a': open('{c}', 'w')}}",
    "True",
    "None",
    "...",
    "0x10",
    "1j",
]

SCENE = """\
title: Hostile
parameters: {{m: mass, l: length, g: gravity, k: stiffness}}
values: {{m: {value}}}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  P: {point}
bodies:
  bob: {{shape: particle, mass: {mass}, at: P}}
springs:
  s: {{stiffness: {stiffness}, between: [P, O]}}
questions:
  - modes: {{about: {{theta: {about}}}}}
"""
SAFE = {"value": "1", "point": "l * [sin(theta), -cos(theta)]", "mass": "m", "stiffness": "k", "about": "0"}
# place -> (the key it replaces, how the payload is written there, the line it is on)
PLACES = {
    "value": ("value", "{p}", 3),
    "point": ("point", "{p}", 8),
    "point component": ("point", "[{p}, 0]", 8),
    "mass": ("mass", "{p}", 10),
    "stiffness": ("stiffness", "{p}", 12),
    "about": ("about", "{p}", 14),
}


def scene(place: str, payload: str) -> str:
    key, template, _ = PLACES[place]
    quoted = json.dumps(payload)  # a JSON string is a YAML double-quoted scalar
    return SCENE.format(**{**SAFE, key: template.format(p=quoted)})


def test_the_safe_scene_solves(tmp_path: Path) -> None:
    path = tmp_path / "safe.yaml"
    path.write_text(SCENE.format(**SAFE), encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path)])
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("place", PLACES)
@pytest.mark.parametrize("payload", PAYLOADS)
def test_payload_is_refused_and_never_runs(tmp_path: Path, place: str, payload: str) -> None:
    canary = tmp_path / "CANARY"
    path = tmp_path / "hostile.yaml"
    path.write_text(scene(place, payload.format(c=canary)), encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path)])
    assert result.exit_code == 2, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "internal error" not in lines[0], result.stderr
    assert lines[0].startswith(f"{path}:{PLACES[place][2]}:"), lines[0]
    assert not canary.exists()


@pytest.mark.parametrize("payload", PAYLOADS)
def test_payload_on_the_command_line_is_refused(tmp_path: Path, payload: str) -> None:
    canary = tmp_path / "CANARY"
    path = tmp_path / "safe.yaml"
    path.write_text(SCENE.format(**SAFE), encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--set", f"m={payload.format(c=canary)}"])
    assert result.exit_code == 2, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("--set"), result.stderr
    assert not canary.exists()
