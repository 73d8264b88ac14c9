"""Session-41 phrasing of issue 12 (lead): a handing or placing told as done, a want taken back by
an idiom, and a want idiom with 'after' are refused (docs/grounding.md, "Session 41 (lead)").

"The chips were handed to Bob, so give Alice the cup." read `chips>B & cup>A` and "The cup's been
put on the shelf." `cup@shelf`: the grammar's passive took the past and perfect auxiliaries as it
takes the present and modal ones, so a report of what was done became a request. 12c's `idioms`
fuzz: "Give Bob the cup. Bob has gone off the cup." read `cup>B` (the sentence dropped as a remark)
and "Give Bob the cup. Carol is hankering after the apple." `cup>B` ('after the apple' taken for a
time gone by)."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites41l, _rewrites56s, offline
from hltl.world.scene import load_scene
from tests.grounding.helpers import CELL, KITCHEN, ROOT, WARD, WORKSHOP, PhrasingCases

CASES = PhrasingCases()

test_a_handing_told_as_done_is_refused = CASES.test(
    ("The chips were handed to Bob, so give Alice the cup.", None, CELL),
    ("The cup has been given to Alice.", None, CELL),
    ("The cup's been put on the shelf.", None, CELL),
    ("The cup was passed to Bob.", None, CELL),
    ("The cup has been handed to Alice, and the bottle to Bob.", None, CELL),
    ("The red mug was set on the table.", None, CELL),
    ("The cup was placed on the shelf, now give Bob the chips.", None, CELL),
    ("The cup should have been given to Alice.", None, CELL),
    ("the cup has already been brought over to carol", None, CELL),
    ("The lemon was left on the worktop, so hand Marco the knife.", None, KITCHEN),
    ("The jug had been taken to Mr Lee.", None, WARD),
    ("The torch was just lent to Kofi; pass him the drill.", None, WORKSHOP),
)

test_present_modal_and_subordinate_passives_read_as_before = CASES.test(
    # a goal said as a state or with a modal, as before
    ("The cup is given to Alice.", "cup>A", CELL),
    ("The cup will be given to Alice.", "cup>A", CELL),
    ("The apple should be delivered to Bob.", "apple>B", CELL),
    ("The cup is being given to Alice.", "cup>A", CELL),
    # a subordinate clause: a condition or a time, not a report
    ("It would be appreciated if the apple were placed on the table.", "apple@table", CELL),
    (
        "The cup should be handed to Carol after Bob has been given the chips",
        "chips>B ; cup>C",
        CELL,
    ),
    # a person as the subject: a state of the person, not a handing
    (
        "Alice could do with the crisps, she's been stuck on the phones all morning.",
        "chips>A",
        CELL,
    ),
)


def test_the_refusal_names_what_was_said_as_done() -> None:
    with pytest.raises(GroundingError, match=r"'The chips were handed to Bob' is said as done"):
        offline.parse_instruction("The chips were handed to Bob, so give Alice the cup.", CELL)


@pytest.mark.parametrize(
    ("text", "was"),
    [
        ("The chips were handed to Bob, so give Alice the cup.", "chips>B & cup>A"),
        ("The cup has been given to Alice.", "cup>A"),
        ("The cup's been put on the shelf.", "cup@shelf"),
        ("The cup was placed on the shelf, now give Bob the chips.", "cup@shelf & chips>B"),
    ],
)
def test_each_read_without_the_rule(text: str, was: str, monkeypatch: pytest.MonkeyPatch) -> None:
    # the rule is what refuses them: without it each reads as it did on main 6b135df
    from hltl.bench.grounding import show_tree

    monkeypatch.setattr(
        offline,
        "_REFUSALS",
        tuple(r for r in offline._REFUSALS if r is not _rewrites41l._done41l),
    )
    assert show_tree(offline.parse_instruction(text, CELL)) == was


test_a_want_taken_back_is_refused = CASES.test(
    ("Give Bob the cup. Bob has gone off the cup.", None, CELL),
    ("Give Bob the cup, Bob has gone off it.", None, CELL),
    ("Give Bob the cup. He's so over it.", None, CELL),
    ("Bob is so over the cup.", None, CELL),
    ("Give Bob the cup. Carol is so over the apple.", None, CELL),
    ("Give Bob the cup. Bob is through with the cup.", None, CELL),
    ("Pass Kofi the torch, he's totally fed up with it.", None, WORKSHOP),
    ("Mr Lee gets the jug. He's had enough of the jug.", None, WARD),
    ("Give Bob the cup. Bob has already got the cup.", None, CELL),
    # a person said as 'Person A' or with a title, in lower case too (12c's idioms fuzz)
    ("Person A is so over the cup.", None, CELL),
    ("Give Person A the cup. Person A has gone off the cup.", None, CELL),
    ("give person b the chips. person b is through with the chips.", None, CELL),
    ("Give Person B the chips. Person B has already got the chips.", None, CELL),
    ("Pass Mrs Khan the magazine; Mrs Khan has lost interest in it.", None, WARD),
    # a thing named with 'of' (12c's fuzz on main f35ba9e5)
    ("Kofi is so over the tin of screws.", None, WORKSHOP),
    ("Hand Marco the knife, he has got the knife already.", None, KITCHEN),
    # a thing the person does not get, a placement, another person, 'over there': as before
    ("Give Bob the cup, he's sick of the apple.", "cup>B", CELL),
    ("Put the cup on the shelf, Bob's done with it.", "cup@shelf", CELL),
    ("Give Bob the cup, Alice is done with it.", "cup>B", CELL),
    ("Give Bob the cup, he's over there.", "cup>B", CELL),
    # a name's 'got' without 'already' assigns (session 27)
    ("Alice's got the apple, Bob's got the cup.", "apple>A & cup>B", CELL),
    # 'she's done with it' beside a placement (session 35): as before
    ("The magazine can go back on the trolley, she's done with it.", "magazine@trolley", WARD),
)

test_a_want_idiom_with_after_is_no_time_gone_by = CASES.test(
    # session 42 (12): 12's session-41 want idioms (_rewrites41._want_idiom41, landed after this)
    # read 'is hankering after' as 'wants', as 'Carol is after the apple' is read beside a request:
    # the want, not a time gone by
    ("Give Bob the cup. Carol is hankering after the apple.", "cup>B & apple>C", CELL),
    ("Give Bob the cup, he's been hankering after the chips.", "cup>B & chips>B", CELL),
    ("Hand Marco the knife, Lena is pining after the tongs.", "knife>A & tongs>B", KITCHEN),
    # a time gone by after a remark: dropped as before
    ("Give Bob the cup, he's tired after his shift.", "cup>B", CELL),
)


@pytest.mark.parametrize(
    ("text", "was"),
    [
        ("Give Bob the cup. Bob has gone off the cup.", "cup>B"),
        ("Give Bob the cup. He's so over it.", "cup>B"),
        ("Bob is so over the cup.", "cup>B"),
        ("Give Bob the cup. Carol is so over the apple.", "cup>B & apple>C"),
    ],
)
def test_each_taken_back_reads_without_the_check(
    text: str, was: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    from hltl.bench.grounding import show_tree

    # session 56 (12s): _was_off56s refuses 'Bob has gone off the cup' beside a handover of the
    # cup to him too (same family), so it is taken out as well
    off = (_rewrites41l._taken_back41l, _rewrites56s._was_off56s)
    monkeypatch.setattr(offline, "_CHECKS", tuple(c for c in offline._CHECKS if c not in off))
    assert show_tree(offline.parse_instruction(text, CELL)) == was


ONE_BOTTLE = load_scene(ROOT / "examples/scenes/1-2.yaml")

test_an_ordinal_beyond_the_scene_is_refused = CASES.test(
    # blind40's one wrong reading at its measurement, in other words
    ("Hand the bottle to Person A, then a second bottle.", None, ONE_BOTTLE),
    ("Give Alice the cup. Give her the second cup too.", None, CELL),
    ("Give Alice the third mug.", None, CELL),
    ("Give Alice the second red mug.", None, CELL),
    # 'second' ordering the tasks: as before
    ("First the cup to Alice, second the apple to Bob.", "cup>A ; apple>B", CELL),
    ("Give Alice the cup; second, give Bob the apple.", "cup>A ; apple>B", CELL),
)
