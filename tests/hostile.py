"""What a stranger writes, for the hostile tests of every wing: byte strings that broke readers
before, random mutations of a valid file built from them, the text a stranger may put in a
name, and the hypothesis settings that keep such tests quick and repeatable.

The tests themselves live with what they try: mutated files given to every command in
``tests/cli/test_hostile_mutations.py``, mutated URDFs in ``tests/identify``, names drawn on
charts in ``tests/reporting/test_plot.py``.
"""

from __future__ import annotations

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

__all__ = ["FUZZ", "HOSTILE", "NAME_CHARS", "mutations"]

# Pieces that broke (or could break) a YAML or XML reader: NUL, invalid UTF-8, a lone surrogate
# in UTF-8, a number of 4,400 digits, aliases, tags, unbalanced brackets, escape sequences,
# document markers, an external entity, non-ASCII digits.
HOSTILE = [
    b"\x00",
    b"\xff",
    b"\xed\xb3\xbf",
    b"9" * 4400,
    b".inf",
    b"1e999",
    b"&a",
    b"*a",
    b"!!python/object:os.system",
    b"[",
    b"{",
    b"]",
    b"}",
    b": ",
    b"\n",
    b"- ",
    b"\t",
    b'"\\udcff"',
    b"\x1b[2J",
    b"'",
    b'"',
    b"<<: *a",
    b"---",
    b"...",
    b"? ",
    b"|",
    b"<!DOCTYPE r [<!ENTITY e SYSTEM 'file:///etc/passwd'>]>",
    b"&e;",
    b"<",
    b">",
    b"</link>",
    b"<link name=''/>",
    b"0x" + b"f" * 40,
    b"\xd9\xa3",
    b"~",
    b"-1",
    b"1.5",
]


@st.composite
def mutations(draw: st.DrawFn, original: bytes) -> bytes:
    """``original`` with one to four places replaced by a :data:`HOSTILE` piece or random bytes."""
    data = bytearray(original)
    for _ in range(draw(st.integers(1, 4))):
        start = draw(st.integers(0, len(data)))
        end = min(len(data), start + draw(st.integers(0, 12)))
        insert = draw(st.sampled_from(HOSTILE) | st.binary(max_size=8))
        data[start:end] = insert
    return bytes(data)


# Bounded numbers of examples, always the same ones: the suite stays quick and a failure repeats.
FUZZ = settings(
    max_examples=25,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)

# Text a stranger may put in a name: TeX and mathtext syntax, markup, line breaks, controls,
# bidi and format characters, astral characters.
NAME_CHARS = st.sampled_from(
    [*"$\\{}^_#%&~|[]()<>*`'\" \t\n\r", "\x1b", "\x85", "\u2028", "\u202e", "\u200d"]
) | st.characters(codec="utf-8")  # no lone surrogate: UTF-8 cannot hold one
