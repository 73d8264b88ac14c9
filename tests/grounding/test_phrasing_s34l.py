"""Session-34 phrasing of issue 12 (lead): wrong readings the fuzz found (docs/grounding.md,
"Session 34 (lead)").

- 12r's repairs fuzz: "Give Person B, er, I mean Person A the bottle, or no, hang on, the other
  one, you know." (2-4-line) read chips>A. After a correction, 'the other one' of an object the
  only one of its kind could as well correct the recipient; that reading was looked for only
  when one person had been said, and here two were (Person B, taken back at once, and Person A).
  The other person is now the one besides the recipient in force (the last one said), so the
  sentence is refused naming both readings, as it is without the first repair.
- The same fuzz: "Either of them can have the bottle, uh, no, the chips, Alice or Bob, makes no
  odds." (two_arms) read chips>A | bottle>A | bottle>B. A correction said as the whole request
  again replaces the clause before it when it names that clause's objects, 'it' standing for
  its one object; the 'it' of "it doesn't matter" was taken for the bottle. The empty subject of
  a remark on the choice ('it doesn't matter', 'it makes no odds', 'it's all the same', 'it's up
  to …') is no longer read as the object.
- 12c's asides fuzz: "The stapler is for Priya? It's been a long morning." (office) read
  stapler>A, where the question alone is refused: taking off the statement after it ended the
  request with the statement's full stop. A statement said as a sentence of its own leaves the
  request its own end.
- 12c's deferrals fuzz: "The cup goes to Person B, the chips go to Person A, the apple stays
  where it is. Nothing else after that." (4-2) read cup>B ; chips>A: 'nothing else' was a
  filler and 'after that' ordered the clause before it after the one before that. 'nothing
  (else/more) after that/this' is one closing filler.
- 12's frames fuzz: "Sorry, could Bob have one of the mugs? Either is fine, sorry. What Carol
  needs is the water bottle." read bottle>C: the closing ', sorry.' was taken for a correction
  cue, and the sentence after it replaced the whole request. A bare apology closing its
  sentence, before a sentence that asks for something by its own verb, is an apology, as the
  grammar already read "…, sorry. Carol needs the bottle."; '…, sorry. Carol.' and '…, sorry,
  Carol needs the bottle.' are corrections still.
- 12c's wrappers fuzz: "The bowl, which Omar has been asking about, should go to her and that's
  us done" (lab) read bowl>B: 'her' before 'and' was not counted as the object, so the check
  that a first name rules out a he / she (12s) never saw it."""

from __future__ import annotations

import pytest

from hltl.world.scene import load_scene
from tests.grounding.helpers import OFFICE, ROOT, assert_reads, assert_refused

L24 = load_scene(ROOT / "examples/scenes/2-4-line.yaml")
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")
F42 = load_scene(ROOT / "examples/scenes/4-2.yaml")


@pytest.mark.parametrize(
    "text",
    [
        "Give Person B, er, I mean Person A the bottle, or no, hang on, the other one, you know.",
        "Give Person B, no, Person A the bottle, or no, the other one.",
        "Give Person B, no, Person A the bottle. No, the other one.",
        "Give Person A the bottle, or no, hang on, the other one, you know.",
        "Give Person A, sorry, Person B the chips, no, wait, the other one.",
    ],
)
def test_the_other_one_after_a_repaired_recipient_is_refused(text: str) -> None:
    assert_refused(text, L24, match="could mean")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Person B, er, I mean Person A the bottle.", "bottle>A"),
        ("Give Person B, no, Person A the bottle, or no, the chips.", "chips>A"),
        ("Give Person B, no, Person A the bottle, or no, Person B.", "bottle>B"),
    ],
)
def test_a_repair_that_names_what_it_means_still_reads(text: str, want: str) -> None:
    assert_reads(text, want, L24)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Either of them can have the bottle, uh, no, the chips, Alice or Bob, makes no odds.",
            "chips>A | chips>B",
        ),
        ("Either of them can have the bottle, no, the chips, Alice or Bob.", "chips>A | chips>B"),
        ("Chips to Alice, no, sorry, give it to Bob.", "chips>B"),
        ("Give Alice the chips, no, sorry, give it to Bob, it's Bob's.", "chips>B"),
    ],
)
def test_the_it_of_a_remark_on_the_choice_is_not_the_object(text: str, want: str) -> None:
    assert_reads(text, want, TWO)


def test_a_question_keeps_its_end_before_a_statement() -> None:
    assert_refused("The stapler is for Priya? It's been a long morning.", OFFICE, match="question")
    assert_refused("The stapler is for Priya?", OFFICE, match="question")
    assert_reads("The stapler is for Priya. It's been a long morning.", "stapler>A", OFFICE)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "The cup goes to Person B, the chips go to Person A, the apple stays where it is. "
            "Nothing else after that.",
            "cup>B & chips>A",
        ),
        (
            "The cup goes to Person B, the chips go to Person A, nothing else after that.",
            "cup>B & chips>A",
        ),
        (
            "The cup goes to Person B and the chips go to Person A. Nothing more after this.",
            "cup>B & chips>A",
        ),
        # an order said stays
        (
            "The cup goes to Person B, then the chips go to Person A, nothing else after that.",
            "cup>B ; chips>A",
        ),
        ("The cup goes to Person B, the chips go to Person A after that.", "cup>B ; chips>A"),
    ],
)
def test_nothing_else_after_that_closes_without_an_order(text: str, want: str) -> None:
    assert_reads(text, want, F42)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Sorry, could Bob have one of the mugs? Either is fine, sorry. What Carol needs is the "
            "water bottle.",
            "(mug_red>B | mug_blue>B) & bottle>C",
        ),
        ("Bob gets the chips, sorry. What Carol needs is the water bottle.", "chips>B & bottle>C"),
        ("Bob gets the chips, sorry. Carol needs the water bottle.", "chips>B & bottle>C"),
        # corrections still
        ("Give Bob the chips, sorry. Carol.", "chips>C"),
        ("Give Bob the chips, sorry, Carol needs the bottle.", "bottle>C"),
    ],
)
def test_a_closing_apology_before_a_new_request_is_no_correction(text: str, want: str) -> None:
    assert_reads(text, want)


LAB = load_scene(ROOT / "tests/grounding/paraphrase/scenes/lab.yaml")


def test_her_before_and_is_the_object_a_mans_name_cannot_be() -> None:
    # 12c's wrappers fuzz: read bowl>B (Omar), though 'her' cannot be Omar
    text = "The bowl, which Omar has been asking about, should go to her and that's us done"
    assert_refused(text, LAB, match="cannot mean Omar")
    assert_refused("Give Omar the bowl and her the spoon", LAB, match="cannot mean Omar")
    # her own name: read as before
    text = "The bowl, which Dana has been asking about, should go to her and that's us done"
    assert_reads(text, "bowl>A", LAB)
