"""Offline assets: styled parametric meshes per object and tileable ground textures.

``SHAPES`` maps each name of the catalogue's shape vocabulary to its generator;
:class:`~scenewright.backends.procedural_meshes.ProceduralMeshes` and
:class:`~scenewright.backends.procedural_images.ProceduralImages` are the offline backends
built on them.
"""

from scenewright.procedural.shapes import SHAPES

__all__ = ["SHAPES"]
