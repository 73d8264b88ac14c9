"""Every update form against tasks pending, running and finished: never accepted and dropped.

Issue 18, item 2: "give Person A the chips instead" after the bottle was delivered was accepted,
the new root inherited "done" and the chips were never delivered. The invariant checked here over
a grid of running specs, progress and update phrasings: an update is either refused with a
reason, or every task it adds is still to do afterwards (not done, the root not accepted) and no
finished task is removed or replaced.
"""

from __future__ import annotations

import itertools

import pytest

from hltl.errors import GroundingError
from hltl.grounding.offline import OfflineGrounder
from hltl.grounding.update import apply_update
from hltl.spec.monitor import HierarchyMonitor, carry_over
from hltl.spec.syntax import Atom
from hltl.world.scene import Scene

RUNNING = (
    "give A the cup",
    "give A the cup and B the chips",
    "give A the cup, then B the chips",
    "give A the cup or B the chips",
)
# how far the running task got: nothing yet (pending; an action may be running), the cup
# delivered, everything delivered
PROGRESS = ((), ("cup",), ("cup", "chips"))
UPDATES = (
    "give A the apple instead",
    "give C the cup instead",
    "give A the apple instead of the cup",
    "give B the apple instead of the chips",
    "cancel the cup",
    "cancel the chips",
    "also give C the apple",
    "after that give C the apple",
    "first give C the apple",
    "do the chips first",
)
DELIVERY = {"cup": Atom("delivered", ("cup", "A")), "chips": Atom("delivered", ("chips", "B"))}


@pytest.mark.parametrize(
    ("running_text", "progress", "update"),
    list(itertools.product(RUNNING, PROGRESS, UPDATES)),
)
def test_an_update_is_refused_or_carried_out(
    cell: Scene, running_text: str, progress: tuple[str, ...], update: str
) -> None:
    grounder = OfflineGrounder()
    running = grounder.ground(running_text, cell).spec
    m = HierarchyMonitor(running)
    q = m.initial
    for obj in progress:
        if DELIVERY[obj] in {a for n in running.leaves for a in _atoms(running, n)}:
            q = m.step(q, [DELIVERY[obj]])
    done = m.done(q)
    try:
        g = apply_update(update, cell, running, grounder, completed=done)
    except GroundingError as exc:
        assert str(exc)  # refused, with a reason
        return
    assert g.update is not None
    new = carry_over(running, q, g.spec)
    nm = HierarchyMonitor(g.spec)
    new_done = nm.done(new)
    added_leaves = [n for n in g.update.added if n in g.spec.leaves]
    for leaf in added_leaves:
        assert leaf not in new_done, (update, leaf)
    if added_leaves:
        assert not nm.accepted(new), f"{update!r} accepted but its task counts as done"
    # a finished task is never removed or replaced
    assert not set(g.update.removed) & done, (update, g.update.removed, done)


def _atoms(spec: object, name: str) -> set[Atom]:
    from hltl.spec.printer import atoms_in_order

    return set(atoms_in_order(spec.formula(name)))  # type: ignore[attr-defined]


def test_the_issue_repro_is_refused_with_a_reason(cell: Scene) -> None:
    grounder = OfflineGrounder()
    running = grounder.ground("give A the cup", cell).spec
    m = HierarchyMonitor(running)
    q = m.step(m.initial, [DELIVERY["cup"]])
    with pytest.raises(GroundingError, match=r"p100 \(delivered\(cup, A\)\) is already done"):
        apply_update("give A the chips instead", cell, running, grounder, completed=m.done(q))


def test_refusal_keeps_the_tokens_spent(cell: Scene) -> None:
    """A refused update still reports what grounding its new task cost."""
    from hltl.grounding.base import Grounding, TokenUsage

    class Paid:
        def ground(self, text: str, scene: Scene, running: object = None) -> Grounding:
            g = OfflineGrounder().ground(text, scene)
            return Grounding(g.spec, g.entities, TokenUsage(500, 40), rounds=1)

    running = OfflineGrounder().ground("give A the cup", cell).spec
    m = HierarchyMonitor(running)
    q = m.step(m.initial, [DELIVERY["cup"]])
    with pytest.raises(GroundingError) as info:
        apply_update("give A the chips instead", cell, running, Paid(), completed=m.done(q))
    assert (info.value.prompt_tokens, info.value.completion_tokens) == (500, 40)
