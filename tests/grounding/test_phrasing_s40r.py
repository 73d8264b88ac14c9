"""Session-40 phrasings of issue 12 (engineer 12r): blind38's choices, counts, negation,
exclusions and corrections, by kind; docs/grounding.md, "Session 40 (engineer 12r)". Each rule
with sentences of its kind in other words and scenes, and near forms that must stay refused."""

from __future__ import annotations

import re

import pytest

from hltl.errors import GroundingError
from hltl.grounding import (
    _rewrites40r,
    _rewrites42r,
    _rewrites43r,
    _rewrites44r,
    _rewrites54r,
    _rewrites55s,
    _rewrites56s,
    offline,
)
from hltl.grounding._normalise4 import _placed_then34r, _where_was_i36r
from hltl.world.scene import Scene
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
)

CASES = PhrasingCases()


# -- negation and exclusion -----------------------------------------------------------------------


test_contrast = CASES.test(
    # "X's not for P, it's Q's / Q's the one who asked / Q wants it": X is for Q
    ("The knife's not for Lena, it's Marco's.", "knife>A", KITCHEN),
    ("The scanner isn't for Tom, Mia's the one who asked.", "scanner>A", DEPOT),
    ("The jug's not for Mr Lee; Mrs Khan wants it.", "jug>C", WARD),
    ("The ruler is not for Zoe, Noah's the one who needs it.", "ruler>B", CLASSROOM),
    # one person twice, no second person, a surface, a thing: refused
    ("The knife's not for Lena, it's Lena's.", None, KITCHEN),
    ("The knife's not for Lena.", None, KITCHEN),
    ("The knife's not for Lena, the counter's the one who asked.", None, KITCHEN),
    ("The knife's not for Lena, it's the lemon's.", None, KITCHEN),
)

test_gone_off = CASES.test(
    # "P's gone (right) off X (since …)", "P says no X for her", "P's had enough of X": P doesn't
    # want X, dropped beside a request that names neither it nor 'it'
    ("Sam's gone off the stapler, it's the notebook he wants.", "notebook>B", OFFICE),
    ("Emma says no spoon for her, it's the sponge she's after.", "sponge>C", LAB),
    ("Mr Lee's had enough of the magazine, take him the jug.", "jug>B", WARD),
    (
        "Kofi's gone right off the hammer since the shelving job, pass him the drill.",
        "drill>A",
        WORKSHOP,
    ),
    # nothing asked, the same thing asked or 'it', no person: refused
    ("Sam's gone off the stapler.", None, OFFICE),
    ("Sam's gone off the stapler, give it to him.", None, OFFICE),
    ("Sam's gone off the stapler, give him the stapler.", None, OFFICE),
    ("The desk's gone off the stapler, pass Sam the notebook.", None, OFFICE),
    ("Emma says no spoon for her.", None, LAB),
)

test_no_need = CASES.test(
    # "No need to ask (check), <request>", "Don't bother asking, …": the request
    ("No need to ask, the lemon's for Lena.", "lemon>B", KITCHEN),
    ("No need to check, give Tom the tape.", "tape>B", DEPOT),
    ("Don't bother asking, the bib goes to Ava.", "bib>C", NURSERY),
    # nothing asked, a request that is not to be done: refused
    ("No need to ask.", None, KITCHEN),
    ("No need to give Lena the lemon, the knife's for her.", None, KITCHEN),
)

test_leave_first = CASES.test(
    # "Leave X (forget about, skip X), just <request of another object>": the request
    ("Leave the stapler, just pass Sam the notebook.", "notebook>B", OFFICE),
    ("Forget about the magazine, just take Mrs Khan the jug.", "jug>C", WARD),
    ("Skip the hammer, just put the torch on the bench.", "torch@bench", WORKSHOP),
    # 'it', the same object, 'with P', no object: refused
    ("Leave the stapler, just pass it to Sam.", None, OFFICE),
    ("Leave the stapler, just pass Sam the stapler.", None, OFFICE),
    ("Leave the stapler with Sam.", None, OFFICE),
    ("Leave the desk, just pass Sam the notebook.", None, OFFICE),
)

test_dont_but = CASES.test(
    # "Don't put X on S, put Y on it (there)": Y on S
    ("Don't put the knife on the counter, put the lemon on it.", "lemon@counter", KITCHEN),
    ("Don't stick the globe on the shelf, put the ruler on it instead.", "ruler@shelf", CLASSROOM),
    ("Do not put the drill in the locker, pop the torch in there.", "torch@locker", WORKSHOP),
    # the same object, nothing asked: refused
    ("Don't put the knife on the counter, put the knife on it.", None, KITCHEN),
    ("Don't put the knife on the counter.", None, KITCHEN),
)

test_neither_nor = CASES.test(
    # "neither the A one nor the B one, (it's) the other one": the one left of a kind of three
    (
        "Sam's pen is neither the blue one nor the black one, it's the other one, pass it over.",
        "pen_red>B",
        OFFICE,
    ),
    (
        "Tom wants neither the small one nor the large one, just the other one.",
        "box_medium>B",
        DEPOT,
    ),
    ("Not the red one or the blue one, the other one, to Priya.", "pen_black>A", OFFICE),
    # a kind of two (no other one left), the same one twice: refused
    (
        "Marco's plate is neither the white one nor the blue one, it's the other one, pass it "
        "over.",
        None,
        KITCHEN,
    ),
    (
        "Sam's pen is neither the blue one nor the blue one, it's the other one, pass it over.",
        None,
        OFFICE,
    ),
)


# -- choice idioms --------------------------------------------------------------------------------


test_indifferent = CASES.test(
    # "P's not fussy (…), he'll take any / either / whichever …": P will take …
    (
        "Jess isn't fussy, she'll take either spanner.",
        "spanner_small>B | spanner_large>B",
        WORKSHOP,
    ),
    (
        "Mr Novak's not picky after the long drive, he'll have any one of the plates.",
        "plate_white>C | plate_blue>C",
        KITCHEN,
    ),
    (
        "Tom is not bothered, he'll take whichever box.",
        "box_small>B | box_medium>B | box_large>B",
        DEPOT,
    ),
    # "one of them, doesn't matter which, …" (two people): either of them
    ("One of them, doesn't matter which, should get the stapler.", "stapler>A | stapler>B", OFFICE),
    # "one of the <things>, X or Y": the choice
    ("Hand Lena one of the utensils, the knife or the tongs.", "knife>B | tongs>B", KITCHEN),
    # "fine / happy with either, X or Y"
    ("Ava's happy with either, the teddy or the bib.", "teddy>C | bib>C", NURSERY),
    ("Sam's fine with either, the notebook or the stapler.", "notebook>B | stapler>B", OFFICE),
    # a pronoun P cannot be, a fussiness about a thing, no choice, another person: refused
    ("Mr Novak's not fussy, she'll take either plate.", None, KITCHEN),
    ("Jess isn't fussy about the drill, she'll take either spanner.", None, WORKSHOP),
    ("One of them, doesn't matter which, should get the lemon.", None, KITCHEN),
    ("Hand Lena one of the utensils, the knife and the tongs.", None, KITCHEN),
)

test_whoever = CASES.test(
    # "to whoever's nearest (free, …), P or Q": P or Q
    ("The lemon can go to whoever's closest, Marco or Lena.", "lemon>A | lemon>B", KITCHEN),
    ("Give the stapler to whoever is free, Priya or Sam.", "stapler>A | stapler>B", OFFICE),
    # "whichever <kind>'s free (going, clean), A or B": the A <kind> or the B <kind>
    (
        "Jess can take whichever spanner's free, small or large.",
        "spanner_small>B | spanner_large>B",
        WORKSHOP,
    ),
    (
        "Mr Novak gets whichever plate is clean, white or blue.",
        "plate_white>C | plate_blue>C",
        KITCHEN,
    ),
    # a surface, no choice, a thing of the scene picking it, no such objects: refused
    ("The lemon can go to whoever's closest, Marco or the counter.", None, KITCHEN),
    ("The lemon can go to whoever's closest.", None, KITCHEN),
    ("The lemon can go to whoever's by the lemon, Marco or Lena.", None, KITCHEN),
    ("Jess can take whichever spanner's free, small or red.", None, WORKSHOP),
    ("Jess can take whichever drill's free, small or large.", None, WORKSHOP),
)


# -- counts and distributions ---------------------------------------------------------------------


test_counts = CASES.test(
    # "the pair of them / the two of them one each: …"
    (
        "Give the pair of them one each: the stapler to Sam, the notebook to Priya.",
        "stapler>B & notebook>A",
        OFFICE,
    ),
    (
        "Give the two of them one each: the drill to Kofi, the torch to Jess.",
        "drill>A & torch>B",
        WORKSHOP,
    ),
    # "Two things for two people: <list>"
    (
        "Two things for two people: Sam's the stapler, Priya's the notebook.",
        "stapler>B & notebook>A",
        OFFICE,
    ),
    (
        "Three things for three people: the jug to Ruth, the magazine to Mr Lee, the pills to "
        "Mrs Khan.",
        "jug>A & magazine>B & pills>C",
        WARD,
    ),
    # "P needs supplies (for …): X and Y"
    ("Lena needs supplies: the knife and the tongs.", "knife>B & tongs>B", KITCHEN),
    (
        "Kofi needs a few things for the shelving job: the drill and the screws.",
        "drill>A & screws>A",
        WORKSHOP,
    ),
    ("Mrs Khan wants some bits: both the jug and the magazine.", "jug>C & magazine>C", WARD),
    # "We've only got the one X, and it's P's", "There's a single X, and P …it…"
    ("We've only got the one lemon, and it's Lena's.", "lemon>B", KITCHEN),
    ("There's just the one thermometer, and Ruth's the one who needs it.", "thermometer>A", WARD),
    ("There's a single hammer, so Jess gets it.", "hammer>B", WORKSHOP),
    # "P's taking X (to <elsewhere>), so hand them over": P gets X
    (
        "Kofi's taking the drill and the screws to the allotment, so hand them over.",
        "drill>A & screws>A",
        WORKSHOP,
    ),
    (
        "Lena's taking the knife and the tongs to the car, so hand them over.",
        "knife>B & tongs>B",
        KITCHEN,
    ),
    # the pair without 'one each', counts that do not fit the list, a person in the list, a
    # kind of two, a surface's, nothing said of it, two things, a pronoun he cannot be, a place
    # of the scene, 'both items' of five: refused
    ("Give the pair of them the stapler.", None, OFFICE),
    ("Two things for two people: Sam's the stapler.", None, OFFICE),
    ("Three things for two people: Sam's the stapler, Priya's the notebook.", None, OFFICE),
    ("Lena needs supplies: the knife and Marco.", None, KITCHEN),
    ("Lena needs supplies for the counter: the knife and the tongs.", None, KITCHEN),
    ("We've only got the one plate, and it's Lena's.", None, KITCHEN),
    ("We've only got the one lemon, and it's the counter's.", None, KITCHEN),
    ("We've only got the one lemon.", None, KITCHEN),
    (
        "There's a single lemon, and Lena wants it and the knife too, give them to her.",
        None,
        KITCHEN,
    ),
    ("Mr Novak is taking the salt, so give it to her.", None, KITCHEN),
    ("Mr Novak is taking the salt to the counter, so hand it over.", None, KITCHEN),
    ("Sam's taking both items, so hand them over.", None, OFFICE),
)


# -- corrections ----------------------------------------------------------------------------------


test_corrections = CASES.test(
    # the speaker's self-blame inside a correction ("wrong name", "my mistake", …)
    ("The tongs to Marco, no, sorry, wrong name, they're for Lena.", "tongs>B", KITCHEN),
    ("The gloves to Tom, sorry, my mistake, they're Mia's.", "gloves>A", DEPOT),
    ("The jug to Ruth, no, correction, it's Mrs Khan's.", "jug>C", WARD),
    ("The screws for Kofi, sorry, I'm all over the place, they're for Jess.", "screws>B", WORKSHOP),
    # "P'd rather the X"
    ("Lena's having the knife, hang on, no, she'd rather the tongs.", "tongs>B", KITCHEN),
    ("Sam would rather the notebook.", "notebook>B", OFFICE),
    # "…, no wait, he asked for the X"
    ("The red book to Noah, no wait, he asked for the green one.", "book_green>B", CLASSROOM),
    ("The white plate to Lena, no, she asked for the blue one.", "plate_blue>B", KITCHEN),
    # a claim on a thing: "P put her name on it", "P's got dibs on X", "P bagged it (at …)"
    ("The knife's for Marco, no, Lena put her name on it.", "knife>B", KITCHEN),
    ("Sam's got dibs on the stapler.", "stapler>B", OFFICE),
    ("The torch is for Kofi, sorry, Jess bagged it at the car boot sale.", "torch>B", WORKSHOP),
    # "…, no, they're P's" (the things)
    ("The chips are for Bob, no, they're Carol's.", "chips>C", CELL),
    ("The gloves to Tom, sorry, my mistake, they're Mia's.", "gloves>A", DEPOT),
    # nothing after the blame, 'rather' before a clause, 'it' after 'asked for', a claim
    # of a surface or at a place of the scene, whose said of a surface: refused
    ("The lemon to Marco, no, sorry, wrong name.", None, KITCHEN),
    ("Alice would rather the cup went to Bob.", None, CELL),
    ("The red book to Noah, no wait, he asked for it.", None, CLASSROOM),
    ("The desk's got dibs on the stapler.", None, OFFICE),
    ("Sam's got dibs on the stapler at the desk.", None, OFFICE),
    ("The chips are for Bob, no, they're the shelf's.", None, CELL),
)


def test_refused_without_these_steps(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence these rules read is refused with the session-40 (12r) steps taken out: each
    rule is what reads it."""
    # session 42 (12r): its rules of the same families read these too
    # session 43 (12r): its rules of the same families read these too
    CASES.refused_without(
        (
            *_rewrites40r._STEPS40R,
            *_rewrites42r._STEPS42R,
            *_rewrites43r._STEPS43R_FIRST,
            *_rewrites43r._STEPS43R,
            # session 44 (12r): its rules of the same families read some of these too
            *_rewrites44r._STEPS44R_FIRST,
            *_rewrites44r._STEPS44R,
            # session 54 (12r; lead at the merge): '…, no wait, he asked for the Y' reads it too
            _rewrites54r._he_said54r,
            # session 55 (12s): 'the green one' after 'the red book' said 'the green book' reads it
            _rewrites55s._bare_adj55s,
            # session 56 (12s): "P's gone off the X, …" said "P doesn't want the X, …" reads it
            _rewrites56s._off_the56s,
        ),
        monkeypatch,
    )


def test_a_sentence_opening_correction_keeps_its_blame() -> None:
    """A correction opening a sentence is left to session 33's rule (it reads the whole
    sentence after it, the blame in it), as before."""
    assert_reads("The lemon to Marco. Sorry, my mistake, it's for Lena.", "lemon>B", KITCHEN)


# old rules widened where they are (their own steps taken out, these are refused)
OLD = PhrasingCases()

test_where_was_i = OLD.test(
    # session 36's "the, sorry, where was I, the bottle": 'oh' or 'ah' before it, "what's its
    # name", "what's the word"
    ("Pass Lena the, oh, what's it called, the tongs.", "tongs>B", KITCHEN),
    ("Give Ava the, erm, what's its name, the teddy.", "teddy>C", NURSERY),
    ("Take Ruth the, ah, what's the word, the thermometer.", "thermometer>A", WARD),
    # nothing found, another thing found after it: refused
    ("Pass Lena the, oh, what's it called.", None, KITCHEN),
    ("Pass Lena the, oh, what's it called, the counter.", None, KITCHEN),
)

test_placed_then = OLD.test(
    # session 34's "Crisps on the shelf, actually no, give them to Bob": 'hang on' / 'hold on',
    # 'I meant', 'up on'
    ("Teddy on the mat, oh, hang on, I meant hand it to Ava.", "teddy>C", NURSERY),
    ("The jug up on the trolley, hold on, I meant give it to Ruth.", "jug>A", WARD),
    # a surface the scene does not have (session 34), no new request: refused
    ("Teddy on the table, oh, hang on, I meant hand it to Ava.", None, NURSERY),
    ("Teddy on the mat, oh, hang on, I meant it.", None, NURSERY),
)


def test_old_rules_read_these(monkeypatch: pytest.MonkeyPatch) -> None:
    """The widened forms are read by the old rules: with them taken out, refused."""
    OLD.refused_without((_where_was_i36r, _placed_then34r), monkeypatch)


# -- refusals that name the readings --------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "scene", "readings"),
    [
        ("One of them's after the stapler, can't recall who.", OFFICE, ("Person A", "Person B")),
        ("One of the two needs the drill.", WORKSHOP, ("Person A", "Person B")),
        (
            "Give Lena the knife, no, the other thing, or maybe not, I'm not sure now.",
            KITCHEN,
            ("knife", "lemon", "tongs"),
        ),
        (
            "Pass Sam the stapler, sorry, the notebook, I don't know.",
            OFFICE,
            ("stapler", "notebook"),
        ),
        ("Sam. The stapler. Or the notebook. Whatever he said.", OFFICE, ("stapler", "notebook")),
    ],
)
def test_refusals_name_the_readings(text: str, scene: Scene, readings: tuple[str, ...]) -> None:
    """ "One of them …" names each person it could mean; a doubted correction and a choice left to
    someone else's word name each object they could mean."""
    with pytest.raises(GroundingError) as refused:
        offline.parse_instruction(text, scene)
    for reading in readings:
        assert reading in str(refused.value)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("One of them's after the stapler, can't recall who.", OFFICE),
        ("Give Lena the knife, no, the other thing, or maybe not, I'm not sure now.", KITCHEN),
    ],
)
def test_refusals_name_nothing_without_these_rules(
    text: str, scene: Scene, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without the session-40 (12r) refusals these sentences are refused without their readings:
    the rules are what name them."""
    monkeypatch.setattr(
        offline,
        "_REFUSALS",
        tuple(r for r in offline._REFUSALS if r not in _rewrites40r.REFUSE40R),
    )
    with pytest.raises(GroundingError) as refused:
        offline.parse_instruction(text, scene)
    assert not re.search(r"could mean .*(?:Person B|lemon)", str(refused.value))


def test_choices_with_people_named_are_not_refused_as_no_one() -> None:
    """ "One of them, Priya or Sam, …" names its people: not the 'names no one' refusal."""
    with pytest.raises(GroundingError) as refused:
        offline.parse_instruction("One of them, Priya or Sam, wants the stapler.", OFFICE)
    assert "names no one" not in str(refused.value)
