"""Object generation: one normalised GLB per object, from any mesh backend, cached and resumable.

The stored convention (docs/architecture.md, "Frames and units"): glTF axes, footprint centred at the origin, bottom at
y = 0, scaled to the object's height. :func:`load_meshes` hands the same assets to the
solver and evaluation in the scene frame (bottom at z = 0, front −Y).
"""

from scenewright.assets.load import asset_mesh, load_meshes
from scenewright.assets.normalise import normalise
from scenewright.assets.stage import generate_assets

__all__ = ["asset_mesh", "generate_assets", "load_meshes", "normalise"]
