"""Session-44 phrasings of issue 12 (engineer 12r): negation and exclusion, corrections, counts,
choices and distributions, each as a family; docs/grounding.md, "Session 44 (engineer 12r)". Each
rule with sentences of its kind in other words and scenes than blind42's, lower case and a typo,
and near forms that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites44r
from tests.grounding.helpers import (
    KITCHEN,
    LAB,
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
