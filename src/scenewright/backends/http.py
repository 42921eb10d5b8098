"""HTTP for the remote backends with two limits a server cannot talk its way around.

httpx's timeouts bound each socket read, so a server that sends one byte a second keeps a
request alive for ever, and a body is read whole however large. :class:`LimitedTransport`
gives every request a total deadline (its read timeout, counted from when it is sent) and a
size limit, checked as each chunk of the body arrives: the download stops there. Both errors
are httpx request errors, so the OpenAI SDK and the Hunyuan3D client treat them as the
transport faults they are, and their messages say what happened.
"""

from __future__ import annotations

import time
from collections.abc import Iterator

import httpx


class DeadlineExceeded(httpx.ReadTimeout):
    """The whole request took longer than its deadline."""


class ResponseTooLarge(httpx.DecodingError):
    """The response body is larger than ``max_download_bytes``."""


class _LimitedStream(httpx.SyncByteStream):
    def __init__(self, inner: httpx.SyncByteStream, request: httpx.Request, deadline: float, seconds: float,
                 max_bytes: int):
        self.inner, self.request = inner, request
        self.deadline, self.seconds, self.max_bytes = deadline, seconds, max_bytes

    def __iter__(self) -> Iterator[bytes]:
        received = 0
        for chunk in self.inner:
            received += len(chunk)
            if received > self.max_bytes:
                raise ResponseTooLarge(too_large(self.max_bytes), request=self.request)
            if time.monotonic() > self.deadline:
                raise DeadlineExceeded(timed_out(self.seconds), request=self.request)
            yield chunk

    def close(self) -> None:
        self.inner.close()


def timed_out(seconds: float) -> str:
    return f"timed out after {seconds:g} s"


def too_large(max_bytes: int) -> str:
    return f"the response is larger than max_download_bytes ({max_bytes:,} bytes); the download was stopped"


class LimitedTransport(httpx.BaseTransport):
    """Wraps a transport: each request ends within its read timeout in total, and reads at most
    ``max_bytes`` of body."""

    def __init__(self, max_bytes: int, inner: httpx.BaseTransport | None = None):
        self.max_bytes = max_bytes
        self.inner = inner or httpx.HTTPTransport()

    def handle_request(self, request: httpx.Request) -> httpx.Response:
        timeouts = request.extensions.get("timeout") or {}
        seconds = timeouts.get("read") or timeouts.get("connect")
        started = time.monotonic()
        response = self.inner.handle_request(request)
        length = response.headers.get("content-length", "")
        if length.isdigit() and int(length) > self.max_bytes:
            response.close()
            raise ResponseTooLarge(too_large(self.max_bytes), request=request)
        deadline = started + seconds if seconds else float("inf")
        if time.monotonic() > deadline:
            response.close()
            raise DeadlineExceeded(timed_out(seconds), request=request)
        assert isinstance(response.stream, httpx.SyncByteStream)
        response.stream = _LimitedStream(response.stream, request, deadline, seconds or 0.0, self.max_bytes)
        return response

    def close(self) -> None:
        self.inner.close()


def limited_client(timeout: float, max_bytes: int, **transport: object) -> httpx.Client:
    """An httpx client whose every request is bounded as :class:`LimitedTransport` says."""
    return httpx.Client(
        timeout=httpx.Timeout(timeout, connect=min(10.0, timeout)),
        transport=LimitedTransport(max_bytes, httpx.HTTPTransport(**transport)),
    )
