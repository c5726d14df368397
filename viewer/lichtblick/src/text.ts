// A stranger's string as the follower shows it: the robot names and values of an answer come
// from the ROS graph, which any participant can write to (docs/live.md). The follower puts text
// on screen only through `textContent` (never as HTML), and only through `shown`, the same rules
// as teleop-ui's own `solver.untrusted.shown`:
//
// - every control, line break, format character (bidirectional overrides, zero-width joiners,
//   the soft hyphen, tag characters), space other than U+0020, surrogate, private-use and
//   unassigned code point is written as an escape (`\n`, `\x1b`, `\u202e`), so a name cannot
//   forge a line, reorder what a line appears to say, or hide characters;
// - so is every character a screen draws as nothing (Unicode's default-ignorable letters and
//   marks: Hangul fillers, variation selectors, the combining grapheme joiner; the braille blank);
// - at most `limit` characters (60 by default) are shown; a longer value ends with a mark that
//   says how long it was: `xxx... (cut from 9,000 characters)`.

/** How many characters of a stranger's string are shown, as teleop-ui's own output does. */
export const SHOWN_CHARS = 60;

const ESCAPED = /[\p{Cc}\p{Cf}\p{Zl}\p{Zp}\p{Zs}\p{Co}\p{Cn}\p{Cs}]/u;
const INVISIBLE = new RegExp(
  "[\\u034f\\u115f\\u1160\\u17b4\\u17b5\\u180b-\\u180d\\u180f\\u2800\\u3164" +
    "\\ufe00-\\ufe0f\\uffa0\\u{1d159}\\u{e0100}-\\u{e01ef}]",
  "u",
);
const NAMED: Readonly<Record<string, string>> = { "\n": "\\n", "\r": "\\r", "\t": "\\t" };

function escaped(char: string): string {
  const named = NAMED[char];
  if (named !== undefined) {
    return named;
  }
  const code = char.codePointAt(0) ?? 0;
  if (code < 0x100) {
    return `\\x${code.toString(16).padStart(2, "0")}`;
  }
  if (code < 0x10000) {
    return `\\u${code.toString(16).padStart(4, "0")}`;
  }
  return `\\U${code.toString(16).padStart(8, "0")}`;
}

/** `value` as the follower may show it: escaped where it must be, cut to `limit` characters
 * (code points; `null`: not cut, for a path or address an operator must copy) with a mark that
 * says so. */
export function shown(value: string, limit: number | null = SHOWN_CHARS): string {
  let out = "";
  let count = 0;
  for (const char of value) {
    if (limit !== null && count === limit) {
      const total = [...value].length.toLocaleString("en-US");
      return `${out}... (cut from ${total} characters)`;
    }
    out += char !== " " && (ESCAPED.test(char) || INVISIBLE.test(char)) ? escaped(char) : char;
    count += 1;
  }
  return out;
}
