"""Session-34 phrasings of issue 12 (engineer 12t): blind17, blind19, blind20, blind23, causes18
and causes15's refusals by kind; docs/grounding.md, "Session 34 (engineer 12t)". Each rule with
the sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

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
)

# the scenes of the numbered parts, as session 33 (12t) has them
from tests.grounding.test_phrasing_s33t import (
    DUO,
    F41,
    F42,
    FIG1,
    L24,
    L44,
    SQ,
    T12,
    T21,
    TWO,
)

CASES = PhrasingCases()

# -- a count after 'those' is the count with 'the' (and is checked) ---------------------------


test_counted_those = CASES.test(
    # ('Those two mugs want to go on the counter' is 12r's _counted_want34r)
    (
        "Those three things that aren't the bottle, give them to Person A.",
        "chips>A & cup>A & apple>A",
        SQ,
    ),
    # the count must agree with the scene
    ("Those two things that aren't the bottle, give them to Person A.", None, SQ),
)


# -- a last sentence naming exactly the objects of the request says them again ----------------


test_objects_said = CASES.test(
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
)


# -- 'P says she'd love X': what P wants --------------------------------------------------------


test_reported_want = CASES.test(
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
)


# -- closers from a closed list, thanks said again, text-speak ----------------------------------


test_closers = CASES.test(
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
)


# -- frames of learners and of talk -------------------------------------------------------------


test_frames = CASES.test(
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
    # (session 39: "D'you reckon Alice could get that bottle?" reads as 'Do you reckon …' always
    # did, bottle>A, now that session 33's _THINK_COULD33 takes "d'you"; the near form names
    # nothing to get)
    ("D'you reckon Alice could get that?", None, FIG1),
    ("Over to Person B with Person A, please.", None, T21),
    ("For Person B, bottle, please take.", None, DUO),
    ("For the bottle, Person B, please give.", None, DUO),
    ("The bottle goes to Bob first. Then the crisps, same time.", None, TWO),
    ("Give Bob the bottle first. Then the crisps, same place.", None, TWO),
    # two targets before it: which one is 'same place'? (session 26's near form)
    (
        "Put the jug on the trolley and the pills on the bedside table, then the thermometer, "
        "same place.",
        None,
        WARD,
    ),
)


# -- 'Drop all three of the pens into the box' is a placement ----------------------------------


test_drop_all = CASES.test(
    (
        "Drop all three of the pens into the box, they keep rolling off.",
        "pen_black@box & pen_blue@box & pen_red@box",
        OFFICE,
    ),
    ("Drop all two of the pens into the box.", None, OFFICE),
    ("Drop all three of the pens.", None, OFFICE),
)


# -- the cleft 'the thing P has been after is X' (12r's _both_something34r reads 'They both want
# something.') ---------------------------------------------------------------------------------


test_thing_cleft = CASES.test(
    ("Honestly, the thing Person B has been after all morning is the bottle.", "bottle>B", L44),
    ("The thing Person A wants is the cup.", "cup>A", L44),
    # not a person
    ("The thing on the table is the bottle.", None, L44),
)


# -- a question that names the two, then 'give it to her'; who comes first ----------------------


test_asked_first = CASES.test(
    ("Would Person B like the apple? Give it to her, yes?", "apple>B", SQ),
    (
        "Priority is Person A, she needs the cup; once she's sorted, Person B would like the "
        "apple.",
        "cup>A ; apple>B",
        F42,
    ),
    # the pronoun cannot be the person by title; more after the request; 'them' of one thing
    ("Would Mr Lee like the magazine? Give it to her.", None, WARD),
    ("Would Person B like the apple? Give it to her, and the cup to Person A.", None, SQ),
    ("Would Person B like the apple? Give them to her.", None, SQ),
    (
        "Priority is Mr Lee, she needs the jug; once she's sorted, Ruth would like the magazine.",
        None,
        WARD,
    ),
)


# -- 'Only one bottle between the lot of us': the count of the scene ---------------------------


test_only_one = CASES.test(
    (
        "Only one bottle between the lot of us, so that single bottle goes to Person A, full stop.",
        "bottle>A",
        T12,
    ),
    # two mugs; another kind said again
    ("Only one mug between the lot of us, so that single mug goes to Alice.", None, CELL),
    ("Only one cup between the lot of us, so that single bottle goes to Person A.", None, T12),
)


# -- where a placement goes, said again in words naming nothing; 'Don't mind me' ----------------


test_remark_places = CASES.test(
    ("the red book goes back up on the bookshelf with the others", "book_red@shelf", CLASSROOM),
    (
        "Why don't you set the globe down on the desk where the class can see the dig site?",
        "globe@desk",
        CLASSROOM,
    ),
    (
        "Morning! Don't mind me up the ladder, could you just hand Person B the apple, ta very "
        "much.",
        "apple>B",
        SQ,
    ),
    # a person, an object, the speaker or a time in the 'where' clause; 'the rest'; a person
    ("the red book goes back up on the bookshelf with the rest", None, CLASSROOM),
    ("Why don't you set the globe down on the desk where Zoe can see it?", None, CLASSROOM),
    ("Set the globe down on the desk where the red book is.", None, CLASSROOM),
    ("Set the globe down on the desk where I can see it.", None, CLASSROOM),
    ("Set the globe down on the desk where the class can see it tomorrow.", None, CLASSROOM),
    ("Don't mind Person A, hand Person B the apple.", None, SQ),
)


# -- closed lists: breathing, a referee, text-speak, 'wee', appositions of a role ---------------


test_idioms = CASES.test(
    (
        "Breathe in... and breathe out. Now, gently, in your own time, bring the grey blanket "
        "over to Mr Lee. Namaste.",
        "blanket_grey>B",
        WARD,
    ),
    ("Namaste. Breathe in, and place the sponge in the sink. Breathe out.", "sponge@sink", LAB),
    ("omg bestie pls give Sam the stapler, slay", "stapler>B", OFFICE),
    ("Play on! Drill to Kofi, advantage played.", "drill>A", WORKSHOP),
    ("Aye, if ye could give Grandad the wee teddy, that'd be magic", "teddy>B", NURSERY),
    (
        "My client, Sam, requires the notepad, and Priya, the manager, wishes to have the red pen.",
        "notebook>B & pen_red>A",
        OFFICE,
    ),
    # breathing said of an object; two blocks; another person's role; a role as 'my' word
    ("Breathe in, and place the sponge in the sink, and breathe out the banana.", None, LAB),
    ("if ye could give Grandad the wee block, that'd be magic", None, NURSERY),
    (
        "My client, Sam, requires the notepad, and Priya, the intern, wishes to have the red pen.",
        None,
        OFFICE,
    ),
    ("My manager, Sam, requires the notepad.", None, OFFICE),
)


# -- 'after those two' says the order again; 'leave the X where it is' the correction ----------


test_said_again = CASES.test(
    (
        "The stapler goes to Sam. The red pen to Sam too. Then the notepad to Priya after "
        "those two.",
        "(stapler>B & pen_red>B) ; notebook>A",
        OFFICE,
    ),
    (
        "Tape to Mia. No, hang on, the scanner to Mia, leave the tape where it is.",
        "scanner>A",
        DEPOT,
    ),
    # a count that does not agree; the object left is still moved, or not the one replaced
    ("The stapler goes to Sam. Then the notepad to Priya after those two.", None, OFFICE),
    (
        "The stapler goes to Sam. The red pen to Sam too. Then the notepad to Priya after "
        "those three.",
        None,
        OFFICE,
    ),
    ("Tape to Mia, leave the tape where it is.", None, DEPOT),
    (
        "Tape to Mia. No, hang on, the scanner and the tape to Mia, leave the tape where it is.",
        None,
        DEPOT,
    ),
    (
        "Tape to Mia. No, hang on, the scanner to Mia, leave the gloves where they are.",
        None,
        DEPOT,
    ),
)


# -- telegraphed requests; a state run on with no commas; what the request is for ---------------


test_telegraphed = CASES.test(
    ("Right. That hammer. Back on the workbench. Ta.", "hammer@bench", WORKSHOP),
    (
        "So. Chips, those are for Person A. Bottle, that one is Person B's. That is all, köszi.",
        "chips>A & bottle>B",
        DUO,
    ),
    (
        "good evening, tonights order chips for person b plus the cup for person a",
        "chips>B & cup>A",
        F42,
    ),
    (
        "Give Jess the small spanner quick she's under the van and after that the hammer to "
        "Kofi he's waiting.",
        "spanner_small>B ; hammer>A",
        WORKSHOP,
    ),
    (
        "For reading group, lay out both books on the desk, the two of them.",
        "book_red@desk & book_green@desk",
        CLASSROOM,
    ),
    # a person after the object's sentence; a person not in the scene; a state naming an
    # object; a person, a time or a count after 'for'
    ("Right. That hammer. Back on Kofi. Ta.", None, WORKSHOP),
    ("Chips to Person A. Bottle, that one is Person C's.", None, DUO),
    (
        "Give Jess the small spanner quick she's under the hammer and after that the drill to "
        "Kofi.",
        None,
        WORKSHOP,
    ),
    ("For Zoe, lay out both books on the desk.", None, CLASSROOM),
    ("For later, lay out both books on the desk.", None, CLASSROOM),
    ("For both, lay out both books on the desk.", None, CLASSROOM),
)


# -- reasons that ask nothing; a list said target first -----------------------------------------


test_reasons_and_targets = CASES.test(
    (
        "Blue blanket to Mr Lee, he's shivering, and after that the jug to Mrs Khan because "
        "she asked earlier and she's been very patient.",
        "blanket_blue>B ; jug>C",
        WARD,
    ),
    ("Tom's after the barcode scanner, his own one has died on him.", "scanner>B", DEPOT),
    ("Crisps straight into Alice's hands, she's on after the interval.", "chips>A", TWO),
    ("shelf for the chips, bob for the bottle, ta", "chips@shelf & bottle>B", FIG1),
    # a correction's note: 12r's _surface_for34r reads it (this rule stands aside)
    (
        "Shelf for the bottle, please, or no, better still, straight to Alice.",
        "bottle>A",
        FIG1,
    ),
    # a reason naming an object, or a pronoun that cannot be the person; an object of the
    # scene dying; a person for a person, a surface for a person; two mugs
    ("The jug to Mrs Khan because she asked for the magazine.", None, WARD),
    ("The jug to Mrs Khan because he asked earlier.", None, WARD),
    # 'she' could be Bob or Carol (no title): session 5's near form
    ("Give Bob the chips and Carol the apple because she asked earlier.", None, CELL),
    ("Tom's after the barcode scanner, his own box has died on him.", None, DEPOT),
    ("shelf for the chips, alice for bob", None, FIG1),
    ("shelf for bob, bottle for the chips", None, FIG1),
    ("Alice for the cup, Bob for the mug.", None, CELL),
)


# -- a pirate's role-play from a closed list; a report taken back news-style --------------------


test_role_play = CASES.test(
    (
        "Arr, Cap'n Lily be wantin' her bib, and old Grandad wants the sippy cup, me hearties!",
        "bib>A & beaker>B",
        NURSERY,
    ),
    ("Find the treasure, matey, the teddy bear, and give it to Lily, arr!", "teddy>A", NURSERY),
    (
        "The two blocks be Lily's treasure, arr, give her both!",
        "block_red>A & block_green>A",
        NURSERY,
    ),
    (
        "The four treasures, all of them, unto Person A.",
        "bottle>A & chips>A & cup>A & apple>A",
        F41,
    ),
    (
        "We reported the cup was going to Person A. Correction: it's the apple.",
        "apple>A",
        F42,
    ),
    # the treasure not said by name, or by a name of two objects; a count the scene does not
    # meet; no pirate's word; a person after 'Correction'; no report's frame
    ("Find the treasure, matey, and give it to Lily, arr!", None, NURSERY),
    ("Find the treasure, matey, the block, and give it to Lily, arr!", None, NURSERY),
    ("The three treasures, all of them, unto Person A.", None, F41),
    ("The two blocks be Lily's treasure, give her both!", None, NURSERY),
    (
        "We reported the cup was going to Person A. Correction: it's Person B.",
        None,
        F42,
    ),
    ("The cup was going to Person A. Correction: it's the apple.", None, F42),
)


# -- Singapore English's particles; a radio dedication; legal wording ---------------------------


test_dialects_and_frames = CASES.test(
    (
        "Bottle is what Alice want, crisps is for Bob one, can or not?",
        "bottle>A & chips>B",
        TWO,
    ),
    ("The crsps, Bob want one lah.", "chips>B", TWO),
    (
        "This one goes out to Lena, who'd love the tongs, and to Marco, who needs the knife!",
        "tongs>B & knife>A",
        KITCHEN,
    ),
    (
        "The stapler, hereinafter 'the item', is to be placed in the box. The notebook likewise.",
        "stapler@box & notebook@box",
        OFFICE,
    ),
    # session 28's near form; no particle; a person not in the scene; a name given that is an
    # object of the scene
    ("Two items, both give Alice lah.", None, TWO),
    ("Bottle is what Alice want, crisps is for Bob one.", None, TWO),
    ("The crsps, Carol want one lah.", None, TWO),
    (
        "This one goes out to Lena, who'd love the tongs, and to Bob, who needs the knife!",
        None,
        KITCHEN,
    ),
    ("The stapler, hereinafter 'the notebook', is to be placed in the box.", None, OFFICE),
    ("The stapler is to be placed in the box. Sam likewise.", None, OFFICE),
)


# -- the object said first, 'sorry' replacing nothing; 'either of them? Either thing' -----------


test_fronted_asked = CASES.test(
    (
        "The chips, sorry, Person A asked for them, could they go to her? Sorry.",
        "chips>A",
        L24,
    ),
    (
        "Sorry, could Person A have either of them? Either thing, I don't mind, sorry.",
        "bottle>A | chips>A",
        T21,
    ),
    # another object after 'sorry' (a correction); the pronoun cannot be the person by
    # title; four things for 'either'; 'either person'
    ("The chips, sorry, the bottle, Person A asked for them, could they go to her?", None, L24),
    ("The jug, sorry, Mr Lee asked for it, could it go to her?", None, WARD),
    (
        "Sorry, could Person A have either of them? Either thing, I don't mind, sorry.",
        None,
        F41,
    ),
    (
        "Sorry, could Person A have either of them? Either person, I don't mind, sorry.",
        None,
        T21,
    ),
)


# -- a closing reason naming only the object left out or corrected away ------------------------


test_reason_for_change = CASES.test(
    (
        "Give Person B everything you've got there but not the apple, she hates apples.",
        "bottle>B & chips>B & cup>B",
        SQ,
    ),
    (
        "Person B's having the chips, wait, sorry, the apple, I had chips on the brain.",
        "apple>B",
        L44,
    ),
    # another object in the reason; nothing left out or corrected away; the object kept
    ("Give Person B everything you've got there but not the apple, she hates cups.", None, SQ),
    ("Give Person B the apple, she hates apples.", None, SQ),
    ("Person B's having the chips and the apple, I had chips on the brain.", None, L44),
    (
        "Person B's having the chips, wait, sorry, the apple, I had apples on the brain.",
        None,
        L44,
    ),
)
