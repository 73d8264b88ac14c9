"""Session-39 phrasing of issue 12 (lead): wrong readings found by 12c's fuzz (docs/grounding.md,
"Session 39 (lead)").

"Ruth is cold. Mr Lee doesn't need the jug, just the magazine." read the magazine to Ruth: the
negated clause was dropped with its person, and the remark's person took the bare object left.
"Lily is sleepy. Ava doesn't want the bib, pass her the beaker." read the beaker to Lily: the
remark's person stood in for a 'her' that may be Ava, named in the request before it.
"Let's get going. Put the lemon on the worktop, chef wants it." read a handover too: the opener's
'let' was taken for a verb of handing, so session 38's placed-then-wanted check did not run."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import offline
from hltl.world.scene import Scene
from tests.grounding.helpers import CELL, KITCHEN, LAB, NURSERY, WARD, WORKSHOP, PhrasingCases

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
