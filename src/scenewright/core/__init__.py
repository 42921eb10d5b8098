"""The low layer every stage shares: the backend protocols (:mod:`.protocols`), the edit plan
(:mod:`.plan`), the relation vocabulary (:mod:`.relations`) and the object catalogue
(:mod:`.catalogue`); the document itself is :mod:`scenewright.scene`, one layer below.

Nothing here imports a stage, a backend implementation or the CLI, and this ``__init__``
imports nothing, so ``import scenewright.core.plan`` loads the plan and the document only
(docs/architecture.md draws the layers).
"""
