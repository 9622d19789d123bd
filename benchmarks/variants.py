"""Benchmark: 1,000 exam variants of seed problem 1 (target: under 5 s).

    python3 -m benchmarks.variants [--count 1000] [--out benchmarks/results]

Times ``variants()`` in-process (median of 5 runs: load, the one exact solve, the
vectorised evaluation, the default 3 verification solves) and the whole ``rbdsolve
variants … -o FILE.csv`` process once; prints the numbers and writes them to
variants.json in --out. See docs/performance.md. Tests never assert on timing.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from benchmarks.run import SEED_P1

RUNS = 5
TARGET_S = 5.0


def in_process(count: int) -> list[float]:
    from rbdsolve.problem import load_file
    from rbdsolve.teaching.variants import variants

    samples = []
    for _ in range(RUNS):
        start = time.perf_counter()
        variants(load_file(SEED_P1), count, 1)
        samples.append(time.perf_counter() - start)
    return samples


def whole_process(count: int) -> float:
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "rbdsolve", "variants", str(SEED_P1), "--count", str(count),
                        "--seed", "1", "-o", str(Path(tmp) / "variants.csv")], check=True,
                       capture_output=True)
        return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=1000)
    parser.add_argument("--out", type=Path, default=Path(__file__).parent / "results")
    args = parser.parse_args()
    samples = in_process(args.count)
    process = whole_process(args.count)
    result = {"problem": str(SEED_P1.relative_to(SEED_P1.parents[2])), "count": args.count,
              "median_s": statistics.median(samples), "samples_s": samples,
              "whole_process_s": process, "target_s": TARGET_S, "python": sys.version.split()[0]}
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "variants.json").write_text(json.dumps(result, indent=1) + "\n", encoding="utf-8")
    verdict = "within" if max(result["median_s"], process) < TARGET_S else "OVER"
    print(f"{args.count} variants of p1: in-process median {result['median_s']:.2f} s "
          f"(runs: {', '.join(f'{s:.2f}' for s in samples)}), whole process {process:.2f} s; "
          f"{verdict} the {TARGET_S:g} s target")


if __name__ == "__main__":
    main()
