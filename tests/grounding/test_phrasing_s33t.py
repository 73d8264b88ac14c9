"""Session-33 phrasings of issue 12 (engineer 12t): blind17, blind23, blind18, causes17 and
blind15's refusals by kind; docs/grounding.md, "Session 33 (engineer 12t)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WORKSHOP,
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
FIG1 = _scene("fig1")  # bottle, chips (crisps); Alice, Bob; shelf


def _assert_case(text: str, want: str | None, scene: Scene) -> None:
    if want is None:
        assert_refused(text, scene)
    else:
        assert_reads(text, want, scene)


# -- a header saying how much each person gets, then the list that says what -----------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Both people get an item each: the chips for Person B and the bottle for Person A",
            "chips>B & bottle>A",
            DUO,
        ),
        (
            "Each of them gets one thing: the bottle to Person A, the chips to Person B.",
            "bottle>A & chips>B",
            F41,
        ),
        (
            "Something for both of them: the cup to Person A and the apple to Person B.",
            "cup>A & apple>B",
            F42,
        ),
        (
            "Each of them gets something to drink from, Person A the cup, Person B the bottle.",
            "cup>A & bottle>B",
            F42,
        ),
        (
            "Two things each: the bottle and cup to Person A, the chips and apple to Person B.",
            "bottle>A & cup>A & chips>B & apple>B",
            F42,
        ),
        (
            "One thing apiece for the two of them: the bottle's Person A's, the chips are "
            "Person B's.",
            "bottle>A & chips>B",
            T21,
        ),
        (
            "Each of them gets one thing: the bottle to Alice, the chips to Bob, the cup to Carol.",
            "bottle>A & chips>B & cup>C",
            CELL,
        ),
        # near forms: someone left out, one person given two (or another count), a placement,
        # the header's number against the scene's people, the same person twice
        ("Each of them gets one thing: the bottle to Person A.", None, F41),
        ("Both people get an item each: the cup and the apple for Person A", None, F41),
        ("Two things each: the bottle to Person A, the chips and apple to Person B.", None, F42),
        ("Something for both of them: the cup to Person A and the apple to Person A.", None, F42),
        ("Each of them gets one thing: the bottle to Alice, the chips to Bob.", None, CELL),
        (
            "Both people get an item each: the bottle for Alice and the chips on the shelf",
            None,
            FIG1,
        ),
        (
            "Both of them get one thing each: the bottle to Alice, the chips to Bob, the cup to "
            "Carol.",
            None,
            CELL,
        ),
        (
            "One thing apiece for the two of them: the bottle's Person A's, the chips are "
            "Person A's.",
            None,
            T21,
        ),
    ],
)
def test_each_header(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'one of the drinks / snacks for P: X or Y': the kind word's closed list --------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("One of the drinks for Person A: the bottle or the cup", "bottle>A | cup>A", F42),
        ("One of the snacks for Person B: the chips or the apple", "chips>B | apple>B", L44),
        ("One of the drinks for Person A: the bottle or the chips", None, F42),
        ("One of the snacks for Person B: the chips or the cup", None, L44),
        ("One of the toys for Person B: the chips or the apple", None, L44),
    ],
)
def test_kind_choice(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'give each of them a pen, P and Q, any colour' -------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Give each of them a spanner, Kofi and Jess, any size",
            "(spanner_small>A & spanner_large>B) | (spanner_large>A & spanner_small>B)",
            WORKSHOP,
        ),
        (
            "Give each of them a pen, Priya and Sam, any colour",
            "(pen_black>A & pen_blue>B) | (pen_black>A & pen_red>B) | (pen_blue>A & pen_black>B)"
            " | (pen_blue>A & pen_red>B) | (pen_red>A & pen_black>B) | (pen_red>A & pen_blue>B)",
            OFFICE,
        ),
        ("Give each of them a pen, Priya and Sam, the red one", None, OFFICE),
        ("Give each of them a pen, Priya and the stapler, any colour", None, OFFICE),
    ],
)
def test_each_any(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'No X for P, one of the other two will do' -------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("No black pen for Priya, one of the other two will do", "pen_blue>A | pen_red>A", OFFICE),
        ("No red pen for Sam, one of the other two will do", "pen_black>B | pen_blue>B", OFFICE),
        # the count against the scene: two other pens, no other stapler; 'pen' is three
        ("No black pen for Priya, one of the other three will do", None, OFFICE),
        ("No stapler for Priya, one of the other two will do", None, OFFICE),
        ("No pen for Priya, one of the other two will do", None, OFFICE),
    ],
)
def test_other_two(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'leave the X where they are' after everything; 'clear everything into S' ---------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Clear everything into the locker, leave the spanners where they are",
            "drill@locker & hammer@locker & screws@locker & torch@locker",
            WORKSHOP,
        ),
        (
            "Clear everything onto the belt, leave the boxes where they are",
            "scanner@conveyor & tape@conveyor & gloves@conveyor",
            DEPOT,
        ),
        (
            "Bob gets the lot, just leave the two mugs where they are.",
            "cup>B & bottle>B & chips>B & apple>B",
            CELL,
        ),
        # 'clear' of what is not everything, or onto a person; 'leave' a person
        ("Clear the bench into the locker, leave the spanners where they are", None, WORKSHOP),
        ("Clear everything onto Jess, leave the spanners where they are", None, WORKSHOP),
        ("Kofi gets the lot, just leave Jess where she is", None, WORKSHOP),
    ],
)
def test_leave_where(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'load P up with X', 'pack S with X' --------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Load Jess up with the spanners, just not the small one", "spanner_large>B", WORKSHOP),
        ("Load Tom up with the boxes, just not the small box", "box_medium>B & box_large>B", DEPOT),
        (
            "Ja, pack the locker with the lot, just not the two spanners.",
            "drill@locker & hammer@locker & screws@locker & torch@locker",
            WORKSHOP,
        ),
        ("Load the drill up with the screws", None, WORKSHOP),
        ("pack Jess with the lot", None, WORKSHOP),
    ],
)
def test_load_up(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'won't you <verb>': a request asked politely ----------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Ava the teddy, won't you give Lily the bib too?", "teddy>C & bib>A", NURSERY),
        ("Won't you give Lily the bib?", "bib>A", NURSERY),
        ("Give Ava the teddy, you won't give Lily the bib", None, NURSERY),
        ("Give Ava the teddy, why won't you give Lily the bib?", None, NURSERY),
        ("Give Ava the teddy, won't you stop giving Lily the bib?", None, NURSERY),
    ],
)
def test_wont_you(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- the recipient said first: 'Unto Person A the chips'; 'whichever thou wilt of X or Y' -------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Unto Person A the chips, nay, I misspeak, the bottle.", "bottle>A", F41),
        ("To Person A the chips.", "chips>A", F41),
        ("Give unto Person B whichever thou wilt of the cup or the apple.", "cup>B | apple>B", F41),
        # 'unto the same' is 'to the same person' ('unto' is read first)
        (
            "Give Person B the bottle, and thereafter the chips unto the same.",
            "bottle>B ; chips>B",
            F41,
        ),
        # a surface said first, a choice with no second object: left
        ("Unto the shelf the chips.", None, F41),
        ("Give unto Person B whichever thou wilt of the cup.", None, F41),
    ],
)
def test_fronted_to(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- an interjection or a word of address beside a correction; 'I mean' after the name ---------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("The hammer for Jess, eish, sorry, the drill for Jess.", "drill>B", WORKSHOP),
        (
            "Glue stick up on the shelf, oh no wait, on the desk, cariad, tidy.",
            "glue@desk",
            CLASSROOM,
        ),
        ("Chips to Person B, oops, Person A, I mean, sorry, love.", "chips>A", DUO),
        ("Forceps, sorry, I mean the spoon, to Omar.", "spoon>B", LAB),
        # no correction: the list is a list; a person after the correction is no address; a
        # first word the scene may name ('nothing')
        ("The hammer for Jess, eish, the drill for Jess.", "hammer>B & drill>B", WORKSHOP),
        ("Glue stick up on the shelf, oh no wait, on the desk, Noah.", None, CLASSROOM),
        ("Nothing, sorry, I mean the spoon, to Omar.", None, LAB),
        ("Forceps, sorry, I mean the spoon.", None, LAB),
    ],
)
def test_exclaimed_fix(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- after a placement, whom it is for and what they do; what an object is for (an -ing verb) ----


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "The two blocks in the high chair for Lily to play with.",
            "block_red@highchair & block_green@highchair",
            NURSERY,
        ),
        (
            "Person A needs the cup for rinsing the core samples, and Person B wants the chips.",
            "cup>A & chips>B",
            SQ,
        ),
        (
            "Everything goes to the sink for washing, except for the spoon and the banana of "
            "course",
            "cup_green@sink & bowl@sink & cup_white@sink & sponge@sink",
            LAB,
        ),
        # a bare 'for P' after a placement (sessions 30, 31: may ask for P to get it); the person
        # named again, a verb of the grammar, an object in the purpose
        ("Would you put the black pen in the box for Priya?", None, OFFICE),
        ("Put the black pen in the box for Priya, and give Priya the stapler.", None, OFFICE),
        ("The two blocks in the high chair for Lily to give.", None, NURSERY),
        ("Person A needs the cup for rinsing the apple, and Person B wants the chips.", None, SQ),
    ],
)
def test_placed_for(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)
