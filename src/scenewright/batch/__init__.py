"""Many scenes at once: ``scenewright batch`` on a local process pool or a Ray cluster.

:mod:`~scenewright.batch.entries` reads the prompts, :mod:`~scenewright.batch.worker` makes
one scene in isolation, :mod:`~scenewright.batch.runner` schedules them, :mod:`~scenewright.batch.limits`
shares the remote backends' limits across workers and :mod:`~scenewright.batch.record` keeps
``batch.json``, ``batch.md`` and ``index.jsonl``. Ray is imported only when asked for.
"""

from scenewright.batch.entries import Entry, Problem, parse_seeds, read_entries
from scenewright.batch.runner import RayOptions, default_workers, run_batch

__all__ = ["Entry", "Problem", "RayOptions", "default_workers", "parse_seeds", "read_entries", "run_batch"]
