"""Session-55 phrasings of issue 12 (engineer 12r): 12c's open wrong readings and blind53's choices,
counts, corrections and questions, each as a family (docs/grounding.md, "Session 55 (engineer
12r)"). Every sentence that reads here was refused (or read wrongly) on main ceed68bd, and is
refused (or read as before) with its rule taken out."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import show_tree
from hltl.errors import GroundingError
from hltl.grounding import _rewrites55r, normalise, offline
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
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
    tree,
)

# the example scenes blind53 uses
DUO, ONE, T12, F41, F42, L44, L24, T21, SQ, FIG1, TWO = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in (
        "2-2",
        "1-1",
        "1-2",
        "4-1",
        "4-2",
        "4-4-line",
        "2-4-line",
        "2-1",
        "4-4-square",
        "fig1",
        "two_arms",
    )
)


def _without_check(check: object, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(offline, "_CHECKS", tuple(c for c in offline._CHECKS if c is not check))


# -- 12c's open wrong readings ---------------------------------------------------------------------

# _later_part55r (a check of the reading): a later time said alone between commas or as a
# sentence is the request's own time; the choice rules had dropped it as a remark naming nothing
# (main read each as the choice, now)
LATER = [
    ("Bob can take his pick of the cup or the apple, tomorrow", CELL),
    ("Person B can take his pick of the cup or the bottle, before I go tomorrow", L44),
    ("Any of the four things, Person B isn't choosy, before I go tomorrow", L44),
    ("Bob can take his pick of the cup or the apple, tonight", CELL),
    ("Bob can take his pick of the cup or the apple, after lunch", CELL),
    ("Bob can take his pick of the cup or the apple, on Monday", CELL),
    ("Bob can take his pick of the cup or the apple, in the morning", CELL),
    ("Either mug, Bob doesn't mind, tomorrow", CELL),
    ("Any mug will do for Bob, he's not fussy, tomorrow", CELL),
    ("Either mug to Bob, he likes them both, tomorrow", CELL),
    ("Bob can grab either mug, after lunch", CELL),
    ("Bob gets his pick of the mugs, tomorrow", CELL),
    ("Sam can take his pick of the pens, tomorrow morning", OFFICE),
    ("Either blanket will do for Mr Lee, this evening", WARD),
]


@pytest.mark.parametrize(("text", "scene"), LATER)
def test_later_part_refused(text: str, scene) -> None:
    assert tree(text, scene) is None


@pytest.mark.parametrize(("text", "scene"), LATER[:3] + LATER[7:10])
def test_later_part_check_is_what_refuses(text: str, scene, monkeypatch) -> None:
    _without_check(_rewrites55r._later_part55r, monkeypatch)
    assert tree(text, scene) is not None


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # no later time, or a time said of someone, not of the request: read as before
        ("Bob can take his pick of the cup or the apple", "cup>B | apple>B", CELL),
        (
            "Any of the four things, Person B isn't choosy",
            "bottle>B | chips>B | cup>B | apple>B",
            L44,
        ),
        ("Bob can take his pick of the cup or the apple, he's earned it", "cup>B | apple>B", CELL),
        ("Bob's off tomorrow, so give him the cup.", "cup>B", CELL),
        ("Give Bob the cup now, he's off tomorrow.", "cup>B", CELL),
        # 'in a minute' is soon; 'first thing' alone is an order (blind44 #65)
        ("Give Bob the apple, in a minute.", "apple>B", CELL),
        (
            "First thing, the cup to Person B then Person A can have the chips, she's back from "
            "the autoharp lesson.",
            "cup>B ; chips>A",
            L44,
        ),
    ],
)
def test_later_part_kept(text: str, want: str, scene) -> None:
    got = tree(text, scene)
    assert got is not None and show_tree(got) == want


# _put_where_it_is55r (a check of the reading): a want of things with a place, one of them lying
# there, read as a handing-over AND a placing (main: book_red>A & book_green@shelf)
PUT_WHERE = [
    ("Mrs Ortiz wants both the books on the shelf.", CLASSROOM),
    ("Mrs Ortiz wants both books on the shelf.", CLASSROOM),
    ("Mrs Ortiz wants the red book and the green book on the shelf.", CLASSROOM),
    ("Mrs Ortiz wants the green book and the red book on the shelf.", CLASSROOM),
    ("Noah needs the green book and the red book on the shelf.", CLASSROOM),
    ("Noah would like both books on the shelf, please.", CLASSROOM),
]


@pytest.mark.parametrize(("text", "scene"), PUT_WHERE)
def test_put_where_it_is_refused(text: str, scene) -> None:
    assert tree(text, scene) is None


@pytest.mark.parametrize(("text", "scene"), PUT_WHERE)
def test_put_where_it_is_check_is_what_refuses(text: str, scene, monkeypatch) -> None:
    _without_check(_rewrites55r._put_where_it_is55r, monkeypatch)
    assert tree(text, scene) is not None


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # none of the things lies there, or no handing-over: read as before
        ("Bob wants the cup and the apple on the shelf.", "cup@shelf & apple@shelf", CELL),
        (
            "Mrs Ortiz wants the red book and the globe on the shelf.",
            "book_red@shelf & globe@shelf",
            CLASSROOM,
        ),
        (
            "Mrs Ortiz wants the red book and the green book on the desk.",
            "book_red@desk & book_green@desk",
            CLASSROOM,
        ),
        ("Mrs Ortiz wants both the books.", "book_red>A & book_green>A", CLASSROOM),
        (
            "Mrs Ortiz wants the green book; put the red book on the shelf.",
            "book_green>A & book_red@shelf",
            CLASSROOM,
        ),
    ],
)
def test_put_where_it_is_kept(text: str, want: str, scene) -> None:
    got = tree(text, scene)
    assert got is not None and show_tree(got) == want


# _or_asked55r (a check of the reading): a choice read where 'or' opens a question (12c's probe;
# main read each as a choice left to the robot)
OR_ASKED = [
    ("Could you give Bob the apple, or does Alice want it?", CELL),
    ("Give Bob the apple, or does Alice want it?", CELL),
    ("Give Bob the apple, or should Alice have it?", CELL),
    ("Give Bob the apple or the cup, or does he want both?", CELL),
    ("Could you bring the lemon to Marco, or does Lena want it?", KITCHEN),
    ("Give Mr Lee the jug, or should Mrs Khan have it?", WARD),
]


@pytest.mark.parametrize(("text", "scene"), OR_ASKED)
def test_or_asked_refused(text: str, scene) -> None:
    assert tree(text, scene) is None


@pytest.mark.parametrize(("text", "scene"), OR_ASKED)
def test_or_asked_check_is_what_refuses(text: str, scene, monkeypatch) -> None:
    _without_check(_rewrites55r._or_asked55r, monkeypatch)
    assert tree(text, scene) is not None


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # no choice read, or no question: read as before
        ("Could you give Mr Novak the lemon, or is that a bother?", "lemon>C", KITCHEN),
        ("Can you give Bob the cup, or is that a bother?", "cup>B", CELL),
        ("Could you give Bob the cup or the apple?", "cup>B | apple>B", CELL),
    ],
)
def test_or_asked_kept(text: str, want: str, scene) -> None:
    got = tree(text, scene)
    assert got is not None and show_tree(got) == want


# -- blind53: questions ----------------------------------------------------------------------------

# _chance_youd55r: "Any chance you'd give …?" is "Any chance you could give …?"
CHANCE_YOUD = PhrasingCases()
test_chance_youd = CHANCE_YOUD.test(
    (
        "Any chance you'd give Sam the black pen, and the notepad as well?",
        "pen_black>B & notebook>B",
        OFFICE,
    ),
    ("Any chance you'd pass Bob the apple?", "apple>B", CELL),
    ("Any chance you'd bring Mr Lee the jug?", "jug>B", WARD),
    ("Any chance you'd put the sponge in the sink?", "sponge@sink", LAB),
    # near: a want of the hearer's or someone's, asked
    ("Any chance you'd like the apple?", None, CELL),
    ("Any chance Bob'd like the apple?", None, CELL),
)


def test_chance_youd_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CHANCE_YOUD.refused_without((_rewrites55r._chance_youd55r,), monkeypatch)


# _wouldnt_mind55r: "Wouldn't mind handing P X, would you?" is "You wouldn't mind …, would you?"
WOULDNT_MIND = PhrasingCases()
test_wouldnt_mind = WOULDNT_MIND.test(
    ("Wouldn't mind handing Person A her bottle, would you?", "bottle>A", ONE),
    ("Wouldn't mind passing Bob the cup, would you?", "cup>B", CELL),
    ("Wouldn't mind taking Marco the lemon, would you?", "lemon>A", KITCHEN),
    ("Wouldn't mind putting the stapler in the box, would you?", "stapler@box", OFFICE),
    # near: no tag asking the hearer (the speaker's own want), or the tag another's
    ("Wouldn't mind the cup, would you?", None, CELL),
    ("Wouldn't mind passing Bob the cup.", None, CELL),
    ("Wouldn't mind passing Bob the cup, would he?", None, CELL),
)


def test_wouldnt_mind_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WOULDNT_MIND.refused_without((_rewrites55r._wouldnt_mind55r,), monkeypatch)


# _passing_asked55r: "…, when you're passing?" closing a question
PASSING_ASKED = PhrasingCases()
test_passing_asked = PASSING_ASKED.test(
    ("Could Person A get her bottle, please, when you're passing?", "bottle>A", T12),
    ("Could you give Bob the cup, please, when you're passing?", "cup>B", CELL),
    ("Could Mr Lee have the jug when you're going past?", "jug>B", WARD),
    ("Would you put the spoon in the sink when you're passing?", "spoon@sink", LAB),
    ("Could Emma have the banana, please, when you're going past?", "banana>C", LAB),
    # near: someone else passing
    ("Could Bob get the cup when he's passing?", None, CELL),
)


def test_passing_asked_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PASSING_ASKED.refused_without((_rewrites55r._passing_asked55r,), monkeypatch)


# _spare_minute55r: "Got a spare minute to get X across to P?" is "Could you get X across to P?"
SPARE_MINUTE = PhrasingCases()
test_spare_minute = SPARE_MINUTE.test(
    ("Got a spare minute to get the bottle across to Person B?", "bottle>B", DUO),
    ("Got a minute to pass Bob the apple?", "apple>B", CELL),
    ("Have you got a moment to bring Mr Lee the jug?", "jug>B", WARD),
    ("Do you have a sec to put the stapler in the box?", "stapler@box", OFFICE),
    # near: only the time asked, or asked of the past, or a later time with it
    ("Got a minute?", None, CELL),
    ("Got a minute to spare?", None, CELL),
    ("Did you have a minute to give Bob the cup?", None, CELL),
    ("Got a minute to give Bob the cup tomorrow?", None, CELL),
)


def test_spare_minute_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SPARE_MINUTE.refused_without((_rewrites55r._spare_minute55r,), monkeypatch)


# _fit_in55r: "Could you fit in (squeeze in, manage) giving P X?" is "Could you give P X?"
FIT_IN = PhrasingCases()
test_fit_in = FIT_IN.test(
    (
        "Do you think you could fit in giving Person B the chips and Person A the bottle?",
        "chips>B & bottle>A",
        T21,
    ),
    ("Could you fit in giving Person B the chips?", "chips>B", T21),
    ("Could you squeeze in bringing Mr Lee the jug?", "jug>B", WARD),
    ("Would you manage taking Marco the lemon?", "lemon>A", KITCHEN),
    ("Can you find time for putting the stapler in the box?", "stapler@box", OFFICE),
    # near: asked of someone else
    ("Could Bob fit in giving Alice the cup?", None, CELL),
)


def test_fit_in_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FIT_IN.refused_without((_rewrites55r._fit_in55r,), monkeypatch)


# _out_to55r: "the lemon go(es) out to P" / "take the lemon out to P" is "… over to P"
OUT_TO = PhrasingCases()
test_out_to = OUT_TO.test(
    ("Might the lemon go out to Mr Novak, for his fish?", "lemon>C", KITCHEN),
    ("Take the lemon out to Mr Novak.", "lemon>C", KITCHEN),
    ("The salt goes out to Lena.", "salt>B", KITCHEN),
    ("Could the jug go out to Mrs Khan?", "jug>C", WARD),
    ("Bring the cup out to Bob, please.", "cup>B", CELL),
    # near: out to a place that is no person, or said as done
    ("Take the lemon out to the van.", None, KITCHEN),
    ("Marco went out to lunch, give the lemon to Lena.", None, KITCHEN),
    ("The lemon went out to Mr Novak.", None, KITCHEN),
)


def test_out_to_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OUT_TO.refused_without((_rewrites55r._out_to55r,), monkeypatch)


# _come_to55r: "Can the X come (down off the shelf) to P?" is "Can you bring the X … to P?"
COME_TO = PhrasingCases()
test_come_to = COME_TO.test(
    ("Can the green book come down off the shelf to Mrs Ortiz?", "book_green>A", CLASSROOM),
    ("Can the cup come over to Bob?", "cup>B", CELL),
    ("Could the grey blanket come across to Mrs Khan?", "blanket_grey>C", WARD),
    ("Might the stapler come to Sam, please?", "stapler>B", OFFICE),
    # near: a person coming, a place that is no person, said as done, a later time
    ("Can Bob come to the shelf?", None, CELL),
    ("Can the cup come to the shelf?", None, CELL),
    ("The cup came to Bob?", None, CELL),
    ("Can the cup come to Bob tomorrow?", None, CELL),
    # near (12c's probe): asking what will happen, or asking which
    ("Will the apple come to Bob?", None, CELL),
    ("Would the apple come to Bob?", None, CELL),
    ("Could the apple come to Bob, or should it go to Alice?", None, CELL),
    ("Can the apple come to Bob, or is Alice having it?", None, CELL),
)


def test_come_to_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    COME_TO.refused_without((_rewrites55r._come_to55r,), monkeypatch)


# -- blind53: corrections --------------------------------------------------------------------------

# _my_error55r: "my error" / "(argh,) my brain" blame the speaker, as "my mistake" does
MY_ERROR = PhrasingCases()
test_my_error = MY_ERROR.test(
    ("Give the bottle to Alice, argh, my brain, Bob I meant.", "bottle>B", FIG1),
    ("Send the chips Person B's way, no, Person A's, my error.", "chips>A", F42),
    ("Give the lemon to Lena, ugh, my head, Marco I meant.", "lemon>A", KITCHEN),
    ("Take the jug to Mr Lee, no, Mrs Khan, my error.", "jug>C", WARD),
    ("Put the stapler in the box, no, on the desk, my error.", "stapler@desk", OFFICE),
    # near: no correction after it, a holding, the words not between commas
    ("Give the cup to Alice, my brain, hurts.", None, CELL),
    ("Give the cup to Alice, my error.", None, CELL),
    ("Bob had the cup, my error, the apple.", None, CELL),
    ("The cup goes above my head.", None, CELL),
)


def test_my_error_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    MY_ERROR.refused_without((_rewrites55r._my_error55r,), monkeypatch)


# _not_word55r: "The grey blanket for P, not grey, I mean blue" is "…, no, the blue one"
NOT_WORD = PhrasingCases()
test_not_word = NOT_WORD.test(
    ("The grey blanket for Mrs Khan, not grey, I mean blue.", "blanket_blue>C", WARD),
    ("The red mug for Bob, not red, I mean blue.", "mug_blue>B", CELL),
    ("The red mug for Bob, not red, blue.", "mug_blue>B", CELL),
    ("The white plate to Lena, not white, the blue one.", "plate_blue>B", KITCHEN),
    # near: no such thing, both said, a holding
    ("The red mug for Bob, not red, I mean green.", None, CELL),
    ("The red mug for Bob, not red, I mean big.", None, CELL),
    ("The red mug and the blue mug for Bob, not red, I mean blue.", None, CELL),
    ("Bob had the red mug, not red, I mean blue.", None, CELL),
)


def test_not_word_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOT_WORD.refused_without((_rewrites55r._not_word55r,), monkeypatch)


# _surface_for55r: "Tray for the spoon, <cue> …, <correction>" is "The spoon on the tray, …"
SURFACE_FOR = PhrasingCases()
test_surface_for = SURFACE_FOR.test(
    ("Tray for the spoon, no, I've changed my mind, the sink.", "spoon@sink", LAB),
    ("Tray for the bowl, sorry, the sink.", "bowl@sink", LAB),
    ("Shelf for the apple, no, wait, the table.", "apple@table", CELL),
    ("Shelf for the cup, no, it's the apple that goes up there.", "apple@shelf", CELL),
    # near: a person for a thing, a correction that names nothing
    ("Shelf for Bob, no, the apple.", None, CELL),
    ("Table for the cup, no, Bob.", None, CELL),
    ("Table for the cup, no, I'd rather you didn't.", None, CELL),
)


def test_surface_for_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SURFACE_FOR.refused_without((_rewrites55r._surface_for55r,), monkeypatch)


# _goes_on55r: "…, hang on, it's the small box that goes on" is "… that goes there"
GOES_ON = PhrasingCases()
test_goes_on = GOES_ON.test(
    (
        "The medium box on the belt, oh hang on, it's the small box that goes on.",
        "box_small@conveyor",
        DEPOT,
    ),
    ("Put the cup on the shelf, hang on, it's the apple that goes on.", "apple@shelf", CELL),
    ("The spoon in the sink, sorry, it's the bowl that goes in.", "bowl@sink", LAB),
    ("Put the teddy on the play mat, no, it's the bib that goes on there.", "bib@mat", NURSERY),
    # near: no thing of the scene
    ("Put the cup on the shelf, hang on, it's the lid that goes on.", None, CELL),
)


def test_goes_on_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GOES_ON.refused_without((_rewrites55r._goes_on55r,), monkeypatch)


# _um_yes55r: "The bottle goes to, um, yes, P(, no change there)" is "The bottle goes to P"
UM_YES = PhrasingCases()
test_um_yes = UM_YES.test(
    ("The bottle goes to, um, yes, Person A, no change there.", "bottle>A", ONE),
    ("The cup goes to, um, yes, Bob.", "cup>B", CELL),
    ("The jug is for, er, yes, Mr Lee, same as ever.", "jug>B", WARD),
    ("Hand the lemon to, erm, right, Marco.", "lemon>A", KITCHEN),
    # near: no one of the scene, a 'no', a change after a correction
    ("The cup goes to, um, yes, Dave.", None, CELL),
    ("The cup goes to, um, no, Bob.", None, CELL),
    ("Give the cup to Alice, no, Bob, no change there.", None, CELL),
)


def test_um_yes_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    UM_YES.refused_without((_rewrites55r._um_yes55r,), monkeypatch)


# _no_such55r: "…to Person B, silly me, there's no Person B, so Person A" is "…to Person A"
NO_SUCH = PhrasingCases()
test_no_such = NO_SUCH.test(
    ("Take the bottle to Person B, silly me, there's no Person B, so Person A.", "bottle>A", T12),
    ("Give the cup to Dave, oops, there's no Dave here, so Bob.", "cup>B", CELL),
    ("Take the jug to Dr Smith, sorry, there's no Dr Smith, so Mrs Khan.", "jug>C", WARD),
    ("Hand the torch to Sue, whoops, there's no Sue, so Jess.", "torch>B", WORKSHOP),
    # near: the person is in the scene, no one after 'so', a place after 'so'
    ("Give the cup to Alice, sorry, there's no Alice, so Bob.", None, CELL),
    ("Give the cup to Dave, there's no Dave, so Zed.", None, CELL),
    ("Give the cup to Dave, there's no Dave, so the shelf.", None, CELL),
)


def test_no_such_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NO_SUCH.refused_without((_rewrites55r._no_such55r,), monkeypatch)


# _was_it55r: "Was it the X or the Y P wanted? <forgot>" is refused, naming both readings
WAS_IT = [
    (
        "Was it the wipes or the sippy cup Grandad wanted? It's gone right out of my head.",
        ("wipes", "beaker"),
        NURSERY,
    ),
    (
        "Was it the cup or the apple Bob wanted? It's gone clean out of my head.",
        ("cup", "apple"),
        CELL,
    ),
    (
        "Was it the knife or the lemon Lena asked for? It's gone out of my head.",
        ("knife", "lemon"),
        KITCHEN,
    ),
    (
        "Was it the stapler or the notepad Sam needed? It's gone completely out of my head.",
        ("stapler", "notebook"),
        OFFICE,
    ),
]


@pytest.mark.parametrize(("text", "readings", "scene"), WAS_IT)
def test_was_it_names_readings(text: str, readings: tuple[str, ...], scene) -> None:
    with pytest.raises(GroundingError) as refused:
        offline.parse_instruction(text, scene)
    assert all(r in str(refused.value) for r in readings)
    assert "which" in str(refused.value)


@pytest.mark.parametrize(("text", "readings", "scene"), WAS_IT)
def test_was_it_is_what_names_them(
    text: str, readings: tuple[str, ...], scene, monkeypatch
) -> None:
    kept = tuple(s for s in normalise._STEPS19 if s is not _rewrites55r._was_it55r)
    monkeypatch.setattr(normalise, "_STEPS19", kept)
    with pytest.raises(GroundingError) as refused:
        offline.parse_instruction(text, scene)
    assert "is a question" in str(refused.value)  # the words quoted, no readings named


@pytest.mark.parametrize(
    "text",
    [
        "Was it the cup or the apple Bob wanted?",
        "Was it the cup or the apple Bob wanted? Give him the cup.",
    ],
)
def test_was_it_question_stays_refused(text: str) -> None:
    assert tree(text, CELL) is None
