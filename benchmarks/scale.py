"""Issue 23 (speed at scale) from a benchmark result: its targets (met or not), the
growth of each route's time with n (the slope of log t against log n) and the chart of
time against n on log–log axes (scaling.png and .svg).

The slope of a route is the least-squares slope of log t against log n over its last
SLOPE_POINTS sizes that finished: t ∝ n^slope there, so 2 is quadratic growth, 3 cubic.
A route that timed out has no time at its last size; its slope is over the sizes
before, which understates the growth (the chart marks the timeout).

Called by benchmarks.report (tables and charts); run.py stores scale_targets too.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

from benchmarks.figures import save

SLOPE_POINTS = 4  # the last sizes that finished, fitted for the slope
DEFAULT = "auto"  # the route `rbdsolve solve FILE` takes without --route


@dataclass(frozen=True)
class ScaleTarget:
    """One row of issue 23's table: the case, the target, what this run measured, met
    (None: not measured in this run)."""

    case: str
    target: str
    measured: str
    met: bool | None


def _rows(rows) -> list[dict]:
    return [r if isinstance(r, dict) else asdict(r) for r in rows]


def _route(routes, family: str, route: str, size: int) -> dict | None:
    return next((r for r in routes if (r["family"], r["route"], r["size"]) == (family, route, size)), None)


def _missing(r: dict | None) -> str:
    if r is None:
        return "not run in this plan"
    if r["status"] == "timeout":
        return f"> {r['timeout_s']:.0f} s (timed out)"
    return r["status"]


def _kb(n_bytes: int | None) -> str:
    return "–" if n_bytes is None else f"{n_bytes / 1000:.0f} KB"


def _chain_whole(routes, n: int, seconds: float, json_kb: float | None = None) -> ScaleTarget:
    """Chain of n rods, modes, default route: the whole process within ``seconds`` (and
    its JSON within ``json_kb`` KB)."""
    case = f"chain of {n} rods, `modes`, default route"
    target = f"whole process ≤ {seconds:g} s" + ("" if json_kb is None else f", JSON ≤ {json_kb:g} KB")
    r = _route(routes, "chain_rods", DEFAULT, n)
    if r is None or r["status"] != "ok":
        return ScaleTarget(case, target, _missing(r), None if r is None else False)
    if r.get("whole_timed_out"):
        return ScaleTarget(case, target, f"whole process timed out; compute {r['compute_s']:.2f} s", False)
    whole, size = r["whole_process_s"], r.get("json_bytes")
    met = whole <= seconds and (json_kb is None or (size is not None and size <= json_kb * 1000))
    return ScaleTarget(case, target, f"{whole:.2f} s whole (compute {r['compute_s']:.2f} s, answered by "
                       f"{r.get('route_ran') or '?'}), JSON {_kb(size)}", met)


def _compute_vs_whole(routes, startup, n: int = 10, factor: float = 1.5) -> ScaleTarget:
    """Whole process against compute (load + build + the solver), with where the rest
    goes: the model section (T and V, in process: the solve's median less compute) and
    the start-up floor (``import sympy`` alone, the same run), which the whole process
    cannot go under whatever the report costs."""
    case, target = f"chain of {n} rods, compute vs whole", f"whole ≤ {factor:g} × compute"
    r = _route(routes, "chain_rods", DEFAULT, n)
    if r is None or r["status"] != "ok":
        return ScaleTarget(case, target, _missing(r), None if r is None else False)
    if r["whole_process_s"] is None:
        return ScaleTarget(case, target, "whole process not measured or timed out", False)
    compute, whole = r["compute_s"], r["whole_process_s"]
    text = f"{compute:.2f} s compute, {whole:.2f} s whole: {whole / compute:.1f}×; model section {r['median_s'] - compute:.2f} s"
    sympy = {row["label"]: row for row in startup}.get("python -c 'import sympy'")
    if sympy is not None:
        text += f"; import sympy alone {sympy['median_s']:.2f} s = {sympy['median_s'] / compute:.1f}× compute"
    return ScaleTarget(case, target, text, whole / compute <= factor)


def _numeric(routes, n: int, seconds: float) -> ScaleTarget:
    """Numeric route, both chains (point masses and rods): compute within ``seconds``;
    met when both are, not measured when either was not run."""
    case, target = f"numeric route, chain of {n}", f"compute ≤ {seconds:g} s (point masses and rods)"
    parts, verdicts = [], []
    for family, label in (("chain_points", "points"), ("chain_rods", "rods")):
        r = _route(routes, family, "numeric", n)
        if r is None or r["status"] != "ok":
            parts.append(f"{label} {_missing(r)}")
            verdicts.append(None if r is None else False)
        else:
            parts.append(f"{label} {r['compute_s']:.3f} s")
            verdicts.append(r["compute_s"] <= seconds)
    met = False if False in verdicts else (None if None in verdicts else True)
    return ScaleTarget(case, target, ", ".join(parts), met)


def _startup(startup, allowance: float = 0.15) -> ScaleTarget:
    case, target = "seed problem 1, whole process", f"≤ import sympy + {allowance:g} s (same run)"
    s = {row["label"]: row for row in startup}
    p1, sympy = s.get("rbdsolve solve p1 --format json"), s.get("python -c 'import sympy'")
    if p1 is None or sympy is None:
        return ScaleTarget(case, target, "not run in this plan", None)
    extra = p1["median_s"] - sympy["median_s"]
    return ScaleTarget(case, target, f"{p1['median_s']:.2f} s vs import sympy {sympy['median_s']:.2f} s: "
                       f"+{extra:.2f} s", extra <= allowance)


def scale_targets(routes, startup) -> list[ScaleTarget]:
    """The rows of issue 23's table, from the measurements (dataclasses or their dicts)."""
    routes, startup = _rows(routes), _rows(startup)
    return [_chain_whole(routes, 12, 1.0), _chain_whole(routes, 16, 2.0, json_kb=200),
            _chain_whole(routes, 32, 10.0), _compute_vs_whole(routes, startup),
            _numeric(routes, 50, 0.1), _numeric(routes, 200, 1.0), _startup(startup)]


# --- growth -----------------------------------------------------------------------------


def slope(points: list[tuple[float, float]]) -> float | None:
    """Least-squares slope of log t on log n over (n, t) points (None under two sizes):
    b = Σ (x − x̄)(y − ȳ) / Σ (x − x̄)², x = ln n, y = ln t."""
    if len({n for n, _ in points}) < 2:
        return None
    xs, ys = [math.log(n) for n, _ in points], [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


@dataclass(frozen=True)
class Series:
    """One curve of the scaling chart: a label, which time it is ("compute" or
    "whole"), its (n, seconds) points that finished, the sizes that timed out (with
    the limit) and the slope over the last SLOPE_POINTS points."""

    label: str
    key: str
    time: str
    points: tuple[tuple[int, float], ...]
    timeouts: tuple[tuple[int, float], ...]

    @property
    def fitted(self) -> tuple[tuple[int, float], ...]:
        return self.points[-SLOPE_POINTS:]

    @property
    def slope(self) -> float | None:
        return slope(list(self.fitted))


# (family, route) of the scaling chart, and the label each is drawn with.
CURVES = {("chain_rods", DEFAULT): "rods, default route (auto)", ("chain_rods", "exact"): "rods, exact",
          ("chain_rods", "numeric"): "rods, numeric", ("chain_points", "exact"): "point masses, exact",
          ("chain_points", "numeric"): "point masses, numeric"}
TIMES = {"compute": "compute_s", "whole": "whole_process_s"}


def series(result: dict) -> list[Series]:
    """Every chain route's compute and whole-process times, and the mechanics baselines
    (point-mass chain; compute = equations + linearize + exact eigenvalues)."""
    out = []
    for (family, route), label in CURVES.items():
        rows = [r for r in result["routes"] if (r["family"], r["route"]) == (family, route)]
        for time, field in TIMES.items():
            points = tuple((r["size"], r[field]) for r in rows if r["status"] == "ok" and r.get(field))
            timeouts = tuple((r["size"], r["timeout_s"]) for r in rows if r["status"] == "timeout")
            if points:
                out.append(Series(label, route, time, points, timeouts))
    for method in ("lagrange", "kane"):
        rows = [b for b in result.get("baselines", []) if b["method"] == method]
        for time, field in TIMES.items():
            points = tuple((b["n"], b[field]) for b in rows if b["status"] == "ok" and b.get(field))
            timeouts = tuple((b["n"], b["timeout_s"]) for b in rows if b["status"] == "timeout")
            if points:
                out.append(Series(f"point masses, mechanics {method}", method, time, points, timeouts))
    return out


def _slope_text(s: Series) -> str:
    if s.slope is None:
        return "slope –"
    return f"slope {s.slope:.1f} (n = {s.fitted[0][0]}–{s.fitted[-1][0]})"


# --- tables and chart -------------------------------------------------------------------


def _s(x) -> str:
    return "–" if x is None else (f"{x:.3f}" if x < 10 else f"{x:.1f}")


def scale_tables(result: dict) -> list[str]:
    """Markdown: issue 23's targets (recomputed from the routes and start-up), the
    default-route chain (answered by, JSON size), and the slope of every curve."""
    lines = ["### Targets of issue 23 (speed at scale)", "", "| case | target | measured (median) | met |",
             "|---|---|---|---|"]
    for t in scale_targets(result["routes"], result["startup"]):
        met = "met" if t.met else ("not met" if t.met is False else "not measured")
        lines.append(f"| {t.case} | {t.target} | {t.measured} | {met} |")
    rows = [r for r in result["routes"] if (r["family"], r["route"]) == ("chain_rods", DEFAULT)]
    if rows:
        lines += ["", "### Rod chains on the default route (auto)", "",
                  "| n | status | answered by | compute s | in-process s | whole process s | JSON |",
                  "|---|---|---|---|---|---|---|"]
        for r in rows:
            status = f"> {r['timeout_s']:.0f} s" if r["status"] == "timeout" else r["status"]
            whole = "timed out" if r.get("whole_timed_out") else _s(r["whole_process_s"])
            lines.append(f"| {r['size']} | {status} | {r.get('route_ran') or '–'} | {_s(r.get('compute_s'))} | "
                         f"{_s(r['median_s'])} | {whole} | {_kb(r.get('json_bytes'))} |")
    lines += ["", f"### Growth with n (slope of log t against log n, least squares over the last "
              f"{SLOPE_POINTS} sizes that finished)", "", "| chain, route | time | sizes | slope | timed out at |",
              "|---|---|---|---|---|"]
    for s in series(result):
        sizes = ", ".join(str(n) for n, _ in s.fitted)
        out = ", ".join(f"n = {n} (> {t:.0f} s)" for n, t in s.timeouts) or "–"
        lines.append(f"| {s.label} | {s.time} | {sizes} | {'–' if s.slope is None else f'{s.slope:.2f}'} | {out} |")
    return lines + [""]


STYLE = {"auto": ("tab:green", "D"), "exact": ("tab:blue", "o"), "numeric": ("tab:orange", "s"),
         "lagrange": ("tab:red", "^"), "kane": ("tab:purple", "v")}


def chart_scaling(result: dict, out) -> None:
    """Time against n, log–log, one curve per chain and route (point masses dashed),
    compute on the left and the whole process on the right; each legend entry carries
    the fitted slope; × marks a timeout at its limit."""
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FuncFormatter, NullFormatter

    fig, axes = plt.subplots(1, 2, figsize=(16, 6.5), sharey=True)
    titles = {"compute": "compute: load + build + solver (in-process median)",
              "whole": "whole process: rbdsolve solve FILE --format json (median)"}
    for ax, time in zip(axes, TIMES):
        for s in (s for s in series(result) if s.time == time):
            color, marker = STYLE[s.key]
            dashed = "--" if s.label.startswith("point masses") else "-"
            xs, ys = zip(*s.points)
            ax.plot(xs, ys, marker=marker, color=color, ls=dashed, mfc="none" if dashed == "--" else color,
                    label=f"{s.label}: {_slope_text(s)}")
            for n, limit in s.timeouts:
                ax.plot([n], [limit], marker="x", color=color, ms=10, mew=2, ls="none")
        ax.set(xscale="log", yscale="log", title=titles[time], xlabel="n (links of the chain)")
        sizes = sorted({n for s in series(result) for n, _ in s.points + s.timeouts})
        ax.set_xticks(sizes)  # the sizes measured, as plain numbers
        ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _: f"{x:g}"))
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    axes[0].set_ylabel("seconds")
    fig.suptitle("Chains, modes: time against n (log–log; slope = least squares over the last "
                 f"{SLOPE_POINTS} sizes that finished; × = timed out at that limit)", fontsize=11)
    fig.tight_layout()
    save(fig, out / "scaling")


BEGIN = "<!-- issue-23 tables:"
END = "<!-- end of issue-23 tables -->"


def fill_docs(result: dict, path) -> None:
    """Rewrite the block between BEGIN's line and END in ``path`` (docs/performance.md)
    with this result's issue-23 tables, headings one level down; the rest is untouched."""
    text = path.read_text()
    start, end = text.index(BEGIN), text.index(END)
    start = text.index("\n", start) + 1
    tables = [("#" + line) if line.startswith("### ") else line for line in scale_tables(result)]
    block = [f"Plan: {result['plan']}; Python {result['python']}; whole run {result['wall_seconds']:.0f} s "
             "(benchmarks/results/results.json).", "", *tables]
    path.write_text(text[:start] + "\n".join(block) + "\n" + text[end:])
