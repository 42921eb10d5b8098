"""Edit history of a scene folder: every version of ``scene.json``, an edit log, undo and redo.

``history/`` holds, for edit *n* of the current line of edits, ``NNNN.json`` (the document
before it, byte for byte) and ``NNNN.after.json`` (the document it produced), one line per
edit in ``log.jsonl``, and ``state.json`` with how many of them are in effect. Undo and redo
copy a stored version back as it was, so undo restores the previous document exactly; a new
edit after an undo drops the undone ones. Asset files are never deleted or overwritten by an
edit (new ones get content-addressed names), so every stored version still has its assets.
"""

from __future__ import annotations

import json
import logging
from dataclasses import dataclass
from datetime import datetime, timezone
from pathlib import Path

from pydantic import ValidationError

from scenewright.errors import InputError
from scenewright.export import assemble
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.scene import Scene, describe_validation_error

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Entry:
    """One edit of the log, and whether it is in effect (not undone)."""

    number: int
    instruction: str
    operation: str
    focus: str
    changes: list[str]
    time: str
    active: bool


def _log(folder: SceneFolder) -> Path:
    return folder.history / "log.jsonl"


def _state(folder: SceneFolder) -> Path:
    return folder.history / "state.json"


def _before(folder: SceneFolder, number: int) -> Path:
    return folder.history / f"{number:04d}.json"


def _after(folder: SceneFolder, number: int) -> Path:
    return folder.history / f"{number:04d}.after.json"


def _broken(folder: SceneFolder, path: Path, why: str) -> InputError:
    return InputError(
        f"{path} is broken ({why}); undo, redo and edit need an intact history: restore it, or move "
        f"{folder.history} away to keep the scene as it is and start a new history"
    )


#: The fields of a log record and the type each must have.
_RECORD = {"number": int, "instruction": str, "operation": str, "focus": str, "changes": list, "time": str}


def _records(folder: SceneFolder) -> list[dict]:
    path = _log(folder)
    if not path.is_file():
        return []
    records = []
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except UnicodeDecodeError as exc:
        raise _broken(folder, path, f"not UTF-8 text: {exc.reason}") from None
    for index, line in enumerate((line for line in lines if line.strip()), start=1):
        try:
            record = json.loads(line)
        except json.JSONDecodeError as exc:
            raise _broken(folder, path, f"edit {index} is not valid JSON: {exc.msg}") from None
        bad = [k for k, kind in _RECORD.items() if not isinstance(record, dict) or not isinstance(record.get(k), kind)]
        if bad or record["number"] != index:
            raise _broken(folder, path, f"edit {index} has no valid {', '.join(bad) or 'number'}")
        records.append(record)
    return records


def _current(folder: SceneFolder) -> int:
    path = _state(folder)
    count = len(_records(folder))
    if not path.is_file():
        return count
    try:
        current = json.loads(path.read_text(encoding="utf-8"))["current"]
    except (json.JSONDecodeError, UnicodeDecodeError, TypeError, KeyError) as exc:
        raise _broken(folder, path, f"no 'current' edit number: {type(exc).__name__}") from None
    if isinstance(current, bool) or not isinstance(current, int) or not 0 <= current <= count:
        raise _broken(folder, path, f"current is {current!r}, not an edit number from 0 to {count}")
    return current


def entries(folder: SceneFolder) -> list[Entry]:
    """The edits of the folder, oldest first; undone ones have ``active`` False."""
    folder.load()
    current = _current(folder)
    return [
        Entry(
            number=r["number"], instruction=r["instruction"], operation=r["operation"], focus=r["focus"],
            changes=list(r.get("changes", [])), time=r["time"], active=r["number"] <= current,
        )
        for r in _records(folder)
    ]


def commit(
    folder: SceneFolder,
    scene: Scene,
    files: dict[str, bytes],
    *,
    instruction: str,
    operation: str,
    focus: str,
    changes: list[str],
) -> int:
    """Write an edited scene: its new files, ``scene.glb``, the history, then ``scene.json``.

    The document goes last, so an interruption before it leaves the old document in effect
    (new asset files have fresh names and the old document does not refer to them).
    Returns the edit's number.
    """
    previous = folder.document.read_bytes()
    old_glb = folder.glb.read_bytes() if folder.glb.is_file() else None
    written: list[Path] = []
    try:
        for relative, data in files.items():
            path = folder.resolve(relative)
            if not path.exists():
                written.append(write_atomic(path, data))
        assemble(scene, folder)
        current = _current(folder)
        kept = [r for r in _records(folder) if r["number"] <= current]
        for stale in _records(folder)[len(kept):]:  # a new edit after undo drops the redo branch
            _before(folder, stale["number"]).unlink(missing_ok=True)
            _after(folder, stale["number"]).unlink(missing_ok=True)
        number = current + 1
        document = scene.to_json()
        write_atomic(_before(folder, number), previous)
        write_atomic(_after(folder, number), document)
        record = {
            "number": number, "instruction": instruction, "operation": operation, "focus": focus,
            "changes": changes, "time": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        }
        lines = [json.dumps(r, ensure_ascii=False) for r in [*kept, record]]
        write_atomic(_log(folder), "\n".join(lines) + "\n")
        write_atomic(_state(folder), json.dumps({"current": number}) + "\n")
        write_atomic(folder.document, document)
    except BaseException:
        for path in written:
            path.unlink(missing_ok=True)
        if old_glb is not None:
            write_atomic(folder.glb, old_glb)
        raise
    log.info("edit %d: %s %s", number, operation, focus)
    return number


def _restore(folder: SceneFolder, source: Path, current: int) -> Scene:
    try:
        data = source.read_bytes()
        scene = Scene.model_validate_json(data)
    except FileNotFoundError:
        raise _broken(folder, source, "missing") from None
    except ValidationError as exc:
        raise _broken(folder, source, describe_validation_error(exc)) from None
    assemble(scene, folder)
    write_atomic(_state(folder), json.dumps({"current": current}) + "\n")
    write_atomic(folder.document, data)
    return scene


def _check_unchanged(folder: SceneFolder, current: int) -> None:
    """Warn when scene.json was changed outside the editor since the last edit: undo drops that."""
    after = _after(folder, current)
    if after.is_file() and after.read_bytes() != folder.document.read_bytes():
        log.warning("%s changed since edit %d; undo/redo replaces those changes", folder.document, current)


def undo(folder: SceneFolder) -> tuple[Scene, Entry]:
    """Go back one edit: the document before it, byte for byte, and ``scene.glb`` to match."""
    done = [e for e in entries(folder) if e.active]
    if not done:
        raise InputError(f"nothing to undo in {folder.root}: no edit is in effect")
    last = done[-1]
    _check_unchanged(folder, last.number)
    return _restore(folder, _before(folder, last.number), last.number - 1), last


def redo(folder: SceneFolder) -> tuple[Scene, Entry]:
    """Re-apply the edit undone last, exactly as it came out the first time."""
    undone = [e for e in entries(folder) if not e.active]
    if not undone:
        raise InputError(f"nothing to redo in {folder.root}: no edit has been undone")
    following = undone[0]
    _check_unchanged(folder, following.number - 1)
    return _restore(folder, _after(folder, following.number), following.number), following
