"""What an OpenAI-compatible server can do, asked cheaply before anything is paid for.

``GET /models`` is free: it proves the server answers, takes the key and serves the model.
The capabilities a run depends on (structured output, image input, a reasoning effort) have
no endpoint of their own on most servers, so :func:`check_server` asks each with the smallest
request that tells: a one-word question, never an image to draw or a scene to analyse.
"""

from __future__ import annotations

import json
import logging
from typing import Any

from scenewright.backends.formats import extract_json
from scenewright.errors import BackendError

log = logging.getLogger(__name__)

_COLOUR_SCHEMA = {
    "type": "object",
    "properties": {"colour": {"type": "string"}},
    "required": ["colour"],
    "additionalProperties": False,
}


def serves(served: set[str], model: str) -> bool:
    """Whether ``model`` is in a model list (Ollama lists ``name:latest`` for ``name``)."""
    return model in served or f"{model}:latest" in served


def served_models(client: Any, server: str) -> set[str] | None:
    """The models ``server`` lists, or None when it has no model list (some proxies do not).

    Raises BackendError when the server cannot be reached or refuses the key: the run would
    fail on its first request anyway, after the first paid one when images come first."""
    import openai

    try:
        page = client.models.list()
    except openai.AuthenticationError as exc:
        raise BackendError(
            f"{server} refused the API key (HTTP {exc.status_code}): check the variable --api-key-env names"
        ) from None
    except openai.PermissionDeniedError as exc:
        raise BackendError(f"{server} denied access (HTTP {exc.status_code}): {exc.message}") from None
    except openai.APIStatusError as exc:
        log.info("%s has no model list (HTTP %s); the model is not checked", server, exc.status_code)
        return None
    except openai.APIConnectionError as exc:
        raise BackendError(f"could not reach {server} ({exc}); check --base-url and that the server runs") from None
    except json.JSONDecodeError:
        log.info("%s answered the model list with something that is not JSON; the model is not checked", server)
        return None
    return {str(getattr(item, "id", "")) for item in page if getattr(item, "id", None)}


def check_server(client: Any, server: str, model: str) -> dict[str, Any]:
    """Each capability of ``server`` for ``model``: "supported", "refused (...)", "ignored (...)"
    or "untested (...)", with the models it lists."""
    from scenewright.backends.structured import user_message

    models = served_models(client, server)
    report: dict[str, Any] = {
        "server": server,
        "model": model,
        "models": sorted(models) if models is not None else None,
        "model_served": serves(models, model) if models is not None else None,
    }
    if models is not None and not serves(models, model):
        for capability in ("json_schema", "json_object", "images", "reasoning"):
            report[capability] = "untested (the server does not serve the model)"
        return report
    colour = [{"role": "user", "content": "Name one colour."}]
    report["json_schema"] = _structured(
        client, model, colour,
        {"type": "json_schema", "json_schema": {"name": "colour", "schema": _COLOUR_SCHEMA, "strict": True}},
    )
    report["json_object"] = _structured(
        client, model, [{"role": "user", "content": 'Name one colour, as JSON: {"colour": "..."}.'}],
        {"type": "json_object"},
    )
    image = [user_message("What colour is this square? One word.", [_red_square()])]
    report["images"] = _accepted(client, model=model, messages=image)
    report["reasoning"] = _accepted(client, model=model, messages=[{"role": "user", "content": "Say OK."}],
                                    reasoning_effort="low")
    return report


def _red_square() -> bytes:
    """An 8×8 red PNG, the image the image-input probe sends."""
    import io

    from PIL import Image

    out = io.BytesIO()
    Image.new("RGB", (8, 8), (220, 20, 20)).save(out, format="PNG")
    return out.getvalue()


def _accepted(client: Any, **request: Any) -> str:
    """"supported" when the server answers the request, else why not."""
    return _ask(client, request)[0]


def _structured(client: Any, model: str, messages: list, response_format: dict) -> str:
    """Whether the server honours a response format: refused (an error), ignored (prose
    back) or supported (an answer that is the requested JSON as it stands)."""
    verdict, content = _ask(client, {"model": model, "messages": messages, "response_format": response_format})
    if verdict != "supported":
        return verdict
    try:
        value = json.loads(content)
    except ValueError:
        wrapped = extract_json(content) != content.strip()
        return f"ignored (the answer is {'JSON wrapped in prose or fences' if wrapped else 'not JSON'})"
    if not isinstance(value, dict) or not isinstance(value.get("colour"), str):
        return "ignored (the answer is JSON of another shape)"
    return "supported"


def _ask(client: Any, request: dict[str, Any]) -> tuple[str, str]:
    import openai

    from scenewright.backends.structured import transport_error

    try:
        completion = client.chat.completions.create(**request)
    except openai.APIStatusError as exc:
        return "refused (" + str(transport_error("", exc)).removeprefix(": ") + ")", ""
    except (openai.APIError, json.JSONDecodeError) as exc:
        raise transport_error(f"probe of {request['model']}", exc) from exc
    choices = completion.choices or []
    return "supported", (choices[0].message.content or "") if choices else ""
