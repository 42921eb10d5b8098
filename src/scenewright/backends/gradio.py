"""Image-to-3D on Gradio apps (TRELLIS, TRELLIS.2, Stable Fast 3D, TripoSR, Hunyuan3D-2mini).

These models ship a Gradio demo, and that is what most people run. Every Gradio app since 4.x
answers the same HTTP API (docs: "Querying Gradio Apps with Curl"), spoken here with httpx so
the deadline and size limits of :mod:`scenewright.backends.http` hold and no extra package is
needed: ``GET /config`` (the app's version and its API prefix, ``/gradio_api`` since 5.0),
``POST {prefix}/upload`` (files in, server paths out), ``POST {prefix}/call/{api}`` with
``{"data": [...], "session_hash"}`` (answered with an ``event_id``) and ``GET
{prefix}/call/{api}/{event_id}``, a server-sent event stream that ends in ``complete`` (the
outputs) or ``error``. File outputs are FileData objects (``path``, ``url``), fetched from
the server that made them.

The apps differ in their endpoints, so a *recipe* per app says which endpoints to call in
order, with which inputs (the image, the seed, a previous step's output, fixed settings), and
which output of the last step is the mesh. Steps share one session, as a browser tab does, so
state an app keeps between its buttons (TRELLIS keeps the generated latent in a ``gr.State``)
carries over; a ``gr.State`` slot is sent as null, as Gradio's own client sends it. A
recipe can be added or replaced in the settings (``[extra.gradio.recipes.NAME]``) when an app
version changes its endpoints. docs/remote.md says which app version each recipe follows.
"""

from __future__ import annotations

import json
import logging
import uuid
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any
from urllib.parse import urlsplit

from scenewright.assets.normalise import check_glb
from scenewright.core.protocols import MeshRequest
from scenewright.backends.scheduler import JobFailed, Server, ServerPool, server_urls
from scenewright.errors import InputError, MissingExtra
from scenewright.settings import Settings

try:
    import httpx
except ImportError:  # the remote extra; Gradio.__init__ says how to install it
    httpx = None  # type: ignore[assignment]

log = logging.getLogger(__name__)

#: Placeholders in a recipe's inputs.
IMAGE, SEED, STATE = "$image", "$seed", "$state"
PREVIOUS = "$prev"  # "$prev0": output 0 of the step before


@dataclass(frozen=True)
class Step:
    api: str
    inputs: tuple[Any, ...]


@dataclass(frozen=True)
class Recipe:
    """How one app turns an image into a mesh: the calls, and which output is the mesh."""

    name: str
    steps: tuple[Step, ...]
    #: Index of the mesh file (GLB, or OBJ that is converted) among the last step's outputs.
    output: int
    #: The app file and version the endpoints were read from.
    source: str

    def as_params(self) -> dict[str, Any]:
        """What goes into the cache key: a changed recipe builds other meshes."""
        return {"recipe": self.name, "steps": [[s.api, list(s.inputs)] for s in self.steps], "output": self.output}


RECIPES: dict[str, Recipe] = {
    recipe.name: recipe
    for recipe in (
        Recipe(
            "trellis",
            (
                Step("/preprocess_image", (IMAGE,)),
                # image, multi-images, detail-variation image, raw mesh, demo mode (state), seed,
                # sparse-structure guidance and steps, latent guidance and steps, multi-image algorithm
                Step("/image_to_3d", (f"{PREVIOUS}0", [], None, None, STATE, SEED, 7.5, 12, 3.0, 12, "stochastic")),
                # latent (state), sRGB texture, bake mode, simplify ratio, texture size
                Step("/extract_mesh", (STATE, False, "fast", 0.95, 1024)),
            ),
            output=1,
            source="microsoft/TRELLIS app.py (2025, with detail variation)",
        ),
        Recipe(
            "trellis2",
            (
                Step("/preprocess_image", (IMAGE,)),
                Step("/image_to_3d", (f"{PREVIOUS}0", SEED, "1024", 7.5, 0.7, 12, 5.0, 7.5, 0.5, 12, 3.0,
                                      1.0, 0.0, 12, 3.0)),
                Step("/extract_glb", (STATE, 500000, 2048)),
            ),
            output=1,
            source="microsoft/TRELLIS.2 app.py",
        ),
        Recipe(
            "sf3d",
            (
                # An image with transparency is cropped and kept in the session's state.
                Step("/requires_bg_remove", (IMAGE, 0.85)),
                Step("/run_button", ("Run", IMAGE, STATE, 0.85, "None", -1, 1024)),
            ),
            output=4,
            source="Stability-AI/stable-fast-3d gradio_app.py",
        ),
        Recipe(
            "triposr",
            (
                Step("/preprocess", (IMAGE, True, 0.85)),
                Step("/generate", (f"{PREVIOUS}0",)),
            ),
            output=0,
            source="VAST-AI-Research/TripoSR gradio_app.py (answers an OBJ)",
        ),
        Recipe(
            "hunyuan3d-2mini",
            (
                # caption, image, four multi-view images, steps, guidance, seed, octree resolution,
                # remove background, chunks, randomise seed
                Step("/generation_all", (None, IMAGE, None, None, None, None, 30, 5.0, SEED, 256, True, 8000, False)),
            ),
            output=1,
            source="Tencent/Hunyuan3D-2 gradio_app.py (multi-view version, --model_path tencent/Hunyuan3D-2mini)",
        ),
    )
}


def recipe_from_settings(name: str, table: Mapping[str, Any]) -> Recipe:
    """A recipe written in the settings: ``steps = [{api = "/x", inputs = [...]}]``, ``output = N``."""
    try:
        steps = tuple(Step(str(s["api"]), tuple(s["inputs"])) for s in table["steps"])
        output = int(table["output"])
    except (KeyError, TypeError, ValueError) as exc:
        raise InputError(
            f"gradio recipe {name!r} in the settings needs steps = [{{api = \"/endpoint\", inputs = [...]}}, ...] "
            f"and output = N (the mesh's index among the last step's outputs); problem: {exc!r}"
        ) from None
    if not steps or not all(s.api.startswith("/") for s in steps):
        raise InputError(f"gradio recipe {name!r}: every step needs an api name starting with '/'")
    return Recipe(name, steps, output, source="settings")


class Gradio(ServerPool):
    """MeshGenerator over one or more servers running the same Gradio image-to-3D app."""

    name = "gradio"
    label = "Gradio app"

    def __init__(
        self,
        urls: Sequence[str],
        recipe: Recipe,
        *,
        concurrency: int = 1,
        seed: int = 1234,
        timeout: float = 120.0,
        job_timeout: float = 1800.0,
        reprobe_interval: float = 60.0,
        max_failures: int = 3,
        max_download_bytes: int = Settings.max_download_bytes,
    ):
        if httpx is None:
            raise MissingExtra("the Gradio mesh backend", "remote", "httpx")
        super().__init__(urls, concurrency=concurrency, max_failures=max_failures, reprobe_interval=reprobe_interval,
                         timeout=timeout, max_download_bytes=max_download_bytes)
        self.recipe = recipe
        self.seed = seed
        self.job_timeout = job_timeout
        self.params = {**recipe.as_params(), "seed": seed}
        self._prefix: dict[str, str] = {}

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> Gradio:
        """``http://gpu1:7860,http://gpu2:7860#trellis``; tuning from ``settings.extra["gradio"]``."""
        urls_text, _, name = argument.rpartition("#")
        example = "--meshes gradio:http://gpu1:7860#trellis"
        if not name or not urls_text:
            raise InputError(f"the gradio backend needs server URLs and an app recipe: {example} "
                             f"(recipes: {', '.join(RECIPES)})")
        extra = dict(settings.extra.get("gradio", {}) or {})
        custom = {n: recipe_from_settings(n, t) for n, t in dict(extra.pop("recipes", {}) or {}).items()}
        recipes = {**RECIPES, **custom}
        if name not in recipes:
            raise InputError(f"unknown gradio recipe {name!r}; choose one of: {', '.join(recipes)} "
                             "or write one under [extra.gradio.recipes.NAME] in the settings")
        knobs = ("seed", "job_timeout", "reprobe_interval", "max_failures")
        unknown = set(extra) - set(knobs)
        if unknown:
            raise InputError(f"unknown gradio settings {sorted(unknown)}; valid ones: recipes, {', '.join(knobs)}")
        return cls(
            server_urls(urls_text, "gradio", example), recipes[name], concurrency=settings.mesh_concurrency,
            timeout=settings.timeout, max_download_bytes=settings.max_download_bytes, **extra,
        )


    # -- the protocol ---------------------------------------------------------------------

    def _health(self, server: Server) -> tuple[str | None, str | None]:
        """The app answers ``/config`` with JSON; its API prefix is kept for the calls."""
        try:
            response = self._client.get(f"{server.url}/config")
            config = response.json()
        except httpx.HTTPError as exc:
            return f"unreachable ({exc})", None
        except ValueError:
            return f"/config answered HTTP {response.status_code} with a body that is not JSON (not a Gradio app?)", None
        if response.status_code != 200 or not isinstance(config, dict):
            return f"/config answered HTTP {response.status_code}", None
        prefix = config.get("api_prefix") or ""
        self._prefix[server.url] = prefix.rstrip("/") if isinstance(prefix, str) else ""
        return None, str(config.get("version")) if config.get("version") else None

    def _run(self, server: Server, request: MeshRequest, progress: Callable[[str], None] | None) -> bytes:
        assert request.image is not None
        base = server.url + self._prefix.get(server.url, "")
        session = uuid.uuid4().hex[:11]
        try:
            uploaded = self._upload(base, request.image)
            outputs: list[Any] = []
            for number, step in enumerate(self.recipe.steps, start=1):
                if self._cancelled.is_set():
                    raise JobFailed("abandoned: the run was interrupted")
                data = [self._fill(value, uploaded, outputs, step) for value in step.inputs]
                outputs = self._call(base, step.api, data, session)
                if progress:
                    progress(f"{request.id}: {self.recipe.name} step {number} of {len(self.recipe.steps)} "
                             f"({step.api}) on {server.url}")
            return self._mesh(server.url, base, outputs)
        except httpx.HTTPError as exc:
            raise JobFailed(f"connection failed ({type(exc).__name__}: {exc})") from None

    def _fill(self, value: Any, uploaded: dict[str, Any], outputs: list[Any], step: Step) -> Any:
        if value == IMAGE:
            return uploaded
        if value == SEED:
            return self.seed
        if value == STATE:
            return None
        if isinstance(value, str) and value.startswith(PREVIOUS):
            index = int(value.removeprefix(PREVIOUS))
            if index >= len(outputs):
                raise JobFailed(f"{step.api} needs output {index} of the step before, which gave {len(outputs)}")
            return outputs[index]
        return value

    def _upload(self, base: str, image: bytes) -> dict[str, Any]:
        response = self._client.post(f"{base}/upload", files=[("files", ("object.png", image, "image/png"))])
        paths = _json(response)
        if response.status_code != 200 or not isinstance(paths, list) or not paths or not isinstance(paths[0], str):
            raise JobFailed(f"/upload answered HTTP {response.status_code}: {_excerpt(response)}")
        return {"path": paths[0], "orig_name": "object.png", "mime_type": "image/png",
                "meta": {"_type": "gradio.FileData"}}

    def _call(self, base: str, api: str, data: list[Any], session: str) -> list[Any]:
        response = self._client.post(f"{base}/call{api}", json={"data": data, "session_hash": session})
        body = _json(response)
        if response.status_code != 200 or not isinstance(body, dict) or not isinstance(body.get("event_id"), str):
            raise JobFailed(f"{api} answered HTTP {response.status_code}: {_excerpt(response)}")
        timeout = httpx.Timeout(self.job_timeout, connect=10.0)
        with self._client.stream("GET", f"{base}/call{api}/{body['event_id']}", timeout=timeout) as stream:
            if stream.status_code != 200:
                stream.read()
                raise JobFailed(f"{api} result answered HTTP {stream.status_code}: {_excerpt(stream)}")
            event = None
            for line in stream.iter_lines():
                if self._cancelled.is_set():
                    raise JobFailed("abandoned: the run was interrupted")
                if line.startswith("event:"):
                    event = line.removeprefix("event:").strip()
                elif line.startswith("data:") and event in ("complete", "error"):
                    payload = line.removeprefix("data:").strip()
                    if event == "error":
                        raise JobFailed(f"{api} ended in error: {_error_text(payload)}")
                    try:
                        outputs = json.loads(payload)
                    except ValueError:
                        raise JobFailed(f"{api} completed with data that is not JSON: {payload[:200]!r}") from None
                    if not isinstance(outputs, list):
                        raise JobFailed(f"{api} completed with {type(outputs).__name__} instead of a list of outputs")
                    return outputs
        raise JobFailed(f"{api}: the event stream ended without a result")

    def _mesh(self, server_url: str, base: str, outputs: list[Any]) -> bytes:
        """The mesh file among the last outputs, downloaded from the server that made it; an
        OBJ (TripoSR) is converted to GLB."""
        index = self.recipe.output
        item = outputs[index] if index < len(outputs) else None
        if isinstance(item, dict) and "value" in item and "path" not in item:  # a gr.update(value=...)
            item = item["value"]
        if not isinstance(item, dict) or not isinstance(item.get("path"), str):
            raise JobFailed(f"output {index} of {self.recipe.steps[-1].api} is not a file: {str(item)[:200]!r}")
        url = item.get("url")
        if not isinstance(url, str) or _origin(url) != _origin(server_url):
            # Only the app's own files are fetched, whatever URL an answer names.
            url = f"{base}/file={item['path']}"
        response = self._client.get(url)
        if response.status_code != 200:
            raise JobFailed(f"the mesh file answered HTTP {response.status_code}: {_excerpt(response)}")
        data = response.content
        if check_glb(data) is None:
            return data
        if item["path"].lower().endswith(".obj"):
            return _obj_to_glb(data)
        raise JobFailed(f"output {index} is not a GLB: {check_glb(data)}")


def _obj_to_glb(data: bytes) -> bytes:
    import io

    import trimesh

    try:
        mesh = trimesh.load(io.BytesIO(data), file_type="obj", force="mesh")
    except Exception as exc:  # trimesh raises many kinds on malformed files
        raise JobFailed(f"the OBJ the app answered cannot be read: {exc}") from None
    if not len(getattr(mesh, "faces", ())):
        raise JobFailed("the OBJ the app answered has no faces")
    return trimesh.Scene(mesh).export(file_type="glb")


def _origin(url: str) -> tuple[str, str]:
    parts = urlsplit(url)
    return parts.scheme, parts.netloc


def _error_text(payload: str) -> str:
    try:
        value = json.loads(payload)
    except ValueError:
        return payload[:300] or "no message"
    if isinstance(value, dict):
        value = value.get("error") or value.get("message") or value
    return str(value)[:300] if value else "no message (the app raised an exception; see its log)"


def _json(response: httpx.Response) -> Any:
    try:
        return response.json()
    except ValueError:
        return None


def _excerpt(response: httpx.Response) -> str:
    text = response.text.strip().replace("\n", " ")
    return repr(text[:200]) if text else "(empty body)"
