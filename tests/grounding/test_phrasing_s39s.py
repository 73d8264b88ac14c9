"""Session-39 phrasings of issue 12 (engineer 12s): a remark beside an ordinary request, by the
kind of its subject (normalise._remark39s, _remark_first39s), and the remarks about a person that
must not be read past (offline's remark_said39s); docs/grounding.md, "Session 39 (engineer 12s)".
Each kind with sentences in other words, scenes and people than blind37's, and near forms that
must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import normalise, offline
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
    tree,
)

F41 = load_scene(ROOT / "examples/scenes/4-1.yaml")
DUO = load_scene(ROOT / "examples/scenes/2-2.yaml")

CASES = PhrasingCases()


# -- a remark closing the request, by its subject (_remark39s) -----------------------------------

test_remarks = CASES.test(
    # they (both) of the people the request names, all of whom get something
    (
        "Give Alice the apple and Bob the crisps, they've both been at the conker championship.",
        "apple>A & chips>B",
        CELL,
    ),
    (
        "Hand Noah the ruler and Zoe the globe; they've both been on the sponsored walk.",
        "ruler>B & globe>C",
        CLASSROOM,
    ),
    # a thing or a place (its going, or a time of its own, puts nothing off)
    ("Put the knife on the rack, the dishwasher crew will be in shortly.", "knife@rack", KITCHEN),
    ("Give Jess the torch, the bulbs on the landing have gone.", "torch>B", WORKSHOP),
    ("Put the globe on the shelf, the inspectors will be here soon.", "globe@shelf", CLASSROOM),
    ("Put the bowl in the sink, the cleaning lot will be round any minute.", "bowl@sink", LAB),
    # a person by a name: an errand ('got X to get to'), 'after' / 'since' a thing gone by, a
    # time ending a thing's name
    ("Put the screws on the bench, Jess has got a quiz night to get to.", "screws@bench", WORKSHOP),
    (
        "Put the magazine on the trolley, Ruth's tidying up after her ward round.",
        "magazine@trolley",
        WARD,
    ),
    ("Pop the notepad in the box, Sam's been doodling since the away day.", "notebook@box", OFFICE),
    # his / her <thing>, with a dislike of something the person does not get
    ("Give Zoe the ruler, her art club's put her off glue.", "ruler>C", CLASSROOM),
    ("Give Mr Novak the lemon, his doctor's put him off salt.", "lemon>C", KITCHEN),
)

# what must stay refused: a remark that could change who gets what or when
test_remarks_refused = CASES.test(
    # a dislike of what the person gets
    ("Give Alice the crisps, her running club's put her off crisps.", None, CELL),
    ("Give Mr Novak the salt, his doctor's put him off salt.", None, KITCHEN),
    # 'they' of one person
    ("Give Alice the apple, they've both been at the regatta.", None, CELL),
    # a time joined to the request, a name of the scene, a want of the speaker's side
    ("Put the knife on the rack, the lunch crowd will be in before we're done.", None, KITCHEN),
    ("Put the tape on the pallet, we need the gloves too.", None, DEPOT),
    ("Give Jess the torch, the bulbs on the landing want the drill.", None, WORKSHOP),
    # a time of the person's own
    ("Put the screws on the bench, Jess has got a quiz to get to at nine.", None, WORKSHOP),
)


# -- the same remarks opening the request (_remark_first39s) -------------------------------------

test_remarks_first = CASES.test(
    (
        "Kofi has been up a ladder all morning. Pass the drill to Jess.",
        "drill>B",
        WORKSHOP,
    ),
    ("The forklift crew will be in shortly, so put the tape on the pallet.", "tape@pallet", DEPOT),
    (
        "We've the cleaners coming round at six, so pop the bib on the high chair.",
        "bib@highchair",
        NURSERY,
    ),
)

test_remarks_first_refused = CASES.test(
    # a pronoun in the request (the remark's person may be whom it means; older rules' reading)
    ("The forklift crew will be in shortly, so put it on the pallet.", None, DEPOT),
    # bare objects (the lead's session-37 rule: the remark's person gets them)
    ("We've the cleaners coming round at six. The bib.", None, NURSERY),
)


def test_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CASES.refused_without((*normalise._STEPS39S, *normalise._STEPS39S_FIRST), monkeypatch)


# -- what a remark about a person must not be read past (offline.remark_said39s) ----------------

SAID: list[tuple[str, Scene]] = [
    # a person said to be leaving, away, back later, fine, done or asleep
    ("Give Bob the cup, Bob's off home.", CELL),
    ("Give Bob the cup, Bob's fine.", CELL),
    ("Hand Tom the scanner, Mia's back in a bit.", DEPOT),
    ("Lena gets the salt, Marco's off to the market.", KITCHEN),
    ("Give Bob the cup, Carol's off to the shops.", CELL),
    ("Give Bob the cup, he's done for the day.", CELL),
    ("Give Mr Lee the magazine, he's asleep.", WARD),
    # a need of someone who gets nothing
    ("Give Alice the apple, Bob's parched.", CELL),
    ("Give Noah the ruler, Zoe's thirsty.", CLASSROOM),
    # a he / she that may be either person the request names
    ("Give Person A the apple and Person B the cup, he's a stone waller.", F41),
    (
        "Give Person A the chips and Person B the bottle, he's been stacking hay all morning.",
        DUO,
    ),
]


@pytest.mark.parametrize(("text", "scene"), SAID)
def test_said_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_said_refused_by_the_check(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the check, each is read (the older rules take the remark off)."""
    monkeypatch.setattr(offline, "remark_said39s", lambda *_: None)
    for text, scene in SAID:
        assert tree(text, scene) is not None, text


# what the check leaves read: a person's state or doing that changes nothing (read before it too)
test_said_read = PhrasingCases().test(
    ("Give Bob the cup, he's just back from the gym.", "cup>B", CELL),
    (
        "Give Alice the apple and Bob the cup, he's been stone walling all day.",
        "apple>A & cup>B",
        CELL,
    ),
    ("Give Mrs Khan the jug, she's thirsty.", "jug>C", WARD),
)
