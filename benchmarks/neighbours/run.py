"""Running rbdsolve on generated scenes: the installed command line, in whole processes
(start-up, loading, solving and printing JSON as a user's shell runs them), a few files
per process; each file's JSON object by its path, or the process's failure."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path


def rbdsolve_command() -> list[str]:
    """The installed command (``rbdsolve`` beside this Python), else ``python -m rbdsolve``."""
    exe = Path(sys.executable).with_name("rbdsolve")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "rbdsolve"]


def solve(paths: list[Path], budget: float, timeout: float, extra: tuple[str, ...] = ()) -> tuple[dict[str, dict], float, str]:
    """Every file's JSON object (``{}`` where the process gave none), the wall seconds
    of the process, and its standard error."""
    cmd = rbdsolve_command() + ["solve", *map(str, paths), "-f", "json", "-q", "--budget", str(budget), *extra]
    start = time.perf_counter()
    env = dict(os.environ)
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
        out, err = done.stdout, done.stderr
    except subprocess.TimeoutExpired as exc:
        out = exc.stdout.decode() if isinstance(exc.stdout, bytes) else (exc.stdout or "")
        err = f"timeout after {timeout} s"
    seconds = time.perf_counter() - start
    found: dict[str, dict] = {}
    for line in out.splitlines():
        try:
            obj = json.loads(line)
        except json.JSONDecodeError:
            continue
        found[obj.get("file", "")] = obj
    return {str(p): found.get(str(p), {}) for p in paths}, seconds, err
