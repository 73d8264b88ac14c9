"""Session-45 phrasings of issue 12 (engineer 12s): run-ons, texts with no marks in lower case,
and remarks of what the person does with the thing (blind43's kinds, said in other words, scenes
and people), and two wrong readings of main refused; docs/grounding.md, "Session 45 (engineer
12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites45s as r45s
from hltl.grounding import _rewrites51s as r51s
from hltl.world.scene import load_scene
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
    PhrasingCases,
)

SQUARE = load_scene(ROOT / "examples/scenes/4-4-square.yaml")  # Person A, Person B
F42 = load_scene(ROOT / "examples/scenes/4-2.yaml")  # Person A, Person B

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

# -- run-ons: a pronoun's clause after a request, no marks ------------------------------------

RUN_ON = PhrasingCases()
test_run_on = RUN_ON.test(
    ("the salt to mr novak he reckons the chips are bland", "salt>C", KITCHEN),
    ("the bowl goes in the sink its got glaze all over", "bowl@sink", LAB),
    ("stapler to sam he needs it for the filing", "stapler>B", OFFICE),
    ("the jug to mrs khan she says its too warm in here", "jug>C", WARD),
    ("give alice the apple and bob the chips they both asked for them", "apple>A & chips>B", CELL),
)
test_run_on_refused = RUN_ON.test(
    # the pronoun is someone else; the clause corrects, negates or names a thing
    ("give bob the crisps shes been on her feet all day", None, CELL),
    ("give alice the apple he says its his", None, CELL),
    ("give bob the cup hes actually after the bottle", None, CELL),
    ("give bob the cup he doesnt want the bottle", None, CELL),
    ("give bob the cup they both want it", None, CELL),
)


def test_run_on_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 51 (12s): its run-on rule says these with their stops too
    RUN_ON.refused_without((r45s._run_on45s, r45s._they_want45s, r51s._run_on51s), monkeypatch)


# -- 'they both want them' closing a request to two people -------------------------------------

THEY_WANT = PhrasingCases()
test_they_want = THEY_WANT.test(
    (
        "Give Bob the cup and Alice the apple, they both want them for the picnic.",
        "cup>B & apple>A",
        CELL,
    ),
    (
        "Noah gets the ruler and Zoe the glue, they've both asked for them.",
        "ruler>B & glue>C",
        CLASSROOM,
    ),
    (
        "Tom gets the tape Mia gets the scanner they both need them for the night shift",
        "tape>B & scanner>A",
        DEPOT,
    ),
)
test_they_want_refused = THEY_WANT.test(
    # one person; a negation after it
    ("Give Bob the cup, they both want them.", None, CELL),
    ("Give Bob the cup and Alice the apple, they both want them but not now.", None, CELL),
)


def test_they_want_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THEY_WANT.refused_without((r45s._they_want45s,), monkeypatch)


# -- 'who's …' after a person, no comma --------------------------------------------------------

WHO = PhrasingCases()
test_who_remark = WHO.test(
    ("Give the gloves to Mia who's been on the forklift all morning.", "gloves>A", DEPOT),
    ("Pass the magazine to Mr Lee who's bored stiff.", "magazine>B", WARD),
    ("Crisps over to Bob who's just back from the allotment.", "chips>B", CELL),
    ("Hand the blue mug to Carol who has been up since five.", "mug_blue>C", CELL),
)
test_who_remark_refused = WHO.test(
    # the clause names a thing; it negates
    ("Give the tape to Tom who's got the gloves.", None, DEPOT),
    ("Give the tape to Tom who isn't in yet.", None, DEPOT),
)


def test_who_remark_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 51 (12s): its 'who' run-on rule says these with their commas too
    WHO.refused_without((r45s._who_remark45s, r51s._who_run_on51s), monkeypatch)


# -- lower case: an opening 'after …' with no comma; a closing courtesy with no comma -----------

OPENING = PhrasingCases()
test_after_opening = OPENING.test(
    ("after two hours of netball zoe could use the ruler", "ruler>C", CLASSROOM),
    ("after an afternoon of sketching noah is gasping for the glue", "glue>B", CLASSROOM),
)
test_after_opening_refused = OPENING.test(
    # an order after the time (puts the task off); the 'after' part names someone
    ("after lunch give bob the cup", None, CELL),
    ("after bob has the cup alice wants the apple", None, CELL),
)


def test_after_opening_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OPENING.refused_without((r45s._after_opening45s,), monkeypatch)


CLOSER = PhrasingCases()
test_closer = CLOSER.test(
    ("person b could do with the chips after his kayaking thx", "chips>B", SQUARE),
    ("mr lee could use the magazine after his physio ta", "magazine>B", WARD),
    ("carol could use the blue mug after her spinning class thx", "mug_blue>C", CELL),
)
test_closer_refused = CLOSER.test(
    # 'after' a person of the scene
    ("bob needs the crisps after alice thx", None, CELL),
)


def test_closer_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CLOSER.refused_without((r45s._closer45s,), monkeypatch)


# -- a state of one person, then 'so' with no comma ---------------------------------------------

STATE_SO = PhrasingCases()
test_state_so = STATE_SO.test(
    ("avas cold so the bib to her", "bib>C", NURSERY),
    ("Grandad's shattered after the fete so the bib to him", "bib>B", NURSERY),
    ("lenas busy so the tongs to her", "tongs>B", KITCHEN),
)
test_state_so_refused = STATE_SO.test(
    # the pronoun is someone else; a negation
    ("marcos busy so the tongs to her", None, KITCHEN),
    ("avas cold so the bib to him", None, NURSERY),
    ("lilys not thirsty so sippy cup to her", None, NURSERY),
)


def test_state_so_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    STATE_SO.refused_without((r45s._state_so45s,), monkeypatch)


# -- a reason naming a thing as the first word of another, then 'so the X's his' ---------------

SO_HIS = PhrasingCases()
test_so_his = SO_HIS.test(
    (
        "Omar's making banana bread so the banana's his, and Emma wants the spoon.",
        "banana>B & spoon>C",
        LAB,
    ),
    (
        "Lena's making lemon curd, so the lemon's hers, and the knife goes to Marco.",
        "lemon>B & knife>A",
        KITCHEN,
    ),
    (
        "Person A's baking an apple pie so the apple's hers, and Person B wants the chips.",
        "apple>A & chips>B",
        SQUARE,
    ),
)
test_so_his_refused = SO_HIS.test(
    # the pronoun is not Omar; the reason names the lemon itself
    ("Omar's making banana bread so the banana's hers.", None, LAB),
    ("Marco's peeling the lemon so the lemon's his, and Lena wants the knife.", None, KITCHEN),
)


def test_so_his_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SO_HIS.refused_without((r45s._so_his45s,), monkeypatch)


# -- what the person does with the thing: 'for P to take home', 'he takes them to judo' ---------

TAKE_TO = PhrasingCases()
test_take_to = TAKE_TO.test(
    ("The chips are for Person B to take home.", "chips>B", F42),
    ("Give Person B the chips, he takes them to judo.", "chips>B", F42),
    ("The magazine is for Mr Lee to take to the day room.", "magazine>B", WARD),
    ("pass bob the crisps he takes them to the allotment", "chips>B", CELL),
)
test_take_to_refused = TAKE_TO.test(
    # to a person or a surface of the scene; a pronoun of the other sex
    ("The apple is for Person B to take to Person A.", None, F42),
    ("Give Person B the chips, she takes them to judo.", None, F42),
    ("The tape is for Tom to take to the pallet.", None, DEPOT),
)


def test_take_to_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    TAKE_TO.refused_without((r45s._take_to45s,), monkeypatch)


# -- who left the thing where it lies, closing a request -----------------------------------------

LEFT_IT = PhrasingCases()
test_left_it = LEFT_IT.test(
    ("Put the tape on the pallet, Tom left it by the door.", "tape@pallet", DEPOT),
    ("Give Mia the scanner, someone left it lying about.", "scanner>A", DEPOT),
    ("Put the gloves on the pallet, the driver left them by the gate.", "gloves@pallet", DEPOT),
)
test_left_it_refused = LEFT_IT.test(
    # 'it' of two things; the place a surface of the scene
    ("Give Mia the tape and the gloves, someone left it on the floor.", None, DEPOT),
    ("Put the tape on the pallet, Tom left it on the belt.", None, DEPOT),
)


def test_left_it_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LEFT_IT.refused_without((r45s._left_it45s,), monkeypatch)


# -- where one person is, then 'and he's shouting for …' ------------------------------------------

AND_PRON = PhrasingCases()
test_and_pronoun = AND_PRON.test(
    ("marcos at the pass tonight and hes yelling for the salt", "salt>A", KITCHEN),
    ("lenas on the tables tonight and shes asking for the salt", "salt>B", KITCHEN),
    ("avas in the garden tonight and shes crying out for the teddy", "teddy>C", NURSERY),
)
test_and_pronoun_refused = AND_PRON.test(
    # the pronoun is someone else; two people before it
    ("marcos on the grill tonight and shes shouting for the tongs", None, KITCHEN),
    ("Marco's on the grill with Lena and he's shouting for the tongs", None, KITCHEN),
)


def test_and_pronoun_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    AND_PRON.refused_without((r45s._and_pron45s,), monkeypatch)


# -- a gapped clause, then 'and the X go to P too' of its own person ------------------------------

GO_TOO = PhrasingCases()
test_go_too = GO_TOO.test(
    (
        "Zoe's getting the glue and Noah the ruler and the scissors go to Noah as well.",
        "glue>C & ruler>B & scissors>B",
        CLASSROOM,
    ),
    (
        "Tom gets the tape and Mia the scanner and the gloves go to Mia too.",
        "tape>B & scanner>A & gloves>A",
        DEPOT,
    ),
    (
        "Alice is having the cup and Bob the apple and the crisps go to Bob as well.",
        "cup>A & apple>B & chips>B",
        CELL,
    ),
)
test_go_too_refused = GO_TOO.test(
    # another person after 'to': the ruler may go with the scissors
    ("Give Zoe the glue and Noah the ruler and the scissors go to Zoe too.", None, CLASSROOM),
    (
        "Person A's having the cup and Person B the apple and the chips go to Person A too.",
        None,
        SQUARE,
    ),
)


def test_go_too_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GO_TOO.refused_without((r45s._go_too45s,), monkeypatch)
