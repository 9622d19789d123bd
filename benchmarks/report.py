"""From a benchmark result: the targets of issue 7 (met or missed, by how much) and of
issue 23 (benchmarks.scale), the Markdown tables and the charts (matplotlib, Agg; PNG
and SVG). The targets are recomputed from the measurements in results.json.

    python3 -m benchmarks.report benchmarks/results   # redraw from results.json
"""

from __future__ import annotations

import argparse
import json
from dataclasses import asdict, dataclass
from pathlib import Path

from benchmarks.figures import save
from benchmarks.scale import chart_scaling, fill_docs, scale_tables

CLIP = 1e-17  # errors below this (the exact route's ~1e-30) are drawn at the clip
ROUTE_STYLE = {"exact": ("tab:blue", "o"), "numeric": ("tab:orange", "s"), "auto": ("tab:green", "D"),
               "lagrange": ("tab:red", "^"), "kane": ("tab:purple", "v")}


@dataclass(frozen=True)
class Target:
    """One target of issue 7: what was asked, what was measured, met or not."""

    name: str
    asked: str
    measured: str
    met: bool | None  # None: could not be measured in this run


def _find(rows, **keys):
    for row in rows:
        row = row if isinstance(row, dict) else asdict(row)
        if all(row.get(k) == v for k, v in keys.items()):
            return row
    return None


def targets(routes, baselines, startup) -> list[Target]:
    """The four targets, from the measurements (dataclasses or their dicts)."""
    return [_exact_target(routes), _ratio_target(routes, baselines), _numeric_target(routes),
            *_startup_targets(startup)]


def _compute(r) -> float:
    """Load + build + solver (older results without it: the whole in-process solve)."""
    return r.get("compute_s") or r["median_s"]


def _exact_target(routes) -> Target:
    r = _find(routes, family="chain_points", size=10, route="exact")
    if r is None or r["status"] != "ok":
        return Target("chain exact n=10", "< 1 s of compute",
                      f"not answered in this run ({r['status'] if r else 'not run'})", False if r else None)
    return Target("chain exact n=10", "< 1 s of compute",
                  f"{_compute(r):.2f} s compute (load + build + modes solver, {r['solution_s']:.2f} s of it in "
                  f"the solver); {r['median_s']:.2f} s with the report's T and V", _compute(r) < 1.0)


def _ratio_target(routes, baselines) -> Target:
    r = _find(routes, family="chain_points", size=10, route="exact")
    b = _find(baselines, method="lagrange", n=10)
    name, asked = "chain exact vs Lagrange n=10", "≥ 50× faster than LagrangesMethod + linearize at n=10"
    if b is None:
        return Target(name, asked, "baseline not run", None)
    if r is None or r["status"] != "ok":
        return Target(name, asked, "rbdsolve exact not answered", False if r else None)
    ours, whole = _compute(r), r["median_s"]
    if b["status"] == "timeout":
        return Target(name, asked, f"Lagrange > {b['timeout_s']:.0f} s (timed out); rbdsolve {ours:.2f} s: "
                      f"ratio > {b['timeout_s'] / ours:.0f}×", b["timeout_s"] / ours >= 50 or None)
    ratio = b["compute_s"] / ours
    return Target(name, asked, f"Lagrange {b['compute_s']:.1f} s compute (equations + linearize + eigenvalues), "
                  f"rbdsolve {ours:.2f} s compute: {ratio:.0f}× ({b['compute_s'] / whole:.0f}× counting the "
                  f"report's T and V, {whole:.2f} s)", ratio >= 50)


def _numeric_target(routes) -> Target:
    asked = "n=50 in < 0.1 s of compute, relative error ≤ 1e-12"
    r = _find(routes, family="chain_points", size=50, route="numeric")
    if r is None or r["status"] != "ok":
        return Target("chain numeric n=50", asked, f"not answered ({r['status'] if r else 'not run'})",
                      False if r else None)
    return Target("chain numeric n=50", asked,
                  f"{_compute(r):.3f} s compute (load + build + solver, {r['solution_s']:.3f} s in the solver), "
                  f"{r['median_s']:.3f} s in-process in all; relative error {r['relative_error']:.1e}",
                  _compute(r) < 0.1 and r["relative_error"] <= 1e-12)


def _startup_targets(startup) -> list[Target]:
    s = {row["label"] if isinstance(row, dict) else row.label: (row if isinstance(row, dict) else asdict(row))
         for row in startup}
    if not s:
        return []
    p1, script, imp = (s["rbdsolve solve p1 --format json"]["median_s"], s["mechanics script for p1"]["median_s"],
                       s["python -c 'import sympy'"]["median_s"])
    out = [Target("p1 whole process vs mechanics script", "≤ 0.6× the script",
                  f"{p1:.2f} s vs {script:.2f} s: {p1 / script:.2f}×", p1 <= 0.6 * script),
           Target("p1 whole process vs import sympy", "within 0.4 s of `python -c 'import sympy'`",
                  f"{p1:.2f} s vs {imp:.2f} s: +{p1 - imp:.2f} s", p1 - imp <= 0.4)]
    for label in ("rbdsolve --help", "rbdsolve check sg2150-2015-10-29/"):
        heavy = s[label]["heavy_modules"]
        out.append(Target(label, "does not import sympy's heavy parts",
                          f"{s[label]['median_s']:.2f} s; imports {', '.join(heavy) or 'none of ' + 'sympy/numpy/scipy'}",
                          "sympy" not in heavy))
    return out


# --- tables -----------------------------------------------------------------------------


def _s(x) -> str:
    return "–" if x is None else (f"{x:.3f}" if x < 10 else f"{x:.1f}")


def _e(x) -> str:
    return "–" if x is None else f"{x:.1e}"


def write_tables(result: dict, path: Path) -> None:
    """Markdown: one table per family (sizes × routes), the baselines, start-up, targets."""
    lines = [f"Plan: {result['plan']}; Python {result['python']}; whole run {result['wall_seconds']:.0f} s. "
             "Seconds are medians of the repeats (in-process: load + build + solve; solver: the "
             "question's own seconds; compute: load + build + solver, without the report's T and V; whole: "
             "the `python -m rbdsolve solve` process).", ""]
    families = sorted({r["family"] for r in result["routes"]}, key=[r["family"] for r in result["routes"]].index)
    for family in families:
        lines += [f"### {family}", "", "| n | route | status | in-process s | compute s | solver s | whole process s | "
                  "relative error | error estimate |", "|---|---|---|---|---|---|---|---|---|"]
        for r in (r for r in result["routes"] if r["family"] == family):
            status = f"> {r['timeout_s']:.0f} s" if r["status"] == "timeout" else r["status"]
            lines.append(f"| {r['size']} | {r['route']} | {status} | {_s(r['median_s'])} | {_s(r.get('compute_s'))} | "
                         f"{_s(r['solution_s'])} | "
                         f"{_s(r['whole_process_s'])} | {_e(r['relative_error'])} | {_e(r['error_estimate'])} |")
        lines.append("")
    if result["baselines"]:
        lines += ["### sympy.physics.mechanics on chain_points (one run per size)", "",
                  "| n | method | status | equations s | linearize s | exact eigenvalues s | compute s | "
                  "whole process s | rel. error exact | numeric eigvals s | rel. error numeric |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for b in result["baselines"]:
            status = f"> {b['timeout_s']:.0f} s" if b["status"] == "timeout" else b["status"]
            lines.append(f"| {b['n']} | {b['method']} | {status} | {_s(b['equations_s'])} | {_s(b['linearize_s'])} | "
                         f"{_s(b['eigen_exact_s'])} | {_s(b['compute_s'])} | {_s(b['whole_process_s'])} | "
                         f"{_e(b['relative_error_exact'])} | {_s(b['eigen_numeric_s'])} | "
                         f"{_e(b['relative_error_numeric'])} |")
        lines.append("")
    lines += ["### Start-up (whole process, median)", "", "| command | s | heavy modules imported |", "|---|---|---|"]
    for s in result["startup"]:
        heavy = "–" if s["heavy_modules"] is None else (", ".join(s["heavy_modules"]) or "none")
        lines.append(f"| `{s['label']}` | {_s(s['median_s'])} | {heavy} |")
    lines += ["", "### Targets", "", "| target | asked | measured | met |", "|---|---|---|---|"]
    for t in (asdict(t) for t in targets(result["routes"], result["baselines"], result["startup"])):
        met = "yes" if t["met"] else ("no" if t["met"] is False else "?")
        lines.append(f"| {t['name']} | {t['asked']} | {t['measured']} | {met} |")
    lines += ["", *scale_tables(result)]
    path.write_text("\n".join(lines) + "\n")


# --- charts -----------------------------------------------------------------------------


def _series(result: dict, family: str, route: str) -> list[dict]:
    return [r for r in result["routes"] if r["family"] == family and r["route"] == route and r["status"] == "ok"]


def _pareto(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The points no other point beats in both time and error, by increasing time."""
    front, best = [], float("inf")
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


def chart_time_error(result: dict, out: Path) -> None:
    """(a) relative error against in-process time, log-log, per route, one labelled point
    per size, the Pareto front (over routes and the mechanics baselines) as a step line."""
    import matplotlib.pyplot as plt

    families = ["chain_points", "chain_rods", "springs"]
    fig, axes = plt.subplots(1, 3, figsize=(16, 5.2), sharey=True)
    for ax, family in zip(axes, families):
        points = []
        for route in ("exact", "numeric"):
            rows = [r for r in _series(result, family, route) if r["relative_error"] is not None]
            xy = [(r["median_s"], max(r["relative_error"], CLIP), r["size"]) for r in rows]
            _scatter(ax, xy, route, ROUTE_STYLE[route])
            points += [(x, y) for x, y, _ in xy]
        if family == "chain_points":
            for method in ("lagrange", "kane"):
                rows = [b for b in result["baselines"] if b["method"] == method and b["status"] == "ok"]
                xy = [(b["compute_s"], max(b["relative_error_exact"], CLIP), b["n"]) for b in rows]
                _scatter(ax, xy, f"mechanics {method} (exact)", ROUTE_STYLE[method])
                points += [(x, y) for x, y, _ in xy]
        front = _pareto(points)
        if front:
            xs, ys = zip(*front)
            ax.step(xs, ys, where="post", color="0.4", lw=1, ls="--", label="Pareto front")
        ax.set(xscale="log", yscale="log", title=family, xlabel="time per solve, in-process median (s)")
        ax.axhline(CLIP, color="0.8", lw=0.8)
        ax.axhline(1e-12, color="tab:green", lw=0.8, ls="-.", label="numeric target 1e-12")
        ax.set_ylim(3e-18, 1e-10)
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=8, loc="best")
    axes[0].set_ylabel("max relative error of the eigenvalues λ")
    fig.suptitle("Speed against accuracy, modes (labels: n). Errors below 1e-17 "
                 "(exact route: ~1e-30) drawn at 1e-17", fontsize=11)
    save(fig, out / "time_vs_error")


def _scatter(ax, xy, label, style) -> None:
    if not xy:
        return
    color, marker = style
    xs, ys, ns = zip(*xy)
    ax.plot(xs, ys, marker=marker, color=color, ls=":", lw=0.8, label=label)
    for x, y, n in xy:
        ax.annotate(str(n), (x, y), textcoords="offset points", xytext=(3, 4), fontsize=7, color=color)


def chart_time_size(result: dict, out: Path) -> None:
    """(b) in-process time against size per route (log y; log x), the mechanics
    baselines' compute time on chain_points, timeouts marked at their limit."""
    import matplotlib.pyplot as plt

    families = ["chain_points", "chain_rods", "springs", "composite", "impact", "spin", "eom_chain"]
    xlabels = {"composite": "parts k", "spin": "digits of the inertia entries"}
    fig, axes = plt.subplots(3, 3, figsize=(16, 13.5))
    for ax in axes.flat[len(families):]:
        ax.set_visible(False)
    for ax, family in zip(axes.flat, families):
        for route in ("exact", "numeric", "auto"):
            rows = _series(result, family, route)
            if rows:
                color, marker = ROUTE_STYLE[route]
                ax.plot([r["size"] for r in rows], [r["median_s"] for r in rows], marker=marker, color=color,
                        label=f"rbdsolve {route}")
            _timeouts(ax, [r for r in result["routes"] if r["family"] == family and r["route"] == route],
                      "size", ROUTE_STYLE[route][0])
        if family == "chain_points":
            for method in ("lagrange", "kane"):
                rows = [b for b in result["baselines"] if b["method"] == method]
                ok = [b for b in rows if b["status"] == "ok"]
                color, marker = ROUTE_STYLE[method]
                if ok:
                    ax.plot([b["n"] for b in ok], [b["compute_s"] for b in ok], marker=marker, color=color,
                            label=f"mechanics {method} + linearize")
                _timeouts(ax, rows, "n", color)
        ax.set(yscale="log", xscale="log", title=family, xlabel=xlabels.get(family, "size n (degrees of freedom)"),
               ylabel="time per solve, in-process median (s)")
        from matplotlib.ticker import ScalarFormatter

        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.grid(True, which="both", alpha=0.3)
        if ax.get_legend_handles_labels()[0]:  # a family this plan did not run has no curve
            ax.legend(fontsize=8)
    fig.suptitle("Time against problem size (× at a time limit: did not finish within it)", fontsize=11)
    fig.tight_layout()
    save(fig, out / "time_vs_size")


def _timeouts(ax, rows, key: str, color: str) -> None:
    for r in rows:
        if r["status"] == "timeout":
            ax.plot([r[key]], [r["timeout_s"]], marker="x", color=color, ms=10, mew=2, ls="none")
            ax.annotate(f"> {r['timeout_s']:.0f} s", (r[key], r["timeout_s"]), textcoords="offset points",
                        xytext=(4, -10), fontsize=7, color=color)


KIND_STYLE = {"mass": ("tab:blue", "o", "one small mass m₃ = r"),
              "stiffness": ("tab:orange", "s", "one stiff spring k₂ = 1/r")}


def chart_conditioning(result: dict, out: Path) -> None:
    """(c) the numeric modes route's actual relative error (against the 50-digit
    reference) and its stated bound against the condition number, log-log: per
    eigenvalue against κ(λ), and per case (its largest error and bound) against κ₂(M)."""
    import matplotlib.pyplot as plt

    rows = result.get("conditioning") or []
    fig, axes = plt.subplots(1, 2, figsize=(14, 5.4), sharey=True)
    for kind, (color, marker, label) in KIND_STYLE.items():
        mine = [r for r in rows if r["kind"] == kind and r["condition"] is not None]
        xs = [r["condition"] for r in mine]
        axes[0].plot(xs, [max(r["actual"], CLIP) for r in mine], marker, color=color, ls="none",
                     label=f"{label}: actual error")
        axes[0].plot(xs, [r["bound"] for r in mine], marker, mfc="none", color=color, ls="none", ms=9,
                     label=f"{label}: stated bound")
        cases = sorted({r["ratio"] for r in mine}, reverse=True)
        per = [[r for r in mine if r["ratio"] == c] for c in cases]
        kM = [p[0]["condition_M"] for p in per]
        axes[1].plot(kM, [max(max(r["actual"] for r in p), CLIP) for p in per], marker, color=color, ls=":",
                     label=f"{label}: largest actual error")
        axes[1].plot(kM, [max(r["bound"] for r in p) for p in per], marker, mfc="none", color=color, ls="--",
                     ms=9, label=f"{label}: largest stated bound")
    kappas = [r["condition"] for r in rows if r["condition"] is not None]
    if kappas:
        line = [min(kappas), max(kappas)]
        axes[0].plot(line, [2.22e-16 * k for k in line], color="0.4", lw=1, ls="--", label="ε κ(λ)")
    for ax, where in zip(axes, ("upper left", "center right")):
        ax.axhline(1e-8, color="tab:green", lw=0.8, ls="-.", label="warning tolerance 1e-8 (relative)")
        ax.axhline(CLIP, color="0.8", lw=0.8)
        ax.set(xscale="log", yscale="log")
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=7, loc=where)
    axes[0].set(xlabel="relative condition number κ(λ) = (‖K‖₂ + |λ| ‖M‖₂) ‖a‖₂²/|λ|, aᵀMa = 1 (dimensionless)",
                ylabel="relative error of λ, |λ̂ − λ|/|λ| (dimensionless)", title="per eigenvalue")
    axes[1].set(xlabel="condition number of the mass matrix κ₂(M) (dimensionless)",
                title="per case (a stiff spring leaves κ₂(M) = 1)")
    fig.suptitle("Numeric modes route, three masses on springs, ratio r = 1 … 1e-12: actual error against the "
                 "50-digit reference and stated bound. Errors below 1e-17 drawn at 1e-17", fontsize=10)
    fig.tight_layout()
    save(fig, out / "conditioning")


def write_charts(result: dict, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    chart_time_error(result, out)
    chart_time_size(result, out)
    chart_scaling(result, out)
    if result.get("conditioning"):
        chart_conditioning(result, out)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description="Redraw the tables and charts from results.json.")
    parser.add_argument("folder", nargs="?", default="benchmarks/results", type=Path)
    parser.add_argument("--docs", type=Path, help="also refill the issue-23 block of this file "
                                                  "(docs/performance.md)")
    args = parser.parse_args(argv)
    data = json.loads((args.folder / "results.json").read_text())
    write_tables(data, args.folder / "tables.md")
    write_charts(data, args.folder)
    if args.docs:
        fill_docs(data, args.docs)


if __name__ == "__main__":
    main()
