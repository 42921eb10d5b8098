"""The layout engine: the ten relations, mesh-level collision, and the DFS solver.

``check``/``violation`` are the one definition of each relation (paper Table 3), used by the
solver, editing, tests and evaluation alike. The pipeline stage that asks a model for
constraints and runs the feedback loop is :mod:`scenewright.layout.stage`.
"""

from scenewright.layout.collision import colliding_pairs
from scenewright.layout.constraints import break_cycles, clean_constraints, topological_order
from scenewright.layout.relations import check, violation
from scenewright.layout.report import feedback_text
from scenewright.layout.solver import LayoutResult, audit, solve

__all__ = [
    "LayoutResult",
    "audit",
    "break_cycles",
    "check",
    "clean_constraints",
    "colliding_pairs",
    "feedback_text",
    "solve",
    "topological_order",
    "violation",
]
