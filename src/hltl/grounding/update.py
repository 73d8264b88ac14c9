"""Instructions given during execution (paper GOAL events): merge them into the running spec."""

from __future__ import annotations

import re
from collections.abc import Collection, Sequence
from dataclasses import dataclass

from hltl.errors import GroundingError, SpecValidationError
from hltl.fileio import quote
from hltl.grounding.base import Grounder, Grounding, TokenUsage, UpdateInfo
from hltl.grounding.lexicon import Lexicon, lex
from hltl.grounding.tree import (
    Names,
    Op,
    Task,
    check_deliveries,
    composite,
    decode,
    recognise_group,
    recognise_task,
)
from hltl.spec.automata import rename_atoms
from hltl.spec.hierarchy import HSpec, spec_from_dict

# carry_over moved to hltl.spec.monitor (a monitor operation); the old import path still works
from hltl.spec.monitor import carry_over as carry_over
from hltl.spec.printer import to_string
from hltl.spec.syntax import Atom
from hltl.world.scene import Scene

_THEN = re.compile(
    r"^\s*(?:and\s+)?(?:then|after\s+that|afterwards?|next|finally|later|"
    r"(?:when|once|after)\s+(?:you\s*(?:'re|are|have|'ve)?\s*)?(?:done|finished|finish)"
    r"(?:\s+with\s+(?:that|this))?)\b[\s,]*",
    re.IGNORECASE,
)
# session 30: 'The flashlight to Jess next.' — a 'next' closing a one-sentence update is 'Next, …'
_NEXT_LAST = re.compile(
    r"^(?P<body>[^.;!?]+?),?\s+next(?P<tail>\s*(?:,[^.;!?]*)?[.!?]?)\s*$", re.IGNORECASE
)
_ADD = re.compile(
    r"^\s*(?:and\s+)?(?:also|additionally|in\s+addition|plus|and)\b[\s,]*", re.IGNORECASE
)
_CANCEL = re.compile(
    r"^\s*(?:please\s+)?(?:cancel|forget(?:\s+about)?|skip|remove|abort|scrap|drop|"
    r"never\s*mind|no\s+longer|don'?t|do\s+not)\b[\s,]*",
    re.IGNORECASE,
)
_NEGATED = re.compile(r"\b(?:don'?t|do\s+not|never|not\s+(?:to|for|on|in|into|onto))\b", re.I)
_INSTEAD_OF = re.compile(r"\binstead\s+of\s+(?P<x>[^,.;]+)", re.IGNORECASE)
_INSTEAD = re.compile(r"\binstead\b", re.IGNORECASE)
_FIRST = re.compile(
    r"\b(?:first|firstly|prioriti[sz]e|priority|urgent(?:ly)?|asap)\b", re.IGNORECASE
)
_SEQ_WORDS = re.compile(r"\b(?:then|after|before|once|next|finally|afterwards)\b", re.IGNORECASE)
_PRIORITY_FILLER = re.compile(
    r"\b(?:please|do|first|firstly|prioriti[sz]e|priority|urgent(?:ly)?|asap|with|as\s+a|"
    r"the\s+)\b",
    re.IGNORECASE,
)
_ROOT_SUFFIX = re.compile(r"^(?P<base>.*?)_(?P<n>\d+)$")


@dataclass(frozen=True, slots=True)
class UpdateCommand:
    """What an update instruction asks for: its kind, the new task text, the running tasks named."""

    kind: str  # add, then, first, priority, cancel, instead
    text: str = ""  # the new task to ground (add, then, first, instead)
    targets: str = ""  # words naming running tasks (cancel, priority, instead of …)


def classify(instruction: str, lexicon: Lexicon) -> UpdateCommand:
    """Read which kind of update ``instruction`` is (see the module docstring)."""
    text = instruction.strip()
    m = _CANCEL.match(text)
    if m:
        rest = text[m.end() :]
        # "don't give B the chips", "cancel giving B the chips": the task is the reference
        return UpdateCommand("cancel", targets=rest)
    m = _INSTEAD_OF.search(text)
    if m:
        rest = (text[: m.start()] + text[m.end() :]).strip(" ,.;")
        return UpdateCommand("instead", text=rest, targets=m.group("x").strip())
    if _INSTEAD.search(text):
        return UpdateCommand("instead", text=_INSTEAD.sub("", text).strip(" ,.;"))
    m = _THEN.match(text)
    if m:
        return UpdateCommand("then", text=text[m.end() :])
    m = _NEXT_LAST.match(text)
    if m:
        return UpdateCommand("then", text=m["body"] + m["tail"])
    if _FIRST.search(text) and not _SEQ_WORDS.search(text):
        rest = _FIRST.sub("", text).strip(" ,.;")
        items = lex(rest, lexicon)
        has_verb = any(i.kind == "word" and i.lemma.startswith("verb:") for i in items)
        if not has_verb:
            return UpdateCommand("priority", targets=rest)
        return UpdateCommand("first", text=rest)
    m = _ADD.match(text)
    if m:
        return UpdateCommand("add", text=text[m.end() :])
    return UpdateCommand("add", text=text)


# -- the running tree ---------------------------------------------------------------------------


@dataclass(slots=True)
class _Tree:
    """The running spec as editable names: formula texts, children, parents."""

    root: str
    texts: dict[str, str]
    children: dict[str, list[str]]
    parent: dict[str, str]

    @classmethod
    def of(cls, spec: HSpec) -> _Tree:
        return cls(
            root=spec.root,
            texts={n: to_string(f) for n, f in spec.formulas},
            children={n: list(spec.children[n]) for n in spec.names},
            parent=dict(spec.parent),
        )


def _task_of(spec: HSpec, name: str) -> Task | None:
    return recognise_task(spec.formula(name)) if spec.is_leaf(name) else None


def _matching(spec: HSpec, targets: str, lexicon: Lexicon, completed: Collection[str]) -> list[str]:
    """Running leaves that mention every entity named in each part of ``targets``."""
    parts = [p for p in re.split(r",|\band\b|\bor\b", targets, flags=re.IGNORECASE) if p.strip()]
    if not parts:
        raise GroundingError("say which task: e.g. 'cancel the chips'")
    leaves = [(n, t) for n in spec.leaves if (t := _task_of(spec, n)) is not None]
    described = "; ".join(f"{n}: {t.atom}" for n, t in leaves) or "none"
    found: list[str] = []
    for part in parts:
        groups = _entity_ids(part, lexicon)
        if not groups:
            continue
        hits = [n for n, t in leaves if all(g & {t.obj, t.target} for g in groups)]
        if not hits:
            raise GroundingError(
                f"no running task mentions {quote(part.strip())}; running tasks: {described}"
            )
        done = [n for n in hits if n in completed]
        if done:
            raise GroundingError(
                f"{quote(part.strip())} is already done ({', '.join(done)}); it cannot be changed"
            )
        found += [n for n in hits if n not in found]
    if not found:
        raise GroundingError(
            f"{quote(targets.strip())} names no object, person or surface; running tasks: "
            f"{described}"
        )
    return found


def _entity_ids(text: str, lexicon: Lexicon) -> list[set[str]]:
    """Per name in ``text``, the ids it can mean (several for a plural such as 'the mugs')."""
    groups: list[set[str]] = []
    for it in lex(text, lexicon):
        if it.kind == "unknown":
            raise GroundingError(
                f"no object, person or surface called {quote(it.text)} in the scene; "
                f"{lexicon.listing('object')}; {lexicon.listing('human')}; "
                f"{lexicon.listing('surface')}"
            )
        if it.kind == "ent":
            singular = {r.id for r in it.refs if not r.plural}
            if len(singular) > 1:
                raise GroundingError(
                    f"{quote(it.text)} is ambiguous: it could be {' or '.join(sorted(singular))}"
                )
            groups.append(singular or {r.id for r in it.refs})
    return groups


def _remove(tree: _Tree, spec: HSpec, name: str) -> list[str]:
    """Remove ``name``; prune parents left without children; return the names removed."""
    removed = [name]
    for gone in _subtree(tree, name):
        if gone != name:
            removed.append(gone)
        tree.texts.pop(gone, None)
        tree.children.pop(gone, None)
    parent = tree.parent.pop(name, None)
    if parent is None:
        raise GroundingError("that would leave nothing to do; the running task would be empty")
    kids = tree.children[parent]
    kids.remove(name)
    if not kids:
        return removed + _remove(tree, spec, parent)
    op = _op_of(spec, parent)
    tree.texts[parent] = composite(op, kids)
    return removed


def _subtree(tree: _Tree, name: str) -> list[str]:
    out = [name]
    for c in tree.children.get(name, []):
        out += _subtree(tree, c)
    return out


def _op_of(spec: HSpec, name: str) -> Op:
    found = recognise_group(spec.formula(name))
    if found is None:
        raise GroundingError(
            f"cannot edit {name}: '{to_string(spec.formula(name))}' is not a conjunction, "
            "alternative or sequence of its children"
        )
    return found[0]


# -- merging ------------------------------------------------------------------------------------


def _renamed(new: HSpec, names: Names) -> tuple[str, dict[str, str]]:
    """The new spec's formulas under fresh names; a root that only wraps one child is dropped."""
    top = new.root
    kids = new.children[top]
    found = recognise_group(new.formula(top))
    if len(kids) == 1 and found is not None and found[1] == list(kids):
        top = kids[0]
    order = [n for n in new.names if n == top or _under(new, n, top)]
    mapping = {n: names.leaf() if new.is_leaf(n) else names.group() for n in order}
    atoms = {Atom(a): Atom(b) for a, b in mapping.items()}
    texts = {mapping[n]: to_string(rename_atoms(new.formula(n), atoms)) for n in order}
    return mapping[top], texts


def _under(spec: HSpec, name: str, top: str) -> bool:
    while name in spec.parent:
        name = spec.parent[name]
        if name == top:
            return True
    return False


def _fresh_root(old: str, taken: Collection[str]) -> str:
    m = _ROOT_SUFFIX.match(old)
    base, n = (m.group("base"), int(m.group("n"))) if m else (old, 0)
    while True:
        n += 1
        name = f"{base}_{n}"
        if name not in taken:
            return name


def merge(
    running: HSpec,
    new: HSpec,
    kind: str = "add",
) -> tuple[HSpec, UpdateInfo]:
    """Put ``new`` beside (``add``), after (``then``) or before (``first``) the running root.

    The running formulas keep their names and texts; the new ones get fresh names.
    """
    tree = _Tree.of(running)
    names = Names(set(tree.texts))
    sub_root, sub = _renamed(new, names)
    root = _fresh_root(running.root, set(tree.texts) | set(sub))
    old = running.root
    if kind == "add":
        text = composite("and", [old, sub_root])
    elif kind == "then":
        text = composite("seq", [old, sub_root])
    elif kind == "first":
        text = composite("seq", [sub_root, old])
    else:
        raise ValueError(f"unknown merge kind {quote(kind)}")
    formulas = {root: text, **tree.texts, **sub}
    spec = _build(root, formulas)
    return spec, _info(kind, running, spec, ())


def _build(root: str, formulas: dict[str, str]) -> HSpec:
    try:
        return spec_from_dict({"root": root, "formulas": formulas}, source="<update>")
    except SpecValidationError as exc:  # pragma: no cover - the edits keep the conventions
        raise GroundingError(f"the updated spec is not valid: {exc}") from None


def _info(kind: str, running: HSpec, spec: HSpec, completed: Collection[str]) -> UpdateInfo:
    old = {n: to_string(f) for n, f in running.formulas}
    new = {n: to_string(f) for n, f in spec.formulas}
    kept = tuple(n for n in spec.names if old.get(n) == new[n])
    return UpdateInfo(
        kind=kind,
        kept=kept,
        changed=tuple(n for n in spec.names if n in old and old[n] != new[n]),
        added=tuple(n for n in spec.names if n not in old),
        removed=tuple(n for n in running.names if n not in new),
        completed_kept=tuple(n for n in kept if n in completed),
    )


def apply_update(
    instruction: str,
    scene: Scene,
    running: HSpec,
    grounder: Grounder,
    completed: Collection[str] = (),
) -> Grounding:
    """Ground an update instruction and merge it into ``running``.

    Args:
        instruction: the update (see the module docstring for the phrasings).
        scene: the scene.
        running: the spec being executed.
        grounder: grounds the new task in the instruction on its own.
        completed: names of the running formulas whose monitors have fired
            (``HierarchyMonitor.done``); completed tasks cannot be cancelled, replaced or moved.

    Raises:
        GroundingError: the update cannot be applied; the message says why. It carries the
            tokens the grounder spent on the new task, which are paid for all the same.
    """
    done = frozenset(completed)
    metered = _Metered(grounder)
    try:
        result = _apply(instruction, scene, running, metered, done)
        _check_not_dropped(result, done)
    except GroundingError as exc:
        if exc.tokens_spent >= metered.spent.total:
            raise
        raise GroundingError(
            str(exc),
            prompt_tokens=metered.spent.prompt,
            completion_tokens=metered.spent.completion,
        ) from None
    return result


class _Metered:
    """A grounder that adds up what the grounder it wraps spends, failures included."""

    def __init__(self, inner: Grounder) -> None:
        self.inner = inner
        self.spent = TokenUsage()

    def ground(self, instruction: str, scene: Scene, running: HSpec | None = None) -> Grounding:
        try:
            g = self.inner.ground(instruction, scene, running)
        except GroundingError as exc:
            self.spent = self.spent + TokenUsage(exc.prompt_tokens, exc.completion_tokens)
            raise
        self.spent = self.spent + g.tokens
        return g


def _check_not_dropped(result: Grounding, done: frozenset[str]) -> None:
    """Refuse an update whose new tasks sit under a formula that is already complete.

    The monitor state carries over by name and a completed formula stays completed, so a task
    added below one would count as done without ever being carried out: accepted and dropped.
    """
    info = result.update
    if info is None or not done:
        return
    spec = result.spec
    for name in info.added:
        node = name
        while node in spec.parent:
            node = spec.parent[node]
            if node in done:
                raise GroundingError(
                    f"the new task would belong to {node}, which is already complete, so it "
                    "would never be carried out; give it as a new task ('also …')"
                )


def _apply(
    instruction: str, scene: Scene, running: HSpec, grounder: Grounder, done: frozenset[str]
) -> Grounding:
    lexicon = Lexicon.of(scene)
    cmd = classify(instruction, lexicon)
    if cmd.kind != "cancel" and _NEGATED.search(instruction):
        # "Give Bob the chips. Don't give him the apple." grounds as the chips alone (the
        # negated command leaves the apple alone), but in an update it could be cancelling a
        # running task: which is meant is not said
        raise GroundingError(
            f"{quote(instruction.strip())} says what not to do beside a new task: to drop a "
            "running task say 'cancel …', and give the new task on its own"
        )
    if cmd.kind in ("add", "then", "first"):
        if not cmd.text.strip():
            raise GroundingError(f"no task in {quote(instruction.strip())}")
        g = grounder.ground(cmd.text, scene)
        if cmd.kind == "first":
            same = _same_tasks(running, g.spec, done)
            if same:  # "give B the chips first" for a running task: move it to the front
                return _priority(running, same, done)
        spec, _ = merge(running, g.spec, cmd.kind)
        _check_spec_deliveries(spec, scene)
        return Grounding(spec, g.entities, g.tokens, _info(cmd.kind, running, spec, done), g.rounds)
    if cmd.kind == "cancel":
        return _cancel(cmd, scene, running, lexicon, done)
    if cmd.kind == "priority":
        return _priority(running, _matching(running, cmd.targets, lexicon, done), done)
    return _instead(cmd, scene, running, grounder, lexicon, done)


def ground_update(instruction: str, scene: Scene, running: HSpec, grounder: Grounder) -> Grounding:
    """:func:`apply_update` with nothing completed yet (what ``Grounder.ground`` calls)."""
    return apply_update(instruction, scene, running, grounder)


def _same_tasks(running: HSpec, new: HSpec, done: frozenset[str]) -> list[str]:
    """Running open leaves doing exactly the new spec's tasks, if all of them are running."""
    old = {t: n for n in running.leaves if n not in done and (t := _task_of(running, n))}
    new_tasks = [_task_of(new, n) for n in new.leaves]
    if new_tasks and all(t is not None and t in old for t in new_tasks):
        return [old[t] for t in new_tasks if t is not None]
    return []


def _check_spec_deliveries(spec: HSpec, scene: Scene) -> None:
    node = decode(spec)
    if node is not None:
        check_deliveries(node, {h.id: h.name for h in scene.humans})


def _cancel(
    cmd: UpdateCommand, scene: Scene, running: HSpec, lexicon: Lexicon, done: frozenset[str]
) -> Grounding:
    hits = _matching(running, cmd.targets, lexicon, done)
    tree = _Tree.of(running)
    for name in hits:
        if name in tree.texts:
            _remove(tree, running, name)
    spec = _build(tree.root, tree.texts)
    return Grounding(spec, _ids_of(running, hits), update=_info("cancel", running, spec, done))


def _priority(running: HSpec, hits: Sequence[str], done: frozenset[str]) -> Grounding:
    tree = _Tree.of(running)
    for name in hits:
        _check_movable(running, name, done)
    try:
        for name in hits:
            _remove(tree, running, name)
            tree.texts[name] = _running_text(running, name)
    except GroundingError:
        raise GroundingError(
            f"{', '.join(hits)} {'is' if len(hits) == 1 else 'are'} all that is left to do; "
            "there is nothing to put after it"
        ) from None
    names = Names(set(tree.texts))
    first = hits[0] if len(hits) == 1 else names.group()
    if len(hits) > 1:
        tree.texts[first] = composite("and", list(hits))
    root = _fresh_root(running.root, set(tree.texts))
    formulas = {root: composite("seq", [first, running.root]), **tree.texts}
    spec = _build(root, formulas)
    return Grounding(spec, _ids_of(running, hits), update=_info("priority", running, spec, done))


def _running_text(spec: HSpec, name: str) -> str:
    return to_string(spec.formula(name))


def _check_movable(running: HSpec, name: str, done: frozenset[str]) -> None:
    """A task can go first only if nothing running must come before it or excludes it."""
    child = name
    while child in running.parent:
        parent = running.parent[child]
        found = recognise_group(running.formula(parent))
        if found is None:
            _op_of(running, parent)  # raises with the formula
            return
        op, kids = found
        if op == "or":
            raise GroundingError(
                f"{name} is one of several alternatives ({parent}); making it first would make "
                "it required: cancel the others instead"
            )
        if op == "seq":
            before = [k for k in kids[: kids.index(child)] if k not in done]
            if before:
                raise GroundingError(
                    f"{name} must come after {', '.join(before)} in the running task; cancel and "
                    "give it again to change the order"
                )
        child = parent


def _instead(
    cmd: UpdateCommand,
    scene: Scene,
    running: HSpec,
    grounder: Grounder,
    lexicon: Lexicon,
    done: frozenset[str],
) -> Grounding:
    if not cmd.text.strip():
        raise GroundingError("say what to do instead, e.g. 'give B the cup instead of the chips'")
    g = grounder.ground(cmd.text, scene)
    if cmd.targets:
        hits = _matching(running, cmd.targets, lexicon, done)
    else:
        hits = _replaced(running, g.spec, done)
    tree = _Tree.of(running)
    names = Names(set(tree.texts))
    sub_root, sub = _renamed(g.spec, names)
    first = hits[0]
    parent = running.parent.get(first)
    if parent is None:  # pragma: no cover - a leaf is never the root in a grounded spec
        raise GroundingError("cannot replace the whole task; give a new instruction instead")
    op = _op_of(running, parent)
    tree.children[parent] = [sub_root if k == first else k for k in tree.children[parent]]
    tree.texts[parent] = composite(op, tree.children[parent])
    tree.texts.pop(first)
    tree.children.pop(first, None)
    tree.parent[sub_root] = parent
    tree.parent.pop(first, None)
    tree.texts.update(sub)
    for name in hits[1:]:
        _remove(tree, running, name)
    spec = _build(tree.root, tree.texts)
    return Grounding(spec, g.entities, g.tokens, _info("instead", running, spec, done), g.rounds)


def _replaced(running: HSpec, new: HSpec, done: frozenset[str]) -> list[str]:
    """The running task an 'X instead' replaces: same object, else same recipient or place."""
    new_tasks = [t for n in new.leaves if (t := _task_of(new, n)) is not None]
    old = [(n, t) for n in running.leaves if (t := _task_of(running, n)) is not None]
    open_ = [(n, t) for n, t in old if n not in done]
    for key in ("obj", "target"):
        hits = [n for n, t in open_ if any(getattr(t, key) == getattr(u, key) for u in new_tasks)]
        if len(hits) == 1:
            return hits
        if len(hits) > 1:
            raise GroundingError(
                f"'instead' could replace {', '.join(hits)}: say 'instead of …' to choose"
            )
        finished = [
            f"{n} ({t.atom})"
            for n, t in old
            if n in done and any(getattr(t, key) == getattr(u, key) for u in new_tasks)
        ]
        if finished:
            raise GroundingError(
                f"{', '.join(finished)} is already done, so there is nothing left to replace; "
                "say 'also …' to add the new task"
            )
    raise GroundingError(
        "no running task shares an object, person or surface with the new one: say "
        "'instead of …' to choose what it replaces"
    )


def _ids_of(spec: HSpec, names: Sequence[str]) -> tuple[str, ...]:
    out: dict[str, None] = {}
    for n in names:
        t = _task_of(spec, n)
        if t is not None:
            out.setdefault(t.obj)
            out.setdefault(t.target)
    return tuple(out)
