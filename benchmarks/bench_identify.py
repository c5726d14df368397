"""Reading and classifying big robot descriptions: time grows with links + joints, not faster.

A ``robot_description`` is whatever a robot publishes, so identification must stay linear.
Three generated shapes, each at 5,000, 20,000 and 80,000 links:

* a *star*: every link hangs from the root on its own revolute joint;
* a *chain* of revolute joints whose last links carry gripper names (the shape that walked the
  gripper's subtree once per gripper joint);
* the same chain with every limit ``0 0``, a CAD exporter's placeholders the reader unlocks
  (the shape whose joints were each checked against a set built anew per joint: 8.75 s for
  20,000 joints before, 0.66 s after, the forty-first stop).

Before the change a star of 20,000 links took 13 s, of 80,000 links 208 s, and the 20,000-link
chain 122 s (issue 18). After (this machine, 2 cores shared, load ~2.5): star 0.18 / 0.76 /
3.45 s and chain 0.13 / 0.55 / 2.89 s at 5k / 20k / 80k links, growth 4.1x and 19x (star),
4.2x and 22x (chain) for 4x and 16x the links: linear, plus what Python's garbage collector
costs on a few hundred thousand live objects at 80k. Each round asserts what it read (the
number of joints, the structure), computed from how the description was built. The growth
ratio (time at 4x the links over time at 1x, about 4 when linear, 16 when quadratic) is
reported by ``test_growth_ratio`` from the same run: it prints the ratios, and asserts only
the counts it timed.

The star became quadratic again with a rule that compared every two of a palm's single hinges
(``f6d3d11``, the fifty-fifth stop): 442 s at 80,000 links in the fifty-eighth stop's full run,
where it was seen (10,000 links: 5.2 s; 0.88 s after). The box around the hinges now tells
(:func:`solver.identify.pose.within`), and ``tests/identify/test_growth.py`` counts the calls
each shape here and ten more cost at four times the size, so that no rule makes one quadratic
unseen again.

Run: ``pytest benchmarks/bench_identify.py --benchmark-only``.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from solver.core.rules import default_rules_path, load_rules
from solver.identify import Identification, identify_urdf, load_profile
from tests.identify.shapes import GRIPPER_TAIL, chain, placeholder_chain, star

SIZES = (5_000, 20_000, 80_000)
# The shapes timed here, by the names the benchmark's ids have always had.
SHAPES: dict[str, Callable[[int], str]] = {
    "star": star,
    "chain ending in gripper names": chain,
    "chain with placeholder limits": placeholder_chain,
}


def read(text: str) -> Identification:
    return identify_urdf(text, rules=RULES, profile=PROFILE)


PROFILE = load_profile()
RULES = load_rules(default_rules_path())


@pytest.mark.parametrize("links", SIZES, ids=[f"{n} links" for n in SIZES])
@pytest.mark.parametrize("shape", list(SHAPES), ids=list(SHAPES))
def test_identifying_a_big_description(benchmark: BenchmarkFixture, shape: str, links: int) -> None:
    benchmark.group = f"identify {shape}"
    text = SHAPES[shape](links)
    # One round: the 80,000-link cases take seconds each.
    result = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pedantic is unannotated
        read, args=(text,), rounds=1, iterations=1
    )
    assert result.body is not None
    moved = sum(len(limb.joints) for limb in result.body.limbs) + len(result.body.trunk)
    if shape == "star":
        # Every link beyond the root is a one-joint chain on the root: fingers of a "palm".
        assert len(result.body.fingers) == links - 1
        assert result.structure == "Hand"
    else:
        # One arm ending in a gripper of GRIPPER_TAIL joints.
        assert moved == links - 1 - GRIPPER_TAIL
        assert result.structure == "Manipulator"


def test_growth_ratio(capsys: pytest.CaptureFixture[str]) -> None:
    """Time at 4x and 16x the links over time at 1x, for each shape, measured in this run."""
    lines = []
    for shape, build in SHAPES.items():
        seconds = []
        for links in SIZES:
            text = build(links)
            start = time.perf_counter()
            result = read(text)
            seconds.append(time.perf_counter() - start)
            assert result.body is not None
        ratios = ", ".join(
            f"{links // SIZES[0]}x links: {t / seconds[0]:.1f}x time"
            for links, t in zip(SIZES[1:], seconds[1:], strict=True)
        )
        lines.append(f"{shape}: {SIZES[0]} links {seconds[0]:.3f} s; {ratios}")
    with capsys.disabled():
        print("\n" + "\n".join(lines))
    assert len(lines) == len(SHAPES)
