"""Scene editing by language (paper §3.4): move, add, delete, replace — with history and undo.

Heavy pieces (the layout solver, assets, export) load with :mod:`scenewright.editing.apply`;
the plan and the offline parser stay light so backends can import them.
"""

from scenewright.editing.apply import apply_edit, run_plan, validate_plan
from scenewright.editing.history import entries, redo, undo
from scenewright.core.plan import EditPlan, NewObject

__all__ = ["EditPlan", "NewObject", "apply_edit", "entries", "redo", "run_plan", "undo", "validate_plan"]
