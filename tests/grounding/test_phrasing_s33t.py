"""Session-33 phrasings of issue 12 (engineer 12t): blind17, blind23, blind18, causes17 and
blind15's refusals by kind; docs/grounding.md, "Session 33 (engineer 12t)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

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
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
)


def _scene(name: str) -> Scene:
    return load_scene(ROOT / f"examples/scenes/{name}.yaml")


F41 = _scene("4-1")  # bottle, chips, cup, apple; A, B
F42 = _scene("4-2")  # bottle, chips, cup, apple; A, B
DUO = _scene("2-2")  # bottle, chips; A, B
T21 = _scene("2-1")  # bottle, chips; A, B
L44 = _scene("4-4-line")  # bottle, chips, cup, apple; A, B
SQ = _scene("4-4-square")  # bottle, chips, cup, apple; A, B
L24 = _scene("2-4-line")  # bottle, chips; A, B
ONE = _scene("1-1")  # bottle; A
T12 = _scene("1-2")  # bottle; A
TWO = _scene("two_arms")  # bottle, chips (crisps); Alice, Bob
FIG1 = _scene("fig1")  # bottle, chips (crisps); Alice, Bob; shelf


CASES = PhrasingCases()
_assert_case = assert_case  # the reading-or-refusal check (later sessions' files import it)


# -- a header saying how much each person gets, then the list that says what -----------------


test_each_header = CASES.test(
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
        "One thing apiece for the two of them: the bottle's Person A's, the chips are Person B's.",
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
        "Both of them get one thing each: the bottle to Alice, the chips to Bob, the cup to Carol.",
        None,
        CELL,
    ),
    (
        "One thing apiece for the two of them: the bottle's Person A's, the chips are Person A's.",
        None,
        T21,
    ),
)


# -- 'one of the drinks / snacks for P: X or Y': the kind word's closed list --------------------


test_kind_choice = CASES.test(
    ("One of the drinks for Person A: the bottle or the cup", "bottle>A | cup>A", F42),
    ("One of the snacks for Person B: the chips or the apple", "chips>B | apple>B", L44),
    ("One of the drinks for Person A: the bottle or the chips", None, F42),
    ("One of the snacks for Person B: the chips or the cup", None, L44),
    ("One of the toys for Person B: the chips or the apple", None, L44),
)


# -- 'give each of them a pen, P and Q, any colour' -------------------------------------------


test_each_any = CASES.test(
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
)


# -- 'No X for P, one of the other two will do' -------------------------------------------------


test_other_two = CASES.test(
    ("No black pen for Priya, one of the other two will do", "pen_blue>A | pen_red>A", OFFICE),
    ("No red pen for Sam, one of the other two will do", "pen_black>B | pen_blue>B", OFFICE),
    # the count against the scene: two other pens, no other stapler; 'pen' is three
    ("No black pen for Priya, one of the other three will do", None, OFFICE),
    ("No stapler for Priya, one of the other two will do", None, OFFICE),
    ("No pen for Priya, one of the other two will do", None, OFFICE),
)


# -- 'leave the X where they are' after everything; 'clear everything into S' ---------------------


test_leave_where = CASES.test(
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
)


# -- 'load P up with X', 'pack S with X' --------------------------------------------------------


test_load_up = CASES.test(
    ("Load Jess up with the spanners, just not the small one", "spanner_large>B", WORKSHOP),
    ("Load Tom up with the boxes, just not the small box", "box_medium>B & box_large>B", DEPOT),
    (
        "Ja, pack the locker with the lot, just not the two spanners.",
        "drill@locker & hammer@locker & screws@locker & torch@locker",
        WORKSHOP,
    ),
    ("Load the drill up with the screws", None, WORKSHOP),
    ("pack Jess with the lot", None, WORKSHOP),
)


# -- 'won't you <verb>': a request asked politely ----------------------------------------------


test_wont_you = CASES.test(
    ("Give Ava the teddy, won't you give Lily the bib too?", "teddy>C & bib>A", NURSERY),
    ("Won't you give Lily the bib?", "bib>A", NURSERY),
    ("Give Ava the teddy, you won't give Lily the bib", None, NURSERY),
    ("Give Ava the teddy, why won't you give Lily the bib?", None, NURSERY),
    ("Give Ava the teddy, won't you stop giving Lily the bib?", None, NURSERY),
)


# -- the recipient said first: 'Unto Person A the chips'; 'whichever thou wilt of X or Y' -------


test_fronted_to = CASES.test(
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
)


# -- an interjection or a word of address beside a correction; 'I mean' after the name ---------


test_exclaimed_fix = CASES.test(
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
)


# -- after a placement, whom it is for and what they do; what an object is for (an -ing verb) ----


test_placed_for = CASES.test(
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
        "Everything goes to the sink for washing, except for the spoon and the banana of course",
        "cup_green@sink & bowl@sink & cup_white@sink & sponge@sink",
        LAB,
    ),
    # a bare 'for P' after a placement: whom it is put there for (session 41, 12s; sessions 30 and
    # 31 had refused it: may ask for P to get it); the person named again, a verb of the grammar,
    # an object in the purpose
    ("Would you put the black pen in the box for Priya?", "pen_black@box", OFFICE),
    ("Put the black pen in the box for Priya, and give Priya the stapler.", None, OFFICE),
    ("The two blocks in the high chair for Lily to give.", None, NURSERY),
    ("Person A needs the cup for rinsing the apple, and Person B wants the chips.", None, SQ),
)


# -- what stays where it starts; 'each <role>, <manner>,'; '…, and not the X either' ------------


test_stays_each = CASES.test(
    (
        "Magazine to Mrs Khan. Jug to Mr Lee. Grey blanket stays on the cart.",
        "magazine>C & jug>B",
        WARD,
    ),
    (
        "Each patient, gently, receives one blanket, whichever colour.",
        "(blanket_blue>B & blanket_grey>C) | (blanket_grey>B & blanket_blue>C)",
        WARD,
    ),
    ("Give Person A the chips but not the apple, and not the cup either.", "chips>A", F42),
    # the blue blanket does not start on the cart (staying there is a move); 'only' is no
    # manner word; 'whichever colour' of what has one colour only; 'either' with no 'not'
    ("Magazine to Mrs Khan. Blue blanket stays on the cart.", None, WARD),
    ("Magazine to Mrs Khan. Grey blanket stays on the locker.", None, WARD),
    ("Each patient, only, receives one blanket.", None, WARD),
    ("Each patient, gently, receives one magazine, whichever colour.", None, WARD),
    ("Give Person A the chips, and not the cup either.", None, F42),
)


# -- 'both mugs, the red and the blue'; 'gently does it' ----------------------------------------


test_both_named = CASES.test(
    (
        "Sorry, both mugs, the red and the blue, could they go to Alice?",
        "mug_red>A & mug_blue>A",
        CELL,
    ),
    (
        "Both mugs, red and blue, up on the shelf, gently does it, they're my good ones.",
        "mug_red@shelf & mug_blue@shelf",
        CELL,
    ),
    # a pair that is not the two mugs
    ("Both mugs, red and green, up on the shelf.", None, CELL),
    ("Both mugs, the red and the cup, could they go to Alice?", None, CELL),
)


# -- 'once he's got them'; 'what I need is X over with P'; a quick note's words ------------------


test_quick_notes = CASES.test(
    (
        "tom wants the gloves and once hes got them mia wants the tape",
        "gloves>B ; tape>A",
        DEPOT,
    ),
    (
        "Person B needs the chips, ugh, and after she's got them Person A's going to want the "
        "bottle.",
        "chips>B ; bottle>A",
        T21,
    ),
    ("What I need is the bottle over with Person B.", "bottle>B", L44),
    ("need the chips over with person b like right now", "chips>B", L24),
    ("Sorry, quick one, could Person B grab the chips off you? Cheers.", "chips>B", L24),
    ("Person B is wanting the bottle only, kindly do the needful.", "bottle>B", DUO),
    ("apple n bottle both for person b pls", "apple>B & bottle>B", L44),
    ("That one bottle, over to Person A, quick as you can.", "bottle>A", ONE),
    # near forms: no one of the scene named; a want with no object; two mugs ('that one'
    # points); 'grab … off' another person; 'only' before another request
    ("What I need is the bottle over with Person C.", None, L44),
    ("need the chips like right now", None, L24),
    ("That one mug, over to Alice.", None, CELL),
    ("Could Person B grab the chips off Person A?", None, L24),
    ("Person B is wanting the bottle only, kindly do the chips.", None, DUO),
)


# -- 'wants X left in S'; 'then the apple same way'; 'while he's at it'; 'Either X or Y shall be
# given to P, at your discretion' ------------------------------------------------------------------


test_said_again = CASES.test(
    (
        "Priya wants the red pen left in the box, she'll sort it out later.",
        "pen_red@box",
        OFFICE,
    ),
    (
        "Pick up the cup and give it Person B, yeah, then the apple same way.",
        "cup>B ; apple>B",
        L44,
    ),
    (
        "Give Marco the knife, he's filleting, and the tongs as well while he's at it.",
        "knife>A & tongs>A",
        KITCHEN,
    ),
    (
        "Either the notebook or the stapler shall be given to Priya, at your discretion.",
        "notebook>A | stapler>A",
        OFFICE,
    ),
    # 'left' with no surface after it; 'at your discretion' with no choice
    ("Priya wants the red pen left on the left.", None, OFFICE),
    ("The notebook shall be given to Priya, at your discretion.", None, OFFICE),
)


# -- an object said as a person's; a count or choice said again ---------------------------------


test_whose_one = CASES.test(
    ("Could you bring Grandad's beaker over to him?", "beaker>B", NURSERY),
    (
        "Now then, dear, be a good helper and put Lily's bib on her high chair, won't you?",
        "bib@highchair",
        NURSERY,
    ),
    ("Marco needs his tongs, just the one pair.", "tongs>A", KITCHEN),
    ("Give Ava the blocks, not the green one, only red.", "block_red>C", NURSERY),
    ("Bottle for Person A, and, honestly, that's the whole job today.", "bottle>A", T12),
    ("Lily wants the two blocks to bang together", "block_red>A & block_green>A", NURSERY),
    # another person named; 'only' naming what was left out; 'one pair' of no pair noun
    ("Could you bring Lily's beaker over to Ava?", None, NURSERY),
    ("Put Lily's bib on her high chair and give Grandad the teddy.", None, NURSERY),
    ("Give Ava the blocks, not the green one, only green.", None, NURSERY),
    ("Marco needs his knife, just the one pair.", None, KITCHEN),
    ("Lily wants the two blocks to bang together with Ava", None, NURSERY),
)


# -- a statement about what the scene does not have, opening a request --------------------------


test_opening_scene = CASES.test(
    (
        "Stock room's a mess, grab whichever box you like and stick it on the belt",
        "box_small@conveyor | box_medium@conveyor | box_large@conveyor",
        DEPOT,
    ),
    (
        "Sorry, the dogs are going mad outside, could you whizz the bib over to the high "
        "chair, cheers.",
        "bib@highchair",
        NURSERY,
    ),
    # the statement names a scene object, negates, puts the task off; the request's 'it'
    # would have only the statement to point back to
    ("The tape's a mess, grab whichever box you like and stick it on the belt", None, DEPOT),
    (
        "Stock room's not ready, grab whichever box you like and stick it on the belt",
        None,
        DEPOT,
    ),
    (
        "Stock room's a mess tomorrow, grab whichever box you like and stick it on the belt",
        None,
        DEPOT,
    ),
    (
        "Sorry, the dogs are going mad outside, could you whizz it over to the high chair.",
        None,
        NURSERY,
    ),
)


# -- a closing count of the hand-overs ----------------------------------------------------------


test_counted_close = CASES.test(
    (
        "Apple, Person A. Chips, Person B. Cup, Person A. Bottle, Person B. Four deliveries, "
        "what a display!",
        "apple>A & chips>B & cup>A & bottle>B",
        SQ,
    ),
    # the count is not the request's; the exclamation names an object
    (
        "Apple, Person A. Chips, Person B. Cup, Person A. Bottle, Person B. Three deliveries, "
        "what a display!",
        None,
        SQ,
    ),
    ("Apple, Person A. Chips, Person B. Four deliveries, what a display!", None, SQ),
    ("Apple, Person A. Chips, Person B. Two deliveries, what a bottle!", None, SQ),
)


# -- the objects said first, then 'give P' ---------------------------------------------------------


test_objects_first = CASES.test(
    ("Bottle or crisps, any one also can, give Bob.", "bottle>B | chips>B", TWO),
    # a count before 'give P' stays refused (session 28's near form "Two items, both give
    # Alice."); a surface among the objects
    ("Two items, both give Alice lah.", None, TWO),
    ("Bottle or shelf, any one also can, give Bob.", None, TWO),
)


# -- openers and pace from a closed list; the speaker's plan run on after a request --------------


test_openers = CASES.test(
    (
        "Right, listen. Person B: bottle. Person A: chips. Quick as you like, the crane's waiting.",
        "bottle>B & chips>A",
        L44,
    ),
    (
        "nothing fancy, just hand person a that bottle, ta, the strings can wait",
        "bottle>A",
        ONE,
    ),
    (
        "Give Person B the bottle I'm just going to check the hammers on this upright.",
        "bottle>B",
        L24,
    ),
    # a time with the pace word; 'nothing' alone; the plan names a person
    ("Right, listen. Person B: bottle. Person A: chips. Quick as you like, later.", None, L44),
    ("nothing, just hand person a that bottle", None, ONE),
    ("Give Person B the bottle I'm just going to give Person A.", None, L24),
)


# -- where an object is, said in words that name nothing; 'meant for P, take them over' ----------


test_places_said = CASES.test(
    ("Person A is hungry, please bring her the alple from the end.", "apple>A", L44),
    ("Put the bnana on the tray next to the films, ta.", "banana@tray", LAB),
    (
        "Jess wants the other spanner, not the big one on the workbench.",
        "spanner_small>B",
        WORKSHOP,
    ),
    (
        "The small and medium boxes, the two little ones, onto the pallet.",
        "box_small@pallet & box_medium@pallet",
        DEPOT,
    ),
    ("The chips are meant for Peraon A, could you take them over.", "chips>A", DUO),
    # a place said after no object or surface (blind27's entry reads as before)
    (
        "Chips to Person B first. After that. Person A gets the cup. Sorry, typing this from "
        "the cave entrance.",
        "chips>B ; cup>A",
        F41,
    ),
    # a place of the scene, a person, a time; the big one does not lie on the locker; a
    # count that is not the list's; another person after 'take them over'
    ("Put the banana on the tray next to the sink, ta.", None, LAB),
    ("Put the banana on the tray next to the green cup, ta.", None, LAB),
    ("Give Person B the apple from the morning.", None, L44),
    ("Jess wants the other spanner, not the big one on the locker.", None, WORKSHOP),
    ("The small and medium boxes, the three little ones, onto the pallet.", None, DEPOT),
    (
        "The chips are meant for Person A, could you take them over to Person B.",
        None,
        DUO,
    ),
)


# -- 'everything (left on the pitch) bar X heads to P' --------------------------------------------


test_everything_bar = CASES.test(
    (
        "Everything left on the pitch bar the bottle and the cup heads to Person A!",
        "chips>A & apple>A",
        SQ,
    ),
    ("The cup heads to Person A.", "cup>A", SQ),
    # a place of the scene narrows 'everything'; a time puts it off; no person after 'heads to'
    ("Everything left on the shelf bar the bottle and the cup heads to Alice!", None, CELL),
    (
        "Everything left on the pitch bar the bottle and the cup heads to Person A tomorrow!",
        None,
        SQ,
    ),
    ("Everything left on the pitch bar the bottle heads to the pitch!", None, SQ),
)


# -- formal and hesitant wrappers ------------------------------------------------------------------


test_formal = CASES.test(
    (
        "For the record, and with the greatest respect, would you kindly deliver the stapler "
        "to Sam. Thank you, no further questions.",
        "stapler>B",
        OFFICE,
    ),
    (
        "Um, sorry, is it okay if, sorry, could you give Person B the bottle? Only if it's no "
        "bother. Sorry!",
        "bottle>B",
        DUO,
    ),
    # the frame given up with no other frame after it
    ("Um, is it okay if, sorry, Person B has the bottle?", None, DUO),
    ("With the greatest respect, no further questions.", None, OFFICE),
)
