"""Session-50 phrasings of issue 12 (engineer 12r): blind48's choices, counts and corrections, each
as a family; docs/grounding.md, "Session 50 (engineer 12r)". Every sentence that reads here was
refused on issue-lead 3667287b."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites50r, _rewrites51r, _rewrites55r
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
)

CASES = PhrasingCases()


def _scene(name: str):
    return load_scene(ROOT / f"examples/scenes/{name}.yaml")


TWO, DUO, ONE, T12, F42, L44, FIG1 = (
    _scene(n) for n in ("two_arms", "2-2", "1-1", "1-2", "4-2", "4-4-line", "fig1")
)

# -- blind48: choices, who is meant, both ------------------------------------------------------

test_batch1 = CASES.test(
    # _will_do_for50r: "… so either mug will do for her", "Any of the four will do for P,
    # whatever's handiest" (near: a count not the scene's; a pronoun that cannot be the person)
    (
        "Carol's off to the allotment, so either mug will do for her.",
        "mug_red>C | mug_blue>C",
        CELL,
    ),
    (
        "Bob's heading out on patrol, so any mug at all will do for him.",
        "mug_red>B | mug_blue>B",
        CELL,
    ),
    (
        "Lena's serving the starters, so either plate'll do for her, white or blue.",
        "plate_white>B | plate_blue>B",
        KITCHEN,
    ),
    (
        "Ava's building a tower, so either block will do for her, she won't be fussy.",
        "block_red>C | block_green>C",
        NURSERY,
    ),
    (
        "Any of the six will do for Carol, whatever's handiest.",
        "cup>C | bottle>C | chips>C | apple>C | mug_red>C | mug_blue>C",
        CELL,
    ),
    ("Any of the four would do for Person B.", "bottle>B | chips>B | cup>B | apple>B", L44),
    ("Any of the three will do for Person A.", None, F42),
    ("Any of the four would do for Carol.", None, CELL),
    ("Bob's off on patrol, so either mug will do for her.", None, CELL),
    ("Sam's in a rush, so either pen will do for him.", None, OFFICE),
    # _not_bothered_which50r: "P's not bothered which, X or Y(, just one of them)" (near: the
    # pronoun is not P; an option not of the kind)
    ("Alice isn't bothered which, bottle or crisps, just one of them.", "bottle>A | chips>A", TWO),
    (
        "Marco's not fussy which plate, the white or the blue.",
        "plate_white>A | plate_blue>A",
        KITCHEN,
    ),
    ("Noah isn't too bothered which book, red or green.", "book_red>B | book_green>B", CLASSROOM),
    (
        "Omar's not fussed which cup, the green or the white, either one.",
        "cup_green>B | cup_white>B",
        LAB,
    ),
    ("Person B's not bothered which, bottle or chips, she'll take one.", None, DUO),
    ("Kofi isn't fussed which spanner, the big or the drill.", None, WORKSHOP),
    # _play_with50r: "P'll play with whichever block, red or green" (near: an option not of the
    # kind; the pronoun)
    ("Ava'll play with either block, red or green.", "block_red>C | block_green>C", NURSERY),
    (
        "Noah'll happily settle for whichever book, the red or the green.",
        "book_red>B | book_green>B",
        CLASSROOM,
    ),
    (
        "Mr Novak will manage with either plate, he won't be fussy.",
        "plate_white>C | plate_blue>C",
        KITCHEN,
    ),
    ("Lily'll play with whichever block, red or teddy.", None, NURSERY),
    ("Mr Novak will manage with either plate, she won't be fussy.", None, KITCHEN),
    # _one_of_and50r: "one of the X and the Y" is the choice (refused when the speaker lost which)
    ("Alice asked for one of the bottle and the crisps.", "bottle>A | chips>A", TWO),
    ("Mr Novak asked for one of the knife and the tongs.", "knife>C | tongs>C", KITCHEN),
    ("Jess asked for either of the torch and the hammer.", "torch>B | hammer>B", WORKSHOP),
    ("Alice asked for one of the bottle and the crisps, and I've forgotten which.", None, TWO),
    # _lay_hands50r: "Whichever bottle you can lay a hand on, P's to get it" (near: the pronoun
    # is not P)
    (
        "Whichever mug you can get your hands on, Alice is to have it.",
        "mug_red>A | mug_blue>A",
        CELL,
    ),
    ("Whatever jug you can get hold of, give it to Ruth.", "jug>A", WARD),
    (
        "Whichever bottle you can put a hand on, Person A's to have it, she's on call.",
        "bottle>A",
        ONE,
    ),
    ("Whichever bottle you can lay a hand on, Person B's to get it.", None, T12),
    # _for_role50r: "For the make-up artist, that's P, <what>" (near: the role is someone else)
    ("For the night watchman, that's Bob, the red mug.", "mug_red>B", CELL),
    (
        "For the head cook, that is Marco, the knife or the tongs, he's not fussy.",
        "knife>A | tongs>A",
        KITCHEN,
    ),
    ("For the scout leader, that's Person B, the chips please.", "chips>B", DUO),
    ("For the waitress, that's Marco, the knife.", None, KITCHEN),
    # _says_both50r: "P says both the X and the Y(, …)" (near: the pronoun is not P)
    (
        "Alice says both the cup and the bottle, she's off to the allotment.",
        "cup>A & bottle>A",
        CELL,
    ),
    ("Lena said both the knife and the lemon.", "knife>B & lemon>B", KITCHEN),
    (
        "Kofi reckons both the torch and the hammer, he's up the ladder.",
        "torch>A & hammer>A",
        WORKSHOP,
    ),
    ("Alice says both the cup and the bottle, he's off to the allotment.", None, CELL),
    # _both_the_and50r: "both the small and the medium box" (near: a word that names no box)
    ("Both the white and the blue plate go to Mr Novak.", "plate_white>C & plate_blue>C", KITCHEN),
    (
        "Both the small and the large spanner go to Jess.",
        "spanner_small>B & spanner_large>B",
        WORKSHOP,
    ),
    (
        "Mia's stacking the shelves, so both the medium and the large box go to Mia.",
        "box_medium>A & box_large>A",
        DEPOT,
    ),
    ("Both the small and the tiny box go to Tom.", None, DEPOT),
    # _role_says50r: "…, the intern isn't choosy", "…, the visitor's brought …" (near: the role
    # is someone else)
    (
        "The stapler or the notebook for Priya, the manager won't be fussy.",
        "stapler>A | notebook>A",
        OFFICE,
    ),
    (
        "Both cups go to Emma, the visitor's brought her sister along.",
        "cup_green>C & cup_white>C",
        LAB,
    ),
    (
        "Any pen at all for Sam, the intern isn't picky.",
        "pen_black>B | pen_blue>B | pen_red>B",
        OFFICE,
    ),
    (
        "The lemon to Marco, sorry, I mean Lena, the waitress wants it squeezed over the fish.",
        "lemon>B",
        KITCHEN,
    ),
    ("Both cups go to Emma, the doctor's brought her sister along.", None, LAB),
    ("Any pen at all for Sam, the manager isn't choosy.", None, OFFICE),
)


# -- blind48: counts and corrections ---------------------------------------------------------------

test_batch2 = CASES.test(
    # _one_there50r: "There's only the one X at <a place not in the scene>, and P's to have
    # it" / "…, and P has called dibs on it" (near: the scene has two; the place is a surface
    # of the scene)
    ("There's only the one apple at the allotment, and Carol's to have it.", "apple>C", CELL),
    ("There's just the one bag of crisps, and Bob's to have it.", "chips>B", FIG1),
    ("There's only the one lemon, and Lena has called dibs on it.", "lemon>B", KITCHEN),
    ("There's just the one jug at the nurses' station, and Mr Lee has bagged it.", "jug>B", WARD),
    ("There's only the one mug at the allotment, and Carol's to have it.", None, CELL),
    ("There's only the one lemon on the rack, and Lena's to have it.", None, KITCHEN),
    # _lone_in50r: "the lone bottle in the room" (near: the scene has two)
    ("The lone apple in the room goes to Bob, he's on nights.", "apple>B", CELL),
    ("Give Dana the sole banana on hand.", "banana>A", LAB),
    ("The one and only lemon in here is for Mr Novak.", "lemon>C", KITCHEN),
    ("The lone cup in the room goes to Dana.", None, LAB),
    # _lot_of_them50r: "The three boxes, onto the belt with the lot of them(, …)" (near: no
    # such surface)
    (
        "The three boxes, onto the pallet with the lot of them.",
        "box_small@pallet & box_medium@pallet & box_large@pallet",
        DEPOT,
    ),
    (
        "Both plates, on the rack with the pair of them, the guests are early.",
        "plate_white@rack & plate_blue@rack",
        KITCHEN,
    ),
    (
        "The two books, onto the shelf with the lot of them, Mrs Ortiz's lesson starts soon.",
        "book_red@shelf & book_green@shelf",
        CLASSROOM,
    ),
    ("The three boxes, onto the van with the lot of them.", None, DEPOT),
    # _pair_wants50r: "The pair of spanners wants locking away in the locker" (near: no pair
    # in the scene)
    (
        "The pair of books needs tidying away on the shelf before the lesson.",
        "book_red@shelf & book_green@shelf",
        CLASSROOM,
    ),
    ("The drill wants locking away in the locker.", "drill@locker", WORKSHOP),
    ("The pair of bananas wants putting away on the tray.", None, LAB),
    # _said_why50r: "…, no, hold on, she said crisps at the meeting(, so the crisps)" (near:
    # the pronoun is not the person; the 'so' names another thing)
    ("The cup to Bob, no, hang on, he said apple at the allotment, so the apple.", "apple>B", CELL),
    (
        "The lemon to Marco, no, my mistake, he asked for the salt on his way to the pass.",
        "salt>A",
        KITCHEN,
    ),
    (
        "The jug to Mrs Khan, no, wait, she said the grey blanket during the ward round.",
        "blanket_grey>C",
        WARD,
    ),
    ("The bottle to Alice, no, hold on, he said crisps at the bill sticker's meeting.", None, TWO),
    (
        "The bottle to Alice, no, hold on, she said crisps at the bill sticker's meeting, so the "
        "bottle.",
        None,
        TWO,
    ),
    # _so_to50r: "…, no, silly me, P's a big girl now, so to Q(, she's …)", "…, it's Q who's
    # back from …, so to him" (near: the pronoun is not Q; the remark names a thing of the
    # scene)
    (
        "Chips to Person B, no, hang on, it's Person A who's back from the fells starving, so to "
        "her.",
        "chips>A",
        DUO,
    ),
    (
        "Teddy to Lily, no, silly me, Lily's fast asleep, so to Ava, she's wide awake.",
        "teddy>C",
        NURSERY,
    ),
    ("Teddy to Lily, no, silly me, Lily's fast asleep, so to Ava, he's wide awake.", None, NURSERY),
    ("Cup to Alice, no, sorry, Alice has the apple, so to Carol.", None, CELL),
    # _instead_why50r: "X to P, no, the Y instead, <why>" (near: the why names someone or
    # something else)
    ("Gloves to Mia, no, the tape instead, she already has a pair.", "tape>A", DEPOT),
    ("Hammer for Jess, no, the screws instead, Jess has her own hammer.", None, WORKSHOP),
    (
        "Hammer for Jess, no, the screws instead, the apprentice is fixing a shelf.",
        "screws>B",
        WORKSHOP,
    ),
    ("Gloves to Mia, no, the tape instead, Tom has the gloves.", None, DEPOT),
    # _where_it_lives50r: "…, no, in the locker, where it lives (…)" (near: the remark names a
    # thing of the scene)
    (
        "Torch on the bench, no, in the locker, where it lives between spelunking trips.",
        "torch@locker",
        WORKSHOP,
    ),
    ("The salt on the counter, no, on the rack, where it always lives.", "salt@rack", KITCHEN),
    ("The globe on the desk, no, on the shelf, where it's kept.", "globe@shelf", CLASSROOM),
    ("Torch on the bench, no, in the locker, where it lives next to the drill.", None, WORKSHOP),
)


def test_rewrites_read_them(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 51 (12r; at the merge): its rules of the same families read some of these too
    # session 55 (lead, at the merge): 12r's _with_them55r reads 'with the lot of them' too
    CASES.refused_without(
        (*_rewrites50r._STEPS50R, *_rewrites51r._STEPS51R, _rewrites55r._with_them55r), monkeypatch
    )
