"""Task trees (deliveries, placements, and/or/sequence groups) and their H-LTLf encoding."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Literal, TypeAlias

from hltl.errors import GroundingError
from hltl.spec.hierarchy import HSpec
from hltl.spec.syntax import And, Atom, Eventually, Formula, Or

Op: TypeAlias = Literal["and", "or", "seq"]
TaskKind: TypeAlias = Literal["deliver", "place"]

ROOT = "p0"


@dataclass(frozen=True, slots=True)
class Task:
    """One leaf: deliver ``obj`` to human ``target`` or place ``obj`` on surface ``target``."""

    kind: TaskKind
    obj: str
    target: str

    @property
    def atom(self) -> str:
        pred = "delivered" if self.kind == "deliver" else "placed"
        return f"{pred}({self.obj}, {self.target})"

    @property
    def formula(self) -> str:
        return f"F {self.atom}"


@dataclass(frozen=True, slots=True)
class Group:
    """Children joined by ``and`` (all, any order), ``or`` (at least one), ``seq`` (in order)."""

    op: Op
    children: tuple[Node, ...]


Node: TypeAlias = Task | Group


def normalise(node: Node) -> Node:
    """Flatten nested groups of the same operator and drop one-child groups.

    Flattening keeps the language: ``(a & b) & c`` and ``a & b & c`` accept the same traces under
    one-shot events, and so do the sequence chains ``seq(seq(a, b), c)`` and ``seq(a, b, c)``.
    """
    if isinstance(node, Task):
        return node
    kids: list[Node] = []
    for child in node.children:
        c = normalise(child)
        if isinstance(c, Group) and c.op == node.op:
            kids.extend(c.children)
        else:
            kids.append(c)
    if len(kids) == 1:
        return kids[0]
    return Group(node.op, tuple(kids))


def tasks(node: Node) -> Iterator[Task]:
    """The leaves in pre-order (for a sequence: in execution order)."""
    if isinstance(node, Task):
        yield node
    else:
        for child in node.children:
            yield from tasks(child)


def has_choice(node: Node) -> bool:
    """Whether ``node`` offers a choice (an ``or`` anywhere in it)."""
    return isinstance(node, Group) and (
        node.op == "or" or any(has_choice(c) for c in node.children)
    )


def entities(node: Node) -> tuple[str, ...]:
    """Scene ids the tree mentions, in order of first mention."""
    seen: dict[str, None] = {}
    for t in tasks(node):
        seen.setdefault(t.obj)
        seen.setdefault(t.target)
    return tuple(seen)


def check_deliveries(node: Node, describe: Mapping[str, str] | None = None) -> None:
    """Reject a tree that must hand one object over twice (a delivered object is gone for good)
    or place it on two surfaces at once.

    Two deliveries of the same object conflict unless an ``or`` separates them (their lowest
    common group is an ``or``); two placements on different surfaces conflict when their lowest
    common group is an ``and`` (a sequence says one after the other).
    """
    name = dict(describe or {})

    def walk(n: Node) -> list[Task]:
        if isinstance(n, Task):
            return [n] if n.kind == "deliver" else []
        per_child = [walk(c) for c in n.children]
        if n.op != "or":
            for i, a_list in enumerate(per_child):
                for b_list in per_child[i + 1 :]:
                    for a in a_list:
                        for b in b_list:
                            if a.obj == b.obj:
                                who = (
                                    f"{name.get(a.target, a.target)} and "
                                    f"{name.get(b.target, b.target)}"
                                    if a.target != b.target
                                    else f"{name.get(a.target, a.target)} twice"
                                )
                                raise GroundingError(
                                    f"the {a.obj} would be handed to {who}; an object can be "
                                    "handed over only once"
                                )
        return [t for lst in per_child for t in lst]

    walk(node)

    def placed(n: Node) -> list[Task]:
        """One object placed on two surfaces with no order and no 'or' between: it cannot be on
        both, and which one stands is not said ('The magazine goes on the cart. It goes on the
        bedside table too.')."""
        if isinstance(n, Task):
            return [n] if n.kind == "place" else []
        per_child = [placed(c) for c in n.children]
        if n.op == "and":
            for i, a_list in enumerate(per_child):
                for b_list in per_child[i + 1 :]:
                    for a in a_list:
                        for b in b_list:
                            if a.obj == b.obj and a.target != b.target:
                                raise GroundingError(
                                    f"the {a.obj} would be placed on {a.target} and on "
                                    f"{b.target}; an object is in one place: say which, or "
                                    "the order ('then')"
                                )
        return [t for lst in per_child for t in lst]

    placed(node)

    # in a sequence, an object handed over in one step cannot be placed in a later one
    pair = given_then_placed(node, "seq")
    if pair is not None:
        given, t = pair
        raise GroundingError(
            f"the {t.obj} would be handed to {name.get(given.target, given.target)} and then "
            f"placed on {t.target}; a handed-over object is gone: say one"
        )


def given_then_placed(node: Node, op: Op) -> tuple[Task, Task] | None:
    """The first object handed over in one child of an ``op`` group and placed in a later child
    (the hand-over task and the placement), searching groups outside in; None without one."""
    if isinstance(node, Task):
        return None
    if node.op == op:
        for i, early in enumerate(node.children):
            given = {t.obj: t for t in tasks(early) if t.kind == "deliver"}
            for late in node.children[i + 1 :]:
                for t in tasks(late):
                    if t.kind == "place" and t.obj in given:
                        return given[t.obj], t
    for c in node.children:
        pair = given_then_placed(c, op)
        if pair is not None:
            return pair
    return None


class Names:
    """Fresh formula names: leaves p100, p200, …; groups p1, p2, …; never one in ``taken``."""

    def __init__(self, taken: frozenset[str] | set[str] = frozenset()) -> None:
        self._taken = set(taken)
        self._leaf = 0
        self._group = 0

    def leaf(self) -> str:
        while True:
            self._leaf += 100
            name = f"p{self._leaf}"
            if name not in self._taken:
                self._taken.add(name)
                return name

    def group(self) -> str:
        while True:
            self._group += 1
            if self._group % 100 == 0:  # p100, p200 … belong to leaves
                continue
            name = f"p{self._group}"
            if name not in self._taken:
                self._taken.add(name)
                return name

    def take(self, name: str) -> str:
        self._taken.add(name)
        return name


def composite(op: Op, children: list[str]) -> str:
    """The formula text of a group over its children's names."""
    if not children:
        raise GroundingError("a group needs at least one child")
    if op == "and" or len(children) == 1:
        return " & ".join(f"F {c}" for c in children)
    if op == "or":
        return " | ".join(f"F {c}" for c in children)
    text = f"F {children[-1]}"
    for c in reversed(children[:-1]):
        text = f"F ({c} & {text})"
    return text


def encode(node: Node, names: Names | None = None, root: str = ROOT) -> dict[str, str]:
    """The formulas of ``node`` as ``{name: text}`` with ``root`` first; a lone task gets a root."""
    names = names if names is not None else Names()
    names.take(root)
    node = normalise(node)
    formulas: dict[str, str] = {}

    def emit(n: Node, name: str) -> None:
        if isinstance(n, Task):
            formulas[name] = n.formula
            return
        formulas[name] = ""  # parent before children; names are handed out depth-first
        child_names = []
        for c in n.children:
            cname = names.leaf() if isinstance(c, Task) else names.group()
            child_names.append(cname)
            emit(c, cname)
        formulas[name] = composite(n.op, child_names)

    if isinstance(node, Task):
        leaf = names.leaf()
        formulas[root] = composite("and", [leaf])
        formulas[leaf] = node.formula
    else:
        emit(node, root)
    return formulas


# -- reading formulas back ---------------------------------------------------------------------


def recognise_group(f: Formula) -> tuple[Op, list[str]] | None:
    """The operator and children of a composite written in the grounding convention, else None.

    ``F a`` alone reads as a one-child ``and``.
    """

    def conj(g: Formula, cls: type[And] | type[Or]) -> list[Formula]:
        if isinstance(g, cls):
            return conj(g.left, cls) + conj(g.right, cls)
        return [g]

    def child(g: Formula) -> str | None:
        if isinstance(g, Eventually) and isinstance(g.operand, Atom) and not g.operand.args:
            return g.operand.name
        return None

    for op, cls in (("and", And), ("or", Or)):
        parts = conj(f, cls)
        if len(parts) > 1:
            names = [child(p) for p in parts]
            if all(n is not None for n in names):
                return op, [n for n in names if n is not None]  # type: ignore[return-value]
    single = child(f)
    if single is not None:
        return "and", [single]
    # sequence: F (a & F (b & … F z))
    chain: list[str] = []
    g = f
    while isinstance(g, Eventually):
        inner = g.operand
        if isinstance(inner, Atom) and not inner.args:
            chain.append(inner.name)
            return ("seq", chain) if len(chain) > 1 else None
        if (
            isinstance(inner, And)
            and isinstance(inner.left, Atom)
            and not inner.left.args
            and isinstance(inner.right, Eventually)
        ):
            chain.append(inner.left.name)
            g = inner.right
            continue
        return None
    return None


def recognise_task(f: Formula) -> Task | None:
    """The task of a leaf ``F delivered(o, u)`` / ``F placed(o, s)``, else None."""
    if isinstance(f, Eventually) and isinstance(f.operand, Atom) and len(f.operand.args) == 2:
        a = f.operand
        if a.name == "delivered":
            return Task("deliver", a.args[0], a.args[1])
        if a.name == "placed":
            return Task("place", a.args[0], a.args[1])
    return None


def decode(spec: HSpec) -> Node | None:
    """The task tree of a spec written in the grounding conventions, else None."""

    def walk(name: str) -> Node | None:
        f = spec.formula(name)
        if spec.is_leaf(name):
            return recognise_task(f)
        found = recognise_group(f)
        if found is None or set(found[1]) != set(spec.children[name]):
            return None
        kids = [walk(c) for c in found[1]]
        if any(k is None for k in kids):
            return None
        return Group(found[0], tuple(k for k in kids if k is not None))

    return walk(spec.root)
