"""Spatial-semantic judging by the vision-language backend: Pos., Rot. and SA (1–100) on a render.

The rubric prompts live with the remote backend (``backends/prompts.py``). The offline
backend cannot judge and raises :class:`BackendError`; the scores are then reported as
unavailable with its reason, never made up.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field

from scenewright.core.protocols import VisionLanguageModel
from scenewright.errors import BackendError

log = logging.getLogger(__name__)

#: criterion passed to ``vlm.judge`` → the name the paper's table uses.
CRITERIA = {"positional": "pos", "rotational": "rot", "semantic": "sa"}


@dataclass
class Judgement:
    scores: dict[str, float] = field(default_factory=dict)
    unavailable: str | None = None


def judge(text: str, image: bytes, vlm: VisionLanguageModel) -> Judgement:
    """All three scores, or none with the reason the backend gave."""
    result = Judgement()
    for criterion, key in CRITERIA.items():
        try:
            result.scores[key] = float(vlm.judge(text, image, criterion))
        except BackendError as exc:
            log.warning("judging unavailable: %s", exc)
            return Judgement(unavailable=str(exc))
    return result


def psa(collision_free: bool, sa: float) -> float:
    """Physically-grounded semantic alignment of one scene: SA, zeroed when anything collides.

    The paper's PSA = CF × SA with CF the collision-free indicator; averaged over scenes
    this is the share of collision-free scenes weighted by their semantic alignment.
    """
    return sa if collision_free else 0.0
