"""An answer key as one self-contained HTML file: no scripts, no fonts or styles from
the network. Math is MathML (form/mathml.py), which every current browser typesets:
fractions, roots, matrices, dots over time derivatives; a result is boxed by its
style. Pictures are embedded as data URIs. The markup is well-formed XML as well as
HTML (void elements closed, every entity XML's own), so an XML parser checks it."""

from __future__ import annotations

import base64
import html
import re
from pathlib import Path

from rbdsolve.form.mathml import relation_mathml
from rbdsolve.form.printers import prose_pieces
from rbdsolve.render.numbers import accuracy_lines, groups, route_text, tail_text
from rbdsolve.report.key import AnswerKey, KeyEntry, Picture
from rbdsolve.report.steps import ProblemReport, Solution, Step, StepKind, accuracy_steps, answer_steps

PAGE_STYLE = """
body { font-family: Georgia, 'DejaVu Serif', serif; max-width: 52em; margin: 2em auto;
       padding: 0 1em; line-height: 1.45; color: #222; }
h1 { border-bottom: 2px solid #444; padding-bottom: .2em; }
h2 { margin-top: 2.5em; border-bottom: 1px solid #bbb; }
"""
PARTS_STYLE = """
.source { color: #666; font-style: italic; }
.statement { background: #f6f6f0; border-left: 4px solid #c8c2a0; padding: .6em 1em; }
.math { margin: .4em 0 .4em 2em; padding: .15em 0; overflow-x: auto; overflow-y: hidden; }
math { font-family: 'STIX Two Math', 'Cambria Math', 'Latin Modern Math', math; font-size: 1.1em; }
.result { border: 1.5px solid #2a6f2a; padding: .2em .6em; display: inline-block;
          margin-left: 2em; }
.note { font-style: italic; color: #444; }
.route { color: #777; font-size: .9em; }
.warning { color: #8a5a00; }
.error { color: #a00000; }
figure { text-align: center; margin: 1em 0; }
figure img { max-width: 100%; max-height: 28em; }
figcaption { font-size: .9em; color: #555; }
"""
STYLE = PAGE_STYLE + PARTS_STYLE
FRAGMENT = "rbdsolve"  # the class of a fragment's outer div: its style applies inside it only


def _scoped(css: str) -> str:
    """Each rule's selectors prefixed with the fragment's class, so that a fragment
    shown inside another page (a notebook) styles nothing of that page."""
    return re.sub(r"(^|})\s*([^{}]+?)\s*{",
                  lambda m: m.group(1) + "\n" + ", ".join(f".{FRAGMENT} {s.strip()}" for s in m.group(2).split(",")) + " {",
                  css)


def render_report(report: ProblemReport) -> str:
    """One report as an HTML fragment (a div with its own scoped style): what a notebook
    shows for a solved problem (the Python API's ``_repr_html_``)."""
    return _fragment(_report(report, ()))


def render_solution(number: int, solution: Solution) -> str:
    """One question's solution as an HTML fragment."""
    return _fragment(_solution(number, solution))


def _fragment(lines: list[str]) -> str:
    return "\n".join([f'<div class="{FRAGMENT}"><style>{_scoped(PARTS_STYLE)}</style>', *lines, "</div>"]) + "\n"


def render_key(key: AnswerKey, folder: Path) -> str:
    """The whole key; picture paths are read relative to ``folder`` and embedded."""
    parts = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8"/>',
             f"<title>{_e(key.title)}</title>", f"<style>{STYLE}</style></head><body>",
             f"<h1>{_e(key.title)}</h1>"]
    for entry in key.entries:
        parts += _entry(entry, folder)
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"


def _entry(entry: KeyEntry, folder: Path) -> list[str]:
    if entry.report is None:
        return [f"<h2>{_e(entry.source)}</h2>", f'<p class="error">Not solved: {_e(entry.failure or "")}</p>']
    return _report(entry.report, tuple(_figure(p, folder) for p in entry.pictures))


def _report(report: ProblemReport, figures: tuple[str, ...]) -> list[str]:
    out = [f"<section><h2>{_e(report.title)}</h2>"]
    if report.source:
        out.append(f'<p class="source">{_e(report.source)}</p>')
    if report.statement:
        out.append(f'<p class="statement">{_e(report.statement)}</p>')
    out += figures
    if report.values:
        out.append("<p>Parameter values: " + ", ".join(_e(report.value_text(k)) for k in report.values) + "</p>")
    if report.model.steps:
        out.append("<h3>Model</h3>")
        out += [line for step in report.model.steps for line in _step(step)]
    for number, solution in enumerate(report.solutions, start=1):
        out += _solution(number, solution)
    return out + ["</section>"]


def _solution(number: int, s: Solution) -> list[str]:
    out = [f'<h3>Question {number}: {_e(s.question)} <span class="route">({_e(route_text(s))})</span></h3>']
    out += [line for step in answer_steps(s.steps) for line in _step(step)]
    out += [f'<p class="warning"><b>Warning:</b> {_prose(w)}</p>' for w in s.warnings]
    if s.error:
        out.append(f'<p class="error"><b>Could not answer:</b> {_e(s.error)}</p>')
    out += _numbers(s)
    accuracy = accuracy_lines(s)
    steps = accuracy_steps(s.steps)
    if steps or accuracy:  # how accurate the numeric route is: small, under the answers
        out += ['<div class="accuracy"><small><p>Accuracy:</p>', *[x for step in steps for x in _step(step)]]
        out += (["<ul>"] + [f"<li><code>{_e(n)}</code></li>" for n in accuracy] + ["</ul>"] if accuracy else [])
        out.append("</small></div>")
    return out


def _numbers(s: Solution) -> list[str]:
    """The numeric block, each value under the name the solution prints, by heading."""
    blocks = groups(s.numbers)
    if not blocks:
        return []
    out = ["<p>Numeric values:</p>"]
    for heading, numbers in blocks:
        out += [f"<p>{_e(heading)}:</p>"] if heading else []
        out += ["<ul>"] + [f"<li>{relation_mathml(n.relation)}{_e(tail_text(n))}</li>" for n in numbers] + ["</ul>"]
    return out


def _step(step: Step) -> list[str]:
    out = []
    if step.text:
        out.append(f'<p class="note">{_prose(step.text)}</p>' if step.kind is StepKind.NOTE
                   else f"<p>{_prose(step.text)}</p>")
    for rel in step.math:
        math = relation_mathml(rel)
        out.append(f'<div class="math"><span class="result">{math}</span></div>' if step.kind is StepKind.RESULT
                   else f'<div class="math">{math}</div>')
    return out


def _figure(picture: Picture, folder: Path) -> str:
    path = folder / picture.path
    kind = "svg+xml" if path.suffix == ".svg" else "png"
    data = base64.b64encode(path.read_bytes()).decode("ascii")
    return (f'<figure><img src="data:image/{kind};base64,{data}" alt="{_e(picture.caption)}"/>'
            f"<figcaption>{_e(picture.caption)}</figcaption></figure>")


def _prose(value: str) -> str:
    """A step's text, escaped, its subscripted names (v_C) set as subscripts."""
    return "".join(_e(before) + (f"<i>{_e(base)}</i><sub>{_e(sub)}</sub>" if base else "")
                   for before, base, sub in prose_pieces(value))


def _e(value: str) -> str:
    return html.escape(value, quote=True)
