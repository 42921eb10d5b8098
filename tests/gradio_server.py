"""A stand-in Gradio app on 127.0.0.1, written from Gradio's HTTP API (the real ``gradio``
package would pull numpy 2 into the environment bpy needs below 2).

It serves what a Gradio 4 (no prefix) or 5+ (``/gradio_api``) app serves to API clients:
``GET /config``, ``POST {prefix}/upload`` (multipart ``files``), ``POST {prefix}/call/{api}``
→ ``{"event_id"}``, ``GET {prefix}/call/{api}/{event_id}`` (server-sent events: ``generating``
then ``complete`` with the outputs, or ``error``) and ``GET {prefix}/file={path}``. Like
Gradio it checks each call's input count against the endpoint (state slots included, sent as
null) and keeps ``gr.State`` values per ``session_hash``. The endpoints are plain functions
``(inputs, state dict) → outputs``, so a test builds the app it needs; it counts every call.
"""

from __future__ import annotations

import json
import threading
import time
import uuid
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from email.parser import BytesParser
from email.policy import HTTP
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

Endpoint = Callable[[list[Any], dict[str, Any], "GradioStandIn"], list[Any]]


class AppError(Exception):
    """An endpoint failed as ``gr.Error`` does: the stream ends in ``error``."""


@dataclass
class GradioStandIn:
    #: api name → (number of inputs, function).
    endpoints: dict[str, tuple[int, Endpoint]]
    prefix: str = "/gradio_api"
    version: str = "5.9.1"
    delay: float = 0.0
    #: Endpoint calls to fail with an error event (all when None) after ``healthy_calls``.
    fail_api: str | None = None
    fail_calls: int | None = None
    counts: Counter = field(default_factory=Counter)
    files: dict[str, bytes] = field(default_factory=dict)
    sessions: dict[str, dict[str, Any]] = field(default_factory=dict)
    #: Every call: (api, inputs, session_hash).
    calls: list[tuple[str, list[Any], str]] = field(default_factory=list)

    def __post_init__(self) -> None:
        self._events: dict[str, tuple[str, list[Any], str]] = {}
        self._lock = threading.Lock()
        self._failed = 0
        self._httpd: ThreadingHTTPServer | None = None
        self.url = ""

    def start(self) -> GradioStandIn:
        handler = type("Handler", (_Handler,), {"app": self})
        self._httpd = ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self._httpd.daemon_threads = True
        self.url = f"http://127.0.0.1:{self._httpd.server_address[1]}"
        threading.Thread(target=self._httpd.serve_forever, args=(0.05,), daemon=True).start()
        return self

    def stop(self) -> None:
        if self._httpd is not None:
            httpd, self._httpd = self._httpd, None
            httpd.shutdown()
            httpd.server_close()

    def __enter__(self) -> GradioStandIn:
        return self.start()

    def __exit__(self, *exc) -> None:
        self.stop()

    def store(self, data: bytes, name: str) -> dict[str, Any]:
        """A file the app made, as Gradio answers it (FileData with path and url)."""
        path = f"/tmp/gradio/{uuid.uuid4().hex}/{name}"
        self.files[path] = data
        return {"path": path, "url": f"{self.url}{self.prefix}/file={path}", "orig_name": name,
                "size": len(data), "mime_type": None, "is_stream": False, "meta": {"_type": "gradio.FileData"}}

    def read(self, filedata: Any) -> bytes:
        """The bytes of an input FileData (an upload or an earlier output)."""
        if not isinstance(filedata, dict) or filedata.get("path") not in self.files:
            raise AppError(f"not a file of this app: {filedata!r}")
        return self.files[filedata["path"]]

    def _fails(self, api: str) -> bool:
        with self._lock:
            if self.fail_api not in (api, "*"):
                return False
            if self.fail_calls is not None and self._failed >= self.fail_calls:
                return False
            self._failed += 1
            return True


class _Handler(BaseHTTPRequestHandler):
    app: GradioStandIn
    protocol_version = "HTTP/1.1"

    def log_message(self, *args) -> None:
        return

    def _reply(self, status: int, body: Any, content_type: str = "application/json") -> None:
        data = body if isinstance(body, bytes) else json.dumps(body).encode()
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    def do_GET(self) -> None:
        app = self.app
        if self.path == "/config":
            app.counts["config"] += 1
            config = {"version": app.version, "mode": "blocks"}
            if app.prefix:
                config["api_prefix"] = app.prefix
            return self._reply(200, config)
        if self.path.startswith(f"{app.prefix}/file="):
            app.counts["file"] += 1
            data = app.files.get(self.path.removeprefix(f"{app.prefix}/file="))
            return self._reply(200, data, "application/octet-stream") if data else self._reply(404, {"detail": "nope"})
        if self.path.startswith(f"{app.prefix}/call/"):
            api, _, event_id = self.path.removeprefix(f"{app.prefix}/call").rpartition("/")
            return self._stream(api, event_id)
        self._reply(404, {"detail": "Not Found"})

    def _stream(self, api: str, event_id: str) -> None:
        app = self.app
        with app._lock:
            call = app._events.pop(event_id, None)
        if call is None or call[0] != api:
            return self._reply(404, {"detail": "unknown event"})
        _, inputs, session = call
        self.send_response(200)
        self.send_header("Content-Type", "text/event-stream")
        self.end_headers()  # no length: the stream ends when the connection closes
        self.close_connection = True

        def send(event: str, data: Any) -> None:
            self.wfile.write(f"event: {event}\ndata: {json.dumps(data)}\n\n".encode())
            self.wfile.flush()

        try:
            send("generating", None)
            time.sleep(app.delay)
            arity, function = app.endpoints[api]
            if len(inputs) != arity:
                return send("error", f"An event handler ({api}) didn't receive enough input values "
                                     f"(needed: {arity}, got: {len(inputs)}).")
            if app._fails(api):
                return send("error", None)
            try:
                outputs = function(inputs, app.sessions.setdefault(session, {}), app)
            except AppError as exc:
                return send("error", str(exc))
            send("heartbeat", None)
            send("complete", outputs)
        except (BrokenPipeError, ConnectionResetError):
            return

    def do_POST(self) -> None:
        app = self.app
        body = self.rfile.read(int(self.headers.get("Content-Length", 0)))
        if self.path == f"{app.prefix}/upload":
            app.counts["upload"] += 1
            content_type = self.headers.get("Content-Type", "")
            message = BytesParser(policy=HTTP).parsebytes(b"Content-Type: " + content_type.encode() + b"\r\n\r\n" + body)
            paths = []
            for part in message.iter_parts():
                if part.get_param("name", header="content-disposition") == "files":
                    paths.append(app.store(part.get_payload(decode=True), part.get_filename() or "file")["path"])
            return self._reply(200, paths)
        if self.path.startswith(f"{app.prefix}/call/"):
            api = self.path.removeprefix(f"{app.prefix}/call")
            if api not in app.endpoints:
                return self._reply(404, {"detail": f"api {api} not found"})
            payload = json.loads(body or b"{}")
            app.counts[api] += 1
            session = payload.get("session_hash") or uuid.uuid4().hex
            event_id = uuid.uuid4().hex
            with app._lock:
                app.calls.append((api, payload["data"], session))
                app._events[event_id] = (api, payload["data"], session)
            return self._reply(200, {"event_id": event_id})
        self._reply(404, {"detail": "Not Found"})


# -- apps shaped like the real ones (input counts and outputs as their gradio_app.py) ------


def trellis_app(glb: bytes, **kw) -> GradioStandIn:
    """TRELLIS: preprocess, then image_to_3d keeps a latent in the session, extract_mesh reads it."""

    def preprocess(inputs, state, app):
        return [app.store(app.read(inputs[0]), "preprocessed.png")]

    def image_to_3d(inputs, state, app):
        if inputs[4] is not None:
            raise AppError("the demo-mode state slot must be sent as null")
        state["latent"] = app.read(inputs[0])
        return [None, app.store(b"video", "sample.mp4")]

    def extract_mesh(inputs, state, app):
        if "latent" not in state:  # another session: the state is not there, as in Gradio
            raise AppError("'NoneType' object is not subscriptable")
        return [app.store(glb, "sample.glb"), app.store(glb, "sample.glb"), app.store(b"zip", "sample_obj.zip")]

    return GradioStandIn({"/preprocess_image": (1, preprocess), "/image_to_3d": (11, image_to_3d),
                          "/extract_mesh": (5, extract_mesh)}, **kw)


def triposr_app(obj: bytes, **kw) -> GradioStandIn:
    """TripoSR: preprocess, then generate answers an OBJ."""

    def preprocess(inputs, state, app):
        return [app.store(app.read(inputs[0]), "processed.png")]

    def generate(inputs, state, app):
        app.read(inputs[0])
        return [app.store(obj, "tmpabc.obj")]

    return GradioStandIn({"/preprocess": (3, preprocess), "/generate": (1, generate)}, prefix="", version="4.44.1",
                         **kw)
