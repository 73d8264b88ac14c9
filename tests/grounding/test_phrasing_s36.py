"""Session-36 phrasings of issue 12 (engineer 12): blind34's refusals by kind in its sections of
politeness, wants, pronouns and ellipsis, sentence splits, lower case, typos and questions
(docs/grounding.md, "Session 36 (engineer 12)"). Each rule with sentences it reads (which fail
with the rules taken out) and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites45, normalise
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_reads,
)
from tests.grounding.test_phrasing_s33t import DUO, F41, FIG1, L24, L44, ONE, SQ, T12, T21, TWO

CASES = PhrasingCases()

# -- courtesies: 'very good of you', 'quick favour before my X lesson:', thanks from a group,
# 'much obliged if you'd' ------------------------------------------------------------------------

test_courtesies = CASES.test(
    (
        "Go on, be a love, the cup to Person B, and thanks a million from the whole ballet class.",
        "cup>B",
        F41,
    ),
    ("Give Carol the apple, and thanks from all the chess club.", "apple>C", CELL),
    (
        "Quick favour before my flamenco lesson: bottle to Person B, and that's everything.",
        "bottle>B",
        DUO,
    ),
    ("Quick favour before my swim: the apple to Bob.", "apple>B", CELL),
    ("Much obliged if you'd get the bottle to Person A, blagodaram.", "bottle>A", ONE),
    (
        "Very good of you, really, just the bottle for Person A and then I'll leave you in peace, "
        "miigwech.",
        "bottle>A",
        T12,
    ),
    ("That's kind of you, the cup for Carol.", "cup>C", CELL),
    # a favour before something of the scene or a time; thanks from a person of the scene; a
    # condition of something else than the speaker's thanks
    ("Quick favour before the apple: the cup to Bob.", None, CELL),
    ("Quick favour before my lesson tomorrow: the cup to Bob.", None, CELL),
    ("Give Carol the apple, and thanks from Bob's chess club.", None, CELL),
    ("Much obliged if the cup is clean, give it to Bob.", None, CELL),
    ("Very good of you.", None, CELL),
)

# -- question frames: 'do you think you could manage', 'any chance of X for P', 'lay X out on S'

test_question_frames = CASES.test(
    (
        "Do you think you could manage the bottle over to Person A, she's the bursar?",
        "bottle>A",
        T12,
    ),
    (
        "Is there any chance of the bottle for Person B, seeing as he's been woodturning all day?",
        "bottle>B",
        F41,
    ),
    ("Is there any chance of the cup for Bob?", "cup>B", CELL),
    (
        "Would you mind laying the small spanner out on the workbench, I've a nut to loosen?",
        "spanner_small@bench",
        WORKSHOP,
    ),
    ("Set the cup out on the table.", "cup@table", CELL),
    # 'out' before a person, a chance of something not in the scene, two people
    ("Lay the cup out for Bob.", None, CELL),
    ("Is there any chance of rain for Bob?", None, CELL),
    ("Any chance of the apple for Carol and Bob or the cup?", None, CELL),
)

# -- after a placement: 'so nobody sits on it', 'with the others' where others of its kind lie --

test_why_placed = CASES.test(
    ("Would you put the banana on the tray so nobody sits on it?", "banana@tray", LAB),
    (
        "Would you pop the white plate up in the plate rack with the others?",
        "plate_white@rack",
        KITCHEN,
    ),
    # no placement; two objects for 'it'; the plate already on the rack
    ("Give Bob the apple so nobody sits on it.", None, CELL),
    ("Put the apple and the cup on the shelf so nobody sits on it.", None, CELL),
    ("Put the blue plate in the plate rack with the others.", None, KITCHEN),
    # 'the rest' may be more to move (test_phrasing_s34t)
    ("Put the white plate in the plate rack with the rest.", None, KITCHEN),
)

# -- closing remarks of a closed list: 'rough poker night', "its porridge oclock", 'hes the one
# back from surfing', 'for the last van of the day', 'snack time so its …' ---------------------

test_closing_remarks = CASES.test(
    ("person a needs the bottle, rough poker night", "bottle>A", T12),
    ("dana the doctor is after the spoon and bowl, its porridge oclock", "spoon>A & bowl>A", LAB),
    ("cup for person b thx hes the one back from surfing", "cup>B", L44),
    ("tom needs the scanner for the last van of the day", "scanner>B", DEPOT),
    ("snack time so its apple for person a and chips for person b", "apple>A & chips>B", SQ),
    # a remark naming the scene, a time, 'he' of two people, a time as the need's purpose
    ("person a needs the bottle, rough bottle night", None, T12),
    ("give bob the cup, its apple oclock", None, CELL),
    ("Give Bob the mug, big one.", None, CELL),
    ("cup for bob and apple for carol thx hes the one back from surfing", None, CELL),
    ("tom needs the scanner for the last time", None, DEPOT),
    ("apple time so its the cup for bob", None, CELL),
)

# -- wants by a frame: the passive 'has been asked for by', 'S is where X ought to be', 'P could
# use X to keep her going', "he'll want Y with it" -----------------------------------------------

test_wants_said = CASES.test(
    (
        "The bottle's been asked for by Person B, who runs the model railway club, and Person A "
        "asked for the chips.",
        "bottle>B & chips>A",
        T21,
    ),
    (
        "The sink is where the green cup ought to be, the aquarist left it out.",
        "cup_green@sink",
        LAB,
    ),
    (
        "Person B would love the apple, and Person A could use the chips to keep her going at the "
        "bonsai show.",
        "apple>B & chips>A",
        L44,
    ),
    ("Person B's to have the apple, and he'll want the cup with it.", "apple>B & cup>B", SQ),
    (
        "The bottle needs putting up on the shelf, the bosun likes things stowed.",
        "bottle@shelf",
        TWO,
    ),
    # asked for by a surface or two people; the pronoun of two people; 'left it out' of two
    # objects; 'keep her going' after two people's wants with a man's name
    ("The cup's been asked for by the shelf.", None, CELL),
    ("The cup's been asked for by Bob and Carol.", None, CELL),
    ("Bob gets the apple and Carol the cup, and she'll want the mug with it.", None, CELL),
    (
        "The sink is where the green cup ought to be, the aquarist left the white cup out.",
        None,
        LAB,
    ),
    ("Bob could use the crisps to keep her going at the chess club.", None, CELL),
    ("Carol could use the crisps to keep her going at the apple show.", None, CELL),
    ("The bottle needs putting up on the shelf, the bosun likes the chips stowed.", None, TWO),
)

# -- pronouns: whose the object is, then the request by pronouns; 'also hers' of one person;
# 'and likewise' ----------------------------------------------------------------------------------

test_pronouns = CASES.test(
    (
        "The coalman left the crisps out, so get them and put them up on the shelf.",
        "chips@shelf",
        TWO,
    ),
    ("Marco's lost his tongs, get them to him, would you.", "tongs>A", KITCHEN),
    ("The scissors are Noah's, so bring them over to him.", "scissors>B", CLASSROOM),
    (
        "Person A's been beachcombing all morning: the bottle to her first, then the chips, also "
        "hers.",
        "bottle>A ; chips>A",
        L24,
    ),
    (
        "Hand the chips to Person A, and likewise the bottle to Person B, he's the hedger.",
        "chips>A & bottle>B",
        DUO,
    ),
    # 'his' of a woman; 'it' of plural tongs; another person named in the request; 'also hers'
    # after two people; the coalman's crisps with no pronoun for them
    ("Carol's lost his apple, get it to her.", None, CELL),
    ("Marco's lost his tongs, get it to him, would you.", None, KITCHEN),
    ("The scissors are Noah's, so bring them over to Emma.", None, CLASSROOM),
    ("The cup to Bob first, then the apple to Carol, also hers.", None, CELL),
    ("The coalman left the crisps out, so put the bottle up on the shelf.", None, TWO),
)

# -- splits and run-ons: a remark run on before a comma or a new clause, 'give them those' after
# wants, "X stays put." of an object not asked for, a body's state, a trade of two words --------

test_splits = CASES.test(
    (
        "Bob's thirsty he wants the bottle and Alice wants the crisps give them those.",
        "bottle>B & chips>A",
        FIG1,
    ),
    (
        "Person B's having the chips and Person A the bottle; give them those when you've got a "
        "hand free.",
        "chips>B & bottle>A",
        T21,
    ),
    (
        "Person B gets the bottle he's been waiting ages Person A gets the chips she's been "
        "waiting longer.",
        "bottle>B & chips>A",
        DUO,
    ),
    (
        "Person A wants the bottle she's been at kickboxing, and Person B the chips he's starving.",
        "bottle>A & chips>B",
        T21,
    ),
    ("Apple to Person A. Cup to Person B. Chips stay put.", "apple>A & cup>B", SQ),
    ("Grey blanket. Mr Lee. His feet are like ice.", "blanket_grey>B", WARD),
    (
        "Chips for Person A. And the bottle. That's for Person B, the park keeper.",
        "chips>A & bottle>B",
        L24,
    ),
    # a remark holding a pronoun or a time; give them those after an order, not wants; the object
    # asked for stays put; 'her feet' of Mr Lee; a trade word that names the scene
    ("Person A wants the bottle she's been at it, and Person B the chips.", None, T21),
    ("Person A wants the bottle she's been out later, and Person B the chips.", None, T21),
    ("Give Bob the bottle and Alice wants the crisps give them those.", None, FIG1),
    ("Person B gets the bottle he's been waiting ages Person A gets it.", None, DUO),
    ("Apple to Person A. Cup to Person B. Apple stays put.", None, SQ),
    ("Everything to Person A. Chips stay put.", None, SQ),
    ("Grey blanket. Mr Lee. Her feet are like ice.", None, WARD),
    ("Give the cup to Bob, the shelf keeper.", None, CELL),
)

# -- lower case: "the bottles going" with one bottle; 'P first with X'; a trade's remark ---------

test_lower_case = CASES.test(
    (
        "the bottles going to person b and person a gets the chips this time round",
        "bottle>B & chips>A",
        T21,
    ),
    (
        "alice first with the bottle and after that bob gets the chips, kendo finishes at six",
        "bottle>A ; chips>B",
        FIG1,
    ),
    ("Pop the chipos up on the shelf, the coastguard will eat later.", "chips@shelf", TWO),
    # 'first with' of two people; the eating of the
    # scene's thing; a time said of a person of the scene
    ("bob and carol first with the cup and after that alice gets the apple", None, CELL),
    # written with its apostrophes: the plural is meant, and the scene has one bottle
    ("the bottles going to Person B, she's waiting", None, T21),
    ("Pop the crisps up on the shelf, the coastguard will eat them later.", None, TWO),
    (
        "alice first with the bottle and after that bob gets the chips, the bottle finishes at six",
        None,
        FIG1,
    ),
)

# -- the same kinds in blind16: the request announced to the room ----------------------------

test_announced = CASES.test(
    (
        "If everyone could just wait a moment, our robot here is going to place the globe on the "
        "desk. Lovely, thank you all.",
        "globe@desk",
        CLASSROOM,
    ),
    ("Our robot is going to give the globe to Noah.", "globe>B", CLASSROOM),
    # the wait asked alone, the robot to wait, a time
    ("If everyone could just wait a moment, place the globe on the desk.", None, CLASSROOM),
    ("Our robot here is going to wait.", None, CLASSROOM),
    (
        "If everyone could just wait a moment, our robot here is going to place the globe on the "
        "desk tomorrow.",
        None,
        CLASSROOM,
    ),
    ("Your robot is going to place the globe on the desk.", None, CLASSROOM),
)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # two mugs in the scene: 'the mugs going' is the plural, as before
        ("the mugs going to bob", "mug_red>B & mug_blue>B", CELL),
        ("the crisps going to bob", "chips>B", CELL),
        # a want run on ('she's craving') is no remark: read as before (blind29)
        (
            "Person A could really do with the cup; for Person B it's the apple she's craving, so "
            "that too.",
            "cup>A & apple>B",
            SQ,
        ),
    ],
)
def test_read_as_before(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


def test_refused_without_the_rules(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 45 (12): _lacking45 reads "Marco's lost his tongs, get them to him" too
    steps = (*normalise._STEPS36_FIRST, *normalise._STEPS36, _rewrites45._lacking45)
    CASES.refused_without(steps, monkeypatch)
