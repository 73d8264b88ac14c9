"""Session-31 phrasings of issue 12 (engineer 12r): blind29's choices, counts, exclusions and
corrections; docs/grounding.md, "Session 31 (engineer 12r)". Each rule with the sentences it
changes and near forms that must still read as before, read otherwise, or stay refused."""

from __future__ import annotations

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    PhrasingCases,
    assert_refused,
)


def _scene(name: str) -> Scene:
    return load_scene(ROOT / f"examples/scenes/{name}.yaml")


SQ = _scene("4-4-square")  # bottle, chips, cup, apple; A, B
L44 = _scene("4-4-line")  # bottle, chips, cup, apple; A, B, C
F41 = _scene("4-1")  # bottle, chips, cup, apple; A, B
F42 = _scene("4-2")  # bottle, chips, cup, apple; A, B
DUO = _scene("2-2")  # bottle, chips; A, B
L24 = _scene("2-4-line")  # bottle, chips; A, B
ONE = _scene("1-1")  # bottle; A
T12 = _scene("1-2")  # bottle; A
T21 = _scene("2-1")  # bottle, chips; A, B
TWO = _scene("two_arms")  # bottle, chips (crisps); Alice, Bob
DEPOT = load_scene(ROOT / "tests/grounding/paraphrase/scenes/depot.yaml")
WORKSHOP = load_scene(ROOT / "tests/grounding/paraphrase/scenes/workshop.yaml")


CASES = PhrasingCases()


# -- 'one of' before a list: a choice among the list (it had taken the first name only) -------


test_one_of_a_list_is_a_choice = CASES.test(
    # before: every object listed (a wrong reading)
    (
        "Person B can have any one of the cup, the apple and the bottle.",
        "cup>B | apple>B | bottle>B",
        F42,
    ),
    ("Give Person B one of the cup and the apple.", "cup>B | apple>B", F42),
    ("Give Person B either of the cup and the apple.", "cup>B | apple>B", F42),
    (
        "Give one of the cup and the apple to Person B and the bottle to Person A.",
        "(cup>B | apple>B) & bottle>A",
        F42,
    ),
    # the list stops at a person: one clause each
    ("Give Person B one of the cup and Person A the apple.", "cup>B & apple>A", F42),
    # a plural first: one of them, and the apple
    ("Give Bob one of the mugs and the apple.", "(mug_red>B | mug_blue>B) & apple>B", CELL),
    # one more, or one of them?
    ("Give Person B one of the cup and the apple too.", None, F42),
    ("Give Person B one of the cup and the cup.", None, F42),
    # which mug is in the choice?
    ("Give Bob one of the mug and the cup.", None, CELL),
)


test_one_of_these_then_the_list = CASES.test(
    (
        "For Person B, any one of these: the cup, the apple, the bottle. She won't mind.",
        "cup>B | apple>B | bottle>B",
        F42,
    ),
    ("Person B can have one of these: the cup or the apple.", "cup>B | apple>B", F42),
    # a count the list does not meet, a list of one object twice, no choice before
    ("For Person B, any one of the two: the cup, the apple, the bottle.", None, F42),
    ("For Person B, any one of these: the cup, the cup.", None, F42),
    ("For Person B, the cup. She won't mind.", None, F42),
)


# -- choices said by an idiom -------------------------------------------------------------------


test_either_will_do_for = CASES.test(
    ("Either mug will do for Carol, she's not fussy.", "mug_red>C | mug_blue>C", CELL),
    ("Either book will do, but it's for Zoe.", "book_red>C | book_green>C", CLASSROOM),
    # a place or a robot is not who it is for
    ("Either mug will do for the shelf, she's not fussy.", None, CELL),
    ("Either book will do, but it's for the desk.", None, CLASSROOM),
    # one mug only is not a choice: 'either' needs two
    ("Either bottle will do for Person A, she's not fussy.", None, T12),
)


def test_either_will_do_for_a_shared_role_names_the_readings() -> None:
    assert_refused(
        "Either book will do, but it's for the student.", CLASSROOM, match="Person B.*Person C"
    )


test_split_whichever_way_round = CASES.test(
    (
        "Split the cup and the apple between Person A and Person B, whichever way round you like.",
        "(cup>A & apple>B) | (cup>B & apple>A)",
        SQ,
    ),
    # three objects for two people, one person twice
    (
        "Split the cup, the apple and the bottle between Person A and Person B, whichever "
        "way round you like.",
        None,
        SQ,
    ),
    (
        "Split the cup and the apple between Person A and Person A, whichever way round.",
        None,
        SQ,
    ),
)


test_either_fine_by_me = CASES.test(
    ("Person B can have the apple or the cup, either's fine by me.", "apple>B | cup>B", L44),
    # someone of the scene saying so is not the speaker
    ("Person B can have the apple or the cup, either's fine by Person A.", None, L44),
)


test_whichever_said_first = CASES.test(
    (
        "Whichever's handier, the bottle or the chips, hand it to Person A.",
        "bottle>A | chips>A",
        L24,
    ),
    # a second task after the choice, a kind with two objects in the list
    (
        "Whichever's handier, the bottle or the chips, hand it to Person A and the bottle "
        "to Person B.",
        None,
        L24,
    ),
    ("Whichever's handier, the mug or the cup, hand it to Alice.", None, CELL),
)


test_whichever_there_with_one_such_object = CASES.test(
    ("Whichever bottle's there, Person A gets it.", "bottle>A", T12),
    # two mugs: which one is there is not said
    ("Whichever mug's there, Alice gets it.", None, CELL),
    ("Whichever bottle's there, Person A gets it and the chips.", None, T21),
)


test_each_of_their_own = CASES.test(
    (
        "Make sure each of the patients ends up with a blanket of their own.",
        "(blanket_blue>B & blanket_grey>C) | (blanket_blue>C & blanket_grey>B)",
        WARD,
    ),
    # one jug for two patients; no two people are nurses
    ("Make sure each of the patients ends up with a jug of their own.", None, WARD),
    ("Make sure each of the nurses ends up with a blanket of their own.", None, WARD),
)


test_may_play_with = CASES.test(
    (
        "Ava may play with one of the blocks, either, she's not fussy about colour.",
        "block_red>C | block_green>C",
        NURSERY,
    ),
    ("Ava can play with the teddy.", "teddy>C", NURSERY),
    # 'either' after one object; a person to play with; two people
    ("Ava may play with the teddy, either, she's not fussy.", None, NURSERY),
    ("Ava may play with Lily.", None, NURSERY),
    ("Ava and Lily may play with the teddy.", None, NURSERY),
)


# -- counts said again --------------------------------------------------------------------------


test_n_things_namely = CASES.test(
    ("Hand over two things to Person A, namely the apple and the cup.", "apple>A & cup>A", SQ),
    ("Hand over three things to Person A, namely the apple and the cup.", None, SQ),
    ("Hand over two things to Person A, namely the apple and the apple.", None, SQ),
    ("Hand over two things to Person A, namely the apple and Person B.", None, SQ),
)


test_only_one_item_and_its = CASES.test(
    ("Person B wants only one item, and it's the bottle.", "bottle>B", F42),
    ("Person B wants only one item, and it's the bottle and the cup.", None, F42),
    ("Bob wants only one item, and it's the mug.", None, CELL),
)


test_one_said_by_a_word = CASES.test(
    (
        "Person A is to have the pair of items, the bottle and the chips alike.",
        "bottle>A & chips>A",
        DUO,
    ),
    ("Person A gets our solitary bottle.", "bottle>A", ONE),
    ("A single bottle will do for Person A.", "bottle>A", T12),
    # two mugs: which is the solitary one?
    ("Alice gets our solitary mug.", None, CELL),
    ("A single mug will do for Alice.", None, CELL),
)


test_gather_up_every_one_of_them = CASES.test(
    (
        "Gather up the three pens, every one of them, and drop them in the box.",
        "pen_black@box & pen_blue@box & pen_red@box",
        OFFICE,
    ),
    # the count is checked; a person is no place
    ("Gather up the two pens, every one of them, and drop them in the box.", None, OFFICE),
    ("Gather up the three pens, every one of them, and drop them on Sam.", None, OFFICE),
)


# -- exclusions ---------------------------------------------------------------------------------


test_cant_stand_the_excluded = CASES.test(
    ("Bob wants a mug, but not the red one, he can't stand red.", "mug_blue>B", CELL),
    # another colour, or a person, is not the reason for the exclusion
    ("Bob wants a mug, but not the red one, he can't stand blue.", None, CELL),
    ("Bob wants a mug, but not the red one, he can't stand Alice.", None, CELL),
)


test_dont_give_it_to_another = CASES.test(
    ("The cup's meant for Person B; don't give it to Person A by mistake.", "cup>B", F41),
    ("Give the cup to Person B, but don't give it to Person A.", "cup>B", F41),
    # the negated task is the request's; 'it' could be either object
    ("The cup's meant for Person B; don't give it to Person B by mistake.", None, F41),
    ("Give the cup to Person B, but don't give it to Person B.", None, F41),
    (
        "The cup and the apple are for Person B; don't give it to Person A by mistake.",
        None,
        F41,
    ),
)


test_the_one_that_isnt = CASES.test(
    (
        "Of the two things, Person A wants the one that isn't a bag of chips.",
        "bottle>A",
        DUO,
    ),
    # four objects: which one?; no such object
    ("Of the two things, Person A wants the one that isn't a bag of chips.", None, F42),
    ("Of the two things, Person A wants the one that isn't a bag of apples.", None, DUO),
)


test_left_out_said_first = CASES.test(
    ("Not to Person A; the bottle goes to Person B.", "bottle>B", L24),
    ("Not to Person A; the bottle goes to Person A.", None, L24),
    ("That bottle is Person A's and no one else's, so see she gets it.", "bottle>A", T12),
    ("That bottle is the shelf's and no one else's, so see she gets it.", None, CELL),
    ("No bottle for Person B today, just his chips.", "chips>B", T21),
    ("No bottle for Person B today, just his bottle.", None, T21),
    ("No bottle for Person B today, just his.", None, T21),
)


test_leave_the_x_then_a_request = CASES.test(
    ("Leave the teddy; the bib to Lily.", "bib>A", NURSERY),
    # the object left is the one asked for
    ("Leave the teddy; the teddy to Lily.", None, NURSERY),
    # a placement with 'leave' is the grammar's
    ("Leave the teddy on the mat.", "teddy@mat", NURSERY),
)


# -- corrections --------------------------------------------------------------------------------


test_the_speakers_slip = CASES.test(
    ("Chips for Person A, no, I tell a lie, it's the bottle she ordered.", "bottle>A", DUO),
    (
        "Take the bottle to Person B, whoops, I've got them mixed up again, it's Person A.",
        "bottle>A",
        L24,
    ),
    ("Take the bottle to Person B, I've got them mixed up, it's Person A.", "bottle>A", L24),
    (
        "The globe is for Noah, wait, I've got that wrong, it's Zoe's turn.",
        "globe>C",
        CLASSROOM,
    ),
    # the correction names an object where a person was corrected; a role of two
    (
        "Take the bottle to Person B, whoops, I've got them mixed up again, it's the chips.",
        None,
        L24,
    ),
    (
        "The globe is for Noah, wait, I've got that wrong, it's the student's turn.",
        None,
        CLASSROOM,
    ),
    # a slip after a correction already made speaks of that one
    ("The chips, no, the bottle, silly me, to Person A.", "bottle>A", ONE),
    # a slip closing the text says the request is wrong, not what is right (these were
    # read as the request, the slip taken off as a remark)
    ("Chips for Person A, I tell a lie.", None, DUO),
    ("Give Person A the chips, I got them mixed up.", None, DUO),
    ("Chips for Person A, oh, I've got that wrong, sorry.", None, DUO),
)


test_yes_i_did_mean_her = CASES.test(
    ("The bottle to Person A. Yes, Person A, I did mean her.", "bottle>A", ONE),
    # another person, or one of two recipients: a correction, not a confirmation
    ("The bottle to Person A. Yes, Person B, I did mean him.", None, T21),
    (
        "The bottle to Person A and the chips to Person B. Yes, Person A, I did mean her.",
        None,
        T21,
    ),
)


test_a_better_place = CASES.test(
    (
        "The sponge can go on the tray, oh, hold on, the sink's a better home for it.",
        "sponge@sink",
        LAB,
    ),
    (
        "Sit the teddy in the high chair, no, better down on the play mat.",
        "teddy@mat",
        NURSERY,
    ),
    ("Sit the teddy in the high chair.", "teddy@highchair", NURSERY),
    # a person is no home; two objects placed; a person is no seat
    ("The sponge can go on the tray, oh, hold on, Dana's a better home for it.", None, LAB),
    (
        "The sponge and the bowl can go on the tray, oh, hold on, the sink's a better home for it.",
        None,
        LAB,
    ),
    ("Sit the teddy in Lily.", None, NURSERY),
)


# -- two wrong readings of the grammar ----------------------------------------------------------


test_all_but_after_a_comma = CASES.test(
    # 'all' after a comma is the pens said before it (it had read every object)
    ("Give Sam the pens, all but the red one.", "pen_black>B & pen_blue>B", OFFICE),
    ("Give Sam the pens, all except the red one.", "pen_black>B & pen_blue>B", OFFICE),
    # 'all but' with nothing before it is every object, as before
    (
        "Give Sam all but the red pen.",
        "pen_black>B & notebook>B & pen_blue>B & stapler>B",
        OFFICE,
    ),
    # the same for a placement: the boxes said before, but the small one
    (
        "Put the boxes on the pallet, all but the small one.",
        "box_medium@pallet & box_large@pallet",
        DEPOT,
    ),
)


test_leave_without_a_place = CASES.test(
    # 'leave' with no place of its own had taken the belt over
    ("Put the small box on the belt, leave the large one.", None, DEPOT),
    ("Put the boxes on the belt, leave the large one.", None, DEPOT),
    # a place of its own, or 'there', is a placement as before
    (
        "Put the small box on the belt, then leave the tape on the pallet.",
        "box_small@conveyor ; tape@pallet",
        DEPOT,
    ),
    (
        "Put the small box on the belt, and leave the large one there too.",
        "box_small@conveyor & box_large@conveyor",
        DEPOT,
    ),
)


test_corrections_said_other_ways = CASES.test(
    ("Lena doesn't want the blue plate, just the white one.", "plate_white>B", KITCHEN),
    ("The knife to Lena, oops, I meant to say the tongs.", "tongs>B", KITCHEN),
    ("The knife to Lena, I should have said the tongs.", "tongs>B", KITCHEN),
    ("The knife to Lena, hmm, better make it the tongs.", "tongs>B", KITCHEN),
    ("Tongs to Lena, hold on, it's Mr Novak who wants them.", "tongs>C", KITCHEN),
    ("Tongs to Lena, no, it's Mr Novak's turn.", "tongs>C", KITCHEN),
    ("Give the apple to Bob, no hang on, it was Carol who asked.", "apple>C", CELL),
    # the same object kept and left out; a person where the object goes; an object where
    # the person was corrected; the one who wants something else
    ("Lena doesn't want the blue plate, just the blue one.", None, KITCHEN),
    ("Lena doesn't want the blue plate, just Marco.", None, KITCHEN),
    ("Tongs to Lena, hold on, it's the knife who wants them.", None, KITCHEN),
    ("Tongs to Lena, hold on, it's Mr Novak who wants the knife.", None, KITCHEN),
)


test_exclusions_said_other_ways = CASES.test(
    # words for 'except' the grammar did not know
    (
        "Put the boxes on the pallet, excluding the big one.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    (
        "The boxes go on the pallet, minus the big one.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    (
        "Put the boxes on the pallet, not including the big one.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    (
        "Put the boxes on the pallet, with the exception of the big one.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    # what stays where it is
    (
        "Put the boxes on the pallet, leave the big one where it is.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    (
        "Put the boxes on the pallet, but leave the big one alone.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    (
        "Put the boxes on the pallet, the big one can stay where it is.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    # 'there' is the pallet (as on main); a person is no object to leave out
    (
        "Put the boxes on the pallet, leave the big one there.",
        "box_small@pallet & box_medium@pallet & box_large@pallet",
        DEPOT,
    ),
    ("Put the boxes on the pallet, leave Tom where he is.", None, DEPOT),
    # who does not need what the request hands to someone else
    ("The gloves go to Tom, Mia doesn't need them.", "gloves>B", DEPOT),
    ("Tom needs the gloves; the tape isn't for him.", "gloves>B", DEPOT),
    # the statement denies the request's own task; 'him' could be either
    ("Tom needs the gloves, Tom doesn't need them.", None, DEPOT),
    ("Tom needs the gloves; the gloves aren't for him.", None, DEPOT),
    ("Give Tom and Mia the gloves; they aren't for him.", None, DEPOT),
)


test_counts_said_other_ways = CASES.test(
    ("Jess needs a couple of spanners.", "spanner_small>B & spanner_large>B", WORKSHOP),
    ("Jess needs a couple of hammers.", None, WORKSHOP),
    (
        "Give Jess the small and large spanners.",
        "spanner_small>B & spanner_large>B",
        WORKSHOP,
    ),
    # one red mug, no green one: the adjectives must each name one object
    ("Give Bob the red and green mugs.", None, CELL),
    ("Give Bob the red and red mugs.", None, CELL),
    (
        "Kofi needs the hammer, the drill and the torch, three things.",
        "hammer>A & drill>A & torch>A",
        WORKSHOP,
    ),
    ("Kofi needs the hammer, the drill and the torch, two things.", None, WORKSHOP),
    (
        "Kofi needs three items - the hammer, the drill and the torch.",
        "hammer>A & drill>A & torch>A",
        WORKSHOP,
    ),
    (
        "The hammer and the drill, one for Kofi and one for Jess.",
        "(hammer>A & drill>B) | (hammer>B & drill>A)",
        WORKSHOP,
    ),
    ("The hammer and the drill, one for Kofi and one for Kofi.", None, WORKSHOP),
    ("The hammer, the drill and the torch, one for Kofi and one for Jess.", None, WORKSHOP),
    (
        "Split the spanners between Kofi and Jess.",
        "(spanner_small>A & spanner_large>B) | (spanner_small>B & spanner_large>A)",
        WORKSHOP,
    ),
    # three boxes between two people: no split is the only one
    ("Split the boxes between Mia and Tom.", None, DEPOT),
)


test_the_choosers_words = CASES.test(
    # the chooser's words after a choice: any of them will do
    ("Give Noah one of the books, his pick.", "book_red>B | book_green>B", CLASSROOM),
    ("Noah gets one book, you choose which.", "book_red>B | book_green>B", CLASSROOM),
    ("A book for Noah, no preference.", "book_red>B | book_green>B", CLASSROOM),
    (
        "Noah wants a book, red or green, either's good.",
        "book_red>B | book_green>B",
        CLASSROOM,
    ),
    ("Noah needs a book, any old one.", "book_red>B | book_green>B", CLASSROOM),
    # with nothing left open they change nothing, as 'whichever' does
    ("Give Noah the red book, his pick.", "book_red>B", CLASSROOM),
    # a choice the scene cannot meet stays refused
    ("Give Noah one of the globes, his pick.", None, CLASSROOM),
)


test_cue_words = CASES.test(
    ("The magazine for Mr Lee, I'm wrong, it's Mrs Khan.", "magazine>C", WARD),
    ("The magazine for Mr Lee, my apologies, Mrs Khan.", "magazine>C", WARD),
    ("Magazine to Mr Lee, sorry, wrong patient, Mrs Khan.", "magazine>C", WARD),
    ("Magazine to Mr Lee, not him, Mrs Khan.", "magazine>C", WARD),
    ("Magazine to Mr Lee, change that to Mrs Khan.", "magazine>C", WARD),
    ("Magazine to Mr Lee, I meant Mrs Khan, sorry about that.", "magazine>C", WARD),
    ("Magazine to Mr Lee, hmm, Mrs Khan actually.", "magazine>C", WARD),
    ("The magazine for Mr Lee. No! Mrs Khan.", "magazine>C", WARD),
    ("The magazine for Mr Lee, no, it's Mrs Khan.", "magazine>C", WARD),
    ("The magazine for Mr Lee, oh no, it's the jug he wants.", "jug>B", WARD),
    ("The magazine for Mr Lee, sorry, swap that for the jug.", "jug>B", WARD),
    # a role two share, a cue cut off, a word that is no name
    ("The magazine for Mr Lee, no, it's the patient.", None, WARD),
    ("The magazine for Mr Lee, my apologies.", None, WARD),
    ("Magazine to Mr Lee, hmm, tomorrow actually.", None, WARD),
)


test_only_and_other = CASES.test(
    ("Give Omar only the cups.", "cup_green>B & cup_white>B", LAB),
    ("Give Omar only the spoon and Emma the bowl.", "spoon>B & bowl>C", LAB),
    ("Dana gets the other cup, not the green one.", "cup_white>A", LAB),
    ("Dana gets the non-green cup.", "cup_white>A", LAB),
    # no red cup; one spoon, no green one
    ("Dana gets the non-red cup.", None, LAB),
    ("Dana gets the other spoon, not the green one.", None, LAB),
)


test_a_correction_by_its_colour = CASES.test(
    ("The black pen for Priya, sorry, make that red.", "pen_red>A", OFFICE),
    ("The black pen for Priya, sorry, red not black.", "pen_red>A", OFFICE),
    # no green pen; the stapler has no red one; 'not blue' is not what was asked
    ("The black pen for Priya, sorry, make that green.", None, OFFICE),
    ("The stapler for Priya, sorry, make that red.", None, OFFICE),
    ("The black pen for Priya, sorry, red not blue.", None, OFFICE),
)


test_happy_with = CASES.test(
    ("Alice would be happy with the bottle or the crisps.", "bottle>A | chips>A", TWO),
    ("Alice: bottle or crisps, she's happy with either.", "bottle>A | chips>A", TWO),
    ("The bottle or the crisps for Alice, either's grand.", "bottle>A | chips>A", TWO),
    # a person is no object; 'is happy with' may say she has it; a count the scene lacks
    ("Alice would be happy with Bob.", None, TWO),
    ("Alice is happy with the bottle but Bob wants it.", None, TWO),
    ("Alice would be happy with the three items.", None, TWO),
)
