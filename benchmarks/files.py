"""Per-file whole-process times: every problem file, as a student runs it.

    python3 -m benchmarks.files [PATH ...] [--repeats 3] [--timeout 300] [--out FILE.json]

PATH: problem files or folders (default: problems/). ``--twins``: each file that asks a
question ``from_rest: {q: v}`` is also timed as its twin asking ``at: {q: v, dot(q): 0}``,
the same instant given as a state (issue 37: released from rest never slower by more than
1 s). Each file is solved in its own process, ``python3 -m rbdsolve solve FILE --format json``, ``--repeats`` times; the
wall-clock seconds (median of the repeats), the processor seconds the child spent (user
+ system, from ``resource.getrusage(RUSAGE_CHILDREN)``: what a loaded machine does not
inflate) and the exit code are recorded. A run past ``--timeout`` is recorded as
"> T s". Prints a table and the p50, p90 and max over the files (issue 37: p90 ≤ 1.0 s
and max ≤ 2 s over problems/, each neighbouring problem ≤ 3 s); ``--out`` writes
every sample as JSON. The rbdsolve measured is this checkout's, or ``--root``'s (another
checkout, for a "before" column: the same files solved by the code before a change).
``--compare BEFORE.json AFTER.json`` prints the two runs side by side (the "before and
after" of docs/performance.md). Not a test: nothing fails on a slow machine.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


@dataclass(frozen=True)
class Timing:
    """One file's runs: wall and processor seconds per repeat, and the exit codes."""

    file: str
    wall: tuple[float, ...]
    cpu: tuple[float, ...]
    codes: tuple[int | None, ...]  # None: past the timeout

    @property
    def seconds(self) -> float:
        return statistics.median(self.wall)

    @property
    def cpu_seconds(self) -> float:
        return statistics.median(self.cpu)


def problem_files(paths: list[str]) -> list[Path]:
    """The problem files under each path (a folder's *.yaml but its *.expected.yaml)."""
    found: list[Path] = []
    for path in map(Path, paths):
        files = sorted(path.rglob("*.yaml")) if path.is_dir() else [path]
        found += [f for f in files if not f.name.endswith(".expected.yaml")]
    return found


def run_once(file: Path, timeout: float, root: Path = ROOT) -> tuple[float, float, int | None]:
    """One whole-process solve: (wall seconds, the child's processor seconds, exit code)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    env = {**os.environ, "PYTHONPATH": str(root)}
    try:
        code: int | None = subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(file.resolve()),
                                           "--format", "json"], cwd=root, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                          timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        code = None
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, code


def measure(file: Path, repeats: int, timeout: float, root: Path = ROOT) -> Timing:
    runs = [run_once(file, timeout, root) for _ in range(repeats if repeats > 0 else 1)]
    if runs[0][2] is None:  # past the timeout once: once is enough
        runs = runs[:1]
    return Timing(_shown(file), tuple(r[0] for r in runs), tuple(r[1] for r in runs), tuple(r[2] for r in runs))


def _shown(file: Path) -> str:
    """problems/… for a file of any checkout's problems/, else the path as given."""
    parts = file.resolve().parts
    return str(Path(*parts[len(parts) - 1 - parts[::-1].index("problems"):])) if "problems" in parts else str(file)


FROM_REST = re.compile(r"from_rest: \{([^{}]*)\}")


def at_rest_twin(text: str) -> str | None:
    """The text with each ``from_rest: {q: v, …}`` asked as ``at: {q: v, …, dot(q): 0, …}``
    (None: no question is released from rest)."""
    if not FROM_REST.search(text):
        return None

    def state(match: re.Match) -> str:
        names = re.findall(r"(\w+)\s*:", match.group(1))
        return "at: {" + match.group(1) + "".join(f", dot({n}): 0" for n in names) + "}"

    return FROM_REST.sub(state, text)


def twins(files: list[Path], repeats: int, timeout: float, folder: Path, root: Path = ROOT) -> list[tuple[Timing, Timing]]:
    """(released from rest, the same instant as a state) for each file with a twin."""
    pairs = []
    for file in files:
        twin = at_rest_twin(file.read_text(encoding="utf-8"))
        if twin is None:
            continue
        path = folder / f"{file.stem}.at-rest.yaml"
        path.write_text(twin, encoding="utf-8")
        pairs.append((measure(file, repeats, timeout, root), measure(path, repeats, timeout, root)))
    return pairs


def twins_table(pairs: list[tuple[Timing, Timing]]) -> str:
    lines = ["| file | from_rest (s) | at the state (s) | difference (s) | processor: from_rest, state, difference (s) |",
             "|---|---:|---:|---:|---:|"]
    for rest, state in pairs:
        lines.append(f"| {rest.file} | {rest.seconds:.2f} | {state.seconds:.2f} | {rest.seconds - state.seconds:+.2f} | "
                     f"{rest.cpu_seconds:.2f}, {state.cpu_seconds:.2f}, {rest.cpu_seconds - state.cpu_seconds:+.2f} |")
    return "\n".join(lines)


def quantile(values: list[float], q: float) -> float:
    """The q-quantile by linear interpolation between order statistics (numpy's default)."""
    ordered = sorted(values)
    if not ordered:
        return math.nan
    k = (len(ordered) - 1) * q
    low, high = math.floor(k), math.ceil(k)
    return ordered[low] + (ordered[high] - ordered[low]) * (k - low)


def summary(timings: list[Timing]) -> dict[str, float]:
    wall = [t.seconds for t in timings]
    cpu = [t.cpu_seconds for t in timings]
    return {"files": len(timings), "p50": quantile(wall, 0.5), "p90": quantile(wall, 0.9), "max": max(wall),
            "cpu_p50": quantile(cpu, 0.5), "cpu_p90": quantile(cpu, 0.9), "cpu_max": max(cpu)}


def table(timings: list[Timing], timeout: float) -> str:
    lines = ["| file | whole (s) | processor (s) | exit |", "|---|---:|---:|---:|"]
    for t in timings:
        past = t.codes[0] is None
        wall = f"> {timeout:g}" if past else f"{t.seconds:.2f}"
        codes = "timeout" if past else ",".join(sorted({str(c) for c in t.codes}))
        lines.append(f"| {t.file} | {wall} | {t.cpu_seconds:.2f} | {codes} |")
    s = summary(timings)
    lines.append("")
    lines.append(f"{s['files']} files: whole p50 {s['p50']:.2f} s, p90 {s['p90']:.2f} s, max {s['max']:.2f} s; "
                 f"processor p50 {s['cpu_p50']:.2f} s, p90 {s['cpu_p90']:.2f} s, max {s['cpu_max']:.2f} s")
    return "\n".join(lines)


def compare(before: dict, after: dict) -> str:
    """Two ``--out`` files side by side: per file, processor and whole seconds and exit
    codes before and after, then each run's p50, p90 and max."""
    old = {t["file"]: t for t in before["timings"]}
    lines = ["| file | before: processor, whole (s), exit | after: processor, whole (s), exit |", "|---|---|---|"]

    def cell(t: dict | None) -> str:
        if t is None:
            return "–"
        if t["codes"][0] is None:
            return f"past the timeout ({t['wall'][0]:.0f} s)"
        return (f"{statistics.median(t['cpu']):.2f}, {statistics.median(t['wall']):.2f}, "
                f"{','.join(sorted({str(c) for c in t['codes']}))}")

    for t in after["timings"]:
        lines.append(f"| {t['file']} | {cell(old.get(t['file']))} | {cell(t)} |")
    for name, run in (("before", before), ("after", after)):
        s = run["summary"]
        lines.append(f"\n{name}: {s['files']} files, processor p50 {s['cpu_p50']:.2f} s, p90 {s['cpu_p90']:.2f} s, "
                     f"max {s['cpu_max']:.2f} s; whole p50 {s['p50']:.2f} s, p90 {s['p90']:.2f} s, max {s['max']:.2f} s")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:
    if argv is None:
        argv = sys.argv[1:]
    if argv[:1] == ["--compare"]:
        before, after = (json.loads(Path(f).read_text()) for f in argv[1:3])
        print(compare(before, after))
        return
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="*", default=["problems"])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--timeout", type=float, default=300.0)
    parser.add_argument("--out", type=Path)
    parser.add_argument("--twins", action="store_true", help="also time each from_rest file asked at the state")
    parser.add_argument("--root", type=Path, default=ROOT, help="the checkout whose rbdsolve is measured")
    args = parser.parse_args(argv)
    load = os.getloadavg()
    timings = []
    for file in problem_files(args.paths):
        timings.append(measure(file, args.repeats, args.timeout, args.root))
        print(f"{timings[-1].file}: {timings[-1].seconds:.2f} s", file=sys.stderr, flush=True)
    print(f"load average before the run: {load[0]:.2f}, {load[1]:.2f}, {load[2]:.2f}; "
          f"after: {', '.join(f'{x:.2f}' for x in os.getloadavg())}; {os.cpu_count()} cores")
    print(table(timings, args.timeout))
    pairs = []
    if args.twins:
        with tempfile.TemporaryDirectory() as folder:
            pairs = twins(problem_files(args.paths), args.repeats, args.timeout, Path(folder), args.root)
        print()
        print(twins_table(pairs))
    if args.out:
        args.out.write_text(json.dumps({"load": load, "timings": [asdict(t) for t in timings],
                                        "summary": summary(timings),
                                        "twins": [[asdict(a), asdict(b)] for a, b in pairs]}, indent=1))


if __name__ == "__main__":
    main()
