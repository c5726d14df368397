"""Big generated robot descriptions: the shapes a huge or hostile ``robot_description`` takes.

Used by ``tests/identify/test_growth.py`` (the function calls a description four times as big
costs) and ``benchmarks/bench_identify.py`` (the seconds it takes). Every shape is built from
one repeated part, so what it must read as is known from how it was built.
"""

from __future__ import annotations

from collections.abc import Callable

GRIPPER_TAIL = 3  # the chain's last joints are named as a gripper's fingers

Place = Callable[[int], tuple[float, float, float]]


def _at_the_root(_i: int) -> tuple[float, float, float]:
    return (0.0, 0.0, 0.0)


def star(
    links: int,
    *,
    kind: str = "revolute",
    name: str = "j{i}",
    depth: int = 1,
    place: Place = _at_the_root,
    axis: str = "",
    mass: bool = False,
) -> str:
    """``links`` links in all: chains of ``depth`` joints of ``kind`` hang from the root, the
    ``i``-th one's first joint named ``name`` and placed at ``place(i)``."""
    limit = '<limit lower="-1" upper="1"/>' if kind in ("revolute", "prismatic") else ""
    inertial = '<inertial><mass value="1"/><origin xyz="0 0 0.01"/></inertial>' if mass else ""
    axis_tag = f'<axis xyz="{axis}"/>' if axis else ""
    parts = ['<robot name="star">', '<link name="base_link"/>']
    for i in range(1, 1 + (links - 1) // depth):
        parent = "base_link"
        for level in range(depth):
            child = f"l{i}_{level}"
            joint = name.format(i=i) + (f"_{level}" if level else "")
            origin = ""
            if level == 0:
                x, y, z = place(i)
                origin = f'<origin xyz="{x} {y} {z}"/>'
            parts.append(
                f'<link name="{child}">{inertial}</link><joint name="{joint}" type="{kind}">'
                f'<parent link="{parent}"/><child link="{child}"/>{origin}{axis_tag}{limit}'
                "</joint>"
            )
            parent = child
    return "\n".join([*parts, "</robot>"])


def chain(links: int, limits: str = 'lower="-1" upper="1"') -> str:
    """A serial chain of revolute joints whose last :data:`GRIPPER_TAIL` carry finger names."""
    parts = ['<robot name="chain">', '<link name="l0"/>']
    for i in range(1, links):
        name = f"finger_{i}" if i >= links - GRIPPER_TAIL else f"j{i}"
        parts.append(
            f'<link name="l{i}"/><joint name="{name}" type="revolute">'
            f'<parent link="l{i - 1}"/><child link="l{i}"/>'
            f"<limit {limits}/></joint>"
        )
    return "\n".join([*parts, "</robot>"])


def placeholder_chain(links: int) -> str:
    """The chain with every limit ``0 0``: a CAD exporter's placeholders the reader unlocks."""
    return chain(links, 'lower="0" upper="0"')


def _scattered(i: int) -> tuple[float, float, float]:
    """Places within 0.2 m of each other, none twice (a deterministic scatter)."""
    return ((i * 37 % 101) / 1000, (i * 53 % 97) / 1000, (i * 71 % 89) / 1000)


def _in_two_rows(i: int) -> tuple[float, float, float]:
    return (i / 1000, 0.2 if i % 2 else -0.2, 0.0)


def _in_a_grid(i: int) -> tuple[float, float, float]:
    return ((i % 50) / 100, (i // 50) / 100, 0.1)


# Each shape a description may take at any size, by what every part of it is.
SHAPES: dict[str, Callable[[int], str]] = {
    "a star of hinges": star,
    "a chain ending in gripper names": chain,
    "a chain with placeholder limits": placeholder_chain,
    "a star of endless joints": lambda n: star(n, kind="continuous"),
    "a star of slides": lambda n: star(n, kind="prismatic"),
    "a star of unmoving parts": lambda n: star(n, kind="fixed"),
    "a star of hinges scattered close": lambda n: star(n, place=_scattered),
    "a star of three-joint chains": lambda n: star(n, depth=3),
    "two rows of wheels": lambda n: star(
        n, kind="continuous", name="wheel_{i}", axis="0 1 0", place=_in_two_rows, mass=True
    ),
    "legs of three joints": lambda n: star(n, name="leg_{i}", depth=3, place=_in_two_rows),
    "a grid of rotors": lambda n: star(
        n, kind="continuous", name="rotor_{i}", axis="0 0 1", place=_in_a_grid, mass=True
    ),
    "casters on swivels": lambda n: star(n, kind="continuous", name="caster_{i}", depth=2),
    "gripper-named slides": lambda n: star(n, kind="prismatic", name="gripper_{i}"),
}
