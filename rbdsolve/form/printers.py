"""Math as text: readable unicode for terminals, LaTeX for documents.

Both printers show a coordinate θ(t) as θ, its derivatives as θ̇ and θ̈, Greek names as
letters, and a rational coefficient in front (7/8 θ̇², as an exam solution writes it).
Display values (:class:`Scaled`, :class:`Terms`, matrices) are laid out here too.
"""

from __future__ import annotations

import re
from contextlib import contextmanager
from contextvars import ContextVar
from functools import lru_cache

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.printing.latex import LatexPrinter
from sympy.printing.str import StrPrinter

from rbdsolve.form.display import Along, Label, Math, Product, Scaled, Terms
from rbdsolve.form.sign_placement import signs_placed
from rbdsolve.form.term_order import exam_order, readable_cosine

GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "lamda": "λ", "mu": "μ",
    "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ",
    "phi": "φ", "varphi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω",
    "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Pi": "Π",
    "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω",
}  # fmt: skip
_SUB = str.maketrans("0123456789+-=()aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")
_SUP = str.maketrans("0123456789+-=()n", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿ")
_SUBSCRIPTABLE = set("0123456789+-=()aehijklmnoprstuvx")


DIGITS = 6  # significant digits of a number in text, unless --digits says otherwise
_DIGITS: ContextVar[int] = ContextVar("digits", default=DIGITS)
NOISE = 64 * 2.0**-52  # relative size below which a float is not told from 0 in binary64


@contextmanager
def significant_digits(digits: int):
    """Numbers printed to ``digits`` significant digits inside the block (every text
    renderer; JSON answers keep full precision, they are not printed here)."""
    token = _DIGITS.set(digits)
    try:
        yield
    finally:
        _DIGITS.reset(token)


def digits() -> int:
    return _DIGITS.get()


def float_text(x: float) -> str:
    """x to the current significant digits, as text: 9.8176, 2.5e-7, −0.5 (an exponent
    without its padding zero: e-7, not e-07)."""
    text = f"{x:.{digits()}g}"
    mantissa, e, exponent = text.partition("e")
    if e:
        text = f"{mantissa}e{int(exponent)}"
    return "−" + text[1:] if text.startswith("-") else text


def float_latex(x: float) -> str:
    """x to the current significant digits, as LaTeX: 2.5 \\cdot 10^{-7}."""
    mantissa, _, exponent = float_text(x).replace("−", "-", 1).partition("e")
    return f"{mantissa} \\cdot 10^{{{exponent}}}" if exponent else mantissa


def within_rounding(values) -> set[int]:
    """The positions of the floats among ``values`` that are zero within rounding:
    smaller than NOISE times the largest (−3.08e-32 beside 1.5 is the residue of a
    cancellation, not a value)."""
    sizes = [abs(float(v)) if isinstance(v, sp.Float) else None for v in values]
    scale = max((x for x in sizes if x is not None), default=0.0)
    return {i for i, x in enumerate(sizes) if x is not None and x != 0 and x <= NOISE * scale}


def _zeroed(values) -> list:
    small = within_rounding(values)
    return [sp.Integer(0) if i in small else v for i, v in enumerate(values)]


def split_name(name: str) -> tuple[str, str]:
    """'omega0' -> ('omega', '0'); 'y_A' -> ('y', 'A'); 'T_long_rod' -> ('T', 'long_rod');
    'theta1_f' -> ('theta', '1,f') (an indexed name, then its own subscript: θ₁,f);
    'xB' -> ('x', 'B') (one small letter and capitals: a point's coordinate, x_B)."""
    if "_" in name.strip("_"):
        base, sub = name.split("_", 1)
        inner, index = _indexed(base)
        return (inner, f"{index},{sub}") if index else (base, sub)
    inner, index = _indexed(name)
    if index:
        return inner, index
    match = re.fullmatch(r"([a-z])([A-Z][A-Z0-9]*)", name)
    return (match.group(1), match.group(2)) if match else (name, "")


def _indexed(name: str) -> tuple[str, str]:
    """'theta1' -> ('theta', '1'); a name without a trailing number -> (name, '')."""
    match = re.fullmatch(r"([A-Za-z]+?)(\d+)", name)
    return (match.group(1), match.group(2)) if match else (name, "")


def unicode_name(name: str) -> str:
    base, sub = split_name(name)
    base = GREEK.get(base, base)
    if not sub:
        return base
    head, comma, rest = sub.partition(",")
    return base + _subscript(head) + (comma + (GREEK.get(rest, rest)) if comma else "")


PROSE_NAME = re.compile(r"(?<![\w'])([A-Za-z])_([A-Za-z0-9]{1,3})(?!\w)")  # v_C, J_G, r_O in prose


def prose_pieces(text: str) -> list[tuple[str, str, str]]:
    """Prose split where it writes a subscripted name as unicode cannot (v_C, a_O: no
    subscript capitals): (text before, base, subscript) for each such name, then (the rest,
    '', ''), so a typeset page writes v<sub>C</sub> or $v_{C}$. A name in quotes (body
    'rod_1') is the file's own and stays as written."""
    pieces, at = [], 0
    for match in PROSE_NAME.finditer(text):
        pieces.append((text[at:match.start()], match.group(1), match.group(2)))
        at = match.end()
    return [*pieces, (text[at:], "", "")]


def point_text(values) -> str:
    """'θ = −2.89055, φ = 0': coordinates' names and numbers, as a heading names a point;
    an exact value (π, recognized at a numeric equilibrium) as it is written."""
    return ", ".join(f"{unicode_name(str(q))} = {_point_value(v)}" for q, v in values.items())


def _point_value(v) -> str:
    if isinstance(v, sp.Basic) and not v.is_Float:
        return to_unicode(v)
    return float_text(float(v))


def _subscript(sub: str) -> str:
    """₁, ₐ where every character has a subscript form (and the subscript is short or a
    number), else _sub: y_A, T_rod."""
    sub_text = GREEK.get(sub, sub)
    if set(sub_text) <= _SUBSCRIPTABLE and (len(sub_text) <= 2 or sub_text.isdigit()):
        return sub_text.translate(_SUB)
    return f"_{sub_text}"


def latex_name(name: str) -> str:
    if len(name) > 2 and name.startswith("|") and name.endswith("|"):  # a norm's name, |v_B|
        return f"\\left|{latex_name(name[1:-1])}\\right|"
    base, sub = split_name(name)
    base = "\\" + base if base in GREEK else (base if len(base) == 1 else f"\\mathrm{{{base}}}")
    base = {"\\phi": "\\varphi", "\\lamda": "\\lambda"}.get(base, base)
    if not sub:
        return base
    sub_tex = {"phi": "\\varphi"}.get(sub, "\\" + sub) if sub in GREEK else sub.replace("_", "\\_")
    if len(sub) > 1 and sub not in GREEK:
        sub_tex = f"\\mathrm{{{sub_tex}}}"
    return f"{base}_{{{sub_tex}}}"


def _coordinate_name(expr) -> str | None:
    """The name of θ(t)-like functions of time."""
    if isinstance(expr, AppliedUndef) and expr.args == (sp.Symbol("t", real=True),):
        return expr.func.__name__
    return None


def _derivative(expr: sp.Derivative) -> tuple[str, int] | None:
    name = _coordinate_name(expr.expr)
    if name is None or len(expr.variable_count) != 1:
        return None
    return name, expr.variable_count[0][1]


def without_noise(terms: list) -> list:
    """A sum's terms without those whose number is zero within rounding beside the
    others' (1.5 θ̈ − 3.08e-32 θ̇ is 1.5 θ̈): only floats are judged, never exact terms."""
    coefficients = [t.as_coeff_Mul()[0] for t in terms]
    small = within_rounding(coefficients)
    return [t for i, t in enumerate(terms) if i not in small] if small and len(small) < len(terms) else terms


class UnicodePrinter(StrPrinter):
    """One-line unicode math: 7/8 m r² θ̇², √3 r, cos(φ − θ)."""

    def _as_ordered_terms(self, expr, order=None):
        return exam_order(without_noise(list(super()._as_ordered_terms(expr, order))))

    def _print_Symbol(self, expr):
        return unicode_name(expr.name)

    _print_Dummy = _print_Symbol

    def _print_Function(self, expr):
        name = _coordinate_name(expr)
        if name is not None:
            return unicode_name(name)
        return super()._print_Function(readable_cosine(expr))

    def _print_Pi(self, expr):
        return "π"

    def _print_ImaginaryUnit(self, expr):
        return "i"

    def _print_Abs(self, expr):
        return f"|{self._print(expr.args[0])}|"

    def _print_Integral(self, expr):
        """∫ f dt (indefinite, one variable), as in F = … + ∫ (½ ẏ² − g y) dt."""
        if len(expr.limits) == 1 and len(expr.limits[0]) == 1:
            inner = self._print(expr.function)
            inner = f"({inner})" if expr.function.is_Add else inner
            return f"∫ {inner} d{self._print(expr.limits[0][0])}"
        return super()._print_Integral(expr)

    def _print_Derivative(self, expr):
        if expr.expr.is_Symbol and len(expr.variables) == 1:  # ∂V/∂θ
            return f"∂{self._print(expr.expr)}/∂{self._print(expr.variables[0])}"
        found = _derivative(expr)
        if found and found[1] <= 3:
            name, order = found
            text = unicode_name(name)
            base = GREEK.get(split_name(name)[0], split_name(name)[0])
            if len(base) > 1:  # no dot over a word: d(name)/dt
                power = "" if order == 1 else str(order).translate(_SUP)
                return f"d{power}{text}/dt{power}"
            mark = {1: "\u0307", 2: "\u0308", 3: "\u20db"}[order]
            return text[0] + mark + text[1:]  # the dot sits over the base letter
        return super()._print_Derivative(expr)

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.as_base_exp()
        if exp in (sp.Rational(1, 2), sp.Rational(-1, 2)):
            inner = self._print(base)
            root = f"√{inner}" if base.is_Atom else f"√({inner})"
            return root if exp > 0 else f"1/{root}"
        if exp.is_Integer and exp > 0:
            if exp % 2 == 0 and base.is_Add and base.could_extract_minus_sign():
                base = -base  # (R − r)², not (r − R)²
            text = self.parenthesize(base, sp.printing.precedence.PRECEDENCE["Pow"])
            return text + str(exp).translate(_SUP)
        return super()._print_Pow(expr, rational)

    def parenthesize(self, item, level, strict=False):
        """A rate in Leibniz's form is bracketed as a power's base: (dth₁/dt)², not dth₁/dt²
        (a derivative with respect to t²); 1/(dth₁/dt), not 1/dth₁/dt."""
        text = super().parenthesize(item, level, strict)
        if isinstance(item, sp.Derivative) and "/" in text and not text.startswith("(") \
                and level >= sp.printing.precedence.PRECEDENCE["Pow"]:
            return f"({text})"
        return text

    def _over_rate(self, expr: sp.Mul, text: str) -> str:
        """g/(dth₁/dt), not g/dth₁/dt (which reads as (g/dth₁)/dt): StrPrinter writes a
        product's one factor below the bar after a bare "/"."""
        below = [f for f in expr.args if (f.is_Pow and f.exp.is_negative) or (f.is_Rational and f.q != 1)]
        if len(below) != 1 or not (below[0].is_Pow and below[0].exp == -1 and isinstance(below[0].base, sp.Derivative)):
            return text
        rate = self._print(below[0].base)
        if "/" in rate and text.endswith("/" + rate):
            return f"{text[:-len(rate)]}({rate})"
        return text

    def _print_Mul(self, expr):
        turned = signs_placed(expr)
        if turned is not None:
            return self._print(turned)
        lead = _rational_lead(expr)
        if lead is None:
            return self._over_rate(expr, super()._print_Mul(expr))
        sign, coeff, rest = lead
        inner = f"({self._print(rest)})" if rest.is_Add else self._print(rest)
        return f"{sign}{coeff.p}/{coeff.q} {inner}"

    def _print_Rational(self, expr):
        return f"{expr.p}/{expr.q}"

    def _print_Float(self, expr):
        text = float_text(float(expr))
        return "-" + text[1:] if text.startswith("−") else text  # made − with the rest (_tidy_unicode)

    def _print_ImmutableDenseMatrix(self, expr):
        if expr.shape == (1, 1):
            return self._print(expr[0, 0])
        entries = _zeroed(list(expr))
        if 1 in expr.shape:  # a vector
            return "(" + ", ".join(self._print(x) for x in entries) + ")"
        cols = expr.shape[1]
        rows = ["[" + ", ".join(self._print(x) for x in entries[r * cols:(r + 1) * cols]) + "]"
                for r in range(expr.shape[0])]
        return "[" + ", ".join(rows) + "]"

    _print_MutableDenseMatrix = _print_ImmutableDenseMatrix

    def _print_Equality(self, expr):
        return f"{self._print(expr.lhs)} = {self._print(expr.rhs)}"


def _rational_lead(expr: sp.Mul) -> tuple[str, sp.Rational, sp.Expr] | None:
    """(sign, |c|, rest) for c·rest with a proper fraction c written first: 7/8 θ̇²;
    None for a number (π/2 reads as itself)."""
    coeff, rest = expr.as_coeff_Mul()
    if coeff.is_Rational and not rest.free_symbols:
        return None
    if coeff.is_Rational and not coeff.is_Integer and rest != 1 and not _has_denominator(rest):
        return ("-" if coeff < 0 else ""), abs(coeff), rest
    return None


def _has_denominator(expr: sp.Expr) -> bool:
    return any(f.is_Pow and f.exp.is_negative for f in sp.Mul.make_args(expr))


def _tidy_unicode(text: str) -> str:
    text = text.replace("**", "^").replace("*", " ")
    text = re.sub(r"(?<=[\w)\]|\u0307\u0308⁰¹²³⁴⁵⁶⁷⁸⁹]) - ", " − ", text)  # also after |x| and [x]
    text = text.replace(" + -", " − ").replace("(-", "(−").replace("[-", "[−").replace(", -", ", −")
    return "−" + text[1:] if text.startswith("-") else text


class TexPrinter(LatexPrinter):
    """LaTeX with \\dot{\\theta}, rational coefficients in front, \\varphi."""

    def _as_ordered_terms(self, expr, order=None):
        return exam_order(without_noise(list(super()._as_ordered_terms(expr, order))))

    def _print_Add(self, expr, order=None):
        """A term whose sign ``signs_placed`` moves back in front (−k (−R cos θ − h),
        negated by the sum to k (−R cos θ − h), printed −k (R cos θ + h)) is joined by
        the one sign it has: + k (R cos θ + h), not - - k (…)."""
        return super()._print_Add(expr, order).replace(" - - ", " + ").replace(" + - ", " - ")

    def _print_Pow(self, expr):
        base, exp = expr.as_base_exp()
        if exp.is_Integer and exp > 0 and exp % 2 == 0 and base.is_Add and base.could_extract_minus_sign():
            return super()._print_Pow(sp.Pow(-base, exp, evaluate=False))  # (R − r)², not (r − R)²
        return super()._print_Pow(expr)

    def _print_Symbol(self, expr, style="plain"):
        return latex_name(expr.name)

    def _print_Float(self, expr):
        return float_latex(float(expr))

    def _print_Function(self, expr, exp=None):
        name = _coordinate_name(expr)
        if name is not None:
            text = latex_name(name)
            return f"{text}^{{{exp}}}" if exp else text
        return super()._print_Function(readable_cosine(expr), exp)

    def _print_Derivative(self, expr):
        if expr.expr.is_Symbol and len(expr.variables) == 1:  # ∂V/∂θ
            return f"\\frac{{\\partial {self._print(expr.expr)}}}{{\\partial {self._print(expr.variables[0])}}}"
        found = _derivative(expr)
        if found and found[1] <= 3:
            name, order = found
            accent = {1: "\\dot", 2: "\\ddot", 3: "\\dddot"}[order]
            head, _, tail = latex_name(name).partition("_{")  # the dot over x in ẋ_f
            return f"{accent}{{{head}}}" + (f"_{{{tail}" if tail else "")
        return super()._print_Derivative(expr)

    def _print_Mul(self, expr):
        turned = signs_placed(expr)
        if turned is not None:
            return self._print(turned)
        lead = _rational_lead(expr)
        if lead is None:
            return super()._print_Mul(expr)
        sign, coeff, rest = lead
        inner = f"\\left({self._print(rest)}\\right)" if rest.is_Add else self._print(rest)
        return f"{sign and '- '}\\frac{{{coeff.p}}}{{{coeff.q}}} {inner}"


_UNICODE = UnicodePrinter()
_TEX = TexPrinter()


def _product_parts(value: Product, printer) -> list[str]:
    """The coefficient, then the factors in their order: 1/4 cos(φ − θ) θ̇ φ̇; a
    coefficient over a symbol divides the whole, λ_A/m, not 1/m λ_A."""
    c = value.coefficient
    if value.divides():
        return [printer(value.value())]
    parts = []
    if c == -1 and value.factors:
        parts.append("-")
    elif c != 1 or not value.factors:
        text = printer(c)
        parts.append(f"({text})" if c.is_Add else text)
    parts += [printer(f) for f in value.factors]
    return parts


def to_unicode(value: Math) -> str:
    if isinstance(value, str):
        return value
    if isinstance(value, Label):
        return value.text
    if isinstance(value, Scaled):
        inner = to_unicode(value.inner)
        if value.negates():
            return f"−({inner})"
        bracket = isinstance(value.inner, Terms) or (
            isinstance(value.inner, sp.MatrixBase) and 1 not in value.inner.shape)
        return f"{to_unicode(value.factor)} {inner}" if bracket and inner.startswith("[") else (
            f"{to_unicode(value.factor)} [{inner}]" if bracket else f"{to_unicode(value.factor)} {inner}"
        )
    if isinstance(value, Terms):
        return _join(to_unicode(x) for x in value.shown())
    if isinstance(value, Product):
        return _tidy_unicode(" ".join(_product_parts(value, to_unicode)).replace("- ", "-", 1))
    if isinstance(value, Along):
        return _along(value, to_unicode(value.component), to_unicode(value.basis), "({})")
    try:
        return _printed(value, digits())
    except TypeError:  # a mutable matrix: not hashable, printed as it is
        return _tidy_unicode(_UNICODE.doprint(value))


@lru_cache(maxsize=8192, typed=True)  # printed to weigh its forms (form/factor.py), then shown: 1 and 1.0 apart
def _printed(value: sp.Basic, significant: int) -> str:
    """The unicode text of an expression at ``significant`` digits (the current ones:
    floats print to them, so they are part of what the text depends on)."""
    return _tidy_unicode(_UNICODE.doprint(value))


def _along(value: Along, component: str, basis: str, brackets: str) -> str:
    """(ẋ − 1/2 l φ̇) eₓ; 1 eₓ is eₓ and −1 eₓ is −eₓ."""
    if component in ("1", "-1", "−1"):
        return component[:-1] + basis
    return f"{brackets.format(component) if value.is_sum() else component} {basis}"


def _join(parts) -> str:
    out = ""
    for part in parts:
        if not out:
            out = part
        elif part.startswith(("-", "−")):
            out += " − " + part[1:].lstrip()
        else:
            out += " + " + part
    return out


def to_latex(value: Math) -> str:
    if isinstance(value, Label):
        return value.latex
    if isinstance(value, str):
        return f"\\text{{{value.encode('ascii', 'replace').decode()}}}"
    if isinstance(value, Scaled):
        inner = to_latex(value.inner)
        if value.negates():
            return f"-\\left({inner}\\right)"
        if isinstance(value.inner, Terms):
            inner = f"\\left[{inner}\\right]"
        return f"{to_latex(value.factor)} {inner}"
    if isinstance(value, Terms):
        out = ""
        for part in (to_latex(x) for x in value.shown()):
            if not out:
                out = part
            elif part.startswith("-"):
                out += " - " + part[1:].lstrip()
            else:
                out += " + " + part
        return out
    if isinstance(value, Product):
        return " ".join(_product_parts(value, to_latex)).replace("- ", "-", 1)
    if isinstance(value, Along):
        return _along(value, to_latex(value.component), to_latex(value.basis), "\\left({}\\right)")
    if isinstance(value, sp.MatrixBase) and value.shape == (1, 1):
        return to_latex(value[0, 0])
    if isinstance(value, sp.MatrixBase) and 1 in value.shape:
        items = " \\\\ ".join(_entries_latex(_zeroed(list(value))))
        return f"\\begin{{pmatrix}} {items} \\end{{pmatrix}}"
    if isinstance(value, sp.MatrixBase):
        cols = value.shape[1]
        entries = _entries_latex(_zeroed(list(value)))
        rows = " \\\\ ".join(" & ".join(entries[i:i + cols]) for i in range(0, len(entries), cols))
        return f"\\begin{{bmatrix}} {rows} \\end{{bmatrix}}"
    return _TEX.doprint(value)


def _entries_latex(entries: list) -> list[str]:
    """Each entry of a matrix in LaTeX, an entry that recurs printed once: a symmetric
    M or K of n coordinates has n(n + 1)/2 distinct entries of n² (an n-link chain's
    M(q): each cos(θⱼ − θᵢ) twice). An entry with a Float is printed each time (0.5 at
    15 and at 30 digits are equal keys), as is anything not hashable."""
    printed: dict = {}
    out = []
    for x in entries:
        if not isinstance(x, sp.Basic) or x.has(sp.Float):
            out.append(_TEX.doprint(x))
            continue
        text = printed.get(x)
        if text is None:
            text = printed[x] = _TEX.doprint(x)
        out.append(text)
    return out


LATEX_OPS = {"≥": r"\geq", "≤": r"\leq", "≠": r"\neq", "<": "<", ">": ">", "=": "="}


def relation_latex(rel) -> str:
    """A Relation in LaTeX math: ⇒ as \\Rightarrow, a worded lead ("stable when") as
    text, ≥ and ≤ as \\geq and \\leq (one home for every renderer that writes TeX)."""
    lead = "" if not rel.lead else r"\Rightarrow" if rel.lead == "⇒" else rf"\text{{{_tex_text(rel.lead)}}}\;"
    parts = [lead, to_latex(rel.lhs), LATEX_OPS.get(rel.op, rel.op), to_latex(rel.rhs)]
    parts += [f"{LATEX_OPS.get(rel.more_op, rel.more_op)} {to_latex(m)}" for m in rel.more]
    return " ".join(p for p in parts if p)


def _tex_text(words: str) -> str:
    """Plain words for \\text{…}: letters, digits and spaces only (they are ours)."""
    return "".join(ch for ch in words if (ch.isascii() and ch.isalnum()) or ch == " ")


def relation_text(rel) -> str:
    """A Relation (report.steps) in readable unicode: ⇒ T = T₁ + T₂ = …"""
    parts = [rel.lead, to_unicode(rel.lhs), rel.op, to_unicode(rel.rhs)]
    parts += [f"{rel.more_op} {to_unicode(m)}" for m in rel.more]
    return " ".join(p for p in parts if p)
