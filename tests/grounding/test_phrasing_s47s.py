"""Session-47 phrasings of issue 12 (engineer 12s): blind45's run-ons and splits, lower case,
negation and exclusion, each as a family (fresh sentences in other scenes, each refused on
issue-lead 4ac0c655, and near sentences that stay refused); docs/grounding.md, "Session 47
(engineer 12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites47s as r47s
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
)

TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # Alice, Bob
FIG1 = load_scene(ROOT / "examples/scenes/fig1.yaml")  # Alice, Bob
T21 = load_scene(ROOT / "examples/scenes/2-1.yaml")  # Person A, Person B
L24 = load_scene(ROOT / "examples/scenes/2-4-line.yaml")  # Person A, Person B


# -- run-ons: a remark about someone outside the scene; two placements ----------------------------

RUN_ON = PhrasingCases()
test_run_on47s = RUN_ON.test(
    (
        "Bottle to Alice crisps to Bob the costermonger's shouting about his barrow again",
        "bottle>A & chips>B",
        TWO,
    ),
    (
        "Spoon to Dana bowl on the tray the porter's whistling about his day off again",
        "spoon>A & bowl@tray",
        LAB,
    ),
    ("pass sam the stapler the postman is late with his round again", "stapler>B", OFFICE),
    (
        "knife to marco lemon to lena the delivery lad's parked his van on the kerb",
        "knife>A & lemon>B",
        KITCHEN,
    ),
    (
        "Magazine to Mr Lee jug on the trolley the window cleaner is up his ladder again",
        "magazine>B & jug@trolley",
        WARD,
    ),
    ("give kofi the torch the milkman was singing about his float", "torch>A", WORKSHOP),
    (
        "Small box onto the belt medium box onto the pallet the cowman's lorry is outside",
        "box_small@conveyor & box_medium@pallet",
        DEPOT,
    ),
    ("sponge in the sink bowl on the tray", "sponge@sink & bowl@tray", LAB),
    ("globe on the shelf ruler on the desk", "globe@shelf & ruler@desk", CLASSROOM),
    ("lemon on the rack knife on the counter", "lemon@rack & knife@counter", KITCHEN),
    ("bib on the high chair teddy on the play mat", "bib@highchair & teddy@mat", NURSERY),
    ("drill on the bench hammer in the locker", "drill@bench & hammer@locker", WORKSHOP),
)
test_run_on47s_near = RUN_ON.test(
    # the remark wants, names a thing, or its subject is a person of the scene ('the driver')
    ("knife to marco the delivery lad wants it", None, KITCHEN),
    ("knife to marco the delivery lad's after the lemon", None, KITCHEN),
    ("tape to mia the driver's asleep in his cab", None, DEPOT),
    ("stapler to sam the postman is late so the notebook too", None, OFFICE),
    # a piece that does not read alone
    ("sponge in the sink bowl", None, LAB),
    ("lemon on the rack knife to him", None, KITCHEN),
)


def test_run_on47s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    RUN_ON.refused_without((r47s._remark_the47s, r47s._placed_run_on47s), monkeypatch)


# -- splits: 'X? P's.' answered by whose it is; 'the farm hand' --------------------------------

SPLIT = PhrasingCases()
test_split47s = SPLIT.test(
    (
        "Chips? Person A's. Bottle? Person B's. The farm hand sends his regards and says ta.",
        "chips>A & bottle>B",
        T21,
    ),
    ("Knife? Marco's. Lemon? Lena's.", "knife>A & lemon>B", KITCHEN),
    ("Banana? Emma's. Spoon? Omar's.", "banana>C & spoon>B", LAB),
    ("Stapler? Sam's.", "stapler>B", OFFICE),
    ("Torch? Kofi's. Hammer? Jess's.", "torch>A & hammer>B", WORKSHOP),
    ("Chips to Person A. The farm hand says ta.", "chips>A", T21),
    ("Knife to Marco. The kitchen hand sends his best.", "knife>A", KITCHEN),
    # a closing 'nobody else has asked'
    ("The chips. Person A wants them. Nobody else has asked.", "chips>A", L24),
    ("The banana's for Emma. No one else has claimed it.", "banana>C", LAB),
    ("Stapler to Sam. Nobody else has called dibs.", "stapler>B", OFFICE),
    ("Teddy to Lily, nobody else has asked yet.", "teddy>A", NURSERY),
    # a closing remark that someone left out will wait
    (
        "Sponge into the sink first. After, the bowl for Omar. Emma's fine with waiting, she's "
        "a visitor.",
        "(sponge@sink ; bowl>B)",
        LAB,
    ),
    ("Knife to Marco. Lena's happy to wait.", "knife>A", KITCHEN),
    ("The magazine to Mr Lee, Mrs Khan can wait.", "magazine>B", WARD),
)
test_split47s_near = SPLIT.test(
    ("Plates? Lena's.", None, KITCHEN),  # two plates
    ("Knife? Nobody's.", None, KITCHEN),
    ("Stapler? The manager wants it. Sam's.", None, OFFICE),
    # two people, or a placement
    ("The lemon to Lena and the knife to Marco, nobody else has asked.", None, KITCHEN),
    ("The lemon on the rack, nobody else has asked.", None, KITCHEN),
    # the role or the pronoun is not the person's; the role names two people
    ("Knife to Marco. Lena can wait, she's the chef.", None, KITCHEN),
    ("Bowl for Omar. Emma can wait, he's a visitor.", None, LAB),
    ("Ruler to Noah. Zoe doesn't mind waiting, she's a student.", None, CLASSROOM),
)


def test_whose_question_still_reads() -> None:
    # blind40's entry: the question is no bare name, so `_whose_answer47s` leaves it (it read
    # before; the first form of the rule refused it, found by the identity run)
    assert_case(
        "Whose are the chips? Person B's. And the bottle? Also his, so take him both.",
        "chips>B & bottle>B",
        L24,
    )


def test_split47s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SPLIT.refused_without(
        (r47s._whose_answer47s, r47s._hand_worker47s, r47s._nobody_else47s, r47s._waits47s),
        monkeypatch,
    )


# -- lower case: "chef marcos got …" -------------------------------------------------------------

LOWER = PhrasingCases()
test_lower47s = LOWER.test(
    ("chef marcos got the damson jam cake to slice give him the knife", "knife>A", KITCHEN),
    ("bobs got a long ride ahead give him the bottle", "bottle>B", FIG1),
    ("doctor danas been on shift all night give her the banana", "banana>A", LAB),
    ("nurse ruths been run ragged give her the jug", "jug>A", WARD),
)
test_lower47s_near = LOWER.test(
    ("waiter marcos got the cake to slice give him the knife", None, KITCHEN),
    ("chef lenas got the cake to slice give her the knife", None, KITCHEN),  # Lena: waitress
    ("marcos got the cake to slice give her the knife", None, KITCHEN),
)


def test_lower47s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LOWER.refused_without((r47s._role_name_s47s,), monkeypatch)


# -- negation and exclusion: '<thing> only' ------------------------------------------------------

NOT = PhrasingCases()
test_not47s = NOT.test(
    (
        "Jess is off power tools until the timekeeper signs the card; hammer only for now, to "
        "Jess.",
        "hammer>B",
        WORKSHOP,
    ),
    ("Torch only, to Kofi.", "torch>A", WORKSHOP),
    ("Lemon only for now, to Lena.", "lemon>B", KITCHEN),
    ("The banana only, to Emma.", "banana>C", LAB),
    ("Tape only, to Mia, she's packing.", "tape>A", DEPOT),
)
test_not47s_near = NOT.test(
    ("Lemon only if she asks, to Lena.", None, KITCHEN),
    ("Plate only, to Lena.", None, KITCHEN),
    ("Lemon only, to him.", None, KITCHEN),
)


def test_not47s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOT.refused_without((r47s._only_after47s,), monkeypatch)
