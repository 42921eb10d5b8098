"""How to get JSON out of a server that may not support structured output.

OpenAI and recent vLLM, llama.cpp and Ollama servers honour ``response_format: json_schema``
and decode only what the schema allows. Older ones refuse it with HTTP 400, or accept it and
ignore it, answering prose. The ladder, best first:

``json_schema``
    strict structured output; the prompt stays as the task wrote it.
``json_object``
    JSON mode: the server promises JSON but knows no shape, so the prompt describes the shape
    (a compact rendering of the answer's pydantic model, see :func:`compact_schema`).
``text``
    no response format at all: the prompt describes the shape and asks for JSON only, and
    the reply is searched for it (:func:`extract_json`: code fences, prose around it).

Which level a server needs is learnt once, on its first structured request, and kept
(:class:`FormatMemory`: in memory and in the request cache), so the next task and a resumed
run start at the level that works. docs/remote.md lists what known server versions need.
"""

from __future__ import annotations

import json
import re
import threading
from typing import Any

from pydantic import BaseModel

from scenewright.cache import RequestCache, request_key

LEVELS = ("json_schema", "json_object", "text")
#: Cache kind of the level learnt per server and model.
CACHE_KIND = "capabilities"

REASONING_EFFORTS = ("low", "medium", "high")


def compact_schema(model: type[BaseModel]) -> str:
    """The answer's shape in a line or two a model reads easily: ``{"id": string, ...}`` with
    enums as ``"a" | "b"`` and optional fields as ``T | null``; generated from the same schema
    strict servers get, so the two never disagree."""
    schema = model.model_json_schema()
    defs = schema.get("$defs", {})

    def render(node: dict[str, Any]) -> str:
        if "$ref" in node:
            return render(defs[node["$ref"].rsplit("/", 1)[-1]])
        if "enum" in node:
            return " | ".join(json.dumps(v) for v in node["enum"])
        if "const" in node:
            return json.dumps(node["const"])
        for key in ("anyOf", "oneOf"):
            if key in node:
                return " | ".join(dict.fromkeys(render(n) for n in node[key]))
        kind = node.get("type")
        if kind == "object" and "properties" in node:
            fields = ", ".join(f"{json.dumps(name)}: {render(sub)}" for name, sub in node["properties"].items())
            return "{" + fields + "}"
        if kind == "array":
            return "[" + render(node.get("items", {})) + ", ...]"
        if kind == "integer":
            return "integer"
        if kind in ("number", "string", "boolean", "null"):
            return kind
        return "any JSON value"

    return render(schema)


def schema_instruction(model: type[BaseModel], level: str) -> str:
    """What the prompt adds at ``level`` (nothing for json_schema, where the server knows)."""
    if level == "json_schema":
        return ""
    text = (
        "Answer with a single JSON object of exactly this shape (every key present; null where "
        f"a value does not apply):\n{compact_schema(model)}"
    )
    if level == "text":
        text += "\nWrite only the JSON object: no explanation before or after it."
    return text


_FENCE = re.compile(r"```[a-zA-Z0-9_-]*\s*\n(.*?)```", re.S)


def extract_json(content: str) -> str:
    """The JSON object in a reply: the reply itself when it is one, else the first fenced
    block that is, else the first ``{...}`` in the text that parses. Returns the reply
    unchanged when nothing is found, so validation reports what is wrong with it."""
    stripped = content.strip()
    if _parses(stripped):
        return stripped
    for block in _FENCE.findall(content):
        if _parses(block.strip()):
            return block.strip()
    decoder = json.JSONDecoder()
    for match in re.finditer(r"\{", content):
        try:
            value, end = decoder.raw_decode(content, match.start())
        except ValueError:
            continue
        if isinstance(value, dict):
            return content[match.start():end]
    fenced = _FENCE.findall(content)
    return fenced[0].strip() if fenced else stripped


def _parses(text: str) -> bool:
    try:
        return isinstance(json.loads(text), dict)
    except ValueError:
        return False


class FormatMemory:
    """The response-format level one server and model need, learnt once and kept: for the
    client's life, and in the request cache for the next run (a resumed run starts where the
    last one ended, so its cached answers are found under the same request)."""

    def __init__(self, cache: RequestCache, base_url: str | None, model: str):
        self.cache = cache
        self.key = request_key("chat-format", base_url, model)
        self._lock = threading.Lock()
        stored = cache.get(CACHE_KIND, self.key)
        level = stored.decode("ascii", "replace") if stored else LEVELS[0]
        self._level = level if level in LEVELS else LEVELS[0]

    def level(self) -> str:
        with self._lock:
            return self._level

    def learn(self, level: str) -> None:
        """Keep ``level`` when it is lower than the one known (a server never gains a format)."""
        with self._lock:
            if LEVELS.index(level) <= LEVELS.index(self._level):
                return
            self._level = level
        self.cache.put(CACHE_KIND, self.key, level.encode("ascii"))
