"""A complete LaTeX document (article, amsmath): compiles with pdflatex."""

from __future__ import annotations

import re
import unicodedata

from rbdsolve.form.printers import GREEK, prose_pieces, relation_latex
from rbdsolve.render.numbers import accuracy_lines, groups, tail_text, unit_text, value_latex
from rbdsolve.report.key import AnswerKey, Picture
from rbdsolve.report.steps import ProblemReport, Step, StepKind, accuracy_steps, answer_steps

PREAMBLE = r"""\documentclass[11pt]{article}
\usepackage[utf8]{inputenc}
\usepackage[T1]{fontenc}
\IfFileExists{lmodern.sty}{\usepackage{lmodern}}{}
\usepackage{amsmath,amssymb}
\usepackage{graphicx}
\usepackage[margin=2.5cm]{geometry}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5em}
\allowdisplaybreaks
"""

_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#",
            "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\^{}"}  # fmt: skip
_MATH_CHARS = {
    "½": r"\tfrac12", "·": r"\cdot", "∂": r"\partial", "−": "-", "⇒": r"\Rightarrow",
    "√": r"\surd", "∈": r"\in", "≤": r"\le", "≥": r"\ge", "×": r"\times",
    "²": "^2", "³": "^3", "₀": "_0", "₁": "_1", "₂": "_2", "₃": "_3", "ᵀ": "^T",
    "∫": r"\int", "±": r"\pm", "∓": r"\mp", "≈": r"\approx", "≠": r"\neq", "∝": r"\propto",
    "°": r"^\circ", "→": r"\to", "∞": r"\infty", "⁴": "^4", "⁵": "^5", "⁶": "^6",
}  # fmt: skip
_GREEK_CHARS = {v: "\\" + ("varphi" if k == "phi" else k) for k, v in GREEK.items()
                if k not in ("lamda", "varphi")}


def text(value: str) -> str:
    """Prose with unicode math symbols -> LaTeX text with inline math. A letter followed by
    a combining dot (U+0307) or diaeresis (U+0308) is a time derivative, q̇ or q̈;
    precomposed letters (ä, é, å) are text and pass through."""
    out = []
    chars = list(value)
    i = 0
    while i < len(chars):
        ch = chars[i]
        nxt = chars[i + 1] if i + 1 < len(chars) else ""
        if nxt in ("\u0307", "\u0308") and ch.isalpha():  # combining dot(s) over a letter: q̇, q̈
            base = _GREEK_CHARS.get(ch, ch)
            out.append(f"\\ensuremath{{\\{'dot' if nxt == chr(0x307) else 'ddot'}{{{base}}}}}")
            i += 2
            continue
        if ch in _SPECIAL:
            out.append(_SPECIAL[ch])
        elif unicodedata.category(ch) == "Cc" and ch not in "\n\t":
            out.append(f"[U+{ord(ch):04X}]")  # a control character: say what it was
        elif ch in _GREEK_CHARS:
            out.append(f"\\ensuremath{{{_GREEK_CHARS[ch]}}}")
        elif ch in _MATH_CHARS:
            out.append(f"\\ensuremath{{{_MATH_CHARS[ch]}}}")
        elif ord(ch) > 0xFF:  # a combining mark too, unless over a letter (above)
            out.append(f"[U+{ord(ch):04X}]")  # not in pdflatex's fonts: say what it was
        else:
            out.append(ch)
        i += 1
    return re.sub(r"\\ensuremath\{([^{}]*)\}\\ensuremath\{", r"\\ensuremath{\1", "".join(out))


def prose(value: str) -> str:
    """A step's text (``text``), its subscripted names (v_C) set in math: $v_{C}$."""
    return "".join(text(before) + (_subscripted(base, sub) if base else "") for before, base, sub in prose_pieces(value))


def _subscripted(base: str, sub: str) -> str:
    sub = sub if len(sub) == 1 else "\\mathrm{" + sub + "}"
    return "\\ensuremath{" + base + "_{" + sub + "}}"


def _step(step: Step) -> list[str]:
    out = []
    if step.text:
        out.append(f"\\emph{{{prose(step.text)}}}" if step.kind is StepKind.NOTE else prose(step.text))
    for rel in step.math:
        math = relation_latex(rel)
        out.append(f"\\[ \\boxed{{{math}}} \\]" if step.kind is StepKind.RESULT else f"\\[ {math} \\]")
    return out + [""]


def body(report: ProblemReport, pictures: tuple[Picture, ...] = ()) -> list[str]:
    lines = [f"\\section*{{{text(report.title)}}}"]
    if report.source:
        lines.append(f"\\emph{{{text(report.source)}}}\\par")
    if report.statement:
        lines += [text(report.statement), ""]
    lines += [line for picture in pictures for line in _picture(picture)]
    if report.values:
        given = (f"${value_latex(k, v)}$" + text(unit_text(report.units.get(k)) + report.degrees_text(k))
                 for k, v in report.values.items())
        lines.append("Parameter values: " + ", ".join(given) + ".")
    if report.model.steps:
        lines += ["\\subsection*{Model}"]
        for step in report.model.steps:
            lines += _step(step)
    for number, s in enumerate(report.solutions, start=1):
        lines.append(f"\\subsection*{{Question {number}: {text(s.question)}}}")
        for step in answer_steps(s.steps):
            lines += _step(step)
        lines += [f"\\textbf{{Warning:}} {prose(w)}\\par" for w in s.warnings]
        if s.error:
            lines.append(f"\\textbf{{Could not answer:}} {text(s.error)}\\par")
        lines += _numbers(s)
        lines += _accuracy(accuracy_steps(s.steps), accuracy_lines(s))
    return lines


def _numbers(s) -> list[str]:
    """The numeric block, each value under the name the solution prints, by heading."""
    blocks = groups(s.numbers)
    if not blocks:
        return []
    lines = ["Numeric values: \\begin{itemize}"]
    for heading, numbers in blocks:
        lines += [f"\\item[] {text(heading)}:"] if heading else []
        lines += [f"\\item ${relation_latex(n.relation)}${text(tail_text(n))}" for n in numbers]
    return lines + ["\\end{itemize}"]


def _accuracy(steps, numbers: list[str]) -> list[str]:
    """How accurate the numeric route's answers are, in small print under them."""
    if not steps and not numbers:
        return []
    lines = ["{\\small \\textit{Accuracy:}\\par"]
    for step in steps:
        lines += _step(step)
    if numbers:
        lines += ["\\begin{itemize}", *[f"\\item \\texttt{{{text(line)}}}" for line in numbers], "\\end{itemize}"]
    return lines + ["}"]


def _picture(picture: Picture) -> list[str]:
    """A figure where it is named, not floated away from its problem."""
    path = picture.path.as_posix()
    return ["\\begin{center}", f"\\includegraphics[width=0.85\\linewidth,height=0.3\\textheight,"
            f"keepaspectratio]{{{path}}}\\\\", f"\\small {text(picture.caption)}", "\\end{center}", ""]


def render_key(key: AnswerKey) -> str:
    """The answer key as one LaTeX document: a title, then each problem on its own page."""
    lines = [PREAMBLE, f"\\title{{{text(key.title)}}}", "\\date{}", "\\begin{document}", "\\maketitle"]
    for number, entry in enumerate(key.entries):
        if number:
            lines.append("\\clearpage")
        if entry.report is None:
            lines += [f"\\section*{{{text(entry.source)}}}", f"\\textbf{{Not solved:}} {text(entry.failure or '')}\\par"]
        else:
            lines += body(entry.report, entry.pictures)
    lines.append("\\end{document}")
    return "\n".join(lines) + "\n"


def render_document(reports: list[ProblemReport]) -> str:
    return document(reports[0].title if len(reports) == 1 else "Solutions",
                    ["\n".join(body(report)) for report in reports])


def document(title: str, bodies: list[str]) -> str:
    """One document around problems' bodies, each rendered on its own (so that one
    problem that cannot be rendered leaves the others whole)."""
    lines = [PREAMBLE, f"\\title{{{text(title)}}}", "\\date{}", "\\begin{document}", *bodies,
             "\\end{document}"]
    return "\n".join(lines) + "\n"
