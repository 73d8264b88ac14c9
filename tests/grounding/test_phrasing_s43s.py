"""Session-43 phrasings of issue 12 (engineer 12s): remarks, reasons, run-ons, sequences and typos
of 'Person' beside a request (blind41's kinds, said in other words, scenes and people);
docs/grounding.md, "Session 43 (engineer 12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites42s as r42s
from hltl.grounding import _rewrites43s as r43s
from hltl.grounding import _rewrites44s as r44s
from hltl.grounding import _rewrites51s as r51s
from hltl.grounding import lexicon as lx
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
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
    assert_refused,
)

SQUARE = load_scene(ROOT / "examples/scenes/4-4-square.yaml")  # Person A, Person B

# -- a typo in 'Person' itself (_person_typo43s) ---------------------------------------------------

TYPO = PhrasingCases()
test_person_typo = TYPO.test(
    ("Persn A keeps pestering me about the stapler, so let her have it.", "stapler>A", OFFICE),
    ("persn b keeps nagging about the blue pen, so let him have it", "pen_blue>B", OFFICE),
    ("Plerson A keeps nagging about the apple, so let her have it.", "apple>A", SQUARE),
)
test_person_typo_refused = TYPO.test(
    # an English word one edit away, a letter no one of the scene is called by
    ("Prison B keeps nagging about the stapler, so let him have it.", None, OFFICE),
    ("Plerson Q keeps nagging about the stapler, so let him have it.", None, OFFICE),
)


def test_person_typo_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    TYPO.refused_without((r43s._person_typo43s,), monkeypatch)


# -- asking again and again, then 'let him have it' (_inferred42s, widened) ------------------------

NAGGING = PhrasingCases()
test_nagging = NAGGING.test(
    ("Zoe keeps nagging about the globe, so let her have it.", "globe>C", CLASSROOM),
    ("zoe keeps nagging about the globe so let her have it", "globe>C", CLASSROOM),
    ("Zoe keeps nagging about the gloeb, so let her have it.", "globe>C", CLASSROOM),
    ("Tom keeps pestering me for the scanner; he can have it.", "scanner>B", DEPOT),
    ("tom keeps pestering me about the scanner so let him have it", "scanner>B", DEPOT),
    ("Noah keeps glancing at the ruler; I reckon he'd love it.", "ruler>B", CLASSROOM),
)
test_nagging_refused = NAGGING.test(
    # a pronoun that cannot be the person, a surface
    ("Noah keeps nagging about the globe, so let her have it.", None, CLASSROOM),
    ("Tom keeps nagging about the pallet, so let him have it.", None, DEPOT),
)


def test_nagging_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NAGGING.refused_without((r42s._inferred42s,), monkeypatch)


# -- 'and <person> takes the X' after a request (_and_takes43s) ------------------------------------

TAKES = PhrasingCases()
test_and_takes = TAKES.test(
    ("Priya gets the notebook and Sam takes the stapler.", "notebook>A & stapler>B", OFFICE),
    ("priya gets the notebook and sam takes the staplr", "notebook>A & stapler>B", OFFICE),
    ("Give Marco the knife, and Lena takes the tongs.", "knife>A & tongs>B", KITCHEN),
)
test_and_takes_refused = TAKES.test(
    # somewhere to take it, or a pronoun for what she takes
    ("Give Marco the knife, and Lena takes the tongs to the rack.", None, KITCHEN),
    ("Give Marco the knife, and Lena takes them.", None, KITCHEN),
)


def test_and_takes_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    TAKES.refused_without((r43s._and_takes43s,), monkeypatch)


# -- a run-on of wants with no stops (_run_on_wants43s) --------------------------------------------

RUN_ON = PhrasingCases()
test_run_on_wants = RUN_ON.test(
    (
        "noah needs the glue zoe wants the globe and mrs ortiz would like the ruler",
        "glue>B & globe>C & ruler>A",
        CLASSROOM,
    ),
    (
        "Tom needs the gloves Mia wants the scanner and Tom would like the tape as well",
        "gloves>B & scanner>A & tape>B",
        DEPOT,
    ),
    (
        "Tom needs the glvoes Mia wants the scanner and Tom would like the tape as well",
        "gloves>B & scanner>A & tape>B",
        DEPOT,
    ),
)
test_run_on_wants_refused = RUN_ON.test(
    # no thing before the person: whom the glue is for?
    ("Noah needs the glue Zoe", None, CLASSROOM),
)


def test_run_on_wants_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 51 (12s): its run-on rule says these wants with their stops too
    RUN_ON.refused_without((r43s._run_on_wants43s, r51s._run_on51s), monkeypatch)


@pytest.mark.parametrize(
    "text",
    [
        "Zoe gets the ruler; the glue is Noah's.",
        "the glue is noah's, zoe wants the ruler",
        "Give Zoe the ruler, the glue is Noah's",
    ],
)
def test_run_on_wants_leaves_possessives(text: str) -> None:
    """A possessive after a thing is no new clause: no comma put in ("the chips are, Person B's"
    had made a corrected blind39 request unreadable)."""
    assert r43s._run_on_wants43s(text, lx.Lexicon.of(CLASSROOM)) == text


# -- a reason per person, then 'so' + what they get (_so_reason43s) --------------------------------

SO_REASON = PhrasingCases()
test_so_reason = SO_REASON.test(
    ("Zoe's painting so the glue is hers.", "glue>C", CLASSROOM),
    (
        "zoe's painting so the glue is hers, noah's measuring so he takes the ruler",
        "glue>C & ruler>B",
        CLASSROOM,
    ),
    ("Poor Marco burnt his thumb, so the lemon is his.", "lemon>A", KITCHEN),
    ("Poor Marco burnt his thumb, so the lemmon is his.", "lemon>A", KITCHEN),
)
test_so_reason_refused = SO_REASON.test(
    # a pronoun that cannot be the person; the reason names a surface of the scene
    ("Noah's painting so the glue is hers.", None, CLASSROOM),
    ("Noah's dusting the shelf so the glue is his.", None, CLASSROOM),
)


def test_so_reason_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 44 (12s): the opening-remark rule reads "Poor Marco burnt his thumb, so …" too
    SO_REASON.refused_without((r43s._so_reason43s, r44s._opening_remark44s), monkeypatch)


# -- a thing said to come before the rest (_priority43s) -------------------------------------------

PRIORITY = PhrasingCases()
test_priority = PRIORITY.test(
    (
        "Noah's globe comes first, and after that Zoe gets the ruler.",
        "globe>B ; ruler>C",
        CLASSROOM,
    ),
    ("noah's globe comes first and after that zoe gets the ruler", "globe>B ; ruler>C", CLASSROOM),
    (
        "Noah's gloeb comes first, and after that Zoe gets the ruler.",
        "globe>B ; ruler>C",
        CLASSROOM,
    ),
)
test_priority_refused = PRIORITY.test(
    # no one to give it to; a person said to come first
    ("The glue comes first.", None, CLASSROOM),
    ("Noah comes first, and after that Zoe gets the ruler.", None, CLASSROOM),
)


def test_priority_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PRIORITY.refused_without((r43s._priority43s,), monkeypatch)


# -- a thing claimed by a person (_claimed_by43s) --------------------------------------------------

CLAIMED = PhrasingCases()
test_claimed = CLAIMED.test(
    ("The torch is spoken for by Jess.", "torch>B", WORKSHOP),
    ("the drill is spoken for by kofi", "drill>A", WORKSHOP),
    ("The torhc is spoken for by Jess.", "torch>B", WORKSHOP),
    ("Mia wants the tape. The gloves are spoken for by Tom.", "tape>A & gloves>B", DEPOT),
)
test_claimed_refused = CLAIMED.test(
    # taken already, a surface, two people
    ("The torch was taken by Jess.", None, WORKSHOP),
    ("The bench is spoken for by Jess.", None, WORKSHOP),
    ("The torch is spoken for by Jess and Kofi.", None, WORKSHOP),
)


def test_claimed_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CLAIMED.refused_without((r43s._claimed_by43s,), monkeypatch)


# -- a surface said to be a thing's spot (_spot_for43s) --------------------------------------------

SPOT = PhrasingCases()
test_spot = SPOT.test(
    (
        "Pallet first, for the small box. After that, Tom gets the scanner.",
        "box_small@pallet ; scanner>B",
        DEPOT,
    ),
    (
        "the belt's the spot for the tape, and mia is having the gloves",
        "tape@conveyor & gloves>A",
        DEPOT,
    ),
    ("The pallett's the place for the tape.", "tape@pallet", DEPOT),
)
test_spot_refused = SPOT.test(
    # a person first, a thing said to be a spot
    ("Tom first, for the tape.", None, DEPOT),
    ("The tape's the spot for the gloves.", None, DEPOT),
)


def test_spot_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SPOT.refused_without((r43s._spot_for43s,), monkeypatch)


# -- the speaker finding the person (_found_person43s) ---------------------------------------------

FOUND = PhrasingCases()
test_found = FOUND.test(
    ("Where's Zoe... oh, there she is. The globe's hers.", "globe>C", CLASSROOM),
    ("where's noah? ah there, give him the ruler", "ruler>B", CLASSROOM),
    ("Where's Zoe... oh, there. The gloeb's hers.", "globe>C", CLASSROOM),
)
test_found_refused = FOUND.test(
    # a pronoun that cannot be them; a thing looked for
    ("Where's Zoe... oh, there. The globe's his.", None, CLASSROOM),
    ("Where's the globe... ah, there. Give it to Zoe.", None, CLASSROOM),
)


def test_found_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FOUND.refused_without((r43s._found_person43s,), monkeypatch)


# -- a remark of the person's liking, with or without 'because' (_liking_remark43s) ----------------

LIKING = PhrasingCases()
test_liking = LIKING.test(
    ("Give Lena the knife and the lemon to Marco he loves a slice", "knife>B & lemon>A", KITCHEN),
    ("give lena the knife and the lemon to marco he loves a slice", "knife>B & lemon>A", KITCHEN),
    ("Give Lena the knife and the lemmon to Marco he loves a slice", "knife>B & lemon>A", KITCHEN),
    (
        "Noah needs the ruler because he's a neat freak and Zoe would like the globe",
        "ruler>B & globe>C",
        CLASSROOM,
    ),
)
test_liking_need = LIKING.test(
    # what they are and a need of theirs, or the need alone
    ("the tongs are marco's, he's a grill cook and starving", "tongs>A", KITCHEN),
    ("The tongs are Marco's, he's the night porter.", "tongs>A", KITCHEN),
    ("The tnogs are Marco's, he's a grill cook.", "tongs>A", KITCHEN),
)
test_liking_refused = LIKING.test(
    # a pronoun that cannot be the person named before it; a thing of the scene in it
    ("Give Lena the knife and the ruler to Zoe he loves a slice", None, CLASSROOM),
    ("Give Lena the knife and the lemon to Marco, he loves the tongs", None, KITCHEN),
    ("The tongs are Marco's, she's a grill cook.", None, KITCHEN),
    # a need alone may ask for something to eat or drink: left to the older rules
    ("Give Lena the knife and Zoe the lemon because she's hungry", None, KITCHEN),
    ("The tongs are Marco's, he's the salt.", None, KITCHEN),
)


def test_liking_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LIKING.refused_without((r43s._liking_remark43s,), monkeypatch)


# -- a person said to be the one a thing is for (_one_for43s) --------------------------------------

ONE_FOR = PhrasingCases()
test_one_for = ONE_FOR.test(
    ("Zoe's the one the globe is for.", "globe>C", CLASSROOM),
    ("zoe's the one the ruler is for", "ruler>C", CLASSROOM),
    ("Dana's the one the bowl is for, ta.", "bowl>A", LAB),
    ("Zoe's the one the gloeb is for.", "globe>C", CLASSROOM),
)
test_one_for_refused = ONE_FOR.test(
    ("Zoe's the one the shelf is for.", None, CLASSROOM),
)


def test_one_for_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ONE_FOR.refused_without((r43s._one_for43s,), monkeypatch)


# -- 'for <person>' after a placement beside a handover (_placed_for43s) ---------------------------

PLACED_FOR = PhrasingCases()
test_placed_for = PLACED_FOR.test(
    ("Give Marco the knife and the salt on the rack for Mr Novak.", "knife>A & salt@rack", KITCHEN),
    ("give marco the knife and the salt on the rack for mr novak", "knife>A & salt@rack", KITCHEN),
    ("Give Marco the knife and the slat on the rack for Mr Novak.", "knife>A & salt@rack", KITCHEN),
)
test_placed_for_refused = PLACED_FOR.test(
    # another 'for' that may hand a thing over; the person who gets the knife
    (
        "Give Marco the knife and the salt on the rack for Lena and the lemon for Mr Novak.",
        None,
        KITCHEN,
    ),
    ("Give Marco the knife and the salt on the rack for Marco.", None, KITCHEN),
)


def test_placed_for_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PLACED_FOR.refused_without((r43s._placed_for43s,), monkeypatch)


# -- a person's doing to another, then a pronoun (_opening_doer43s) --------------------------------

DOER = PhrasingCases()
test_opening_doer = DOER.test(
    ("Ruth is washing Mr Lee; can you pass her the jug?", "jug>A", WARD),
    ("ruth is washing mr lee so pass her the jug", "jug>A", WARD),
    ("Grandad's feeding Lily; pass him the beakr.", "beaker>B", NURSERY),
)
test_opening_doer_refused = DOER.test(
    # the pronoun may be either; the pronoun is the other
    ("Ava's feeding Lily; pass her the beaker.", None, NURSERY),
    ("Ruth is washing Mr Lee; can you pass him the jug?", None, WARD),
)


def test_opening_doer_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DOER.refused_without((r43s._opening_doer43s,), monkeypatch)


# -- 'in with it' after a placement (_in_with43s) --------------------------------------------------

IN_WITH = PhrasingCases()
test_in_with = IN_WITH.test(
    ("Knife on the counter. Tongs on with it.", "knife@counter & tongs@counter", KITCHEN),
    (
        "put the knife on the counter and the salt on with it",
        "knife@counter & salt@counter",
        KITCHEN,
    ),
    (
        "The drill goes in the locker; the trorch in with it.",
        "drill@locker & torch@locker",
        WORKSHOP,
    ),
)
test_in_with_refused = IN_WITH.test(
    # a handover 'in with it'; two surfaces before it
    ("Put the knife on the counter. Give Lena the salt in with it.", None, KITCHEN),
    ("Put the knife on the counter and the tongs on the rack. The salt in with it.", None, KITCHEN),
)


def test_in_with_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    IN_WITH.refused_without((r43s._in_with43s,), monkeypatch)


# -- a thing, then whose it is, as a sentence of its own (_whose_after43s) -------------------------

WHOSE = PhrasingCases()
test_whose_after = WHOSE.test(
    ("Tape first. That's Tom's. After that, Mia's scanner.", "tape>B ; scanner>A", DEPOT),
    ("tape first. tom's. after that, mia's scanner", "tape>B ; scanner>A", DEPOT),
    ("Glvoes first. That's Tom's. After that, Mia's scanner.", "gloves>B ; scanner>A", DEPOT),
)
test_whose_after_refused = WHOSE.test(
    # a surface, two people
    ("The pallet first. Tom's.", None, DEPOT),
    ("Tape first. Tom's and Mia's.", None, DEPOT),
)


def test_whose_after_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHOSE.refused_without((r43s._whose_after43s,), monkeypatch)


# -- a second thing 'to go with it' (_go_with_it43s) -----------------------------------------------

GO_WITH_IT = PhrasingCases()
test_go_with_it = GO_WITH_IT.test(
    ("Give Zoe the glue and the ruler to go with it.", "glue>C & ruler>C", CLASSROOM),
    ("zoe needs the glue, plus the ruler to go with it", "glue>C & ruler>C", CLASSROOM),
    ("Zoe needs the glue, plus the rular to go with it.", "glue>C & ruler>C", CLASSROOM),
)
test_go_with_it_refused = GO_WITH_IT.test(
    # two people, a placement, one thing only: what does it go with?
    ("Give Zoe the glue and Noah the ruler to go with it.", None, CLASSROOM),
    ("Put the glue on the shelf and the ruler to go with it.", None, CLASSROOM),
    ("Give Zoe the glue to go with it.", None, CLASSROOM),
)


def test_go_with_it_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GO_WITH_IT.refused_without((r43s._go_with_it43s,), monkeypatch)


# -- 'when they're down', 'once he's holding it' (_once_there42s, widened) -------------------------

ONCE = PhrasingCases()
test_once_holding = ONCE.test(
    (
        "Put the hammer in the locker and when it's in, Jess gets the drill.",
        "hammer@locker ; drill>B",
        WORKSHOP,
    ),
    (
        "give tom the scanner and once he's holding it mia can have the tape",
        "scanner>B ; tape>A",
        DEPOT,
    ),
    (
        "Give Tom the scanner and once he's holding it, Mia gets the tpae.",
        "scanner>B ; tape>A",
        DEPOT,
    ),
)
test_once_holding_refused = ONCE.test(
    # nothing before it to be down; nothing after it (which is 'it', and when?)
    ("When it's down, give Kofi the drill.", None, WORKSHOP),
    (
        "Put the tape and the gloves on the belt, and give Tom the scanner once it's there",
        None,
        DEPOT,
    ),
    ("Give Mia the tape and put the scanner on the pallet when it's there", None, DEPOT),
    # 'he' who holds it cannot be Mia, who was given it
    ("give mia the tape and once he's holding it tom can have the scanner", None, DEPOT),
)


def test_once_holding_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ONCE.refused_without((r42s._once_there42s,), monkeypatch)


# -- out of reach, height (_placed_aside43s, _height43s) -----------------------------------------

ASIDE = PhrasingCases()
test_placed_aside = ASIDE.test(
    ("Pop the salt on the rack where the kids can't reach it.", "salt@rack", KITCHEN),
    ("pop the salt on the rack where the kids can't reach it", "salt@rack", KITCHEN),
    ("Pop the salt on the rack, out of sight of the twins.", "salt@rack", KITCHEN),
    ("Pop the slat on the rack, away from the cat.", "salt@rack", KITCHEN),
    ("Put the globe on the shelf where Noah's puppy can't chew it.", "globe@shelf", CLASSROOM),
)
test_placed_aside_refused = ASIDE.test(
    # a handover, a thing or a surface of the scene in the reason
    ("Give Lena the salt where the kids can't reach it.", None, KITCHEN),
    ("Pop the salt on the rack where the tongs can't reach it.", None, KITCHEN),
    ("Pop the salt on the rack out of reach of the counter.", None, KITCHEN),
)


def test_placed_aside_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ASIDE.refused_without((r43s._placed_aside43s,), monkeypatch)


HEIGHT = PhrasingCases()
test_height = HEIGHT.test(
    ("Put the globe high up on the shelf.", "globe@shelf", CLASSROOM),
    ("put the globe high up on the bookshelf", "globe@shelf", CLASSROOM),
    ("Put the gloeb way up on the shelf.", "globe@shelf", CLASSROOM),
)
test_height_refused = HEIGHT.test(
    ("Put the globe high up on the ceiling.", None, CLASSROOM),
)


def test_height_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HEIGHT.refused_without((r43s._height43s,), monkeypatch)


# -- a spell of work before a want, a doing over after it (_after_spell43s, _now_over43s) ----------

SPELL = PhrasingCases()
test_after_spell = SPELL.test(
    ("After a night on the fishing boats, Marco would love the lemon.", "lemon>A", KITCHEN),
    ("after a hard morning in the cold store, marco could murder the salt", "salt>A", KITCHEN),
    ("After a night on the fishing boats, Marco would love the lemmon.", "lemon>A", KITCHEN),
)
test_after_spell_refused = SPELL.test(
    # an order (when), a surface of the scene, two people
    ("After a night on the fishing boats, put the lemon on the rack.", None, KITCHEN),
    ("After a night on the counter, Marco would love the lemon.", None, KITCHEN),
    (
        "After a night on the fishing boats, Marco would love the lemon and Lena the knife.",
        None,
        KITCHEN,
    ),
)


def test_after_spell_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SPELL.refused_without((r43s._after_spell43s,), monkeypatch)


NOW_OVER = PhrasingCases()
test_now_over = NOW_OVER.test(
    ("Tom wants the scanner now his tea break is over.", "scanner>B", DEPOT),
    ("tom wants the scanner now that he's back from his run", "scanner>B", DEPOT),
    ("Tom wants the scannr now his tea break's over.", "scanner>B", DEPOT),
)
test_now_over_refused = NOW_OVER.test(
    # an order (now is when); a pronoun that is not him; a thing of the scene done
    ("Give Tom the scanner now his tea break is over.", None, DEPOT),
    ("Tom wants the scanner now her tea break is over.", None, DEPOT),
    ("Tom wants the scanner now the tape is done.", None, DEPOT),
)


def test_now_over_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOW_OVER.refused_without((r43s._now_over43s,), monkeypatch)


# -- putting away and clearing onto a place: placing verbs (lexicon.VERB_CLASS) --------------------

PLACING = [
    ("Pack the notebook away in the box.", "notebook@box", OFFICE),
    ("pack the blue pen in the box", "pen_blue@box", OFFICE),
    ("Clear the hammer and the torch onto the bench.", "hammer@bench & torch@bench", WORKSHOP),
    (
        "clear the hammer into the locker, then Jess gets the drill",
        "hammer@locker ; drill>B",
        WORKSHOP,
    ),
]
test_placing_verbs = PhrasingCases().test(
    *PLACING,
    # with nowhere to put it, or a person as the place
    ("Pack the stapler.", None, OFFICE),
    ("Pack Priya the stapler.", None, OFFICE),
    ("Clear the bench.", None, WORKSHOP),
)


def test_placing_verbs_are_verbs() -> None:
    """'pack' and 'clear' are verbs of the put class; 'packing' ('packing tape') and 'cleared'
    are not read as them."""
    assert lx.VERB_CLASS["pack"] == lx.VERB_CLASS["clear"] == "put"
    assert "packing" not in lx.VERBS and "cleared" not in lx.VERBS
    assert_refused("Pack the packing tape.", DEPOT)
