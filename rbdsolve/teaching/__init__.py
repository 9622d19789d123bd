"""Teaching: applications built on the solvers and the renderers, for a course rather
than for one problem: exam variants (variants.py) and answer keys (key.py)."""
