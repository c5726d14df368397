"""Screenshots side by side, each under its caption, scaled to one width: for docs/layouts.md.

usage: python montage.py OUT.png WIDTH SHOT.png CAPTION [SHOT.png CAPTION ...]

Each shot (``drive.py --shots``) is scaled to WIDTH / (number of shots) pixels wide, keeping
its proportions, and put beside the others, left to right, with its caption above it (the
comparison of two UI configurations of one team, or of one configuration before and after a
change). Needs Pillow.
"""

from __future__ import annotations

import sys
from pathlib import Path

from PIL import Image, ImageDraw

CAPTION = 28  # pixels above each shot for its caption
GAP = 8  # pixels between shots


def montage(out: Path, width: int, shots: list[tuple[Path, str]]) -> None:
    each = (width - GAP * (len(shots) - 1)) // len(shots)
    images = []
    for path, _ in shots:
        image = Image.open(path).convert("RGB")
        images.append(image.resize((each, round(image.height * each / image.width)), Image.LANCZOS))
    height = CAPTION + max(image.height for image in images)
    sheet = Image.new("RGB", (width, height), "white")
    draw = ImageDraw.Draw(sheet)
    for index, (image, (_, caption)) in enumerate(zip(images, shots, strict=True)):
        left = index * (each + GAP)
        draw.text((left + 4, 8), caption, fill="black")
        sheet.paste(image, (left, CAPTION))
    sheet.save(out, optimize=True)


def main() -> None:
    out, width, rest = Path(sys.argv[1]), int(sys.argv[2]), sys.argv[3:]
    if not rest or len(rest) % 2:
        raise SystemExit(__doc__)
    montage(out, width, [(Path(rest[i]), rest[i + 1]) for i in range(0, len(rest), 2)])


if __name__ == "__main__":
    main()
