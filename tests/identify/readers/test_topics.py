"""Topic list files in the formats rostopic and ros2 print."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from solver.errors import InputError
from solver.identify.readers.topics import parse_topic_list, read_topic_list
from solver.ros.names import Topic, normalise_type

ROSTOPIC_V = """\
Published topics:
 * /scan [sensor_msgs/LaserScan] 1 publisher
 * /camera/rgb/image_raw [sensor_msgs/Image] 1 publisher

Subscribed topics:
 * /cmd_vel [geometry_msgs/Twist] 2 subscribers
"""


def test_rostopic_list_v_sections_give_directions() -> None:
    assert parse_topic_list(ROSTOPIC_V) == (
        Topic("/scan", "sensor_msgs/LaserScan", "published"),
        Topic("/camera/rgb/image_raw", "sensor_msgs/Image", "published"),
        Topic("/cmd_vel", "geometry_msgs/Twist", "subscribed"),
    )


def test_ros2_topic_list_t_is_normalised_to_ros1_spelling() -> None:
    text = (
        "/scan [sensor_msgs/msg/LaserScan]\n/parameter_events [rcl_interfaces/msg/ParameterEvent]\n"
    )
    assert parse_topic_list(text)[0] == Topic("/scan", "sensor_msgs/LaserScan")


def test_topic_and_type_pairs_and_comments_are_read() -> None:
    text = "# rostopic list + rostopic type\n/imu/data sensor_msgs/Imu\n\n/odom nav_msgs/Odometry\n"
    assert [t.type for t in parse_topic_list(text)] == ["sensor_msgs/Imu", "nav_msgs/Odometry"]


def test_every_bad_line_is_reported_with_its_line_number() -> None:
    text = "/scan\n/ok sensor_msgs/Imu\n/x not-a-type!\n!!! what\n"
    with pytest.raises(InputError) as caught:
        parse_topic_list(text, "t.txt")
    lines = [(f.location.line, f.message.split(" ")[0]) for f in caught.value.faults]
    assert [line for line, _ in lines] == [1, 3, 4]
    assert "has no message type" in caught.value.faults[0].message


def test_an_empty_or_binary_file_is_refused(tmp_path: Path) -> None:
    (tmp_path / "e.txt").write_text("# nothing\n")
    with pytest.raises(InputError, match="no topics"):
        read_topic_list(tmp_path / "e.txt")
    (tmp_path / "b.txt").write_bytes(b"\xff\xfe\x00")
    with pytest.raises(InputError, match="binary file, not a topic list"):
        read_topic_list(tmp_path / "b.txt")


names = st.from_regex(r"/[a-z][a-z0-9_]{0,8}(/[a-z][a-z0-9_]{0,8}){0,3}", fullmatch=True)
types = st.from_regex(r"[a-z][a-z_]{0,8}_msgs/[A-Z][A-Za-z0-9]{0,10}", fullmatch=True)


@given(
    st.lists(st.tuples(names, types), min_size=1, max_size=20),
    st.sampled_from(["{n} [{t}]", "{n} {t}", " * {n} [{t}] 1 publisher"]),
)
def test_any_list_of_pairs_reads_back_in_every_format(
    pairs: list[tuple[str, str]], line: str
) -> None:
    text = "\n".join(line.format(n=n, t=t) for n, t in pairs)
    assert [(t.name, t.type) for t in parse_topic_list(text)] == pairs


@given(types)
def test_normalising_a_type_is_idempotent_and_accepts_ros2_spelling(kind: str) -> None:
    package, name = kind.split("/")
    assert normalise_type(f"{package}/msg/{name}") == kind == normalise_type(kind)


# What a secret looks like when it is given, by mistake or by a link, as a topic list.
SECRETS = {
    "shadow": "root:$6$hunter2hash:19000:0:99999:7:::\nalice:$6$hunter2too:19000:0::::\n",
    "dotenv": "# settings\nAPI_TOKEN=hunter2\n",
    "one word": "hunter2\n",
    "private key": "-----BEGIN OPENSSH PRIVATE KEY-----\nhunter2AAAAB3NzaC1yc2E\n",
    "two words": "hunter2 sesame/Open\n",
}


@pytest.mark.parametrize("secret", list(SECRETS))
def test_a_file_that_is_no_topic_list_is_named_and_never_quoted(secret: str) -> None:
    with pytest.raises(InputError) as caught:
        parse_topic_list(SECRETS[secret], "secret.txt")
    assert len(caught.value.faults) == 1
    line = 2 if secret == "dotenv" else 1  # the first line that is not a comment
    assert str(caught.value).startswith(f"secret.txt:{line}: not a topic list: ")
    assert "hunter2" not in str(caught.value)


def test_a_bad_line_of_a_topic_list_is_quoted_short_and_escaped() -> None:
    text = "/scan sensor_msgs/LaserScan\n" + "!\x1b[2J" + "x" * 200 + "\n"
    with pytest.raises(InputError) as caught:
        parse_topic_list(text, "t.txt")
    message = caught.value.faults[0].message
    assert message.startswith("not a topic line: '!\\x1b[2Jxxx")
    assert message.endswith("...' (cut from 205 characters)")
    assert "\x1b" not in message
    # 60 characters shown: "!", ESC, "[2J" and 55 x, plus the x of the escape "\\x1b".
    assert message.count("x") == 55 + 1


def test_a_topic_list_may_start_with_a_section_a_bullet_or_a_name_without_type() -> None:
    assert parse_topic_list("Published topics:\n * /scan [sensor_msgs/LaserScan] 1 publisher\n")
    assert parse_topic_list(" * /scan [sensor_msgs/LaserScan] 1 publisher\n")
    with pytest.raises(InputError, match="topic '/scan' has no message type"):
        parse_topic_list("/scan\n")
