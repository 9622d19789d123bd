"""Exam problems next door, judged by an independent oracle (issue 43).

    python3 -m benchmarks.neighbours --count N --seed S [--out DIR] [--jobs J]
           [--families a,b] [--budget SECONDS] [--chunk K] [--report FILE] [--start I]
    python3 -m benchmarks.neighbours --merge DIR DIR … --seed S --report FILE

Generates N scenes (scene i depends on the seed and i only), solves them with the
installed rbdsolve in whole processes (K files per process, J processes at once),
judges every answer with the oracle, writes the report (--report, default
DIR/report.md) and saves every mismatch and crash in DIR/failures/. The last line is
``neighbours: N scenes, M mismatches, C crashes, R refused (…)``."""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

from benchmarks.neighbours.report import markdown, save_failures, summary_line
from benchmarks.neighbours.work import run


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python3 -m benchmarks.neighbours", description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--start", type=int, default=0, help="the first scene's index")
    ap.add_argument("--out", type=Path, default=None)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--chunk", type=int, default=5, help="files per rbdsolve process")
    ap.add_argument("--budget", type=float, default=20.0, help="rbdsolve's --budget (processor seconds)")
    ap.add_argument("--families", default="", help="comma-separated family names (default: all)")
    ap.add_argument("--report", type=Path, default=None)
    ap.add_argument("--merge", type=Path, nargs="+", default=None,
                    help="no run: the report of earlier runs' --out folders together (a large run in pieces, by --start)")
    args = ap.parse_args(argv)
    if args.merge:
        return merge(args.merge, args.seed, args.report or Path("report.md"))
    out = args.out or Path(tempfile.mkdtemp(prefix="neighbours-"))
    families = tuple(f for f in args.families.split(",") if f)
    start = time.perf_counter()
    outcomes = run(args.seed, range(args.start, args.start + args.count), families, args.budget, args.jobs,
                   args.chunk, progress=_progress)
    seconds = time.perf_counter() - start
    report = args.report or out / "report.md"
    report.parent.mkdir(parents=True, exist_ok=True)
    report.write_text(markdown(outcomes, args.seed, seconds))
    (out / "outcomes.json").write_text(json.dumps([_plain(o) for o in outcomes], default=str) + "\n")
    saved = save_failures(outcomes, out / "failures")
    print(f"report: {report}; {len(saved)} failing scenes saved in {out / 'failures'}", file=sys.stderr)
    oracle = sum(1 for o in outcomes if o.status == "oracle")
    if oracle:
        print(f"neighbours: {oracle} scenes where the oracle itself failed (see the report)")
    print(summary_line(outcomes))
    return 0


def merge(folders: list[Path], seed: int, report: Path) -> int:
    """The report and last line of several runs' outcomes.json (their scenes in order)."""
    outcomes = [_outcome(d) for folder in folders for d in json.loads((folder / "outcomes.json").read_text())]
    report.write_text(markdown(outcomes, seed, 0.0).replace("Wall time 0 s. ", f"Merged from {len(folders)} runs. "))
    print(f"report: {report}", file=sys.stderr)
    print(summary_line(outcomes))
    return 0


def _outcome(d: dict):
    from benchmarks.neighbours.check import QuestionOutcome, SceneOutcome
    questions = [QuestionOutcome(**q) for q in d.pop("questions")]
    return SceneOutcome(**{**d, "features": tuple(d["features"]), "questions": questions})


def _plain(o):
    from dataclasses import asdict
    return asdict(o)


def _progress(done: int, total: int) -> None:
    print(f"\r{done}/{total} scenes", end="", file=sys.stderr, flush=True)
    if done == total:
        print(file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
