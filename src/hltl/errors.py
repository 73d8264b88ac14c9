"""Error hierarchy: one root, subclasses that also inherit the matching builtin."""

from __future__ import annotations


class HltlError(Exception):
    """Root of every error hltl raises on purpose."""


class SpecSyntaxError(HltlError, ValueError):
    """An LTLf formula does not parse; carries the line and column of the problem."""

    def __init__(self, message: str, *, text: str = "", line: int = 0, column: int = 0) -> None:
        super().__init__(message)
        self.text = text
        self.line = line
        self.column = column


class SpecValidationError(HltlError, ValueError):
    """An H-LTLf specification breaks one of the validity rules (DESIGN.md §4)."""


class SceneError(HltlError, ValueError):
    """A scene file or scene value is malformed (names file, field and value)."""


class UnknownEntityError(HltlError, KeyError):
    """A name refers to no robot, object, human or surface of the scene."""

    def __str__(self) -> str:  # KeyError would quote the message otherwise
        return str(self.args[0]) if self.args else ""


class AutomatonError(HltlError, RuntimeError):
    """Compiling a formula to a DFA failed (MONA missing, crashed or timed out)."""


class BackendUnavailableError(HltlError, ImportError):
    """An optional dependency or external binary is missing; names the extra to install."""


class GroundingError(HltlError, ValueError):
    """An instruction could not be turned into a valid H-LTLf specification.

    ``prompt_tokens`` and ``completion_tokens`` are what the failed attempt spent on an LLM:
    tokens are paid for whether or not the answer is used, so they are always reported.
    """

    def __init__(self, message: str, *, prompt_tokens: int = 0, completion_tokens: int = 0) -> None:
        super().__init__(message)
        self.prompt_tokens = prompt_tokens
        self.completion_tokens = completion_tokens

    @property
    def tokens_spent(self) -> int:
        """All tokens spent before the failure."""
        return self.prompt_tokens + self.completion_tokens


class EventsError(HltlError, ValueError):
    """An events file is malformed or names unknown entities."""


class PlanFormatError(HltlError, ValueError):
    """A plan or log file does not follow the documented format."""


class BusError(HltlError, RuntimeError):
    """The Zenoh bus cannot be used: no node answers, a malformed message, a bad endpoint."""


class OutputError(HltlError, OSError):
    """A file or folder hltl was asked to write cannot be written (names the path and why)."""


class PerceptionError(HltlError, ValueError):
    """A frame folder or camera file is malformed, or frames cannot be interpreted."""


MAX_ERROR_CHARS = 2000


def error_line(message: str) -> str:
    """One bounded line: messages quote user input, which must not flood the terminal."""
    line = " ".join(message.split("\n"))
    if len(line) > MAX_ERROR_CHARS:
        line = f"{line[:MAX_ERROR_CHARS]}… (message of {len(line):,} characters cut)"
    return line
