"""Session-36 phrasing of issue 12 (lead): wrong readings the fuzz found (docs/grounding.md,
"Session 36 (lead)").

- 12c's remarks fuzz: "Give Person B a snack, the heating's off" (4-2) read any of the four
  objects: 'a snack, the …' was taken for a kind said before the object it is ("Person B wants a
  snack, the chips") whatever followed 'the', so 'a snack' became 'something' and the remark was
  dropped as a reason. The phrase after the comma must name an object of the scene now."""

from __future__ import annotations

from tests.grounding.helpers import PhrasingCases
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
