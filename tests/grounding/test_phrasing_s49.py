"""Session-49 phrasings of issue 12 (engineer 12): blind47's politeness and fillers, wants and
needs, pronouns and ellipsis and questions, each as a family (docs/grounding.md, "Session 49
(engineer 12)"). Each rule with sentences in other words and scenes it reads (refused on main and
with the rule taken out), and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites49
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
)

# the example scenes blind47 uses
DUO, ONE, T21 = (load_scene(ROOT / f"examples/scenes/{n}.yaml") for n in ("2-2", "1-1", "2-1"))

# -- sympathy with a word the grounder does not know ('poor mite') (_poor49) -----------------------

POOR = PhrasingCases()
test_poor = POOR.test(
    ("Lily's grizzling for her teddy bear again, poor mite.", "teddy>A", NURSERY),
    ("Carol's after the apple, poor mite.", "apple>C", CELL),
    ("Give Lena the lemon, poor mite.", "lemon>B", KITCHEN),
    ("Mrs Khan would like the magazine, poor old duck.", "magazine>C", WARD),
    ("Give the cup, poor mite.", None, CELL),
    ("Bob wants the cup, poor Carol.", None, CELL),
)


def test_poor_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    POOR.refused_without((_rewrites49._poor49,), monkeypatch)


# -- 'seeing' alone opening a reason ('seeing she's asked twice') (_seeing49) ----------------------

SEEING = PhrasingCases()
test_seeing = SEEING.test(
    ("Could the bottle go over to Person A, seeing she's asked twice?", "bottle>A", ONE),
    ("Could Carol have the apple, seeing she's been waiting?", "apple>C", CELL),
    ("Pass Sam the stapler, seeing he's asked nicely.", "stapler>B", OFFICE),
    ("Could the cup go to Bob, seeing she's asked?", None, CELL),
    ("Give it to her, seeing she's asked.", None, CELL),
)


def test_seeing_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SEEING.refused_without((_rewrites49._seeing49,), monkeypatch)


# -- 'sorting P out with the X' (_sort_out49) ------------------------------------------------------

SORT = PhrasingCases()
test_sort = SORT.test(
    ("Person B's thirsty, would you mind sorting him out with the bottle?", "bottle>B", DUO),
    ("Would you mind sorting Person A out with the chips?", "chips>A", DUO),
    ("Would you mind sorting Mrs Khan out with the magazine?", "magazine>C", WARD),
    ("Sort it out with Bob.", None, CELL),
    ("Sort the cup out with Bob.", None, CELL),
    ("Sort him out with the cup.", None, CELL),
)


def test_sort_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SORT.refused_without((_rewrites49._sort_out49,), monkeypatch)


# -- 'it's in P's way' closing a placing (_in_way49) -----------------------------------------------

IN_WAY = PhrasingCases()
test_in_way = IN_WAY.test(
    ("Would you set the bowl down on the tray, it's in Dana's way?", "bowl@tray", LAB),
    ("Put the red mug on the shelf, it's in Carol's way.", "mug_red@shelf", CELL),
    ("Would you put the knife on the rack, it's in Marco's way?", "knife@rack", KITCHEN),
    ("It's in Carol's way.", None, CELL),
)


def test_in_way_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    IN_WAY.refused_without((_rewrites49._in_way49,), monkeypatch)


# -- 'for that' closing a request after a remark (_for_that49) -------------------------------------

FOR_THAT = PhrasingCases()
test_for_that = FOR_THAT.test(
    (
        "Jess is putting up brackets, could you fetch Jess the power drill for that?",
        "drill>B",
        WORKSHOP,
    ),
    ("Carol's making tea, could you bring her the red mug for that?", "mug_red>C", CELL),
    ("Sam's stapling the minutes, pass him the stapler for that.", "stapler>B", OFFICE),
    ("Could you bring the red mug for that?", None, CELL),
    ("Could you fetch the power drill for that?", None, WORKSHOP),
)


def test_for_that_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FOR_THAT.refused_without((_rewrites49._for_that49,), monkeypatch)


# -- 'any objection to' / 'any chance of' before what to do (_objection49) -------------------------

OBJECTION = PhrasingCases()
test_objection = OBJECTION.test(
    ("Person B's hungry, any objection to giving him the chips?", "chips>B", T21),
    ("Carol's thirsty, any chance of passing her the bottle?", "bottle>C", CELL),
    ("Any objection to handing Marco the knife?", "knife>A", KITCHEN),
    ("Got any objection to passing Sam the stapler?", "stapler>B", OFFICE),
    ("Any objection to the bottle?", None, CELL),
)


def test_objection_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OBJECTION.refused_without((_rewrites49._objection49,), monkeypatch)
