"""Where each part is at rest: links placed and joints' axes turned into the root's frame."""

from __future__ import annotations

import math

import pytest

from solver.identify import identify_urdf
from solver.identify.pose import (
    Poses,
    distance,
    parallel,
    perpendicular,
    principal_axes,
    spread,
    within,
)
from solver.identify.readers.urdf import parse_urdf
from tests.identify import builders
from tests.identify.builders import RobotText


def poses_of(robot: RobotText) -> Poses:
    urdf = parse_urdf(robot.text(), strict=False)
    return Poses(urdf)


def test_places_add_up_along_the_chain() -> None:
    poses = poses_of(builders.snake(3))
    assert poses.place("m3") == pytest.approx((0.3, 0.0, 0.0))


def test_an_axis_is_turned_by_every_turn_above_it() -> None:
    robot = RobotText("turned", root="a")
    # Turned 90 degrees about z, a joint about x turns about y in the root's frame.
    link = builders.placed(robot, "yaw", "fixed", "a", "b", rpy="0 0 1.5707963267948966")
    builders.placed(robot, "j", "revolute", link, "c", axis="1 0 0")
    urdf = parse_urdf(robot.text(), strict=False)
    joint = urdf.joint("j")
    assert joint is not None
    assert Poses(urdf).axis(joint) == pytest.approx((0.0, 1.0, 0.0), abs=1e-9)
    assert Poses(urdf).local_axis(joint) == pytest.approx((1.0, 0.0, 0.0))


def test_a_joint_hung_from_a_body_above_it_is_written_in_that_bodys_frame() -> None:
    # A palm 1 m out and turned a quarter about y; a plate 0.1 m out along the palm's x,
    # rolled a quarter; a hinge 0.05 m up the plate's z, yawed a quarter, about its own x.
    robot = RobotText("hung", root="base")
    quarter = math.pi / 2
    palm = builders.placed(robot, "p", "fixed", "base", "palm", xyz="1 0 0", rpy=f"0 {quarter} 0")
    plate = builders.placed(robot, "f", "fixed", palm, "plate", xyz="0.1 0 0", rpy=f"{quarter} 0 0")
    builders.placed(
        robot, "h", "revolute", plate, "jaw", xyz="0 0 0.05", rpy=f"0 0 {quarter}", axis="1 0 0"
    )
    urdf = parse_urdf(robot.text(), strict=False)
    joint = urdf.joint("h")
    assert joint is not None
    hung = Poses(urdf).hung_from("palm", joint)
    # The plate's roll takes its z to the palm's -y; the hinge's yaw takes x to y, the roll y to z.
    assert hung.parent == "palm"
    assert hung.origin == pytest.approx((0.1, -0.05, 0.0), abs=1e-9)
    assert hung.rpy == (0.0, 0.0, 0.0)
    assert hung.axis == pytest.approx((0.0, 0.0, 1.0), abs=1e-9)


def test_a_place_is_written_in_a_turned_links_frame() -> None:
    # A link 1 m up, turned a quarter about z: a place 1 m along the root's y beside it is 1 m
    # along the link's x, and its own origin is its frame's.
    robot = RobotText("seen", root="base")
    quarter = math.pi / 2
    builders.placed(robot, "t", "fixed", "base", "top", xyz="0 0 1", rpy=f"0 0 {quarter}")
    poses = poses_of(robot)
    assert poses.seen_from("top", (0.0, 1.0, 1.0)) == pytest.approx((1.0, 0.0, 0.0), abs=1e-9)
    assert poses.seen_from("top", poses.place("top")) == pytest.approx((0.0, 0.0, 0.0))


def test_roll_pitch_yaw_is_urdfs_fixed_axis_order() -> None:
    # Roll 90 then yaw 90 (about the fixed axes): x stays along the yawed x, z goes to x.
    robot = RobotText("rpy", root="a")
    builders.placed(robot, "j", "revolute", "a", "b", rpy="1.5707963267948966 0 1.5707963267948966")
    urdf = parse_urdf(robot.text(), strict=False)
    joint = urdf.joint("j")
    assert joint is not None
    assert Poses(urdf).axis(joint) == pytest.approx((1.0, 0.0, 0.0), abs=1e-9)


def test_axes_are_told_parallel_or_square() -> None:
    assert parallel((0, 0, 1), (0, 0, -2))
    assert perpendicular((0, 0, 1), (1, 0, 0))
    assert not parallel((1, 0, 0), (1, 1, 0))
    assert not perpendicular((1, 0, 0), (1, 1, 0))
    assert distance((0, 0, 0), (3, 4, 0)) == 5


def test_a_link_no_joint_reaches_sits_at_the_root() -> None:
    poses = poses_of(builders.snake(2))
    assert poses.place("nowhere") == (0.0, 0.0, 0.0)


def test_places_too_far_out_to_square_are_measured_not_an_error() -> None:
    # A stranger's origin of 1e200 m is a finite number the reader takes; squaring it overflows.
    assert distance((0.0, 0.0, 0.0), (0.0, 3e200, -4e200)) == pytest.approx(5e200)


def test_a_chain_hanging_from_an_origin_far_out_is_read_not_a_traceback() -> None:
    robot = RobotText("r", root="pelvis")
    for side, y in (("a", 0.1), ("b", -0.1)):
        link = builders.placed(
            robot, f"{side}0", "revolute", "pelvis", f"{side}l0", xyz=f"0 {y} -1e200"
        )
        builders.placed(robot, f"{side}1", "revolute", link, f"{side}l1", xyz="0 0 -1e200")
    assert identify_urdf(robot.text()).structure


def test_the_spread_of_values_is_how_far_apart_the_farthest_two_lie() -> None:
    assert spread([0.5, -0.25, 0.125]) == 0.75
    assert spread([3.0]) == 0.0


def test_places_within_reach_of_each_other_are_told_by_their_box_or_two_by_two() -> None:
    # A hundred parts at one place, or in a box whose diagonal is within reach: all within.
    assert within([(0.1, 0.2, 0.3)] * 100, 0.3)
    assert within([(0.0, 0.0, 0.0), (0.1, 0.1, 0.1), (0.2, 0.0, 0.1)], 0.3)
    # One side of the box longer than the reach: not all within.
    assert not within([(0.0, 0.0, 0.0), (0.31, 0.0, 0.0), (0.1, 0.0, 0.0)], 0.3)
    # Where the box settles nothing, each two are compared: the six ends of a ball's three
    # axes are each within its diameter of the others, but its box's diagonal is not.
    ends = [
        (s * 0.14 * (i == 0), s * 0.14 * (i == 1), s * 0.14 * (i == 2))
        for i in range(3)
        for s in (1, -1)
    ]
    assert math.hypot(0.28, 0.28, 0.28) > 0.3
    assert within(ends, 0.3)
    # A corner of the box added: that one is too far from the opposite end.
    assert not within([*ends, (0.14, 0.14, 0.14)], 0.3)
    assert within([], 0.3)
    # A place too far out to measure (or no number) is within reach of none, even its twin.
    far = (math.inf, 0.0, 0.0)
    assert not within([far, far], 0.3)
    assert not within([(math.nan, 0.0, 0.0), (0.0, 0.0, 0.0)], 0.3)
    assert within([far], 0.3)


def test_past_a_thousand_distinct_places_the_box_alone_tells_and_says_no_where_it_cannot() -> None:
    # Two by two, 1,885 places would be 1.8 million pairs: a hostile description's size.
    ring = [(0.14 * math.cos(k / 300), 0.14 * math.sin(k / 300), 0.0) for k in range(1885)]
    assert within(ring[:1000], 0.3)  # a ring within its own diameter, compared two by two
    assert not within(ring, 0.3)  # too many to compare: not taken as within


def test_a_symmetric_matrixs_principal_axes_come_least_first() -> None:
    # Along x + y and x - y, a coupling of 1 beside moments of 2 gives 3 and 1; z keeps 5.
    axes = principal_axes(((2.0, 1.0, 0.0), (1.0, 2.0, 0.0), (0.0, 0.0, 5.0)))
    assert [value for value, _ in axes] == pytest.approx([1.0, 3.0, 5.0])
    half = math.sqrt(0.5)
    assert parallel(axes[0][1], (half, -half, 0.0))
    assert parallel(axes[1][1], (half, half, 0.0))
    assert parallel(axes[2][1], (0.0, 0.0, 1.0))


def rod(inertia: str) -> Poses:
    """The poses of a base with one link whose inertial writes ``inertia``."""
    robot = RobotText("rod", root="base")
    builders.placed(robot, "j", "revolute", "base", "link", xyz="0 0 0.1")
    text = robot.text().replace(
        '<link name="link"/>',
        f'<link name="link"><inertial><mass value="1"/>{inertia}</inertial></link>',
    )
    return Poses(parse_urdf(text, strict=False))


@pytest.mark.parametrize(
    ("inertia", "expected"),
    [
        ('<inertia ixx="0.002" ixy="0" ixz="0" iyy="0.03" iyz="0" izz="0.03"/>', (1.0, 0, 0)),
        (
            '<origin rpy="0 0 1.5707963267948966"/>'
            '<inertia ixx="0.002" ixy="0" ixz="0" iyy="0.03" iyz="0" izz="0.03"/>',
            (0.0, 1.0, 0.0),
        ),
        ('<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.02"/>', None),
        ('<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>', None),
        ('<inertia ixx="1" ixy="5" ixz="0" iyy="1" iyz="0" izz="1"/>', None),
        (
            '<inertia ixx="1e308" ixy="1e308" ixz="1e308" iyy="1e308" iyz="-1e308" izz="1e308"/>',
            None,
        ),
        ("", None),
    ],
    ids=[
        "a rod along x",
        "the rod turned by its inertial",
        "a plate",
        "a ball",
        "no body's: a principal moment below 0",
        "no body's: terms too large to turn",
        "no inertia",
    ],
)
def test_a_link_is_long_along_its_least_moments_axis_when_it_is_a_rod(
    inertia: str, expected: tuple[float, float, float] | None
) -> None:
    found = rod(inertia).long_axis("link")
    if expected is None:
        assert found is None
    else:
        assert found is not None
        assert parallel(found, expected)
