"""Session-53 phrasings of issue 12 (engineer 12): blind51's politeness and fillers, wants and
needs, pronouns and ellipsis, lower case and questions, each as a family (docs/grounding.md,
"Session 53 (engineer 12)"). Each rule with sentences in other words and scenes it reads (refused
on main and with the rule taken out), and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites53
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene, load_scene
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
    assert_reads,
    assert_refused,
)

# the example scenes blind51 uses
DUO, ONE, F41, T12, T21, FIG1, L44, SQ = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("2-2", "1-1", "4-1", "1-2", "2-1", "fig1", "4-4-line", "4-4-square")
)

# -- politeness and fillers ---

# thanks ahead in two or three foreign words (_thanks_two53)
THANKS_TWO = PhrasingCases()
test_thanks_two = THANKS_TWO.test(
    ("Baie dankie in advance, my friend, Person B would really like the chips.", "chips>B", DUO),
    ("Vielen Dank in advance, Lena wants the salt.", "salt>B", KITCHEN),
    ("Baie dankie so much, could Mr Lee have the magazine?", "magazine>B", WARD),
    ("Kiitos paljon in advance, give Bob the apple.", "apple>B", CELL),
    ("Muito obrigado again, the torch to Jess.", "torch>B", WORKSHOP),
    ("Danke sehr in advance, Bob wanted the apple.", None, CELL),
    ("Dave Jones in advance, Bob wants the apple.", None, CELL),
    ("Mille grazie in advance, give Bob the apple tomorrow.", None, CELL),
    ("Merci bien again, Bob had the apple.", None, CELL),
)


def test_thanks_two_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THANKS_TWO.refused_without((_rewrites53._thanks_two53,), monkeypatch)


# "Whenever's convenient," and 'whenever ur free' (_whenever53)
WHENEVER = PhrasingCases()
test_whenever = WHENEVER.test(
    (
        "Whenever's convenient, pal, the packing tape wants to go on the belt.",
        "tape@conveyor",
        DEPOT,
    ),
    ("the bottle is for person a whenever ur free no rush", "bottle>A", T12),
    ("Whenever's good for you, give Bob the apple.", "apple>B", CELL),
    ("give bob the apple when ur done", "apple>B", CELL),
    ("Whenever's convenient, Priya would like the stapler.", "stapler>A", OFFICE),
    ("Whenever's convenient, Tom has the gloves.", None, DEPOT),
    ("give bob the apple when ur back tomorrow", None, CELL),
    ("bob had the apple whenever ur free", None, CELL),
    ("Whenever's convenient, Bob's had the apple.", None, CELL),
)


def test_whenever_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHENEVER.refused_without((_rewrites53._whenever53,), monkeypatch)


# an opening 'bit of a ramble, but' (_ramble53)
RAMBLE = PhrasingCases()
test_ramble = RAMBLE.test(
    ("Right, bit of a ramble, but the bottle, Person A, whenever suits you.", "bottle>A", T12),
    ("Right, bit of a ramble, but the apple, Bob, whenever suits you.", "apple>B", CELL),
    ("Right, bit of a waffle, but Marco needs the lemon.", "lemon>A", KITCHEN),
    ("Bit of a saga, but the jug to Mrs Khan.", "jug>C", WARD),
    ("So, such a rigmarole, but Lily wants her teddy.", "teddy>A", NURSERY),
    ("Bit of a ramble, but Bob has the apple.", None, CELL),
    ("Bit of a ramble, but give Bob the apple tomorrow.", None, CELL),
    ("Bit of a muddle, but give Bob the apple, no, Alice.", None, CELL),
)


def test_ramble_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    RAMBLE.refused_without((_rewrites53._ramble53,), monkeypatch)


# -- pronouns and ellipsis ---

# an opening 'That bottle over there,' (_over_there53)
OVER_THERE = PhrasingCases()
test_over_there = OVER_THERE.test(
    ("That bottle over there, Person A has her eye on it.", "bottle>A", T12),
    ("That apple over there, give it to Bob.", "apple>B", CELL),
    ("The apple over there, put it on the shelf.", "apple@shelf", CELL),
    ("That lemon over there, Marco wants it.", "lemon>A", KITCHEN),
    ("That magazine over there, give it to Mr Lee.", "magazine>B", WARD),
    ("That mug over there, Bob wants it.", None, CELL),
    ("That apple over there, Bob had it.", None, CELL),
    ("That apple over there, Bob's got it.", None, CELL),
    ("That apple over there is Bob's.", None, CELL),
)


def test_over_there_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OVER_THERE.refused_without((_rewrites53._over_there53,), monkeypatch)


# "That bottle's cluttering up the floor," said "That bottle's in the way," (_clutter53)
CLUTTER = PhrasingCases()
test_clutter = CLUTTER.test(
    (
        "That bottle's cluttering up the floor, could you lift it onto the shelf?",
        "bottle@shelf",
        FIG1,
    ),
    ("That apple's cluttering up the floor, could you put it on the shelf?", "apple@shelf", CELL),
    ("That apple's cluttering up the hallway, could you give it to Bob?", "apple>B", CELL),
    ("That stapler's hogging the windowsill, could you put it in the box?", "stapler@box", OFFICE),
    ("That hammer's cluttering up the doorway, could you give it to Jess?", "hammer>B", WORKSHOP),
    # 12c: a surface of the scene named, where the request then puts it
    ("That apple's cluttering up the table, put it on the table.", None, CELL),
    ("That cup's hogging the table, put it on the table.", None, CELL),
    ("That apple's blocking the shelf, put it on the shelf.", None, CELL),
    ("That apple's cluttering up the shelf, put it on the table.", None, CELL),
    ("That apple's cluttering up the table, Bob has it.", None, CELL),
    ("That apple was cluttering up the table, could you put it on the shelf?", None, CELL),
    ("That apple's cluttering up the table, could you put it on the shelf tomorrow?", None, CELL),
    ("That apple's cluttering up the table, I've put it on the shelf.", None, CELL),
)


def test_clutter_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CLUTTER.refused_without((_rewrites53._clutter53,), monkeypatch)


# "as for P, the X's hers" said "the X's P's" (_as_for53)
AS_FOR = PhrasingCases()
test_as_for = AS_FOR.test(
    (
        "Person B has put in for the chips; as for Person A, the bottle's hers.",
        "chips>B & bottle>A",
        T21,
    ),
    ("Bob wants the apple; as for Alice, the cup's hers.", "apple>B & cup>A", CELL),
    ("Lena wants the salt; as for Marco, the lemon's his.", "salt>B & lemon>A", KITCHEN),
    ("Mr Lee wants the jug, as for Mrs Khan, the magazine's hers.", "jug>B & magazine>C", WARD),
    ("Bob wants the apple; as for Alice, the cup's his.", None, CELL),
    ("Bob wanted the apple; as for Alice, the cup's hers.", None, CELL),
    ("Bob has the apple; as for Alice, the cup's hers.", None, CELL),
    ("Give Bob the apple; as for Alice, the cup's hers?", None, CELL),
)


def test_as_for_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    AS_FOR.refused_without((_rewrites53._as_for53,), monkeypatch)


# -- wants and needs ---

# "P has dibs on X" / "P has her eye on it" anywhere (_dibs53)
DIBS = PhrasingCases()
test_dibs = DIBS.test(
    ("chips are for person b and person a has dibs on the bottle", "chips>B & bottle>A", T21),
    ("The apple, Bob has his eye on it.", "apple>B", CELL),
    ("The apple, Carol has her eye on it.", "apple>C", CELL),
    ("the crisps are for alice and bob has dibs on the apple", "chips>A & apple>B", CELL),
    ("the teddy is for lily and grandad has dibs on the bib", "teddy>A & bib>B", NURSERY),
    ("the crisps are for alice and bob had dibs on the apple", None, CELL),
    ("The apple, Alice has his eye on it.", None, CELL),
    ("Bob has his eye on the apple, he's got it now.", None, CELL),
    ("Bob has dibs on the apple, but Alice wants it.", None, CELL),
    ("Sam's got dibs on the stapler at the desk.", None, OFFICE),
)


def test_dibs_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DIBS.refused_without((_rewrites53._dibs53,), monkeypatch)


# "P's throat is like sandpaper" said "P's thirsty" (_throat53)
THROAT = PhrasingCases()
test_throat = THROAT.test(
    (
        "Person A's throat is like sandpaper after the crossing warden shift, so give her the "
        "bottle.",
        "bottle>A",
        ONE,
    ),
    (
        "Mrs Khan's throat is like sandpaper after her walk, so give her the water jug.",
        "jug>C",
        WARD,
    ),
    ("Bob's mouth is as dry as a bone after football, so the cup for him.", "cup>B", CELL),
    (
        "Lily's mouth is as dry as dust after her nap, so give her the sippy cup.",
        "beaker>A",
        NURSERY,
    ),
    ("Bob's throat is like sandpaper after football, he had the cup.", None, CELL),
    ("Bob's throat is like sandpaper after football.", None, CELL),
    ("Bob's throat is like sandpaper after football, so give him the cup tomorrow.", None, CELL),
)


def test_throat_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THROAT.refused_without((_rewrites53._throat53,), monkeypatch)


# an opening 'If you ask me,' (_ask_me53)
ASK_ME = PhrasingCases()
test_ask_me = ASK_ME.test(
    (
        "If you ask me, the thing Person A has been angling for all along is that bottle.",
        "bottle>A",
        F41,
    ),
    ("If you ask me, give Bob the apple.", "apple>B", CELL),
    ("Between you and me, Alice wants the crisps.", "chips>A", CELL),
    ("If you ask me, Marco needs the lemon.", "lemon>A", KITCHEN),
    ("In my opinion, the stapler should go in the box.", "stapler@box", OFFICE),
    ("If you ask me, Bob had the apple.", None, CELL),
    ("If you ask me, Bob doesn't want the apple.", None, CELL),
    ("Between you and me, Alice is sick of the crisps.", None, CELL),
)


def test_ask_me_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ASK_ME.refused_without((_rewrites53._ask_me53,), monkeypatch)


# "the thing P has been angling for is X" said "P wants X" (_cleft53)
CLEFT = PhrasingCases()
test_cleft = CLEFT.test(
    ("The thing Bob has been angling for all along is the apple.", "apple>B", CELL),
    ("The thing Marco has been itching for all morning is the knife.", "knife>A", KITCHEN),
    ("The one thing Zoe has been hoping for is the glue stick.", "glue>C", CLASSROOM),
    ("The thing Person A has been angling for all along is that bottle.", "bottle>A", F41),
    ("The thing Bob was angling for all along is the apple.", None, CELL),
    ("The thing Bob had been angling for is the apple.", None, CELL),
    ("The thing Bob has been angling for all along is the apple, he's got it now.", None, CELL),
    ("The thing Bob has been angling for all along is the apple?", None, CELL),
)


def test_cleft_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CLEFT.refused_without((_rewrites53._cleft53,), monkeypatch)


# -- questions ---

# "swing by P with the X" said "take the X to P" (_swing_by53)
SWING_BY = PhrasingCases()
test_swing_by = SWING_BY.test(
    (
        "Any chance you could drop the apple off with Person A and swing by Person B with the cup?",
        "apple>A & cup>B",
        F41,
    ),
    ("Could you swing by Bob with the apple?", "apple>B", CELL),
    ("Nip round to Alice with the crisps, would you?", "chips>A", CELL),
    ("Nip across to Mrs Khan with the jug.", "jug>C", WARD),
    ("Pop over to Marco with the knife.", "knife>A", KITCHEN),
    ("Swing by Bob with the apple tomorrow.", None, CELL),
    ("Did you swing by Bob with the apple?", None, CELL),
    ("I'll swing by Bob with the apple.", None, CELL),
    ("Swing by Bob with the apple, he's got it.", None, CELL),
    ("Swing by the shelf with the apple.", None, CELL),
    ("Bob will swing by Alice with the apple.", None, CELL),
)


def test_swing_by_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SWING_BY.refused_without((_rewrites53._swing_by53,), monkeypatch)


# -- batch 2 ---

# "while you're about it" said "while you're at it" (_about_it53)
ABOUT_IT = PhrasingCases()
test_about_it = ABOUT_IT.test(
    (
        "The apple, grab it and pass it along to Carol, and while you're about it, the red mug "
        "for her as well.",
        "apple>C & mug_red>C",
        CELL,
    ),
    (
        "Give Bob the apple, and while you're about it, the crisps for Alice.",
        "apple>B & chips>A",
        CELL,
    ),
    (
        "Give Marco the lemon, and while you're about it, the salt for Lena.",
        "lemon>A & salt>B",
        KITCHEN,
    ),
    (
        "Take Mr Lee the jug, and while you're about it, the magazine for Mrs Khan.",
        "jug>B & magazine>C",
        WARD,
    ),
    ("Give Bob the apple, and while you're about it, Alice had the crisps.", None, CELL),
    ("Give Bob the apple, and while you're about it, the crisps for Alice tomorrow.", None, CELL),
    ("While you're about it, what's Bob doing?", None, CELL),
)


def test_about_it_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ABOUT_IT.refused_without((_rewrites53._about_it53,), monkeypatch)


# an opening 'Between the two of them' before "it's simple:" (_between53)
BETWEEN = PhrasingCases()
test_between = BETWEEN.test(
    (
        "Between the two of them it's simple: the cup is what Person A is after, Person B the "
        "apple.",
        "cup>A & apple>B",
        L44,
    ),
    (
        "Between the two of them it's simple: Alice wants the crisps, Bob the apple.",
        "chips>A & apple>B",
        CELL,
    ),
    (
        "Between the two of them it's easy: the crisps for Alice and the apple for Bob.",
        "chips>A & apple>B",
        CELL,
    ),
    (
        "Between the pair of them it's simple: Marco wants the lemon, Lena the salt.",
        "lemon>A & salt>B",
        KITCHEN,
    ),
    ("Between the two of them it's simple: Alice had the crisps, Bob the apple.", None, CELL),
    ("Between the two of them it's simple: Alice wanted the crisps, Bob the apple.", None, CELL),
    ("Between the two of them it's simple: they can share the crisps.", None, CELL),
)


def test_between_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    BETWEEN.refused_without((_rewrites53._between53,), monkeypatch)


# a closing 'since her shift (as a crossing warden) ended' after a want (_since_ended53)
SINCE_ENDED = PhrasingCases()
test_since_ended = SINCE_ENDED.test(
    (
        "Person A has been craving the chips since her shift as a crossing warden ended.",
        "chips>A",
        DUO,
    ),
    (
        "Mr Lee has been craving the magazine since his visit from the vicar ended.",
        "magazine>B",
        WARD,
    ),
    (
        "Grandad has been craving the wipes since his walk round the big park finished.",
        "wipes>B",
        NURSERY,
    ),
    ("Bob's been craving the apple since his walk round the big park finished.", "apple>B", CELL),
    ("Bob's been craving the apple since his match ended, he's got it now.", None, CELL),
    ("Marco has been dying for the lemon since his stint as head chef finished.", None, KITCHEN),
    ("Bob had the apple since his walk round the big park finished.", None, CELL),
)


def test_since_ended_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SINCE_ENDED.refused_without((_rewrites53._since_ended53,), monkeypatch)


# a closing "P wants them there" after a placing (_wants_there53)
WANTS_THERE = PhrasingCases()
test_wants_there = WANTS_THERE.test(
    ("pop the tongs down on the worktop please lena wants them there", "tongs@counter", KITCHEN),
    ("put the apple on the shelf please bob wants it there", "apple@shelf", CELL),
    ("Put the apple on the shelf, Bob wants it there.", "apple@shelf", CELL),
    ("put the bib on the high chair please grandad wants it there", "bib@highchair", NURSERY),
    ("put the apple on the shelf please bob wanted it there", None, CELL),
    ("give bob the apple please alice wants it there", None, CELL),
    ("put the apple on the shelf please dave wants it there", None, CELL),
    ("put the apple on the shelf tomorrow please bob wants it there", None, CELL),
    ("Put the apple on the shelf, Bob wants it over there.", None, CELL),
)


def test_wants_there_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WANTS_THERE.refused_without((_rewrites53._wants_there53,), monkeypatch)


# "P's got a stack of X to clip together," said "P's busy," (_stack_of53)
STACK_OF = PhrasingCases()
test_stack_of = STACK_OF.test(
    (
        "Priya's got a stack of rota packs to clip together, would you be able to bring her the "
        "stapler?",
        "stapler>A",
        OFFICE,
    ),
    ("Bob's got a pile of homework to get through, could you give him the apple?", "apple>B", CELL),
    (
        "Jess has got a load of shelves to put up, could you pass her the drill?",
        "drill>B",
        WORKSHOP,
    ),
    (
        "Bob's got a pile of homework to get through, could you give Alice the apple?",
        "apple>A",
        CELL,
    ),
    ("Bob's got a pile of homework to get through, he had the apple.", None, CELL),
    ("Lena's got a mountain of plates to wash up, could you pass her the salt?", None, KITCHEN),
    (
        "Bob's got a pile of homework to get through, could you give him the apple tomorrow?",
        None,
        CELL,
    ),
    ("Bob had a pile of homework to get through, could you give him the apple?", None, CELL),
)


def test_stack_of_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    STACK_OF.refused_without((_rewrites53._stack_of53,), monkeypatch)


# "P's packing her lunch box and would be grateful for X" (_doing_and53)
DOING_AND = PhrasingCases()
test_doing_and = DOING_AND.test(
    (
        "Person A's packing her own lunch box this morning and would be grateful for the cup and "
        "the apple.",
        "cup>A & apple>A",
        SQ,
    ),
    ("Bob's packing his bag this morning and would be grateful for the apple.", "apple>B", CELL),
    ("Tom's loading the van this morning and would be grateful for the gloves.", "gloves>B", DEPOT),
    ("Alice's packing her bag this morning and would be grateful for the crisps.", "chips>A", CELL),
    ("Bob's doing his homework and would have liked the apple.", None, CELL),
    ("Bob's eating the apple and wanted the crisps.", None, CELL),
    ("Bob's doing his homework and needs the apple tomorrow.", None, CELL),
    ("Bob's doing his homework and would like the apple, he has it.", None, CELL),
)


def test_doing_and_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DOING_AND.refused_without((_rewrites53._doing_and53,), monkeypatch)


# "…, she's after her teddy" said "…, she wants her teddy" (_pron_after53)
PRON_AFTER = PhrasingCases()
test_pron_after = PRON_AFTER.test(
    (
        "Lily's grizzling and reaching out her little arms, she's after her teddy.",
        "teddy>A",
        NURSERY,
    ),
    ("Alice is hungry, she's after her apple.", "apple>A", CELL),
    ("Bob's grumpy, he's after his crisps.", "chips>B", CELL),
    ("Lena's tired, she's after her knife.", "knife>B", KITCHEN),
    ("Alice is hungry, he's after his apple.", None, CELL),
    ("Alice is hungry, she was after her apple.", None, CELL),
    ("Alice and Carol are hungry, she's after her apple.", None, CELL),
    ("Alice is hungry, she's after her apple, she's had it.", None, CELL),
)


def test_pron_after_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PRON_AFTER.refused_without((_rewrites53._pron_after53,), monkeypatch)


# -- refused with its readings ---

# 'Did P ask for X or Y? I can't remember.' (_forgot_which53): both readings named
FORGOT_WHICH = [
    (
        "Did Zoe ask for the glue stick or the red book? I can't remember.",
        CLASSROOM,
        ("glue", "book_red"),
    ),
    ("Did Bob ask for the apple or the cup? I can't remember.", CELL, ("apple", "cup")),
    ("Was it the apple or the cup Bob wanted? I forget.", CELL, ("apple", "cup")),
    ("Did Marco ask for the lemon or the salt? No idea.", KITCHEN, ("lemon", "salt")),
    ("Did Mrs Khan want the jug or the magazine? I can't recall.", WARD, ("jug", "magazine")),
]


@pytest.mark.parametrize(("text", "scene", "readings"), FORGOT_WHICH)
def test_forgot_which_names_both(text: str, scene: Scene, readings: tuple[str, str]) -> None:
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, scene)
    assert all(f"({r})" in str(refused.value) for r in readings)


@pytest.mark.parametrize(("text", "scene", "readings"), FORGOT_WHICH)
def test_forgot_which_is_this_rule(text: str, scene: Scene, readings: tuple[str, str]) -> None:
    # the rule alone names both (without it the question was refused naming neither)
    with pytest.raises(GroundingError) as refused:
        _rewrites53._forgot_which53(text, Lexicon.of(scene))
    assert all(f"({r})" in str(refused.value) for r in readings)


@pytest.mark.parametrize(
    "text",
    [
        "Did Bob ask for the apple or the cup?",
        "Did Bob ask for the apple or a mug? I can't remember.",
        "Did you give Bob the apple or the cup? I can't remember.",
    ],
)
def test_forgot_which_near(text: str) -> None:
    # still refused, and not by this rule
    assert_refused(text, CELL)
    _rewrites53._forgot_which53(text, Lexicon.of(CELL))


# a closing 'so does he want the apple?' (_does_he53): a question that only asks (read on main)
DOES_HE = [
    ("Bob's hungry, so does he want the apple?", CELL),
    ("Bob, does he want the apple?", CELL),
    ("Bob's hungry, does he want the apple?", CELL),
    ("Marco's busy, so does he need the knife?", KITCHEN),
    ("Mr Lee is poorly, so does he want the jug?", WARD),
]


@pytest.mark.parametrize(("text", "scene"), DOES_HE)
def test_does_he_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)
    with pytest.raises(GroundingError):
        _rewrites53._does_he53(text, Lexicon.of(scene))


@pytest.mark.parametrize(
    ("text", "want"),
    [("Could you give Bob the apple?", "apple>B"), ("Bob wants the apple, would you?", "apple>B")],
)
def test_does_he_near_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)
