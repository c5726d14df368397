"""What a person sees of a page: a screenshot by Debian's headless Chromium, as painted colours.

Chromium runs with a fresh profile and without its background networking (this machine's
network is closed; it would otherwise retry connections at every start). Missing Chromium is a
failure, not a skip: tools/test.sh installs it.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

__all__ = ["painted_colours"]


def painted_colours(page: Path, scratch: Path, size: tuple[int, int]) -> set[tuple[int, ...]]:
    """The colours covering more than 500 pixels of ``page`` rendered at ``size`` (w, h)."""
    from PIL import Image

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        pytest.fail("needs Debian's chromium: tools/test.sh installs it")
    shot = scratch / "shot.png"
    subprocess.run(
        [
            chromium,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            f"--user-data-dir={scratch / 'profile'}",
            f"--screenshot={shot}",
            f"--window-size={size[0]},{size[1]}",
            page.as_uri(),
        ],
        check=True,
        capture_output=True,
        timeout=120,
    )
    colours = Image.open(shot).convert("RGB").getcolors(maxcolors=1 << 20)
    assert colours is not None
    # An RGB image's colours are (r, g, b) tuples; PIL types them wider (float for "F" mode).
    return {colour for count, colour in colours if count > 500 and isinstance(colour, tuple)}
