"""Session-46 phrasings of issue 12 (engineer 12s): order words in texts with no marks (12c's
`texted` fuzz family: its wrong readings refused, with fresh sentences of each kind in other
scenes and the marked sentences that still read); docs/grounding.md, "Session 46 (engineer
12s)"."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import show_tree
from hltl.grounding import _rewrites46s as r46s
from hltl.grounding import offline
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WORKSHOP,
    PhrasingCases,
    assert_refused,
    tree,
)

SQUARE = load_scene(ROOT / "examples/scenes/4-4-square.yaml")  # Person A, Person B
F42 = load_scene(ROOT / "examples/scenes/4-2.yaml")  # Person A, Person B
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # Alice, Bob
FIG1 = load_scene(ROOT / "examples/scenes/fig1.yaml")  # Alice, Bob


def _without(check: object, monkeypatch: pytest.MonkeyPatch) -> None:
    """``check`` taken out of the refusals and checks of offline.py."""
    monkeypatch.setattr(offline, "_REFUSALS", tuple(c for c in offline._REFUSALS if c != check))
    monkeypatch.setattr(offline, "_CHECKS", tuple(c for c in offline._CHECKS if c != check))


def _read_without(
    check: object, cases: list[tuple[str, Scene]], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each of ``cases`` reads (as something) with ``check`` taken out: the check refuses it."""
    _without(check, monkeypatch)
    for text, scene in cases:
        got = tree(text, scene)
        assert got is not None, f"{text!r} is refused without {check}"


# -- the order word orders only a remark of the speaker -----------------------------------------
#
# blind22's "Bottle to Bob. Crisps to Alice. Then I'm off to warm up my voice." without its stops:
# the remark was taken off and the 'then' left behind ordered the tasks before it.

REMARK = [
    ("bottle to bob crisps to alice then im off to warm up my voice", TWO),
    ("Bottle to Bob Crisps to Alice Then I'm off to warm up my voice", TWO),
    (
        "The globe goes on the shelf and the scissors on the desk and then we're sorted for the "
        "inspector",
        CLASSROOM,
    ),
    ("tape to mia scanner to tom then im off for my break", DEPOT),
    ("spoon to dana and the bowl to omar then im off to the seminar", LAB),
]
REMARK_CASES = PhrasingCases()
test_remark_then_refused = REMARK_CASES.test(*((t, None, s) for t, s in REMARK))
test_remark_then_marked_reads = REMARK_CASES.test(
    (
        "Bottle to Bob. Crisps to Alice. Then I'm off to warm up my voice.",
        "bottle>B & chips>A",
        TWO,
    ),
    (
        "The globe goes on the shelf and the scissors on the desk and then we're sorted for the "
        "inspector.",
        "globe@shelf & scissors@desk",
        CLASSROOM,
    ),
    ("Tape to Mia. Scanner to Tom. Then I'm off for my break.", "tape>A & scanner>B", DEPOT),
    ("tape to mia then the scanner to tom", "tape>A ; scanner>B", DEPOT),
    (
        "ok so first the apple goes to person b and then the bottle goes to person a and then "
        "we're done gg",
        "apple>B ; bottle>A",
        SQUARE,
    ),
)


def test_remark_then_read_without(monkeypatch: pytest.MonkeyPatch) -> None:
    _read_without(r46s.order_of_remark46s, REMARK, monkeypatch)


# -- 'then' and a clause added after it --------------------------------------------------------
#
# blind4's "First give Person A the bottle, then Person B the chips, and also Person A the cup and
# the apple" without its commas: 'then' took in what 'and also' adds.

ADDED = [
    (
        "First give Person A the bottle then Person B the chips and also Person A the cup and the "
        "apple",
        F42,
    ),
    ("give person b the bottle then person a the chips and also person b the cup", F42),
    (
        "lilys hungry so put the bib on the high chair and then give her the sippy cup oh and "
        "grandad wants the teddy",
        NURSERY,
    ),
    ("give dana the spoon then omar the bowl and also dana the banana", LAB),
    ("spoon to dana then the bowl to omar and emma wants the banana", LAB),
    ("tongs to marco then the knife to lena plus the salt to mr novak", KITCHEN),
]
ADDED_CASES = PhrasingCases()
test_then_added_refused = ADDED_CASES.test(*((t, None, s) for t, s in ADDED))
test_then_added_marked_reads = ADDED_CASES.test(
    (
        "First give Person A the bottle, then Person B the chips, and also Person A the cup and "
        "the apple",
        "(bottle>A ; chips>B) & cup>A & apple>A",
        F42,
    ),
    (
        "Give Dana the spoon, then Omar the bowl, and also Dana the banana",
        "(spoon>A ; bowl>B) & banana>A",
        LAB,
    ),
    (
        "put the apple on the shelf then give the cup to bob and the bottle to carol",
        "apple@shelf ; (cup>B & bottle>C)",
        CELL,
    ),
    (
        "spoon to dana then the bowl to omar and the banana to emma",
        "spoon>A ; (bowl>B & banana>C)",
        LAB,
    ),
    (
        "first the cup to person A then the apple to person B then the bottle and chips to "
        "person A",
        "cup>A ; apple>B ; (bottle>A & chips>A)",
        load_scene(ROOT / "examples/scenes/4-1.yaml"),
    ),
)


def test_then_added_read_without(monkeypatch: pytest.MonkeyPatch) -> None:
    _read_without(r46s.then_more46s, ADDED, monkeypatch)


# -- 'the third' is not an order word ----------------------------------------------------------

NTH = [
    ("Tom and Mia one box each the third goes on the belt", DEPOT),
    ("tom and mia one box each the third goes on the belt", DEPOT),
    ("Mia and Tom one box each the second goes on the pallet", DEPOT),
]
NTH_CASES = PhrasingCases()
test_the_ordinal_refused = NTH_CASES.test(*((t, None, s) for t, s in NTH))


def test_the_ordinal_read_without(monkeypatch: pytest.MonkeyPatch) -> None:
    _read_without(r46s.the_ordinal46s, NTH, monkeypatch)


# -- 'first' and 'after <a thing>' -------------------------------------------------------------

FIRST_AFTER = [
    ("bottle first to alice after chips to bob", TWO),
    ("Bottle first To Alice After chips to Bob", TWO),
    ("tape first to mia after gloves to tom", DEPOT),
    ("spoon first to dana after banana to omar", LAB),
]
FIRST_AFTER_CASES = PhrasingCases()
test_first_after_refused = FIRST_AFTER_CASES.test(*((t, None, s) for t, s in FIRST_AFTER))
test_first_after_marked_reads = FIRST_AFTER_CASES.test(
    ("Bottle first. To Alice. After, chips to Bob.", "bottle>A ; chips>B", TWO),
    ("tape first to mia and after that the gloves to tom", "tape>A ; gloves>B", DEPOT),
    (
        "chips to person b first and the bottle to person a after",
        "chips>B ; bottle>A",
        load_scene(ROOT / "examples/scenes/2-2.yaml"),
    ),
)


def test_first_after_read_without(monkeypatch: pytest.MonkeyPatch) -> None:
    _read_without(r46s.first_after46s, FIRST_AFTER, monkeypatch)


# -- 'first' and 'next' said, no order read ----------------------------------------------------

DROPPED = [
    ("Chips first to Person A Bottle next Same person Person A the clarinettist", SQUARE),
    ("chips first to person a bottle next same person person a the clarinettist", SQUARE),
    ("gloves first to tom scanner next same person tom", DEPOT),
]
DROPPED_CASES = PhrasingCases()
test_order_dropped_refused = DROPPED_CASES.test(*((t, None, s) for t, s in DROPPED))
test_order_dropped_marked_reads = DROPPED_CASES.test(
    (
        "Chips first, to Person A. Bottle next. Same person, Person A, the clarinettist.",
        "chips>A ; bottle>A",
        SQUARE,
    ),
)


def test_order_dropped_read_without(monkeypatch: pytest.MonkeyPatch) -> None:
    _read_without(r46s.order_dropped46s, DROPPED, monkeypatch)


# -- a time clause between two requests --------------------------------------------------------

BETWEEN = [
    (
        "clear the drill and the screws onto the bench when theyre down kofi gets the torch",
        WORKSHOP,
    ),
    (
        "Clear the drill and the screws onto the bench When they're down Kofi gets the torch",
        WORKSHOP,
    ),
    ("put the plates on the rack when theyre up marco gets the tongs", KITCHEN),
    ("put the bowl and the spoon in the sink when theyre in omar gets the banana", LAB),
    ("give mia the tape once shes got it tom gets the gloves", DEPOT),
]
BETWEEN_CASES = PhrasingCases()
test_sub_between_refused = BETWEEN_CASES.test(*((t, None, s) for t, s in BETWEEN))
test_sub_between_marked_reads = BETWEEN_CASES.test(
    (
        "Clear the drill and the screws onto the bench. When they're down, Kofi gets the torch.",
        "(drill@bench & screws@bench) ; torch>A",
        WORKSHOP,
    ),
    (
        "tom wants the gloves and once hes got them mia wants the tape",
        "gloves>B ; tape>A",
        DEPOT,
    ),
    (
        "pop the notebook into the box first and once its in there priya can have the stapler",
        "notebook@box ; stapler>A",
        OFFICE,
    ),
)


def test_sub_between_read_without(monkeypatch: pytest.MonkeyPatch) -> None:
    _read_without(r46s.sub_between46s, BETWEEN, monkeypatch)


def test_messages_say_the_words() -> None:
    assert_refused(
        "bottle first to alice after chips to bob", TWO, match="'first' and 'after chips'"
    )
    assert_refused("tom and mia one box each the third goes on the belt", DEPOT, match="the third")
    got = tree("tape to mia then the scanner to tom", DEPOT)
    assert got is not None and show_tree(got) == "tape>A ; scanner>B"


# -- run-ons with no marks: a courtesy inside the text, a person's 'wants to <verb>' -----------
#
# blind44's "crisps up on the shelf ta the pipe fitter keeps nicking them" and "tin of screws on
# the workbench kofi wants to count them" (not landed in session 46: no identity run in time).

RUN_ON = PhrasingCases()
test_run_on46s = RUN_ON.test(
    ("crisps up on the shelf ta the pipe fitter keeps nicking them", "chips@shelf", FIG1),
    ("bottle to bob cheers the lads are thirsty", "bottle>B", FIG1),
    ("tape to mia ta the lads keep pinching it", "tape>A", DEPOT),
    ("gloves on the pallet cheers the forklift is waiting", "gloves@pallet", DEPOT),
    ("stapler to sam please the printer jammed again", "stapler>B", OFFICE),
    ("tin of screws on the workbench kofi wants to count them", "screws@bench", WORKSHOP),
    (
        "the plates on the rack lena wants to dry them",
        "plate_white@rack & plate_blue@rack",
        KITCHEN,
    ),
    (
        "pens in the box priya wants to count them",
        "pen_black@box & pen_blue@box & pen_red@box",
        OFFICE,
    ),
    ("books on the shelf noah wants to sort them", "book_red@shelf & book_green@shelf", CLASSROOM),
)
test_run_on46s_near = RUN_ON.test(
    ("crisps to alice thanks the pipe fitter says bob wants them", None, FIG1),
    ("give bob the bottle please the crisps to alice", None, FIG1),
    ("drill on the bench kofi wants to take it", None, WORKSHOP),
    ("drill on the bench jess wants to use the hammer", None, WORKSHOP),
)


def test_run_on46s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    RUN_ON.refused_without((r46s._courtesy_mid46s, r46s._person_to46s), monkeypatch)
