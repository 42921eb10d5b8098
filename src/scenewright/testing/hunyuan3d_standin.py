"""A stand-in Hunyuan3D-2.1 API server on 127.0.0.1, for protocol tests and the assets benchmark.

It speaks the real server's endpoints (``/health``, ``/send``, ``/status/{uid}``,
``/generate``) with the same bodies, runs its jobs one after another like a single GPU, and
can misbehave on purpose the ways real servers do: die in the middle of a job, restart and
forget its jobs (still answering ``processing`` for them, as the real one does), report an
``error`` status, send base64 that does not decode or bytes that are not a GLB, or lack the
job endpoints altogether, or turn a job away at once (``reject``: HTTP 500 from ``/send``); or hold the client with a ``/status`` answer sent one byte at a
time (``drip``) or one that never ends (``flood``). It counts every request so a test can prove what was (not) asked.
The meshes it returns come from the ``model`` callable its user supplies.
"""

from __future__ import annotations

import base64
import json
import threading
import time
import uuid
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

FAULTS = ("die", "restart", "error", "reject", "bad_base64", "not_glb", "generate_only", "unhealthy", "drip", "flood")
#: Seconds between the bytes of a ``drip`` answer, and bytes of each piece of a ``flood``.
DRIP_INTERVAL = 0.2
FLOOD_PIECE = 1 << 20


@dataclass
class Job:
    image: bytes
    done_at: float
    delay: float
    fault: str | None = None


@dataclass
class StandInServer:
    """One server. ``fault`` (one of FAULTS or None) hits ``fault_jobs`` jobs (all when None)
    after the first ``healthy_jobs`` jobs went well."""

    model: Callable[[bytes], bytes]
    delay: float = 0.05
    fault: str | None = None
    fault_jobs: int | None = None
    healthy_jobs: int = 0
    counts: Counter = field(default_factory=Counter)
    #: Images of every job submitted (by /send or /generate), in order.
    submitted: list[bytes] = field(default_factory=list)
    #: The most jobs it ever held at once (queued or running).
    peak: int = 0

    def __post_init__(self) -> None:
        if self.fault is not None and self.fault not in FAULTS:
            raise ValueError(f"unknown fault {self.fault!r}; faults: {', '.join(FAULTS)}")
        self._jobs: dict[str, Job] = {}
        self._lock = threading.Lock()
        self._free_at = 0.0
        self._pending: list[float] = []
        self._faulted = 0
        self._httpd: ThreadingHTTPServer | None = None
        self._url = ""
        self._restarts = 0

    @property
    def url(self) -> str:
        """Where it listens (kept after it stops or dies, to recognise it in reports)."""
        assert self._url, "start() the server first"
        return self._url

    def start(self) -> StandInServer:
        handler = type("Handler", (_Handler,), {"standin": self})
        self._httpd = ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self._httpd.daemon_threads = True
        host, port = self._httpd.server_address[:2]
        self._url = f"http://{host}:{port}"
        threading.Thread(target=self._httpd.serve_forever, args=(0.05,), daemon=True, name=f"standin-{self.url}").start()
        return self

    def stop(self) -> None:
        if self._httpd is not None:
            httpd, self._httpd = self._httpd, None
            httpd.shutdown()
            httpd.server_close()

    def __enter__(self) -> StandInServer:
        return self.start()

    def __exit__(self, *exc) -> None:
        self.stop()

    @property
    def worker_id(self) -> str:
        return f"standin-{self._restarts}"

    def restart(self) -> None:
        """Lose every job, as a restarted server does, and come back with a new worker id."""
        with self._lock:
            self._jobs.clear()
            self._pending.clear()
            self._free_at = 0.0
            self._restarts += 1

    def _faulty(self) -> str | None:
        """The fault this job suffers, counting it against ``fault_jobs``."""
        with self._lock:
            if self.fault is None or self.fault in ("generate_only", "unhealthy"):
                return None
            if self.counts["send"] + self.counts["generate"] <= self.healthy_jobs:
                return None
            if self.fault_jobs is not None and self._faulted >= self.fault_jobs:
                return None
            self._faulted += 1
            return self.fault

    def _queue(self, image: bytes) -> Job:
        """Jobs run one after another, as on one GPU."""
        with self._lock:
            now = time.monotonic()
            self._pending = [t for t in self._pending if t > now]
            start = max(now, self._free_at)
            self._free_at = start + self.delay
            self._pending.append(self._free_at)
            self.peak = max(self.peak, len(self._pending))
            self.submitted.append(image)
            return Job(image=image, done_at=self._free_at, delay=self.delay)


class _Handler(BaseHTTPRequestHandler):
    standin: StandInServer

    def log_message(self, format, *args) -> None:  # keep test output clean
        return

    def _reply(self, status: int, body: bytes | dict, content_type: str = "application/json") -> None:
        data = json.dumps(body).encode() if isinstance(body, dict) else body
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    def _stream(self, fault: str) -> None:
        """An answer that takes for ever: one byte at a time, or pieces without end (no length,
        so only closing the connection ends it); stops when the client hangs up."""
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.end_headers()
        piece = b" " * FLOOD_PIECE
        try:
            for _ in range(100_000):
                if fault == "drip":
                    self.wfile.write(b" ")
                    self.wfile.flush()
                    time.sleep(DRIP_INTERVAL)
                else:
                    self.wfile.write(piece)
        except (BrokenPipeError, ConnectionResetError):
            return

    def _payload(self) -> dict:
        length = int(self.headers.get("Content-Length", 0))
        return json.loads(self.rfile.read(length) or b"{}")

    def do_GET(self) -> None:
        s = self.standin
        if self.path == "/health":
            s.counts["health"] += 1
            if s.fault == "unhealthy":
                return self._reply(503, b"<html>bad gateway</html>", "text/html")
            return self._reply(200, {"status": "healthy", "worker_id": s.worker_id})
        if self.path.startswith("/status/") and s.fault != "generate_only":
            s.counts["status"] += 1
            job = s._jobs.get(self.path.removeprefix("/status/"))
            if job is None:  # the real server cannot tell an unknown uid from a running one
                return self._reply(200, {"status": "processing"})
            if job.fault in ("drip", "flood"):
                return self._stream(job.fault)
            return self._reply(200, self._status(job))
        self._reply(404, {"detail": "Not Found"})

    def _status(self, job: Job) -> dict:
        now = time.monotonic()
        if now < job.done_at - job.delay * 0.3:
            return {"status": "processing"}
        if now < job.done_at:
            return {"status": "texturing"}
        fault = job.fault
        if fault == "error":
            return {"status": "error", "message": "CUDA out of memory"}
        if fault == "bad_base64":
            return {"status": "completed", "model_base64": "not*base64!"}
        if fault == "not_glb":
            return {"status": "completed", "model_base64": base64.b64encode(b"<html>oops</html>").decode()}
        return {"status": "completed", "model_base64": base64.b64encode(self.standin.model(job.image)).decode()}

    def do_POST(self) -> None:
        s = self.standin
        if self.path == "/send" and s.fault != "generate_only":
            s.counts["send"] += 1
            payload = self._payload()
            if s.fault == "reject" and s._faulty():  # refused before it takes any GPU time
                return self._reply(500, {"detail": "CUDA out of memory"})
            job = s._queue(base64.b64decode(payload["image"]))
            job.fault = s._faulty()
            uid = str(uuid.uuid4())
            s._jobs[uid] = job
            self._reply(200, {"uid": uid})
            if job.fault == "die":
                threading.Thread(target=s.stop, daemon=True).start()
            elif job.fault == "restart":
                s.restart()
            return
        if self.path == "/generate":
            s.counts["generate"] += 1
            payload = self._payload()
            job = s._queue(base64.b64decode(payload["image"]))
            fault = s._faulty()
            time.sleep(max(0.0, job.done_at - time.monotonic()))
            if fault == "error":
                return self._reply(404, {"text": "NETWORK ERROR", "error_code": 1})
            if fault in ("bad_base64", "not_glb"):
                return self._reply(200, b"<html>oops</html>", "text/html")
            if fault == "die":
                threading.Thread(target=s.stop, daemon=True).start()
                self.close_connection = True
                return
            return self._reply(200, s.model(job.image), "model/gltf-binary")
        self._reply(404, {"detail": "Not Found"})
