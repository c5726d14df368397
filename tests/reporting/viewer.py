"""What a reader sees of the pages the reports write: Markdown rendered as a viewer renders it
(CommonMark, tables, raw HTML passed through), and HTML taken apart into its tags, the
references a browser would load, its visible text and its table cells."""

from __future__ import annotations

from html.parser import HTMLParser

from markdown_it import MarkdownIt

__all__ = ["Cells", "Page", "parsed", "viewer"]


class Page(HTMLParser):
    """Collects what a page would make a browser load, and its visible text."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.references: list[tuple[str, str, str]] = []
        self.text: list[str] = []
        self.meta: list[dict[str, str | None]] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        if tag == "meta":
            self.meta.append(dict(attrs))
        for name, value in attrs:
            if name in ("src", "href", "srcset", "data", "action") and value is not None:
                self.references.append((tag, name, value))

    def handle_data(self, data: str) -> None:
        self.text.append(data)


def parsed(text: str) -> Page:
    """``text`` as a browser would take it apart."""
    found = Page()
    found.feed(text)
    found.close()
    return found


def viewer(text: str) -> str:
    """Markdown rendered as a viewer would: CommonMark, tables, raw HTML passed through."""
    rendered: str = (
        MarkdownIt("commonmark", {"html": True}).enable(["table", "strikethrough"]).render(text)
    )
    return rendered


class Cells(HTMLParser):
    """Collects the tags of a rendered table and the text of each of its cells."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.cells: list[str] = []
        self._cell: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:  # noqa: ARG002 (HTMLParser's signature)
        self.tags.append(tag)
        if tag in ("th", "td"):
            self._cell = []

    def handle_endtag(self, tag: str) -> None:
        if tag in ("th", "td") and self._cell is not None:
            self.cells.append("".join(self._cell))
            self._cell = None

    def handle_data(self, data: str) -> None:
        if self._cell is not None:
            self._cell.append(data)
