"""Session-39 phrasings of issue 12 (engineer 12): blind37's refusals by kind in its sections of
politeness, wants, pronouns and ellipsis, sentence splits, lower case, typos and questions
(docs/grounding.md, "Session 39 (engineer 12)"). Each rule with sentences it reads (which fail
with the rules taken out) and near sentences that must stay refused."""

from __future__ import annotations

import re

import pytest

from hltl.errors import GroundingError
from hltl.grounding import (
    _normalise1,
    _normalise2,
    _normalise4,
    _rewrites39,
    _rewrites50l,
    _rewrites51s,
    normalise,
    offline,
)
from hltl.grounding.offline import parse_instruction
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_reads,
    assert_refused,
)
from tests.grounding.test_phrasing_s33t import TWO

CASES = PhrasingCases()

# -- wants said by an idiom before 'a' / 'an' / 'some' (could murder, could kill for, heart set
# on, put one's name down for); 'P is after a brew' (thirsty); 'P needs a <kind>, and the X's the
# only one going' -----------------------------------------------------------------------------

test_wants = CASES.test(
    ("Dana could murder a banana.", "banana>A", LAB),
    ("Mr Novak could kill for a lemon, he says.", "lemon>C", KITCHEN),
    ("Zoe has her heart set on a ruler.", "ruler>C", CLASSROOM),
    ("Noah's put his name down for the globe.", "globe>B", CLASSROOM),
    (
        "Tom put his name down for some tape, and Mia wants the scanner.",
        "tape>B & scanner>A",
        DEPOT,
    ),
    ("Ruth's after a cuppa, so she'll be wanting the water jug.", "jug>A", WARD),
    ("Omar is after a snack, so pass him the banana.", "banana>B", LAB),
    ("Jess needs a drink, and the flashlight's the only one going.", None, WORKSHOP),
    ("Mrs Khan needs a read, and the magazine's the only one left.", "magazine>C", WARD),
    ("Sam wants a pen, and the red pen is the only one we've got.", "pen_red>B", OFFICE),
    # two people; a person after the idiom (no object); the idiom before a kind the scene has no
    # name for, with nothing after it; the only one naming two objects
    ("Dana and Omar could murder a banana.", None, LAB),
    ("Zoe has her heart set on Noah.", None, CLASSROOM),
    ("Ruth's after a cuppa.", None, WARD),
    ("Sam wants a pen, and the red pen and the blue pen are the only ones going.", None, OFFICE),
)

# -- an 'after' closing a want or state of one person that says what they have been doing: 'after
# all that <doing>', 'after a go on the <thing>' -------------------------------------------------

test_after_all = CASES.test(
    ("Noah could use the ruler after all that long division.", "ruler>B", CLASSROOM),
    ("Tom wants the gloves after all that shrink wrapping.", "gloves>B", DEPOT),
    ("Ava could do with the beaker after a go on the slide.", "beaker>C", NURSERY),
    ("Mr Lee needs the blanket_blue after a turn on the exercise bike.", None, WARD),
    ("Mr Lee needs the blue blanket after a turn on the exercise bike.", "blanket_blue>B", WARD),
    # an order, not a want; a surface in the clause; two people; what was done names something
    ("Give Noah the ruler after all that long division.", None, CLASSROOM),
    ("Tom wants the gloves on the belt after all that shrink wrapping.", None, DEPOT),
    ("Ava and Lily want the beaker after a go on the slide.", None, NURSERY),
    ("Tom wants the gloves after all that pallet wrapping.", None, DEPOT),
)

# -- courtesy: thanks and a word of address opening a request; 'at all' in 'Is it at all possible
# to …' --------------------------------------------------------------------------------------------

test_courtesy = CASES.test(
    ("Thanks, pet, could Zoe have the glue stick?", "glue>C", CLASSROOM),
    ("Cheers, pet, and could Mr Lee have his magazine?", "magazine>B", WARD),
    ("Is it at all possible to put the stapler in the box?", "stapler@box", OFFICE),
    ("Is it at all possible to hand Marco the knife?", "knife>A", KITCHEN),
    # thanks and an address with nothing asked after it; 'at all' in a question of whether it
    # was done
    ("Thanks, pet, and that's all.", None, CLASSROOM),
    ("Is it at all likely that the stapler is in the box?", None, OFFICE),
)

# -- an object 'is to' go somewhere, said with "'s" --------------------------------------------

test_is_to = CASES.test(
    ("The sponge's to go in the sink.", "sponge@sink", LAB),
    ("The knife's to be given to Marco.", "knife>A", KITCHEN),
    ("The grey blanket's to go to Mrs Khan, she's cold.", "blanket_grey>C", WARD),
    # no scene name before it
    ("The kettle's to go on the rack.", None, KITCHEN),
)

# -- order: 'Start off with', "P's after X, so sort him out first", 'once both are sorted', 'once
# she's sorted' ------------------------------------------------------------------------------

test_order = CASES.test(
    (
        "Start off with the glue for Zoe. Once that's done, Noah can have the ruler.",
        "glue>C ; ruler>B",
        CLASSROOM,
    ),
    (
        "Begin out with the knife for Marco, he's off soon, then give Lena the lemon.",
        "knife>A ; lemon>B",
        KITCHEN,
    ),
    (
        "Mrs Khan's after the magazine, so sort her out first. Then the jug can go on the trolley.",
        "magazine>C ; jug@trolley",
        WARD,
    ),
    ("Omar is waiting for the spoon, so see to him first.", "spoon>B", LAB),
    (
        "The tape goes on the belt and the gloves to Tom. Once both are sorted, the scanner's for "
        "Mia.",
        "(tape@conveyor & gloves>B) ; scanner>A",
        DEPOT,
    ),
    (
        "the knife goes to marco first and once hes sorted the lemon to lena",
        "knife>A ; lemon>B",
        KITCHEN,
    ),
    # the pronoun the other sex; two people before 'sort'; 'once she's sorted' with no one before
    # it; 'once both are sorted' after one task
    ("Mrs Khan's after the magazine, so sort him out first.", None, WARD),
    ("Mrs Khan and Ruth are after the magazine, so sort her out first.", None, WARD),
    ("once shes sorted the lemon to lena", None, KITCHEN),
    ("The tape goes on the belt. Once both are sorted, the scanner's for Mia.", None, DEPOT),
)

# -- pronouns and ellipsis: 'As for P, he …' / 'As for P, the X'; 'The X? P's.' / 'The X? That's
# P's.'; "The X's P's, if you would" ---------------------------------------------------------------

test_pronouns = CASES.test(
    ("Marco wants the knife. As for Lena, the lemon.", "knife>A & lemon>B", KITCHEN),
    (
        "The tape's wanted by Tom. As for Mia, she's had her eye on the scanner.",
        "tape>B & scanner>A",
        DEPOT,
    ),
    ("The globe? Noah's. The glue stick? That's Zoe's.", "globe>B & glue>C", CLASSROOM),
    ("The sponge's Omar's, if you would.", "sponge>B", LAB),
    ("The stapler's Sam's, if you wouldn't mind.", "stapler>B", OFFICE),
    # the pronoun the other sex; 'as for' a thing; whose it is with no courtesy after it (whose,
    # or to hand over); the answer a thing
    ("The tape's wanted by Tom. As for Mia, he's had his eye on the scanner.", None, DEPOT),
    ("As for the knife, the lemon.", None, KITCHEN),
    # session 42: said alone it is a handover (the lead's possession policy): test_phrasing_s42
    ("The globe? The shelf's.", None, CLASSROOM),
)

# -- a remark that says 'it' of the one object the request names: what the person did with it or
# what is on it (he / she the one person named, or a person of the scene after a placement) -----

test_it_remark = CASES.test(
    ("The magazine to Mrs Khan, she does the crossword in it every morning.", "magazine>C", WARD),
    ("Bowl in the sink please, Dana's got soup all over it.", "bowl@sink", LAB),
    ("The tape to Tom, he won it in the raffle.", "tape>B", DEPOT),
    ("Knife on the rack, Marco's got fish scales on it.", "knife@rack", KITCHEN),
    ("stapler in the box please sam is sick of tripping over it", "stapler@box", OFFICE),
    # the pronoun the other sex; two objects; the remark naming a thing or putting; a person
    # named after a handover to another, or a remark naming a thing after a placement
    ("Give Tom the tape, she won it in the raffle.", None, DEPOT),
    ("Give Tom the tape and the gloves, he won it in the raffle.", None, DEPOT),
    ("Knife on the rack, Marco's got lemon on it.", None, KITCHEN),
    ("Give Noah the ruler, he'll put glue on it.", None, CLASSROOM),
    ("Knife to Lena, Marco's got fish scales on it.", None, KITCHEN),
    ("stapler in the box please sam has the red pen", None, OFFICE),
)

# -- lower case: a name with 's' run on, its apostrophe left out --------------------------------

test_lower = CASES.test(
    ("glue stick to zoe and noahs after the ruler", "glue>C & ruler>B", CLASSROOM),
    ("knife over to marco and lenas after the lemon", "knife>A & lemon>B", KITCHEN),
    # a text that writes its apostrophes; a name of no one in the scene
    ("glue stick to zoe and noahs' after the ruler", None, CLASSROOM),
    ("glue stick to zoe and bobs after the ruler", None, CLASSROOM),
)


# -- a text with no marks, in lower case: ', ' put back before a remark run on (he's, she's,
# we're) and before a clause said again without its verb ----------------------------------------

test_run_on = CASES.test(
    ("tape for tom please hes at bay four", "tape>B", DEPOT),
    ("put the stapler in the box please were off to the pub quiz", "stapler@box", OFFICE),
    (
        "zoe could do with the ruler shes only just back from netball and shes shattered",
        "ruler>C",
        CLASSROOM,
    ),
    ("marco gets the knife for his prep lena the lemon", "knife>A & lemon>B", KITCHEN),
    ("marco gets the knife lena the lemon shes on her break", "knife>A & lemon>B", KITCHEN),
    # the pronoun the other sex; the remark naming a thing of the scene, or negating; two people
    # before it; the gapped clause a thing, or a surface
    ("tape for tom please shes at bay four", None, DEPOT),
    ("tape for tom please hes at the pallet", None, DEPOT),
    ("tape for tom please hes not at bay four", None, DEPOT),
    ("tape for tom and mia please hes at bay four", None, DEPOT),
    ("give bob the cup and the crisps were stale", None, CELL),
    ("marco gets the knife for his prep lemon the salt", None, KITCHEN),
    ("marco gets the knife for his prep lena the rack", None, KITCHEN),
)

# -- questions: 'P's been stood there for ages after his <doing>.' before the request; ', do you
# reckon,' between a question and a remark ------------------------------------------------------

test_questions = CASES.test(
    (
        "Noah's been stood there for ages after his spelling test. Pass him the ruler, would you.",
        "ruler>B",
        CLASSROOM,
    ),
    (
        "Could Zoe have the globe, do you reckon, she wants it for her project?",
        "globe>C",
        CLASSROOM,
    ),
    # the pronoun the other sex
    (
        "Noah's been stood there for ages after her spelling test. Pass him the ruler, would you.",
        None,
        CLASSROOM,
    ),
    ("Could Zoe have the globe, do you reckon, he wants it for his project?", None, CLASSROOM),
)

# -- old rules said more widely: session 37's 'after his <doing>' with 'ever since'; 'bonny' a
# word of address (session 14's closing stretch) ------------------------------------------------

EVER = PhrasingCases()
test_ever_since = EVER.test(
    ("Omar's been craving the banana ever since the egg judging.", "banana>B", LAB),
    ("Mrs Khan has been wanting the magazine ever since her physio.", "magazine>C", WARD),
    # the doing naming a thing of the scene; two people
    ("Omar's been craving the banana ever since the spoon judging.", None, LAB),
    ("Omar and Dana have been craving the banana ever since the egg judging.", None, LAB),
)
BONNY = PhrasingCases()
test_bonny = BONNY.test(
    ("Pass Marco the knife, bonny lad.", "knife>A", KITCHEN),
    ("If you'd be so kind, hand Zoe the globe, bonny lass.", "globe>C", CLASSROOM),
    # 'bonny' naming a thing of the scene ('the bonny one')
    ("Pass Marco the knife, bonny one.", None, KITCHEN),
)


BEFORE = PhrasingCases()
test_before_asked = BEFORE.test(
    # session 32's closing 'before …' after a request said as a question
    ("Could Mrs Khan have the jug before she heads off to her physio?", "jug>C", WARD),
    ("Could Omar have the spoon before he nips off to his lecture?", "spoon>B", LAB),
    # the pronoun the other sex; a surface in it
    ("Could Mrs Khan have the jug before he heads off to his physio?", None, WARD),
    ("Could Mrs Khan have the jug before the trolley goes?", None, WARD),
)


def test_before_asked_refused_before(monkeypatch: pytest.MonkeyPatch) -> None:
    old = _normalise2._BEFORE32.pattern.replace("[.!?]?", "[.!]?")
    BEFORE.refused_with(_normalise2, "_BEFORE32", re.compile(old, re.I), monkeypatch)


def test_ever_since_refused_before(monkeypatch: pytest.MonkeyPatch) -> None:
    old = _normalise4._AFTER_DOING37.pattern.replace("(?:ever )?since", "since")
    EVER.refused_with(_normalise4, "_AFTER_DOING37", re.compile(old, re.I), monkeypatch)


def test_bonny_refused_before(monkeypatch: pytest.MonkeyPatch) -> None:
    BONNY.refused_with(_normalise1, "_ADDRESS", _normalise1._ADDRESS - {"bonny"}, monkeypatch)


def test_doubt_which() -> None:
    # a choice the speaker cannot say the answer to: refused naming both readings
    assert_refused(
        "Zoe wants the ruler or the glue stick, I can't remember which.",
        CLASSROOM,
        match=r"ruler.*glue",
    )
    assert_refused("Give Marco the knife or the tongs, not sure which.", KITCHEN, match="tongs")
    # a choice left to the robot reads as one
    assert_reads("Zoe wants the ruler or the glue stick, whichever.", "ruler>C | glue>C", CLASSROOM)


def test_usual() -> None:
    # 'her usual': each object of the scene named as a reading
    assert_refused("Mrs Khan asked for her usual.", WARD, match=r"jug.*magazine")
    assert_refused("tom wants his usual please", DEPOT, match=r"box_small.*box_large")


def test_readings_named_before(monkeypatch: pytest.MonkeyPatch) -> None:
    # without the checks the refusals named no reading
    monkeypatch.setattr(_rewrites39, "doubt_which39", lambda _t, _l: None)
    monkeypatch.setattr(_rewrites39, "usual39", lambda _t, _l: None)
    # session 50 (lead): `forgot_which50l` names a forgotten choice's readings too
    monkeypatch.setattr(
        offline,
        "_REFUSALS",
        tuple(r for r in offline._REFUSALS if r is not _rewrites50l.forgot_which50l),
    )
    with pytest.raises(GroundingError) as refused:
        parse_instruction(
            "Zoe wants the ruler or the glue stick, I can't remember which.", CLASSROOM
        )
    assert "ruler" not in str(refused.value)
    with pytest.raises(GroundingError) as refused:
        parse_instruction("Mrs Khan asked for her usual.", WARD)
    assert "magazine" not in str(refused.value)


def test_dyou_think() -> None:
    # session 33's 'Do you think P could …?' said with "D'you" (its pattern had read "d'you you")
    assert_reads("D'you think Jess could get the hammer?", "hammer>B", WORKSHOP)
    assert_reads("D'ya reckon Lena can have the lemon?", "lemon>B", KITCHEN)


def test_dyou_think_refused_before(monkeypatch: pytest.MonkeyPatch) -> None:
    old = _normalise2.re.compile(
        r"(?:^|(?<=[.!?]\s))(?:do|d'you|don't) you (?:think|reckon|suppose) (?:that )?(?P<p>[A-Z]"
        r"[^,.;!?]*?) (?P<m>could|can|might) (?=(?:have|get|take|use)\b)",
        _normalise2._F,
    )
    cases = PhrasingCases()
    cases.read.append(("D'you think Jess could get the hammer?", "hammer>B", WORKSHOP))
    cases.refused_with(_normalise2, "_THINK_COULD33", old, monkeypatch)


def test_refused_without_the_rules(monkeypatch: pytest.MonkeyPatch) -> None:
    # 12s's remarks said without punctuation (sessions 39 and 40) read _run_on39's kind too
    CASES.refused_without(
        (
            *normalise._STEPS39,
            *normalise._STEPS39S_FIRST,
            *normalise._STEPS39S,
            *normalise._STEPS40S_FIRST,
            # session 51 (12s): its run-on rule says these remarks with their stops too
            _rewrites51s._run_on51s,
        ),
        monkeypatch,
    )


_ = (CELL, TWO)
