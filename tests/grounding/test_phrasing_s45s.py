"""Session-45 phrasings of issue 12 (engineer 12s): two wrong readings of main refused;
docs/grounding.md, "Session 45 (engineer 12s)"."""

from __future__ import annotations

from tests.grounding.helpers import (
    KITCHEN,
    LAB,
    OFFICE,
    PhrasingCases,
)

# -- two wrong readings of main ----------------------------------------------------------------
#
# 'Emma' and 'Priya' said no sex ("Emma wants the banana so pass it to him." read
# banana>C); a remark said before a request stood in for an 'it' whose object the request names
# before it (normalise._remarks: the salt handed over).

WRONG = PhrasingCases()
test_wrong_readings_refused = WRONG.test(
    ("Emma wants the banana so pass it to him.", None, LAB),
    ("Give Emma the banana. Pass the spoon to him.", None, LAB),
    ("Priya wants the stapler, hand it to him.", None, OFFICE),
    (
        "Marco has been given the salt shaker already. Don't put the lemon on the rack, give it "
        "to Marco",
        None,
        KITCHEN,
    ),
)
test_her_still_reads = WRONG.test(
    ("Lena wants the knife, give it to her.", "knife>B", KITCHEN),
    ("Emma wants the banana so pass it to her.", "banana>C", LAB),
)
