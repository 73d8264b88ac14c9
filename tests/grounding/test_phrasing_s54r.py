"""Session-54 phrasings of issue 12 (engineer 12r): 12c's open wrong reading and blind52's choices,
counts and corrections, each as a family (docs/grounding.md, "Session 54 (engineer 12r)"). Every
sentence that reads here was refused (or read wrongly) on main 8977c130, and is refused (or read
as before) with its rule taken out."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import show_tree
from hltl.grounding import phrasing
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
    tree,
)

# the example scenes blind52 uses
DUO, ONE, T12, F41, F42, L44, L24, T21, SQ, FIG1, TWO = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in (
        "2-2",
        "1-1",
        "1-2",
        "4-1",
        "4-2",
        "4-4-line",
        "2-4-line",
        "2-1",
        "4-4-square",
        "fig1",
        "two_arms",
    )
)

# -- 12c's fuzz: a correction after a sentence of words lexing drops ----------------------------

# phrasing._one_stop54r: 'Please.' / 'Um.' alone are sentences lexing empties ('. .'), and '?!' is
# two stops: the correction across the full stop took one stop off, found another and dropped the
# correction as 'nothing to correct' (main read each as the first thing AND the second)
ONE_STOP = PhrasingCases()
test_one_stop = ONE_STOP.test(
    ("Alice. Cup. Please. Sorry, the crisps.", "chips>A", CELL),
    ("Alice. Cup. Please. Sorry, the crisps. No wait, the water bottle.", "bottle>A", CELL),
    ("Give Bob the cup?! No, the apple.", "apple>B", CELL),
    ("Give Bob the cup. Please. Thanks. Sorry, the apple.", "apple>B", CELL),
    ("Marco. Salt. Please. Sorry, the lemon.", "lemon>A", KITCHEN),
    ("Give Mr Lee the jug. Please. No, the pills.", "pills>B", WARD),
    ("Mrs Khan. Magazine. Please. Oops, the grey blanket.", "blanket_grey>C", WARD),
    ("Hammer to Jess. Um. No wait, the drill.", "drill>B", WORKSHOP),
    ("Bottle for Person A. Please. Sorry, the chips.", "chips>A", DUO),
    # near: as refused without the empty sentence — a correction of one of two tasks, a time,
    # a past holding, a question, a correction naming nothing
    ("Give Alice the cup and Bob the apple. Please. No, give Bob the crisps.", None, CELL),
    ("Give Bob the cup tomorrow. Please. No, the apple.", None, CELL),
    ("Give Bob the cup. Please. No, the apple tomorrow.", None, CELL),
    ("Bob had the cup. Please. Sorry, the apple.", None, CELL),
    ("Did Bob get the cup? Please. No, the apple.", None, CELL),
    ("Give Bob the cup. Please. No.", None, CELL),
    ("Give Bob the cup. Please. No, the apple, Carol wants it.", None, CELL),
)
# read on main as they are here: an addition, an apology, a person or a place corrected
test_one_stop_kept = PhrasingCases().test(
    ("Give Bob the cup. Please. Also the crisps.", "cup>B & chips>B", CELL),
    ("Give Bob the cup. Please. Sorry.", "cup>B", CELL),
    ("Stapler to Priya. Please. No, to Sam.", "stapler>B", OFFICE),
    ("Teddy on the play mat. Please. No, the high chair.", "teddy@highchair", NURSERY),
    ("Put the small box on the pallet. Please. Sorry, the belt.", "box_small@conveyor", DEPOT),
)


@pytest.mark.parametrize(
    ("text", "scene", "said"),
    [
        ("Alice. Cup. Please. Sorry, the crisps.", CELL, "Alice. Cup. Sorry, the crisps."),
        ("Give Bob the cup?! No, the apple.", CELL, "Give Bob the cup? No, the apple."),
        (
            "Hammer to Jess. Um. No wait, the drill.",
            WORKSHOP,
            "Hammer to Jess. No wait, the drill.",
        ),
        (
            "Give Alice the cup and Bob the apple. Please. No, give Bob the crisps.",
            CELL,
            "Give Alice the cup and Bob the apple. No, give Bob the crisps.",
        ),
        ("Globe to Zoe. Please. Actually, Noah.", CLASSROOM, "Globe to Zoe. Actually, Noah."),
    ],
)
def test_one_stop_reads_as_without(text: str, scene, said: str) -> None:
    # the empty sentence (or the second stop) changes nothing: read as the text without it
    got, plain = tree(text, scene), tree(said, scene)
    assert (got and show_tree(got)) == (plain and show_tree(plain))


def test_one_stop_is_what_reads(monkeypatch: pytest.MonkeyPatch) -> None:
    # without it, none of the corrections reads as its reading (main's: both things)
    monkeypatch.setattr(phrasing, "_one_stop54r", lambda before: None)
    assert ONE_STOP.read
    for text, want, scene in ONE_STOP.read:
        got = tree(text, scene)
        assert got is None or show_tree(got) != want, text
