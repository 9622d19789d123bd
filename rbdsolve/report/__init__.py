"""The vocabulary of results: typed steps, solutions, problem reports, answer keys and
variant tables. Solvers and the teaching layer build these as data; renderers turn them
into text. Nothing here prints or computes; how mathematics is arranged for reading
lives in rbdsolve.form.
"""
