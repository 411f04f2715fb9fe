"""Benchmarks: each bench/bench_*.py has main() that prints its figures (never asserts time)."""
