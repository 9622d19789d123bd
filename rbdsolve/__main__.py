from rbdsolve.cli import run

run()
