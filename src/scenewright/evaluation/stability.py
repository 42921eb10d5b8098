"""Physical stability: does the scene stay put when a simulator lets it settle?

The scene's MJCF is loaded in MuJoCo, run for :data:`SETTLE_SECONDS` of simulated time, and
each dynamic object's body frame (its bottom centre) is compared with where it started: an
object is stable when it moved less than :data:`MAX_SHIFT` and turned less than
:data:`MAX_TURN`. Static objects (fixtures, hanging things) cannot move and are not counted.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np

from scenewright.cache import RequestCache
from scenewright.errors import MissingExtra
from scenewright.export.mjcf import Mjcf, build_mjcf
from scenewright.export.physics import ensure_physics
from scenewright.folder import SceneFolder
from scenewright.scene import Scene

log = logging.getLogger(__name__)

SETTLE_SECONDS = 2.0
MAX_SHIFT = 0.02
MAX_TURN = 5.0


@dataclass
class Settled:
    id: str
    shift: float
    turn: float

    @property
    def stable(self) -> bool:
        return self.shift < MAX_SHIFT and self.turn < MAX_TURN


@dataclass
class Stability:
    objects: list[Settled] = field(default_factory=list)
    static: list[str] = field(default_factory=list)

    @property
    def unstable(self) -> list[Settled]:
        return [o for o in self.objects if not o.stable]

    @property
    def stable(self) -> bool:
        return not self.unstable

    def to_dict(self) -> dict:
        return {
            "stable": self.stable,
            "dynamic": len(self.objects),
            "stable_objects": len(self.objects) - len(self.unstable),
            "static": self.static,
            "unstable": [
                {"id": o.id, "shift_m": round(o.shift, 4), "turn_deg": round(o.turn, 2)} for o in self.unstable
            ],
        }


def load_mujoco():
    try:
        import mujoco
    except ImportError:
        raise MissingExtra("the physics check and MJCF loading", "sim", "mujoco") from None
    return mujoco


def _turn(q0: np.ndarray, q1: np.ndarray) -> float:
    """Angle (degrees) between two unit quaternions."""
    return float(np.degrees(2.0 * np.arccos(min(1.0, abs(float(np.dot(q0, q1)))))))


def settle(model: Mjcf, seconds: float = SETTLE_SECONDS) -> dict[str, tuple[float, float]]:
    """Body name → (metres moved, degrees turned) after ``seconds`` of simulation, for every
    body with a free joint; a run that blows up reports infinite motion for everything."""
    mujoco = load_mujoco()
    files = {name.split("/", 1)[1]: data for name, data in model.files.items()}
    spec = mujoco.MjModel.from_xml_string(model.xml, assets=files)
    data = mujoco.MjData(spec)
    mujoco.mj_forward(spec, data)
    bodies = [spec.jnt_bodyid[j] for j in range(spec.njnt) if spec.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    start = {b: (data.xpos[b].copy(), data.xquat[b].copy()) for b in bodies}
    steps = int(round(seconds / spec.opt.timestep))
    mujoco.mj_step(spec, data, nstep=steps)
    result = {}
    finite = bool(np.isfinite(data.qpos).all())
    for b in bodies:
        name = mujoco.mj_id2name(spec, mujoco.mjtObj.mjOBJ_BODY, b)
        if not finite:
            result[name] = (float("inf"), float("inf"))
            continue
        p0, q0 = start[b]
        result[name] = (float(np.linalg.norm(data.xpos[b] - p0)), _turn(q0, data.xquat[b]))
    return result


def stability(scene: Scene, folder: SceneFolder, cache: RequestCache, seconds: float = SETTLE_SECONDS) -> Stability:
    """Settle the scene in MuJoCo and say which dynamic objects stayed where they were."""
    load_mujoco()  # fail before any work when the extra is missing
    pieces = ensure_physics(scene, folder, cache)
    motion = settle(build_mjcf(scene, folder, pieces), seconds)
    result = Stability(static=[o.id for o in scene.objects if o.physics.static])
    for obj in scene.objects:
        if obj.id in motion:
            result.objects.append(Settled(obj.id, *motion[obj.id]))
    log.info("stability: %d of %d dynamic objects stable", len(result.objects) - len(result.unstable), len(result.objects))
    return result


def settle_check(metrics, scene: Scene, folder: SceneFolder, cache: RequestCache | None = None) -> None:
    """Put the settle check into an evaluation's metrics, or say why it could not run."""
    try:
        metrics.stability = stability(scene, folder, cache or RequestCache(None)).to_dict()
    except MissingExtra as exc:
        metrics.unavailable["stability"] = str(exc)


def stability_figures(results) -> dict:
    """Share of stable dynamic objects and of stable scenes (%) among the results that have the check."""
    checked = [r.stability for r in results if r.stability is not None]
    dynamic = sum(c["dynamic"] for c in checked)
    return {
        "stable_objects": round(100.0 * sum(c["stable_objects"] for c in checked) / dynamic, 2) if dynamic else None,
        "stable_scenes": round(100.0 * sum(c["stable"] for c in checked) / len(checked), 2) if checked else None,
    }
