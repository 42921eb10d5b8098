"""Export: the assembled ``scene.glb`` that Blender, Unreal and Godot open as it is."""

from scenewright.export.glb import assemble, node_matrix

__all__ = ["assemble", "node_matrix"]
