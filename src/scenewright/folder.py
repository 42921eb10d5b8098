"""The scene folder of DESIGN.md §2: where each file of a scene lives.

One class names the paths so no stage spells them out; :meth:`SceneFolder.create` refuses
to write into a folder that holds something other than a scene, so nothing is overwritten
by mistake.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from scenewright.errors import InputError
from scenewright.scene import Scene


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

    def resolve(self, relative: str) -> Path:
        return self.root / relative

    def is_scene(self) -> bool:
        return self.document.is_file()

    def load(self) -> Scene:
        if not self.is_scene():
            raise InputError(
                f"{self.root} is not a scene folder (no scene.json); "
                "create one with `scenewright generate TEXT --out DIR`"
            )
        return Scene.load(self.document)

    def save(self, scene: Scene) -> Path:
        return scene.save(self.document)

    def create(self) -> None:
        """Make the folder ready for a new scene, refusing anything that would lose files."""
        if self.root.exists() and not self.root.is_dir():
            raise InputError(f"{self.root} exists and is not a folder; choose another --out")
        if self.root.is_dir() and any(self.root.iterdir()) and not self.is_scene():
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
