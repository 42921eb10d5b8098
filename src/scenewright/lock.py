"""One writer per scene folder: an exclusive ``flock`` on a lock file inside the folder.

Two commands writing one folder at once lose updates (each saves the document it read) and
break the edit history's chain, so every command that writes holds this lock from before it
reads the document until after its last write. A second one waits for it, up to a timeout,
then says which process holds the folder. The kernel drops the lock when its holder exits,
however it exits, so a killed run never leaves a folder locked.
"""

from __future__ import annotations

import fcntl
import logging
import os
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from scenewright.errors import FolderBusy, InputError

log = logging.getLogger(__name__)

#: The lock file's name inside the scene folder.
LOCK_NAME = ".scenewright.lock"
#: Seconds between attempts while another process holds the folder.
POLL_SECONDS = 0.05


def _holder(fd: int) -> str:
    """Who holds the lock, as its holder wrote it (its pid), for the message of a waiter."""
    try:
        text = os.pread(fd, 64, 0).decode("ascii", "replace").strip()
    except OSError:
        return "another process"
    return f"process {text}" if text.isdigit() else "another process"


def _acquire(path: Path, timeout: float) -> int:
    """An open descriptor of ``path`` holding its exclusive lock; the file is created if need be."""
    deadline = time.monotonic() + timeout
    warned = False
    while True:
        try:
            fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o644)
        except OSError as exc:
            raise InputError(
                f"cannot write in {path.parent} (to lock it: {exc.strerror}); check the folder and its permissions"
            ) from None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = _holder(fd)
            os.close(fd)
            if time.monotonic() >= deadline:
                raise FolderBusy(
                    f"{path.parent} is being changed by {holder} (another scenewright command); "
                    f"gave up after waiting {timeout:g} s. Run this again when it has finished, "
                    "or raise lock_timeout in the config file"
                ) from None
            if not warned:
                warned = True
                log.warning("%s is being changed by %s; waiting up to %g s", path.parent, holder, timeout)
            time.sleep(POLL_SECONDS)
            continue
        try:
            same = os.path.samestat(os.fstat(fd), os.stat(path))
        except FileNotFoundError:
            same = False
        if same:
            return fd
        os.close(fd)  # its holder removed the file on release: lock the one that is there now


@contextmanager
def locked(root: str | os.PathLike, timeout: float) -> Iterator[None]:
    """Hold ``root``'s lock for the ``with`` block; wait up to ``timeout`` seconds for it.

    ``root`` must exist. Raises :class:`~scenewright.errors.FolderBusy` naming the holder's
    pid when the wait runs out. The lock file is removed on release, so a command leaves the
    folder as it found it; a waiter then finds the file gone and locks a new one.
    """
    path = Path(root) / LOCK_NAME
    fd = _acquire(path, timeout)
    try:
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode("ascii"), 0)
        yield
    finally:
        try:
            path.unlink(missing_ok=True)
        except OSError:
            pass  # a folder made read-only meanwhile: the file stays, unlocked, harmless
        os.close(fd)  # closing the only descriptor releases the lock
