"""Renderers: one per output format (terminal, Markdown, LaTeX, HTML, JSON, the variants
sheets), each a function of reports only; ``drawing/`` draws planar scenes and their
mode shapes from a model.

Only this package (and the CLI) knows about rich, and only the terminal renderer uses it.
"""
