"""A complexity gate: no function of the package is ranked D or worse by cyclomatic complexity.

Radon's ranks: A 1-5, B 6-10, C 11-20, D 21-30, E 31-40, F 41 and more. A function above 20
decisions is where bugs hide and reviews stop; break it up (a helper per case, a table instead
of a chain of ``if``). The functions above the line when the gate came were listed in ``KNOWN`` with
their complexity then, and left it as they were broken up: the list is empty now and only
shrinks; the gate fails if a listed function grows or any other crosses the line.
"""

from __future__ import annotations

from collections.abc import Iterator

from radon.complexity import cc_visit
from radon.visitors import Class, Function

from tests.conftest import ROOT

LIMIT = 20  # the top of rank C

# (module path, qualified name) -> complexity when the gate came (issue 24); all broken up since.
KNOWN: dict[tuple[str, str], int] = {}


def _functions(blocks: list[Function | Class]) -> Iterator[Function]:
    for block in blocks:
        if isinstance(block, Class):
            yield from _functions(list(block.methods))
        else:
            yield block
            yield from _functions(list(block.closures))


def complexities() -> dict[tuple[str, str], int]:
    """Every function and method of the package: (module path, qualified name) -> complexity."""
    found: dict[tuple[str, str], int] = {}
    for path in sorted((ROOT / "solver").rglob("*.py")):
        module = path.relative_to(ROOT).as_posix()
        for function in _functions(cc_visit(path.read_text(encoding="utf-8"))):
            key = (module, function.fullname)
            found[key] = max(found.get(key, 0), function.complexity)
    return found


def test_the_gate_sees_a_function_of_many_branches() -> None:
    source = "def f(x):\n" + "".join(f"    if x == {i}:\n        return {i}\n" for i in range(25))
    assert [f.complexity for f in _functions(cc_visit(source))] == [26]


def test_no_new_function_is_ranked_d_or_worse() -> None:
    over = {key: value for key, value in complexities().items() if value > LIMIT}
    new = sorted(
        f"{m}: {name} ({value})" for (m, name), value in over.items() if (m, name) not in KNOWN
    )
    assert new == []


def test_known_complex_functions_only_shrink_and_leave_the_list_when_broken_up() -> None:
    now = complexities()
    grown = sorted(
        f"{m}: {name} {was} -> {now[m, name]}"
        for (m, name), was in KNOWN.items()
        if now.get((m, name), 0) > was
    )
    done = sorted(f"{m}: {name}" for (m, name) in KNOWN if now.get((m, name), 0) <= LIMIT)
    assert grown == []
    assert done == [], "broken up (or gone): remove from KNOWN"
