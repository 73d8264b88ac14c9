"""Phrasings the session-50 lead rules read or refuse (docs/grounding.md, Session 50 (lead))."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CLASSROOM,
    DEPOT,
    KITCHEN,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    assert_reads,
)

# -- the speaker has forgotten which, said in words no list had (blind48: "…, blue or grey, and
# I've gone blank on which." read the choice as the robot's)


@pytest.mark.parametrize(
    ("text", "scene", "named"),
    [
        (
            "Mrs Khan wanted one of the blankets, blue or grey, and I've gone blank on which.",
            WARD,
            ("blanket_blue", "blanket_grey"),
        ),
        (
            "Tom wanted the small box or the medium box, I've drawn a blank on which.",
            DEPOT,
            ("box_small", "box_medium"),
        ),
        (
            "Tom asked for the small box or the large box, but I went blank.",
            DEPOT,
            ("box_small", "box_large"),
        ),
        (
            "Tom wanted the small box or the medium one, my memory's shot.",
            DEPOT,
            ("box_small", "box_medium"),
        ),
        (
            "Tom wanted the small box or the large one, I haven't the foggiest which.",
            DEPOT,
            ("box_small", "box_large"),
        ),
        (
            "Tom wanted the small box or the large one, I'm blanking on which.",
            DEPOT,
            ("box_small", "box_large"),
        ),
        (
            "Tom wanted the small box or the large one, I've lost track.",
            DEPOT,
            ("box_small", "box_large"),
        ),
        (
            "Tom wanted the small box or the large one, I'm not sure which.",
            DEPOT,
            ("box_small", "box_large"),
        ),
        (
            "Marco asked for the salt or the lemon, and I've completely lost track of which.",
            KITCHEN,
            ("salt", "lemon"),
        ),
        (
            "Jess wanted the drill or the hammer, it's gone from me now.",
            WORKSHOP,
            ("drill", "hammer"),
        ),
        (
            "Jess wanted the drill or the hammer. Can't recall which.",
            WORKSHOP,
            ("drill", "hammer"),
        ),
        # 'I' names no person of the scene: the remark's clause is taken off, the rest read
        (
            "Zoe wanted a book for the egyptologist's talk, the red or the green one, I can't "
            "recall which.",
            CLASSROOM,
            ("book_red", "book_green"),
        ),
        (
            "Priya asked for a pen, the black or the red, and I've gone and forgotten which, "
            "sorry.",
            OFFICE,
            ("pen_black", "pen_red"),
        ),
    ],
)
def test_forgotten_choice_refused_naming_options(
    text: str, scene: Scene, named: tuple[str, ...]
) -> None:
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, scene)
    said = str(refused.value)
    assert "forgotten which" in said
    for obj in named:
        assert obj in said


@pytest.mark.parametrize(
    ("text", "scene", "spec"),
    [
        # the speaker does not mind, or the person does not: the choice is the robot's
        (
            "Give Tom the small box or the large one, I don't mind which.",
            DEPOT,
            "box_small>B | box_large>B",
        ),
        (
            "Give Tom the small box or the large one, he doesn't mind which.",
            DEPOT,
            "box_small>B | box_large>B",
        ),
        (
            "Give Tom the small box or the large one, I'm sure he won't mind.",
            DEPOT,
            "box_small>B | box_large>B",
        ),
        (
            "Give Mrs Khan the blue blanket or the grey one, she doesn't mind which.",
            WARD,
            "blanket_blue>C | blanket_grey>C",
        ),
        # no choice in what is left: the remark is about something else
        ("Tom wanted a box, the small one.", DEPOT, "box_small>B"),
    ],
)
def test_choice_without_forgetting_still_reads(text: str, scene: Scene, spec: str) -> None:
    assert_reads(text, spec, scene)


# -- any remark of the speaker's about knowing, memory, hearing or attention beside a choice (12c's
# probes: thirty wordings no list had)


@pytest.mark.parametrize(
    "remark",
    [
        "I'm drawing a blank.",
        "I had a mental blank.",
        "my memory's failed me.",
        "it's on the tip of my tongue.",
        "I'm a bit foggy on which.",
        "I wasn't paying attention.",
        "your guess is as good as mine.",
        "my brain's fried.",
        "I'm not a hundred percent.",
        "I should've written it down.",
        "it'll come back to me.",
        "it didn't stick.",
        "I never asked.",
        "it's all a blur.",
        "I'm not fussed about remembering which.",
    ],
)
def test_choice_beside_a_doubt_refused(remark: str) -> None:
    text = f"Kofi wanted one of the spanners, the small or the large, {remark}"
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, WORKSHOP)
    said = str(refused.value)
    assert "spanner_small" in said and "spanner_large" in said


@pytest.mark.parametrize(
    "text",
    [
        "Mrs Khan asked for the jug or the magazine, I'd have to check.",
        "Mrs Khan asked for the jug or the magazine, I only caught half of it.",
        "Mrs Khan asked for the jug or the magazine, I wasn't really listening.",
        "The jug goes on the trolley or the bedside, I've forgotten where.",
    ],
)
def test_choice_beside_a_doubt_refused_ward(text: str) -> None:
    with pytest.raises(GroundingError, match="jug"):
        parse_instruction(text, WARD)


@pytest.mark.parametrize(
    "text",
    [
        "Give Kofi the small spanner or the large one, I don't mind which.",
        "Give Kofi the small spanner or the large one, either will do.",
        "Kofi can have the small spanner or the large one, he's not fussy.",
        "Give Kofi the small spanner or the large one, I'm in a hurry.",
        # no doubt about the want: the choice is free, or the remark forgets something else
        "Give Kofi the small spanner or the large one, I don't think he minds.",
        "Give Kofi the small spanner or the large one, I don't think it matters.",
        "I forgot to mention, give Kofi the small spanner or the large one.",
        "Give Kofi the small spanner or the large one, I've forgotten my glasses.",
    ],
)
def test_free_choice_beside_a_remark_still_reads(text: str) -> None:
    assert_reads(text, "spanner_small>A | spanner_large>A", WORKSHOP)


# -- 'she' said of Grandad: a word of kin (or a title) says the sex as a first name does (12r:
# "Grandad said she wants the teddy." read teddy>B)


@pytest.mark.parametrize(
    "text",
    [
        "Grandad said she wants the teddy.",
        "The teddy on the mat, sorry, Grandad's just said she wants it.",
        "Grandad's asked for the bib, give it to her.",
        # 12c's probes: other wants, and having it
        "Grandad says she's been asking for the teddy.",
        "Grandad says she's got her eye on the teddy.",
        "Grandad says she's desperate for the teddy.",
        "Grandad wants the bib, she's going to have it.",
        # a state said of her by Grandad, who is not named to get it
        "Grandad says she's thirsty, the beaker please.",
    ],
)
def test_pronoun_of_the_other_sex_than_kin_refused(text: str) -> None:
    with pytest.raises(GroundingError, match=r"'she' is not resolved|'her' is not resolved"):
        parse_instruction(text, NURSERY)


@pytest.mark.parametrize(
    ("text", "scene", "spec"),
    [
        ("Grandad said he wants the teddy.", NURSERY, "teddy>B"),
        ("Lily said she wants the teddy.", NURSERY, "teddy>A"),
        # the pronoun neither wants nor is given: not the person named
        ("Could Grandad have the wipes? She's made a mess again.", NURSERY, "wipes>B"),
        ("Give Grandad the bib, he needs it.", NURSERY, "bib>B"),
        # Grandad named to get it; her state is why
        ("Could Grandad have the beaker? She's thirsty.", NURSERY, "beaker>B"),
        ("Give Grandad the bib, she's hungry.", NURSERY, "bib>B"),
        ("Give Mr Lee the magazine, he's bored.", WARD, "magazine>B"),
    ],
)
def test_pronoun_of_the_same_sex_still_reads(text: str, scene: Scene, spec: str) -> None:
    assert_reads(text, spec, scene)
