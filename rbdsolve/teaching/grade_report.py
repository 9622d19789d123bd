"""A grading run as data: the JSON of ``rbdsolve grade`` (docs/json.md) and the class's
CSV, one row per student. The terminal's tables are cli/grade.py's (rich lives there)."""

from __future__ import annotations

from rbdsolve.render import spreadsheet
from rbdsolve.render.json_text import strict_json
from rbdsolve.teaching.check import CheckRun, Checked
from rbdsolve.teaching.grading import ClassGrades, Outcome, score_counts, tallies
from rbdsolve.teaching.verdicts import Different, EqualFor, Equivalent, Factor, Undecided, describe, slips_of

SCHEMA_VERSION = 1


def check_object(run: CheckRun, show: bool) -> dict:
    """A student's check: each answer's verdict; rbdsolve's answer only with ``show``."""
    return {
        "schema": SCHEMA_VERSION,
        "kind": "check",
        "file": run.file,
        "ok": not run.errors and all(c.right for c in run.checked),
        "answers": [_checked(c, show) for c in run.checked],
        "errors": [str(e) for e in run.errors],
    }


def _checked(c: Checked, show: bool) -> dict:
    v = c.verdict
    out = {"answer": c.address, "given": c.given, "right": c.right, "verdict": v.name,
           "text": describe(v, show), "slips": [s.value for s in slips_of(v)]}
    if isinstance(v, Equivalent):
        out["how"] = v.how.value
    if isinstance(v, Factor) and (show or v.slips):
        out["factor"] = str(v.factor)
    if isinstance(v, EqualFor):
        out["condition"] = v.condition
    if isinstance(v, Different):
        out["point"] = dict(v.point)
        out["yours"] = v.yours
        if show:
            out["expected_there"] = v.expected
    if isinstance(v, Undecided):
        out["reason"] = v.reason
    if show:
        out["expected"] = c.answer
    return out


def class_object(grades: ClassGrades) -> dict:
    """A class's grading: the rule, every student's marks, the tally per answer."""
    rule = grades.rule
    return {
        "schema": SCHEMA_VERSION,
        "kind": "class",
        "variants": grades.key.file,
        "problem": grades.key.problem,
        "answers_file": grades.answers_file,
        "ok": not grades.errors and grades.all_right,
        "rule": {"rtol": rule.rtol, "atol": rule.atol, "sig_figs": rule.sig_figs, "slip_credit": rule.slip_credit},
        "answers": list(grades.answers),
        "students": [{"student": s.student, "variant": s.variant, "line": s.line, "score": grades.score(s),
                      "out_of": len(grades.answers),
                      "marks": [{"answer": m.answer, "given": m.given, "key": m.key, "outcome": m.outcome.value,
                                 "slips": [x.value for x in m.slips]} for m in s.marks]}
                     for s in grades.students],
        "summary": [{"answer": t.answer, **{o.value: n for o, n in t.counts.items()}, "slips": t.slips}
                    for t in tallies(grades)],
        "scores": [{"score": score, "students": n} for score, n in score_counts(grades)],
        "errors": [str(e) for e in grades.errors],
    }


def dumps(body: dict) -> str:
    return strict_json(body)


def class_csv(grades: ClassGrades) -> str:
    """student, variant, score, out_of, then per answer its outcome: right, wrong,
    blank, ungraded, or the slips (sign, two_pi, sign+two_pi, …); every cell as a
    spreadsheet shows text (render/spreadsheet.py: no formula, no control character)."""
    rows = [["student", "variant", "score", "out_of", *grades.answers]]
    for s in grades.students:
        words = {m.answer: m.word for m in s.marks}
        rows.append([s.student, s.variant, f"{grades.score(s):g}", len(grades.answers),
                     *(words.get(a, Outcome.UNGRADED.value) for a in grades.answers)])
    return spreadsheet.table(rows)
