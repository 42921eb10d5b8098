"""A local stand-in for an OpenAI-compatible server, for protocol and fault tests and for
``scenewright bench analysis`` (which is why it ships in the package, not in ``tests/``).

It speaks ``/v1/chat/completions`` (JSON), ``/v1/images/generations`` (JSON),
``/v1/images/edits`` (multipart) and, when given a list, ``GET /v1/models`` on 127.0.0.1 in a thread per request, records every request
it saw, and answers from scripts: a queue of :class:`Reply` per route, else a responder
function per route. Replies can be delayed (latency, hung requests), trickle a byte at a time, be any bytes at
all (not JSON, huge) or be HTTP faults.
"""

from __future__ import annotations

import base64
import io
import json
import threading
import time
from collections import defaultdict, deque
from collections.abc import Callable
from dataclasses import dataclass, field
from email.parser import BytesParser
from email.policy import HTTP
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

from PIL import Image

CHAT = "/v1/chat/completions"
GENERATE = "/v1/images/generations"
EDIT = "/v1/images/edits"


@dataclass
class Reply:
    body: Any = None
    status: int = 200
    delay: float = 0.0
    headers: dict[str, str] = field(default_factory=dict)
    #: Seconds between the bytes of the body (a server that trickles); 0 sends it at once.
    drip: float = 0.0


@dataclass
class Request:
    path: str
    headers: dict[str, str]
    json: dict[str, Any] | None = None
    fields: dict[str, str] = field(default_factory=dict)
    files: dict[str, list[bytes]] = field(default_factory=dict)

    @property
    def schema_name(self) -> str | None:
        fmt = (self.json or {}).get("response_format") or {}
        return (fmt.get("json_schema") or {}).get("name")

    @property
    def text(self) -> str:
        """All text of the last user turn (chat) or the prompt (images)."""
        if self.json is None:
            return self.fields.get("prompt", "")
        if "prompt" in self.json:
            return self.json["prompt"]
        content = self.json["messages"][-1]["content"]
        if isinstance(content, str):
            return content
        return "\n".join(p["text"] for p in content if p["type"] == "text")

    @property
    def image_urls(self) -> list[str]:
        urls = []
        for message in (self.json or {}).get("messages", []):
            if isinstance(message["content"], list):
                urls += [p["image_url"]["url"] for p in message["content"] if p["type"] == "image_url"]
        return urls


def png(colour=(200, 80, 40, 255), size=(8, 8)) -> bytes:
    out = io.BytesIO()
    Image.new("RGBA", size, colour).save(out, format="PNG")
    return out.getvalue()


def chat_reply(content: str | dict | None, *, refusal: str | None = None, **kw) -> Reply:
    if isinstance(content, dict):
        content = json.dumps(content)
    message = {"role": "assistant", "content": content, "refusal": refusal}
    return Reply(
        {
            "id": "chatcmpl-test",
            "object": "chat.completion",
            "created": int(time.time()),
            "model": "test-model",
            "choices": [{"index": 0, "message": message, "finish_reason": "stop"}],
        },
        **kw,
    )


def image_reply(data: bytes | None = None, **kw) -> Reply:
    return Reply({"created": int(time.time()), "data": [{"b64_json": base64.b64encode(data or png()).decode()}]}, **kw)


def object_item(id: str, name: str, size=(1.0, 1.0, 1.0), x: float = 0.0, yaw: float = 0.0) -> dict[str, Any]:
    """One object as the ``scene_objects`` task answers it, standing on the ground at ``x``."""
    return {
        "id": id,
        "name": name,
        "position": {"x": x, "y": 0, "z": size[2] / 2},
        "rotation": {"x": 0, "y": 0, "z": yaw},
        "size": dict(zip("xyz", size)),
        "visual_description": f"a {name}",
    }


def error_reply(status: int, message: str = "scripted fault", **kw) -> Reply:
    return Reply({"error": {"message": message, "type": "server_error", "code": None}}, status=status, **kw)


class FakeOpenAI:
    """``with FakeOpenAI() as server:`` → ``server.url`` is the base URL (``.../v1``)."""

    def __init__(self) -> None:
        self.requests: list[Request] = []
        self.queues: dict[str, deque[Reply]] = defaultdict(deque)
        #: route → responder(request) → Reply, when the route's queue is empty.
        self.responders: dict[str, Callable[[Request], Reply]] = {
            CHAT: lambda r: error_reply(500, f"no scripted chat answer for {r.schema_name}"),
            GENERATE: lambda r: image_reply(),
            EDIT: lambda r: image_reply(),
        }
        #: Model ids ``GET /v1/models`` lists; None answers it 404, as servers without a list do.
        self.models: list[str] | None = None
        #: Paths of every GET (kept apart from ``requests``, which are the billable calls).
        self.gets: list[str] = []
        #: Seconds added to every images request (latency benchmarks).
        self.image_latency = 0.0
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._server = ThreadingHTTPServer(("127.0.0.1", 0), self._handler())
        self._server.daemon_threads = True
        self._thread = threading.Thread(target=self._server.serve_forever, args=(0.05,), daemon=True)

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self._server.server_address[1]}/v1"

    def __enter__(self) -> FakeOpenAI:
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stop.set()  # releases hung requests
        self._server.shutdown()
        self._server.server_close()

    def script(self, route: str, *replies: Reply) -> None:
        self.queues[route].extend(replies)

    def seen(self, route: str) -> list[Request]:
        return [r for r in self.requests if r.path == route]

    def _answer(self, request: Request) -> Reply:
        with self._lock:
            self.requests.append(request)
            queue = self.queues[request.path]
            if queue:
                return queue.popleft()
        return self.responders[request.path](request)

    def _handler(self):
        server = self

        class Handler(BaseHTTPRequestHandler):
            protocol_version = "HTTP/1.1"

            def log_message(self, *args) -> None:  # keep test output quiet
                return

            def do_GET(self) -> None:
                server.gets.append(self.path)
                if self.path == "/v1/models" and server.models is not None:
                    body = {"object": "list", "data": [
                        {"id": m, "object": "model", "created": 0, "owned_by": "local"} for m in server.models
                    ]}
                    status = 200
                else:
                    body, status = {"error": {"message": f"no route {self.path}", "type": "not_found"}}, 404
                data = json.dumps(body).encode()
                self.send_response(status)
                self.send_header("content-type", "application/json")
                self.send_header("content-length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

            def do_POST(self) -> None:
                body = self.rfile.read(int(self.headers.get("content-length", 0)))
                request = Request(path=self.path, headers={k.lower(): v for k, v in self.headers.items()})
                content_type = self.headers.get("content-type", "")
                if content_type.startswith("multipart/form-data"):
                    message = BytesParser(policy=HTTP).parsebytes(
                        b"Content-Type: " + content_type.encode() + b"\r\n\r\n" + body
                    )
                    for part in message.iter_parts():
                        name = part.get_param("name", header="content-disposition")
                        payload = part.get_payload(decode=True)
                        if part.get_filename() is not None:
                            request.files.setdefault(name.removesuffix("[]"), []).append(payload)
                        else:
                            request.fields[name] = payload.decode()
                else:
                    request.json = json.loads(body or b"{}")
                if self.path not in (CHAT, GENERATE, EDIT):
                    reply = error_reply(404, f"no route {self.path}")
                else:
                    reply = server._answer(request)
                delay = reply.delay + (server.image_latency if self.path != CHAT else 0.0)
                if delay and server._stop.wait(delay):
                    return
                data = reply.body if isinstance(reply.body, (bytes, str)) else json.dumps(reply.body)
                data = data.encode() if isinstance(data, str) else data
                try:
                    self.send_response(reply.status)
                    self.send_header("content-type", "application/json")
                    self.send_header("content-length", str(len(data)))
                    for key, value in reply.headers.items():
                        self.send_header(key, value)
                    self.end_headers()
                    if not reply.drip:
                        self.wfile.write(data)
                    for k in range(len(data) if reply.drip else 0):
                        self.wfile.write(data[k : k + 1])
                        self.wfile.flush()
                        if server._stop.wait(reply.drip):
                            return
                except (BrokenPipeError, ConnectionResetError):  # the client gave up (timeout test)
                    return

        return Handler
