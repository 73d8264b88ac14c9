"""Session-43 phrasings of issue 12 (engineer 12r): negation and exclusion, corrections, counts,
choices and distributions, and refusals that name their readings, each as a family;
docs/grounding.md, "Session 43 (engineer 12r)". Each rule with sentences of its kind in other
words and scenes than blind41's, lower case and a typo, and near forms that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites43r
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
)

CASES = PhrasingCases()

# -- corrections -----------------------------------------------------------------------------------

test_slip_cue = CASES.test(
    # _slip_cue43r: the speaker saying in words of its own that the request was wrong
    ("Noah gets the globe... hang on, I've mixed them up, it's Zoe's.", "globe>C", CLASSROOM),
    ("Stapler in the box, um, strike that, stapler to Sam.", "stapler>B", OFFICE),
    ("Tom gets the tape, erm, no, rewind, he's supposed to have the gloves.", "gloves>B", DEPOT),
    ("Teddy over to Ava; change of plans, it's Grandad who's having it.", "teddy>B", NURSERY),
    ("Salt to Marco, except that's not right, it's Lena who gets it.", "salt>B", KITCHEN),
    ("Jug for Ruth; oops, I'm looking at the wrong list, it's Mr Lee's.", "jug>B", WARD),
    ("Drill over to Kofi, my mistake, it's meant to go on the bench.", "drill@bench", WORKSHOP),
    ("Spoon for Dana, silly me, it's supposed to go in the sink.", "spoon@sink", LAB),
    ("spoon for dana, silly me, it's supposed to go in the sink", "spoon@sink", LAB),
    ("Spoon for Dana, sily me, it's supposed to go in the sink.", None, LAB),
    # near forms: a correction that takes the request back, or names nothing, stays refused
    ("Bottle to Alice. Actually, scrap that, nothing for now.", None, CELL),
    ("Noah gets the globe... hang on, I've mixed them up.", None, CLASSROOM),
    ("Noah gets the globe, my bad, it's the wrong one.", None, CLASSROOM),
)

test_said_wrong = CASES.test(
    # _said_wrong43r: "did I say X?" and "not X actually, Y" take back one name of the request
    ("Tom gets the scanner, er, did I say Tom? Mia, sorry.", "scanner>A", DEPOT),
    ("Marco needs the lemon, hmm, did I just say lemon? The salt, sorry.", "salt>A", KITCHEN),
    ("Give Zoe the ruler, well, not the ruler really, the scissors.", "scissors>C", CLASSROOM),
    ("Pass Kofi the hammer, well, not the hammer after all, the torch.", "torch>A", WORKSHOP),
    ("give zoe the ruler, well, not the ruler really, the scissors", "scissors>C", CLASSROOM),
    ("Give Zoe the ruler, well, not the ruler really, the sissors.", "scissors>C", CLASSROOM),
    # near forms: the name taken back is not in the request, or the two are of different kinds
    ("Tom gets the scanner, did I say Mia? Tom, sorry.", None, DEPOT),
    ("Give Zoe the ruler, well, not the globe really, the scissors.", None, CLASSROOM),
    ("Tom gets the scanner, did I say Tom? The tape, sorry.", None, DEPOT),
)

test_changed_order = CASES.test(
    # _changed_order43r: an earlier choice, then a change of it
    ("Mr Novak was down for the lemon but he's changed his order to the salt.", "salt>C", KITCHEN),
    ("Tom ordered the tape but he's switched to the gloves.", "gloves>B", DEPOT),
    ("tom ordered the tape but he's switched to the gloves", "gloves>B", DEPOT),
    ("Tom ordered the tape but he's switched to the glovse.", "gloves>B", DEPOT),
    # near forms: a pronoun that cannot be the person, or the same thing again
    ("Mr Novak was down for the lemon but she's changed her order to the salt.", None, KITCHEN),
    ("Tom ordered the tape but he's switched to the tape.", None, DEPOT),
)

test_other_way = CASES.test(
    # _other_way43r: one delivery, then the other way round said whole
    ("Scanner to Mia. No wait, it's the other way round: scanner to Tom.", "scanner>B", DEPOT),
    (
        "Magazine for Mr Lee; hmm, it's the other way about: magazine for Mrs Khan.",
        "magazine>C",
        WARD,
    ),
    # near forms: two deliveries, or the other way round names another thing
    (
        "Scanner to Mia and tape to Tom. Wait, it's the other way round: scanner to Tom.",
        None,
        DEPOT,
    ),
    ("Scanner to Mia. Wait, it's the other way round: tape to Tom.", None, DEPOT),
)

test_mid_sized = CASES.test(
    # _mid_sized43r: a size said with '-sized'
    ("Tom wants the big box; no, sorry, the mid-sized one.", "box_medium>B", DEPOT),
    ("Put the middle-sized spanner on the bench.", None, WORKSHOP),
)

# -- negation and exclusion ------------------------------------------------------------------------

test_not_idiom = CASES.test(
    # _not_idiom43r: not wanting said as an idiom, then what is wanted or where it goes
    ("Zoe turned her nose up at the glue; she'll have the scissors.", "scissors>C", CLASSROOM),
    ("Tom's gone right off the tape, so it's the gloves that go to him.", "gloves>B", DEPOT),
    (
        "Mrs Khan won't thank you for the magazine; bring her the thermometer.",
        "thermometer>C",
        WARD,
    ),
    ("Lena won't be having the lemon, it's going to Marco.", "lemon>A", KITCHEN),
    ("Omar can't abide the banana; give him the spoon.", "spoon>B", LAB),
    ("Omar's sick of the banana; it's the spoon he wants.", "spoon>B", LAB),
    ("Noah's had his turn with the globe, it's Zoe who gets it now.", "globe>C", CLASSROOM),
    ("Grandad is fed up with the teddy; pass him the wipes.", "wipes>B", NURSERY),
    ("Sam won't thank you for the red pen; hand him the black.", "pen_black>B", OFFICE),
    ("zoe turned her nose up at the glue; she'll have the scissors", "scissors>C", CLASSROOM),
    ("Zoe turned her nose up at the glue; she'll have the scisors.", "scissors>C", CLASSROOM),
    # near forms: the same thing wanted, a pronoun that is not the person, the thing to the same
    # person, or a list that holds the thing wanted
    ("Zoe turned her nose up at the glue; she'll have the glue.", None, CLASSROOM),
    ("Mrs Khan won't thank you for the magazine; bring him the thermometer.", None, WARD),
    ("Lena won't be having the lemon, it's going to Lena.", None, KITCHEN),
    ("Omar can't stand the banana.", None, LAB),
    ("Omar's sick of the banana; it's the banana he wants.", None, LAB),
)

test_never_asked = CASES.test(
    # _never_asked43r: "P never asked for X; Q did"
    ("Priya never asked for the stapler; Sam did.", "stapler>B", OFFICE),
    ("Emma didn't ask for the banana; Omar did, so take it over to him.", "banana>B", LAB),
    ("emma didn't ask for the banana; omar did, so take it over to him", "banana>B", LAB),
    ("Emma didn't ask for the bananna; Omar did, so take it over to him.", "banana>B", LAB),
    ("Emma didn't ask for the banana; Omar did, so take it over to her.", None, LAB),
    ("Priya never asked for the stapler; Priya did.", None, OFFICE),
)

test_no_need_wait = CASES.test(
    # _no_need_wait43r: urging the robot on
    ("No reason to hesitate, Jess gets the torch.", "torch>B", WORKSHOP),
    ("There's really no call to hesitate: the bib to Lily.", "bib>A", NURSERY),
    ("there's no need to wait, the tape to tom", "tape>B", DEPOT),
    ("No need to hang about.", None, WORKSHOP),
)

test_nothing_more = CASES.test(
    # _nothing_more43r: negations that only say the request is all there is
    ("Nothing fancy, only the salt to Lena and not a scrap besides.", "salt>B", KITCHEN),
    ("The glue to Zoe, not a thing more.", "glue>C", CLASSROOM),
    (
        "Nothing complicated: the jug on the trolley and not a single thing besides.",
        "jug@trolley",
        WARD,
    ),
    ("nothing fancy, only the salt to lena and not a scrap besides", "salt>B", KITCHEN),
    ("Nothing special, and nothing else.", None, KITCHEN),
)

test_bar_first = CASES.test(
    # _bar_first43r: 'bar' before "the lot", and everything put somewhere "only leave X"
    (
        "Barring the globe, the lot is Zoe's to keep.",
        "book_red>C & scissors>C & glue>C & ruler>C & book_green>C",
        CLASSROOM,
    ),
    (
        "Put the lot on the desk, only leave the pens where they are.",
        "notebook@desk & stapler@desk",
        OFFICE,
    ),
    (
        "put the lot on the desk, only leave the pens where they are",
        "notebook@desk & stapler@desk",
        OFFICE,
    ),
    ("Barring the kettle, the lot is Zoe's to keep.", None, CLASSROOM),
)

test_need_without = CASES.test(
    # _need_without43r: a need said by what cannot be done without the thing
    ("Marco can't finish the sauce without the lemon.", "lemon>A", KITCHEN),
    ("Without the scanner, Tom can't get through his round.", "scanner>B", DEPOT),
    ("Ruth says nothing else will do but the thermometer.", "thermometer>A", WARD),
    ("marco can't finish the sauce without the lemon", "lemon>A", KITCHEN),
    ("Marco can't finish the sauce without the lemmon.", "lemon>A", KITCHEN),
    # near forms: a pronoun that is not the person, another person in what is done
    ("Marco can't finish her sauce without the lemon.", None, KITCHEN),
    ("Marco can't finish Lena's sauce without the lemon.", None, KITCHEN),
)


def test_rewrites_read_them(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each case that reads is read by these rules: refused without them."""
    CASES.refused_without((*_rewrites43r._STEPS43R_FIRST, *_rewrites43r._STEPS43R), monkeypatch)


# read without these rules too: kept read (not in CASES: what `refused_without` asks is these
# rules')
test_read_already = PhrasingCases().test(
    (
        "Zoe had asked for the glue, but now she'd rather have the scissors.",
        "scissors>C",
        CLASSROOM,
    ),
    ("Put the medium-sized box on the pallet.", "box_medium@pallet", DEPOT),
    ("Omar can't stand the banana; give him the spoon.", "spoon>B", LAB),
    ("No need to hang about; Jess gets the torch.", "torch>B", WORKSHOP),
    ("Nothing special, just the salt to Lena and nothing else.", "salt>B", KITCHEN),
    (
        "Save for the knife and the tongs, everything else goes to Mr Novak.",
        "plate_white>C & lemon>C & salt>C & plate_blue>C",
        KITCHEN,
    ),
)
