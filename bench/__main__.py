"""`make bench`: run every bench/bench_*.py (or those named on the command line)."""

import importlib
import sys
import time
from pathlib import Path

from bench import machine


def main(argv: list[str]) -> int:
    names = argv or sorted(p.stem for p in Path(__file__).parent.glob("bench_*.py"))
    for name in names:
        module = importlib.import_module(f"bench.{name}")
        print(f"== {name}\n{machine.state()}", flush=True)
        started, stolen = time.perf_counter(), machine.stolen()
        module.main()
        took = f"{time.perf_counter() - started:.1f} s{machine.stolen_since(stolen)}"
        print(f"== {name} took {took}; {machine.state()}\n", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
