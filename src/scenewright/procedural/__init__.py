"""Offline assets: styled parametric meshes per object and tileable ground textures.

``SHAPES`` maps each name of the catalogue's shape vocabulary to its generator;
:class:`~scenewright.procedural.meshes.ProceduralMeshes` and
:class:`~scenewright.procedural.images.ProceduralImages` are the offline backends.
"""

from scenewright.procedural.shapes import SHAPES

__all__ = ["SHAPES"]
