"""A stranger's string as human-readable output shows it: escaped, cut short, marked as cut."""

from __future__ import annotations

import sys
import unicodedata

import pytest

from solver.untrusted import SHOWN_CHARS, shown

# One of each kind the security issues name, with the escape a reader sees instead.
HOSTILE = {
    "\n": "\\n",
    "\r": "\\r",
    "\t": "\\t",
    "\x00": "\\x00",
    "\x1b": "\\x1b",
    "\x7f": "\\x7f",
    "\x85": "\\x85",  # NEL, a C1 control some terminals take as a line break
    "\x9b": "\\x9b",  # CSI, a one-character escape sequence start
    "\u00ad": "\\xad",  # soft hyphen, invisible
    "\u061c": "\\u061c",  # Arabic letter mark, a bidi control
    "\u200d": "\\u200d",  # zero-width joiner
    "\u2028": "\\u2028",  # line separator
    "\u2029": "\\u2029",  # paragraph separator
    "\u202e": "\\u202e",  # right-to-left override
    "\u2066": "\\u2066",  # left-to-right isolate
    "\ufeff": "\\ufeff",  # byte-order mark
    "\U000e0041": "\\U000e0041",  # tag letter A
    "\U000e007f": "\\U000e007f",  # cancel tag
    "\ud800": "\\ud800",  # an unpaired surrogate (from surrogateescape)
}


@pytest.mark.parametrize(("char", "escape"), HOSTILE.items())
def test_each_hostile_character_is_shown_as_its_escape(char: str, escape: str) -> None:
    assert shown(f"a{char}b") == f"a{escape}b"


def test_a_newline_in_a_name_cannot_start_a_forged_line() -> None:
    text = shown("robot\nERROR: core meltdown")
    assert text == "robot\\nERROR: core meltdown"
    assert len(text.splitlines()) == 1


def test_every_format_character_of_unicode_is_escaped() -> None:
    # Category Cf in the interpreter's own Unicode database, and every line-breaking
    # character str.splitlines knows: none survives.
    format_chars = [
        chr(code)
        for code in range(sys.maxunicode + 1)
        if unicodedata.category(chr(code)) in ("Cf", "Cc", "Zl", "Zp")
    ]
    assert len(format_chars) > 200
    text = shown("".join(format_chars), limit=None)
    assert text.isprintable()
    assert text.isascii()
    assert len(text.splitlines()) == 1


def test_printable_names_in_any_script_are_left_as_they_are() -> None:
    for name in ("UAV", "Bézier arm", "ロボット", "робот", "\\input{x}", "a $b$ c"):
        assert shown(name) == name


def test_a_long_value_is_cut_with_a_mark_that_says_how_long_it_was() -> None:
    text = shown("v" * 9_000_000)
    assert text == "v" * SHOWN_CHARS + "... (cut from 9,000,000 characters)"


def test_a_value_at_the_limit_is_not_cut() -> None:
    assert shown("v" * SHOWN_CHARS) == "v" * SHOWN_CHARS


def test_the_limit_counts_characters_before_escaping() -> None:
    text = shown("\x1b" * 100)
    assert text == "\\x1b" * SHOWN_CHARS + "... (cut from 100 characters)"


def test_no_limit_shows_the_whole_value_escaped() -> None:
    assert shown("w\n" * 100, limit=None) == "w\\n" * 100


def test_quoted_values_cannot_end_their_quote_early() -> None:
    assert shown("it's", quoted=True) == '"it\'s"'
    assert shown("a'\"b", quoted=True) == "'a\\'\"b'"
    assert shown("a\nb", quoted=True) == "'a\\nb'"
    assert shown("q" * 61, quoted=True) == "'" + "q" * 60 + "...' (cut from 61 characters)"


def test_a_huge_list_is_shown_by_its_first_items_and_its_length() -> None:
    assert shown(list(range(100_000))) == "[0, 1, 2, 3, 4, 5, ...] (cut from 100,000 items)"


def test_a_deep_list_is_shown_without_recursing_into_it() -> None:
    deep: list[object] = []
    for _ in range(100_000):
        deep = [deep]
    assert shown(deep) == "[[[[...]]]]"


def test_strings_inside_a_list_are_escaped() -> None:
    text = shown(["a\nb", "\u202e"])
    assert text == "['a\\nb', '\\u202e']"


def test_a_number_too_long_to_print_is_described() -> None:
    assert shown(10**5000) == "a whole number of about 5,001 digits"
    assert shown(-(10**70)) == "-1" + "0" * 58 + "... (cut from 72 characters)"


# ---- printable but invisible (issue 36.14a) ----------------------------------------------------
# str.isprintable accepts these: letters, marks and a symbol that a terminal draws as nothing
# (or as a blank), so a name holding them looks like another name, or like none. Unicode's
# Default_Ignorable_Code_Point property lists the letters and marks (the rest of it is format
# characters and unassigned code points, escaped already); the braille blank and the musical
# null notehead are symbols drawn empty.
INVISIBLE_PRINTABLE = {
    "\u115f": "\\u115f",  # Hangul choseong filler
    "\u1160": "\\u1160",  # Hangul jungseong filler
    "\u3164": "\\u3164",  # Hangul filler
    "\uffa0": "\\uffa0",  # halfwidth Hangul filler
    "\u034f": "\\u034f",  # combining grapheme joiner
    "\u17b4": "\\u17b4",  # Khmer vowel inherent aq
    "\u17b5": "\\u17b5",  # Khmer vowel inherent aa
    "\u180b": "\\u180b",  # Mongolian free variation selector one
    "\u180f": "\\u180f",  # Mongolian free variation selector four
    "\ufe00": "\\ufe00",  # variation selector 1
    "\ufe0f": "\\ufe0f",  # variation selector 16
    "\U000e0100": "\\U000e0100",  # variation selector 17 (hides bytes after a letter)
    "\U000e01ef": "\\U000e01ef",  # variation selector 256
    "\u2800": "\\u2800",  # braille pattern blank
    "\U0001d159": "\\U0001d159",  # musical symbol null notehead
}


@pytest.mark.parametrize(("char", "escape"), INVISIBLE_PRINTABLE.items())
def test_a_printable_character_drawn_as_nothing_is_shown_as_its_escape(
    char: str, escape: str
) -> None:
    assert char.isprintable()  # what str.isprintable lets through...
    assert shown(f"a{char}b") == f"a{escape}b"  # ...is escaped all the same
    assert shown(char * 3, quoted=True) == f"'{escape * 3}'"


def test_the_spaces_unicode_calls_separators_were_escaped_already() -> None:
    # U+3000 (ideographic space) and U+180E (Mongolian vowel separator, a format character
    # since Unicode 6.3) are not printable to Python: escaped before this issue, and still.
    assert shown("a\u3000b\u180ec\u00a0d") == "a\\u3000b\\u180ec\\xa0d"


def test_visible_letters_and_marks_of_every_script_are_left_as_they_are() -> None:
    for name in ("로봇", "ㄱ", "e\u0301", "ក៏", "ᠮᠣᠩᠭᠣᠯ", "⠁⠃", "\U0001d15d"):
        assert shown(name) == name
