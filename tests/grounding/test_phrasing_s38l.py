"""Session-38 phrasing of issue 12 (lead): a want of a placed thing said after the placement
(docs/grounding.md, "Session 38 (lead)").

"Put the cup on the shelf, Bob wants it (for his lunch)." had read as the placement and a
handover of the cup to Bob. With no verb of handing anywhere, the want is the reason for the
placement (it waits there for him) or a second request: refused naming both readings.

"The jug for Mr Lee, he's just had his tablets." (12r) read the tablets to Mr Lee too: what
someone 'has had' is a remark, never a request; a reading that hands it over is refused."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites55, _rewrites55s, offline
from tests.grounding.helpers import CELL, WARD, WORKSHOP, PhrasingCases, assert_case, tree

CASES = PhrasingCases()

test_a_want_of_the_placed_thing = CASES.test(
    # the want after the placement: refused (the reason, or a second request?)
    ("Put the cup on the shelf, Bob wants it for his lunch.", None, CELL),
    ("Cup on the shelf, Bob wants it.", None, CELL),
    ("Put the red mug on the counter, Carol needs it for her tea.", None, CELL),
    ("Pop the crisps on the table; Alice is after them.", None, CELL),
    ("Put the drill on the workbench, the apprentice could use it this afternoon.", None, WORKSHOP),
    ("Put the torch in the locker, Kofi wants it for the night shift.", None, WORKSHOP),
    ("Put the cup on the shelf, she wants it.", None, CELL),
    # a verb of handing said, another object wanted, or no want: read as before
    ("Put the cup on the shelf, then give it to Bob, he wants it.", "cup@shelf ; cup>B", CELL),
    ("Put the cup on the shelf, Bob wants the apple.", "cup@shelf & apple>B", CELL),
    ("Put the cup on the shelf and give Bob the apple.", "cup@shelf & apple>B", CELL),
    ("Put the cup on the shelf, please.", "cup@shelf", CELL),
    ("Bob wants the apple, give it to him.", "apple>B", CELL),
)


def test_the_refusal_names_both_readings() -> None:
    with pytest.raises(GroundingError) as refused:
        offline.parse_instruction("Put the cup on the shelf, Bob wants it for his lunch.", CELL)
    said = str(refused.value)
    assert "cup@shelf)" in said and "cup@shelf & cup>B" in said


def test_without_the_check_the_handover_is_read(monkeypatch: pytest.MonkeyPatch) -> None:
    # the check is what refuses: turned off, the old reading (placement and handover) comes back
    monkeypatch.setattr(offline, "_placed_wanted38l", lambda text, node, lexicon: None)
    # session 55 (lead, at the merge): 12's _placed_wanted55 (the run-on form) and 12s's
    # _where_is55s ('Cup on the shelf, …' may say where it is) refuse the same sentences: out too
    later = {_rewrites55._placed_wanted55, _rewrites55s._where_is55s}
    monkeypatch.setattr(offline, "_CHECKS", tuple(c for c in offline._CHECKS if c not in later))
    assert_case("Put the cup on the shelf, Bob wants it for his lunch.", "cup@shelf & cup>B", CELL)
    assert tree("Cup on the shelf, Bob wants it.", CELL) is not None


test_what_someone_has_had = CASES.test(
    # 'has had X': X was had already; a reading handing X over is refused
    ("The jug for Mr Lee, he's just had his tablets.", None, WARD),
    ("Give Mr Lee the jug, he has had his pills.", None, WARD),
    ("Give Bob the cup, he's just had the apple.", None, CELL),
    ("Give Bob the cup, he's already had the crisps.", None, CELL),
    # a state said with 'had', or the had thing not handed over: read as before
    ("Give Mr Lee the jug, he's had a bad night.", "jug>B", WARD),
    ("Give Bob the cup, he's had a long day.", "cup>B", CELL),
    # 'once/after P has had X' orders steps; 'had her eye on X' is a want: read as before
    ("Give Bob the apple once Alice has had the cup.", "cup>A ; apple>B", CELL),
    ("After Bob has had the crisps, give Alice the apple.", "chips>B ; apple>A", CELL),
    ("Alice has had her eye on the red mug all morning.", "mug_red>A", CELL),
)


def test_without_the_had_check_the_had_thing_is_handed(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(offline, "_had_already38l", lambda text, node, lexicon: None)
    assert_case("The jug for Mr Lee, he's just had his tablets.", "jug>B & pills>B", WARD)
