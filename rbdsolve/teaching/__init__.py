"""Teaching: applications built on the solvers and the renderers, for a course rather
than for one problem: exam variants (variants.py), answer keys (key.py), and grading —
a student's check of expressions (check.py, compare.py) and a class's numbers against
its variants (grading.py), in the words of verdicts.py, answers named as in addresses.py."""
