"""Session-44 phrasings of issue 12 (engineer 12r): negation and exclusion, corrections, counts,
choices and distributions, each as a family; docs/grounding.md, "Session 44 (engineer 12r)". Each
rule with sentences of its kind in other words and scenes than blind42's, lower case and a typo,
and near forms that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites44r
from tests.grounding.helpers import (
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
)

CASES = PhrasingCases()

# -- corrections -----------------------------------------------------------------------------------

test_reason_fix = CASES.test(
    # _reason_fix44r: a cue, maybe a reason, then what takes the place of the request's person,
    # place or thing
    ("Salt to Marco. Ooh wait, he's got some, make it Lena.", "salt>B", KITCHEN),
    (
        "Tongs for Lena; hang on, my mistake, she's off today, they're for Marco.",
        "tongs>A",
        KITCHEN,
    ),
    ("Tongs to Lena. No hang on, she's got her own, Marco should have them.", "tongs>A", KITCHEN),
    ("Tongs to Lena, correction, Marco's at the grill so they're his.", "tongs>A", KITCHEN),
    (
        "Put the lemon on the counter, oh hang about, it's sticky, the rack's better.",
        "lemon@rack",
        KITCHEN,
    ),
    ("Stapler to Sam, correction, Priya's filing so it's hers.", "stapler>A", OFFICE),
    ("Jug for Mr Lee. Wait, he's asleep, make it Mrs Khan.", "jug>C", WARD),
    ("salt to marco. ooh wait, he's got some, make it lena.", "salt>B", KITCHEN),
    # near forms: no cue that takes it back, two requests, a reason that names more, 'and', a
    # pronoun that is not the person
    ("Salt to Marco. Oh, he's got some, make it Lena.", None, KITCHEN),
    ("Salt to Marco and the knife to Lena. Wait, he's got some, make it Mr Novak.", None, KITCHEN),
    ("Salt to Marco. Wait, the knife's there too, make it Lena.", None, KITCHEN),
    ("Salt to Marco. Wait, he's got some, and make it Lena.", None, KITCHEN),
    ("Tongs to Lena, correction, Marco's at the grill so they're hers.", None, KITCHEN),
)


# -- negation and exclusion ------------------------------------------------------------------------

test_no_for = CASES.test(
    # _no_for44r: a thing P is not to have, then what P is to have
    ("No salt for Mr Novak, pass him the lemon instead.", "lemon>C", KITCHEN),
    ("No teddy for Lily, give her the beaker instead.", "beaker>A", NURSERY),
    ("No stapler for Sam, hand him the notebook instead.", "notebook>B", OFFICE),
    ("no salt for mr novak, pass him the lemon instead", "lemon>C", KITCHEN),
    # near forms: another person, the same thing, a pronoun that is not the person
    ("No salt for Mr Novak, pass Lena the lemon instead.", None, KITCHEN),
    ("No salt for Mr Novak, pass him the salt instead.", None, KITCHEN),
    ("No salt for Mr Novak, pass her the lemon instead.", None, KITCHEN),
)

test_not_aside = CASES.test(
    # _not_aside44r: who does not get it, said as an aside after the person who does
    ("Marco, not the new lad on the pass, gets the tongs.", "tongs>A", KITCHEN),
    ("Lena, not the chap from table six, should have the lemon.", "lemon>B", KITCHEN),
    ("Mrs Khan, not the lady in the next bed, gets the jug.", "jug>C", WARD),
    ("marco, not the new lad on the pass, gets the tongs", "tongs>A", KITCHEN),
    # near forms: the aside names a thing, or the person
    ("Marco, not the knife, gets the tongs.", None, KITCHEN),
    ("Marco, not Marco, gets the tongs.", None, KITCHEN),
)

test_said_leave = CASES.test(
    # _said_leave44r: a person saying to leave a thing, then what they are after
    ("Lena says to skip the salt, she's only after the lemon.", "lemon>B", KITCHEN),
    ("Mr Lee said to leave the jug, he's only after the magazine.", "magazine>B", WARD),
    ("Tom says to skip the tape, he's only after the gloves.", "gloves>B", DEPOT),
    ("tom says to skip the tape, he's only after the gloves", "gloves>B", DEPOT),
    # near forms: a pronoun that is not the person, a place
    ("Mr Lee said to leave the jug, she's only after the magazine.", None, WARD),
    ("Lena said to leave the salt on the counter.", None, KITCHEN),
)

test_skip_and = CASES.test(
    # _skip_and44r: "skip X and <request>", maybe after a remark about the request's person
    ("Lena's not hungry, so skip the lemon and pass her the salt.", "salt>B", KITCHEN),
    ("Mr Lee's not thirsty, so forget the jug and give him the magazine.", "magazine>B", WARD),
    ("Skip the tape and give Tom the gloves.", "gloves>B", DEPOT),
    ("mr lee's not thirsty, so forget the jug and give him the magazine", "magazine>B", WARD),
    # near forms: the thing skipped is the one given, a pronoun that is not the person, more after
    ("Lena's not hungry, so skip the lemon and pass her the lemon.", None, KITCHEN),
    ("Mr Lee's not thirsty, so forget the jug and give her the magazine.", None, WARD),
    ("Skip the lemon and pass Lena the salt, then the knife.", None, KITCHEN),
)


def test_rewrites_read_them(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each case that reads is read by these rules: refused without them."""
    CASES.refused_without((*_rewrites44r._STEPS44R_FIRST, *_rewrites44r._STEPS44R), monkeypatch)


# -- wrong readings put right ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # 12c's session-43 fuzz: _not_list_first42r took "the lemon" after a bare comma as a
        # second thing left out and read tongs>A; the lemon takes the knife's place
        ("Not the knife, the lemon, oh, and the tongs, for Marco", "lemon>A & tongs>A", KITCHEN),
        ("Not the hammer, the torch, oh, and the drill, for Kofi", "torch>A & drill>A", WORKSHOP),
        ("Not the spoon, the sponge, oh, and the banana, for Omar.", "sponge>B & banana>B", LAB),
        # a list left out, joined by 'nor' / 'and not', is still left out
        ("Not the knife, nor the lemon; the tongs for Marco.", "tongs>A", KITCHEN),
    ],
)
def test_not_then_thing(text: str, want: str, scene: object) -> None:
    assert_case(text, want, scene)  # type: ignore[arg-type]
