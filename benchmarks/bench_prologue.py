"""Benchmark: reading the prologue of an XML description, hostile or long, before libxml2 does.

Every URDF and SRDF, from a file or a live ``robot_description``, is scanned up to its root
element first (:mod:`solver.identify.readers.prologue`). A regular expression searching for
the internal subset from every ``<!DOCTYPE[`` was quadratic: 40,000 of them took more than a
minute in ``identify``. Here the whole reader (:func:`parse_xml`) meets prologues of the same
shape 1 KB and 1 MiB long: a comment, processing instructions (the scan stops at 10,000
items), and open document types (the scan stops at the first byte no subset holds). The ratio
``1 MiB / 1 KB`` says how the time follows the length: about 1,000 when linear, and far above
it if the work grew faster than the input.

Run: ``python -m pytest benchmarks/bench_prologue.py``.
"""

from __future__ import annotations

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from solver.errors import InputError
from solver.identify.readers.safexml import parse_xml

ROBOT = b'<robot name="r"><link name="base_link"/></robot>'
SHAPES = {
    "comment": (b"<!--", b"x", b"-->"),
    "instructions": (b"", b"<?a?>", b""),
    "open-doctypes": (b"", b"<!DOCTYPE[", b""),
}


def prologue(shape: str, length: int) -> bytes:
    head, unit, tail = SHAPES[shape]
    return head + unit * (length // len(unit)) + tail + ROBOT


@pytest.mark.parametrize("length", [1_000, 1_000_000], ids=["1 KB", "1 MB"])
@pytest.mark.parametrize("shape", list(SHAPES))
def test_read_a_prologue(benchmark: BenchmarkFixture, shape: str, length: int) -> None:
    data = prologue(shape, length)

    def read() -> str:
        try:
            root = parse_xml(data, "r.urdf")
        except InputError as error:
            return error.faults[0].code
        return str(root.tag)

    outcome = benchmark(read)
    # A comment of either length and 200 instructions are a prologue like any other; 200,000
    # instructions pass the 10,000-item bound; open document types are malformed XML.
    expected = {
        "comment": "robot",
        "instructions": "robot" if length < 50_000 else "xml-prologue",
        "open-doctypes": "xml",
    }
    assert outcome == expected[shape]
