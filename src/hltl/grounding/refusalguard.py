"""The refusals and checks asked of every text, indexed by their words (session 51, 12b)."""

# offline._REFUSALS (``refuse(text, lexicon)``, asked before the read) and offline._CHECKS
# (``check(text, node, lexicon)``, asked of the whole reading) raise GroundingError to refuse and
# return None otherwise. Most begin with a test of the text's words (``if "which" not in
# text.lower(): return``) or search the text for a pattern and return where it finds nothing. Their
# guards are read from that source with the step guards' reader (stepguard.py), a refusal's
# ``return`` (None) read as a step's ``return text`` (it does nothing) and the function's end as a
# ``return`` too: a guard's atoms are words one of which the text must hold for the function to
# refuse anything. offline asks the guard first (``asked``) and does not call a refusal that cannot
# refuse the text. A refusal whose first statements are of no kind the reader knows has no guard
# and is always called; so is one changed since the list was made (its fingerprint, and what the
# module names it was read with hold, are checked as the step guards' are).

from __future__ import annotations

import ast
import inspect
import sys
import textwrap
import types
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

from hltl.grounding import stepguard
from hltl.grounding.stepguard import Atom, Entry, Guard


class _Returns(ast.NodeTransformer):
    """A refusal's ``return`` / ``return None`` as ``return <text>`` (nested functions kept)."""

    def __init__(self, text: str) -> None:
        self.text = text

    def visit_Return(self, node: ast.Return) -> ast.Return:
        if node.value is None or (
            isinstance(node.value, ast.Constant) and node.value.value is None
        ):
            return ast.copy_location(ast.Return(ast.Name(self.text, ast.Load())), node)
        return node

    def visit_FunctionDef(self, node: ast.FunctionDef) -> ast.FunctionDef:
        return node  # its returns are its own

    def visit_AsyncFunctionDef(self, node: ast.AsyncFunctionDef) -> ast.AsyncFunctionDef:
        return node

    def visit_Lambda(self, node: ast.Lambda) -> ast.Lambda:
        return node


class _RefusalReader(stepguard._Reader):
    """Reads one refusal's (or check's) guard: where it returns without raising, it is read as
    a step returning its text as it is."""

    def read(self) -> frozenset[Atom]:
        source = textwrap.dedent(inspect.getsource(self.fn))
        fdef = ast.parse(source).body[0]
        if not isinstance(fdef, ast.FunctionDef) or fdef.decorator_list or not fdef.args.args:
            raise stepguard._Unread("not a plain function")
        self.text = fdef.args.args[0].arg
        self.same = {self.text}
        body = list(fdef.body)
        if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
            body = body[1:]  # the docstring
        returns = _Returns(self.text)
        body = [returns.visit(stmt) for stmt in body]
        # the function's end returns None: nothing refused
        body.append(ast.Return(ast.Name(self.text, ast.Load())))
        atoms: set[Atom] = set()
        if not self._block(body, atoms):
            raise stepguard._Unread("no guard")
        if not atoms:
            raise stepguard._Unread("no atoms")  # never a guard that turns every text away
        return frozenset(atoms)


def read_guard(fn: Callable[..., Any]) -> Entry | None:
    """``fn``'s entry (its fingerprint, guard and the module names it was read with), or None
    where its first statements are not of the kinds a guard is read from."""
    if (
        not isinstance(fn, types.FunctionType)
        or fn.__closure__
        or "<" in fn.__qualname__
        or fn.__code__.co_argcount < 1
    ):
        return None
    reader = _RefusalReader(fn)
    try:
        atoms = reader.read()
    except (stepguard._Unread, OSError, TypeError, SyntaxError):
        return None
    plain: set[str] = set()
    folded: set[str] = set()
    patterned = False
    for kind, said, flags in atoms:
        if kind == "in":
            (folded if flags else plain).add(said)
            continue
        found = stepguard._words(said, flags)
        if found is None:
            return None  # a pattern that may match without any word: always asked
        words, fold = found
        if kind == "re-low":
            folded.update(w.lower() for w in words)
        else:
            (folded if fold else plain).update(words)
        patterned = True
    if "" in plain or "" in folded:
        return None
    deps = tuple(sorted(reader.deps.items()))
    return stepguard.fingerprint(fn), (tuple(sorted(plain)), tuple(sorted(folded)), patterned), deps


# the list's entry saying how its guards were read (the gate's derivation of a pattern's words
# and this reader's code): where it differs, no guard is used
_DERIVATION = "derivation"


def derivation() -> str:
    """A digest of how the list's guards were read."""
    return (
        stepguard.derivation()
        + "".join(
            stepguard.fingerprint(f)
            for f in (_Returns.visit_Return, _RefusalReader.read, read_guard)
        )
    )[:48]


def guards(
    fns: Sequence[Callable[..., Any]], known: Mapping[str, Entry | str]
) -> tuple[Guard | None, ...]:
    """Each function's guard (None: it is always asked)."""
    if known.get(_DERIVATION) != derivation():
        return (None,) * len(fns)
    out = []
    for fn in fns:
        entry = known.get(stepguard.key(fn))
        out.append(stepguard.guard(fn, entry if isinstance(entry, tuple) else None))
    return tuple(out)


# each tuple's guards, kept with the tuple (a test may ask another one)
_GUARDED: dict[int, tuple[tuple[Callable[..., Any], ...], tuple[Guard | None, ...]]] = {}


def guards_of(fns: tuple[Callable[..., Any], ...]) -> tuple[Guard | None, ...]:
    """``fns``' guards, read once per tuple."""
    kept = _GUARDED.get(id(fns))
    if kept is None or kept[0] is not fns:
        # why: the generated list imports this module's Entry; read on first use
        from hltl.grounding._refusal_guards import GUARDS

        if len(_GUARDED) > 64:
            _GUARDED.clear()
        kept = _GUARDED[id(fns)] = (fns, guards(fns, GUARDS))
    return kept[1]


def asked(fns: tuple[Callable[..., Any], ...], text: str) -> list[Callable[..., Any]]:
    """The functions of ``fns`` that may refuse ``text``, in order: those without a guard and
    those a word of whose guard ``text`` holds (the others return None for it)."""
    rules = guards_of(fns)
    low, plain = text.lower(), text.isascii()
    out = []
    for fn, rule in zip(fns, rules, strict=True):
        if rule is None or (rule[2] and not plain):
            out.append(fn)
            continue
        for word in rule[1]:  # a loop: any() over a generator costs more
            if word in low:
                out.append(fn)
                break
        else:
            for word in rule[0]:
                if word in text:
                    out.append(fn)
                    break
    return out


# -- remaking the list ---------------------------------------------------------------------------


def read_all(fns: Iterable[Callable[..., Any]]) -> dict[str, Entry]:
    """The entries of every function that has a guard."""
    return stepguard.read_all(fns, read_guard)


def all_refusals() -> tuple[Callable[..., Any], ...]:
    """Every refusal and check offline asks through the index, once each."""
    # why: offline imports this module (its loops ask the index)
    from hltl.grounding import offline

    return tuple(dict.fromkeys((*offline._REFUSALS, *offline._CHECKS)))


def main(argv: Sequence[str]) -> int:
    """``--write``: remake _refusal_guards.py from the refusals' source."""
    if list(argv) != ["--write"]:
        print("usage: python -m hltl.grounding.refusalguard --write", file=sys.stderr)
        return 2
    fns = all_refusals()
    out = Path(__file__).with_name("_refusal_guards.py")
    what = "The refusals' and checks' guards"
    n = stepguard.write_list(
        out, fns, read_guard, what, "hltl.grounding.refusalguard", derivation()
    )
    print(f"{n} of {len(fns)} refusals and checks guarded, written to {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
