"""The scene folder (docs/architecture.md, "Data flow"): where each file of a scene lives, and nowhere else.

One class names the paths so no stage spells them out; :meth:`SceneFolder.create` refuses
to write into a folder that holds something other than a scene, so nothing is overwritten
by mistake.

A scene folder is input a user may have been handed, so it is not trusted either: every
path the document (or ``renders/renders.json``) names goes through :meth:`SceneFolder.resolve`,
which accepts only a relative path that stays inside the folder once symbolic links are
followed and that names a file of the expected kind. Otherwise a tampered ``scene.json``
could make scenewright upload any local file to a model server, or copy it into
``scene.glb``. The sub-folders scenewright writes into must be real folders, not links, so
nothing is ever written outside the folder either.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path, PurePosixPath, PureWindowsPath
from typing import TYPE_CHECKING

from scenewright.errors import InputError
from scenewright.files import check_image
from scenewright.lock import LOCK_NAME

if TYPE_CHECKING:  # the document model (pydantic) is loaded by what reads a document, not by paths
    from scenewright.scene import Scene, SceneObject

#: Sub-folders scenewright writes into; a link in their place would send writes elsewhere.
SUBFOLDERS = ("images", "images/objects", "assets", "renders", "history")
#: Files with fixed names that scenewright reads; a link to outside the folder is refused.
FIXED_FILES = (
    "scene.json", "scene.glb", "images/reference.png", "images/ground.png", "renders/renders.json",
    "history/log.jsonl", "history/state.json",
)
#: The suffixes each kind of named file may have.
KINDS = {
    "asset": (".glb",),
    "image": (".png", ".jpg", ".jpeg", ".webp"),
}


@dataclass(frozen=True)
class SceneFolder:
    root: Path

    def __post_init__(self) -> None:
        object.__setattr__(self, "root", Path(self.root))

    @property
    def document(self) -> Path:
        return self.root / "scene.json"

    @property
    def images(self) -> Path:
        return self.root / "images"

    @property
    def object_images(self) -> Path:
        return self.images / "objects"

    @property
    def reference_image(self) -> Path:
        return self.images / "reference.png"

    @property
    def ground_image(self) -> Path:
        return self.images / "ground.png"

    @property
    def assets(self) -> Path:
        return self.root / "assets"

    def asset(self, object_id: str) -> Path:
        return self.assets / f"{object_id}.glb"

    @property
    def colliders(self) -> Path:
        return self.root / "colliders"

    def collider(self, object_id: str) -> Path:
        return self.colliders / f"{object_id}.npz"

    @property
    def simulation(self) -> Path:
        """Where ``scenewright export`` writes the simulator formats by default."""
        return self.root / "sim"

    def object_image(self, object_id: str) -> Path:
        return self.object_images / f"{object_id}.png"

    @property
    def glb(self) -> Path:
        return self.root / "scene.glb"

    @property
    def renders(self) -> Path:
        return self.root / "renders"

    @property
    def history(self) -> Path:
        return self.root / "history"

    def relative(self, path: Path) -> str:
        """How the document refers to a file of the folder (portable, POSIX separators).

        Both sides are resolved, so a folder given as a relative path still recognises the
        absolute paths a subprocess (the Blender worker) reports back.
        """
        return Path(path).resolve().relative_to(self.root.resolve()).as_posix()

    def resolve(self, relative: object, field: str = "path", kind: str | None = None) -> Path:
        """The file a document names in ``field``, checked before anything reads it.

        It must be a relative path, inside the folder after following symbolic links, with a
        suffix of ``kind`` (see :data:`KINDS`), and a regular file when it exists; anything
        else is an :class:`InputError` naming the field. A missing file is returned as it is:
        whether that is fine is the caller's call (a missing asset is rebuilt).
        """
        problem = _path_problem(relative, kind)
        if problem is None:
            path = self.root / str(relative)
            try:
                resolved = path.resolve()
                inside = resolved.is_relative_to(self.root.resolve()) and resolved != self.root.resolve()
            except (OSError, RuntimeError):  # a link loop
                inside = False
            if not inside:
                problem = "leads outside the scene folder"
            elif path.exists() and not resolved.is_file():
                problem = "is not a regular file"
        if problem is not None:
            raise InputError(
                f"{self.root}: {field} {str(relative)[:200]!r} {problem}; a scene names only files "
                "inside its own folder by relative paths (fix the field or set it to null)"
            )
        return path

    def asset_of(self, obj: SceneObject) -> Path | None:
        """The checked path of ``obj``'s asset, ``None`` when it has none."""
        return None if obj.asset is None else self.resolve(obj.asset, f"scene.json objects[{obj.id}].asset", "asset")

    def image_of(self, obj: SceneObject) -> Path | None:
        """The checked path of ``obj``'s image, ``None`` when it has none."""
        return None if obj.image is None else self.resolve(obj.image, f"scene.json objects[{obj.id}].image", "image")

    def ground_texture(self, scene: Scene) -> Path | None:
        """The checked path of the ground texture the document names, ``None`` when it names none."""
        texture = scene.ground.texture
        return None if texture is None else self.resolve(texture, "scene.json ground.texture", "image")

    def read_image(self, path: Path, field: str) -> bytes:
        """The bytes of an image of the folder, decoded first: only a real image is ever sent to a
        model server (``field`` names it in the error)."""
        self._check_fixed(path)
        return check_image(path.read_bytes(), f"{field} ({path})")

    def reference(self) -> bytes | None:
        """The reference image, checked, or ``None`` when there is none."""
        path = self.reference_image
        return self.read_image(path, "images/reference.png") if path.is_file() else None

    def _check_fixed(self, path: Path) -> None:
        """A file at a fixed place that links outside the folder is refused."""
        try:
            resolved = path.resolve()
        except (OSError, RuntimeError):
            resolved = None
        if path.is_symlink() and (resolved is None or not resolved.is_relative_to(self.root.resolve())):
            raise InputError(
                f"{path} is a symbolic link to outside the scene folder; scenewright reads and "
                "writes only inside the folder: replace the link with the file itself"
            )

    def check(self) -> None:
        """Refuse a folder whose sub-folders are links, or whose fixed files link outside it.

        Called whenever a folder is opened, so that no command reads or writes through them.
        """
        for name in SUBFOLDERS:
            path = self.root / name
            if path.is_symlink():
                raise InputError(
                    f"{path} is a symbolic link; scenewright writes only inside the scene folder: "
                    f"replace the link with a real folder (e.g. `rm {path} && mkdir {path}`)"
                )
            if path.exists() and not path.is_dir():
                raise InputError(f"{path} is not a folder; move it away so scenewright can use {name}/")
        for name in FIXED_FILES:
            path = self.root / name
            self._check_fixed(path)
            if path.exists() and not path.is_file():
                raise InputError(f"{path} is not a regular file; move it away")
        if self.history.is_dir():
            for path in self.history.iterdir():
                self._check_fixed(path)

    def is_scene(self) -> bool:
        return self.document.is_file()

    def load(self) -> Scene:
        if not self.is_scene():
            raise InputError(
                f"{self.root} is not a scene folder (no scene.json); "
                "create one with `scenewright generate TEXT --out DIR`"
            )
        self.check()
        from scenewright.scene import Scene

        return Scene.load(self.document)

    def save(self, scene: Scene) -> Path:
        return scene.save(self.document)

    def _leftover(self, path: Path) -> bool:
        """A file scenewright leaves in a folder before it holds a scene: the lock file, and the
        temporary file of a first save that was cut short."""
        name = path.name
        return name == LOCK_NAME or (name.startswith(f".{self.document.name}.") and name.endswith(".tmp"))

    def create(self) -> None:
        """Make the folder ready for a new scene, refusing anything that would lose files."""
        if self.root.exists() and not self.root.is_dir():
            raise InputError(f"{self.root} exists and is not a folder; choose another --out")
        if self.root.is_dir() and any(not self._leftover(p) for p in self.root.iterdir()) and not self.is_scene():
            raise InputError(
                f"{self.root} is not empty and holds no scene.json; refusing to write into it. "
                "Choose an empty or new folder for --out"
            )
        try:
            self.root.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise InputError(f"cannot create {self.root}: {exc.strerror}") from None
        if not os.access(self.root, os.W_OK):
            raise InputError(f"{self.root} is not writable; choose another --out")
        self.check()


class DocumentSaver:
    """The one writer of a run's ``scene.json``: whole at the end of each stage, and as a
    checkpoint while a long stage runs.

    Each save rewrites and syncs the whole document, so saving after every asset grew as the
    square of the object count and cost more than building the offline assets. A stage calls
    :meth:`checkpoint` when it has something worth keeping (a paid asset, a drawn image); that
    writes only when ``interval`` seconds have passed since the last save, so a fast offline
    stage saves once and a killed run of a slow remote backend loses at most ``interval``
    seconds of work (files it wrote meanwhile are on disk, but the document does not name
    them yet, so they are built again).
    """

    def __init__(self, folder: SceneFolder, scene: Scene, interval: float = 2.0,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.folder, self.scene, self.interval, self._clock = folder, scene, interval, clock
        self._last = clock()
        #: How many times the document was written (the benchmarks and tests read it).
        self.saves = 0

    def save(self) -> None:
        self.folder.save(self.scene)
        self.saves += 1
        self._last = self._clock()

    def checkpoint(self) -> None:
        if self._clock() - self._last >= self.interval:
            self.save()


def _path_problem(relative: object, kind: str | None) -> str | None:
    """Why ``relative`` cannot name a file of a scene folder, before the disk is looked at."""
    if not isinstance(relative, str) or not relative.strip():
        return "is not a file name"
    if "\x00" in relative or len(relative) > 1024:
        return "is not a usable path"
    if PurePosixPath(relative).is_absolute() or PureWindowsPath(relative).is_absolute() or relative.startswith("~"):
        return "is an absolute path"
    if kind is not None and PurePosixPath(relative).suffix.lower() not in KINDS[kind]:
        return f"is not a {kind} file (expected {', '.join(KINDS[kind])})"
    return None


def as_folder(folder: SceneFolder | str | Path) -> SceneFolder:
    """The scene folder a library caller named by path or passed as is."""
    return folder if isinstance(folder, SceneFolder) else SceneFolder(Path(folder))
