"""Math as MathML, for HTML: what a browser typesets with no script and no network.

sympy's presentation printer, extended as printers.py extends the LaTeX one: a
coordinate θ(t) is θ, its derivatives carry dots (θ̇, θ̈), Greek names are letters with
subscripts (ω₀), a rational coefficient stands in front as a fraction (7/4 m r² θ̈), a
positive term first. The display values (Scaled, Terms, Product, Along, Label) are
laid out here as they are in to_latex, so every medium shows one arrangement.

The markup is well-formed XML: sympy's named entities (&InvisibleTimes;, &pi;) become
the characters they name, and text is escaped.
"""

from __future__ import annotations

import html
import re

import sympy as sp
from sympy.printing.mathml import MathMLPresentationPrinter

from rbdsolve.form.display import Along, Label, Math, Product, Relation, Scaled, Terms
from rbdsolve.form.printers import GREEK, _coordinate_name, _derivative, _rational_lead, float_text, split_name
from rbdsolve.form.sign_placement import signs_placed
from rbdsolve.form.term_order import exam_order, readable_cosine

# ˙ ¨ ⃛ : spacing accents over the base letter. Set over it as an ordinary script, not
# with accent="true": Chromium then lowers the accent onto the letter's top stroke
# (measured in a screenshot: the dot touches θ and vanishes at text size); as a script
# it stands clear above (tests/render/test_html.py measures the gap).
_DOTS = {1: "\u02d9", 2: "\u00a8", 3: "\u20db"}
_XML_ENTITIES = {"lt", "gt", "amp", "quot", "apos"}
_ENTITY = re.compile(r"&(#x[0-9A-Fa-f]+|#[0-9]+|[A-Za-z][A-Za-z0-9]*);")


def _tag(name: str, *children: str, **attributes: str) -> str:
    attrs = "".join(f' {k.rstrip("_")}="{html.escape(v, quote=True)}"' for k, v in attributes.items())
    return f"<{name}{attrs}>{''.join(children)}</{name}>"


def _token(name: str, text: str) -> str:
    return _tag(name, html.escape(text, quote=False))


def _mo(op: str) -> str:
    return _token("mo", op)


def fenced(inner: str, left: str = "(", right: str = ")") -> str:
    """Brackets around ``inner``: stretched to its height where it holds a fraction, a
    table or a root, else at the text's size (a stretchy bracket gets an operator's
    spacing in a browser: cos ( θ ) instead of cos(θ))."""
    tall = any(tag in inner for tag in ("<mfrac", "<mtable", "<msqrt", "<mroot", "<mover", "<munder"))
    attrs = {} if tall else {"stretchy": "false"}
    return _tag("mrow", _tag("mo", left, **attrs), inner, _tag("mo", right, **attrs))


def name_mathml(name: str) -> str:
    """A declared name: Greek as letters, the part after _ or a trailing number as a
    subscript (omega0 -> ω₀, y_A -> y_A, T_long_rod -> T with 'long_rod' below)."""
    base, sub = _name_parts(name)
    return base if sub is None else _tag("msub", base, sub)


def _name_parts(name: str) -> tuple[str, str | None]:
    """A name's letter and its subscript (None: it has none), as MathML tokens."""
    base, sub = split_name(name)
    base_el = _token("mi", GREEK.get(base, base))
    if not sub:
        return base_el, None
    return base_el, _token("mn", sub) if sub.isdigit() else _token("mi", GREEK.get(sub, sub))


def _dotted(name: str, order: int) -> str:
    """θ̇, θ̈, ẋ_f: the dots over the base letter, a subscript after them."""
    letter, sub = _name_parts(name)
    over = _tag("mover", letter, _mo(_DOTS[order]))
    return over if sub is None else _tag("msub", over, sub)


class MathMLPrinter(MathMLPresentationPrinter):
    """sympy's presentation MathML with the exam's conventions (printers.py's)."""

    def __init__(self) -> None:
        super().__init__({"mat_delim": "["})

    def _raw(self, markup: str):
        """Markup already made (by the helpers above) as a node of sympy's DOM: its text
        nodes are written raw, so the string goes out as it is."""
        return self.dom.createTextNode(markup)

    def _as_ordered_terms(self, expr, order=None):
        return exam_order(list(super()._as_ordered_terms(expr, order)))

    def parenthesize(self, item, level, strict=False):
        from sympy.printing.precedence import precedence_traditional

        prec = precedence_traditional(item)
        if _is_letter(item):  # θ̇ reads as one letter: no brackets in a product
            return self._print(item)
        if prec < level or (not strict and prec <= level):
            return self._raw(fenced(self.doprint_inner(item)))
        return self._print(item)

    def _paren_comma_separated(self, *args):
        return self._raw(fenced(_mo(",").join(self.doprint_inner(a) for a in args)))

    def _print_Symbol(self, sym, style="plain"):
        return self._raw(name_mathml(sym.name))

    _print_Dummy = _print_Symbol

    def _print_Function(self, e):
        name = _coordinate_name(e)
        if name is not None:
            return self._raw(name_mathml(name))
        return super()._print_Function(readable_cosine(e))

    def _print_Derivative(self, e):
        if e.expr.is_Symbol and len(e.variables) == 1:  # ∂V/∂θ
            top = _tag("mrow", _mo("∂"), self.doprint_inner(e.expr))
            return self._raw(_tag("mfrac", top, _tag("mrow", _mo("∂"), self.doprint_inner(e.variables[0]))))
        found = _derivative(e)
        if found and found[1] <= 3:
            name, order = found
            if len(GREEK.get(split_name(name)[0], split_name(name)[0])) == 1:
                return self._raw(_dotted(name, order))
        return super()._print_Derivative(e)

    def _print_Pow(self, e):
        base, exp = e.as_base_exp()
        if exp.is_Integer and exp > 0 and exp % 2 == 0 and base.is_Add and base.could_extract_minus_sign():
            return super()._print_Pow(sp.Pow(-base, exp, evaluate=False))  # (R − r)², not (r − R)²
        if exp.is_Integer and exp > 0 and _is_letter(base):  # θ̇², not (θ̇)²
            return self._raw(_tag("msup", self.doprint_inner(base), self.doprint_inner(exp)))
        if exp.is_Integer and exp > 0 and isinstance(base, sp.Symbol) and split_name(base.name)[1]:
            letter, sub = _name_parts(base.name)  # ω₀²: the power over the subscript, not after it
            return self._raw(_tag("msubsup", letter, sub, self.doprint_inner(exp)))
        return super()._print_Pow(e)

    def _print_Mul(self, expr):
        turned = signs_placed(expr)
        if turned is not None:
            return self._print(turned)
        lead = _rational_lead(expr)
        return super()._print_Mul(expr) if lead is None else self._raw(self._led(*lead))

    def _led(self, sign: str, coeff: sp.Rational, rest: sp.Expr) -> str:
        """−7/4 m r² θ̈: a proper fraction in front of the rest, as the exam writes it."""
        inner = fenced(self.doprint_inner(rest)) if rest.is_Add else self.doprint_inner(rest)
        fraction = _tag("mfrac", _token("mn", str(coeff.p)), _token("mn", str(coeff.q)))
        return _tag("mrow", *([_mo("−")] if sign else []), fraction, inner)

    def _print_Pi(self, e):
        """π upright, a constant (a one-letter <mi> is italic by default, a variable's style)."""
        return self._raw(_tag("mi", "π", mathvariant="normal"))

    def _print_MatrixBase(self, m):
        """A matrix in square brackets, a vector as a column in round ones (the LaTeX's
        bmatrix and pmatrix); entries at display size, so 7/4 is not a script."""
        if m.shape == (1, 1):
            return self._print(m[0, 0])
        rows = m.tolist() if 1 not in m.shape else [[x] for x in m]
        table = _tag("mtable", *(_tag("mtr", *(_tag("mtd", _tag("mstyle", self.doprint_inner(x), displaystyle="true"))
                                                for x in row)) for row in rows))
        return self._raw(fenced(table) if 1 in m.shape else fenced(table, "[", "]"))

    def _print_Number(self, e):
        """A negative number with a minus sign (U+2212), not a hyphen: −2."""
        if e.is_negative:
            return self._raw(_tag("mrow", _mo("−"), self.doprint_inner(-e)))
        return super()._print_Number(e)

    _print_Integer = _print_Number

    def _print_Float(self, e):
        """A float to the significant digits asked (``--digits``, as in every other
        format): 3.14159, 2.5·10⁻⁷ (sympy's own printer writes all 15)."""
        if e.is_negative:
            return self._raw(_tag("mrow", _mo("−"), self.doprint_inner(-e)))
        mantissa, _, exponent = float_text(float(e)).partition("e")
        if not exponent:
            return self._raw(_token("mn", mantissa))
        power = _tag("msup", _token("mn", "10"), _token("mn", exponent.replace("-", "−")))
        return self._raw(_tag("mrow", _token("mn", mantissa), _mo("·"), power))

    def doprint_inner(self, expr) -> str:
        """One sympy object's markup (no <math> around it); a minus sign is U+2212, as
        in the unicode printer, not the hyphen sympy writes."""
        return _characters(self._print(expr).toxml()).replace("<mo>-</mo>", "<mo>−</mo>")


def _is_letter(expr) -> bool:
    """A coordinate θ(t), or a derivative of one printed with dots: a power of it
    needs no brackets."""
    if _coordinate_name(expr) is not None:
        return True
    found = _derivative(expr) if isinstance(expr, sp.Derivative) else None
    return bool(found) and found[1] <= 3 and len(GREEK.get(split_name(found[0])[0], split_name(found[0])[0])) == 1


def _characters(markup: str) -> str:
    """Every entity but XML's five as its character: &InvisibleTimes; is U+2062, and a
    document needs no entity table to read the markup."""
    def one(match: re.Match) -> str:
        if match.group(1) in _XML_ENTITIES:
            return match.group(0)
        text = html.unescape(match.group(0))
        return html.escape(text, quote=False) if text != match.group(0) else "&amp;" + match.group(0)[1:]

    return _ENTITY.sub(one, markup)


_PRINTER = MathMLPrinter()


def _negated(value: Math) -> Math | None:
    """The value without its leading minus sign, or None where it has none (to write
    a − b, not a + −b, in a sum)."""
    if isinstance(value, sp.Basic) and not isinstance(value, sp.MatrixBase) and value.could_extract_minus_sign():
        return -value
    if isinstance(value, Product) and value.coefficient.could_extract_minus_sign():
        return Product(-value.coefficient, value.factors)
    if isinstance(value, Scaled) and isinstance(value.factor, sp.Basic) and value.factor.could_extract_minus_sign():
        return Scaled(-value.factor, value.inner)
    if isinstance(value, Along) and (inner := _negated(value.component)) is not None:
        return Along(inner, value.basis)
    return None


def _terms(items) -> str:
    out: list[str] = []
    for i, item in enumerate(items):
        negative = _negated(item)
        if negative is not None:
            out += [_mo("−"), to_mathml(negative)]
        else:
            out += ([_mo("+")] if i else []) + [to_mathml(item)]
    return _tag("mrow", *out)


def to_mathml(value: Math) -> str:
    """A value's MathML (an mrow or a token; no <math> element around it)."""
    if isinstance(value, Label):
        return _token("mtext", value.text)
    if isinstance(value, str):
        return _token("mtext", value)
    if isinstance(value, Scaled):
        inner = to_mathml(value.inner)
        if value.negates():
            return _tag("mrow", _mo("−"), fenced(inner))
        return _tag("mrow", to_mathml(value.factor), fenced(inner, "[", "]") if isinstance(value.inner, Terms) else inner)
    if isinstance(value, Terms):
        return _terms(value.shown())
    if isinstance(value, Product):
        return _product(value)
    if isinstance(value, Along):
        return _along(value)
    return _PRINTER.doprint_inner(value)


def _product(value: Product) -> str:
    c = value.coefficient
    if value.divides():
        return to_mathml(value.value())
    parts = []
    if c == -1 and value.factors:
        parts.append(_mo("−"))
    elif c != 1 or not value.factors:
        parts.append(fenced(to_mathml(c)) if c.is_Add else to_mathml(c))
    return _tag("mrow", *parts, *(to_mathml(f) for f in value.factors))


def _along(value: Along) -> str:
    """(ẋ − 1/2 l φ̇) eₓ; 1 eₓ is eₓ and −1 eₓ is −eₓ."""
    basis = to_mathml(value.basis)
    c = value.component
    if isinstance(c, sp.Basic) and c in (sp.S.One, sp.S.NegativeOne):
        return basis if c == 1 else _tag("mrow", _mo("−"), basis)
    component = to_mathml(c)
    if value.is_sum():
        component = fenced(component)
    return _tag("mrow", component, basis)


def _lead(words: str) -> str:
    return _mo("⇒") if words == "⇒" else _tag("mtext", html.escape(words + "\u2002", quote=False))


def relation_mathml(rel: Relation) -> str:
    """A Relation (report.steps) as one <math> element, typeset as a display: ⇒ T = …"""
    parts = [_lead(rel.lead)] if rel.lead else []
    parts += [to_mathml(rel.lhs), _mo(rel.op), to_mathml(rel.rhs)]
    for more in rel.more:
        parts += [_mo(rel.more_op), to_mathml(more)]
    # No xmlns: HTML puts <math> in MathML's namespace itself, and the key names no URL.
    return _tag("math", _spaced(_tag("mrow", *parts)), displaystyle="true")


_BEFORE_FUNCTION = re.compile("(</(?:mi|mn|msup|msub|mover|mfrac|mrow)>)(?:<mo>\u2062</mo>)?"
                              "(?=<mrow><mi>[A-Za-z]{2,}</mi>)")


_BEFORE_WORD = re.compile("<mo>\u2062</mo>(?=<mi>[A-Za-z]{2,}</mi>)")


def _spaced(markup: str) -> str:
    """A thin space before a function's name or a word in a product, as TeX sets
    g m r cos θ and r·spin (a browser puts none for an invisible times)."""
    markup = _BEFORE_FUNCTION.sub(r'\1<mspace width="0.1667em"/>', markup)
    return _BEFORE_WORD.sub('<mspace width="0.1667em"/>', markup)
