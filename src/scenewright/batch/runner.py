"""Run every entry of a batch on a local process pool or on Ray, and keep the record current.

The parent process only schedules and records: each finished scene updates ``batch.json``,
``batch.md`` and ``index.jsonl`` at once (atomically), so a batch killed at any moment leaves
a record of everything that finished, and a re-run picks up from the folders themselves.

Local: :class:`concurrent.futures.ProcessPoolExecutor` with the ``spawn`` context (no forked
copies of a parent's threads or locks). A worker that dies (out of memory, a crash in native
code) breaks the pool; the scenes it took down are tried once more in a fresh pool, then
recorded as failed. Ctrl-C: queued scenes are cancelled, running ones are asked to stop at
their next step (each keeps what it finished); a second Ctrl-C ends the workers at once.

Ray (the ``batch`` extra): one task per scene with its resources declared, the limit table in
one actor; ``address="auto"`` joins a running cluster, ``None`` starts a local instance.
"""

from __future__ import annotations

import logging
import multiprocessing
import os
import signal
import time
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from scenewright.batch.entries import Entry, Problem
from scenewright.batch.limits import ActorSlots, FileSlots, Limits, SlotTable
from scenewright.batch.record import Record
from scenewright.batch.worker import Job, Outcome, finished_outcome, init_worker, outcome, run_scene
from scenewright.errors import InputError, MissingExtra
from scenewright.settings import Settings

log = logging.getLogger(__name__)

#: Called with each scene's outcome as it arrives (the CLI's progress bar).
OnOutcome = Callable[[Outcome], None]


@dataclass(frozen=True)
class RayOptions:
    """Where and how to run on Ray: ``address`` (``"auto"``, ``ray://host:10001``, or None for a
    local instance of ``num_cpus``), and the resources each scene's task declares."""

    address: str | None = None
    num_cpus: int | None = None
    cpus_per_scene: float = 1.0
    gpus_per_scene: float = 0.0


def default_workers() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not Linux
        return max(1, os.cpu_count() or 1)


def import_ray():
    try:
        import ray
    except ImportError as exc:
        raise MissingExtra("running a batch on Ray", "batch", "ray") from exc
    return ray


def run_batch(
    entries: Sequence[Entry],
    out: str | Path,
    *,
    settings: Settings,
    workers: int | None = None,
    render: bool = True,
    ray: RayOptions | None = None,
    remote_limit: int | None = None,
    requests_per_minute: int | None = None,
    problems: Sequence[Problem] = (),
    source: str = "",
    on_outcome: OnOutcome | None = None,
) -> Record:
    """Make every entry's scene under ``out/<id>``; returns the record (also on disk).

    ``remote_limit`` is the number of requests in flight to any one OpenAI-compatible server
    across all workers (default ``settings.image_concurrency``); a Hunyuan3D server takes
    ``settings.mesh_concurrency`` jobs from all workers together; ``requests_per_minute`` spaces
    the requests to each server (None: no such limit). A KeyboardInterrupt stops
    the batch cleanly: the record says ``interrupted`` and the call returns normally.
    """
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InputError(f"{out} exists and is not a folder; choose another --out")
    clash = [e.id for e in entries if (out / e.id).exists() and not (out / e.id).is_dir()]
    if clash:
        raise InputError(f"{out} holds files named like scenes ({', '.join(clash[:5])}); choose another --out")
    out.mkdir(parents=True, exist_ok=True)
    workers = workers or (ray.num_cpus if ray and ray.num_cpus else default_workers())
    if workers < 1:
        raise InputError(f"--workers must be at least 1, got {workers}")
    if remote_limit is not None and remote_limit < 1:
        raise InputError(f"--remote-limit must be at least 1, got {remote_limit}")
    if requests_per_minute is not None and requests_per_minute < 1:
        raise InputError(f"--requests-per-minute must be at least 1, got {requests_per_minute}")
    limit = remote_limit or settings.image_concurrency
    record = Record(out, entries, problems, source=source, executor="ray" if ray else "local", workers=workers)
    start = time.perf_counter()

    def arrived(outcome: Outcome) -> None:
        record.add(outcome)
        record.seconds = time.perf_counter() - start
        record.write()
        if on_outcome is not None:
            on_outcome(outcome)

    jobs = []
    for entry in entries:  # finished scenes are recorded here, without a worker
        earlier = finished_outcome(entry, out, render)
        if earlier is not None:
            record.add(earlier)
            if on_outcome is not None:
                on_outcome(earlier)
        else:
            jobs.append(Job(entry=entry, out=out.absolute(), settings=settings, render=render))
    record.write()
    if not jobs:
        return record
    try:
        if ray is None:
            limits = Limits(FileSlots(out.absolute() / ".limits"), limit, requests_per_minute)
            _run_local([replace(j, limits=limits) for j in jobs], workers, arrived, record)
        else:
            _run_ray(jobs, ray, workers, limit, requests_per_minute, arrived, record)
    except KeyboardInterrupt:  # between two waits; the workers had the signal too and stop
        record.interrupted = True
    finally:
        record.seconds = time.perf_counter() - start
        record.write()
    return record


# --- local ------------------------------------------------------------------------------------

def _run_local(jobs: list[Job], workers: int, arrived: OnOutcome, record: Record) -> None:
    context = multiprocessing.get_context("spawn")
    pending, retried = jobs, set()
    while pending and not record.interrupted:
        lost = _pool_round(pending, workers, context, arrived, record)
        pending = []
        for job in lost:
            if job.entry.id in retried:
                arrived(_crashed(job, "its worker process died twice while it ran (out of memory or a native crash)"))
            else:
                retried.add(job.entry.id)
                pending.append(job)


def _pool_round(jobs: list[Job], workers: int, context, arrived: OnOutcome, record: Record) -> list[Job]:
    """Run ``jobs`` in one pool; returns the ones a broken pool took down.

    A future leaves ``unrecorded`` only after its outcome is recorded, so a Ctrl-C that lands
    while one is being recorded loses nothing: the next turn of the loop records it again.
    """
    lost: list[Job] = []
    level = logging.getLogger().getEffectiveLevel()
    pool = ProcessPoolExecutor(
        max_workers=min(workers, len(jobs)), mp_context=context, initializer=init_worker, initargs=(level,)
    )
    try:
        futures = {pool.submit(run_scene, job): job for job in jobs}
        unrecorded = set(futures)
        stopping = False
        while unrecorded:
            try:
                finished, _ = wait(unrecorded, return_when=FIRST_COMPLETED)
                for future in finished:
                    if future.cancelled():
                        arrived(_interrupted(futures[future], "not started"))
                    else:
                        try:
                            arrived(future.result())
                        except BrokenProcessPool:
                            lost.append(futures[future])
                    unrecorded.discard(future)
            except KeyboardInterrupt:
                if stopping:  # the second Ctrl-C: end the workers now
                    _signal_workers(kill=True)
                    _give_up(unrecorded, futures, arrived, "ended by a second Ctrl-C; a re-run resumes it")
                    break
                stopping = record.interrupted = True
                log.warning("stopping: queued scenes cancelled, running ones stop at their next step")
                for future in unrecorded:
                    future.cancel()
                _signal_workers(kill=False)
    except BaseException:
        _signal_workers(kill=False)  # whatever escapes, running scenes stop at their next step
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    return lost


def _signal_workers(kill: bool) -> None:
    """SIGINT (stop at the next step) or SIGKILL to this process's pool workers."""
    for child in multiprocessing.active_children():
        try:
            os.kill(child.pid, signal.SIGKILL if kill else signal.SIGINT)
        except (ProcessLookupError, TypeError):
            pass


def _give_up(waiting, futures, arrived: OnOutcome, reason: str) -> None:
    for future in waiting:
        arrived(_interrupted(futures[future], reason))


def _interrupted(job: Job, reason: str) -> Outcome:
    return outcome(job.entry, "interrupted", {}, reason=reason)


def _crashed(job: Job, reason: str) -> Outcome:
    return outcome(job.entry, "failed", {}, reason=reason, error="crash")


# --- Ray --------------------------------------------------------------------------------------

def _run_ray(
    jobs: list[Job], options: RayOptions, workers: int, limit: int, per_minute: int | None, arrived: OnOutcome,
    record: Record,
) -> None:
    ray = import_ray()
    started_here = not ray.is_initialized()
    if started_here:
        kwargs: dict[str, Any] = {"include_dashboard": False, "log_to_driver": False}
        if options.address:
            kwargs["address"] = options.address
        else:
            kwargs["num_cpus"] = options.num_cpus or workers
        ray.init(**kwargs)
    try:
        table = ray.remote(num_cpus=0)(SlotTable).remote()
        limits = Limits(ActorSlots(table), limit, per_minute)
        task = ray.remote(num_cpus=options.cpus_per_scene, num_gpus=options.gpus_per_scene, max_retries=1)(run_scene)
        refs = {task.remote(replace(job, limits=limits)): job for job in jobs}
        waiting = list(refs)
        try:
            while waiting:
                ready, waiting = ray.wait(waiting, num_returns=1)
                for ref in ready:
                    try:
                        arrived(ray.get(ref))
                    except ray.exceptions.RayError as exc:
                        arrived(_crashed(refs[ref], f"the Ray task failed: {str(exc).splitlines()[0]}"))
        except KeyboardInterrupt:
            record.interrupted = True
            for ref in waiting:
                ray.cancel(ref)
            _give_up(waiting, refs, arrived, "cancelled by Ctrl-C; a re-run resumes it")
    finally:
        if started_here:
            ray.shutdown()
