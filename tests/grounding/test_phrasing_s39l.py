"""Session-39 phrasing of issue 12 (lead): wrong readings found by 12c's fuzz (docs/grounding.md,
"Session 39 (lead)").

"Ruth is cold. Mr Lee doesn't need the jug, just the magazine." read the magazine to Ruth: the
negated clause was dropped with its person, and the remark's person took the bare object left.
"Lily is sleepy. Ava doesn't want the bib, pass her the beaker." read the beaker to Lily: the
remark's person stood in for a 'her' that may be Ava, named in the request before it.
"Let's get going. Put the lemon on the worktop, chef wants it." read a handover too: the opener's
'let' was taken for a verb of handing, so session 38's placed-then-wanted check did not run; and
"…, chef wants it. Also, give Lena the salt." skipped it too, for a 'give' said of another thing.
"Bob wants the red mug, leave the blue one where it is, no, Alice gets it." read the blue mug to
Alice: the correction's 'it' was taken for the thing said to be left."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import offline
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    KITCHEN,
    LAB,
    NURSERY,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
)

CASES = PhrasingCases()

test_a_bare_object_after_a_negated_want_keeps_its_person = CASES.test(
    # a remark's person before 'P doesn't need X, just Y': never the one who gets Y
    ("Ruth is cold. Mr Lee doesn't need the jug, just the magazine.", None, WARD),
    ("Jess is cold. Kofi doesn't need the drill, just the torch.", None, WORKSHOP),
    # a remark taken off (session 39, 12s): the rest is read alone, for Kofi, never for Jess
    ("Jess is busy. Kofi doesn't need the drill, just the torch.", "torch>A", WORKSHOP),
    ("Carol is freezing. Bob doesn't need the cup, just the apple.", None, CELL),
    # said alone, or with a verb or person of its own after the comma: read as before
    ("Kofi doesn't need the drill, just the torch.", "torch>A", WORKSHOP),
    ("Bob doesn't need the cup, just the apple.", "apple>B", CELL),
    ("Bob doesn't want the crisps, put the apple on the shelf.", "apple@shelf", CELL),
    ("Bob doesn't want the crisps, give him the apple.", "apple>B", CELL),
)

test_a_pronoun_after_another_person_is_not_the_remarks = CASES.test(
    # the request names someone the pronoun may be: not resolved to the remark's person
    ("Lily is sleepy. Ava doesn't want the bib, pass her the beaker.", None, NURSERY),
    ("Carol is thirsty. Alice doesn't want the crisps, give her the apple.", None, CELL),
    # the request's other person cannot be the pronoun (Grandad), or there is none: as before
    ("Lily is sleepy. Grandad doesn't want the bib, pass her the beaker.", "beaker>A", NURSERY),
    ("Lily is sleepy, pass her the beaker.", "beaker>A", NURSERY),
    ("Carol is thirsty, give her the cup.", "cup>C", CELL),
)

test_an_opener_with_let_is_no_handover = CASES.test(
    # "let's …" / "let me …" open the instruction: the want after the placement is refused
    ("Let's get going. Put the lemon on the worktop, chef wants it.", None, KITCHEN),
    ("Let's get cracking. Put the spoon in the sink, Omar wants it.", None, LAB),
    ("Right, let me think. Cup on the shelf, Bob needs it for his lunch.", None, CELL),
    ("Let us see. Put the cup on the shelf, Bob wants it.", None, CELL),
    # 'let P have it' hands it over: read as before
    ("Put the cup on the shelf and let Bob have it.", "cup@shelf & cup>B", CELL),
)


@pytest.mark.parametrize(
    ("text", "scene", "names"),
    [
        ("Lily is sleepy. Ava doesn't want the bib, pass her the beaker.", NURSERY, ("A", "C")),
        ("Let's get going. Put the lemon on the worktop, chef wants it.", KITCHEN, ("lemon@",)),
    ],
)
def test_the_refusals_say_what_was_unclear(text: str, scene: Scene, names: tuple[str, ...]) -> None:
    with pytest.raises(GroundingError) as refused:
        offline.parse_instruction(text, scene)
    said = str(refused.value)
    assert all(n in said for n in names), said


test_a_thing_said_to_be_left_is_not_moved = CASES.test(
    # "leave the blue one where it is", then a correction whose 'it' was taken for it: refused
    ("Bob wants the red mug, leave the blue one where it is, no, Alice gets it.", None, CELL),
    (
        "Bob wants the red mug, mind, leave the blue one where it is, what am I saying, Carol "
        "gets it.",
        None,
        CELL,
    ),
    (
        "Ruth wants the grey blanket, leave the blue one where it is, sorry, Mr Lee gets it.",
        None,
        WARD,
    ),
    # the thing left stays where it is, and nothing moves it: read as before
    ("Bob wants the red mug, leave the blue one where it is.", "mug_red>B", CELL),
    ("Bob wants the red mug, leave the blue one alone.", "mug_red>B", CELL),
    ("Ruth wants the grey blanket, leave the blue one where it is.", "blanket_grey>A", WARD),
    # 'don't leave X where it is' asks to move it
    ("Don't leave the apple where it is, give it to Bob.", "apple>B", CELL),
)

test_a_handover_of_another_thing_says_nothing_of_the_placed_one = CASES.test(
    # 'give' said of another thing in another sentence: the want after the placement is refused
    ("Put the cup on the shelf, Bob wants it. Also, give Alice the apple.", None, CELL),
    ("Put the spoon in the sink, Omar wants it. Then give Emma the bowl.", None, LAB),
    # 'give' said of the placed thing (by name or 'it'): read as before
    ("Put the cup on the shelf. Then give Bob the cup, he wants it.", "cup@shelf ; cup>B", CELL),
    ("Put the cup on the shelf, then give it to Bob, he wants it.", "cup@shelf ; cup>B", CELL),
)


def test_without_the_left_check_the_left_thing_moves(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(offline, "_left_moved39l", lambda text, node, lexicon: None)
    assert_case(
        "Bob wants the red mug, leave the blue one where it is, no, Alice gets it.",
        "mug_red>B & mug_blue>A",
        CELL,
    )
