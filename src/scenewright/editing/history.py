"""Edit history of a scene folder: every version of ``scene.json``, an edit log, undo and redo.

``history/`` holds, for edit *n* of the current line of edits, ``NNNN.json`` (the document
before it, byte for byte) and ``NNNN.after.json`` (the document it produced), one line per
edit in ``log.jsonl``, and ``state.json`` with how many of them are in effect. Undo and redo
copy a stored version back as it was, so undo restores the previous document exactly; a new
edit after an undo drops the undone ones. Asset files are never deleted or overwritten by an
edit (new ones get content-addressed names), so every stored version still has its assets.

``scene.json`` is the commit point of every change. A change first writes what it will do to
the history as ``pending.json`` (with the hash of the document it is about to save), then the
document, then the history files. Whoever opens the folder next finishes a pending change
whose document was saved and forgets one whose document was not (:func:`recover`), so a run
killed at any point leaves a history that matches the document: undo never undoes an edit
that never took effect.
"""

from __future__ import annotations

import hashlib
import json
import logging
from dataclasses import dataclass
from datetime import datetime, timezone
from pathlib import Path

from pydantic import ValidationError

from scenewright.assets.load import AssetMeshes
from scenewright.errors import InputError
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.integrity import assemble_recorded, file_sha256
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


def _pending(folder: SceneFolder) -> Path:
    return folder.history / "pending.json"


def _staged(folder: SceneFolder) -> dict | None:
    """The pending change when its document is the one in effect (it got saved), else None."""
    path = _pending(folder)
    if not path.is_file():
        return None
    try:
        pending = json.loads(path.read_text(encoding="utf-8"))
    except (ValueError, UnicodeDecodeError):
        return None  # cut short: its document cannot have been written after it
    if not isinstance(pending, dict) or pending.get("document_sha256") != file_sha256(folder.document):
        return None
    if not {"current", "records", "write", "remove"} <= set(pending):
        return None  # not one this module wrote
    return pending


def _in_effect(folder: SceneFolder) -> tuple[list[dict], int]:
    """The log's records and how many are in effect, counting a pending change whose document
    was saved (so reading the history needs no write)."""
    staged = _staged(folder)
    if staged is not None:
        return staged["records"], staged["current"]
    return _records(folder), _current(folder)


def entries(folder: SceneFolder) -> list[Entry]:
    """The edits of the folder, oldest first; undone ones have ``active`` False."""
    folder.load()
    records, current = _in_effect(folder)
    return [
        Entry(
            number=r["number"], instruction=r["instruction"], operation=r["operation"], focus=r["focus"],
            changes=list(r.get("changes", [])), time=r["time"], active=r["number"] <= current,
        )
        for r in records
    ]


def _finish(folder: SceneFolder, pending: dict) -> None:
    """Write the history files of a change whose document is saved; safe to run again."""
    for name, text in pending["write"].items():
        write_atomic(folder.history / name, text)
    for name in pending["remove"]:
        (folder.history / name).unlink(missing_ok=True)
    lines = [json.dumps(r, ensure_ascii=False) for r in pending["records"]]
    write_atomic(_log(folder), "".join(line + "\n" for line in lines))
    write_atomic(_state(folder), json.dumps({"current": pending["current"]}) + "\n")
    _pending(folder).unlink(missing_ok=True)


def _apply(folder: SceneFolder, pending: dict, document: bytes) -> None:
    """Save ``document`` as the change ``pending`` describes: intent, document, history."""
    pending = {**pending, "document_sha256": hashlib.sha256(document).hexdigest()}
    write_atomic(_pending(folder), json.dumps(pending, ensure_ascii=False))
    write_atomic(folder.document, document)
    _finish(folder, pending)


def recover(folder: SceneFolder) -> None:
    """Finish the history of a change whose document was saved; forget one whose was not."""
    if not _pending(folder).exists():
        return
    staged = _staged(folder)
    if staged is not None:
        log.warning("finishing the history of an interrupted change in %s", folder.root)
        _finish(folder, staged)
    else:
        log.warning("dropping an interrupted change of %s that never took effect", folder.root)
        _pending(folder).unlink(missing_ok=True)


def _checked(document: bytes | str, what: str) -> Scene:
    """The document a change is about to save, refused when it does not validate."""
    try:
        return Scene.from_json(document)
    except ValidationError as exc:
        raise InputError(f"{what} would be invalid, so nothing was written: {describe_validation_error(exc)}") from None


def commit(
    folder: SceneFolder,
    scene: Scene,
    files: dict[str, bytes],
    *,
    instruction: str,
    operation: str,
    focus: str,
    changes: list[str],
    meshes: AssetMeshes | None = None,
) -> int:
    """Write an edited scene: its new files, ``scene.glb``, then the document and its history.
    ``meshes`` holds the assets the edit has parsed already.

    Nothing is written when the edited document does not validate. An interruption before the
    document is saved leaves the old one in effect (new asset files have fresh names and the
    old document does not refer to them; a ``scene.glb`` left newer than it does not match its
    recorded hash and is rebuilt). Returns the edit's number.
    """
    recover(folder)
    _checked(scene.to_json(), "the edited scene")
    previous = folder.document.read_bytes()
    old_glb = folder.glb.read_bytes() if folder.glb.is_file() else None
    records, current = _records(folder), _current(folder)
    kept = [r for r in records if r["number"] <= current]
    number = current + 1
    # A new edit after undo drops the redo branch; its own number's files are overwritten.
    dropped = [path(folder, r["number"]).name for r in records if r["number"] > number for path in (_before, _after)]
    written: list[Path] = []
    document = b""
    try:
        for relative, data in files.items():
            path = folder.resolve(relative)
            if not path.exists():
                written.append(write_atomic(path, data))
        assemble_recorded(scene, folder, meshes)
        document = scene.to_json().encode("utf-8")
        record = {
            "number": number, "instruction": instruction, "operation": operation, "focus": focus,
            "changes": changes, "time": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        }
        pending = {
            "current": number,
            "records": [*kept, record],
            "write": {_before(folder, number).name: previous.decode("utf-8"),
                      _after(folder, number).name: document.decode("utf-8")},
            "remove": dropped,
        }
        _apply(folder, pending, document)
    except BaseException:
        if file_sha256(folder.document) != hashlib.sha256(document).hexdigest():  # not saved: undo the rest
            for path in written:
                path.unlink(missing_ok=True)
            if old_glb is not None:
                write_atomic(folder.glb, old_glb)
            _pending(folder).unlink(missing_ok=True)
        raise
    log.info("edit %d: %s %s", number, operation, focus)
    return number


def _restore(folder: SceneFolder, source: Path, current: int) -> Scene:
    """Make the stored version ``source`` the document again, with ``current`` edits in effect."""
    try:
        data = source.read_bytes()
        scene = Scene.from_json(data)
    except FileNotFoundError:
        raise _broken(folder, source, "missing") from None
    except ValidationError as exc:
        raise _broken(folder, source, describe_validation_error(exc)) from None
    recorded = scene.glb_sha256
    assemble_recorded(scene, folder)
    if recorded is not None and scene.glb_sha256 != recorded:  # another trimesh wrote other bytes
        data = scene.to_json().encode("utf-8")
    records, _ = _in_effect(folder)
    _apply(folder, {"current": current, "records": records, "write": {}, "remove": []}, data)
    return scene


def _check_unchanged(folder: SceneFolder, current: int) -> None:
    """Warn when scene.json was changed outside the editor since the last edit: undo drops that."""
    after = _after(folder, current)
    if after.is_file() and after.read_bytes() != folder.document.read_bytes():
        log.warning("%s changed since edit %d; undo/redo replaces those changes", folder.document, current)


def undo(folder: SceneFolder) -> tuple[Scene, Entry]:
    """Go back one edit: the document before it, byte for byte, and ``scene.glb`` to match."""
    recover(folder)
    done = [e for e in entries(folder) if e.active]
    if not done:
        raise InputError(f"nothing to undo in {folder.root}: no edit is in effect")
    last = done[-1]
    _check_unchanged(folder, last.number)
    return _restore(folder, _before(folder, last.number), last.number - 1), last


def redo(folder: SceneFolder) -> tuple[Scene, Entry]:
    """Re-apply the edit undone last, exactly as it came out the first time."""
    recover(folder)
    undone = [e for e in entries(folder) if not e.active]
    if not undone:
        raise InputError(f"nothing to redo in {folder.root}: no edit has been undone")
    following = undone[0]
    _check_unchanged(folder, following.number - 1)
    return _restore(folder, _after(folder, following.number), following.number), following
