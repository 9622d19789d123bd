from rbdsolve.cli import main

main()
