"""Object generation: one normalised GLB per object, from any mesh backend, cached and resumable.

The stored convention (docs/architecture.md, "Frames and units"): glTF axes, footprint centred at the origin, bottom at
y = 0, scaled to the object's height. :func:`load_meshes` hands the same assets to the
solver and evaluation in the scene frame (bottom at z = 0, front −Y).

The names are imported on first use (PEP 562), so reading stored assets (:mod:`.load`, what an
edit does) does not import the mesh library that making new ones (:mod:`.normalise`) needs.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

_LAZY = {
    "asset_mesh": "scenewright.assets.load",
    "load_meshes": "scenewright.assets.load",
    "generate_assets": "scenewright.assets.stage",
}

if TYPE_CHECKING:
    from scenewright.assets.load import asset_mesh, load_meshes
    from scenewright.assets.stage import generate_assets

#: ``normalise`` is its module's name here (``scenewright.assets.normalise.normalise`` the function):
#: a package attribute of the same name would be the module or the function depending on
#: what was imported first.
__all__ = ["asset_mesh", "generate_assets", "load_meshes"]


def __getattr__(name: str) -> Any:
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'scenewright.assets' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value
