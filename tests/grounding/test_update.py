"""Updates during execution: merging, cancelling, replacing, reordering; monitor carry-over."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.offline import OfflineGrounder
from hltl.grounding.update import apply_update, classify
from hltl.spec.equivalence import equivalent
from hltl.spec.hierarchy import HSpec, spec_from_dict, spec_to_dict
from hltl.spec.monitor import DONE, HierarchyMonitor, carry_over
from hltl.spec.syntax import Atom
from hltl.world.scene import Scene

CUP_A, CHIPS_B, APPLE_C = (
    Atom("delivered", ("cup", "A")),
    Atom("delivered", ("chips", "B")),
    Atom("delivered", ("apple", "C")),
)


def spec(formulas: dict[str, str], root: str = "p0") -> HSpec:
    return spec_from_dict({"root": root, "formulas": formulas})


@pytest.fixture
def running(cell: Scene) -> HSpec:
    return OfflineGrounder().ground("give A the cup, B the chips and C the apple", cell).spec


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("Also give Person B the bottle", "add"),
        ("give B the bottle", "add"),
        ("in addition, put the cup on the shelf", "add"),
        ("then give B the bottle", "then"),
        ("When you are done, give B the bottle", "then"),
        ("after that put the apple on the table", "then"),
        ("first give B the bottle", "first"),
        ("do the chips first", "priority"),
        ("prioritise the apple", "priority"),
        ("cancel the chips", "cancel"),
        ("never mind the apple", "cancel"),
        ("don't give B the chips", "cancel"),
        ("forget about the delivery to Carol", "cancel"),
        ("give B the bottle instead of the chips", "instead"),
        ("instead of the chips, give B the bottle", "instead"),
        ("give the chips to C instead", "instead"),
    ],
)
def test_classify(cell: Scene, text: str, kind: str) -> None:
    assert classify(text, Lexicon(cell)).kind == kind


def test_add_keeps_every_running_formula(cell: Scene, running: HSpec) -> None:
    g = OfflineGrounder().ground("Also give Person B the bottle", cell, running)
    d = spec_to_dict(g.spec)
    old = spec_to_dict(running)["formulas"]
    assert all(d["formulas"][n] == f for n, f in old.items())  # names and texts unchanged
    assert d["root"] == "p0_1" and d["formulas"]["p0_1"] == "F p0 & F p400"
    assert d["formulas"]["p400"] == "F delivered(bottle, B)"
    assert g.update is not None and g.update.kept == running.names
    assert g.entities == ("bottle", "B")
    # and a second update gets fresh names again
    g2 = OfflineGrounder().ground("then put the red mug on the shelf", cell, g.spec)
    d2 = spec_to_dict(g2.spec)
    assert d2["root"] == "p0_2" and d2["formulas"]["p0_2"] == "F (p0_1 & F p500)"


def test_then_and_first_order_the_new_task(cell: Scene, running: HSpec) -> None:
    then = OfflineGrounder().ground("afterwards, give B the bottle", cell, running).spec
    first = OfflineGrounder().ground("first give B the bottle", cell, running).spec
    bottle = "F delivered(bottle, B)"
    old = spec_to_dict(running)["formulas"]
    assert equivalent(then, spec({"q": "F (p0 & F p9)", "p9": bottle, **old}, root="q"))
    assert equivalent(first, spec({"q": "F (p9 & F p0)", "p9": bottle, **old}, root="q"))


def test_cancel_prunes_and_keeps_other_names(cell: Scene, running: HSpec) -> None:
    g = OfflineGrounder().ground("cancel the chips", cell, running)
    assert spec_to_dict(g.spec)["formulas"] == {
        "p0": "F p100 & F p300",
        "p100": "F delivered(cup, A)",
        "p300": "F delivered(apple, C)",
    }
    assert g.update is not None
    assert (g.update.changed, g.update.removed) == (("p0",), ("p200",))


def test_cancel_a_whole_group_prunes_it(cell: Scene) -> None:
    run = (
        OfflineGrounder().ground("give A the cup and the bottle, then give B the chips", cell).spec
    )
    g = OfflineGrounder().ground("cancel the deliveries to Alice", cell, run)
    assert equivalent(g.spec, spec({"p0": "F p300", "p300": "F delivered(chips, B)"}))
    assert g.update is not None and set(g.update.removed) == {"p1", "p100", "p200"}


def test_cancel_everything_is_refused(cell: Scene) -> None:
    run = OfflineGrounder().ground("give A the cup", cell).spec
    with pytest.raises(GroundingError, match="nothing to do"):
        OfflineGrounder().ground("cancel the cup", cell, run)


def test_cancel_needs_a_running_match(cell: Scene, running: HSpec) -> None:
    with pytest.raises(GroundingError, match="no running task mentions 'the bottle'"):
        OfflineGrounder().ground("cancel the bottle", cell, running)
    with pytest.raises(GroundingError, match="no object, person or surface called 'spoon'"):
        OfflineGrounder().ground("cancel the spoon", cell, running)


def test_completed_tasks_cannot_be_changed(cell: Scene, running: HSpec) -> None:
    with pytest.raises(GroundingError, match="already done"):
        apply_update("cancel the cup", cell, running, OfflineGrounder(), completed={"p100"})
    with pytest.raises(GroundingError, match="already done"):
        apply_update("do the cup first", cell, running, OfflineGrounder(), completed={"p100"})


def test_instead_replaces_in_place(cell: Scene, running: HSpec) -> None:
    for text in ("give B the bottle instead of the chips", "give B the bottle instead"):
        g = OfflineGrounder().ground(text, cell, running)
        f = spec_to_dict(g.spec)["formulas"]
        assert f["p0"] == "F p100 & F p400 & F p300" and f["p400"] == "F delivered(bottle, B)"
        assert "p200" not in f
    g = OfflineGrounder().ground("give the chips to C instead", cell, running)
    assert spec_to_dict(g.spec)["formulas"]["p400"] == "F delivered(chips, C)"


def test_instead_without_a_unique_match_asks(cell: Scene) -> None:
    run = OfflineGrounder().ground("give B the chips and the apple", cell).spec
    with pytest.raises(GroundingError, match="say 'instead of"):
        OfflineGrounder().ground("give B the cup instead", cell, run)


def test_priority_moves_a_task_to_the_front(cell: Scene, running: HSpec) -> None:
    for text in ("do the apple first", "give C the apple first", "the apple first"):
        g = OfflineGrounder().ground(text, cell, running)
        d = spec_to_dict(g.spec)
        assert d["formulas"][d["root"]] == "F (p300 & F p0)"
        assert d["formulas"]["p0"] == "F p100 & F p200"


def test_priority_respects_the_running_order(cell: Scene) -> None:
    run = OfflineGrounder().ground("give A the cup, then give B the chips", cell).spec
    with pytest.raises(GroundingError, match="must come after p100"):
        OfflineGrounder().ground("do the chips first", cell, run)
    alt = OfflineGrounder().ground("give A the cup or B the chips", cell).spec
    with pytest.raises(GroundingError, match="alternatives"):
        OfflineGrounder().ground("do the chips first", cell, alt)


def test_update_refuses_a_double_delivery(cell: Scene, running: HSpec) -> None:
    with pytest.raises(GroundingError, match="handed over only once"):
        OfflineGrounder().ground("also give A the chips", cell, running)


# -- carry-over ----------------------------------------------------------------------------------


def test_carry_over_keeps_done_leaves_and_states(cell: Scene, running: HSpec) -> None:
    m = HierarchyMonitor(running)
    q = m.step(m.initial, [CUP_A])  # p100 done
    g = apply_update("Also give B the bottle", cell, running, OfflineGrounder(), m.done(q))
    new = carry_over(running, q, g.spec)
    nm = HierarchyMonitor(g.spec)
    assert nm.done(new) == {"p100"}
    assert nm.state_of(new, "p0") == m.state_of(q, "p0")
    # finishing the rest completes the merged spec
    end = nm.run([[CHIPS_B], [APPLE_C], [Atom("delivered", ("bottle", "B"))]], new)
    assert nm.accepted(end)


def test_carry_over_after_cancel_can_finish_a_group(cell: Scene, running: HSpec) -> None:
    m = HierarchyMonitor(running)
    q = m.run([[CUP_A], [APPLE_C]])
    g = apply_update("cancel the chips", cell, running, OfflineGrounder(), m.done(q))
    new = carry_over(running, q, g.spec)
    assert HierarchyMonitor(g.spec).accepted(new)  # nothing left: the task is complete


def test_carry_over_replays_a_sequence_in_order(cell: Scene) -> None:
    run = OfflineGrounder().ground("give A the cup, then B the chips, then C the apple", cell).spec
    m = HierarchyMonitor(run)
    q = m.run([[CUP_A]])
    g = apply_update("cancel the chips", cell, run, OfflineGrounder(), m.done(q))
    assert spec_to_dict(g.spec)["formulas"]["p0"] == "F (p100 & F p300)"
    new = carry_over(run, q, g.spec)
    nm = HierarchyMonitor(g.spec)
    assert not nm.accepted(new)
    assert nm.accepted(nm.step(new, [APPLE_C]))  # the cup is done: the apple alone finishes


def test_carry_over_of_a_finished_task_into_a_new_root(cell: Scene) -> None:
    run = OfflineGrounder().ground("give A the cup", cell).spec
    m = HierarchyMonitor(run)
    q = m.run([[CUP_A]])
    assert m.accepted(q)
    g = apply_update("then give B the chips", cell, run, OfflineGrounder(), m.done(q))
    new = carry_over(run, q, g.spec)
    nm = HierarchyMonitor(g.spec)
    assert nm.state_of(new, "p0") is None and not nm.accepted(new)
    assert nm.accepted(nm.step(new, [CHIPS_B]))
    assert new[nm.nodes.index("p0")] == DONE
