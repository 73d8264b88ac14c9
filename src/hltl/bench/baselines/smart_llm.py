"""SMART-LLM-R: an LLM writes a Python script over the action API; it runs in a sandbox."""

from __future__ import annotations

import ast
import os
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from hltl.bench.baselines.policy import PlanContext, Script
from hltl.errors import BackendUnavailableError
from hltl.grounding.llm import (
    DEFAULT_CONFIG_PATH,
    content_of,
    load_config,
    make_openai_client,
    usage_of,
)
from hltl.grounding.local import default_model_path, load_llama
from hltl.skills.library import Action
from hltl.world.scene import Scene
from hltl.world.state import WorldState

MAX_CALLS = 400
MAX_RANGE = 1000
ChatFn = Callable[[list[dict[str, str]]], Any]

SYSTEM = """\
You control a team of fixed-base robot arms that hand objects to people. Write a Python script \
that completes the instruction using only these functions. Each call is one action; calls run \
one after another, each after the previous one has finished.

pick(robot, obj): the robot grasps obj. The robot must hold nothing; obj must rest within the \
robot's reach (distance from its base <= reach).
handover_r2r(giver, receiver, obj): the giver passes obj to the receiver. The giver holds obj, the \
receiver holds nothing, their bases are closer than the sum of their reaches, and no person \
stands inside both robots' workspaces.
handover_r2h(robot, obj, person): the robot hands obj to the person; the person's horizontal \
distance from the robot's base must be <= reach + 0.3.
place(robot, obj, surface): the robot puts obj on the surface (within its reach).
parallel(a, b, ...): run the actions a, b, ... (values returned by the calls above) at the same \
time; they must use different robots and different objects.

A robot holds at most one object. Finish all deliveries as fast as possible: use robots in \
parallel where you can. Work as follows: (1) decompose the instruction into subtasks, written as \
comments; (2) allocate robots to each subtask, as comments; (3) write the code. No imports. \
Answer with one ```python code block."""

EXAMPLE_USER = """\
Robots:
- r1: base (0.0, 0.0), reach 0.7
- r2: base (1.0, 0.0), reach 0.7
Objects:
- mug: resting at (0.1, 0.2)
- book: resting at (1.2, -0.1)
People:
- X (Person X) at (-0.8, 0.0)
- Y (Person Y) at (1.8, 0.0)
Surfaces: none
Already done: nothing
Instruction: Give Person X the mug and the book."""

EXAMPLE_ANSWER = """\
```python
# Subtasks: (1) mug to X; (2) book to X.
# Allocation: mug is within r1's reach and X is in r1's workspace: r1 alone.
# book is within r2's reach only; X is in r1's workspace only: r2 picks, hands over to r1.
parallel(pick("r1", "mug"), pick("r2", "book"))
handover_r2h("r1", "mug", "X")
handover_r2r("r2", "r1", "book")
handover_r2h("r1", "book", "X")
```"""


class ScriptError(Exception):
    """The script cannot be executed (syntax, a forbidden construct, a runtime error)."""


_SAFE_BUILTINS: dict[str, Any] = {
    name: getattr(__builtins__, name) if not isinstance(__builtins__, dict) else __builtins__[name]
    for name in (
        "abs",
        "all",
        "any",
        "bool",
        "dict",
        "enumerate",
        "float",
        "int",
        "len",
        "list",
        "max",
        "min",
        "reversed",
        "set",
        "sorted",
        "str",
        "sum",
        "tuple",
        "zip",
        "isinstance",
    )
}
_FORBIDDEN = (
    ast.Import,
    ast.ImportFrom,
    ast.While,
    ast.Global,
    ast.Nonlocal,
    ast.ClassDef,
    ast.AsyncFunctionDef,
    ast.Await,
    ast.AsyncFor,
    ast.AsyncWith,
    ast.Yield,
    ast.YieldFrom,
)


def extract_code(text: str) -> str:
    """The code of the first fenced block (``python`` or bare), else the whole text."""
    m = re.search(r"```(?:python|py)?[ \t]*\n(.*?)```", text, re.S)
    return m.group(1) if m else text


def _check_ast(tree: ast.AST) -> None:
    for node in ast.walk(tree):
        if isinstance(node, _FORBIDDEN):
            raise ScriptError(
                f"line {getattr(node, 'lineno', '?')}: {type(node).__name__} "
                "is not allowed in a script"
            )
        if isinstance(node, ast.Attribute) and node.attr.startswith("_"):
            raise ScriptError(f"line {node.lineno}: access to {node.attr!r} is not allowed")
        if isinstance(node, ast.Name) and node.id.startswith("__"):
            raise ScriptError(f"line {node.lineno}: name {node.id!r} is not allowed")


@dataclass(frozen=True, slots=True)
class _Call:
    index: int
    action: Action


def run_script(code: str, scene: Scene) -> tuple[tuple[Action, ...], ...]:
    """Execute ``code`` in the sandbox and return the steps it scheduled.

    Raises:
        ScriptError: the script does not parse, uses a forbidden construct, names an id the
            scene does not have, calls the API wrongly, or raises.
    """
    try:
        tree = ast.parse(code, mode="exec")
    except SyntaxError as exc:
        raise ScriptError(f"syntax error on line {exc.lineno}: {exc.msg}") from None
    _check_ast(tree)
    steps: list[list[Action]] = []
    calls = 0

    def known(value: object, ids: tuple[str, ...], kind: str) -> str:
        if not isinstance(value, str) or value not in ids:
            raise ScriptError(f"unknown {kind} {value!r}; the scene has: {', '.join(ids)}")
        return value

    def record(action: Action) -> _Call:
        nonlocal calls
        calls += 1
        if calls > MAX_CALLS:
            raise ScriptError(f"more than {MAX_CALLS} actions")
        steps.append([action])
        return _Call(len(steps) - 1, action)

    def pick(robot: object, obj: object) -> _Call:
        return record(
            Action(
                "pick",
                (known(robot, scene.robot_ids, "robot"),),
                known(obj, scene.object_ids, "object"),
            )
        )

    def place(robot: object, obj: object, surface: object) -> _Call:
        return record(
            Action(
                "place",
                (known(robot, scene.robot_ids, "robot"),),
                known(obj, scene.object_ids, "object"),
                surface=known(surface, scene.surface_ids, "surface"),
            )
        )

    def handover_r2r(giver: object, receiver: object, obj: object) -> _Call:
        return record(
            Action(
                "handover_r2r",
                (known(giver, scene.robot_ids, "robot"), known(receiver, scene.robot_ids, "robot")),
                known(obj, scene.object_ids, "object"),
            )
        )

    def handover_r2h(robot: object, obj: object, person: object) -> _Call:
        return record(
            Action(
                "handover_r2h",
                (known(robot, scene.robot_ids, "robot"),),
                known(obj, scene.object_ids, "object"),
                human=known(person, scene.human_ids, "person"),
            )
        )

    def parallel(*items: object) -> None:
        flat: list[object] = []
        for it in items:
            flat.extend(it if isinstance(it, list | tuple) else [it])
        idx = []
        for it in flat:
            if not isinstance(it, _Call):
                raise ScriptError(f"parallel() takes the results of action calls, got {it!r}")
            idx.append(it.index)
        if not idx:
            return
        first = min(idx)
        for i in sorted(set(idx)):
            if i != first:
                steps[first].extend(steps[i])
                steps[i] = []

    def bounded_range(*args: int) -> range:
        r = range(*args)
        if len(r) > MAX_RANGE:
            raise ScriptError(f"range of {len(r)} elements (at most {MAX_RANGE})")
        return r

    env: dict[str, Any] = {
        "__builtins__": {**_SAFE_BUILTINS, "range": bounded_range, "print": lambda *a, **k: None},
        "pick": pick,
        "place": place,
        "handover_r2r": handover_r2r,
        "handover_r2h": handover_r2h,
        "parallel": parallel,
    }
    try:
        exec(compile(tree, "<script>", "exec"), env)
    except ScriptError:
        raise
    except RecursionError:
        raise ScriptError("the script recursed too deeply") from None
    except Exception as exc:  # any runtime error makes the script non-executable
        raise ScriptError(f"{type(exc).__name__}: {exc}") from None
    return tuple(tuple(s) for s in steps if s)


def describe_state(scene: Scene, world: WorldState) -> str:
    """The scene and the current state as the prompt shows them."""
    lines = ["Robots:"]
    for r in scene.robots:
        down = " (unavailable now)" if r.id in world.unavailable else ""
        held = world.holding(r.id)
        hold = f", holding {held}" if held else ""
        lines.append(
            f"- {r.id}: base ({r.base[0]:.2f}, {r.base[1]:.2f}), reach {r.reach:.2f}{hold}{down}"
        )
    lines.append("Objects:")
    for o in scene.objects:
        st = world.object_status(o.id)
        if st.loc.kind == "rest":
            where = f"resting at ({st.position[0]:.2f}, {st.position[1]:.2f})"
        elif st.loc.kind == "held":
            where = f"held by {st.loc.ref}"
        elif st.loc.kind == "on":
            where = f"on {st.loc.ref}"
        else:
            where = f"already delivered to {st.loc.ref}"
        lines.append(f"- {o.id}: {where}")
    lines.append("People:")
    for hid, pos in world.humans:
        lines.append(f"- {hid} ({scene.human(hid).name}) at ({pos[0]:.2f}, {pos[1]:.2f})")
    if scene.surfaces:
        lines.append("Surfaces:")
        lines += [f"- {s.id} at ({s.center[0]:.2f}, {s.center[1]:.2f})" for s in scene.surfaces]
    else:
        lines.append("Surfaces: none")
    return "\n".join(lines)


def build_messages(ctx: PlanContext) -> list[dict[str, str]]:
    """The chat messages of one SMART-LLM-R query."""
    delivered = [
        f"{o} to {st.loc.ref}" for o, st in ctx.world.objects if st.loc.kind == "delivered"
    ]
    said = " ".join(ctx.instructions)
    user = (
        f"{describe_state(ctx.scene, ctx.world)}\n"
        f"Already done: {', '.join(delivered) or 'nothing'}\n"
        f"Instruction: {said}"
    )
    if ctx.trigger not in ("initial",):
        user += (
            f"\nThe plan is being revised ({ctx.trigger}). Write the script for what remains, "
            "from the current state."
        )
    return [
        {"role": "system", "content": SYSTEM},
        {"role": "user", "content": EXAMPLE_USER},
        {"role": "assistant", "content": EXAMPLE_ANSWER},
        {"role": "user", "content": user},
    ]


def _get(obj: Any, name: str) -> Any:
    if isinstance(obj, Mapping):
        return obj.get(name)
    return getattr(obj, name, None)


class SmartLLMPolicy:
    """SMART-LLM-R's planner (see the module docstring).

    Args:
        chat: ``messages -> OpenAI-shaped chat completion``; default: from ``client``, else the
            configured endpoint (:func:`default_chat`).
        client: an object with ``client.chat.completions.create(**kwargs)`` (tests inject one).
        model: the model name for ``client``.
        max_tokens: completion limit per query.
    """

    name = "smart-llm"
    replan_on_context = False

    def __init__(
        self,
        chat: ChatFn | None = None,
        client: Any = None,
        model: str = "gpt-4o-mini",
        max_tokens: int = 1500,
    ) -> None:
        if chat is None and client is not None:

            def chat(messages: list[dict[str, str]]) -> Any:
                return client.chat.completions.create(
                    model=model, messages=messages, temperature=0.0, max_tokens=max_tokens
                )

        self._chat = chat

    def plan(self, ctx: PlanContext) -> Script:
        if self._chat is None:
            self._chat = default_chat()
        response = self._chat(build_messages(ctx))
        usage = usage_of(response)
        text = content_of(response) or ""
        try:
            steps = run_script(extract_code(text), ctx.scene)
        except ScriptError as exc:
            return Script((), usage.total, 1, str(exc), text)
        return Script(steps, usage.total, 1, None, text)


def llm_unavailable() -> str | None:
    """Why SMART-LLM-R cannot run here, or None when an LLM backend is configured."""
    if (
        os.environ.get("HLTL_LLM_BASE_URL")
        or os.environ.get("HLTL_LLM_CONFIG")
        or DEFAULT_CONFIG_PATH.expanduser().is_file()
    ):
        try:
            import openai  # noqa: F401
        except ImportError:
            return "an LLM endpoint is configured but openai is missing: pip install 'hltl[llm]'"
        return None
    if os.environ.get("HLTL_LOCAL_MODEL"):
        try:
            import llama_cpp  # noqa: F401
        except ImportError:
            return (
                "HLTL_LOCAL_MODEL is set but llama-cpp-python is missing: pip install 'hltl[local]'"
            )
        return None
    return "no LLM configured (set HLTL_LLM_BASE_URL, or HLTL_LOCAL_MODEL with the local extra)"


def default_chat() -> ChatFn:
    """A chat function for the configured backend: the OpenAI-compatible endpoint first.

    Raises:
        BackendUnavailableError: no backend is configured or its package is missing.
    """
    missing = llm_unavailable()
    if missing is not None:
        raise BackendUnavailableError(f"SMART-LLM-R cannot run: {missing}")
    if os.environ.get("HLTL_LOCAL_MODEL") and not os.environ.get("HLTL_LLM_BASE_URL"):
        llm = load_llama(default_model_path())

        def local(messages: list[dict[str, str]]) -> Any:
            return llm.create_chat_completion(messages=messages, temperature=0.0, max_tokens=1500)

        return local

    config = load_config()
    client = make_openai_client(config)

    def remote(messages: list[dict[str, str]]) -> Any:
        return client.chat.completions.create(
            model=config.model, messages=messages, temperature=config.temperature, max_tokens=1500
        )

    return remote
