"""Session-39 phrasings of issue 12 (engineer 12s): a remark beside an ordinary request, by the
kind of its subject (normalise._remark39s, _remark_first39s), and the remarks about a person that
must not be read past (offline's remark_said39s); docs/grounding.md, "Session 39 (engineer 12s)".
Each kind with sentences in other words, scenes and people than blind37's, and near forms that
must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites46r, _rewrites51s, normalise, offline
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

# said without punctuation: before he's / she's / we're, or 'were' after 'please'; a place by its
# number ('at table six'), 'a long one', 'since noon' (a time gone by)
test_remarks_run_on = CASES.test(
    ("stapler on the desk please were off to the staff quiz", "stapler@desk", OFFICE),
    (
        "the bowl to omar please hes only just back from the dentist and hes starving",
        "bowl>B",
        LAB,
    ),
    ("the knife to lena please shes at table four", "knife>B", KITCHEN),
    ("Hand Lena the tongs; her shift was a long one.", "tongs>B", KITCHEN),
)

# a remark as a sentence, or closing one, with another sentence of the request after it
test_remarks_middle = CASES.test(
    (
        "Give Tom the scanner. The loading bay doors are jammed again. Then the tape to Mia.",
        "scanner>B ; tape>A",
        DEPOT,
    ),
    (
        "Put the bowl in the sink. Dana has been on the wards all day. Then the spoon to Omar.",
        "bowl@sink ; spoon>B",
        LAB,
    ),
    (
        "Give Lena the tongs. Marco has been at the grill since noon. Then the salt to Mr Novak.",
        "tongs>B ; salt>C",
        KITCHEN,
    ),
)

# what must stay refused: a remark that could change who gets what or when
test_remarks_refused = CASES.test(
    # a time of the person's own, said without punctuation; a pronoun that cannot be the person
    ("pass the drill to kofi please hes back at six", None, WORKSHOP),
    ("Give Lena the tongs, Marco has been at the grill since six tonight.", None, KITCHEN),
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


# -- blind37's corrections, by kind (_corrections39s) ---------------------------------------------
# (each with other words, scenes and people than blind37's sentence)

test_corrections = CASES.test(
    # the speaker's slip said after a cue, or as one
    ("The stapler goes to Priya, sorry, I keep saying Priya, it's for Sam.", "stapler>B", OFFICE),
    ("Wipes to Grandad, oops, my muddle, they're for Ava.", "wipes>C", NURSERY),
    (
        "The jug's for Mr Lee, oh no, I've mixed them up, Mrs Khan's the one needing it.",
        "jug>C",
        WARD,
    ),
    # 'hold up' as 'hold on'; where it goes said again ('it should go to P')
    ("Tongs for Lena, ah, hold up, it was the knife she asked for.", "knife>B", KITCHEN),
    ("Pass the globe to Noah, scratch that, it should go to Zoe.", "globe>C", CLASSROOM),
    # the object corrected to in a pseudo-cleft of the person's want
    (
        "Dana's having the banana, no, my mistake, the green cup's what she asked for.",
        "cup_green>A",
        LAB,
    ),
    # a place instead of the person
    ("Hammer to Kofi, or no, on the workbench.", "hammer@bench", WORKSHOP),
    # the person taken back not here, the one who is
    (
        "Take the spoon over to Omar, oh silly me, he's not here, it's Emma who's about.",
        "spoon>C",
        LAB,
    ),
)

test_corrections_refused = CASES.test(
    # the slip names someone the request did not
    ("The stapler goes to Priya, sorry, I keep saying Sam, it's for Sam.", None, OFFICE),
    # the want of someone else, or of a pronoun that cannot be the person
    (
        "Dana's having the banana, no, my mistake, the green cup's what Omar asked for.",
        None,
        LAB,
    ),
    ("Omar's having the banana, no, the bowl's what she asked for.", None, LAB),
    # two objects: which goes there?
    ("Hammer and screws to Kofi, or no, on the workbench.", None, WORKSHOP),
    # 'she's not here' of Omar
    ("Take the spoon over to Omar, oh silly me, she's not here, it's Emma who's about.", None, LAB),
)


def test_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # 12's _run_on39 (session 39) reads a remark said without punctuation too; session 40's
    # widened rules (12s) read some of these kinds again
    CASES.refused_without(
        (
            *normalise._STEPS39S,
            *normalise._STEPS39S_FIRST,
            *normalise._STEPS39,
            *normalise._STEPS40S,
            *normalise._STEPS40S_FIRST,
            # session 43 (12r): its corrections read some of these too
            *normalise._STEPS43R_FIRST,
            *normalise._STEPS43R,
            # session 44 (12r): its rules of the same families read some of these too
            *normalise._STEPS44R_FIRST,
            *normalise._STEPS44R,
            # session 46 (12r): a closing remark on what a person is doing after a placing reads
            # by its rule too
            _rewrites46r._placed_remark46r,
            # session 51 (12s): its run-on rule says these remarks with their stops too
            _rewrites51s._run_on51s,
        ),
        monkeypatch,
    )


# -- what a remark about a person must not be read past (offline.remark_said39s) ----------------

SAID: list[tuple[str, Scene]] = [
    # the one who gets it, said again by name to be leaving or fine; asleep
    ("Give Bob the cup, Bob's off home.", CELL),
    ("Give Bob the cup, Bob's fine.", CELL),
    ("Give Mr Lee the magazine, he's asleep.", WARD),
    # a need of someone who gets nothing
    ("Give Alice the apple, Bob's parched.", CELL),
    ("Give Noah the ruler, Zoe's thirsty.", CLASSROOM),
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
    ("Give Tom the scanner, he's off on his round.", "scanner>B", DEPOT),
    ("Scanner to Mia, no, make it Tom, Mia's gone on break.", "scanner>B", DEPOT),
    ("The salt is going to Lena, Marco's had his fill.", "salt>B", KITCHEN),
    # of someone who gets nothing, leaving or back later is said now (sessions 8 and 37)
    ("Lena gets the salt, Marco's off to the market.", "salt>B", KITCHEN),
    ("Hand Tom the scanner, Mia's back in a bit.", "scanner>B", DEPOT),
)
