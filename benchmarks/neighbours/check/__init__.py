"""Judging one scene: rbdsolve's JSON for it, question by question, against the oracle.

Each question ends as one of: ``answered`` (every number checked agrees), ``mismatch``
(one does not: the message says which, where and by how much), ``refused`` (rbdsolve
said it cannot answer: exit 2 for the file or an unanswered question, with the
reason's category), ``crashed`` (exit 3, a traceback, or no answer at all), or
``oracle`` (the oracle itself failed: a bug of this benchmark, counted apart)."""

from __future__ import annotations

import re
import traceback
from dataclasses import dataclass, field

from benchmarks.neighbours.check import (energy, eom, equilibria, impact, inertia, kinematics, modes, reactions, spin,
                                         steady)
from benchmarks.neighbours.check.context import Mismatch, Partial, context
from benchmarks.neighbours.scene import Scene

CHECKS = {"eom": eom.check, "equilibria": equilibria.check, "modes": modes.check, "energy": energy.check,
          "inertia": inertia.check, "kinematics": kinematics.check, "reactions": reactions.check,
          "impact": impact.check, "steady_spin": spin.check, "steady_motion": steady.check}


@dataclass
class QuestionOutcome:
    kind: str
    status: str          # answered, mismatch, refused, crashed, oracle, unchecked
    reason: str = ""     # a refusal's category, or the mismatch / crash message
    detail: str = ""
    seconds: float | None = None
    route: str | None = None
    notes: list[str] = field(default_factory=list)


@dataclass
class SceneOutcome:
    name: str
    family: str
    variant: str
    features: tuple[str, ...]
    questions: list[QuestionOutcome]
    exit_code: int | None
    text: str
    points: list[dict] = field(default_factory=list)
    future: str | None = None
    oracle_values: list = field(default_factory=list)  # what the oracle expects, for a failing scene

    @property
    def status(self) -> str:
        order = ["crashed", "mismatch", "oracle", "refused", "unchecked", "answered"]
        got = [q.status for q in self.questions] or ["crashed"]
        return min(got, key=order.index)


def category(message: str) -> str:
    """The reason of a refusal, with names and numbers taken out, so that refusals for
    one missing capability count together."""
    m = message or ""
    m = re.sub(r"^could not answer: ", "", m)
    m = re.sub(r"^\S+\.ya?ml:\d+:\d+: ", "", m)
    m = re.sub(r"^\S+\.ya?ml: ", "", m)
    rules = [
        (r"unknown key '(forces|couples|torques)'", r"format: no '\1:' (applied forces and couples)"),
        (r"unknown key '(\w+)' in (\w+)", r"format: unknown key '\1' in \2"),
        (r"unknown key '(\w+)'", r"format: unknown key '\1'"),
        (r"ran out of its [\d.]+ s budget|ran out of its share", "out of the time budget"),
        (r"not an equilibrium", "about: not an equilibrium"),
        (r"no stable equilibrium", "no stable equilibrium found"),
        (r"depends (explicitly )?on time", "the scene depends on time t"),
        (r"gyroscopic", "gyroscopic coupling (modes in a turning frame)"),
        (r"no compact closed form", "no closed form without values"),
        (r"mass matrix is singular", "singular mass matrix"),
        (r"may miss", "may miss solutions"),
        (r"= 0 along the motion has no closed-form solution", "contact loss: no closed form of where N = 0 (transcendental)"),
        (r"transcendental.*Other equilibria may exist", "equilibria: the evident roots only (transcendental equations)"),
        (r"give either 'shape' or 'inertia'|explicit inertia takes no dimensions",
         "format: a rolling body must be a shape (no given inertia)"),
        (r"give it one shape, not parts", "format: a rolling body must be one shape (no parts)"),
        (r"still depends on t", "a body turns in the frame: no relative equilibria (solid body in a turning frame)"),
        (r"unknown point", "format: unknown point (no points of a body placed by a contact)"),
        (r"needs a 'shape'", "format: a body needs a shape here"),
        (r"sticks' is for a particle", "format: only a particle sticks"),
    ]
    for pattern, name in rules:
        found = re.search(pattern, m)
        if found:
            return found.expand(name)
    m = re.sub(r"^[\w.\[\]]+: ", "", m)            # the key path
    m = re.sub(r"'[^']*'", "'…'", m)
    m = re.sub(r"-?\d+(\.\d+)?(e-?\d+)?", "#", m)
    m = m.split(";")[0].split(" (")[0]
    return m[:80]


def judge(scene: Scene, obj: dict) -> SceneOutcome:
    """Every question of ``scene`` against rbdsolve's JSON object ``obj`` for it."""
    outcome = SceneOutcome(scene.name, scene.family, scene.variant, scene.features, [], obj.get("exit_code"),
                           scene.text, future=scene.future)
    kinds = [q.kind for q in scene.questions]
    if not obj:
        outcome.questions = [QuestionOutcome(k, "crashed", "no output (the process died or timed out)") for k in kinds]
        return outcome
    if "results" not in obj:
        err = obj.get("error") or {}
        code = obj.get("exit_code")
        status = "crashed" if code == 3 else "refused"
        reason = err.get("message", "") if status == "crashed" else category(err.get("message", ""))
        outcome.questions = [QuestionOutcome(k, status, reason, err.get("message", "")) for k in kinds]
        return outcome
    try:
        ctx = context(scene, obj)
        outcome.points = [{k: float(v) for k, v in p.items()} for p in ctx.points]
    except Exception as exc:  # noqa: BLE001 - the oracle's own failure, counted apart
        outcome.questions = [QuestionOutcome(k, "oracle", f"context: {exc!r}") for k in kinds]
        return outcome
    for question, result in zip(scene.questions, obj["results"]):
        outcome.questions.append(_question(ctx, question, result))
    if outcome.status in ("mismatch", "crashed"):
        outcome.oracle_values = [_expected(ctx, q) for q in scene.questions]
    return outcome


def _expected(ctx, question) -> dict:
    from benchmarks.neighbours.check.expected import expected
    try:
        return {"question": question.kind, **expected(ctx, question)}
    except Exception as exc:  # noqa: BLE001 - a record, not a verdict
        return {"question": question.kind, "error": f"{type(exc).__name__}: {exc}"}


def _question(ctx, question, result: dict) -> QuestionOutcome:
    out = QuestionOutcome(question.kind, "answered", seconds=result.get("seconds"), route=result.get("route"))
    if not result.get("ok"):
        out.status, out.detail = "refused", result.get("error") or ""
        out.reason = category(out.detail)
        return out
    check = CHECKS.get(question.kind)
    if check is None:
        out.status = "unchecked"
        return out
    kept = len(ctx.points)
    try:
        notes = check(ctx, question, result)
        out.notes = list(notes or [])
    except Mismatch as exc:
        out.status, out.reason = "mismatch", str(exc)
    except Partial as exc:
        out.status, out.reason, out.detail = "refused", category(exc.reason), str(exc)
    except Exception as exc:  # noqa: BLE001 - the oracle's own failure, counted apart
        out.status, out.reason = "oracle", f"{type(exc).__name__}: {exc}"
        out.detail = traceback.format_exc(limit=6)
    finally:  # the points a check added on both sides of a critical value are its own
        del ctx.points[kept:]
        for key in [k for k in ctx._systems if k[0] >= kept]:
            del ctx._systems[key]
    return out
