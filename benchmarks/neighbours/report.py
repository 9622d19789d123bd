"""The report of a run: a table per feature and per question kind (answered, refused
by reason, crashed, mismatched, the oracle's own failures; median and slowest seconds
of rbdsolve's answer), the failing scenes saved to run again, and the last line
``neighbours: N scenes, M mismatches, C crashes, R refused (…)``."""

from __future__ import annotations

import json
import statistics
from collections import Counter, defaultdict
from pathlib import Path

from benchmarks.neighbours.check import SceneOutcome

STATUSES = ("answered", "mismatch", "crashed", "refused", "oracle", "unchecked")


def _row(outcomes: list) -> dict:
    c = Counter(o.status for o in outcomes)
    secs = [o.seconds for o in outcomes if getattr(o, "seconds", None) is not None]
    return {**{s: c.get(s, 0) for s in STATUSES},
            "median": statistics.median(secs) if secs else None, "slowest": max(secs) if secs else None}


def tables(outcomes: list[SceneOutcome]) -> dict:
    """Counts per question kind, per feature (a question counts for each feature of its
    scene), per family, and the refusals by reason."""
    by_kind, by_feature, by_family = defaultdict(list), defaultdict(list), defaultdict(list)
    reasons: Counter = Counter()
    for s in outcomes:
        for q in s.questions:
            by_kind[q.kind].append(q)
            by_family[s.family].append(q)
            for f in s.features:
                by_feature[f].append(q)
            if q.status == "refused":
                reasons[q.reason] += 1
    return {"kinds": {k: _row(v) for k, v in sorted(by_kind.items())},
            "features": {k: _row(v) for k, v in sorted(by_feature.items())},
            "families": {k: _row(v) for k, v in sorted(by_family.items())},
            "refusals": dict(reasons.most_common())}


def summary_line(outcomes: list[SceneOutcome]) -> str:
    """The last line: scenes by their worst question (a crash before a mismatch before a
    refusal), the refusals by the reason of each refused scene's first refusal."""
    c = Counter(s.status for s in outcomes)
    reasons: Counter = Counter()
    for s in outcomes:
        if s.status == "refused":
            reasons[next(q.reason for q in s.questions if q.status == "refused")] += 1
    why = "; ".join(f"{n} {r}" for r, n in reasons.most_common())
    return (f"neighbours: {len(outcomes)} scenes, {c.get('mismatch', 0)} mismatches, {c.get('crashed', 0)} crashes, "
            f"{c.get('refused', 0)} refused ({why or 'none'})")


def markdown(outcomes: list[SceneOutcome], seed: int, seconds: float) -> str:
    t = tables(outcomes)
    lines = [f"# Neighbours: {len(outcomes)} scenes, seed {seed}", "",
             f"Wall time {seconds:.0f} s. Scenes by their worst question: " +
             ", ".join(f"{k} {v}" for k, v in Counter(s.status for s in outcomes).most_common()) + ".", ""]
    for title, key in (("Question kinds", "kinds"), ("Features", "features"), ("Families", "families")):
        lines += [f"## {title}", "", "| | answered | mismatch | crashed | refused | oracle | unchecked | median s | slowest s |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for name, r in t[key].items():
            med = f"{r['median']:.2f}" if r["median"] is not None else "–"
            slow = f"{r['slowest']:.2f}" if r["slowest"] is not None else "–"
            lines.append(f"| {name} | {r['answered']} | {r['mismatch']} | {r['crashed']} | {r['refused']} | "
                         f"{r['oracle']} | {r['unchecked']} | {med} | {slow} |")
        lines.append("")
    lines += ["## Refusals by reason (questions)", "", "| reason | questions |", "|---|---|"]
    lines += [f"| {r} | {n} |" for r, n in t["refusals"].items()] + [""]
    bad = [s for s in outcomes if s.status in ("mismatch", "crashed", "oracle")]
    if bad:
        lines += ["## Failures", ""]
        for s in bad:
            for q in s.questions:
                if q.status in ("mismatch", "crashed", "oracle"):
                    lines.append(f"- `{s.name}` {q.kind}: **{q.status}** — {q.reason[:400]}")
        lines.append("")
    return "\n".join(lines)


def save_failures(outcomes: list[SceneOutcome], folder: Path) -> list[Path]:
    """Each scene with a mismatch, a crash or an oracle failure: its file, ready to run,
    and beside it NAME.oracle.json with what the oracle found (the parameter values it
    judged at, each question's verdict and message)."""
    folder.mkdir(parents=True, exist_ok=True)
    saved = []
    for s in outcomes:
        if s.status not in ("mismatch", "crashed", "oracle"):
            continue
        path = folder / f"{s.name}.yaml"
        path.write_text(s.text)
        record = {"scene": s.name, "family": s.family, "variant": s.variant, "features": list(s.features),
                  "exit_code": s.exit_code, "parameter_points": s.points,
                  "questions": [{"kind": q.kind, "status": q.status, "route": q.route, "message": q.reason,
                                 "notes": q.notes} for q in s.questions],
                  "oracle": s.oracle_values}
        (folder / f"{s.name}.oracle.json").write_text(json.dumps(record, indent=1, default=str) + "\n")
        saved.append(path)
    return saved
