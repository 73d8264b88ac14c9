"""Session-34 phrasings of issue 12 (engineer 12r): blind32's choices, counts, negation,
exclusions and corrections, and its two refusals without their readings; docs/grounding.md,
"Session 34 (engineer 12r)". Each rule with the sentences it changes and near forms that must stay
refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.grounding import normalise
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
    assert_refused,
)

# the example scenes session 32's tests load (bottle, chips, cup, apple; people A and B; …)
from tests.grounding.test_phrasing_s32r import (
    DUO,
    F41,
    F42,
    FIG1,
    L24,
    L44,
    ONE,
    SQ,
    T12,
    T21,
    TWO,
)

CASES = PhrasingCases()


# -- corrections ----------------------------------------------------------------------------------


test_corrections = CASES.test(
    # 'final answer' closing a correction
    ("Drill to Jess, no, Kofi, final answer.", "drill>A", WORKSHOP),
    ("The cup to Person A, sorry, Person B, final answer.", "cup>B", SQ),
    ("Drill to Kofi, final answer.", None, WORKSHOP),  # no correction before it
    # '…, sorry, on the tray is better'
    ("The spoon in the sink, oh no, sorry, on the tray is better.", "spoon@tray", LAB),
    (
        "Medium box on the pallet, no, on the belt would be better.",
        "box_medium@conveyor",
        DEPOT,
    ),
    ("The spoon in the sink, on the tray is better.", None, LAB),  # no correction cue
    # "it's P who's meant to get it"
    (
        "Over to Person A with the cup, hmm, no, it's Person B who's meant to get it.",
        "cup>B",
        SQ,
    ),
    (
        "Over to Person B with the apple, no, it's Person A who's supposed to get it.",
        "apple>A",
        SQ,
    ),
    ("It's Person C who's meant to get the cup.", None, SQ),  # no Person C in the scene
    # "ugh, wrong one, she's been after the X all along"
    (
        "Chips for Person A, ugh, wrong one, she's been after the bottle all along.",
        "bottle>A",
        DUO,
    ),
    ("The chips for Bob, sorry, he's been after the bottle all along.", "bottle>B", TWO),
    # without a correction 'all along' could add the bottle or replace the chips
    ("Chips for Person A, she has been after the bottle all along.", None, DUO),
    ("Chips for Person A, ugh, wrong one, she's been after the banana all along.", None, DUO),
    # "First I said X, but …"
    (
        "First I said chips, but Person A is actually after the apple, so give her that.",
        "apple>A",
        L44,
    ),
    (
        "At first I said the cup, but Person B is actually after the bottle, so give her that.",
        "bottle>B",
        SQ,
    ),
    # X not of the scene; X named again in the request
    (
        "First I said banana, but Person A is actually after the apple, so give her that.",
        None,
        L44,
    ),
    ("First I said chips, but Person A is actually after the chips and the apple.", None, L44),
    # a placement without its verb, then a whole new request
    ("Crisps on the shelf, actually no, give them to Bob.", "chips>B", FIG1),
    ("The crisps on the shelf, hmm, no, hand them to Alice.", "chips>A", FIG1),
    ("Crisps on the table, actually no, give them to Bob.", None, FIG1),  # no table
    # 'there's only her here' with one person in the scene
    ("Bottle to Person B, no, Person A, there's only her here.", "bottle>A", T12),
    ("Bottle to Person B, no, Person A, there's only her here.", None, DUO),  # two people
)


def test_a_better_place_the_scene_lacks_is_refused() -> None:
    """'…, sorry, on the floor is better' names a place the scene lacks: refused (it had been
    dropped as a remark, and the spoon put in the sink, the place corrected away)."""
    assert_refused("The spoon in the sink, sorry, on the floor is better.", LAB, "'floor'")


# -- choices --------------------------------------------------------------------------------------


test_choices = CASES.test(
    (
        "Whichever of Person A and Person B is closer gets the bottle.",
        "bottle>A | bottle>B",
        DUO,
    ),
    ("Whichever of Alice and Bob is nearer to you gets the crisps.", "chips>A | chips>B", TWO),
    ("Whichever of Person A and Person B is hungrier gets the bottle.", None, DUO),
    ("Whichever of Person A and Person C is closer gets the bottle.", None, DUO),
    (
        "Something to eat for Person A, apple or chips, pick whichever you like.",
        "apple>A | chips>A",
        F41,
    ),
    ("Something to drink for Person B, the bottle or the cup.", "bottle>B | cup>B", SQ),
    ("Give Person B the bottle or the cup, pick either one.", "bottle>B | cup>B", SQ),
    ("Something to eat for Person A, apple or banana, pick whichever you like.", None, F41),
    ("The apple for Person A, pick whichever you like.", None, F41),  # nothing to pick from
    (
        "Scissors to either of the students, Zoe or Noah, doesn't matter.",
        "scissors>C | scissors>B",
        CLASSROOM,
    ),
    # Mrs Ortiz is no student
    ("Scissors to either of the students, Zoe or Mrs Ortiz, doesn't matter.", None, CLASSROOM),
    (
        "Either patient can have the magazine, they both like the puzzles.",
        "magazine>B | magazine>C",
        WARD,
    ),
    # the remark names another object of the scene
    ("Either patient can have the magazine, they both like the blanket.", None, WARD),
    (
        "One for Person A, one for Person B, that's the apple and the cup; who gets which is "
        "up to you.",
        "(apple>A & cup>B) | (apple>B & cup>A)",
        SQ,
    ),
    (
        "One for Alice, one for Bob, that's the crisps and the bottle.",
        "(chips>A & bottle>B) | (chips>B & bottle>A)",
        TWO,
    ),
    ("One for Person A, one for Person B, that's the apple and the banana.", None, SQ),
    ("One for Person A, one for Person A, that's the apple and the cup.", None, SQ),
    (
        "Split it up so Person A ends up with the bottle and Person B ends up with the cup.",
        "bottle>A & cup>B",
        F42,
    ),
    ("Split it up so Person A ends up with the bottle.", None, F42),  # nothing split
    ("Any bottle you can lay hands on, give it to Person A.", "bottle>A", ONE),
    ("Any mug you can get your hands on, give it to Bob.", "mug_red>B | mug_blue>B", CELL),
    ("Any banana you can lay hands on, give it to Person A.", None, ONE),
    (
        "There's a lone bottle in this cell and Person A is the one to have it.",
        "bottle>A",
        T12,
    ),
    # two mugs: the count is wrong; no Person C
    ("There's a lone mug in this cell and Bob is the one to have it.", None, CELL),
    ("There's a lone bottle here and Person C is the one to have it.", None, DUO),
    (
        "Nobody goes without: Person A gets handed the bottle, Person B the bag of chips.",
        "bottle>A & chips>B",
        T21,
    ),
    ("Person A gets handed the bottle.", "bottle>A", T21),
    ("Nobody goes without: Person A gets handed the bottle.", None, T21),  # B goes without
)


# -- counts ---------------------------------------------------------------------------------------


test_counts = CASES.test(
    (
        "Both mugs need shifting up to the shelf, the red and the blue alike.",
        "mug_red@shelf & mug_blue@shelf",
        CELL,
    ),
    ("Both mugs up to the shelf, the red and the green alike.", None, CELL),
    ("Hand everything we've got, both the items, over to Person A.", "bottle>A & chips>A", DUO),
    # four things, not both
    ("Hand everything we've got, both the items, over to Person A.", None, SQ),
    ("One bottle, one person: bottle to Person A.", "bottle>A", T12),
    ("One bottle, one person: bottle to Person A.", None, T21),  # two people
    ("One mug, one person: mug to Person A.", None, CELL),
    (
        "Ava's building a tower so she needs the pair of blocks, red and green.",
        "block_red>C & block_green>C",
        NURSERY,
    ),
    ("Ava needs the pair of blocks, red and blue.", None, NURSERY),
    (
        "The locker's where the two spanners live, so in they go.",
        "spanner_small@locker & spanner_large@locker",
        WORKSHOP,
    ),
    ("The locker's where the three spanners live, so in they go.", None, WORKSHOP),
    ("The shed's where the two spanners live, so in they go.", None, WORKSHOP),
)


# -- negation and exclusion -----------------------------------------------------------------------


test_negation_and_exclusion = CASES.test(
    ("Carol asked for a mug, anything but the red one.", "mug_blue>C", CELL),
    ("Sam asked for a pen, anything but the blue one.", "pen_black>B | pen_red>B", OFFICE),
    ("Carol asked for anything but the red one.", None, CELL),  # anything of what kind?
    ("Carol asked for a mug, anything but the green one.", None, CELL),
    ("Leaving the crisps aside, Bob can take what's left.", "bottle>B", FIG1),
    (
        "Leaving the chips aside, Person B can take what's left.",
        "bottle>B & cup>B & apple>B",
        SQ,
    ),
    ("Leaving the banana aside, Bob can take what's left.", None, FIG1),
    ("Only Person B gets anything today, and it's the chips.", "chips>B", F42),
    ("Only Person C gets anything today, and it's the chips.", None, F42),
    ("Only Person B gets anything today, and it's the banana.", None, F42),
    ("No fuss, nothing else, just the bottle for Person A.", "bottle>A", ONE),
    ("Nothing fancy, no glass, just the bottle for Person A.", "bottle>A", T12),
    ("No cup, just the bottle for Person A.", "bottle>A", SQ),
    # the thing said not wanted is the one asked for
    ("Nothing fancy, no bottle, just the bottle for Person A.", None, T12),
    ("No bottle, just the bottle for Person A.", None, ONE),
    ("Person B, not Person A, is the one getting the chips.", "chips>B", T21),
    ("Person B, not Person B, is the one getting the chips.", None, T21),
    ("Lena wants the plate, but not the one on the plate rack.", "plate_white>B", KITCHEN),
    # neither plate is on the counter
    ("Lena wants the plate, but not the one on the counter.", None, KITCHEN),
    ("Zoe wants to read the book that isn't green.", "book_red>C", CLASSROOM),
    ("Zoe wants to read the book.", None, CLASSROOM),  # which book
    ("Zoe wants to read the newspaper.", None, CLASSROOM),
)


# -- the same kinds in blind19 and blind20 ------------------------------------------------


test_blind19_and_blind20_kinds = CASES.test(
    # the owner said between the object and 'hand it to him'
    ("Whichever cup isn't the green one, that's Omar's, hand it to him.", "cup_white>B", LAB),
    (
        "The book that's lying about, not the one up on the bookshelf, is Zoe's, give it her.",
        "book_red>C",
        CLASSROOM,
    ),
    # 'him' cannot be Mrs Khan (a title says who is who)
    ("The magazine on the bed, that's Mrs Khan's, hand it to him.", None, WARD),
    # a note 'Shelf for the bottle' before a correction
    ("Shelf for the bottle, please, or no, better still, straight to Alice.", "bottle>A", FIG1),
    ("Shelf for the bottle, please, or no, better still, straight to Carol.", None, FIG1),
    ("Table for the bottle, please, or no, straight to Alice.", None, FIG1),  # no table
    ("Bottle on the shelf, no wait, to Alice.", "bottle>A", TWO),
    ("Bottle on the shelf, no wait, to Carol.", None, TWO),
    # the better place said twice
    (
        "Sponge on the tray... actually no, sink's better, put it in the sink.",
        "sponge@sink",
        LAB,
    ),
    ("Sponge on the tray... actually no, tray's better, put it in the sink.", None, LAB),
    # the speaker's reason for what is left out
    (
        "Clear the lot into the locker, bar the drill and the hammer, I still need those.",
        "spanner_small@locker & screws@locker & torch@locker & spanner_large@locker",
        WORKSHOP,
    ),
    ("Clear the lot into the locker, I still need those.", None, WORKSHOP),
    # 'X's no good, so one of the others'
    (
        "Sam's after a pen. Red's no good for forms, so one of the others.",
        "pen_black>B | pen_blue>B",
        OFFICE,
    ),
    ("Omar's after a cup. Green's no good, so one of the others.", "cup_white>B", LAB),
    ("Sam's after a pen. Green's no good for forms, so one of the others.", None, OFFICE),
    # 'Not the red one, the other' with two of the kind
    (
        "Lily wants a block to chew on. Not the red one, love, the other.",
        "block_green>A",
        NURSERY,
    ),
    ("Lily wants a block to chew on. Not the blue one, love, the other.", None, NURSERY),
    ("Sam wants a pen. Not the red one, the other.", None, OFFICE),  # three pens
    # a person named by role and place, then by name
    (
        "The guest on table five, Mr Novak, gets the white plate, not the blue.",
        "plate_white>C",
        KITCHEN,
    ),
    ("The guest on table five, Lena, gets the white plate, not the blue.", None, KITCHEN),
    # the order said again
    (
        "The cup and then the apple to Person B, or rather the apple first and then the cup.",
        "apple>B ; cup>B",
        F41,
    ),
    (
        "The cup and then the apple to Person B, or rather the apple first and then the bottle.",
        None,
        F41,
    ),
    (
        "Cup to Person A, then the apple to Person B; no, hang on, swap the order round, "
        "apple to Person B first and the cup after.",
        "apple>B ; cup>A",
        F42,
    ),
    (
        "Cup to Person A, then the apple to Person B; no, hang on, swap the order round, "
        "apple to Person A first and the cup after.",
        None,
        F42,
    ),
    # a heading for the two people of the scene
    (
        "They both want something. Bottle over to Person A please, and cup across to Person B.",
        "bottle>A & cup>B",
        F41,
    ),
    ("They both want something. Bottle over to Person A please.", None, F41),
    # 'Everything that's a box', and the one left out staying where it starts
    (
        "Everything that's a box goes on the conveyor, except the big one, leave that on the "
        "pallet.",
        "box_small@conveyor & box_medium@conveyor",
        DEPOT,
    ),
    (
        "Everything that's a box goes on the conveyor, except the small one, leave that on "
        "the pallet.",
        None,
        DEPOT,
    ),
    # counted plurals wanting to go somewhere
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
    ("Those three mugs want to go on the counter, please.", None, CELL),
)


# -- the same kinds in blind19 and blind24 to blind31 ---------------------------------------------


test_blind24_to_blind31_kinds = CASES.test(
    # "she's got one" after a correction cue, the request after it for another person
    (
        "The stapler's for Priya. Oh hang on, she's got one, give it to Sam.",
        "stapler>B",
        OFFICE,
    ),
    ("The stapler's for Priya. Oh hang on, she's got one, give it to Priya.", None, OFFICE),
    ("The magazine's for Mr Lee. Oh hang on, she's got one, give it to Mrs Khan.", None, WARD),
    # 'alike' after a list without 'the'
    (
        "Wash-up time: both cups into the sink, green and white alike.",
        "cup_green@sink & cup_white@sink",
        LAB,
    ),
    ("Both cups into the sink, green and blue alike.", None, LAB),
    # the reason after a correction
    (
        "The white plate on the rack, no, the counter, we need it for service.",
        "plate_white@counter",
        KITCHEN,
    ),
    ("The white plate on the rack, we need it for service.", None, KITCHEN),  # no correction
    # 'Split the two things between them'
    (
        "Split the two things between them, one apiece, with the bottle going to Person B and "
        "the chips to Person A.",
        "bottle>B & chips>A",
        T21,
    ),
    (
        "Split the two things between them, one apiece, with the bottle going to Person B.",
        None,
        T21,
    ),
    (
        "Split the two things between them, one apiece, with the bottle going to Person B and "
        "the bottle to Person A.",
        None,
        T21,
    ),
    # 'Not the X for P, he's after Y'
    (
        "Not the bottle for Bob, he said so twice, he's after a packet of crisps.",
        "chips>B",
        TWO,
    ),
    ("Not the bottle for Bob, he's after a packet of biscuits.", None, TWO),
    ("Not the jug for Mrs Khan, he's after the magazine.", None, WARD),  # 'he' is not Mrs Khan
    # 'straight to P with it' after a correction
    (
        "Pop the bottle up on the shelf — actually, on second thoughts, straight to Alice with it.",
        "bottle>A",
        FIG1,
    ),
    (
        "Pop the bottle up on the shelf — actually, on second thoughts, straight to Carol with it.",
        None,
        FIG1,
    ),
    # 'she said black, the black pen'
    (
        "Priya wants the red pen — wait, no, she said black, the black pen.",
        "pen_black>A",
        OFFICE,
    ),
    ("Priya wants the red pen — wait, no, she said green, the green pen.", None, OFFICE),
    # why of the surface corrected away
    (
        "The ruler goes on the desk. Sorry, the bookshelf, the desk's covered in paint.",
        "ruler@shelf",
        CLASSROOM,
    ),
    (
        "The ruler goes on the desk. Sorry, the bookshelf, the bookshelf's covered in paint.",
        None,
        CLASSROOM,
    ),
    # 'can join the big one on S' when the big one starts there
    (
        "The two smaller boxes can join the big one on the pallet.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    ("The two smaller boxes can join the big one on the conveyor.", None, DEPOT),
    # why the thing is left out
    (
        "Don't bother with the bottle, she's brought a flask, just the chips to Person A.",
        "chips>A",
        DUO,
    ),
    # 'whichever one's closer to P, give her that'
    ("whichever ones closer to person a, give her that", "bottle>A | chips>A", L24),
    ("whichever ones closer to person c, give her that", None, L24),
    # 'and the X stays where it is'
    (
        "Person B gets the bottle and Person A gets the chips and the apple stays where it is.",
        "bottle>B & chips>A",
        F42,
    ),
    # the bottle is asked for and said to stay
    (
        "Person B gets the bottle and Person A gets the chips and the bottle stays where it is.",
        None,
        F42,
    ),
    # "It's P who's getting X, not Q, <remark>"
    (
        "It's Person B who's getting the cup, not Person A, the caddie got it wrong earlier.",
        "cup>B",
        L44,
    ),
    (
        "It's Person B who's getting the cup, not Person A, the apple got it wrong earlier.",
        None,
        L44,
    ),
    # 'better down on S (with her)' after a correction
    (
        "Sit the teddy in the high chair, no, better down on the play mat with her.",
        "teddy@mat",
        NURSERY,
    ),
    ("Sit the teddy in the high chair, no, better down on the floor with her.", None, NURSERY),
    # 'Over to P with X' before a correction of the object
    (
        "Over to Person B with the chips, no, I mean the bottle, it's the bottle she's after.",
        "bottle>B",
        DUO,
    ),
    ("Over to Person B with the chips, no, I mean the banana.", None, DUO),
    # blind18: 'Both of the mugs are Alice's, give her the pair.'
    ("Both of the mugs are Alice's, give her the pair.", "mug_red>A & mug_blue>A", CELL),
    ("Both of the cups are Alice's, give her the pair.", None, CELL),  # one cup
    # 'Two things going out:' and 'the bottle is Person B's' under it
    (
        "Two things going out: Person A has the chips and the bottle is Person B's.",
        "chips>A & bottle>B",
        T21,
    ),
    ("Three things going out: Person A has the chips and the bottle is Person B's.", None, T21),
)


# -- refusals that name their readings ------------------------------------------------------------


def test_it_after_a_description_of_the_person_names_its_readings() -> None:
    """'the one by the window' describes Person B only (it names nothing of the scene): the
    refusal is the pronoun's, with the objects 'it' could mean (it had been refused on 'one')."""
    assert_refused("Give it to Person B, the one by the window.", T21, "bottle or chips")
    assert_case("Give the bottle to Person B, the one by the window.", "bottle>B", T21)
    # a description naming an object of the scene is left, and refused
    assert_refused("Give the bottle to Person B, the one by the chips.", T21)


def test_a_recipient_them_names_the_people() -> None:
    """A recipient 'them' no one named before may be a singular 'they': the refusal names the
    people of the scene (it had said only that 'them' cannot be a recipient)."""
    for text in ("just give them the bottle, the one who asked", "give them the bottle"):
        assert_refused(text, L24, "Person A or Person B")


def test_refused_without_these_steps(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence these rules read is refused with the session-34 (12r) steps taken out: each
    rule is what reads it."""
    # session 51 (12r; at the merge): its rules of the same families read some of these too
    CASES.refused_without((*normalise._STEPS34R, *normalise._STEPS51R), monkeypatch)
