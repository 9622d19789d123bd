"""A VariantTable as CSV, strict JSON, or a LaTeX sheet (one page per student, then the
teacher's answers). Numbers are written with NUMBER_FORMAT; an empty cell is empty in
CSV and null in JSON (the warnings say why)."""

from __future__ import annotations

import math

from rbdsolve.render import spreadsheet
from rbdsolve.form.printers import latex_name
from rbdsolve.render.numbers import unit_text
from rbdsolve.render.json_text import strict_json
from rbdsolve.render.latex import PREAMBLE, text
from rbdsolve.report.variants import VariantTable
from rbdsolve.problem.quantities.quantity import Value

NUMBER_FORMAT = "{:.10g}"  # ten significant digits: exact to well past what an exam marks


ASKED = {  # a question kind as a student sheet asks it
    "eom": "Lagrange's equations of motion.",
    "equilibria": "All equilibria and their stability.",
    "modes": "The small oscillations: eigenvalues, frequencies and mode shapes.",
    "inertia": "The inertia tensor, principal moments and principal axes.",
    "impact": "The velocities and impulses just after the impact.",
    "steady_spin": "The steady spins of the free body and their stability.",
    "steady_motion": "The steady motion: the relations it needs.",
}


def _number(value: float | None) -> str:
    return "" if value is None else NUMBER_FORMAT.format(value)


def _parameter(value: Value) -> str:
    return NUMBER_FORMAT.format(float(value))


def _kinds(table: VariantTable) -> tuple[tuple[str | None, ...], ...]:
    """Each variant's kinds (a stability, a motion), or none per variant without kinds."""
    return table.kinds or tuple(() for _ in table.draws)


def render_csv(table: VariantTable) -> str:
    """Header: variant, seed, the ranged parameters, the answer labels; one row per variant."""
    header = ["variant", "seed", *table.parameters, *table.columns, *table.kind_columns]
    return spreadsheet.table([header, *([n, table.seed, *map(_parameter, draw), *map(_number, answers),
                                         *(k or "" for k in kinds)]
                                        for n, (draw, answers, kinds) in enumerate(zip(table.draws, table.answers,
                                                                                       _kinds(table)), start=1))])


def render_json(table: VariantTable) -> str:
    """One object: the problem, seed, fixed values, columns and rows (strict JSON)."""
    body = {
        "file": table.file,
        "title": table.title,
        "seed": table.seed,
        "fixed": {name: float(value) for name, value in table.fixed},
        "parameters": list(table.parameters),
        "columns": list(table.columns),
        "kind_columns": list(table.kind_columns),
        "rows": [{"variant": n, "values": [float(v) for v in draw], "answers": list(answers), "kinds": list(kinds)}
                 for n, (draw, answers, kinds) in enumerate(zip(table.draws, table.answers, _kinds(table)),
                                                            start=1)],
        "verified": list(table.verified),
        "notes": list(table.notes),
        "warnings": list(table.warnings),
    }
    return strict_json(body, indent=1)


def render_latex(table: VariantTable) -> str:
    """One page per variant (title, statement, that student's values, the questions),
    then the teacher's answers, variant by variant. Compiles with pdflatex."""
    lines = [PREAMBLE, "\\usepackage{longtable}", "\\begin{document}"]
    for n, draw in enumerate(table.draws, start=1):
        lines += _student_page(table, n, draw)
    lines += _answers(table)
    lines.append("\\end{document}")
    return "\n".join(lines) + "\n"


def _values_line(table: VariantTable, draw: tuple[Value, ...]) -> str:
    """m = 3 kg, β = 20°: each value with its unit, an angle the file wrote in degrees in
    degrees (its value in radians is what the answers use)."""
    given = [*zip(table.parameters, draw), *table.fixed]
    units = dict(table.units)
    return ", ".join(f"${_given(name, value, units.get(name), name in table.angles)}" for name, value in given)


def _given(name: str, value: Value, unit: str | None, angle: bool) -> str:
    if angle:
        return f"{latex_name(name)} = {NUMBER_FORMAT.format(math.degrees(float(value)))}^\\circ$"
    return f"{latex_name(name)} = {_parameter(value)}$" + text(unit_text(unit))


def _student_page(table: VariantTable, n: int, draw: tuple[Value, ...]) -> list[str]:
    lines = [f"\\section*{{{text(table.title)} \\hfill Variant {n}}}"]
    if table.statement:
        lines += [text(table.statement), ""]
    lines += [f"\\textbf{{Your values:}} {_values_line(table, draw)}.", "", "\\textbf{Questions:}",
              "\\begin{enumerate}"]
    lines += [f"\\item {text(ASKED.get(q.split('(')[0], q))}" for q in table.questions]
    return lines + ["\\end{enumerate}", "\\newpage"]


def _answers(table: VariantTable) -> list[str]:
    lines = [f"\\section*{{Answers: {text(table.title)}}}",
             f"Seed {table.seed}; every number to ten significant digits; an empty cell has no real "
             f"value for that variant. Checked by a full solve: variants "
             f"{', '.join(map(str, table.verified)) or 'none'}.", ""]
    lines += [f"\\emph{{{text(note)}}}\\par" for note in table.notes]
    lines += [f"\\textbf{{Warning:}} {text(w)}\\par" for w in table.warnings]
    for n, (draw, answers, kinds) in enumerate(zip(table.draws, table.answers, _kinds(table)), start=1):
        lines += [f"\\subsection*{{Variant {n}}}", _values_line(table, draw) + "\\par",
                  "{\\footnotesize\\begin{longtable}{ll}"]
        lines += [f"\\texttt{{{text(c)}}} & {_number(a) or '---'} \\\\" for c, a in zip(table.columns, answers)]
        lines += [f"\\texttt{{{text(c)}}} & {text(k or '---')} \\\\" for c, k in zip(table.kind_columns, kinds)]
        lines.append("\\end{longtable}}")
    return lines


RENDERERS = {"csv": render_csv, "json": render_json, "tex": render_latex}
