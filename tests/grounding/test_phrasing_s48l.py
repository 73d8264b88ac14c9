"""Phrasings the session-48 lead rules read (docs/grounding.md, Session 48 (lead))."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene
from tests.grounding.helpers import KITCHEN, LAB, assert_reads

# -- "the salt or the lemon, and it's slipped my mind which": the speaker has forgotten which of
# two things was asked for (blind46's one wrong reading offered the robot the choice)


@pytest.mark.parametrize(
    ("text", "scene", "named"),
    [
        (
            "Mr Novak asked for something for his fish, the salt or the lemon, and it's slipped "
            "my mind which.",
            KITCHEN,
            ("salt", "lemon"),
        ),
        (
            "Marco wants the salt or the lemon, it slipped my mind which one.",
            KITCHEN,
            ("salt", "lemon"),
        ),
        (
            "Marco wants the salt or the lemon; it has slipped my mind which.",
            KITCHEN,
            ("salt", "lemon"),
        ),
        (
            "Dana wants the spoon or the bowl, it's gone out of my head which.",
            LAB,
            ("spoon", "bowl"),
        ),
        (
            "Dana asked for the spoon or the bowl but it's gone clean out of my head which.",
            LAB,
            ("spoon", "bowl"),
        ),
    ],
)
def test_a_forgotten_choice_is_refused_naming_both(
    text: str, scene: Scene, named: tuple[str, str]
) -> None:
    with pytest.raises(GroundingError) as err:
        parse_instruction(text, scene)
    message = str(err.value)
    assert "does not know which" in message
    assert all(f"({n})" in message for n in named)
    # the 'it' of "it's slipped my mind" names no object: no "'it' could mean" in the refusal
    assert "'it' could mean" not in message


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # a choice left to the robot is still a choice
        ("Marco wants the salt or the lemon, whichever.", "salt>A | lemon>A", KITCHEN),
        ("Marco wants the salt or the lemon.", "salt>A | lemon>A", KITCHEN),
    ],
)
def test_a_choice_with_no_doubt_still_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)
