"""The exam form of mathematics, in one home: how a result is arranged for reading.

    display.py   display values: a sum in order, a scale pulled out, a relation
    tidy.py      bounded, targeted simplification of one coefficient or fraction
    arrange.py   common scales, the exam's order of terms, vectors along a basis
    printers.py  unicode for terminals and LaTeX for documents
    mathml.py    MathML for HTML, with the printers' conventions

Used by the model (tidy coefficients), the solvers' steps and every renderer; imports
nothing of rbdsolve but itself."""

from rbdsolve.form import sympy_fixes  # noqa: E402,F401 - sympy#28621, before any solving
