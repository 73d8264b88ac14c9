"""Phrasings the session-43 lead rules refuse or read (docs/grounding.md, Session 43 (lead))."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites43l
from hltl.world.scene import Scene
from tests.grounding.helpers import CELL, OFFICE, WORKSHOP, assert_case, assert_refused, tree

# -- another person's thing named beside the one who gets it (_rewrites43l.owned_other43l): 12c's
# `said` fuzz found "Carol gets Bob's crisps." read chips>B (the owner for the subject); refused
# now naming both people, as session 7 refuses "Give Bob Carol's bottle"

OWNER_OTHER = [
    ("Carol gets Bob's crisps.", CELL, ("Person C", "Person B")),
    ("Could Carol have Bob's cup?", CELL, ("Person C", "Person B")),
    ("Let Carol have Bob's apple.", CELL, ("Person C", "Person B")),
    ("carol wants bob's crisps", CELL, ("Person C", "Person B")),
    ("Carol should get Bob's crisps, not the bottle.", CELL, ("Person C", "Person B")),
    ("Carol gets Bob's cup and Bob gets the crisps.", CELL, ("Person C", "Person B")),
    ("Sam can borrow Priya's stapler.", OFFICE, ("Person B", "Person A")),
    ("Priya needs Sam's notebook.", OFFICE, ("Person A", "Person B")),
    ("Kofi can borrow Jess's hammer.", WORKSHOP, ("Person A", "Person B")),
    # the thing in three words (12c's final sweep: "… Kofi's tin of screws" read for Kofi)
    ("Jess can borrow Kofi's tin of screws.", WORKSHOP, ("Person B", "Person A")),
    ("Priya would like Sam's notebok.", OFFICE, ("Person A", "Person B")),
]
# refused by the grammar too (two people in one clause), now with both named
GIVEN = [("Give Sam Priya's notebook, please.", OFFICE, ("Person B", "Person A"))]


@pytest.mark.parametrize(("text", "scene", "people"), OWNER_OTHER + GIVEN)
def test_owner_beside_another_refused(text: str, scene: Scene, people: tuple[str, str]) -> None:
    assert_refused(text, scene, match=f"could go to {people[0]}.* or to {people[1]}")


@pytest.mark.parametrize(("text", "scene", "people"), OWNER_OTHER)
def test_owner_beside_another_read_without(
    text: str, scene: Scene, people: tuple[str, str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without the check the grammar reads each one (the owner for the one who gets it, or the
    subject): the check is what refuses it."""
    monkeypatch.setattr(_rewrites43l, "owned_other43l", lambda t, lexicon: None)
    assert tree(text, scene) is not None


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # the owner is the one who gets it, or the possessive says whom it is for: as before
        ("Bob wants Bob's crisps.", "chips>B", CELL),
        ("Do Carol's bottle first and then Bob's chips", "bottle>C ; chips>B", CELL),
        ("Sam wants his notebook.", "notebook>B", OFFICE),
        ("Take Bob's cup back to him.", "cup>B", CELL),
        # a state ('has') or a doer: not this check's
        ("Carol likes Bob's cup.", None, CELL),
        ("Carol takes Bob's cup to the shelf.", None, CELL),
    ],
)
def test_owner_kept(text: str, want: str | None, scene: Scene) -> None:
    assert_case(text, want, scene)


# -- a correction to a place said as a reason ('…, sorry, it's meant to go on the shelf, thanks.'):
# 12c's fuzz found the first handover read with anything after it (`_cue_reason28r` and
# `_cue_reason29r` took the place for a reason); a scene place in the 'reason' keeps it now
@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Cup over to Bob, sorry, it's meant to go on the shelf, thanks.", CELL),
        ("Give Carol the cup, sorry, it's meant to go on the shelf, thanks.", CELL),
        ("Hammer over to Kofi, sorry, it's meant to go in the locker, thanks.", WORKSHOP),
        ("Give Jess the torch, sorry, it's meant to go in the locker, cheers.", WORKSHOP),
    ],
)
def test_place_in_a_correction_is_no_reason(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


def test_a_reason_without_a_place_still_comes_off() -> None:
    assert_case("Give the bottle to Bob, no wait, Bob's got one, to Alice", "bottle>A", CELL)
