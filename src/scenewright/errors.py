"""The package's exceptions: one base, a subclass per kind of culprit.

Messages carry the offending value and, where there is a choice, the valid options, so the
CLI can print them as they are.
"""


class ScenewrightError(Exception):
    """Base of every error scenewright raises on purpose."""


class InputError(ScenewrightError, ValueError):
    """The user's input (a file, a flag, a text, an instruction) is wrong."""


class BackendError(ScenewrightError, RuntimeError):
    """A model backend failed, answered nonsense past the retry budget, or is not installed."""


class InfeasibleLayout(ScenewrightError):
    """The constraints admit no collision-free layout for some objects."""


class FolderBusy(ScenewrightError):
    """Another process is writing the scene folder, and did not finish within the wait allowed."""


class MissingExtra(BackendError, ImportError):
    """An optional dependency is missing; the message names the extra to install."""

    def __init__(self, feature: str, extra: str, module: str):
        super().__init__(
            f"{feature} needs the '{module}' package: install it with "
            f"`pip install 'scenewright[{extra}]'` (or `make install-{extra}`)."
        )
        self.extra = extra
