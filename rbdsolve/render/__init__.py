"""Renderers: one per output format, each a function of reports only.

Only this package (and the CLI) knows about rich, and only the terminal renderer uses it.
"""
