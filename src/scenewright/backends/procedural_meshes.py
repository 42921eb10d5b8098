"""The offline mesh backend: a styled parametric model per request (:mod:`scenewright.procedural`).

The generators (and trimesh under them) are imported when a mesh is asked for: every command
creates its backends, and an edit that moves things never builds one.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Sequence

import numpy as np

from scenewright.core.protocols import MeshRequest
from scenewright.errors import BackendError, InputError
from scenewright.settings import Settings

log = logging.getLogger(__name__)


class ProceduralMeshes:
    """Parametric styled meshes, offline and instant; the default mesh backend."""

    name = "procedural"
    #: Building is CPU-bound Python; threads would only queue on the interpreter lock.
    concurrency = 1
    #: Each mesh is built to its box in the stored asset convention, so storing it needs no
    #: mesh library (:func:`scenewright.assets.normalise.stored_glb`).
    in_convention = True

    @property
    def params(self) -> dict[str, str]:
        """What else decides the output (part of the asset cache key): the generators' code."""
        from scenewright.procedural.meshes import code_fingerprint

        return {"code": code_fingerprint()}

    def cancel(self) -> None:
        """Nothing runs in the background: each model is built inside ``generate``."""

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> ProceduralMeshes:
        if argument:
            raise InputError(f"the procedural mesh backend takes no argument, got {argument!r}; use 'procedural'")
        return cls()

    def generate(
        self, requests: Sequence[MeshRequest], progress: Callable[[str], None] | None = None
    ) -> dict[str, bytes]:
        from scenewright.procedural.meshes import build_glb, choose_shape, seed_of

        results: dict[str, bytes] = {}
        failures: list[str] = []
        for request in requests:
            shape = choose_shape(request.name, request.category)
            try:
                name = f"{request.name} {request.category or ''}".strip()
                results[request.id] = build_glb(
                    shape, request.size.tuple(), request.style, seed_of(request.id), request.description, name
                )
            except (ValueError, np.linalg.LinAlgError) as exc:
                failures.append(f"{request.id} ({shape}): {exc}")
                continue
            log.debug("built %s as %s in %s style", request.id, shape, request.style)
            if progress is not None:
                progress(f"{request.id}: {shape}")
        if failures:
            raise BackendError("procedural meshes failed for: " + "; ".join(failures))
        return results
