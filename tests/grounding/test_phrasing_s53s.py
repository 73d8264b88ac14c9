"""Session-53 phrasings of issue 12 (engineer 12s): 12c's wrong readings and blind51's sentence
splits, negation and exclusion, and typos, each as a family (fresh sentences in other scenes,
each read (wrongly) or refused on main b4e4e6fc as the test says, and near sentences);
docs/grounding.md, "Session 53 (engineer 12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites38s as r38s
from hltl.grounding import _rewrites42r as r42r
from hltl.grounding import _rewrites53s as r53s
from hltl.grounding import _rewrites54s as r54s
from hltl.grounding import offline
from hltl.world.scene import Scene, load_scene
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
    assert_case,
    tree,
)

FIG1, F41, ONE, T12, SQ, DUO, L24, T21 = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("fig1", "4-1", "1-1", "1-2", "4-4-square", "2-2", "2-4-line", "2-1")
)

# -- a he / she after a person left out by 'not' (_not_them53s, a check) ----------------------
#
# each read on main b4e4e6fc with the thing the pronoun's clause names given to the one the
# request hands to, though the pronoun may be (or can only be) the person left out (12c's fuzz,
# sessions 52 and 53)
NOT_THEM = [
    ("Give Alice the apple, not Bob, he wanted the crisps.", CELL),
    ("Give Alice the apple, not Carol, she wants the crisps.", CELL),
    ("Give Alice the cup, not Bob, he had the apple.", CELL),
    ("Give Alice the apple, not Bob. He wanted the crisps.", CELL),
    ("Give Alice the apple, not Carol, then give her the crisps.", CELL),
    ("Give Alice the apple, not Bob, the crisps are for him.", CELL),
    ("Give Alice the apple instead of Carol, she wants the crisps.", CELL),
    ("The apple to Alice, not Carol, she'd like the crisps.", CELL),
    ("Give Marco the salt, not Mr Novak, he wants the knife.", KITCHEN),
    ("Give Lena the salt, not Marco, he wanted the knife.", KITCHEN),
    ("Give Marco the salt, not Lena, she wanted the knife.", KITCHEN),
    ("Give Ava the teddy, not Lily, she wants the bib.", NURSERY),
    ("Give Mia the tape, not Tom, he wanted the scanner.", DEPOT),
    ("Give Priya the stapler, not Sam, he had the notepad.", OFFICE),
]


@pytest.mark.parametrize(("text", "scene"), NOT_THEM)
def test_not_them53s_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_not_them53s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the check each is read (the thing given to the one the request hands to)."""
    kept = tuple(c for c in offline._CHECKS if c is not r53s._not_them53s)
    monkeypatch.setattr(offline, "_CHECKS", kept)
    # 'he had the apple' is refused before the read too (_pronoun_had53s, below)
    asked = tuple(r for r in offline._REFUSALS if r is not r53s._pronoun_had53s)
    monkeypatch.setattr(offline, "_REFUSALS", asked)
    for text, scene in NOT_THEM:
        assert tree(text, scene) is not None, text


# near sentences: the pronoun cannot be the person left out, its clause names no thing ('it'), a
# person is named instead of a pronoun, a remark before the request: read as before
test_not_them53s_near = PhrasingCases().test(
    ("Give Bob the cup, not Alice, he wants the apple.", "cup>B & apple>B", CELL),
    ("Give Lena the salt, not Marco, she wants the knife too.", "salt>B & knife>B", KITCHEN),
    ("Give Alice the apple, not Bob, he wanted it.", "apple>A", CELL),
    ("Give Alice the cup, not Bob, Carol wants the apple.", "cup>A & apple>C", CELL),
    ("Not Bob, he's on a diet for the arm wrestling; the crisps go to Alice.", "chips>A", CELL),
    ("Give Alice the cup, not the apple, she wants the crisps.", "cup>A & chips>A", CELL),
)


# -- a placing or handover said the other way round (_goes_to53s) -----------------------------
GOES_TO = PhrasingCases()
test_goes_to53s = GOES_TO.test(
    (
        "Bob gets the crisps first. Once he has them, over to Alice goes the cup.",
        "chips>B ; cup>A",
        CELL,
    ),
    ("Onto the belt goes the small box.", "box_small@conveyor", DEPOT),
    (
        "Over to Mia goes the tape, then onto the pallet go the gloves.",
        "tape>A ; gloves@pallet",
        DEPOT,
    ),
    (
        "First the pills to Mr Lee, then over to Mrs Khan goes the magazine.",
        "pills>B ; magazine>C",
        WARD,
    ),
    ("Across to Jess goes the torch.", "torch>B", WORKSHOP),
    ("Onto the shelf go the crisps and the apple.", "chips@shelf & apple@shelf", CELL),
)
test_goes_to53s_near = GOES_TO.test(
    # asked, said as done, a pronoun for the thing or the person: refused as before
    ("Over to Alice goes the cup?", None, CELL),
    ("Over to Alice goes the cup, doesn't it?", None, CELL),
    ("Over to Alice went the cup.", None, CELL),
    ("Over to Alice goes it.", None, CELL),
    ("To Alice goes the cup tomorrow.", None, CELL),
)


def test_goes_to53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GOES_TO.refused_without((r53s._goes_to53s,), monkeypatch)


# -- a claim said by an idiom (_claimed53s; each refused on main b4e4e6fc) ---------------------
CLAIMED = PhrasingCases()
test_claimed53s = CLAIMED.test(
    (
        "Crisps for Alice, she put her hand up for them. Bob, on the other hand, has picked the "
        "bottle.",
        "chips>A & bottle>B",
        FIG1,
    ),
    ("Knife for Marco, he put his hand up for it.", "knife>A", KITCHEN),
    ("Mrs Khan put her hand up for the magazine.", "magazine>C", WARD),
    (
        "Lena's picked the blue plate, Marco has chosen the white one.",
        "plate_blue>B & plate_white>A",
        KITCHEN,
    ),
    ("Mr Lee has picked the jug.", "jug>B", WARD),
    ("Jess has opted for the torch.", "torch>B", WORKSHOP),
)
test_claimed53s_near = CLAIMED.test(
    # picked up / out (a doing), gone for (may be gone to fetch it), a past perfect, a tag, the
    # pronoun not fitting the request's person, a pick then given to another: refused
    ("Alice's picked the crisps up.", None, CELL),
    ("Alice has picked the red mug up.", None, CELL),
    ("Alice's picked the crisps out.", None, CELL),
    ("Bob's gone for the apple.", None, CELL),
    ("Crisps for Alice, she had put her hand up for them.", None, CELL),
    ("Crisps for Alice, she put her hand up for them, didn't she?", None, CELL),
    ("Crisps for Alice, he put his hand up for them.", None, CELL),
    ("Alice has picked the crisps, give them to Bob.", None, CELL),
    ("Alice has picked the crisps, hasn't she?", None, CELL),
)


def test_claimed53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CLAIMED.refused_without((r53s._claimed53s,), monkeypatch)


# -- a negated 'put the X down' before its handover (_dont_down53s; each refused on main) -------
DONT_DOWN = PhrasingCases()
test_dont_down53s = DONT_DOWN.test(
    ("Don't put the bottle down, give it straight to Person A.", "bottle>A", ONE),
    ("Don't put the knife down, hand it straight to Marco.", "knife>A", KITCHEN),
    ("Don't set the salt down, Lena wants it.", "salt>B", KITCHEN),
    ("Don't put the jug down, take it to Mr Lee.", "jug>B", WARD),
    ("Don't put the drill down, give it to Kofi.", "drill>A", WORKSHOP),
)
test_dont_down53s_near = DONT_DOWN.test(
    # a placing after it, a later time, a holding, a question, a wait: refused as before
    ("Don't put the cup down, put it on the shelf.", None, CELL),
    ("Don't put the cup down, give it to Bob tomorrow.", None, CELL),
    ("Don't put the cup down, Bob had it.", None, CELL),
    ("Don't put the cup down, did Bob want it?", None, CELL),
    ("Don't put the cup down, give it to Bob once Alice is back.", None, CELL),
    ("Don't put the cup down, give it to Bob, he's had one.", None, CELL),
)


def test_dont_down53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DONT_DOWN.refused_without((r53s._dont_down53s,), monkeypatch)


# -- 'much rather' (_much_rather53s; each refused on main) --------------------------------------
MUCH_RATHER = PhrasingCases()
test_much_rather53s = MUCH_RATHER.test(
    ("Person A has gone off the bottle, she'd much rather have the cup.", "cup>A", F41),
    ("Marco has gone off the knife, he'd much rather have the tongs.", "tongs>A", KITCHEN),
    ("Mr Lee would far rather have the magazine.", "magazine>B", WARD),
    ("Kofi would much rather have the hammer.", "hammer>A", WORKSHOP),
)
test_much_rather53s_near = MUCH_RATHER.test(
    # what would have been, asked, a tag, 'than', someone else having it: refused as before
    ("Alice would much rather have had the cup.", None, CELL),
    ("Would Alice much rather have the cup?", None, CELL),
    ("Alice would much rather have the cup, wouldn't she?", None, CELL),
    ("Alice would much rather Bob had the cup.", None, CELL),
)


def test_much_rather53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    MUCH_RATHER.refused_without((r53s._much_rather53s,), monkeypatch)


# -- 'and to nobody else' before a remark (_nobody_else53s; each refused on main) ---------------
NOBODY_ELSE = PhrasingCases()
test_nobody_else53s = NOBODY_ELSE.test(
    (
        "The bottle goes to Person A and to nobody else, she put her name on it this morning.",
        "bottle>A",
        T12,
    ),
    (
        "The pills go to Mr Lee and to no one else, he asked for them this morning.",
        "pills>B",
        WARD,
    ),
    (
        "The magazine goes to Mrs Khan and nobody else, she asked for it this morning.",
        "magazine>C",
        WARD,
    ),
    (
        "The torch goes to Jess and nobody else, she put her hand up for it this morning.",
        "torch>B",
        WORKSHOP,
    ),
)
test_nobody_else53s_near = NOBODY_ELSE.test(
    # another person named after it, a pronoun that does not fit: refused as before
    ("The cup goes to Alice and to nobody else, Bob wanted it.", None, CELL),
    ("The cup goes to Alice and to nobody else, he asked for it.", None, CELL),
)


def test_nobody_else53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOBODY_ELSE.refused_without((r53s._nobody_else53s,), monkeypatch)


# -- "It's the X for P" and 'at all' after a not-wanting (_its_for53s; each refused on main) ----
ITS_FOR = PhrasingCases()
test_its_for53s = ITS_FOR.test(
    ("It's the cup for Person B, he doesn't want the apple at all.", "cup>B", SQ),
    ("It's the stapler for Sam, he doesn't want the notepad at all.", "stapler>B", OFFICE),
    ("It's the jug for Mr Lee, he doesn't need the pills at all.", "jug>B", WARD),
    ("Give Mrs Khan the magazine, she doesn't want the jug at all.", "magazine>C", WARD),
    ("It's the tape for Mia, she doesn't want the gloves at all.", "tape>A", DEPOT),
    ("It's the notepad for Priya.", "notebook>A", OFFICE),
)
test_its_for53s_near = ITS_FOR.test(
    # asked, past, a time, a thing the person has had, the thing not wanted given: refused
    ("It's the cup for Bob, isn't it?", None, CELL),
    ("It's the cup for Bob?", None, CELL),
    ("It was the cup for Bob.", None, CELL),
    ("It's the cup for Bob tomorrow.", None, CELL),
    ("It's the cup for Bob, he had the apple.", None, CELL),
    ("It's the cup for Bob, he doesn't want the cup at all.", None, CELL),
)


def test_its_for53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ITS_FOR.refused_without((r53s._its_for53s,), monkeypatch)


# -- a he / she / they who had or got a thing (_pronoun_had53s, a refusal) ---------------------
#
# each read on main b4e4e6fc with the thing had handed over too
PRONOUN_HAD = [
    ("Give Bob the cup, he had the apple.", CELL),
    ("Give Bob the cup. He had the apple.", CELL),
    ("Give Alice the cup and she had the apple.", CELL),
    ("Give Bob the cup, they had the apple.", CELL),
    ("Give Marco the salt, he had the lemon.", KITCHEN),
    ("Give Sam the stapler, he had the notepad.", OFFICE),
    ("Give Priya the stapler. She got the notepad.", OFFICE),
]


@pytest.mark.parametrize(("text", "scene"), PRONOUN_HAD)
def test_pronoun_had53s_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_pronoun_had53s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the refusal each is read (the thing had handed over too; session 55: 12s's check
    `_had_it55s` refuses 'he had the apple' beside a handover of the apple to him too, the same
    family, and is taken out as well)."""
    from hltl.grounding import _rewrites55s

    kept = tuple(r for r in offline._REFUSALS if r is not r53s._pronoun_had53s)
    monkeypatch.setattr(offline, "_REFUSALS", kept)
    checks = tuple(c for c in offline._CHECKS if c is not _rewrites55s._had_it55s)
    monkeypatch.setattr(offline, "_CHECKS", checks)
    for text, scene in PRONOUN_HAD:
        assert tree(text, scene) is not None, text


# near sentences: 'had it' (the thing of the request), 'had to': read as before
test_pronoun_had53s_near = PhrasingCases().test(
    ("Give Bob the apple, he had it first.", "apple>B", CELL),
    ("Give Bob the apple, he asked for it.", "apple>B", CELL),
)


# -- 'the Y is what P should get' after a not-wanting (session 42's _negated_then42r, widened) --
SHOULD_GET = PhrasingCases()
test_should_get42r = SHOULD_GET.test(
    (
        "Noah's not to have the scissors today, the ruler is what he should get instead.",
        "ruler>B",
        CLASSROOM,
    ),
    ("Zoe's not to have the glue stick, the ruler is what she should get.", "ruler>C", CLASSROOM),
    ("Bob isn't after the apple, the cup is what he should have.", "cup>B", CELL),
    (
        "Mr Lee's not to have the pills today, the jug is what he should get instead.",
        "jug>B",
        WARD,
    ),
)
test_should_get42r_near = SHOULD_GET.test(
    # another person, a pronoun that does not fit, what should have been: refused as before
    ("Bob's not to have the apple, the cup is what Alice should get.", None, CELL),
    ("Bob's not to have the apple, the cup is what she should get.", None, CELL),
    ("Bob's not to have the apple, the cup is what he should have had.", None, CELL),
)


def test_should_get42r_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SHOULD_GET.refused_without((r42r._negated_then42r,), monkeypatch)


# -- 'it isn't P who …, it's Q' (_not_who53s; each refused on main b4e4e6fc) --------------------
NOT_WHO = PhrasingCases()
test_not_who53s = NOT_WHO.test(
    ("It isn't Person A who's having the bottle, it's Person B, give it to him.", "bottle>B", DUO),
    (
        "Person B's not the one the chips are meant for, it's Person A who gets them.",
        "chips>A",
        L24,
    ),
    ("It isn't Lena who's having the knife, it's Marco, give it to him.", "knife>A", KITCHEN),
    ("Marco's not the one the lemon is meant for, it's Lena who gets it.", "lemon>B", KITCHEN),
    ("Lena isn't the one who's getting the salt, it's Mr Novak.", "salt>C", KITCHEN),
    (
        "It isn't Mr Lee who's getting the magazine, it's Mrs Khan, hand it to her.",
        "magazine>C",
        WARD,
    ),
    ("It's not Sam who's having the stapler, it's Priya.", "stapler>A", OFFICE),
)
test_not_who53s_near = NOT_WHO.test(
    # a tag, a remark, a pronoun that is not Q's, said as past, the same person: refused
    ("It isn't Alice who's having the apple, it's Bob, is it?", None, CELL),
    ("It isn't Alice who's having the apple, it's Bob, he had it yesterday.", None, CELL),
    ("It isn't Alice who's having the apple, it's Bob, give it to her.", None, CELL),
    ("Alice's not the one the crisps are meant for, it's Carol, she had them.", None, CELL),
    ("It wasn't Alice who was having the apple, it was Bob.", None, CELL),
    ("It isn't Alice who's having the apple, it's Alice.", None, CELL),
    ("It isn't Alice who's getting the apple, it's Bob who wanted it.", None, CELL),
)


def test_not_who53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 54's _not_that54s reads the same family in its own words (it calls this rule)
    NOT_WHO.refused_without((r53s._not_who53s, r54s._not_that54s), monkeypatch)


# -- 'on the S beside it' and a closing "that's all for the S" (_all_for53s; refused on main) ---
ALL_FOR = PhrasingCases()
test_all_for53s = ALL_FOR.test(
    (
        "The small box goes on the belt. Stick the medium box on the belt beside it. That's all "
        "for the belt.",
        "box_small@conveyor & box_medium@conveyor",
        DEPOT,
    ),
    (
        "Put the tape on the pallet, and the gloves on the pallet next to it. That's all for the "
        "pallet.",
        "tape@pallet & gloves@pallet",
        DEPOT,
    ),
    (
        "Lemon on the worktop, salt on the worktop beside it, that's everything for the worktop.",
        "lemon@counter & salt@counter",
        KITCHEN,
    ),
    ("Put the cup on the shelf. That's all for the shelf.", "cup@shelf", CELL),
)
test_all_for53s_near = ALL_FOR.test(
    # an 'it' with nothing to stand for, beside a person or a surface, a closer naming a surface
    # nothing goes to, asked, said as done: refused as before
    ("Put the cup on the shelf next to it.", None, CELL),
    ("Put the apple on the shelf next to Bob.", None, CELL),
    ("Put the cup on the shelf beside the table.", None, CELL),
    ("Put the cup on the shelf beside the apple.", None, CELL),
    ("Put the cup on the shelf, and the apple on the table beside it.", None, CELL),
    ("Put the cup on the shelf. That's all for the table.", None, CELL),
    ("Put the cup on the shelf. That's all for the shelf?", None, CELL),
    ("Bob put the cup on the shelf beside it. That's all for the shelf.", None, CELL),
)


def test_all_for53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ALL_FOR.refused_without((r53s._all_for53s,), monkeypatch)


# -- exclusion said with more words (_every_single53s; each refused on main b4e4e6fc) -----------
EVERY_SINGLE = PhrasingCases()
test_every_single53s = EVERY_SINGLE.test(
    (
        "Every single thing goes on the belt apart from the work gloves and the barcode scanner.",
        "box_small@conveyor & box_medium@conveyor & box_large@conveyor & tape@conveyor",
        DEPOT,
    ),
    (
        "Every single thing goes on the bench apart from the drill.",
        "spanner_small@bench & hammer@bench & screws@bench & torch@bench & spanner_large@bench",
        WORKSHOP,
    ),
    (
        "Each and every thing goes to Lena apart from the knife.",
        "plate_white>B & lemon>B & salt>B & plate_blue>B & tongs>B",
        KITCHEN,
    ),
    (
        "Apart from the mugs, which are staying exactly where they are, everything's going to "
        "Alice for her picnic.",
        "cup>A & bottle>A & chips>A & apple>A",
        CELL,
    ),
    (
        "Except for the plates, which are staying put, everything goes to Marco.",
        "knife>A & lemon>A & salt>A & tongs>A",
        KITCHEN,
    ),
)
test_every_single53s_near = EVERY_SINGLE.test(
    # said as done, asked, what is left out wanted by another: refused
    (
        "Apart from the mugs, which are staying where they are, everything went to Alice.",
        None,
        CELL,
    ),
    ("Every single thing goes to Alice, apart from the mugs?", None, CELL),
    ("Apart from the mugs, which Bob wants, everything's going to Alice.", None, CELL),
)


def test_every_single53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    EVERY_SINGLE.refused_without((r53s._every_single53s,), monkeypatch)


# -- 'everything' said as done or asked (_everything_said53s, a refusal) ------------------------
#
# each read on main b4e4e6fc as every thing handed over or placed
EVERYTHING_SAID = [
    ("Everything went to Alice.", CELL),
    ("Everything goes to Alice?", CELL),
    ("Everything's gone to Alice apart from the mugs.", CELL),
    ("Everything goes to Alice, apart from the mugs?", CELL),
    ("Everything went on the shelf.", CELL),
]


@pytest.mark.parametrize(("text", "scene"), EVERYTHING_SAID)
def test_everything_said53s_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_everything_said53s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the refusal each is read."""
    kept = tuple(r for r in offline._REFUSALS if r is not r53s._everything_said53s)
    monkeypatch.setattr(offline, "_REFUSALS", kept)
    for text, scene in EVERYTHING_SAID:
        assert tree(text, scene) is not None, text


# near sentences: a request for everything, asked of the hearer: read as before
test_everything_said53s_near = PhrasingCases().test(
    ("Everything goes to Alice apart from the mugs.", "cup>A & bottle>A & chips>A & apple>A", CELL),
    (
        "Can you give Alice everything except the mugs?",
        "cup>A & bottle>A & chips>A & apple>A",
        CELL,
    ),
)


# -- a remark of what another has already had (session 38's _about_them38s, widened) ------------
ALREADY_HAD = PhrasingCases()
test_already_had38s = ALREADY_HAD.test(
    ("Omar's the one getting the banana, Emma's already had her fruit.", "banana>B", LAB),
    (
        "Mr Lee's the one getting the magazine, Mrs Khan's already had her turn.",
        "magazine>B",
        WARD,
    ),
    ("Marco's the one getting the lemon, Lena's already had her break.", "lemon>A", KITCHEN),
    ("Sam's the one getting the stapler, Priya's already had her coffee.", "stapler>B", OFFICE),
)
test_already_had38s_near = ALREADY_HAD.test(
    # the one who gets it has already had theirs: refused
    ("Give Omar the banana, Omar's already had his fruit.", None, LAB),
)


def test_already_had38s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ALREADY_HAD.refused_without((r38s._about_them38s,), monkeypatch)


# -- 12c's probes of the batch (session 53, 16:22): each rewrite leaves a holding, a having had
# or a doing beside its request as it is (_UNSAFE53S): refused
test_unsafe53s_near = PhrasingCases().test(
    ("Bob's picked the apple, he's eating it.", None, CELL),
    ("Bob put his hand up for the apple and got it.", None, CELL),
    ("It's the apple for Bob, he had it yesterday.", None, CELL),
    ("Bob has picked the apple, so it's his now.", None, CELL),
    ("Don't put the cup down, Bob's got it.", None, CELL),
    ("Over to Alice goes the cup, she's had one.", None, CELL),
    ("Kofi would much rather have the hammer, he took the drill.", None, WORKSHOP),
)


# -- 'over to P with the X' in a later clause (_to_with53s; each refused on main b4e4e6fc) -------
TO_WITH = PhrasingCases()
test_to_with53s = TO_WITH.test(
    (
        "Over to Pesson A with the bottle, and across to Person B with the chips.",
        "bottle>A & chips>B",
        T21,
    ),
    (
        "Over to Marco with the knife, and across to Lena with the salt.",
        "knife>A & salt>B",
        KITCHEN,
    ),
    ("Give Lena the tongs, then over to Mr Novak with the lemon.", "tongs>B ; lemon>C", KITCHEN),
    (
        "Over to Mr Lee with the jug, and across to Mrs Khan with the magazine.",
        "jug>B & magazine>C",
        WARD,
    ),
    ("Over to Alice with the cup, and across to Bob with the crisps.", "cup>A & chips>B", CELL),
)
test_to_with53s_near = TO_WITH.test(
    # asked, 'it' for the thing, a having had, said as done: refused as before
    ("Over to Alice with the cup, and across to Bob with the crisps?", None, CELL),
    ("Over to Alice with the cup, and across to Bob with it.", None, CELL),
    ("Give Alice the cup, and over to Bob with the crisps, he had them.", None, CELL),
    ("Give Alice the cup, and Bob went over to Carol with the crisps.", None, CELL),
)


def test_to_with53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    TO_WITH.refused_without((r53s._to_with53s,), monkeypatch)
