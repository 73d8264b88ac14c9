"""Session-30 phrasings of issue 12 (engineer 12): blind28's refusals by kind in its sections of
politeness, wants, pronouns and ellipsis, sentence splits, lower case and questions
(docs/grounding.md, "Session 30 (engineer 12)"). Each rule with sentences it reads (which fail
with the rule taken out) and near sentences that must stay refused or read otherwise."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import show_tree
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.update import classify
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    NURSERY,
    OFFICE,
    ROOT,
    WORKSHOP,
    assert_reads,
    assert_refused,
    tree,
)

DUO = load_scene(ROOT / "examples/scenes/2-2.yaml")  # bottle, chips; Person A, Person B

READS = [
    # (a) a closing 'next' of one task is 'Next, …': now (an update: 'then')
    ("The torch to Jess next, please.", "torch>B", WORKSHOP),
    ("Can the small box go onto the belt next?", "box_small@conveyor", DEPOT),
    ("The red mug on the shelf next.", "mug_red@shelf", CELL),
    # (b) 'by any chance' in a question; "D'you"
    ("Could you pop the apple on the shelf, by any chance?", "apple@shelf", CELL),
    ("Could you, by any chance, hand Bob the chips?", "chips>B", CELL),
    ("D'you mind handing Bob the chips?", "chips>B", CELL),
    # (c) leave for P to take X: P has X
    ("Would it be OK if Bob took the chips off you?", "chips>B", CELL),
    ("Would that be fine if Alice got the apple?", "apple>A", CELL),
    # (d) 'run' carrying, after 'so' and as 'running'
    ("Sam forgot the stapler, so run it over to him.", "stapler>B", OFFICE),
    ("Any chance of running the apple across to Alice?", "apple>A", CELL),
    # (e) 'how about X going to P'
    ("How about the apple going over to Alice?", "apple>A", CELL),
    ("What about the chips going to Bob?", "chips>B", CELL),
    # (f) 'then' and 'after it / after that (is done)' around one task
    (
        "Bob gets the chips first then Alice gets the apple after that is done",
        "chips>B ; apple>A",
        CELL,
    ),
    ("Could Bob have the chips first, then after it the apple?", "chips>B ; apple>B", CELL),
    # (g) the speaker introducing themself
    ("Hi, it's the distiller from upstairs, the apple for Bob please.", "apple>B", CELL),
    ("Sorry, the cooper again, could Alice have the apple?", "apple>A", CELL),
    # (h) idioms of wanting (a closed list), 'ever since', a state before the want
    ("Alice could murder a cuppa, so the water bottle, please.", "bottle>A", CELL),
    ("Carol has had her eye on the red mug.", "mug_red>C", CELL),
    ("Noah's grizzling for the ruler.", "ruler>B", CLASSROOM),
    ("Carol has had her eye on the red mug ever since the meeting.", "mug_red>C", CELL),
    ("Bob's peckish and wants the chips.", "chips>B", CELL),
    # (i) why the want presses, said after it
    ("Alice wants the apple; she won't settle till she's got it.", "apple>A", CELL),
    ("Lily wants the teddy; she won't sleep until she's got it.", "teddy>A", NURSERY),
    # (j) 'needs something to eat, the X'll do'
    ("Alice needs something to drink, the water bottle will do.", "bottle>A", CELL),
    ("Alice needs something to eat, the apple or the chips will do.", "apple>A | chips>A", CELL),
    # (k) an object wanted 'set / left out on' a surface; 'for …' opening without a comma
    ("Carol wants her red mug set out on the shelf.", "mug_red@shelf", CELL),
    ("For the spelling test Noah would like the ruler put on the desk.", "ruler@desk", CLASSROOM),
    # (l) the object put first in a cleft
    ("It's the apple that Alice wants, not the chips.", "apple>A", CELL),
    # (m) 'The X. Over to P.'; 'grab the X take it to P'
    ("The apple. Over to Alice.", "apple>A", CELL),
    ("The apple. Over to the shelf.", "apple@shelf", CELL),
    ("grab the apple take it to Alice", "apple>A", CELL),
    # (n) a numbered place after a person; 'all', then what it is
    ("marco at table 3 needs the lemon", "lemon>A", KITCHEN),
    ("Mr Novak at table four gets the salt shaker", "salt>C", KITCHEN),
    ("everything goes to person b, that's the bottle and the chips", "bottle>B & chips>B", DUO),
    # (o) 'while you're over there': the hearer passing
    (
        "The chips to Bob, and while you're over there the apple for him too.",
        "chips>B & apple>B",
        CELL,
    ),
    # (p) a state said with 'need(s) …ing' of what the scene does not name, asking nothing
    (
        "The two cooks need feeding: bottle for Person A, chips for Person B.",
        "bottle>A & chips>B",
        DUO,
    ),
    ("Mind popping the apple on the shelf? The cooper's crates need sealing.", "apple@shelf", CELL),
    # (q) 'while' between two tasks; the trade said to be P, then a pronoun
    ("Give Bob the cup, while the chips go to Alice.", "cup>B & chips>A", CELL),
    ("The cooper's Bob and he's getting the apple.", "apple>B", CELL),
    # (r) a pronoun, then its name; a note said with 'and' after notes
    ("The chips go to Bob, and the apple, well, him again, Bob.", "chips>B & apple>B", CELL),
    ("Apple: Alice. Cup: Bob. And the chips, also Carol.", "apple>A & cup>B & chips>C", CELL),
    # (s) 'P can take X' in a later clause; a state's cause before 'so'; a remark on 'it'
    ("Alice gets the apple, then Bob can take the chips.", "apple>A ; chips>B", CELL),
    (
        "Alice gets the apple, and once that's done Bob can take his chips.",
        "apple>A ; chips>B",
        CELL,
    ),
    ("bob is hungry after the match so he wants the chips", "chips>B", CELL),
    ("Could the apple go on the shelf? The juice is sticky on it.", "apple@shelf", CELL),
    # (t) the way an object is carried, before where it goes
    ("Take the apple along the corridor to Alice.", "apple>A", CELL),
    ("Could you carry the chips down the hall to Bob?", "chips>B", CELL),
    # (u) what the request is for, with a subject the scene does not name
    ("Put the chips on the shelf so the dog can't reach them.", "chips@shelf", CELL),
]


@pytest.mark.parametrize(("text", "want", "scene"), READS)
def test_blind28_kinds_read(text: str, want: str, scene: object) -> None:
    assert_reads(text, want, scene)  # type: ignore[arg-type]


REFUSED = [
    # (a) 'next' with nothing to do, or 'next to'
    ("The torch next.", WORKSHOP),
    # (b) a question of what is so stays a question
    ("Is the apple on the shelf, by any chance?", CELL),
    ("Did Bob get the chips by any chance?", CELL),
    ("D'you know where the chips are?", CELL),
    # (c) taken to someone else, or off a surface or a person: not the robot letting go
    ("Would it be OK if Bob took the chips to Alice?", CELL),
    ("Would it be OK if Bob took the chips off the shelf?", CELL),
    ("Would it be OK if Bob took the chips off Alice?", CELL),
    # (d) 'run' with no object of the scene
    ("Any chance of running the numbers for Alice?", CELL),
    ("Bob is waiting, so run to him.", CELL),
    # (e) a person going somewhere, or no place at all
    ("How about Alice going to the shelf?", CELL),
    ("How about the apple?", CELL),
    # (g) a name of the scene is no introduction; one said without 'it's' or 'again' is left
    ("It's the shelf again, the apple for Bob.", CELL),
    ("Hi, the cooper, the apple for Bob.", CELL),
    ("It's the cooper, he wants the apple.", CELL),
    # (h) an idiom with a person after it, or with nothing to give
    ("Alice could murder Bob.", CELL),
    ("Carol has her eye on Bob.", CELL),
    ("Alice could murder a drink.", CELL),
    ("Give Bob the chips ever since Alice got the apple.", CELL),
    ("Carol wants the red mug ever since it was washed.", CELL),
    ("Bob's first and wants the chips.", CELL),
    ("Bob's hungry and Alice wants the chips.", CELL),
    # (i) the reason names an object, another person, or two people could be 'she'
    ("Alice wants the apple; she won't settle till she's got the cup.", CELL),
    ("Alice wants the apple; Bob won't settle till he's got it.", CELL),
    ("Alice wants the apple and Bob the chips; she won't settle till she's got it.", CELL),
    # (j) a person will not do
    ("Alice needs something to eat, Bob will do.", CELL),
    # (k) set out on a person; 'for' an object of the scene; no person after the opener
    ("Carol wants the red mug set out on Bob.", CELL),
    ("For the ruler Noah would like the globe.", CLASSROOM),
    ("For the spelling test the ruler on the desk.", CLASSROOM),
    # (l) what the person wants it for follows: not the cleft's want
    ("It's the apple that Alice wants to give Bob.", CELL),
    ("It's the apple that the shelf wants.", CELL),
    # (m) two people after 'over to'; an unclear object; nowhere for it to go
    ("The apple. Over to Alice and Bob.", CELL),
    ("The mug. Over to Alice.", CELL),
    ("grab the mug take it to Alice", CELL),
    ("grab the apple take it", CELL),
    # (n) a place of the scene after the person; a list that is not everything
    ("Bob at table four wants the cup", CELL),
    ("everything goes to person b, that's the bottle", DUO),
    ("everything goes to person b, that's the bottle and person a", DUO),
    # the tails fuzz (seed 32): a deferring time after the list is no item of it
    ("everything goes to person b, that's the bottle and the chips, before I go tomorrow", DUO),
    # (p) a count the people after the colon do not match; an object of the scene needing it
    ("The two cooks need feeding: bottle for Person A.", DUO),
    ("The cups need washing: the red mug to Alice.", CELL),
    ("The stagehands need feeding.", CELL),
    # (q) no task before 'while', or nowhere of the scene after it; a pronoun that cannot be P
    ("Give Bob the cup, while the chips go to the kitchen.", CELL),
    ("Bob is waiting, while the chips go to Alice.", CELL),
    ("The diner's Mr Novak and she's getting the salt shaker.", KITCHEN),
    ("The red's Bob and he's getting the apple.", CELL),
    # (r) the name is not the one person named before; a note of two people
    ("The chips go to Bob, and the apple, well, him again, Alice.", CELL),
    ("Give Alice and Bob the chips, and the apple, him again, Bob.", CELL),
    ("Apple: Alice. And the chips, also Bob and Carol.", CELL),
    # (s) X taken on to someone else; the cause names an object; a remark on two objects
    ("Alice gets the apple, then Bob can take the chips to Carol.", CELL),
    ("bob is hungry after the apple so he wants the chips", CELL),
    ("Put the apple and the cup on the shelf. The juice is sticky on it.", CELL),
    ("Mind the apple on the shelf.", CELL),
    # (t) the way is a place of the scene, or points back; nothing carried
    ("Take the apple down the shelf to Alice.", CELL),
    ("Take the apple down the other one to Alice.", CELL),
    ("Walk down the hall to Alice.", CELL),
    # (u) the purpose names someone or something of the scene
    ("Put the chips on the shelf so the red mug can go on the table.", CELL),
    ("Put the chips on the shelf so the dog won't give Bob the apple.", CELL),
    ("Put the chips on the shelf so the dog can't reach the cup.", CELL),
]


@pytest.mark.parametrize(("text", "scene"), REFUSED)
def test_near_sentences_stay_refused(text: str, scene: object) -> None:
    assert_refused(text, scene)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    "text",
    ["Give Kofi the drill and Jess the torch next.", "Give Kofi the drill, Jess the torch next."],
)
def test_next_after_two_tasks_orders_them(text: str) -> None:
    # a 'next' closing two tasks is not taken off: the torch after the drill, never side by side
    assert_reads(text, "drill>A ; torch>B", WORKSHOP)


def test_a_closing_next_is_then_in_an_update() -> None:
    lexicon = Lexicon(WORKSHOP)
    cmd = classify("The torch to Jess next, please.", lexicon)
    assert (cmd.kind, cmd.text) == ("then", "The torch to Jess, please.")
    assert classify("The torch to Jess.", lexicon).kind == "add"
    assert classify("Put the torch next to the drill.", lexicon).kind == "add"


def test_the_reason_names_one_person_of_one_sex() -> None:
    # 'her' and 'he' cannot both be Lily: the reason is not taken off
    assert tree("Lily wants her teddy; he won't sleep until he's got it.", NURSERY) is None


def test_whom_it_is_for_after_a_cue_is_no_reason() -> None:
    # the wrappers fuzz (seed 31) on main df76ad6: the gloves read to Mia, the person corrected
    # away ('it's for Tom' was taken off as a reason between the cue and the corrected words)
    text = "The tape is for Mia. Sorry, my mistake, it's for Tom, no wait, the work gloves"
    assert tree(text, DEPOT) is None or show_tree(tree(text, DEPOT)) == "gloves>B"
    assert_reads("The tape is for Mia. Sorry, my mistake, it's for Tom.", "tape>B", DEPOT)
    assert_reads("Give the bottle to Bob, no wait, Bob's got one, to Alice.", "bottle>A", CELL)
