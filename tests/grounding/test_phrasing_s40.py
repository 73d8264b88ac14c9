"""Session-40 phrasings of issue 12 (engineer 12): blind38's refusals by kind and the placing and
lending verbs the lexicon lacked (docs/grounding.md, "Session 40 (engineer 12)"). Each rule with
sentences it reads (which fail with the rule taken out) and near sentences that must stay
refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _normalise1, _rewrites40, lexicon, normalise, offline
from hltl.grounding.lexicon import VERB_CLASS, VERBS
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
    assert_reads,
)

# -- verbs of setting a thing down in a posture (stand, sit, hang; 'drop' in its other forms):
# placing verbs of the lexicon, with the frames of 'put' ---------------------------------------

POSTURE = PhrasingCases()

test_posture = POSTURE.test(
    ("Could you stand the cup on the counter?", "cup@table", CELL),
    ("Could you stand the teddy on the play mat, please?", "teddy@mat", NURSERY),
    ("Hang the tongs on the plate rack.", "tongs@rack", KITCHEN),
    ("Would you hang the large spanner in the locker?", "spanner_large@locker", WORKSHOP),
    ("Would you sit the teddy bear in the high chair?", "teddy@highchair", NURSERY),
    ("Fancy dropping the spoon in the sink?", "spoon@sink", LAB),
    ("Dropping the gloves on the pallet would be great.", "gloves@pallet", DEPOT),
    ("The blue blanket should be hung on the trolley.", "blanket_blue@trolley", WARD),
    ("Give Noah the ruler and stand the globe on the shelf.", "ruler>B & globe@shelf", CLASSROOM),
    (
        "Hang the torch on the workbench, then pass Jess the drill.",
        "torch@bench ; drill>B",
        WORKSHOP,
    ),
    # a person where a surface goes; the correction 'hang on'; 'hang about'; 'stand by'; 'drop'
    # alone (the update command); a posture said of a person
    ("Hang the tongs on Marco.", None, KITCHEN),
    ("Hang on to the tongs.", None, KITCHEN),
    ("Hang about, the tongs.", None, KITCHEN),
    ("Stand by.", None, KITCHEN),
    ("Drop the tongs.", None, KITCHEN),
    ("Sit Lily in the high chair.", None, NURSERY),
)


def test_posture_verbs_are_placing_verbs() -> None:
    """The lexicon's classes hold the posture verbs (not 'stood' / 'sat', said of people waiting,
    nor bare 'drop', the update command)."""
    for form, lemma in (("stand", "stand"), ("hanging", "hang"), ("sits", "sit")):
        assert VERBS[form] == lemma and VERB_CLASS[lemma] == "put"
    assert VERBS["dropping"] == "drop" and VERB_CLASS["drop"] == "put"
    assert "drop" not in VERBS and "stood" not in VERBS and "sat" not in VERBS


def _lexed_anew() -> None:
    """Forget what was lexed (lexicons keep texts lexed across instructions, and the keyword
    tables are cached): the lexicon's verbs are read anew."""
    lexicon._LEXICONS.clear()
    for fn in vars(lexicon).values():
        clear = getattr(fn, "cache_clear", None)
        if callable(clear):
            clear()


def test_posture_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the posture verbs in the lexicon each case is refused."""
    _lexed_anew()
    try:
        for form in [k for k, v in VERBS.items() if v in ("stand", "hang", "sit", "drop")]:
            monkeypatch.delitem(VERBS, form)
        POSTURE.refused_with(lexicon, "VERBS", VERBS, monkeypatch)
    finally:
        monkeypatch.undo()
        _lexed_anew()


# -- where a thing stands, sits or hangs: a description, refused (the posture verbs would read it
# as a placement); a modal or 'to be' asks for it ----------------------------------------------

test_posture_state = PhrasingCases().test(
    ("The cup is standing on the counter.", None, CELL),
    ("The red mug stands on the shelf.", None, CELL),
    ("The tongs are hanging on the plate rack, give them to Lena.", None, KITCHEN),
    ("The teddy sits on the play mat.", None, NURSERY),
    ("The magazine is still sitting on the trolley, so pass it to Mrs Khan.", None, WARD),
    ("The blue blanket is to be hung on the trolley.", "blanket_blue@trolley", WARD),
    ("The teddy can sit on the play mat.", "teddy@mat", NURSERY),
)


def test_posture_state_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the refusal, a posture said of a thing reads as its placement."""
    kept = tuple(r for r in offline._REFUSALS40 if r is not _rewrites40.posture_state40)
    monkeypatch.setattr(offline, "_REFUSALS40", kept)
    assert_reads("The red mug stands on the shelf.", "mug_red@shelf", CELL)
    assert_reads("The cup is standing on the counter.", "cup@table", CELL)


# -- 'X can be left on S': the passive of 'leave X on S' --------------------------------------

LEFT = PhrasingCases()

test_left_on = LEFT.test(
    ("The red mug can be left on the counter.", "mug_red@table", CELL),
    (
        "The apple is for Alice. Crisps, Bob. The blue mug can be left on the shelf.",
        "apple>A & chips>B & mug_blue@shelf",
        CELL,
    ),
    ("The stapler should be left in the box.", "stapler@box", OFFICE),
    ("the wipes can just be left on the play mat, thanks", "wipes@mat", NURSERY),
    ("The scanner is to be left on the belt.", "scanner@conveyor", DEPOT),
    # where it is; a person where a surface goes; a person left; said of the past; 'not'
    ("The red mug can be left where it is.", None, CELL),
    ("The stapler can be left with Sam.", None, OFFICE),
    ("Lily can be left on the play mat.", None, NURSERY),
    ("The stapler was left in the box.", None, OFFICE),
    ("The stapler shouldn't be left in the box.", None, OFFICE),
)


def test_left_on_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LEFT.refused_without(_rewrites40._STEPS40[:1], monkeypatch)


# -- lending: 'Would P be able to borrow X?' is 'Would P be able to have X?' (session 18's frame) --

BORROW = PhrasingCases()

test_borrow = BORROW.test(
    ("Would the teacher be able to borrow the red book?", "book_red>A", CLASSROOM),
    ("Would Jess be able to borrow the torch?", "torch>B", WORKSHOP),
    ("Is Sam able to borrow the stapler, do you reckon?", "stapler>B", OFFICE),
    # no person; two people; a person asked for
    ("Would you be able to borrow the torch?", None, WORKSHOP),
    ("Would Jess and Kofi be able to borrow the torch?", None, WORKSHOP),
    ("Would Jess be able to borrow Kofi?", None, WORKSHOP),
)


def test_borrow_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    """Session 18's frames (in both lists of rewrites) are what read the cases."""
    steps = tuple(s for s in normalise._STEPS if s is not _normalise1._frames18)
    monkeypatch.setattr(normalise, "_STEPS", steps)
    BORROW.refused_without((_normalise1._frames18,), monkeypatch)
