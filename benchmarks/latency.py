"""Latency figures of the live benchmarks (ROS 1 and ROS 2 watchers): median, p95, max."""

from __future__ import annotations

import statistics

from pytest_benchmark.fixture import BenchmarkFixture

__all__ = ["report"]


def report(benchmark: BenchmarkFixture, name: str, latencies: list[float], note: str = "") -> None:
    """Record ``latencies`` (seconds) in the benchmark's extra info and print them when timed."""
    ordered = sorted(latencies)
    p95 = ordered[min(len(ordered) - 1, round(0.95 * (len(ordered) - 1)))]
    median = statistics.median(ordered)
    benchmark.extra_info.update(
        {
            "changes": len(ordered),
            "median_ms": round(median * 1000, 1),
            "p95_ms": round(p95 * 1000, 1),
            "max_ms": round(ordered[-1] * 1000, 1),
        }
    )
    if not benchmark.disabled:
        print(
            f"\n{name}: {len(ordered)} changes: median {median * 1000:.1f} ms, 95th percentile "
            f"{p95 * 1000:.1f} ms, max {ordered[-1] * 1000:.1f} ms{note}"
        )
