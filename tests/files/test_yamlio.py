"""Safe YAML loading: positions for every value, and hostile or broken files refused cleanly."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from solver.errors import InputError
from solver.files.yamlio import load_document, load_hashed, parse_document, prescan
from tests.conftest import holds_alone, run_cli


def test_values_and_keys_are_located_by_line_and_column() -> None:
    document = parse_document("team:\n  UAV:\n    sensor_type: [2D Camera, Mic]\n", "t.yaml")
    location = document.location(("team", "UAV", "sensor_type", 1))
    assert (location.line, location.column, location.path) == (3, 30, "team.UAV.sensor_type[1]")
    assert document.location(("team", "UAV"), key=True).line == 2


def test_a_missing_path_is_located_at_its_nearest_ancestor() -> None:
    document = parse_document("team:\n  UAV: {}\n", "t.yaml")
    assert document.location(("team", "UAV", "sensor_count")).line == 2


def test_duplicate_keys_are_refused_with_both_lines() -> None:
    with pytest.raises(InputError) as caught:
        parse_document("team:\n  UAV: 1\n  UAV: 2\n", "t.yaml")
    assert str(caught.value) == "t.yaml:3:3: team.UAV: duplicate key 'UAV' (first at line 2)"


def test_syntax_errors_name_line_and_column() -> None:
    with pytest.raises(InputError) as caught:
        parse_document("team: [unclosed\n  UAV: 1\n", "t.yaml")
    fault = caught.value.faults[0]
    assert (fault.location.line, fault.location.column) == (2, 6)
    assert "YAML syntax error" in fault.message


def test_python_object_tags_are_refused_without_being_constructed() -> None:
    with pytest.raises(InputError, match="unsupported YAML tag"):
        parse_document('team: !!python/object/apply:os.system ["echo pwned"]\n', "t.yaml")


def test_an_alias_bomb_is_refused_before_it_expands() -> None:
    lines = ['a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]']
    for previous, name in zip("abcdefgh", "bcdefghi", strict=True):
        lines.append(f"{name}: &{name} [" + ",".join([f"*{previous}"] * 9) + "]")
    with pytest.raises(InputError, match="alias bomb"):
        parse_document("\n".join(lines) + "\n", "bomb.yaml")


def test_a_recursive_alias_is_refused() -> None:
    with pytest.raises(InputError, match="recursive alias"):
        parse_document("a: &a [1, *a]\n", "loop.yaml")


def test_merge_keys_are_refused_with_advice() -> None:
    with pytest.raises(InputError, match="merge keys"):
        parse_document("base: &b {x: 1}\nother:\n  <<: *b\n", "merge.yaml")


def test_binary_files_are_not_yaml(tmp_path: Path) -> None:
    path = tmp_path / "image.yaml"
    path.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00")
    with pytest.raises(InputError, match="contains NUL bytes: a binary file, not a YAML file"):
        load_document(path)


def test_text_in_another_encoding_is_named_as_not_utf8(tmp_path: Path) -> None:
    path = tmp_path / "latin1.yaml"
    path.write_bytes("name: Düsseldorf\n".encode("latin-1"))
    with pytest.raises(InputError, match="not UTF-8 text"):
        load_document(path)


def test_endless_special_files_are_refused_without_being_read() -> None:
    with pytest.raises(InputError, match="is a character device, not a YAML file"):
        load_document("/dev/zero")


def test_deep_nesting_is_refused_without_a_traceback() -> None:
    with pytest.raises(InputError, match="nested more than 64 levels deep"):
        parse_document("team: " + "[" * 100 + "]" * 100 + "\n", "deep.yaml")
    with pytest.raises(InputError, match="nested more than 64 levels deep"):
        parse_document("team: " + "[" * 5000 + "]" * 5000 + "\n", "deeper.yaml")


def test_64_levels_are_read_and_the_65th_is_refused_at_its_bracket() -> None:
    # 65 brackets: the innermost list is at depth 64, the deepest allowed.
    assert parse_document("[" * 65 + "]" * 65).data is not None
    with pytest.raises(InputError) as caught:
        parse_document("[" * 66 + "]" * 66, "deep.yaml")
    assert str(caught.value) == "deep.yaml:1:66: nested more than 64 levels deep; refused"


def test_a_block_nest_of_50000_levels_is_refused_at_its_entry_not_a_crash(tmp_path: Path) -> None:
    # In a process of its own: composing this ended the process with SIGSEGV.
    path = tmp_path / "deep.yaml"
    path.write_text("- " * 50_000 + "x")
    result = run_cli("check", path)
    assert result.returncode == 2, result.stderr
    # The 66th "- " opens the 66th sequence, at column 2 * 65 + 1.
    assert result.stderr == f"{path}:1:131: nested more than 64 levels deep; refused\n"


@pytest.mark.parametrize(
    "text",
    [
        "[" * 1_000_000,
        "{a: " * 500_000,
        "- " * 1_000_000,
        "".join(f"{' ' * (2 * level)}k{level}:\n" for level in range(2_000)),
        "".join(f"{' ' * level}- \n" for level in range(2_000)),
    ],
    ids=["flow sequences", "flow mappings", "block sequences", "block mappings", "indented"],
)
def test_deep_text_is_refused_at_the_first_level_too_deep(text: str) -> None:
    with pytest.raises(InputError, match="nested more than 64 levels deep; refused"):
        parse_document(text + "\n", "deep.yaml")


def test_the_prescan_stops_at_the_first_level_too_deep_before_reading_on() -> None:
    # The syntax error after the 100 brackets is never reached: the pre-scan stops at the 66th.
    with pytest.raises(InputError) as caught:
        prescan("[" * 100 + "}" * 100, "deep.yaml")
    assert str(caught.value) == "deep.yaml:1:66: nested more than 64 levels deep; refused"


@pytest.mark.parametrize(
    "text",
    [
        "[" * 1500 + "]" * 1500,
        "[" * 100 + "}" * 100,
        "- " * 70 + "x",
        "[" * 66 + "&a x, *a" + "]" * 66,
    ],
    ids=["past libyaml's own cap", "a syntax error after", "block", "an alias inside"],
)
def test_a_short_text_composed_before_its_prescan_is_refused_as_the_prescan_refuses(
    text: str,
) -> None:
    with pytest.raises(InputError) as caught:
        prescan(text, "deep.yaml")
    with pytest.raises(InputError) as read:
        parse_document(text, "deep.yaml")
    assert str(read.value) == str(caught.value)
    assert "nested more than 64 levels deep; refused" in str(read.value)


def test_the_prescan_reports_a_syntax_error_it_meets_first() -> None:
    with pytest.raises(InputError) as caught:
        prescan("a: [1, 2}\n", "broken.yaml")
    assert str(caught.value).startswith("broken.yaml:1:9: YAML syntax error")


def test_the_prescan_accepts_what_the_reader_reads() -> None:
    prescan("team:\n  UAV:\n    sensor_type: [2D Camera, Mic]\n", "t.yaml")


def test_keys_that_read_alike_are_duplicates() -> None:
    with pytest.raises(InputError, match="duplicate key '1'"):
        parse_document("team:\n  1: a\n  '1': b\n", "t.yaml")


def test_missing_files_and_directories_are_named(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="no such file"):
        load_document(tmp_path / "absent.yaml")
    with pytest.raises(InputError, match="is a directory"):
        load_document(tmp_path)


def test_oversized_files_are_refused_without_reading_them(tmp_path: Path) -> None:
    path = tmp_path / "huge.yaml"
    with path.open("wb") as stream:
        stream.truncate(17 * 1024 * 1024)
    with pytest.raises(InputError, match="larger than 16777216 bytes; refused"):
        load_document(path)


def test_timestamps_stay_text_instead_of_becoming_dates() -> None:
    assert parse_document("published: 2017-03-15\n").data == {"published": "2017-03-15"}


SCALARS = ["7", "007", "0x1F", "0o17", "1_000", "+5", "-3", "0", "1:30", "3.5", "1e3", "true"]
SCALARS += ["null", "~", "text", "'12'", '"12"', "999999999999999999", "2001-12-14"]


@pytest.mark.parametrize("scalar", SCALARS)
def test_scalars_read_as_pyyaml_reads_them(scalar: str) -> None:
    data = parse_document(f"value: {scalar}\n").data
    expected = yaml.safe_load(f"value: {scalar}\n")["value"]
    if scalar == "2001-12-14":
        expected = scalar  # dates stay text (see the test above)
    assert data == {"value": expected}
    assert type(data["value"]) is type(expected)


def test_reading_leaves_the_cycle_collector_as_it_was() -> None:
    # In an interpreter of its own: the collector's switch is one per process.
    holds_alone(
        """
        import gc
        import pytest
        from solver.errors import InputError
        from solver.files.yamlio import parse_document

        parse_document("a: [1, 2]\\n")
        assert gc.isenabled()
        with pytest.raises(InputError):
            parse_document("a: [1, 2\\n")
        assert gc.isenabled()
        gc.disable()
        parse_document("a: [1, 2]\\n")
        assert not gc.isenabled()
        """
    )


def test_a_file_loaded_with_its_hash_is_hashed_from_the_bytes_read(tmp_path: Path) -> None:
    import hashlib

    path = tmp_path / "team.yaml"
    path.write_bytes("\ufeffname: Équipe\nteam: {UGV: {}}\n".encode())
    document, digest = load_hashed(path, display="team.yaml")
    assert document == load_document(path, display="team.yaml")
    assert digest == hashlib.sha256(path.read_bytes()).hexdigest()
    for broken in (b"name: \x00", b"name: \xff"):
        path.write_bytes(broken)
        with pytest.raises(InputError) as loaded:
            load_document(path, display="team.yaml")
        with pytest.raises(InputError) as hashed:
            load_hashed(path, display="team.yaml")
        assert str(hashed.value) == str(loaded.value)


# ---- a file that reads as no kind of file is quoted nowhere (issue 36.13) ----------------------


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("the-secret-key:\nthe-secret-key:\n", "x:2:1: a key written twice (first at line 1)"),
        (
            "!the-secret-tag value\n",
            "x:1:1: unsupported YAML tag; only plain strings, numbers, booleans, lists and "
            "mappings are allowed",
        ),
        (
            "the-secret-name: !vault |\n  $ANSIBLE_VAULT;1.1;AES256\n",
            "x:1:18: unsupported YAML tag; only plain strings, numbers, booleans, lists and "
            "mappings are allowed",
        ),
        (
            "the-secret-key:\n  nested: 1\n  nested: 2\n",
            "x:3:3: a key written twice (first at line 2)",
        ),
    ],
    ids=["a key twice", "a tag", "an Ansible vault", "a nested key twice"],
)
def test_what_reads_as_no_kind_of_file_is_refused_at_its_line_quoting_nothing(
    text: str, message: str
) -> None:
    # No 'team:', 'characteristics:', ... at the top: the file may be anyone's secret, and
    # neither the faults nor their YAML paths (its keys) quote it.
    with pytest.raises(InputError) as caught:
        parse_document(text, "x")
    assert str(caught.value) == message


def test_a_file_of_a_kind_still_has_its_faults_quoted_with_their_paths() -> None:
    with pytest.raises(InputError) as caught:
        parse_document("team:\n  UAV: !odd 1\n", "t.yaml")
    assert str(caught.value) == (
        "t.yaml:2:8: team.UAV: unsupported YAML tag '!odd'; only plain strings, numbers, "
        "booleans, lists and mappings are allowed"
    )


@pytest.mark.parametrize(
    "text",
    ['name: "a\\0b"\n', 'name: "\\x00"\n', 'team:\n  "U\\0AV": {}\n', 'x: ["\\u0000"]\n'],
    ids=["\\0", "\\x00", "in a key", "\\u0000 in a list"],
)
def test_a_nul_written_as_an_escape_is_refused_at_its_line(text: str) -> None:
    # The documented limit: text holds no NUL. A NUL byte was refused, its escape was read.
    with pytest.raises(InputError) as caught:
        parse_document(text, "t.yaml")
    fault = caught.value.faults[0]
    assert fault.location.line == text.count("\n", 0, text.index("\\")) + 1
    assert fault.message == "contains a NUL character (\\0); not text"
