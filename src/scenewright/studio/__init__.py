"""``scenewright studio``: a local browser editor on a scene folder.

:mod:`scenewright.studio.session` holds the editing state and needs no browser library, so it
is tested on its own; :mod:`scenewright.studio.server` draws it with viser (the ``studio``
extra), imported only when the editor starts.
"""

from scenewright.studio.panel import ConstraintState, ObjectPanel, object_panel
from scenewright.studio.session import Session, inside

__all__ = ["ConstraintState", "ObjectPanel", "Session", "inside", "object_panel"]
