"""Session-34 phrasings of issue 12 (engineer 12t): blind17, blind19, blind20, blind23, causes18
and causes15's refusals by kind; docs/grounding.md, "Session 34 (engineer 12t)". Each rule with
the sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    OFFICE,
    ROOT,
    WARD,
    assert_reads,
    assert_refused,
)


def _scene(name: str) -> Scene:
    return load_scene(ROOT / f"examples/scenes/{name}.yaml")


F41 = _scene("4-1")  # bottle, chips, cup, apple; A, B
F42 = _scene("4-2")  # bottle, chips, cup, apple; A, B
DUO = _scene("2-2")  # bottle, chips; A, B
T21 = _scene("2-1")  # bottle, chips; A, B
L44 = _scene("4-4-line")  # bottle, chips, cup, apple; A, B
SQ = _scene("4-4-square")  # bottle, chips, cup, apple; A, B
TWO = _scene("two_arms")  # bottle, chips (crisps); Alice, Bob
FIG1 = _scene("fig1")  # bottle, chips (crisps); Alice, Bob; shelf


def _assert_case(text: str, want: str | None, scene: Scene) -> None:
    if want is None:
        assert_refused(text, scene)
    else:
        assert_reads(text, want, scene)


# -- a count after 'all … of the' or 'those' is the count with 'the' (and is checked) -----------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Those two mugs want to go on the counter, please.",
            "mug_red@table & mug_blue@table",
            CELL,
        ),
        (
            "All three of the boxes want to go on the conveyor, in whatever order suits you.",
            "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
            DEPOT,
        ),
        (
            "Those three things that aren't the bottle, give them to Person A.",
            "chips>A & cup>A & apple>A",
            SQ,
        ),
        # the count must agree with the scene
        ("Those three mugs want to go on the counter.", None, CELL),
        ("All two of the boxes want to go on the conveyor.", None, DEPOT),
        ("Those two things that aren't the bottle, give them to Person A.", None, SQ),
    ],
)
def test_counted_those(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- a last sentence naming exactly the objects of the request says them again ----------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Could Person B have the two things that aren't the cup or the apple? Sorry, the "
            "bottle and the chips.",
            "bottle>B & chips>B",
            F42,
        ),
        (
            "Give Person A the three things that aren't the bottle. I mean the chips, the cup "
            "and the apple.",
            "chips>A & cup>A & apple>A",
            SQ,
        ),
        # other objects: a correction, not said again (left as it was: refused)
        ("Give Person A the cup and the apple. Sorry, the bottle and the chips.", None, F41),
        (
            "Could Person B have the two things that aren't the cup or the apple? Sorry, the "
            "bottle and the cup.",
            None,
            F42,
        ),
    ],
)
def test_objects_said(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'P says she'd love X': what P wants --------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Carol says she'd love the blue mug, oh, and Bob fancies the apple.",
            "mug_blue>C & apple>B",
            CELL,
        ),
        ("Person B reckons she fancies the chilps now.", "chips>B", L44),
        # the pronoun cannot be the person by title, a person named before, or 'they'
        ("Mr Lee says she'd love the magazine.", None, WARD),
        ("Alice wants the bottle and Bob says she'd love the crisps.", None, TWO),
        ("Carol says they'd love the blue mug.", None, CELL),
        ("Person A reckons she fancies the chips, and Person B says she'd love them.", None, L44),
    ],
)
def test_reported_want(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- closers from a closed list, thanks said again, text-speak ----------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "okay so Person A's having the cup and the apple's going over to Person B off you go",
            "cup>A & apple>B",
            SQ,
        ),
        (
            "okay listen the chips are for Person A the bottle's for Person B got it",
            "chips>A & bottle>B",
            DUO,
        ),
        (
            "Bob wants the bottle Alice wants the crisps that's all of it.",
            "bottle>B & chips>A",
            TWO,
        ),
        (
            "Bonjour! Excuse me, please, I would like that you give the stapler to Priya. Thank "
            "you, you are very kind.",
            "stapler>A",
            OFFICE,
        ),
        (
            "Do me a favour, robot, be a love and give Person A the chips. Obrigado, eh, I mean "
            "thanks.",
            "chips>A",
            T21,
        ),
        ("the apple over to person b when u can", "apple>B", L44),
        ("the crisps r alice's, the bottle goes to bob", "chips>A & bottle>B", TWO),
        # a closer after what does not read alone, a thanks put right into a person
        ("okay so Person A's having the cup and the off you go", None, SQ),
        ("Obrigado, eh, I mean Bob.", None, TWO),
        ("Bob wants the bottle Alice wants the that's all of it.", None, TWO),
        ("the crisps r alice", None, TWO),
    ],
)
def test_closers(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- frames of learners and of talk -------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("I would like that you give the stapler to Priya.", "stapler>A", OFFICE),
        ("D'you reckon you could get that bottle up on the shelf?", "bottle@shelf", FIG1),
        ("Over to Person B with the bpttle, please.", "bottle>B", T21),
        ("For Person B, bottle, please give. Thank you.", "bottle>B", DUO),
        ("The bottle goes to Bob first. Then the crisps, same place.", "bottle>B ; chips>B", TWO),
        (
            "The bottle goes on the shelf first, then the crisps, same spot.",
            "bottle@shelf ; chips@shelf",
            FIG1,
        ),
        # near forms
        ("I would like that.", None, OFFICE),
        ("D'you reckon Alice could get that bottle?", None, FIG1),
        ("Over to Person B with Person A, please.", None, T21),
        ("For Person B, bottle, please take.", None, DUO),
        ("For the bottle, Person B, please give.", None, DUO),
        ("The bottle goes to Bob first. Then the crisps, same time.", None, TWO),
    ],
)
def test_frames(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)
