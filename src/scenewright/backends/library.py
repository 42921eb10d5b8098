"""A mesh backend over the user's own asset collection (the first Holodeck's retrieval, local).

A folder of GLB and OBJ files, described by ``index.toml``::

    [[asset]]
    file = "seating/red_sofa.glb"     # relative to the folder
    name = "red leather sofa"
    category = "sofa"                 # a catalogue category (optional)
    tags = ["modern", "leather"]
    up = "y"                          # "y" (glTF, the default) or "z" (Blender/CAD, front −Y)
    turn = 0                          # degrees about the up axis that turn its front to the viewer

Without an index, one is inferred from the paths: the file name gives the name, the
catalogue recognises the category in it or in a folder name, and folder names become tags.
Requests are matched by a token score: the category counts most, then words of the
object's name, then words of its description and style.
"""

from __future__ import annotations

import hashlib
import logging
import tomllib
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
import trimesh

from scenewright.core.catalogue import load_catalogue, lookup, singular, words
from scenewright.core.protocols import MeshRequest
from scenewright.errors import BackendError, InputError
from scenewright.geometry import SCENE_TO_GLTF
from scenewright.settings import Settings

log = logging.getLogger(__name__)

INDEX = "index.toml"
SUFFIXES = (".glb", ".obj")
CATEGORY_SCORE, NAME_SCORE, WORD_SCORE = 6, 3, 1
#: Words of descriptions that say nothing about which asset fits.
STOPWORDS = frozenset(
    "a an and the of with in on at to for from by its it is are this that small large big "
    "tall short wide".split()
)


def tokens(text: str) -> set[str]:
    return {singular(w) for w in words(text)}


@dataclass(frozen=True)
class LibraryAsset:
    file: str
    name: str
    category: str | None = None
    tags: tuple[str, ...] = ()
    up: str = "y"
    turn: float = 0.0

    def tokens(self) -> set[str]:
        found = tokens(self.name) | tokens(" ".join(self.tags))
        if self.category:
            found |= tokens(self.category.replace("_", " "))
        return found


def _guess_category(parts: Sequence[str]) -> str | None:
    """The catalogue category named in a file name or folder (longest phrase first)."""
    for part in parts:
        ws = words(part.replace("_", " "))
        for length in range(len(ws), 0, -1):
            for start in range(len(ws) - length, -1, -1):
                found = lookup(" ".join(ws[start : start + length]))
                if found is not None:
                    return found.name
    return None


def infer_index(root: Path) -> list[LibraryAsset]:
    """An index from file and folder names, for a collection that has no ``index.toml``."""
    entries = []
    for path in sorted(p for p in root.rglob("*") if p.suffix.lower() in SUFFIXES and p.is_file()):
        rel = path.relative_to(root)
        folders = rel.parts[:-1]
        entries.append(
            LibraryAsset(
                file=rel.as_posix(),
                name=" ".join(words(path.stem.replace("_", " "))) or path.stem,
                category=_guess_category([path.stem, *reversed(folders)]),
                tags=tuple(" ".join(words(f.replace("_", " "))) for f in folders),
            )
        )
    return entries


def read_index(root: Path) -> list[LibraryAsset]:
    """The entries of ``index.toml``, checked: every file exists, every field is known."""
    path = root / INDEX
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{path}: not valid TOML ({exc})") from None
    fields = set(LibraryAsset.__dataclass_fields__)
    entries = []
    for number, raw in enumerate(data.get("asset", []), start=1):
        unknown = set(raw) - fields
        if unknown or "file" not in raw:
            raise InputError(
                f"{path}: asset #{number} needs 'file' and may have only {', '.join(sorted(fields))}"
                + (f"; unknown: {', '.join(sorted(unknown))}" if unknown else "")
            )
        if not (root / raw["file"]).is_file() or Path(raw["file"]).suffix.lower() not in SUFFIXES:
            raise InputError(f"{path}: asset #{number} file {raw['file']!r} is not a GLB or OBJ file in {root}")
        if raw.get("up", "y") not in ("y", "z"):
            raise InputError(f"{path}: asset #{number} has up = {raw['up']!r}; use \"y\" or \"z\"")
        entries.append(
            LibraryAsset(
                file=raw["file"],
                name=raw.get("name") or Path(raw["file"]).stem.replace("_", " "),
                category=raw.get("category"),
                tags=tuple(raw.get("tags", ())),
                up=raw.get("up", "y"),
                turn=float(raw.get("turn", 0.0)),
            )
        )
    return entries


class AssetLibrary:
    """MeshGenerator that picks, for each request, the best-matching file of a collection."""

    name = "library"
    #: Reading a file is quick; one request at a time.
    concurrency = 1

    def __init__(self, root: str | Path):
        self.root = Path(root).expanduser()
        if not self.root.is_dir():
            raise InputError(f"asset library {self.root} is not a folder; write --meshes library:FOLDER")
        self.entries = read_index(self.root) if (self.root / INDEX).is_file() else infer_index(self.root)
        if not self.entries:
            raise InputError(f"asset library {self.root} holds no .glb or .obj files")
        self._tokens = [entry.tokens() for entry in self.entries]
        #: Part of the cache key: a changed collection must not answer from old results.
        self.params = {"library": self._fingerprint()}

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> AssetLibrary:
        if not argument:
            raise InputError("the library backend needs a folder: --meshes library:/path/to/assets")
        return cls(argument)

    def _fingerprint(self) -> str:
        h = hashlib.sha256()
        for entry in self.entries:
            stat = (self.root / entry.file).stat()
            h.update(repr((asdict(entry), stat.st_size, stat.st_mtime_ns)).encode())
        return h.hexdigest()

    def cancel(self) -> None:
        """Nothing runs in the background: each request is answered inside ``generate``."""

    def score(self, request: MeshRequest, index: int) -> int:
        entry, have = self.entries[index], self._tokens[index]
        category = request.category or getattr(lookup(request.name), "name", None)
        score = 0
        if category is not None:
            known = load_catalogue().get(category)
            phrases = known.phrases if known else (category.replace("_", " "),)
            if entry.category == category or any(tokens(p) <= have for p in phrases):
                score += CATEGORY_SCORE
        name_words = tokens(request.name) - STOPWORDS
        score += NAME_SCORE * len(name_words & have)
        other = tokens(f"{request.description} {request.style}") - STOPWORDS - name_words
        return score + WORD_SCORE * len(other & have)

    def match(self, request: MeshRequest) -> LibraryAsset:
        """The best entry (ties go to the first in the index); it must share the category or a name word."""
        scores = [self.score(request, i) for i in range(len(self.entries))]
        best = max(range(len(scores)), key=lambda i: (scores[i], -i))
        if scores[best] >= NAME_SCORE:
            return self.entries[best]
        ranked = sorted(range(len(scores)), key=lambda i: (-scores[i], i))[:3]
        candidates = ", ".join(f"{self.entries[i].name!r} ({self.entries[i].file})" for i in ranked)
        raise BackendError(
            f"the asset library {self.root} has nothing for {request.id!r} ({request.name}"
            f"{', category ' + request.category if request.category else ''}); closest: {candidates}. "
            f"Add a matching file or an entry to {INDEX}"
        )

    def generate(
        self, requests: Sequence[MeshRequest], progress: Callable[[str], None] | None = None
    ) -> dict[str, bytes]:
        results: dict[str, bytes] = {}
        errors: list[str] = []
        for request in requests:
            try:
                entry = self.match(request)
            except BackendError as exc:
                errors.append(str(exc))
                continue
            log.info("library: %s ← %s", request.id, entry.file)
            results[request.id] = self._glb(entry)
            if progress:
                progress(f"{request.id}: {entry.file}")
        if errors:
            raise BackendError("; ".join(errors))
        return results

    def _glb(self, entry: LibraryAsset) -> bytes:
        """The file in glTF axes; a GLB that already is comes back byte for byte."""
        path = self.root / entry.file
        if path.suffix.lower() == ".glb" and entry.up == "y" and entry.turn == 0:
            return path.read_bytes()
        try:
            scene = trimesh.load(path, force="scene")
        except Exception as exc:  # trimesh raises many kinds on malformed files
            raise BackendError(f"library file {path} cannot be read: {exc}") from None
        if entry.up == "z":
            scene.apply_transform(SCENE_TO_GLTF)
        if entry.turn:
            scene.apply_transform(trimesh.transformations.rotation_matrix(np.radians(entry.turn), [0, 1, 0]))
        return scene.export(file_type="glb")
