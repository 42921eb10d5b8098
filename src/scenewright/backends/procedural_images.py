"""The offline image generator: no pictures of the scene, procedural ground textures.

The texture code (PIL, scipy) is imported when a ground is drawn, not by every command that
creates the backends."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from scenewright.errors import InputError
from scenewright.scene import SceneObject
from scenewright.settings import Settings


class ProceduralImages:
    """Offline there is no image model: no reference or object images (the offline VLM and
    the procedural meshes work from text), and the ground is drawn procedurally."""

    name = "offline"

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> ProceduralImages:
        if argument:
            raise InputError(f"the offline image backend takes no argument, got {argument!r}; use 'offline'")
        return cls()

    def reference_image(self, text: str, style: str) -> bytes | None:
        return None

    def object_images(
        self,
        objects: Sequence[SceneObject],
        style: str,
        reference: bytes | None,
        progress: Callable[[str], None] | None = None,
    ) -> dict[str, bytes]:
        return {}

    def ground_texture(self, text: str, style: str, kind: str, reference: bytes | None) -> bytes:
        """A seamless 512×512 PNG of the ground kind (or of what the text says the ground is)."""
        from scenewright.procedural.meshes import seed_of
        from scenewright.procedural.style import resolve_style
        from scenewright.procedural.textures import ground_texture, normalise_kind, png_bytes

        texture_kind = normalise_kind(kind, text)
        style_name = resolve_style(style).name  # the seed's: "cartoon-style" draws the ground "cartoon" does
        image = ground_texture(texture_kind, style, seed_of(f"{texture_kind}|{style_name}|{text}"))  # in its colours
        return png_bytes(image)
