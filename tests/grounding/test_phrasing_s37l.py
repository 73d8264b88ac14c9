"""Session-37 phrasing of issue 12 (lead): wrong readings the fuzz found (docs/grounding.md,
"Session 37 (lead)").

- 12c's afterthoughts fuzz: "Zoe is thirsty. Books. Red one to Zoe." (classroom) read both books
  to Zoe, where "Books. Red one to Zoe." reads the red one alone: objects alone after a remark
  about one person are what that person gets ("Person A is thirsty. Bottle, please."), and
  'Books' was taken so though a later sentence picks one of them. Such objects alone are a
  heading now, and the remark only goes.
- 12c's frames fuzz: "Give Person B the bottle, er, no, the apple, my mistake. Person B's going to
  need the chips." (4-2) read chips>B: 'my mistake' closing the repair's sentence was taken for a
  correction of everything before the next sentence. It is said of the repair before it now, as
  at the end of the instruction."""

from __future__ import annotations

from tests.grounding.helpers import CLASSROOM, PhrasingCases
from tests.grounding.test_phrasing_s32r import F42

CASES = PhrasingCases()

test_objects_alone_as_a_heading = CASES.test(
    # a later sentence picks one of the objects alone: never both books to Zoe (refused)
    ("Zoe is thirsty. Books. Red one to Zoe.", None, CLASSROOM),
    ("Zoe is tired. Books. Red one to Zoe.", None, CLASSROOM),
    ("Zoe is thirsty. Books. Green one to Noah.", None, CLASSROOM),
    # without the remark, or without a later pick: read as before
    ("Books. Red one to Zoe.", "book_red>C", CLASSROOM),
    ("Zoe is thirsty. Red one to Zoe.", "book_red>C", CLASSROOM),
    ("Zoe is thirsty. Books.", "book_red>C & book_green>C", CLASSROOM),
    ("Person A is thirsty. Bottle, please.", "bottle>A", F42),
    ("Person A is thirsty. Bottle. Chips to Person B.", "bottle>A & chips>B", F42),
)

test_a_cue_closing_a_repairs_sentence = CASES.test(
    (
        "Give Person B the bottle, er, no, the apple, my mistake. Person B's going to need the "
        "chips.",
        "apple>B & chips>B",
        F42,
    ),
    (
        "Give Person B the bottle, er, no, the apple, my mistake. Person B wants the chips.",
        "apple>B & chips>B",
        F42,
    ),
    (
        "Give Person B the bottle, er, no, the apple, sorry. Person B wants the chips.",
        "apple>B & chips>B",
        F42,
    ),
    (
        "Give Person B the bottle, no, the apple, whoops. Give Person A the chips.",
        "apple>B & chips>A",
        F42,
    ),
    # at the end, or a correction after it: read as before
    ("Give Person B the bottle, no, the apple, my mistake.", "apple>B", F42),
    ("Give Person B the bottle, no, the apple, my mistake. No, the cup.", "cup>B", F42),
    ("Give Person B the bottle, my mistake. Person A gets it.", "bottle>A", F42),
)
