"""One worker's share of a run: generate its scenes, solve them with rbdsolve in one
process, and judge them; a file that crashed is solved again one question at a time,
so the crash is pinned on its question, and one that the process left without output
(a timeout) is solved again alone."""

from __future__ import annotations

import tempfile
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from benchmarks.neighbours.check import QuestionOutcome, SceneOutcome, judge
from benchmarks.neighbours.families import generate
from benchmarks.neighbours.run import solve

TIMEOUT_PER_FILE = 600.0


def run_chunk(seed: int, indices: list[int], families: tuple[str, ...], budget: float) -> list[SceneOutcome]:
    scenes = [generate(seed, i, families) for i in indices]
    with tempfile.TemporaryDirectory(prefix="neighbours-") as tmp:
        paths = []
        for s in scenes:
            p = Path(tmp) / f"{s.name}.yaml"
            p.write_text(s.text)
            paths.append(p)
        objs, _, _ = solve(paths, budget, TIMEOUT_PER_FILE * len(paths))
        outcomes = []
        for s, p in zip(scenes, paths):
            obj = objs[str(p)]
            if not obj and len(paths) > 1:
                obj = solve([p], budget, TIMEOUT_PER_FILE)[0][str(p)]
            o = judge(s, obj)
            if obj.get("exit_code") == 3 or not obj:
                o.questions = _one_by_one(s, Path(tmp), budget, obj)
                o.oracle_values = _values(s, obj)
            outcomes.append(o)
    return outcomes


def _values(scene, obj) -> list:
    """The oracle's numbers for a scene rbdsolve crashed on (no results to judge)."""
    from benchmarks.neighbours.check import _expected
    from benchmarks.neighbours.check.context import context
    try:
        ctx = context(scene, {"symbols": [p.name for p in scene.params]})
        return [_expected(ctx, q) for q in scene.questions]
    except Exception as exc:  # noqa: BLE001 - a record, not a verdict
        return [{"error": repr(exc)}]


def _one_by_one(scene, tmp: Path, budget: float, obj: dict) -> list[QuestionOutcome]:
    """A crashed file's questions each alone: which one crashes, and how the others fare."""
    head, _, tail = scene.text.partition("\nquestions:\n")
    lines = [ln for ln in tail.splitlines() if ln.startswith("  - ")]
    if len(lines) != len(scene.questions):
        return [QuestionOutcome(q.kind, "crashed", (obj.get("error") or {}).get("message", "no output"))
                for q in scene.questions]
    out = []
    for k, (q, line) in enumerate(zip(scene.questions, lines)):
        p = tmp / f"{scene.name}-q{k}.yaml"
        p.write_text(f"{head}\nquestions:\n{line}\n")
        single = solve([p], budget, TIMEOUT_PER_FILE)[0][str(p)]
        copy = type(scene)(**{**scene.__dict__, "questions": [q], "text": p.read_text()})
        got = judge(copy, single).questions
        out.append(got[0] if got else QuestionOutcome(q.kind, "crashed", "no output"))
    return out


def run(seed: int, indices, families: tuple[str, ...] = (), budget: float = 20.0, jobs: int = 1, chunk: int = 5,
        progress=None) -> list[SceneOutcome]:
    """The outcomes of scenes ``indices`` of ``seed``, in order: ``chunk`` files per rbdsolve
    process, ``jobs`` chunks at once (each generated, solved and judged in its worker)."""
    indices = list(indices)
    chunks = [indices[i:i + chunk] for i in range(0, len(indices), chunk)]
    outcomes: list = []
    if jobs <= 1:
        for c in chunks:
            outcomes += run_chunk(seed, c, families, budget)
            if progress:
                progress(len(outcomes), len(indices))
        return outcomes
    with ProcessPoolExecutor(jobs) as pool:
        futures = [pool.submit(run_chunk, seed, c, families, budget) for c in chunks]
        for f, c in zip(futures, chunks):
            # a hang guard: a chunk's rbdsolve process is itself killed after TIMEOUT_PER_FILE per file
            outcomes += f.result(timeout=4 * TIMEOUT_PER_FILE * len(c) + 600)
            if progress:
                progress(len(outcomes), len(indices))
    return outcomes
