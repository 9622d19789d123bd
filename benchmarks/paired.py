"""Paired processor seconds per problem file: two checkouts, run in turn.

    python3 -m benchmarks.paired OLD_ROOT NEW_ROOT [--repeats N] [--out FILE] [FILES…]

Each file is solved as a student runs it (``python -m rbdsolve solve FILE --format json``,
one process) from each checkout, the two alternating (old first on even files, new
first on odd ones, and in turn within a file's repeats), and the child's processor
seconds (user + system, ``os.wait4``) are kept. On a machine whose speed drifts from one
minute to the next (this one: ``import sympy`` 0.34 s in one hour, 0.46–0.64 s in
another), runs side by side compare two versions where runs an hour apart do not. The
least of a file's repeats is its time; printed: the sums, the median ratio new/old, and
the files that moved most each way.
"""

from __future__ import annotations

import argparse
import glob
import json
import os
import statistics
import subprocess
import sys


def processor_seconds(root: str, path: str) -> float:
    """One solve of ``path`` with the rbdsolve of checkout ``root``: its processor seconds."""
    env = dict(os.environ, PYTHONPATH=root)
    env.pop("PYTHONDONTWRITEBYTECODE", None)  # as a student's run: compiled modules kept
    child = subprocess.Popen([sys.executable, "-m", "rbdsolve", "solve", path, "--format", "json"], cwd=root,
                             env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, usage = os.wait4(child.pid, 0)
    return usage.ru_utime + usage.ru_stime


def paired(old: str, new: str, files: list[str], repeats: int) -> list[tuple[str, float, float]]:
    rows = []
    for i, path in enumerate(files):
        a, b = [], []
        for k in range(repeats):
            if (i + k) % 2 == 0:
                a.append(processor_seconds(old, path))
                b.append(processor_seconds(new, path))
            else:
                b.append(processor_seconds(new, path))
                a.append(processor_seconds(old, path))
        rows.append((path, min(a), min(b)))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("files", nargs="*", help="paths inside the checkouts (default: every file of problems/)")
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--out")
    args = parser.parse_args()
    files = args.files or sorted(os.path.relpath(p, args.new)
                                 for p in glob.glob(f"{args.new}/problems/**/*.yaml", recursive=True)
                                 if not p.endswith(".expected.yaml"))
    rows = paired(args.old, args.new, files, args.repeats)
    if args.out:
        with open(args.out, "w") as out:
            json.dump(rows, out)
    old_sum, new_sum = sum(a for _, a, _ in rows), sum(b for *_, b in rows)
    print(f"{len(rows)} files: old {old_sum:.2f} s, new {new_sum:.2f} s in all; "
          f"median ratio new/old {statistics.median(b / a for _, a, b in rows):.3f}")
    moved = sorted(rows, key=lambda r: r[2] - r[1])
    for path, a, b in moved[:5] + moved[-5:]:
        print(f"{a:7.2f} {b:7.2f} {b - a:+6.2f}  {path}")


if __name__ == "__main__":
    main()
