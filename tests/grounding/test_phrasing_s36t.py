"""Session-36 phrasings of issue 12 (engineer 12t): blind23, causes10, blind13, blind17 and
causes15's refusals by kind; docs/grounding.md, "Session 36 (engineer 12t)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.grounding import normalise, phrasing
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    PhrasingCases,
)

# the two-arm scene, as session 33 (12t) has it (Alice, Bob; bottle, chips)
from tests.grounding.test_phrasing_s33t import TWO

CASES = PhrasingCases()  # read by the _STEPS36T rewrites
SEX = PhrasingCases()  # read by normalise._named_by_sex36t
ONE_OF = PhrasingCases()  # read by phrasing._one_of36t


# -- a deadline 'before the next <event>': met by doing the task now ---------------------------


test_next_event = CASES.test(
    ("Drop the scnner on the belt before the next load comes down.", "scanner@conveyor", DEPOT),
    ("Give Tom the tape before the next shift starts", "tape>B", DEPOT),
    # 'next' of a task or an object; a scene object; a later time; another task after it; a
    # scene object said again as what the event does
    ("Drop the scanner on the belt before the next one.", None, DEPOT),
    ("Drop the scanner on the belt before the next bit.", None, DEPOT),
    ("Drop the scanner on the belt before the next box comes down.", None, DEPOT),
    ("Drop the scanner on the belt before the next load arrives tomorrow.", None, DEPOT),
    ("Drop the scanner on the belt before the next week.", None, DEPOT),
    ("Drop the scanner on the belt before the next load comes down, then the tape.", None, DEPOT),
    ("Drop the scanner on the belt before the next lorry gets the tape.", None, DEPOT),
)


# -- 'P and Q are (both) in (now)': they have come in -----------------------------------------


test_people_in = CASES.test(
    ("Marco and Lena are both in now, pass Lena the lemon", "lemon>B", KITCHEN),
    ("Marco and Lena are both in, pass Lena the lemon", "lemon>B", KITCHEN),
    # an object among them; 'in' with a place of the scene after it
    ("Marco and the lemon are both in now, pass Lena the lemon", None, KITCHEN),
    ("Marco and Lena are both in the lemon", None, KITCHEN),
)


# -- a condition of courtesy straight before a polite question ---------------------------------


test_no_trouble = CASES.test(
    (
        "Sorry, I'm so sorry to bother you, but if it's not too much trouble could the apple "
        "maybe go to Carol? Sorry. Thank you.",
        "apple>C",
        CELL,
    ),
    ("if it's not too much trouble could the apple maybe go to Carol?", "apple>C", CELL),
    # a choice, a negation, a 'maybe not' left in the question
    ("if it's not too much trouble could the apple maybe go to Carol or Bob?", None, CELL),
    ("if it's not too much trouble could the apple not go to Carol?", None, CELL),
    ("if it's not too much trouble could the apple go to Carol, or maybe not?", None, CELL),
)


# -- '<word> habit' after an apology: 'force of habit' ----------------------------------------


test_habit = CASES.test(
    ("Behind! Sorry, chef habit. Tongs to Lena please, thank you!", "tongs>B", KITCHEN),
    # a word not in the list (an object, a person by name, another role); a request before the
    # apology; no full stop
    ("Behind! Sorry, salt habit. Tongs to Lena please", None, KITCHEN),
    ("Behind! Sorry, Lena habit. Tongs to Marco please", None, KITCHEN),
    ("Behind! Sorry, waitress habit. Tongs to Marco please", None, KITCHEN),
    ("Tongs to Marco. Sorry, chef habit. Tongs to Lena please", None, KITCHEN),
    ("Behind! Sorry, chef habit, tongs to Lena please", None, KITCHEN),
)


# 'old habit' reads as before (not this rule's)
test_old_habit = PhrasingCases().test(
    ("Behind! Sorry, old habit. Tongs to Lena please", "tongs>B", KITCHEN),
)


# -- 'the kids' of a scene whose people share a role for children -----------------------------


test_kids = CASES.test(
    (
        "Each of the kids gets a book",
        "(book_red>B & book_green>C) | (book_green>B & book_red>C)",
        CLASSROOM,
    ),
    (
        "Give the children a book each",
        "(book_red>B & book_green>C) | (book_green>B & book_red>C)",
        CLASSROOM,
    ),
    # one globe for two; a scene with no role shared by children (the nursery)
    ("Give the kids the globe", None, CLASSROOM),
    ("Each of the kids gets a block", None, NURSERY),
)


# -- 'human <noun>': an adjective, not a person ------------------------------------------------


test_human_noun = CASES.test(
    (
        "Ava is building a tower like the acrobats' human pyramid; the two blocks to her.",
        "block_red>C & block_green>C",
        NURSERY,
    ),
    # 'a human being' (a person); 'the human' of three
    ("Ava is a human being; the two blocks to her.", None, NURSERY),
    ("Give the human the teddy", None, NURSERY),
)


# -- 'P, then Q: X for him, Y for her' ---------------------------------------------------------


test_then_header = CASES.test(
    ("Bob, then Alice: chips for him, bottle for her", "chips>B ; bottle>A", TWO),
    # the pronouns in the other order; one pronoun twice; a person as the second thing; two
    # women; a name the list gives no sex (Sam)
    ("Bob, then Alice: chips for her, bottle for him", None, TWO),
    ("Bob, then Alice: chips for him, bottle for him", None, TWO),
    ("Bob, then Alice: chips for him, Bob for her", None, TWO),
    ("Ruth, then Mrs Khan: the jug for her, the magazine for her", None, WARD),
    ("Priya, then Sam: the stapler for her, the red pen for him", None, OFFICE),
)

# titles alone read it as before (not this rule's)
test_then_header_by_titles = PhrasingCases().test(
    ("Mr Lee, then Mrs Khan: the jug for him, the magazine for her", "jug>B ; magazine>C", WARD),
)


# -- '<P> said he wanted the X': P's want; 'but he can wait' of the last want ------------------


test_said_wanted = CASES.test(
    (
        "so the doctor wants her spoon and the visitor wants the white cup and omar said he "
        "wanted the bowl but he can wait so do that last",
        "(spoon>A & cup_white>C) ; bowl>B",
        LAB,
    ),
    ("Omar said he wanted the bowl", "bowl>B", LAB),
    # a pronoun of the other sex; a name the list gives no sex; 'it' or a person wanted
    ("Omar said she wanted the bowl", None, LAB),
    ("Emma said he wanted the bowl", None, LAB),
    ("Dana wants the spoon and Omar said he wanted it", None, LAB),
    ("Dana wants the spoon and Omar said he wanted Emma", None, LAB),
)

# session 15's `_can_wait` took the first 'and … wants' as the one who can wait: "… the visitor
# wants the white cup and Omar wants the bowl but he can wait …" had read `spoon>A ;
# (cup_white>C & bowl>B)` (a wrong reading); the want of the one who waits names no other person
test_can_wait_is_the_last_want = PhrasingCases().test(
    (
        "the doctor wants her spoon and the visitor wants the white cup and Omar wants the bowl "
        "but he can wait so do that last",
        "(spoon>A & cup_white>C) ; bowl>B",
        LAB,
    ),
    (
        "the doctor wants her spoon and Omar wants the bowl but he can wait so do that last",
        "spoon>A ; bowl>B",
        LAB,
    ),
)


# -- a remark of several people, then a request whose one person is he / him / she / her -------


test_named_by_sex = SEX.test(
    ("Ruth and Mr Lee are both here now, pass him the magazine", "magazine>B", WARD),
    ("Ruth and Mr Lee are both here now, pass her the magazine", "magazine>A", WARD),
    ("Mr Lee and Ruth are both here now, pass her the magazine", "magazine>A", WARD),
    ("Marco and Lena are both in now, pass her the lemon", "lemon>B", KITCHEN),
    ("Mr Novak and Lena are both in now, pass her the lemon", "lemon>B", KITCHEN),
    ("Alice and Bob are both here now, pass him the crisps", "chips>B", TWO),
    # both may be it (two men; a name the list does not give a sex; two women); a 'her' before a
    # noun; a pronoun in the remark itself; two sentences
    ("Marco and Mr Novak are both in now, pass him the lemon", None, KITCHEN),
    # session 46 (lead's decision): 'Lena' is a woman's name, so 'him' is Marco
    ("Marco and Lena are both in now, pass him the lemon", "lemon>A", KITCHEN),
    ("Ruth and Mrs Khan are both here now, pass her the magazine", None, WARD),
    ("Ruth and Mr Lee are both here now, pass her cup to him", None, WARD),
    ("Alice and Bob are here and she's thirsty, pass him the crisps", None, TWO),
    ("Marco and Lena are all in now. Pass her the lemon.", None, KITCHEN),
)


# -- 'one of the <kind>' … 'the other N': the one choice, then the rest of that kind ----------


test_one_of_then_other = ONE_OF.test(
    (
        "Give Sam one of the pens and put the other two in the box",
        "(pen_black>B & pen_blue@box & pen_red@box) | (pen_blue>B & pen_black@box & pen_red@box)"
        " | (pen_red>B & pen_black@box & pen_blue@box)",
        OFFICE,
    ),
    (
        "Give Tom one of the boxes and put the other two on the pallet",
        "(box_small>B & box_medium@pallet & box_large@pallet) | (box_medium>B & box_small@pallet"
        " & box_large@pallet) | (box_large>B & box_small@pallet & box_medium@pallet)",
        DEPOT,
    ),
    (
        "One of the pens for Sam and the other two for Priya",
        "(pen_black>B & pen_blue>A & pen_red>A) | (pen_blue>B & pen_black>A & pen_red>A)"
        " | (pen_red>B & pen_black>A & pen_blue>A)",
        OFFICE,
    ),
    # a count the scene does not hold; 'any of' (no one choice); another choice; 'them' (no
    # kind said); the rest said first
    ("Give Sam one of the pens and put the other three in the box", None, OFFICE),
    ("Give Sam any of the pens and put the other two in the box", None, OFFICE),
    ("Give Sam one of the pens or the stapler and put the other two in the box", None, OFFICE),
    ("Give Sam one of them and put the other two in the box", None, OFFICE),
    ("Put the other two in the box and give Sam one of the pens", None, OFFICE),
)


def test_refused_without_these_steps(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence the session-36 (12t) rewrites read is refused with them taken out."""
    CASES.refused_without(normalise._STEPS36T, monkeypatch)


def test_refused_without_named_by_sex(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence `_named_by_sex36t` reads is refused without it (as it was before)."""
    SEX.refused_with(normalise, "_named_by_sex36t", lambda *_: None, monkeypatch)


def test_refused_without_one_of(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every 'one of the …' sentence `_one_of36t` reads is refused without it ('One pen for Sam
    and the other two …', session 32's form, is not its)."""
    ONE_OF.refused_with(phrasing, "_one_of36t", lambda *_: False, monkeypatch)
