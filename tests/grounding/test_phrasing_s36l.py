"""Session-36 phrasing of issue 12 (lead): wrong readings the fuzz found (docs/grounding.md,
"Session 36 (lead)").

- 12c's remarks fuzz: "Give Person B a snack, the heating's off" (4-2) read any of the four
  objects: 'a snack, the …' was taken for a kind said before the object it is ("Person B wants a
  snack, the chips") whatever followed 'the', so 'a snack' became 'something' and the remark was
  dropped as a reason. The phrase after the comma must name an object of the scene now.
- 12c's repairs fuzz: "The stapler is for Sam, uh, no, Priya?" (office) read stapler>A, where
  "The stapler is for Priya?" is refused as a question: a comma beside a repair word ends no
  clause, but a filler between them ('uh') hid the repair. Fillers are passed over now.
- 12c's remarks fuzz: "Marco needs the knife so Lena can have the lemon. It's for the bake sale."
  (kitchen) read knife>A & lemon>B, where the sentence without the remark is refused: a want run
  on into 'so …' is split when the request after 'so' says 'it'/'them', and the 'It' of the next
  sentence was taken for it. Only the request's own sentence counts now."""

from __future__ import annotations

from tests.grounding.helpers import CELL, DEPOT, KITCHEN, NURSERY, OFFICE, PhrasingCases
from tests.grounding.test_phrasing_s32r import F42

CASES = PhrasingCases()

test_kind_before_its_object = CASES.test(
    # the kind, then the object it is: read as before
    ("Person B wants a snack, the chips please.", "chips>B", F42),
    ("Person B wants a drink, the bottle.", "bottle>B", F42),
    # the kind, then a remark naming nothing of the scene: no object is said (refused)
    ("Give Person B a snack, the heating's off", None, F42),
    ("Give Person B a drink, the heating's off", None, F42),
    ("Give Person B a snack, the lift's out again", None, F42),
    ("Person B wants a snack, the heating's off.", None, F42),
    # the kind does not fit the object (refused, as before)
    ("Person B wants a snack, the cup please.", None, F42),
)

test_repair_said_as_a_question = CASES.test(
    ("The stapler is for Sam, uh, no, Priya?", None, OFFICE),
    ("The stapler is for Sam, erm, no, Priya?", None, OFFICE),
    ("The stapler is for Sam, no, Priya?", None, OFFICE),
    # said as a statement or a request, the repair reads as before
    ("The stapler is for Sam, uh, no, Priya.", "stapler>A", OFFICE),
    ("Give the stapler to Sam, uh, no, Priya.", "stapler>A", OFFICE),
    ("Sam's busy, uh, can you give Priya the stapler?", "stapler>A", OFFICE),
)

test_run_on_want_its_own_sentence = CASES.test(
    ("Marco needs the knife so Lena can have the lemon. It's for the bake sale.", None, KITCHEN),
    ("Marco needs the knife so Lena can have the lemon.", None, KITCHEN),
    # the request after 'so' saying 'it' itself: split as before
    ("Marco needs the knife so hand it over.", "knife>A", KITCHEN),
    ("Marco needs the knife. It's for the bake sale.", "knife>A", KITCHEN),
)

test_both_said_to_go_on_a_surface = CASES.test(
    (
        "Tom's off, so can the packing tape and, er, the scanner go on the pallet for now?",
        None,
        DEPOT,
    ),
    ("Tom's off, so can the packing tape and the scanner go on the pallet for now?", None, DEPOT),
    # no person before them: both go there, as before
    (
        "Can the packing tape and, er, the scanner go on the pallet for now?",
        "tape@pallet & scanner@pallet",
        DEPOT,
    ),
    # a handover and a placement said apart: read as before
    (
        "Can Tom have the tape, and can the scanner go on the pallet?",
        "tape>B & scanner@pallet",
        DEPOT,
    ),
    ("the bottle goes to Alice and the chips go on the shelf", "bottle>A & chips@shelf", CELL),
)

test_an_order_word_keeps_the_opening_statement = CASES.test(
    ("Order's up so last, give Carol the apple. Then give Bob the chips.", None, CELL),
    # no order word: the statement is taken off as before
    ("Order's up, give Carol the apple.", "apple>C", CELL),
    ("Stock room's a mess, give Carol the apple.", "apple>C", CELL),
)

test_a_name_inside_a_things_name = CASES.test(
    ("give Lily the baby wipes, he's drawing margins.", None, NURSERY),
    ("give Ava the baby wipes, he's thirsty.", None, NURSERY),
    # a pronoun the person named may be, or no first name said: read as before
    ("give Lily the baby wipes, she's drawing margins.", "wipes>A", NURSERY),
    ("give the baby the baby wipes, he's drawing margins.", "wipes>A", NURSERY),
)
