"""The shared client for OpenAI-compatible servers: structured answers, retries, a reply cache.

A model's reply is untrusted input. Every answer is parsed and validated here; an answer that
is not valid JSON, does not match the schema, is refused, or fails a task's own checks goes
back to the model with the error appended to the conversation, a bounded number of times,
before the task fails with a :class:`BackendError` that names it and the last error.
Transport faults (429, 5xx, timeouts, dropped connections) are the SDK's job: it retries them
with exponential backoff, honouring ``Retry-After``, ``settings.max_retries`` times.

Servers differ in how they can be held to a schema, so structured answers are asked in the
best response format the server supports, found on the first request and remembered
(:mod:`scenewright.backends.formats`; docs/remote.md lists what known servers need). A
request the server refuses for its format (HTTP 400) is asked again one level down and does
not count as an attempt.

Accepted replies are cached by a hash of the request, so a resumed or repeated run never asks
the same question twice.
"""

from __future__ import annotations

import base64
import copy
import json
import logging
import os
import re
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from scenewright.backends.formats import LEVELS, REASONING_EFFORTS, FormatMemory, extract_json, schema_instruction
from scenewright.cache import RequestCache, request_key
from scenewright.errors import BackendError, InputError, MissingExtra
from scenewright.scene import describe_validation_error
from scenewright.settings import Settings

log = logging.getLogger(__name__)

T = TypeVar("T")
Message = dict[str, Any]

#: Local servers (vLLM, Ollama, llama.cpp) accept any key; the SDK insists on one.
_PLACEHOLDER_KEY = "not-needed"


class InvalidAnswer(ValueError):
    """A reply the model must redo; the message is what the model is told."""


def openai_client(settings: Settings):
    """An SDK client for ``settings``: base URL, key from the named variable, timeout, retries."""
    try:
        import openai

        from scenewright.backends.http import limited_client
    except ImportError as exc:
        raise MissingExtra("the openai backends", "remote", "openai") from exc
    key = os.environ.get(settings.api_key_env)
    if not key:
        if settings.base_url is None:
            raise BackendError(
                f"the openai backends need an API key: set the environment variable "
                f"{settings.api_key_env} (or choose another with --api-key-env), "
                "or point --base-url at a local OpenAI-compatible server"
            )
        key = _PLACEHOLDER_KEY
    return openai.OpenAI(
        api_key=key,
        base_url=settings.base_url,
        timeout=settings.timeout,
        max_retries=settings.max_retries,
        http_client=limited_client(settings.timeout, settings.max_download_bytes),
    )


#: Characters a model name may have (servers name models in a few dozen).
MAX_MODEL_CHARS = 128
_MODEL = re.compile(r"^[\w.:/@+-]+$")


def model_name(argument: str, default: str) -> str:
    """The model a backend spec names (``openai:MODEL``), checked: a name, not a paragraph."""
    name = argument or default
    if len(name) > MAX_MODEL_CHARS or not _MODEL.match(name):
        raise InputError(
            f"model name {name[:60]!r}{'...' if len(name) > 60 else ''} is not a model name: at most "
            f"{MAX_MODEL_CHARS} letters, digits and . : / @ + - _ (e.g. openai:o3)"
        )
    return name


def transport_error(task: str, exc: Exception) -> BackendError:
    """The SDK's failure, after its own retries, as one line naming the task."""
    import openai

    from scenewright.backends.http import DeadlineExceeded, ResponseTooLarge

    cause = exc.__cause__
    if isinstance(exc, json.JSONDecodeError):
        what = f"the server answered with a body that is not JSON ({exc.msg} at line {exc.lineno})"
    elif isinstance(cause, (DeadlineExceeded, ResponseTooLarge)):
        hint = " (raise --timeout or check the server)" if isinstance(cause, DeadlineExceeded) else ""
        what = f"{cause}{hint}"
    elif isinstance(exc, openai.APITimeoutError):
        what = "timed out (raise --timeout or check the server)"
    elif isinstance(exc, openai.APIConnectionError):
        what = f"could not reach the server ({exc})"
    elif isinstance(exc, openai.APIStatusError):
        detail = exc.body.get("message") if isinstance(exc.body, dict) else None
        what = f"server answered HTTP {exc.status_code}: {_short(detail or exc.message)}"
    else:
        what = str(exc)
    return BackendError(f"{task}: {what}")


def sdk_errors() -> tuple[type[Exception], ...]:
    """What a request through the SDK raises when the server or the connection fails; a 200
    whose body is not JSON surfaces as a JSONDecodeError from the SDK's parsing."""
    import openai

    return (openai.APIError, json.JSONDecodeError)


def image_mime(data: bytes) -> str:
    if data.startswith(b"\x89PNG"):
        return "image/png"
    if data.startswith(b"\xff\xd8"):
        return "image/jpeg"
    if data[:4] == b"RIFF" and data[8:12] == b"WEBP":
        return "image/webp"
    if data[:6] in (b"GIF87a", b"GIF89a"):
        return "image/gif"
    raise BackendError(f"cannot send an image that is not PNG, JPEG, WebP or GIF (starts {data[:8]!r})")


def image_part(data: bytes) -> dict[str, Any]:
    """A chat content part carrying an image inline as a data URL."""
    url = f"data:{image_mime(data)};base64,{base64.b64encode(data).decode('ascii')}"
    return {"type": "image_url", "image_url": {"url": url}}


def user_message(text: str, images: Sequence[bytes | tuple[str, bytes]] = ()) -> Message:
    """A user turn: the text, then each image (optionally preceded by its own caption)."""
    parts: list[dict[str, Any]] = [{"type": "text", "text": text}]
    for image in images:
        if isinstance(image, tuple):
            caption, data = image
            parts.append({"type": "text", "text": caption})
            image = data
        parts.append(image_part(image))
    return {"role": "user", "content": parts}


def strict_schema(model: type[BaseModel]) -> dict[str, Any]:
    """The model's JSON schema in the subset strict structured output accepts.

    Strict mode wants every property listed as required, ``additionalProperties: false`` on
    every object, and no ``default``; optional fields stay optional by being nullable, which
    pydantic already writes as ``anyOf [..., null]``.
    """
    schema = copy.deepcopy(model.model_json_schema())

    def visit(node: Any) -> None:
        if isinstance(node, dict):
            node.pop("default", None)
            if node.get("type") == "object" and "properties" in node:
                node["required"] = list(node["properties"])
                node["additionalProperties"] = False
            for value in node.values():
                visit(value)
        elif isinstance(node, list):
            for value in node:
                visit(value)

    visit(schema)
    return schema


class NotJSON(InvalidAnswer):
    """The reply holds no JSON object."""


class OffSchema(InvalidAnswer):
    """The reply is JSON of another shape than the answer's."""


def parse_json(content: str, answer: type[BaseModel]) -> Any:
    """Validate a reply against ``answer``; the JSON may come fenced or wrapped in prose
    (servers without structured output), so it is looked for first."""
    try:
        return answer.model_validate_json(extract_json(content))
    except ValidationError as exc:
        if any(err["type"] == "json_invalid" for err in exc.errors()):
            raise NotJSON(f"the reply is not valid JSON ({_short(str(exc.errors()[0]['msg']))})") from None
        raise OffSchema(f"the reply does not match the schema: {describe_validation_error(exc)}") from None


def _checked(parse: Callable[[str], T], content: str) -> T:
    """``parse(content)``, where a model object that does not validate (a task's check builds
    scene objects from the answer) is an answer to redo like any other."""
    try:
        return parse(content)
    except ValidationError as exc:
        raise InvalidAnswer(f"the answer does not fit the scene: {describe_validation_error(exc)}") from None


def _short(text: str, limit: int = 300) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 3] + "..."


class RemoteModel:
    """One model on an OpenAI-compatible server: its settings, a cache for its answers and the
    SDK client, made when the backend is (so a missing key stops a run before it starts)."""

    def __init__(self, model: str, settings: Settings, client: Any = None):
        check_options(settings)
        self.model = model
        self.settings = settings
        self.cache = RequestCache(settings.cache_dir)
        self.client = client if client is not None else openai_client(settings)

    @property
    def server(self) -> str:
        """The server, as errors name it."""
        return self.settings.base_url or "api.openai.com"

    def preflight(self) -> None:
        """Cheap checks before anything is paid for: the server answers, takes the key and
        serves the model (``GET /models``, free). A server without a model list passes."""
        from scenewright.backends.probe import served_models, serves

        served = served_models(self.client, self.server)
        if served is not None and not serves(served, self.model):
            listed = ", ".join(sorted(served)[:20]) + (" ..." if len(served) > 20 else "")
            raise InputError(
                f"{self.server} does not serve the model {self.model!r}; it serves: {listed or 'nothing'}. "
                "Name one of those (e.g. --vlm openai:NAME) or point --base-url at the right server"
            )


class ChatClient(RemoteModel):
    """Asks one OpenAI-compatible chat model for validated answers, in the best response format
    its server supports (:mod:`scenewright.backends.formats`)."""

    def __init__(self, model: str, settings: Settings, client: Any = None):
        super().__init__(model, settings, client)
        self.formats = FormatMemory(self.cache, settings.base_url, model)

    def ask(
        self,
        task: str,
        messages: list[Message],
        answer: type[BaseModel],
        check: Callable[[Any], T] = lambda parsed: parsed,
    ) -> T:
        """A structured answer: JSON that validates as ``answer`` and passes ``check``.

        ``check`` turns the validated answer into the task's result and raises
        :class:`InvalidAnswer` for what the schema cannot express (an unknown focus object).
        """
        return self._converse(task, messages, answer, lambda content: check(parse_json(content, answer)))

    def ask_text(self, task: str, messages: list[Message], parse: Callable[[str], T]) -> T:
        """A free-text answer that ``parse`` accepts (raising :class:`InvalidAnswer` otherwise)."""
        return self._converse(task, messages, None, parse)

    def _request(self, task: str, messages: list[Message], answer: type[BaseModel] | None, level: str) -> dict[str, Any]:
        """The request at one response-format level (the prompt describes the shape below json_schema)."""
        request: dict[str, Any] = {"model": self.model, "messages": list(messages)}
        if answer is not None:
            if level == "json_schema":
                request["response_format"] = {
                    "type": "json_schema",
                    "json_schema": {"name": task, "schema": strict_schema(answer), "strict": True},
                }
            else:
                if level == "json_object":
                    request["response_format"] = {"type": "json_object"}
                request["messages"] = _with_system(messages, schema_instruction(answer, level))
        if self.settings.reasoning_effort:
            request["reasoning_effort"] = self.settings.reasoning_effort
        return request

    def _converse(
        self,
        task: str,
        messages: list[Message],
        answer: type[BaseModel] | None,
        parse: Callable[[str], T],
    ) -> T:
        level = self.formats.level() if answer is not None else LEVELS[-1]
        request = self._request(task, messages, answer, level)
        key = request_key("openai-chat", self.settings.base_url, request)
        cached = self.cache.get("chat", key)
        if cached is not None:
            try:
                return parse(cached.decode("utf-8"))
            except InvalidAnswer:
                log.info("%s: cached reply no longer validates; asking again", task)

        attempts = self.settings.max_retries + 1
        error = "no attempt made"
        refused: dict[str, str] = {}  # format level → why the server refused it
        turns: list[Message] = []  # the rejected answers and what was wrong with them
        attempt = 0
        while attempt < attempts:
            try:
                completion = self.client.chat.completions.create(**request)
            except sdk_errors() as exc:
                if answer is not None and level != LEVELS[-1] and _format_refused(exc):
                    refused[level] = "refused: " + str(transport_error("", exc)).removeprefix(": ")
                    log.warning("%s: %s %s; trying the next response format", task, self.server, refused[level])
                    level = LEVELS[LEVELS.index(level) + 1]
                    request = {**self._request(task, messages, answer, level)}
                    request["messages"] = [*request["messages"], *turns]
                    continue  # a refused request was not served: it does not count as an attempt
                raise self._failure(task, exc, refused) from exc
            attempt += 1
            if answer is not None:
                self.formats.learn(level)  # the server took this format
            if not completion.choices:
                error = "the reply has no choices"
                content = ""
            else:
                message = completion.choices[0].message
                content = message.content or ""
                try:
                    if getattr(message, "refusal", None):
                        raise InvalidAnswer(f"the model refused: {_short(message.refusal)}")
                    if not content.strip():
                        raise InvalidAnswer("the reply is empty")
                    limit = self.settings.max_answer_chars
                    if len(content) > limit:
                        raise InvalidAnswer(
                            f"the reply has {len(content):,} characters, more than max_answer_chars ({limit:,}); "
                            "answer briefly"
                        )
                    result = _checked(parse, content)
                except InvalidAnswer as exc:
                    error = str(exc)
                    if answer is not None and _format_ignored(level, exc, content):
                        ignored = level
                        level = LEVELS[LEVELS.index(level) + 1]
                        refused[ignored] = f"accepted but ignored ({error})"
                        log.warning("%s: %s ignores response format %s; describing the schema in the prompt (%s)",
                                    task, self.server, ignored, level)
                        self.formats.learn(level)
                else:
                    stored = self._request(task, messages, answer, level)
                    self.cache.put("chat", request_key("openai-chat", self.settings.base_url, stored),
                                   content.encode("utf-8"))
                    return result
            log.warning("%s: invalid answer (attempt %d of %d): %s", task, attempt, attempts, error)
            turns += [
                # An oversized answer goes back as an excerpt: never re-sent whole on each retry.
                {"role": "assistant", "content": _short(content, 2_000) if len(content) > self.settings.max_answer_chars
                 else content or "(no answer)"},
                {
                    "role": "user",
                    "content": f"That answer cannot be used: {error}. Answer the same request again, "
                    "following every instruction and the required format exactly.",
                },
            ]
            request = self._request(task, messages, answer, level)
            request["messages"] = [*request["messages"], *turns]
        formats = f" in response format {level}" if answer is not None else ""
        raise BackendError(
            f"{task} ({self.model} at {self.server}): no valid answer after {attempts} attempts{formats}"
            f"{_refused_note(refused)}; last error: {error}. {_advice(answer is not None)}"
        )

    def _failure(self, task: str, exc: Exception, refused: dict[str, str]) -> BackendError:
        failure = transport_error(f"{task} ({self.model} at {self.server})", exc)
        if refused:
            return BackendError(f"{failure}{_refused_note(refused)}. {_advice(True)}")
        return failure


def check_options(settings: Settings) -> None:
    """Options a server would only reject after something was paid for, checked here first."""
    effort = settings.reasoning_effort
    if effort is not None and effort not in REASONING_EFFORTS:
        raise InputError(
            f"--reasoning-effort {effort!r} is not one of: {' | '.join(REASONING_EFFORTS)} "
            "(leave it out for models without a reasoning effort)"
        )


def _with_system(messages: list[Message], instruction: str) -> list[Message]:
    """``messages`` with ``instruction`` appended to the system turn (one is added if none)."""
    out = list(messages)
    if out and out[0].get("role") == "system" and isinstance(out[0].get("content"), str):
        out[0] = {**out[0], "content": f"{out[0]['content']}\n\n{instruction}"}
    else:
        out.insert(0, {"role": "system", "content": instruction})
    return out


def _format_refused(exc: Exception) -> bool:
    """Whether the server turned the request down as malformed (HTTP 400, 422 or 501): what
    servers without a response format answer; the next level down may be accepted."""
    import openai

    return isinstance(exc, openai.APIStatusError) and exc.status_code in (400, 422, 501)


def _format_ignored(level: str, exc: InvalidAnswer, content: str) -> bool:
    """Whether a bad answer proves the server ignored ``level``: a server that honours
    json_schema answers schema-shaped JSON, one that honours json_object answers JSON. JSON
    that starts right but breaks off (an answer cut at the token limit) proves nothing."""
    cut_short = isinstance(exc, NotJSON) and content.lstrip().startswith("{")
    if level == "json_schema":
        return isinstance(exc, OffSchema) or (isinstance(exc, NotJSON) and not cut_short)
    return level == "json_object" and isinstance(exc, NotJSON) and not cut_short


def _refused_note(refused: dict[str, str]) -> str:
    return "".join(f"; {level}: {why}" for level, why in refused.items())


def _advice(structured: bool) -> str:
    if not structured:
        return "Try a higher --max-retries or a stronger model"
    return (
        "Try a model that follows JSON instructions more closely, a higher --max-retries, or a server "
        "version with structured output (see the README's 'your own model'; "
        "`scenewright backends --check --base-url URL` shows what a server supports)"
    )


def json_text(value: Any) -> str:
    """Compact, readable JSON for prompts."""
    return json.dumps(value, indent=1, ensure_ascii=False)
