"""Where each part of a robot is at rest: every link's place and every joint's axis in the root's
frame.

A joint's ``<origin>`` places its child on its parent (``xyz``, then turned by ``rpy``), and its
``<axis>`` is written in the child's frame. Walking the tree from the root with every joint at
zero gives each link's place and turn in one frame, the frame a description is drawn in
(ROS: x forward, y left, z up). The body's steps ask two questions of it: which way a joint
turns (a snake's joints alternate their axes; a parallel gripper's jaws turn about one line) and
where a chain ends (a leg's foot is below its hip; a finger points away from the palm).

:class:`Poses` works them out once per description, in one pass over the joints (linear in
their number, iterative: a hostile depth costs no recursion).

Not here: what the answers mean (:mod:`solver.identify.limbs`, :mod:`solver.identify.hands`,
:mod:`solver.identify.actuation`).
"""

from __future__ import annotations

import math
from dataclasses import replace
from itertools import combinations

from solver.identify.readers.urdf import Joint, Urdf

__all__ = [
    "CELLS_AROUND",
    "Poses",
    "Vector",
    "centroid",
    "cross",
    "distance",
    "dot",
    "grid_cell",
    "local_axis",
    "minus",
    "parallel",
    "perpendicular",
    "same_way",
    "spread",
    "within",
]

Vector = tuple[float, float, float]
_Matrix = tuple[Vector, Vector, Vector]
_IDENTITY: _Matrix = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
# Axes closer than this (|cos| of the angle between them) count as parallel; below the second,
# as perpendicular.
_PARALLEL = 0.98
_PERPENDICULAR = 0.1
# A link is long when its least principal moment is at most this part of the next: a rod about
# three times as long as it is thick, or longer (a plate's two least moments are alike).
_SLENDER = 0.25


def _rotation(rpy: Vector) -> _Matrix:
    """URDF's fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    roll, pitch, yaw = rpy
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return (
        (cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr),
        (sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr),
        (-sp, cp * sr, cp * cr),
    )


def _turn(matrix: _Matrix, vector: Vector) -> Vector:
    x, y, z = vector
    return (
        matrix[0][0] * x + matrix[0][1] * y + matrix[0][2] * z,
        matrix[1][0] * x + matrix[1][1] * y + matrix[1][2] * z,
        matrix[2][0] * x + matrix[2][1] * y + matrix[2][2] * z,
    )


def _compose(first: _Matrix, second: _Matrix) -> _Matrix:
    columns = [_turn(first, (second[0][c], second[1][c], second[2][c])) for c in range(3)]
    return (
        (columns[0][0], columns[1][0], columns[2][0]),
        (columns[0][1], columns[1][1], columns[2][1]),
        (columns[0][2], columns[1][2], columns[2][2]),
    )


def _unit(vector: Vector) -> Vector:
    size = math.sqrt(sum(v * v for v in vector))
    return (0.0, 0.0, 0.0) if size == 0 else (vector[0] / size, vector[1] / size, vector[2] / size)


def cosine(one: Vector, other: Vector) -> float:
    """How nearly the two axes lie along one line: the cosine of the angle between them, either
    way round (1 along one line, 0 square)."""
    return abs(dot(_unit(one), _unit(other)))


def principal_axes(matrix: _Matrix) -> list[tuple[float, Vector]]:
    """A symmetric matrix's eigenvalues and unit eigenvectors, least value first (Jacobi's
    rotations, a bounded number of sweeps: an inertia tensor's principal moments and axes)."""
    a = [list(row) for row in matrix]
    v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    for _ in range(_JACOBI_SWEEPS):
        p, q = max(((0, 1), (0, 2), (1, 2)), key=lambda pq: abs(a[pq[0]][pq[1]]))
        if abs(a[p][q]) <= 1e-12 * (abs(a[p][p]) + abs(a[q][q])):
            break
        theta = 0.5 * math.atan2(2 * a[p][q], a[q][q] - a[p][p])
        c, s = math.cos(theta), math.sin(theta)
        for k in range(3):  # columns p and q turned, then rows: A <- G^T A G
            a[k][p], a[k][q] = c * a[k][p] - s * a[k][q], s * a[k][p] + c * a[k][q]
        for k in range(3):
            a[p][k], a[q][k] = c * a[p][k] - s * a[q][k], s * a[p][k] + c * a[q][k]
        for k in range(3):
            v[k][p], v[k][q] = c * v[k][p] - s * v[k][q], s * v[k][p] + c * v[k][q]
    found = [(a[i][i], (v[0][i], v[1][i], v[2][i])) for i in range(3)]
    return sorted(found, key=lambda pair: pair[0])


# Jacobi's rotations on a 3 x 3 matrix converge in a few sweeps; more is no matter of accuracy.
_JACOBI_SWEEPS = 50


def parallel(one: Vector, other: Vector) -> bool:
    """The two axes lie along one line (either way round)."""
    return cosine(one, other) >= _PARALLEL


def same_way(one: Vector, other: Vector) -> bool:
    """The two directions point one way (parallel, not opposed)."""
    return parallel(one, other) and dot(one, other) > 0


def perpendicular(one: Vector, other: Vector) -> bool:
    """The two axes are square to each other."""
    return cosine(one, other) <= _PERPENDICULAR


def dot(one: Vector, other: Vector) -> float:
    """The dot product of two vectors."""
    return one[0] * other[0] + one[1] * other[1] + one[2] * other[2]


def cross(one: Vector, other: Vector) -> Vector:
    """The cross product of two vectors (square to both, as long as the area they span)."""
    return (
        one[1] * other[2] - one[2] * other[1],
        one[2] * other[0] - one[0] * other[2],
        one[0] * other[1] - one[1] * other[0],
    )


def off_axis(vector: Vector, axis: Vector) -> float:
    """How far ``vector`` reaches square to the unit ``axis`` (its length less its part along
    it): a point's distance from the line along ``axis`` through where ``vector`` starts."""
    along = dot(vector, axis)
    return math.sqrt(max(dot(vector, vector) - along * along, 0.0))


def minus(one: Vector, other: Vector) -> Vector:
    """``one`` less ``other``: the way from ``other`` to ``one``."""
    return (one[0] - other[0], one[1] - other[1], one[2] - other[2])


def centroid(places: list[Vector]) -> Vector:
    """The mean of ``places`` (at least one)."""
    count = len(places)
    return (
        sum(p[0] for p in places) / count,
        sum(p[1] for p in places) / count,
        sum(p[2] for p in places) / count,
    )


def spread(values: list[float]) -> float:
    """How far apart the farthest two of ``values`` (coordinates along one line) lie."""
    return max(values) - min(values)


def distance(one: Vector, other: Vector) -> float:
    """How far apart two places are; ``inf`` for places too far out to square (1e200)."""
    return math.dist(one, other)


# Places further out than this (metres) are no robot's: they stand in no grid cell.
_FAR = 1e6
# The grid cells around one, itself among them (offsets along x, y and z).
CELLS_AROUND = tuple((dx, dy, dz) for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1))


def grid_cell(place: Vector, size: float) -> tuple[int, int, int] | None:
    """The cell of a grid of cubes of side ``size`` that ``place`` stands in: places within
    ``size`` of it stand in it or in the cells :data:`CELLS_AROUND` it, so near places are
    found by looking there, not by comparing every two. None for a place too far out (or no
    number): it is near nothing."""
    if not all(math.isfinite(c) and abs(c) < _FAR for c in place):
        return None
    x, y, z = (math.floor(c / size) for c in place)
    return x, y, z


# Distinct places compared two by two at most (half a million pairs): past that, where the box
# around them settles nothing, they are taken as too many to lie that close (a hostile
# description's thousands of parts must not cost a square of their number).
_PAIRWISE_LIMIT = 1000


def within(places: list[Vector], reach: float) -> bool:
    """Whether every two of ``places`` lie within ``reach`` of each other. The box around them
    settles it at once where it is as small (all within) or one side is longer (not all);
    otherwise the distinct places are compared two by two (at most :data:`_PAIRWISE_LIMIT`;
    more are not all within). A place not finite is within reach of none, itself included."""
    if len(places) < 2:
        return True
    if not all(math.isfinite(c) for place in places for c in place):
        return False  # a place too far out (or no number) is within reach of no other
    distinct = list(set(places))
    if len(distinct) < 2:
        return True
    sides = [max(p[i] for p in distinct) - min(p[i] for p in distinct) for i in range(3)]
    if any(side > reach for side in sides):
        return False
    if math.hypot(*sides) <= reach:
        return True
    if len(distinct) > _PAIRWISE_LIMIT:
        return False
    return all(distance(a, b) <= reach for a, b in combinations(distinct, 2))


class Poses:
    """Each link's place and turn in the root's frame, every joint at rest (zero)."""

    def __init__(self, urdf: Urdf) -> None:
        self.urdf = urdf
        self._frames: dict[str, tuple[_Matrix, Vector]] = {urdf.root: (_IDENTITY, (0.0, 0.0, 0.0))}
        stack = [urdf.root]
        while stack:
            link = stack.pop()
            turn, place = self._frames[link]
            for joint in urdf.children(link):
                if joint.child in self._frames:
                    continue
                offset = _turn(turn, joint.origin)
                child_place = (place[0] + offset[0], place[1] + offset[1], place[2] + offset[2])
                self._frames[joint.child] = (_compose(turn, _rotation(joint.rpy)), child_place)
                stack.append(joint.child)

    def place(self, link: str) -> Vector:
        """Where ``link``'s frame is, in the root's frame (the root's place for a link it lacks)."""
        return self._frames.get(link, (_IDENTITY, (0.0, 0.0, 0.0)))[1]

    def seen_from(self, link: str, place: Vector) -> Vector:
        """``place`` (in the root's frame) written in ``link``'s frame."""
        return _turn(self._back(link), minus(place, self.place(link)))

    def _back(self, link: str) -> _Matrix:
        """The turn from the root's frame into ``link``'s: its frame's turn's inverse, which is
        its transpose."""
        turn = self._frames.get(link, (_IDENTITY, (0.0, 0.0, 0.0)))[0]
        return (
            (turn[0][0], turn[1][0], turn[2][0]),
            (turn[0][1], turn[1][1], turn[2][1]),
            (turn[0][2], turn[1][2], turn[2][2]),
        )

    def turned(self, link: str, rpy: Vector, vector: Vector) -> Vector:
        """``vector``, written in a frame turned by ``rpy`` on ``link`` (a visual's), in the
        root's frame."""
        turn = self._frames.get(link, (_IDENTITY, (0.0, 0.0, 0.0)))[0]
        return _turn(_compose(turn, _rotation(rpy)), vector)

    def extent(self, link: str, rpy: Vector, size: Vector) -> Vector:
        """How far a box of ``size`` (along its own x, y and z), turned by ``rpy`` on ``link``,
        reaches along the root's x, y and z, end to end."""
        sides: tuple[Vector, ...] = ((size[0], 0.0, 0.0), (0.0, size[1], 0.0), (0.0, 0.0, size[2]))
        edges = [self.turned(link, rpy, side) for side in sides]
        x, y, z = (sum(abs(edge[k]) for edge in edges) for k in range(3))
        return (x, y, z)

    def long_axis(self, link: str) -> Vector | None:
        """The direction, in the root's frame, along which ``link``'s inertia says it is long
        (a rod's, a boom's): the principal axis of its least moment, when that moment is at
        most a :data:`_SLENDER` part of the next; None for a plate, a block or a ball, a link
        whose inertia is not written, or one no body has (a principal moment of 0 or less, or
        terms too large to turn)."""
        found = self.urdf.link(link)
        if found is None or found.inertia is None:
            return None
        xx, xy, xz, yy, yz, zz = found.inertia.terms
        axes = principal_axes(((xx, xy, xz), (xy, yy, yz), (xz, yz, zz)))
        (least, along), (next_least, _) = axes[0], axes[1]
        if not (0 < least <= _SLENDER * next_least) or not all(map(math.isfinite, along)):
            return None  # a plate, a block or a ball; or no body's inertia (a moment of 0 or less)
        return self.turned(link, found.inertia.rpy, along)

    def mass_centre(self, link: str) -> Vector | None:
        """Where ``link``'s mass centre is (its first ``<inertial>``'s origin), in the root's
        frame; None when its inertial says no place."""
        found = self.urdf.link(link)
        if found is None or found.mass_centre is None:
            return None
        offset = self.turned(link, (0.0, 0.0, 0.0), found.mass_centre)
        place = self.place(link)
        return (place[0] + offset[0], place[1] + offset[1], place[2] + offset[2])

    def facing(self, link: str) -> Vector:
        """Where ``link``'s x axis points, in the root's frame (a camera's view, when its
        sensor is not turned on the link)."""
        return self.turned(link, (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))

    def axis(self, joint: Joint) -> Vector:
        """The joint's axis, written in the root's frame."""
        turn = self._frames.get(joint.child, (_IDENTITY, (0.0, 0.0, 0.0)))[0]
        return _unit(_turn(turn, joint.axis))

    def local_axis(self, joint: Joint) -> Vector:
        """The joint's axis written in its parent link's frame (turned by its ``rpy``)."""
        return local_axis(joint)

    def hung_from(self, link: str, joint: Joint) -> Joint:
        """``joint`` as if it hung from ``link`` (a link its parent is fixed below): its place
        and its axis written in ``link``'s frame, as two joints on one link are compared."""
        origin = self.seen_from(link, self.place(joint.child))
        axis = _turn(self._back(link), self.axis(joint))
        return replace(joint, parent=link, origin=origin, rpy=(0.0, 0.0, 0.0), axis=axis)


def local_axis(joint: Joint) -> Vector:
    """The joint's axis written in its parent link's frame (turned by its ``rpy``): what two
    joints on one link are compared by, with no walk of the tree."""
    return _unit(_turn(_rotation(joint.rpy), joint.axis))
