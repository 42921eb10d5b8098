"""Files of a scene, written and read safely.

Writes go through a temporary file and a rename, so a reader never sees a half-written file
and a crash never loses one. Images are decoded before anything sends them to a server, so
a file that only claims to be an image (or a decompression bomb) goes nowhere.
"""

from __future__ import annotations

import io
import os
import tempfile
from pathlib import Path

from scenewright.errors import InputError

#: Pixels an image may have; a 1536×1024 reference has 1.6 million, a bomb has billions.
MAX_IMAGE_PIXELS = 64_000_000


def write_atomic(path: str | os.PathLike, data: bytes | str) -> Path:
    """Write ``data`` to ``path`` through a temporary file in the same folder and a rename."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(payload)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def check_image(data: bytes, what: str) -> bytes:
    """``data`` when it decodes as a PNG, JPEG or WebP image of sane size; else an InputError
    naming ``what``."""
    from PIL import Image

    try:
        with Image.open(io.BytesIO(data)) as image:
            if image.format not in ("PNG", "JPEG", "WEBP"):
                raise InputError(f"{what} is a {image.format} image; use PNG, JPEG or WebP")
            width, height = image.size
            if width * height > MAX_IMAGE_PIXELS:
                raise InputError(f"{what} has {width}×{height} pixels, more than {MAX_IMAGE_PIXELS:,}")
            image.load()
    except InputError:
        raise
    except Exception as exc:  # Pillow raises many kinds on broken files
        raise InputError(f"{what} is not a readable image ({type(exc).__name__}: {str(exc)[:120]})") from None
    return data
