"""The image generator behind the OpenAI Images API (``gpt-image-1`` or any compatible server).

The reference image comes from ``images.generate``; every object image and the ground texture
come from ``images.edit`` with the reference image as input, so they share its style and
shapes (``images.generate`` stands in when there is no reference). Object images are drawn
concurrently, at most ``settings.image_concurrency`` at a time, and every answer is cached by
a hash of its request: a resumed run only pays for the images it does not have yet.
"""

from __future__ import annotations

import base64
import io
import logging
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor, as_completed
from typing import Any

from scenewright.backends import prompts
from scenewright.backends.structured import RemoteModel, image_mime, model_name, sdk_errors, transport_error
from scenewright.cache import request_key
from scenewright.errors import BackendError
from scenewright.scene import SceneObject
from scenewright.settings import Settings

log = logging.getLogger(__name__)

DEFAULT_MODEL = "gpt-image-1"
REFERENCE_SIZE = "1536x1024"
SQUARE = "1024x1024"


class OpenAIImages(RemoteModel):
    """ImageGenerator over ``images.generate`` / ``images.edit``."""

    name = "openai"

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> OpenAIImages:
        images = cls(model_name(argument, DEFAULT_MODEL), settings)
        images.preflight()  # before the run pays for anything
        return images

    def reference_image(self, text: str, style: str) -> bytes:
        return self._draw("reference image", prompts.reference_image(text, style), None, size=REFERENCE_SIZE)

    def object_images(
        self,
        objects: Sequence[SceneObject],
        style: str,
        reference: bytes | None,
        progress: Callable[[str], None] | None = None,
    ) -> dict[str, bytes]:
        """One transparent, front-view PNG per object; a failed object fails the call, but
        only after the others are finished and cached. Objects described alike (a pair of
        matching chairs) share one picture, drawn once."""
        prompts_by_id = {obj.id: prompts.object_image(obj.name, obj.visual_description, style) for obj in objects}
        unique = list(dict.fromkeys(prompts_by_id.values()))

        def draw(prompt: str) -> bytes:
            ids = ", ".join(i for i, p in prompts_by_id.items() if p == prompt)
            data = self._draw(f"image of {ids}", prompt, reference, size=SQUARE, background="transparent")
            if not _has_alpha(data):
                log.warning("the image of %s has no transparency; its background reaches the mesh backend", ids)
            return data

        drawn: dict[str, bytes] = {}
        failures: list[str] = []
        workers = max(1, min(self.settings.image_concurrency, len(unique)))
        pool = ThreadPoolExecutor(max_workers=workers, thread_name_prefix="openai-images")
        try:
            futures = {pool.submit(draw, prompt): prompt for prompt in unique}
            for future in as_completed(futures):
                prompt = futures[future]
                try:
                    drawn[prompt] = future.result()
                except BackendError as exc:
                    failures.append(str(exc))
                if progress is not None:
                    for object_id in (i for i, p in prompts_by_id.items() if p == prompt):
                        progress(f"{object_id}: image {len(drawn) + len(failures)} of {len(unique)}")
        finally:
            # Ctrl-C: images not yet requested are never requested (nor paid for); those in
            # flight finish in the background and land in the cache for the resumed run.
            pool.shutdown(wait=False, cancel_futures=True)
        if failures:
            raise BackendError(
                f"{len(failures)} of {len(unique)} object images failed (the others are cached): "
                + "; ".join(failures)
            )
        return {object_id: drawn[prompt] for object_id, prompt in prompts_by_id.items()}

    def ground_texture(self, text: str, style: str, kind: str, reference: bytes | None) -> bytes:
        return self._draw("ground texture", prompts.ground_texture(text, style, kind), reference, size=SQUARE)

    def _draw(self, what: str, prompt: str, reference: bytes | None, **params: Any) -> bytes:
        endpoint = "edit" if reference is not None else "generate"
        request = {"model": self.model, "prompt": prompt, "n": 1, **params}
        key = request_key("openai-images", self.settings.base_url, endpoint, request, reference or b"")
        cached = self.cache.get("images", key)
        if cached is not None:
            return cached
        try:
            if reference is not None:
                extension = image_mime(reference).split("/")[1]
                response = self.client.images.edit(
                    image=(f"reference.{extension}", reference, image_mime(reference)), **request
                )
            else:
                response = self.client.images.generate(**request)
        except sdk_errors() as exc:
            raise transport_error(f"{what} ({self.model})", exc) from exc
        data = self._image_bytes(what, response)
        self.cache.put("images", key, data)
        return data

    def _image_bytes(self, what: str, response: Any) -> bytes:
        """PNG bytes from the answer's first image (base64, or a URL some servers return)."""
        items = getattr(response, "data", None) or []
        if not items:
            raise BackendError(f"{what} ({self.model}): the server returned no image")
        item = items[0]
        if item.b64_json:
            try:
                data = base64.b64decode(item.b64_json, validate=True)
            except ValueError as exc:
                raise BackendError(f"{what} ({self.model}): the image is not valid base64 ({exc})") from None
        elif item.url:
            import httpx

            try:
                reply = httpx.get(item.url, timeout=self.settings.timeout, follow_redirects=True)
                reply.raise_for_status()
            except httpx.HTTPError as exc:
                raise BackendError(f"{what} ({self.model}): cannot download {item.url}: {exc}") from None
            data = reply.content
        else:
            raise BackendError(f"{what} ({self.model}): the answer holds neither b64_json nor url")
        return _as_png(what, data)


def _as_png(what: str, data: bytes) -> bytes:
    """The image as PNG (the scene folder stores PNG), refusing anything that is not an image."""
    from PIL import Image, UnidentifiedImageError

    if data.startswith(b"\x89PNG"):
        return data
    try:
        with Image.open(io.BytesIO(data)) as image:
            out = io.BytesIO()
            image.save(out, format="PNG")
            return out.getvalue()
    except (UnidentifiedImageError, OSError) as exc:
        raise BackendError(f"{what}: the server's answer is not an image ({exc})") from None


def _has_alpha(png: bytes) -> bool:
    from PIL import Image

    with Image.open(io.BytesIO(png)) as image:
        return image.mode in ("RGBA", "LA", "PA") or "transparency" in image.info
