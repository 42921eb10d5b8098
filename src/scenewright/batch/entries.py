"""The entries of a batch: one scene each, read from a text file or JSONL.

A text file holds one description a line (blank lines and ``#`` comments skipped); its ids
come from the text itself (first words + a short hash), so they survive reordering and
appending lines, which is what lets a re-run find the scenes it already made. A JSONL line
is an object with ``id`` and ``text`` and optionally ``style``, ``seed``, ``room`` (as
``generate --room``: auto, none, WxD or WxDxH) and backend overrides (the keys of
:data:`OVERRIDES`, checked as a config file's are).

A line that cannot be used is a :class:`Problem` naming its line number and what is wrong;
the caller skips it or, in strict mode, refuses the file.
"""

from __future__ import annotations

import hashlib
import json
import re
from dataclasses import dataclass, field, replace
from pathlib import Path

from scenewright.analysis.parser.room import parse_room_option
from scenewright.errors import InputError
from scenewright.settings import Settings, apply

#: Settings keys a JSONL entry may override for its own scene.
OVERRIDES = ("vlm", "images", "meshes", "base_url", "reasoning_effort", "feedback_rounds", "max_faces", "time_limit")
KEYS = ("id", "text", "style", "seed", "room", *OVERRIDES)
#: Ids become folder names: letters, digits, '_', '-', '.', not starting with '.'.
_ID = re.compile(r"^[A-Za-z0-9_\-][A-Za-z0-9_\-.]{0,99}$")
_WORD = re.compile(r"[a-z0-9]+")


@dataclass(frozen=True)
class Entry:
    """One scene to make: where it came from, what to make, which settings differ."""

    id: str
    text: str
    line: int
    style: str | None = None
    #: ``None``: not given (the scene uses seed 0, or each of ``--seeds``).
    seed: int | None = None
    #: ``generate --room``: auto (the default), none, WxD or WxDxH metres.
    room: str = "auto"
    overrides: dict[str, object] = field(default_factory=dict)

    def settings(self, base: Settings) -> Settings:
        """``base`` with this entry's backend overrides (already checked when read)."""
        return apply(replace(base, extra=dict(base.extra)), self.overrides, f"entry {self.id}")


@dataclass(frozen=True)
class Problem:
    line: int
    reason: str

    def __str__(self) -> str:
        return f"line {self.line}: {self.reason}"


def text_id(text: str) -> str:
    """A readable, stable id for a description: its first words and a hash of all of it."""
    words = _WORD.findall(text.lower())[:4]
    digest = hashlib.sha1(text.encode("utf-8")).hexdigest()[:6]
    return "-".join([*words, digest])[:60]


def _is_jsonl(path: Path, lines: list[str]) -> bool:
    if path.suffix.lower() in (".jsonl", ".ndjson"):
        return True
    first = next((line.strip() for line in lines if line.strip() and not line.lstrip().startswith("#")), "")
    return first.startswith("{")


def _seed(value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise ValueError(f"seed must be an integer >= 0, got {value!r}")
    return value


def _json_entry(number: int, raw: str) -> Entry:
    try:
        data = json.loads(raw)
    except json.JSONDecodeError as exc:
        raise ValueError(f"not valid JSON ({exc.msg} at column {exc.colno})") from None
    if not isinstance(data, dict):
        raise ValueError(f"expected a JSON object with 'id' and 'text', got {type(data).__name__}")
    unknown = sorted(set(data) - set(KEYS))
    if unknown:
        raise ValueError(f"unknown keys {', '.join(unknown)}; valid keys: {', '.join(KEYS)}")
    text = data.get("text")
    if not isinstance(text, str) or not text.strip():
        raise ValueError("'text' must be a non-empty string (the scene description)")
    entry_id = data.get("id", text_id(text))
    if not isinstance(entry_id, str) or not _ID.match(entry_id):
        raise ValueError(
            f"id {entry_id!r} cannot name a folder; use letters, digits, '_', '-' and '.' (not first), at most 100"
        )
    style = data.get("style")
    if style is not None and (not isinstance(style, str) or not style.strip()):
        raise ValueError(f"'style' must be a non-empty string, got {style!r}")
    room = data.get("room", "auto")
    if not isinstance(room, str):
        raise ValueError(f"'room' must be a string (auto, none, WxD or WxDxH metres), got {room!r}")
    try:
        parse_room_option(room)
    except InputError as exc:
        raise ValueError(str(exc).removeprefix("--")) from None
    overrides = {k: data[k] for k in OVERRIDES if k in data}
    try:
        apply(Settings(), overrides, "entry")  # checked now, applied per scene
    except InputError as exc:
        raise ValueError(str(exc).removeprefix("entry: ")) from None
    return Entry(
        id=entry_id,
        text=text.strip(),
        line=number,
        style=style.strip() if style else None,
        seed=_seed(data["seed"]) if "seed" in data else None,
        room=room,
        overrides=overrides,
    )


def read_entries(
    path: str | Path, *, style: str | None = None, seeds: list[int] | None = None
) -> tuple[list[Entry], list[Problem]]:
    """Entries of ``path`` and the lines that could not be used.

    ``style`` is the style of entries that name none; ``seeds`` replaces the seed of entries
    that give none with each of these seeds (ids get ``-seed<N>`` when there are several).
    """
    path = Path(path)
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except FileNotFoundError:
        raise InputError(f"prompts file {path} does not exist") from None
    except UnicodeDecodeError as exc:
        raise InputError(f"prompts file {path} is not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    except OSError as exc:
        raise InputError(f"cannot read prompts file {path}: {exc.strerror}") from None
    jsonl = _is_jsonl(path, lines)
    entries: list[Entry] = []
    problems: list[Problem] = []
    for number, raw in enumerate(lines, start=1):
        stripped = raw.strip()
        if not stripped or stripped.startswith("#"):
            continue
        if not jsonl:
            entries.append(Entry(id=text_id(stripped), text=stripped, line=number))
            continue
        try:
            entries.append(_json_entry(number, stripped))
        except ValueError as exc:
            problems.append(Problem(number, str(exc)))
    entries = [_with_defaults(e, style, seeds) for e in entries]
    expanded = [e for group in entries for e in group]
    first_line: dict[str, int] = {}
    unique: list[Entry] = []
    for entry in expanded:
        if entry.id in first_line:
            problems.append(Problem(entry.line, f"id {entry.id!r} is already used on line {first_line[entry.id]}"))
            continue
        first_line[entry.id] = entry.line
        unique.append(entry)
    problems.sort(key=lambda p: p.line)
    if not unique and not problems:
        raise InputError(f"prompts file {path} holds no description (one a line, or JSONL with 'id' and 'text')")
    return unique, problems


def _with_defaults(entry: Entry, style: str | None, seeds: list[int] | None) -> list[Entry]:
    if style and entry.style is None:
        entry = replace(entry, style=style)
    if not seeds or entry.seed is not None:
        return [entry]
    if len(seeds) == 1:
        return [replace(entry, seed=seeds[0])]
    return [replace(entry, id=f"{entry.id}-seed{s}", seed=s) for s in seeds]


def parse_seeds(spec: str) -> list[int]:
    """``"0,1,2"`` or ``"0-4"`` (inclusive), or both mixed: the seeds, in order, each once."""
    seeds: list[int] = []
    for part in spec.split(","):
        part = part.strip()
        match = re.fullmatch(r"(\d+)(?:\s*-\s*(\d+))?", part)
        if not match:
            raise InputError(f"--seeds: {part!r} is not a seed; write e.g. '0,1,2' or '0-4'")
        low = int(match.group(1))
        high = int(match.group(2)) if match.group(2) else low
        if high < low:
            raise InputError(f"--seeds: the range {part!r} runs backwards; write it low-high")
        seeds += [s for s in range(low, high + 1) if s not in seeds]
    return seeds
