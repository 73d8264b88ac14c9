"""LLM grounder for any OpenAI-compatible endpoint (OpenAI, Ollama, vLLM, llama.cpp server)."""

from __future__ import annotations

import math
import os
import tomllib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from hltl.errors import BackendUnavailableError, GroundingError
from hltl.fileio import clip, quote, read_text
from hltl.grounding.base import Grounding, TokenUsage
from hltl.grounding.prompt import build_messages, repair_message, response_format
from hltl.grounding.update import ground_update
from hltl.grounding.validate import AnswerError, check_answer
from hltl.spec.hierarchy import HSpec
from hltl.world.scene import Scene

DEFAULT_CONFIG_PATH = Path("~/.config/hltl/llm.toml")
ENV_PREFIX = "HLTL_LLM_"
INSTALL_HINT = "pip install 'hltl[llm]'"


@dataclass(frozen=True, slots=True)
class LLMConfig:
    """Where and how to query the model.

    Attributes:
        base_url: the endpoint (``None``: OpenAI's), e.g. ``http://localhost:11434/v1``.
        model: the model name the endpoint knows.
        api_key: the key; local servers accept any (``None``: ``$OPENAI_API_KEY`` or a dummy
            when ``base_url`` is set).
        max_repairs: rounds that send a rejected answer's error back (0: no repair).
        temperature: sampling temperature (0 for repeatable answers).
        timeout: seconds per request.
        structured: try JSON-schema structured output first (falls back to JSON mode, then none).
        max_tokens: completion token limit per query.
    """

    base_url: str | None = None
    model: str = "gpt-4o-mini"
    api_key: str | None = field(default=None, repr=False)
    max_repairs: int = 2
    temperature: float = 0.0
    timeout: float = 60.0
    structured: bool = True
    max_tokens: int = 600


def load_config(path: str | Path | None = None, env: Mapping[str, str] | None = None) -> LLMConfig:
    """The configuration from a TOML file and the environment (see the module docstring).

    Raises:
        GroundingError: the file is unreadable, not TOML, or has unknown keys or bad values.
    """
    env = os.environ if env is None else env
    values: dict[str, Any] = {}
    file = Path(path) if path is not None else None
    if file is None and env.get("HLTL_LLM_CONFIG"):
        file = Path(env["HLTL_LLM_CONFIG"])
    if file is None and DEFAULT_CONFIG_PATH.expanduser().is_file():
        file = DEFAULT_CONFIG_PATH.expanduser()
    if file is not None:
        values.update(_read_toml(file.expanduser(), env))
    for key in ("base_url", "model", "api_key"):
        value = env.get(ENV_PREFIX + key.upper())
        if value:
            values[key] = value
    timeout = env.get(ENV_PREFIX + "TIMEOUT")
    if timeout:
        try:
            values["timeout"] = float(timeout)
        except ValueError:
            values["timeout"] = math.nan  # refused below with the variable's name
        where = f"{ENV_PREFIX}TIMEOUT"
    else:
        where = "timeout"
    config = replace(LLMConfig(), **values)
    if config.max_repairs < 0:
        raise GroundingError(f"max_repairs must be >= 0, got {config.max_repairs}")
    if not (math.isfinite(config.timeout) and config.timeout > 0):
        raise GroundingError(
            f"{where}: expected seconds, a finite number > 0, got "
            f"{quote(timeout or config.timeout)}"
        )
    if config.max_tokens < 1:
        raise GroundingError(f"max_tokens must be >= 1, got {config.max_tokens}")
    return config


def _read_toml(file: Path, env: Mapping[str, str]) -> dict[str, Any]:
    try:
        data = tomllib.loads(read_text(file, "LLM config", GroundingError))
    except tomllib.TOMLDecodeError as exc:
        raise GroundingError(f"{file}: not valid TOML: {exc}") from None
    data = dict(data.get("llm", data))  # a [llm] table or top-level keys
    key_env = data.pop("api_key_env", None)
    if key_env is not None:
        if not isinstance(key_env, str):
            raise GroundingError(f"{file}: api_key_env must be a variable name, got {key_env!r}")
        if env.get(key_env):
            data.setdefault("api_key", env[key_env])
    types = {f.name: f.type for f in fields(LLMConfig)}
    for key, value in data.items():
        if key not in types:
            raise GroundingError(
                f"{file}: unknown key {key!r}; expected one of {', '.join([*types, 'api_key_env'])}"
            )
        want = str(types[key])
        ok = (
            (want.startswith("str") and isinstance(value, str))
            or (want == "int" and isinstance(value, int) and not isinstance(value, bool))
            or (want == "float" and isinstance(value, int | float) and not isinstance(value, bool))
            or (want == "bool" and isinstance(value, bool))
        )
        if not ok:
            raise GroundingError(f"{file}: {key} must be {want.split(' |')[0]}, got {value!r}")
    return data


class LLMGroundingError(GroundingError):
    """Every answer was rejected; ``history`` holds each (answer, error) and ``tokens`` the cost."""

    def __init__(self, message: str, history: list[tuple[str, str]], tokens: TokenUsage) -> None:
        super().__init__(message, prompt_tokens=tokens.prompt, completion_tokens=tokens.completion)
        self.history = history
        self.tokens = tokens


# An answer is a few hundred characters; far more is a misbehaving endpoint or model. Only this
# much of a refused answer goes back into the repair prompt (the prompt must stay small).
MAX_ANSWER_CHARS = 20_000
ECHO_CHARS = 2_000


# A chat function: (messages, output mode) -> an OpenAI-shaped chat completion. Modes, best
# first: "json_schema" (structured output with the answer schema), "json_object" (JSON mode),
# "text" (plain; the answer is still parsed as JSON).
ChatFn = Callable[[list[dict[str, str]], str], Any]
MODES = ("json_schema", "json_object", "text")


def ground_with_chat(
    chat: ChatFn,
    instruction: str,
    scene: Scene,
    *,
    max_repairs: int,
    modes: list[str],
    max_tokens: int | None = None,
) -> Grounding:
    """The query-validate-repair loop shared by the LLM and local grounders.

    ``modes`` are the output modes to try, best first; a mode the endpoint rejects (the chat
    function raises ``UnsupportedFormat``) is removed from the list, which the caller may keep
    for its next queries, and the same query is sent in the next mode. ``max_tokens`` is the
    completion limit sent with each query; a response reporting more is refused.

    Raises:
        LLMGroundingError: every answer was refused, the model declined or the endpoint failed;
            it carries the tokens spent.
    """
    if not instruction.strip():
        raise GroundingError("the instruction is empty")
    messages = build_messages(instruction, scene)
    tokens = TokenUsage()
    history: list[tuple[str, str]] = []
    rounds = 0
    for _ in range(max_repairs + 1):
        try:
            response = _query(chat, messages, modes)
        except GroundingError as exc:  # the endpoint failed: earlier rounds are still paid for
            raise LLMGroundingError(str(exc), history, tokens) from None
        rounds += 1
        used = usage_of(response)
        tokens = tokens + used
        if max_tokens is not None and used.completion > max_tokens:
            raise LLMGroundingError(
                f"the endpoint reports {used.completion:,} completion tokens for one answer "
                f"although max_tokens is {max_tokens:,}: it ignores the limit; its answers are "
                "refused",
                history,
                tokens,
            )
        text = content_of(response)
        try:
            if text is not None and len(text) > MAX_ANSWER_CHARS:
                raise AnswerError(
                    f"the answer has {len(text):,} characters; an answer is one short JSON "
                    f"object (at most {MAX_ANSWER_CHARS:,} characters)"
                )
            spec, ids = check_answer(text, scene)
        except AnswerError as exc:
            echo = (text or "")[:ECHO_CHARS]
            history.append((echo, str(exc)))
            messages = [
                *messages,
                {"role": "assistant", "content": echo},
                {"role": "user", "content": repair_message(str(exc))},
            ]
            continue
        except GroundingError as exc:  # the model declined: final
            raise LLMGroundingError(str(exc), [*history, (text or "", str(exc))], tokens) from None
        return Grounding(spec=spec, entities=ids, tokens=tokens, rounds=rounds)
    last = history[-1][1] if history else "no answer"
    raise LLMGroundingError(
        f"the model's answer was rejected {len(history)} time(s) for "
        f"{quote(instruction.strip())}; last error: {last}",
        history,
        tokens,
    )


class UnsupportedFormat(Exception):
    """Raised by a chat function when the endpoint rejects the requested response format."""


def _query(chat: ChatFn, messages: list[dict[str, str]], modes: list[str]) -> Any:
    while True:
        if not modes:
            raise GroundingError("the endpoint rejected every response format")
        try:
            return chat(messages, modes[0])
        except UnsupportedFormat:
            modes.pop(0)


def _get(obj: Any, name: str) -> Any:
    if isinstance(obj, Mapping):
        return obj.get(name)
    return getattr(obj, name, None)


def content_of(response: Any) -> str | None:
    """The first choice's message text of an OpenAI-shaped response (object or dict)."""
    choices = _get(response, "choices") or []
    if not choices:
        return None
    message = _get(choices[0], "message")
    content = _get(message, "content") if message is not None else None
    return content if isinstance(content, str) else None


def usage_of(response: Any) -> TokenUsage:
    """Prompt and completion tokens from a response's ``usage`` (0 when absent or not a count)."""
    usage = _get(response, "usage")
    if usage is None:
        return TokenUsage()

    def count(name: str) -> int:
        v = _get(usage, name)
        return v if isinstance(v, int) and not isinstance(v, bool) and v >= 0 else 0

    return TokenUsage(count("prompt_tokens"), count("completion_tokens"))


class LLMGrounder:
    """Grounds instructions with a chat model behind an OpenAI-compatible API.

    Args:
        config: endpoint and model (default: :func:`load_config`).
        client: anything with ``client.chat.completions.create(**kwargs)`` returning an
            OpenAI-shaped chat completion; tests inject a fake. Default: an ``openai.OpenAI``.
        config_path: a TOML file for :func:`load_config` when ``config`` is not given.
    """

    name = "llm"

    def __init__(
        self,
        config: LLMConfig | None = None,
        client: Any = None,
        config_path: str | Path | None = None,
    ) -> None:
        self.config = config if config is not None else load_config(config_path)
        self._client = client
        # output modes still worth trying with this endpoint, best first
        self.modes: list[str] = list(MODES if self.config.structured else MODES[1:])

    @property
    def client(self) -> Any:
        if self._client is None:
            self._client = make_openai_client(self.config)
        return self._client

    def ground(self, instruction: str, scene: Scene, running: HSpec | None = None) -> Grounding:
        """Ground ``instruction``; with ``running``, merge it as an update (update.py)."""
        if running is not None:
            return ground_update(instruction, scene, running, self)
        client = self.client
        formats: dict[str, dict[str, Any]] = {
            "json_schema": response_format(scene),  # names this scene's ids
            "json_object": {"type": "json_object"},
        }

        def chat(messages: list[dict[str, str]], mode: str) -> Any:
            kwargs: dict[str, Any] = {
                "model": self.config.model,
                "messages": messages,
                "temperature": self.config.temperature,
                "max_tokens": self.config.max_tokens,
            }
            if mode in formats:
                kwargs["response_format"] = formats[mode]
            where = self.config.base_url or "api.openai.com"
            try:
                return client.chat.completions.create(**kwargs)
            except Exception as exc:
                if mode in formats and _rejects_format(exc):
                    raise UnsupportedFormat(str(exc)) from exc
                if "Timeout" in type(exc).__name__:
                    raise GroundingError(
                        f"the LLM endpoint {where} did not answer within "
                        f"{self.config.timeout:g} s; set {ENV_PREFIX}TIMEOUT (or 'timeout' in "
                        "the config file) to wait longer"
                    ) from exc
                raise GroundingError(
                    f"the LLM endpoint {where} failed ({type(exc).__name__}): {clip(str(exc))}"
                ) from exc

        return ground_with_chat(
            chat,
            instruction,
            scene,
            max_repairs=self.config.max_repairs,
            modes=self.modes,
            max_tokens=self.config.max_tokens,
        )


def _rejects_format(exc: Exception) -> bool:
    """Whether an API error says the request (its response_format) is not supported.

    Servers differ: OpenAI and vLLM answer 400, some 422, and llama-cpp-python's server 500
    with a validation message naming ``response_format``.
    """
    status = getattr(exc, "status_code", None)
    return (
        status in (400, 404, 415, 422)
        or "response_format" in str(exc)
        or type(exc).__name__ in ("BadRequestError", "UnprocessableEntityError")
    )


def make_openai_client(config: LLMConfig) -> Any:
    """An ``openai.OpenAI`` client for ``config``.

    Raises:
        BackendUnavailableError: the ``openai`` package is missing.
        GroundingError: no API key for OpenAI's own endpoint.
    """
    try:
        import openai
    except ImportError:
        raise BackendUnavailableError(
            f"the llm grounder needs the openai package: {INSTALL_HINT}"
        ) from None
    key = config.api_key or os.environ.get("OPENAI_API_KEY")
    if not key:
        if config.base_url is None:
            raise GroundingError(
                "no API key for OpenAI: set HLTL_LLM_API_KEY or OPENAI_API_KEY, or point "
                "HLTL_LLM_BASE_URL at a local server"
            )
        key = "not-needed"  # Ollama, vLLM and llama.cpp servers accept any key
    # no retries: the timeout the user set is then the longest a query can take
    return openai.OpenAI(
        base_url=config.base_url, api_key=key, timeout=config.timeout, max_retries=0
    )
