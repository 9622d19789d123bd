"""The benchmark: speed against accuracy, per family, route and size.

    python3 -m benchmarks.run [--quick | --scale [--max-size N]] [--out benchmarks/results]

``--scale`` runs only the rows of issue 23 (rod chains on the default route to n = 32,
the numeric route to n = 200, start-up), a few minutes; ``--max-size N`` keeps only
the sizes ≤ N (a smoke test of the benchmark itself).

Writes results.json and the charts (PNG and SVG) into --out, among them
conditioning.png (benchmarks.conditioning: the numeric modes route's actual error and
stated bound against the condition number, a few seconds). Every measurement runs in
a child process with a timeout; a size that times out is recorded as "> T s" and the
family/route stops growing there. See docs/performance.md.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass, replace
from pathlib import Path

from benchmarks.families import FAMILIES
from benchmarks.measure import LONG

ROOT = Path(__file__).resolve().parent.parent
SEED_P1 = ROOT / "problems" / "sg2150-2015-10-29" / "p1-two-rods.yaml"
SEED_CHECK = ROOT / "problems" / "sg2150-2015-10-29"
HEAVY = ("sympy", "numpy", "scipy", "mpmath", "rich")


@dataclass(frozen=True)
class Plan:
    """Sizes per family and route, the per-measurement timeout and the repeats."""

    sizes: dict[tuple[str, str], tuple[int, ...]]
    timeout: float
    baseline_sizes: tuple[int, ...]
    baseline_timeout: float
    repeats: int = 3
    whole_process_limit: float = 5.0  # whole-process timings only where one solve takes less
    # Measured as a whole process whatever one solve takes (issue 23's rows: its targets
    # are whole-process seconds and JSON bytes); the timeout still bounds each.
    whole_always: frozenset[tuple[str, str]] = frozenset()


# Issue 23 (speed at scale): rod chains on the default route (auto: what
# `rbdsolve solve FILE` does without --route) to n = 32, the numeric route to n = 200.
SCALE_SIZES = {
    ("chain_rods", "auto"): (8, 10, 12, 16, 24, 32),
    ("chain_points", "numeric"): (10, 20, 50, 100, 200),
    ("chain_rods", "numeric"): (10, 20, 50, 100, 200),
}
# Run as a whole process at every size: issue 23 judges these by whole-process seconds
# and JSON bytes (the numeric rows by compute: whole only under whole_process_limit).
WHOLE_ALWAYS = frozenset({("chain_rods", "auto")})

FULL = Plan({
    ("chain_points", "exact"): (1, 2, 3, 5, 8, 10),
    ("chain_points", "numeric"): (1, 2, 3, 5, 8, 10, 15, 20, 30, 50, 100, 200),
    ("chain_rods", "exact"): (1, 2, 3, 5, 8, 10),
    ("chain_rods", "auto"): SCALE_SIZES[("chain_rods", "auto")],
    ("chain_rods", "numeric"): (1, 2, 3, 5, 10, 20, 30, 50, 100, 200),
    ("springs", "exact"): (1, 2, 5, 10),
    ("springs", "numeric"): (1, 2, 5, 10, 20, 50),
    ("composite", "exact"): (1, 3, 9, 27),
    ("composite", "numeric"): (1, 3, 9, 27),
    ("impact", "exact"): (1, 2, 5),
    ("impact", "numeric"): (1, 2, 5, 10),
    ("spin", "exact"): (1, 2, 4, 8),
    ("spin", "numeric"): (1, 2, 4, 8),
    ("eom_chain", "exact"): (1, 2, 3, 5, 8),
    ("eom_chain", "numeric"): (1, 2, 3, 5, 8),
}, timeout=60.0, baseline_sizes=(1, 2, 3, 5, 8, 10, 12, 16), baseline_timeout=60.0, whole_process_limit=3.0,
    whole_always=WHOLE_ALWAYS)

QUICK = Plan({key: tuple(n for n in sizes if n <= 2) for key, sizes in FULL.sizes.items()},
             timeout=30.0, baseline_sizes=(1, 2), baseline_timeout=30.0, repeats=3,
             whole_process_limit=2.0)

SCALE = Plan(SCALE_SIZES, timeout=60.0, baseline_sizes=(), baseline_timeout=60.0,
             whole_process_limit=3.0, whole_always=WHOLE_ALWAYS)


def up_to(plan: Plan, largest: int) -> Plan:
    """The plan with only the sizes ≤ ``largest`` (a smoke test of the benchmark)."""
    return replace(plan, sizes={key: tuple(n for n in sizes if n <= largest) for key, sizes in plan.sizes.items()},
                   baseline_sizes=tuple(n for n in plan.baseline_sizes if n <= largest))


@dataclass(frozen=True)
class RouteMeasurement:
    """One family/size/route: in-process median of solve_problem (load+build+solve), the
    question's own seconds, whole-process median (None where not measured) and the bytes
    of its JSON on standard output, relative error against the 50-digit reference, the
    route's own error estimate, the route that answered (auto: exact or numeric), and a
    status ("ok", "timeout", or the solver's error)."""

    family: str
    size: int
    route: str
    status: str
    median_s: float | None = None
    samples_s: tuple[float, ...] = ()
    solution_s: float | None = None
    compute_s: float | None = None  # load + build + the solver, without the model section (T, V)
    whole_process_s: float | None = None
    relative_error: float | None = None
    error_estimate: float | None = None
    timeout_s: float | None = None
    route_ran: str | None = None
    json_bytes: int | None = None
    whole_timed_out: bool = False  # the whole process did not finish within the timeout


@dataclass(frozen=True)
class BaselineMeasurement:
    """sympy.physics.mechanics on the n-link point-mass chain: seconds of each phase in
    its process (compute = equations + linearize + exact eigenvalues), the whole process
    and the relative errors of its exact and numeric eigenvalues."""

    method: str
    n: int
    status: str
    equations_s: float | None = None
    linearize_s: float | None = None
    eigen_exact_s: float | None = None
    eigen_numeric_s: float | None = None
    compute_s: float | None = None
    whole_process_s: float | None = None
    relative_error_exact: float | None = None
    relative_error_numeric: float | None = None
    timeout_s: float | None = None


@dataclass(frozen=True)
class StartupMeasurement:
    """A whole command's wall time (median of the samples) and which heavy modules its
    process had imported when it ended."""

    label: str
    command: tuple[str, ...]
    median_s: float
    samples_s: tuple[float, ...]
    heavy_modules: tuple[str, ...] | None = None


def _python() -> list[str]:
    return [sys.executable]


def _wall(command: list[str], timeout: float, cwd: Path = ROOT) -> tuple[float, subprocess.CompletedProcess]:
    """Wall-clock seconds of one child process (perf_counter around subprocess.run)."""
    start = time.perf_counter()
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    return time.perf_counter() - start, done


def _median_wall(command: list[str], repeats: int, timeout: float) -> tuple[float, tuple[float, ...]]:
    samples = tuple(_wall(command, timeout)[0] for _ in range(repeats))
    return statistics.median(samples), samples


@dataclass(frozen=True)
class WholeProcess:
    """`python -m rbdsolve solve FILE [--route R] --format json`: median seconds, the
    bytes of the JSON it printed, or timed_out."""

    median_s: float | None
    json_bytes: int | None
    timed_out: bool = False


def measure_whole(path: Path, route: str, repeats: int, timeout: float) -> WholeProcess:
    """Up to ``repeats`` runs (one more only while a run takes under LONG s); the default
    route (auto) is run without --route, as a user would."""
    command = _python() + ["-m", "rbdsolve", "solve", str(path), "--format", "json"]
    if route != "auto":
        command[4:4] = ["--route", route]
    samples, size = [], None
    try:
        while len(samples) < repeats and (not samples or samples[-1] <= LONG):
            seconds, done = _wall(command, timeout)
            samples.append(seconds)
            size = len(done.stdout.encode())
    except subprocess.TimeoutExpired:
        return WholeProcess(None, None, True)
    return WholeProcess(statistics.median(samples), size)


def measure_route(family: str, size: int, route: str, plan: Plan, files: Path) -> RouteMeasurement:
    """In-process timing in a child (benchmarks.measure), then, if one solve is short,
    the whole process `python -m rbdsolve solve FILE --route R --format json`."""
    command = _python() + ["-m", "benchmarks.measure", family, str(size), route, str(plan.repeats)]
    try:
        _, done = _wall(command, plan.timeout)
    except subprocess.TimeoutExpired:
        return RouteMeasurement(family, size, route, "timeout", timeout_s=plan.timeout)
    if done.returncode != 0:
        return RouteMeasurement(family, size, route, "failed: " + done.stderr.strip().splitlines()[-1][:200])
    data = json.loads(done.stdout)
    if data["error"]:
        return RouteMeasurement(family, size, route, data["error"][:200])
    whole = WholeProcess(None, None)
    if data["median"] < plan.whole_process_limit or (family, route) in plan.whole_always:
        path = files / f"{family}-{size}.yaml"
        path.write_text(FAMILIES[family](size).text)
        whole = measure_whole(path, route, plan.repeats, plan.timeout)
    return RouteMeasurement(family, size, route, "ok", data["median"], tuple(data["samples"]),
                            data["solution_seconds"], data["compute"], whole.median_s, data["relative_error"],
                            data["error_estimate"], route_ran=data["route_ran"], json_bytes=whole.json_bytes,
                            whole_timed_out=whole.timed_out)


def measure_routes(plan: Plan, files: Path) -> list[RouteMeasurement]:
    """Every family and route over its sizes; a route stops growing after a timeout (of
    the in-process solve or of the whole process)."""
    out = []
    for (family, route), sizes in plan.sizes.items():
        for size in sizes:
            m = measure_route(family, size, route, plan, files)
            out.append(m)
            whole = "> timeout" if m.whole_timed_out else _fmt(m.whole_process_s)
            json_kb = "" if m.json_bytes is None else f"  JSON {m.json_bytes / 1000:.0f} KB"
            _log(f"{family:13s} {route:8s} n={size:3d} {m.status:22s} in-process {_fmt(m.median_s)}  "
                 f"compute {_fmt(m.compute_s)}  whole {whole}{json_kb}  ran {m.route_ran}  rel.err {m.relative_error}")
            if m.status != "ok" or m.whole_timed_out:
                break
    return out


def measure_conditioning(timeout: float = 120.0) -> list[dict]:
    """The numeric modes route against the condition number (benchmarks.conditioning, a
    few seconds) in its own process; [] with a logged reason if it fails or times out."""
    try:
        _, done = _wall(_python() + ["-m", "benchmarks.conditioning"], timeout)
    except subprocess.TimeoutExpired:
        _log(f"conditioning  timed out after {timeout:.0f} s")
        return []
    if done.returncode != 0:
        _log("conditioning  failed: " + (done.stderr.strip().splitlines() or ["?"])[-1][:200])
        return []
    rows = json.loads(done.stdout)
    worst = max((r["actual"] / r["bound"] for r in rows if r["bound"]), default=None)
    _log(f"conditioning  {len(rows)} eigenvalues; largest actual error / stated bound {worst}")
    return rows


def measure_baseline(method: str, n: int, timeout: float) -> BaselineMeasurement:
    """One run of benchmarks.baseline in its own process, with a timeout."""
    try:
        whole, done = _wall(_python() + ["-m", "benchmarks.baseline", method, str(n)], timeout)
    except subprocess.TimeoutExpired:
        return BaselineMeasurement(method, n, "timeout", timeout_s=timeout)
    if done.returncode != 0:
        return BaselineMeasurement(method, n, "failed: " + done.stderr.strip().splitlines()[-1][:200])
    d = json.loads(done.stdout)
    ref = _chain_reference(n)
    return BaselineMeasurement(method, n, "ok", d["equations"], d["linearize"], d["eigen_exact"],
                               d["eigen_numeric"], d["equations"] + d["linearize"] + d["eigen_exact"], whole,
                               _rel(d["eigenvalues_exact"], ref), _rel(d["eigenvalues_numeric"], ref))


def _chain_reference(n: int) -> list:
    import sympy as sp

    from rbdsolve.solvers.modes.numeric import reference_eigenvalues

    case = FAMILIES["chain_points"](n)
    rational = [[[sp.Rational(x.numerator, x.denominator) for x in row] for row in A] for A in (case.K, case.M)]
    return reference_eigenvalues(*rational)


def _rel(values, ref) -> float:
    import mpmath

    with mpmath.workdps(40):
        got = sorted(mpmath.mpf(str(x)) for x in values)
        return float(max(abs(a - b) / abs(b) for a, b in zip(got, ref)))


def measure_baselines(plan: Plan) -> list[BaselineMeasurement]:
    """LagrangesMethod and KanesMethod over the baseline sizes, one run each (they are
    long; a rerun of the benchmark is the repeat), stopping after a timeout."""
    out = []
    for method in ("lagrange", "kane"):
        for n in plan.baseline_sizes:
            m = measure_baseline(method, n, plan.baseline_timeout)
            out.append(m)
            _log(f"mechanics     {method:8s} n={n:3d} {m.status:22s} compute {_fmt(m.compute_s)}  "
                 f"whole {_fmt(m.whole_process_s)}")
            if m.status != "ok":
                break
    return out


def _imports_of(args: list[str]) -> tuple[str, ...]:
    """The heavy modules loaded by running the rbdsolve CLI with ``args`` in a child:
    main() is called in-process and sys.modules inspected when it exits."""
    probe = ("import sys\nfrom rbdsolve.cli import main\n"
             "try:\n    main(%r)\nexcept SystemExit:\n    pass\n"
             "print('HEAVY', ','.join(m for m in %r if m in sys.modules), file=sys.stderr)\n") % (args, HEAVY)
    _, done = _wall(_python() + ["-c", probe], 120)
    line = [x for x in done.stderr.splitlines() if x.startswith("HEAVY")][-1]
    return tuple(x for x in line.split(" ", 1)[1].split(",") if x)


def measure_startup(plan: Plan) -> list[StartupMeasurement]:
    """Whole-process medians: python -c "import sympy", rbdsolve --help, rbdsolve check,
    rbdsolve solve p1 --format json, and the plain mechanics script for p1."""
    repeats = max(plan.repeats, 5)
    cases = [
        ("python -c 'import sympy'", _python() + ["-c", "import sympy"], None),
        ("python -c 'pass'", _python() + ["-c", "pass"], None),
        ("rbdsolve --help", _python() + ["-m", "rbdsolve", "--help"], ["--help"]),
        ("rbdsolve check sg2150-2015-10-29/", _python() + ["-m", "rbdsolve", "check", str(SEED_CHECK)],
         ["check", str(SEED_CHECK)]),
        ("rbdsolve solve p1 --format json", _python() + ["-m", "rbdsolve", "solve", str(SEED_P1), "--format", "json"],
         ["solve", str(SEED_P1), "--format", "json"]),
        ("mechanics script for p1", _python() + [str(ROOT / "benchmarks" / "seed_p1_mechanics.py")], None),
    ]
    out = []
    for label, command, cli_args in cases:
        median, samples = _median_wall(command, repeats, 300)
        heavy = _imports_of(cli_args) if cli_args is not None else None
        out.append(StartupMeasurement(label, tuple(command), median, samples, heavy))
        _log(f"startup       {label:36s} {_fmt(median)}  heavy: {heavy}")
    return out


def compiled_package() -> None:
    """rbdsolve's modules compiled to bytecode (__pycache__), as an installed package's
    are (pip compiles them when it installs) and as sympy's already are: a checkout run
    with PYTHONDONTWRITEBYTECODE set would otherwise compile its ~100 modules from source
    in every process, about 0.09 s that no user pays. No result is cached: only the
    compiled form of the source, which Python checks against the source's time stamp."""
    import compileall

    compileall.compile_dir(str(ROOT / "rbdsolve"), quiet=1)


def _fmt(x: float | None) -> str:
    return "   -   " if x is None else f"{x:7.3f}s"


def _log(text: str) -> None:
    print(text, flush=True)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--quick", action="store_true", help="small sizes only (a minute or two)")
    which.add_argument("--scale", action="store_true",
                       help="only issue 23's rows: rod chains to n = 32 on the default route, numeric to "
                            "n = 200, start-up (a few minutes)")
    parser.add_argument("--max-size", type=int, help="only the sizes ≤ this (a smoke test of the benchmark)")
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "results"))
    parser.add_argument("--skip-baselines", action="store_true", help="leave out sympy.physics.mechanics")
    args = parser.parse_args(argv)
    name = "quick" if args.quick else "scale" if args.scale else "full"
    plan = {"quick": QUICK, "scale": SCALE, "full": FULL}[name]
    if args.max_size is not None:
        plan, name = up_to(plan, args.max_size), f"{name}, sizes ≤ {args.max_size}"
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    compiled_package()  # every whole process below reads rbdsolve as an installed copy would
    with tempfile.TemporaryDirectory() as files:
        routes = measure_routes(plan, Path(files))
    conditioning = [] if args.scale else measure_conditioning()
    baselines = [] if args.skip_baselines else measure_baselines(plan)
    startup = measure_startup(plan)
    from benchmarks.report import targets, write_charts, write_tables
    from benchmarks.scale import scale_targets

    result = {"plan": name, "python": sys.version.split()[0],
              "routes": [asdict(m) for m in routes], "baselines": [asdict(m) for m in baselines],
              "startup": [asdict(m) for m in startup], "conditioning": conditioning,
              "targets": [asdict(t) for t in targets(routes, baselines, startup)],
              "scale_targets": [asdict(t) for t in scale_targets(routes, startup)],
              "wall_seconds": time.perf_counter() - started}
    (out / "results.json").write_text(json.dumps(result, indent=1))
    write_tables(result, out / "tables.md")
    write_charts(result, out)
    _log(f"wrote {out}/results.json, tables.md and charts in {time.perf_counter() - started:.0f} s")


if __name__ == "__main__":
    main()
