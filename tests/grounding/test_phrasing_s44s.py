"""Session-44 phrasings of issue 12 (engineer 12s): run-ons, sequences, remarks, asides, typos,
claim conditions and 'shelve' beside a request (blind42's kinds, said in other words, scenes and
people), and a name corrected after a clause; docs/grounding.md, "Session 44 (engineer 12s)"."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hltl.grounding import _rewrites44s as r44s
from hltl.grounding import phrasing
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    LAB,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
    tree,
)

TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # Alice (A), Bob (B); shelf
FIG1 = load_scene(ROOT / "examples/scenes/fig1.yaml")  # Alice (A), Bob (B); shelf
SQUARE = load_scene(ROOT / "examples/scenes/4-4-square.yaml")  # Person A, Person B
F41 = load_scene(ROOT / "examples/scenes/4-1.yaml")  # Person A, Person B

# -- a name corrected after a clause (phrasing._apply_correction, _name_after_clause44s) ----------
#
# "The bottle goes on the shelf, and Bob, sorry, Alice is having the crisps" had read chips>A
# alone: the whole first clause was taken back with the name.

NAME_FIXED = PhrasingCases()
test_name_corrected = NAME_FIXED.test(
    (
        "The shelf's the spot for the bottle, and Bob, sorry, Alice is having the crisps.",
        "bottle@shelf & chips>A",
        TWO,
    ),
    (
        "The bottle goes on the shelf, and Bob, sorry, Alice is having the crisps.",
        "bottle@shelf & chips>A",
        TWO,
    ),
    (
        "Put the globe on the shelf and Noah, sorry, Zoe is having the glue.",
        "globe@shelf & glue>C",
        CLASSROOM,
    ),
    (
        "The drill goes in the locker, and Jess, no, Kofi is having the screws.",
        "drill@locker & screws>A",
        WORKSHOP,
    ),
    (
        "Put the jug on the trolley, and Ruth, sorry, Mrs Khan is having the magazine.",
        "jug@trolley & magazine>C",
        WARD,
    ),
    (
        "Put the cup on the table, and Alice, sorry, Carol is having the apple.",
        "cup@table & apple>C",
        CELL,
    ),
)
test_name_corrected_refused = NAME_FIXED.test(
    # a list of people before the cue: which name does it take back?
    ("Give the bottle to Alice and Bob, sorry, Alice is having the crisps.", None, TWO),
)


def test_name_corrected_needs_the_fix(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the name found after the clause, the cue took the whole clause back (the placement
    dropped: a wrong reading, not a refusal)."""
    monkeypatch.setattr(phrasing, "_name_after_clause44s", lambda before, start: None)
    for text, want, scene in NAME_FIXED.read:
        got = tree(text, scene)
        assert got is not None and "place" not in str(got), (text, want, got)


PEOPLE_TWO = ("Alice", "Bob")


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    first=st.sampled_from(["The bottle goes on the shelf", "Put the bottle on the shelf"]),
    join=st.sampled_from([", and", " and"]),
    cue=st.sampled_from(["sorry", "no", "I mean"]),
    wrong=st.sampled_from(PEOPLE_TWO),
    right=st.sampled_from(PEOPLE_TWO),
    verb=st.sampled_from(["is having", "gets", "wants", "can have"]),
)
def test_name_corrected_keeps_the_clause(
    first: str, join: str, cue: str, wrong: str, right: str, verb: str
) -> None:
    """A placement, then a name taken back by a cue and a clause of the right person's: the
    placement is never dropped (read with it, or refused)."""
    text = f"{first}{join} {wrong}, {cue}, {right} {verb} the crisps."
    got = tree(text, TWO)
    assert got is None or "place" in str(got), (text, got)


# -- a claim condition after a thing (_if_spare44s) ------------------------------------------------

SPARE = PhrasingCases()
test_if_spare = SPARE.test(
    ("person b's asking for the cup, also the apple if it's going spare", "cup>B & apple>B", F41),
    (
        "Zoe's after the glue, and the ruler too if it's going spare.",
        "glue>C & ruler>C",
        CLASSROOM,
    ),
    ("Give Dana the bowl and the spoon if it's going begging.", "bowl>A & spoon>A", LAB),
    (
        "tom wants the gloves, also the tape if nobody else has claimed it",
        "gloves>B & tape>B",
        DEPOT,
    ),
    (
        "Mrs Khan would like the jug, and the magazine if its going spare.",
        "jug>C & magazine>C",
        WARD,
    ),
)
test_if_spare_refused = SPARE.test(
    # a condition on someone's word or doing, a surface that may or may not be free
    ("Give Zoe the glue if Noah's finished with it.", None, CLASSROOM),
    ("Give Dana the bowl, and the spoon if Omar says so.", None, LAB),
)


def test_if_spare_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SPARE.refused_without((r44s._if_spare44s,), monkeypatch)


# -- 'shelve' (_shelve44s) -------------------------------------------------------------------------

SHELVE = PhrasingCases()
test_shelve = SHELVE.test(
    (
        "shelve the crisps first and when that's done bob can have the bottle",
        "chips@shelf ; bottle>B",
        FIG1,
    ),
    ("Shelve the globe, then give Zoe the glue.", "globe@shelf ; glue>C", CLASSROOM),
    (
        "shelve the red book and the green book please",
        "book_red@shelf & book_green@shelf",
        CLASSROOM,
    ),
    ("Grab the crisps and shelve them.", "chips@shelf", TWO),
    ("Could you shelve the bottle for me?", "bottle@shelf", TWO),
    ("shelve the globle first, then the ruler to noah", "globe@shelf ; ruler>B", CLASSROOM),
)
test_shelve_refused = SHELVE.test(
    # another place said, no shelf in the scene, a person
    ("Shelve the globe on the desk.", None, CLASSROOM),
    ("Shelve the banana.", None, LAB),
    ("Shelve Zoe.", None, CLASSROOM),
)


def test_shelve_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SHELVE.refused_without((r44s._shelve44s,), monkeypatch)
