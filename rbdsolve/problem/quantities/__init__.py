"""The problem's quantities: values as exams write them (exact constants, quantities
with units, in SI), which parameters are masses, lengths, accelerations (their
dimensions, read off the scene), a parameter's range per exam variant, and values
given from outside a file (--set, the Python API).

Used by problem/loader.py, by model/values/ (the SI unit of each answer) and by
teaching/ (exam variants)."""
