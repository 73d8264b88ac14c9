"""Session-35 phrasings of issue 12 (engineer 12r): blind33's choices, counts, negation,
exclusions and corrections; docs/grounding.md, "Session 35 (engineer 12r)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.grounding import normalise
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
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


# -- choices --------------------------------------------------------------------------------------


test_choices = CASES.test(
    # "she can take X" after a remark about her: "she can have X"
    (
        "Person A's the au pair, she can take the cup or the apple, whichever comes to hand.",
        "cup>A | apple>A",
        SQ,
    ),
    ("Person A's the au pair, she can take the cup.", "cup>A", SQ),
    # where to, or a person after 'take': left (refused)
    ("Person A's the au pair, she can take the cup to Person B.", None, SQ),
    ("Person A's the au pair, she can take Person B.", None, SQ),
    # "she really doesn't mind which"
    (
        "Pick any one of the four things for Person A, she really doesn't mind which, erokamano.",
        "bottle>A | chips>A | cup>A | apple>A",
        F42,
    ),
    ("Give Person A the bottle, she really doesn't mind which.", None, F42),  # no choice
    # a robot's choice said as the subject
    (
        "Whichever robot's idle can fetch the bottle for Person A, it makes no odds to me.",
        "bottle>A",
        T12,
    ),
    ("Whichever arm is free can take the cup to Person B.", "cup>B", SQ),
    ("Whichever person's idle can fetch the bottle for Person A.", None, T12),
    # "any of the K will do for P"
    (
        "Sam's the typist today, any of the pens will do for him.",
        "pen_black>B | pen_blue>B | pen_red>B",
        OFFICE,
    ),
    (
        "Kofi's on the lathe, any of the spanners will do for him.",
        "spanner_small>A | spanner_large>A",
        WORKSHOP,
    ),
    ("Any of the cups will do for Kofi.", None, WORKSHOP),  # no cups there
    ("Any of the pens will do for the box.", None, OFFICE),  # a surface: no such choice
    # "whichever K's handy"
    ("Kofi can take whichever spanner's handy.", "spanner_small>A | spanner_large>A", WORKSHOP),
    ("Kofi can take whichever cup's handy.", None, WORKSHOP),
)


# -- counts ---------------------------------------------------------------------------------------


test_counts = CASES.test(
    # a heading "one thing apiece", said otherwise; "the bottle finds Person A"
    (
        "They're to have one thing apiece, so the bottle finds Person A and the chips find "
        "Person B.",
        "bottle>A & chips>B",
        DUO,
    ),
    (
        "A single thing for each of them, so the cup across to Person A and the bottle across "
        "to Person B.",
        "cup>A & bottle>B",
        F42,
    ),
    # one person twice: the heading's count is checked, refused
    (
        "They're to have one thing apiece, so the bottle finds Person A and the chips find "
        "Person A.",
        None,
        DUO,
    ),
    (
        "A single thing for each of them, so the cup and the bottle across to Person A.",
        None,
        F42,
    ),
    # "There's just the one X here and it's meant for P": one X in the scene
    (
        "There's just the one bottle here and it's meant for Person A, after her gymnastics.",
        "bottle>A",
        L24,
    ),
    ("There's just the one mug here and it's meant for Bob.", None, CELL),  # two mugs
    ("There's just the one banana here and it's meant for Person A.", None, L24),
    # ', after her <activity>' closing a request (an object there is an order: left)
    ("The bottle is for Person A, after her gymnastics.", "bottle>A", L24),
    ("The bottle is for Person A after her gymnastics.", None, L24),  # no comma: a time
    ("The bottle is for Person A, after her pills.", None, L24),  # no pills there
    # "Those two cups are filthy, put the pair of them in the sink"
    (
        "Those two cups are filthy, put the pair of them in the sink to soak.",
        "cup_green@sink & cup_white@sink",
        LAB,
    ),
    ("Those three cups are filthy, put them in the sink.", None, LAB),  # two cups
    ("Those three cups are filthy, put the pair of them in the sink.", None, LAB),
    ("Those two cups are sponge, put them in the sink.", None, LAB),  # names a scene object
    # "Gather up X and drop them in S"
    (
        "Gather up all three pens and drop them in the box, we're closing for the night.",
        "pen_black@box & pen_blue@box & pen_red@box",
        OFFICE,
    ),
    ("Gather up all four pens and drop them in the box.", None, OFFICE),  # three pens
    ("Gather up all three pens and drop them on Sam.", None, OFFICE),  # a person
    # "Load S with every K (we've got), all N"
    (
        "Load the belt with every box we've got, all three, the longshoreman's waiting.",
        "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
        DEPOT,
    ),
    ("Load the belt with every box we've got, all four.", None, DEPOT),
    ("Load Tom with every box.", None, DEPOT),  # a person: no place
    # "Both Ks, the A one and the B one, go (away) in S"
    (
        "Both spanners, the big one and the small one, go away in the locker.",
        "spanner_small@locker & spanner_large@locker",
        WORKSHOP,
    ),
    ("Both spanners, the big one and the red one, go in the locker.", None, WORKSHOP),
    ("Both spanners, the big one and the big one, go in the locker.", None, WORKSHOP),
)


# -- negation and exclusion -----------------------------------------------------------------------


test_negation = CASES.test(
    (
        "It's the bottle Alice wants, not the crisps, she's off to her knitting circle.",
        "bottle>A",
        TWO,
    ),
    # what follows names the scene: left, and refused
    ("It's the bottle Alice wants, not the crisps, give Bob the crisps.", None, TWO),
    ("It's the bottle Alice wants, not the crisps, she's after the crisps.", None, TWO),
    (
        "It's the bottle Alice wants, not the banana, she's off to her knitting circle.",
        None,
        TWO,
    ),
    # "… and leave the X be"
    ("Bob fancies the crisps, so give him those and leave the bottle be.", "chips>B", FIG1),
    ("Give Bob the crisps and leave the crisps be.", None, FIG1),  # the task's own object
    ("Leave the bottle be.", None, FIG1),  # nothing else asked
    # "…, she brought her own flask" / "he's got wipes of his own"
    (
        "Person A can have the lot apart from the cup, she brought her own flask.",
        "bottle>A & chips>A & apple>A",
        SQ,
    ),
    ("Just the bib for Grandad, he's got wipes of his own.", "bib>B", NURSERY),
    # the thing she brought is one the request hands her; two people before 'he'
    ("Person A can have the lot apart from the cup, she brought her own bottle.", None, SQ),
    ("Just the bib for Grandad and Lily, he's got wipes of his own.", None, NURSERY),
    # 'she' cannot be Mr Lee (a title says he is a man)
    ("Just the jug for Mr Lee, she's got pills of her own.", None, WARD),
    # "P's allergic, so X goes to Q instead"
    ("Person A's allergic, so the apple goes to Person B instead.", "apple>B", L44),
    ("Person A's allergic, so the apple goes to Person A instead.", None, L44),
    ("Person A's allergic, so put the apple on the shelf instead.", None, CELL),
    # "…, though the apple stays where it is"
    ("Person B may have the cup, though the apple stays where it is.", "cup>B", F42),
    ("Person B may have the cup, though the cup stays where it is.", None, F42),
    # "…, so the bottle's hers"
    (
        "Person A doesn't want chips, she's on a diet for the dressage, so the bottle's hers.",
        "bottle>A",
        DUO,
    ),
    ("Alice is thirsty, so the bottle's hers.", "bottle>A", TWO),
    ("Person A doesn't want chips, so the banana's hers.", None, DUO),
    # "Only the X, and only to P, no other jobs for now"
    ("Only the bottle, and only to Person A, no other jobs for now.", "bottle>A", T12),
    ("Only the bottle, and only to Person C, no other jobs for now.", None, T12),
    ("Only the bottle, and only to the shelf.", None, T12),
    # "Apart from the two Ks, load every item onto S"
    (
        "Apart from the two cups, load every item onto the tray.",
        "spoon@tray & banana@tray & bowl@tray & sponge@tray",
        LAB,
    ),
    ("Apart from the three cups, load every item onto the tray.", None, LAB),  # two cups
)


# -- corrections ----------------------------------------------------------------------------------


test_corrections = CASES.test(
    (
        "Crisps to Alice, oops, I've gone and got it wrong, Bob's the one who ordered them.",
        "chips>B",
        TWO,
    ),
    # no correction cue before it; the same person again
    ("Crisps to Alice, Bob's the one who ordered them.", None, TWO),
    ("Crisps to Alice, oops, I got it wrong, Carol's the one who ordered them.", None, TWO),
    (
        "Stick the bottle on the shelf; actually, no, Alice would rather have it in her hand.",
        "bottle>A",
        FIG1,
    ),
    ("Stick the bottle on the shelf; Alice would rather have it in her hand.", None, FIG1),
    (
        "Person B's getting the bottle. Hang about, no, it's Person A who's getting it.",
        "bottle>A",
        DUO,
    ),
    (
        "Person B's getting the bottle. Hang about, no, it's Person C who's getting it.",
        None,
        DUO,
    ),
    ("Person A's getting the chips, oh wait, I meant the bottle for her.", "bottle>A", L24),
    # two people before 'her': which one the correction is for is unsaid
    (
        "Person A's getting the chips, Person B the cup, oh wait, I meant the bottle for her.",
        None,
        SQ,
    ),
    (
        "Take the bottle over to Person B, or rather Person A, I keep mixing them up.",
        "bottle>A",
        T12,
    ),
    ("Take the bottle over to Person B, or rather Person C.", None, T12),
    (
        "Chips for Person A, no, hang on, I had them the wrong way about: Person B's chips.",
        "chips>B",
        T21,
    ),
    ("Chips for Person A, I had them the wrong way about: Person B's chips.", None, T21),
    (
        "Priya was to get the stapler, but change that, Sam's doing the filing, so him.",
        "stapler>B",
        OFFICE,
    ),
    # the reason names an object; the person corrected to is the one corrected away
    (
        "Priya was to get the stapler, but change that, Sam's got the pens, so him.",
        None,
        OFFICE,
    ),
    (
        "Priya was to get the stapler, but change that, Priya's doing the filing, so her.",
        None,
        OFFICE,
    ),
    (
        "Give the teddy to Ava, whoops, no, it belongs to Lily, give it to her.",
        "teddy>A",
        NURSERY,
    ),
    ("Give the teddy to Ava, it belongs to Lily, give it to her.", None, NURSERY),
    (
        "Give the jug to Mr Lee, sorry, no, it belongs to Mrs Khan, give it to her.",
        "jug>C",
        WARD,
    ),
    # 'him' cannot be Mrs Khan; the owner no person
    ("Give the jug to Mr Lee, sorry, no, it belongs to Mrs Khan, give it to him.", None, WARD),
    (
        "Give the teddy to Ava, whoops, no, it belongs to the play mat, give it to her.",
        None,
        NURSERY,
    ),
)


# -- blind20's two left: a remark of the hour, a handover from the person's side ----------------


test_blind20 = CASES.test(
    (
        "Sorry, it's gone three in the morning and I'm the only one on the floor. If you could "
        "just, um, set the thermometer on the bedside table, that'd be grand.",
        "thermometer@bedside",
        WARD,
    ),
    (
        "It's past midnight and I'm the only one in the office. Give Sam the stapler, please.",
        "stapler>B",
        OFFICE,
    ),
    # the place names the scene; the sentence says more than the hour
    (
        "It's gone three in the morning and I'm the only one on the trolley. Set the jug on "
        "the bedside table.",
        None,
        WARD,
    ),
    (
        "It's gone three in the morning and I'm the only one who knows. Set the jug on the "
        "bedside table.",
        None,
        WARD,
    ),
    (
        "Okay, so Person A takes the bottle off you. And for Person B, the cup, she's been "
        "patient.",
        "bottle>A & cup>B",
        SQ,
    ),
    ("Person A takes the bottle off Person B.", None, SQ),  # from another person
    ("Person A takes the bottle off you. And for Person C, the cup.", None, SQ),
    ("Person A takes the banana off you.", None, SQ),
)


# -- blind21's corrections and counts -------------------------------------------------------------


test_blind21 = CASES.test(
    # "…, or, ugh, my notes are smudged, the apple it says": what the notes say corrects
    ("Person A gets the cup, or, ugh, my notes are smudged, the apple it says.", "apple>A", SQ),
    ("Person A gets the cup, or, ugh, the banana it says.", None, SQ),  # no banana
    # two tasks before it: which one the notes correct is not said
    ("Person A gets the cup and the chips, or, ugh, the apple it says.", None, SQ),
    ("Person A gets the cup, Person B the chips, or, ugh, the apple it says.", None, SQ),
    # "<one handover>. Er, hold on, she'd rather have the X, go with that."
    (
        "For Person A, the chips. Er, hold on, she'd rather have the bottle, go with that.",
        "bottle>A",
        DUO,
    ),
    ("Give Alice the crisps. Hang on, she'd rather have the bottle.", "bottle>A", TWO),
    # the same object; two handovers before it; 'she' cannot be Mr Lee
    ("For Person A, the chips. Er, hold on, she'd rather have the chips.", None, DUO),
    (
        "For Person A, the chips, and Person B the bottle. Er, hold on, she'd rather have the cup.",
        None,
        DUO,
    ),
    ("Give Mr Lee the jug. Hang on, she'd rather have the magazine.", None, WARD),
    # "P likes both her Ks …, so put the pair of them in S"
    (
        "Lily likes both her blocks with her when she eats, so put the pair of them in the "
        "high chair.",
        "block_red@highchair & block_green@highchair",
        NURSERY,
    ),
    (
        "Bob likes both his mugs, so put the pair of them on the shelf.",
        "mug_red@shelf & mug_blue@shelf",
        CELL,
    ),
    ("Emma likes her spoons, so put them in the sink.", None, LAB),  # one spoon
    ("Bob likes both his mugs, so put the pair of them on Alice.", None, CELL),
)


# -- blind25, blind29 and blind31: the same kinds ------------------------------------------------


test_blind25_to_31 = CASES.test(
    (
        "There's just the single bottle, so hand that to Person A, she'll make it last.",
        "bottle>A",
        ONE,
    ),
    ("There's just the single mug, so hand that to Bob.", None, CELL),  # two mugs
    ("There's just the single bottle, so hand that to Person C.", None, L24),
    ("Not apple. Bottle, for Person B, please. Madloba.", "bottle>B", F41),
    ("Not apple. Apple, for Person B.", None, F41),  # the same object
    ("Not banana. Bottle, for Person B.", None, F41),  # no banana there
    # a time after a request puts it off (session 34's "Give Carol the apple after her
    # walk."), with or without a comma; a single mug of two (session 31)
    ("A single bottle will do for Person A after her orienteering.", None, T12),
    ("Give Person A the bottle, after her orienteering.", None, T12),
    ("A single mug will do for Alice, after her walk.", None, CELL),
    (
        "They each get a thing, so bottle for Person A and chips for Person B, natotela.",
        "bottle>A & chips>B",
        T21,
    ),
    (
        "They each get a thing, so the bottle for Person A and the chips for Person A.",
        None,
        DUO,
    ),
)


# -- blind22's choices, negation and corrections ---------------------------------------------------


test_blind22 = CASES.test(
    (
        "Give Carol either of the mugs, she's not fussed which, she only wants a brew.",
        "mug_red>C | mug_blue>C",
        CELL,
    ),
    # what she wants is a thing of the scene
    (
        "Give Carol either of the mugs, she's not fussed which, she only wants a mug.",
        None,
        CELL,
    ),
    ("Give Person A the apple, there is only one only, don't worry.", "apple>A", F41),
    ("Give Alice the red mug, there is only one.", None, CELL),  # two mugs
    (
        "Give Alice a mug, but not the red one, that's the controller's and they're funny "
        "about it.",
        "mug_blue>A",
        CELL,
    ),
    # 'he' could be someone of the scene (offline.py's guard); an owner of the scene
    (
        "Give Alice a mug, but not the red one, that's the controller's and he's funny about it.",
        None,
        CELL,
    ),
    ("Give Bob a mug, but not the red one, that's Carol's.", None, CELL),
    (
        "Don't give Bob the crisps, they're bad for his teeth, give him the bottle instead.",
        "bottle>B",
        FIG1,
    ),
    ("Don't give Bob the crisps, give her the bottle instead.", None, FIG1),
    ("Don't give Bob the crisps, Alice wants them, give him the bottle instead.", None, FIG1),
    ("Give the bottle to whoever isn't Person A.", "bottle>B", DUO),
    ("Give the cup to whoever isn't Alice.", None, CELL),  # three people
    ("Give the bottle to whoever isn't Person C.", None, DUO),
    (
        "Tom can have anything but the tape and the boxes and the scanner, I'm not fussed what.",
        "gloves>B",
        DEPOT,
    ),
    ("Tom can have anything but the tape and the boxes.", "scanner>B | gloves>B", DEPOT),
    ("Tom can have anything but the tape and the hammer.", None, DEPOT),  # no hammer
    # nothing left
    ("Tom can have anything but the boxes, the gloves, the tape and the scanner.", None, DEPOT),
    (
        "Put the stapler in the box, actually, on the desk is better, I keep losing it.",
        "stapler@desk",
        OFFICE,
    ),
    (
        "Give Jess the spanner that isn't already sitting on the bench, she'll know why.",
        "spanner_small>B",
        WORKSHOP,
    ),
    ("Give Jess the spanner that isn't already sitting on the floor.", None, WORKSHOP),
)


def test_a_label_the_scene_has_is_the_grammars_correction() -> None:
    """With a Person B in the scene, "… to Person B, or rather Person A" is the grammar's own
    correction (read before these steps, as it is now)."""
    assert_case("Take the bottle over to Person B, or rather Person A.", "bottle>A", DUO)


def test_refused_without_these_steps(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence these rules read is refused with the session-35 (12r) steps taken out: each
    rule is what reads it."""
    CASES.refused_without(normalise._STEPS35R, monkeypatch)
