"""Large test inputs written once and kept between runs under ``build/test-data``.

Some benchmarks need inputs that take a library a minute to write (bags of thousands of
topics). :func:`cached` writes such an input once into a folder named by everything it depends
on (sizes, the writing library's version), atomically (a half-written folder is never found),
and every later run reads it from there. ``build/`` is ignored by git; deleting it is always
safe.
"""

from __future__ import annotations

import shutil
import tempfile
from collections.abc import Callable
from pathlib import Path

from tests.conftest import ROOT

__all__ = ["CACHE", "cached"]

CACHE = ROOT / "build" / "test-data"


def cached(key: str, write: Callable[[Path], None]) -> Path:
    """The folder ``CACHE/key``, made by ``write(folder)`` the first time it is asked for."""
    folder = CACHE / key
    if folder.is_dir():
        return folder
    CACHE.mkdir(parents=True, exist_ok=True)
    partial = Path(tempfile.mkdtemp(prefix=f".{key}-", dir=CACHE))
    try:
        write(partial)
        partial.rename(folder)
    except OSError:
        if not folder.is_dir():  # not another run finishing first
            raise
    finally:
        shutil.rmtree(partial, ignore_errors=True)
    return folder
