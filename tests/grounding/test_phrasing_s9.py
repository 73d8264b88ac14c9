"""Session-9 phrasings of issue 12: blind7's misses met by cause (a task said again, people named
in a refusal, ...), each as a family, with properties checked against independent oracles and
that none of them turns a refusal into a wrong reading."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import CELL, ROOT, assert_refused, assert_same_or_refused, tree
from tests.grounding.helpers import assert_reads as assert_means

WARD = load_scene(ROOT / "tests/grounding/paraphrase/scenes/ward.yaml")

# -- a task said again: two hand-overs of one object cannot be done, so refused -----------------

TASKS = [
    ("give Alice the apple", "give her the apple", "apple>A"),
    ("put the cup on the shelf", "put it on the shelf", "cup@shelf"),
    ("hand Bob the chips", "hand him the chips", "chips>B"),
    ("give Carol the bottle", "give the bottle to Carol", "bottle>C"),
]
JOINS = [" and then ", ", then ", ". Then ", " and ", ", and after that "]


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(TASKS), st.sampled_from(JOINS))
def test_a_task_said_again_is_refused_not_read_once(task: tuple[str, str, str], join: str) -> None:
    first, second, want = task
    # the oracle: without 'again' a restated task is that task (one hand-over) ...
    assert_means(f"{first}{join}{second}", want)
    # ... with 'again' it asks for a second hand-over, which cannot be done: refused
    assert_refused(f"{first}{join}{second} again", match="a second time")


def test_again_alone_changes_nothing() -> None:
    assert_means("Give Alice the apple again", "apple>A")
    assert_means("Give Alice the apple and Bob the chips again", "apple>A & chips>B")
    assert_means("give Alice the apple, thanks again", "apple>A")


# -- an alias two people share: the refusal names the people -----------------------------------


@pytest.mark.parametrize(
    "text",
    ["Give the patient the magazine", "the patient needs the jug", "hand the patient a blanket"],
)
def test_a_shared_alias_names_the_people(text: str) -> None:
    assert_refused(
        text, WARD, match=r"Person B \(Mr Lee, patient\) or Person C \(Mrs Khan, patient\)"
    )


def test_a_shared_alias_among_others_is_still_refused() -> None:
    assert tree("Give Ruth the jug and the patient the magazine", WARD) is None
    assert_means("Give Mr Lee the magazine", "magazine>B", WARD)
    assert_means("Give Mrs Khan the magazine", "magazine>C", WARD)
    assert_means("Give Ruth the magazine and the jug", "magazine>A & jug>A", WARD)
    assert tree("give Alice the apple", CELL) is not None


OFFICE = load_scene(ROOT / "tests/grounding/paraphrase/scenes/office.yaml")
LAB = load_scene(ROOT / "tests/grounding/paraphrase/scenes/lab.yaml")
DEPOT = load_scene(ROOT / "tests/grounding/paraphrase/scenes/depot.yaml")
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")

# -- notes without verbs: each form means the note written out ---------------------------------

NOTES = [
    ("cup", "A", "Alice"),
    ("apple", "C", "Carol"),
    ("chips", "B", "Bob"),
    ("bottle", "A", "Alice"),
]


@settings(max_examples=40, deadline=None)
@given(st.permutations(NOTES).map(lambda p: p[:2]), st.sampled_from(["for", "to", "run-on"]))
def test_notes_without_verbs_mean_their_deliveries(
    notes: list[tuple[str, str, str]], form: str
) -> None:
    (o1, p1, n1), (o2, p2, n2) = notes
    if o1 == o2 or p1 == p2:
        return
    text = {
        "for": f"for {n1} the {o1}, for {n2} the {o2}",
        "to": f"the {o1} to {n1}, the {o2} to {n2}",
        "run-on": f"{o1} to {n1.lower()} {o2} to {n2.lower()}",
    }[form]
    # the oracle: the same notes with a verb
    assert_means(text, f"{o1}>{p1} & {o2}>{p2}")
    assert_means(f"give {n1} the {o1} and {n2} the {o2}", f"{o1}>{p1} & {o2}>{p2}")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Shelf: the cup and the apple", "cup@shelf & apple@shelf"),
        ("table - the chips", "chips@table"),
        ("Shelf: the cup. Table: the apple.", "cup@shelf & apple@table"),
        ("first the shelf: the cup, then the table: the apple", "cup@shelf ; apple@table"),
        (
            "Shelf first: the mugs go there. Then the chips to Bob.",
            "(mug_red@shelf & mug_blue@shelf) ; chips>B",
        ),
    ],
)
def test_a_surface_then_its_objects(text: str, want: str) -> None:
    assert_means(text, want)


@pytest.mark.parametrize(
    "text", ["Shelf: Alice", "Shelf: the cup to Bob", "shelf: give Bob the cup"]
)
def test_a_surface_note_with_more_than_objects_is_not_a_placement(text: str) -> None:
    assert tree(text) in (None, tree("give Bob the cup"))


# -- first, last and in between ------------------------------------------------------------------

STEPS = [
    ("the cup to Alice", "cup>A"),
    ("the chips to Bob", "chips>B"),
    ("the apple to Carol", "apple>C"),
]


@settings(max_examples=30, deadline=None)
@given(st.permutations(range(3)), st.permutations(["first", "last", "in between"]))
def test_first_last_and_in_between_order_three_steps(which: list[int], words: list[str]) -> None:
    parts = [f"{w} {STEPS[n][0]}" for w, n in zip(words, which, strict=True)]
    text = f"{parts[0]}, {parts[1]}, and {parts[2]}"
    rank = {"first": 0, "in between": 1, "last": 2}
    order = sorted(zip(words, which, strict=True), key=lambda p: rank[p[0]])
    assert_means(text, " ; ".join(STEPS[n][1] for _, n in order))


def test_one_of_the_objects_last_or_first() -> None:
    assert_means("Put the mugs on the shelf, the red one last", "mug_blue@shelf ; mug_red@shelf")
    assert_means("Put the mugs on the shelf, the red one first", "mug_red@shelf ; mug_blue@shelf")
    assert_means("Give Alice the mugs, the blue one last", "mug_red>A ; mug_blue>A")
    assert_refused("Give Alice the mugs, the blue one")  # all of them, or only that one?
    assert_means("Give Bob the chips. The apple goes on the table last.", "chips>B ; apple@table")
    assert_means(
        "Give Bob the chips, and the cup and the apple to Alice last", "chips>B ; (cup>A & apple>A)"
    )
    assert tree("Give Bob the chips and the apple to Alice last") is None  # whose list?
    assert tree("Hand Alice the cup, then give Bob the chips last, and Carol the apple") is None


def test_a_trailing_first_after_a_clause_with_its_own_place_moves_it() -> None:
    # session 9 found the 'first' dropped here (read as two placements in any order)
    assert_means(
        "put the small box on the belt, the large box on the pallet first",
        "box_large@pallet ; box_small@conveyor",
        DEPOT,
    )


# -- people: an alias before a name, a shared alias in the plural ------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Nurse Ruth the thermometer", "thermometer>A"),
        ("give the patient Mr Lee the jug", "jug>B"),
        (
            "The patients each want a blanket",
            "(blanket_blue>B & blanket_grey>C) | (blanket_grey>B & blanket_blue>C)",
        ),
    ],
)
def test_titles_and_shared_aliases(text: str, want: str) -> None:
    assert_means(text, want, WARD)


def test_a_role_that_is_someone_else_is_refused() -> None:
    assert tree("Give Visitor Omar the bowl", LAB) is None
    assert tree("give the patients the magazine", WARD) is None  # one magazine, two people


# -- descriptions: relative clauses, superlatives before the noun, shared nouns ---------------


@pytest.mark.parametrize("rel", ["", "that's ", "that is ", "which is "])
def test_a_relative_clause_on_a_surface_picks_the_object(rel: str) -> None:
    assert_means(f"Give the intern the pen {rel}on the desk", "pen_blue>B", OFFICE)
    assert_means(
        f"put the pen {rel}on the desk in the box", "pen_blue@box", OFFICE
    ) if rel else None
    assert tree(f"Give Sam the pen {rel}on the box", OFFICE) is None


@pytest.mark.parametrize(
    ("text", "plain"),
    [
        ("Hand Dana the closest cup to her", "Hand Dana the cup closest to her"),
        (
            "Emma should get whichever cup is nearest to her",
            "Emma should get the cup nearest to her",
        ),
        ("Give Omar the nearest thing to him", "Give Omar the thing nearest to him"),
    ],
)
def test_a_superlative_before_the_noun_means_it_after(text: str, plain: str) -> None:
    assert tree(plain, LAB) is not None
    assert tree(text, LAB) == tree(plain, LAB)


ADJECTIVES = ["black", "blue", "red"]


@settings(max_examples=30, deadline=None)
@given(
    st.lists(st.sampled_from(ADJECTIVES), min_size=2, max_size=3, unique=True),
    st.sampled_from(["or", "and"]),
)
def test_an_adjective_before_a_shared_noun(adjs: list[str], join: str) -> None:
    said = ", the ".join(adjs[:-1]) + f" {join} the {adjs[-1]} pen"
    full = ", the ".join(f"{a} pen" for a in adjs[:-1]) + f" {join} the {adjs[-1]} pen"
    # the oracle: the noun said after every adjective
    assert tree(f"Give Sam the {said}", OFFICE) == tree(f"Give Sam the {full}", OFFICE)
    assert tree(f"Give Sam the {full}", OFFICE) is not None
    assert tree(f"Give Sam the green {join} the {adjs[-1]} pen", OFFICE) is None


def test_a_want_with_a_place() -> None:
    assert_means("Ruth wants the blue blanket on the bedside table", "blanket_blue@bedside", WARD)
    # the blanket there, among two: which one she wants
    assert_means("Mrs Khan wants the blanket on the trolley", "blanket_grey>C", WARD)
    # the one object already there: given, or put there? refused
    assert tree("Tom wants the large box on the pallet", DEPOT) is None
    assert tree("Mrs Khan wants the blankets on the trolley", WARD) is None


# -- requests run together, remarks, formal and non-native English ------------------------------

PEOPLE = [("alice", "A"), ("bob", "B"), ("carol", "C")]
THINGS = ["cup", "apple", "chips", "bottle"]


@settings(max_examples=40, deadline=None)
@given(
    st.permutations(PEOPLE).map(lambda p: p[:2]),
    st.permutations(THINGS).map(lambda t: t[:2]),
    st.sampled_from(["needs", "wants", "gets"]),
)
def test_subject_run_ons_are_each_done(
    people: list[tuple[str, str]], things: list[str], verb: str
) -> None:
    (n1, p1), (n2, p2) = people
    text = f"{n1} {verb} the {things[0]} {n2} {verb} the {things[1]}"
    # the oracle: the same requests joined by 'and'
    want = f"{things[0]}>{p1} & {things[1]}>{p2}"
    assert_means(text, want)
    assert_means(text.replace(f" {n2} ", f" and {n2} "), want)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Carol keeps asking for a snack, could you get her the apple", "apple>C", CELL),
        ("Carol hasn't eaten all day, bring her the apple", "apple>C", CELL),
        ("Bob hasn't had lunch, give him the chips", "chips>B", CELL),
        ("Tom's loading the truck so he needs the gloves", "gloves>B", DEPOT),
        ("give the apple to carol she said she wants it", "apple>C", CELL),
        ("Carol gets the apple, Bob doesn't get anything", "apple>C", CELL),
        ("Alice gets the cup, Bob gets nothing, and Carol gets the apple", "cup>A & apple>C", CELL),
        (
            "Person A: chips or apple, I'm not fussy",
            "chips>A | apple>A",
            load_scene(ROOT / "examples/scenes/4-2.yaml"),
        ),
        ("Mrs Khan is due her tablets, please give them to her", "pills>C", WARD),
        ("Meds to Mr Lee first, then the jug to Mrs Khan", "pills>B ; jug>C", WARD),
    ],
)
def test_remarks_and_reasons(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        "Carol keeps asking for the cup, give her the apple",  # the remark may ask for the cup
        "Carol hasn't got the cup, bring her the apple",
        "give the apple to carol, she said bob wants it",
    ],
)
def test_a_remark_naming_an_object_or_someone_else_is_not_dropped(text: str) -> None:
    assert tree(text) is None


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Please you give to Bob the chips", "chips>B"),
        ("Bob want the chips, and Alice want the apple also", "chips>B & apple>A"),
        ("place the apple upon the shelf", "apple@shelf"),
        ("It would be appreciated if the apple were placed on the counter.", "apple@table"),
        ("Carol would like the cup to drink", "cup>C"),
        ("can bob have the crisps pleeease", "chips>B"),
        ("The cup and the bottle, both of them to Carol", "cup>C & bottle>C"),
        ("give person a the apple the chips and the cup", "apple>A & chips>A & cup>A"),
        (
            "put all the stuff on the counter apart from the mugs",
            "cup@table & bottle@table & chips@table & apple@table",
        ),
        ("Alice should receive the cup prior to Carol receiving the apple", "cup>A ; apple>C"),
    ],
)
def test_formal_and_non_native_english(text: str, want: str) -> None:
    assert_means(text, want)


@pytest.mark.parametrize(
    "text",
    [
        "give Alice the cup to Dave",  # a person the scene lacks, not a purpose
        "give Alice the cup to carl",
        "The cup, the apple and the bottle, both of them to Carol",  # 'both' of three
        "give Alice the apple the chips",  # no 'and': not a list
        "give Bob the stuff",
    ],
)
def test_near_forms_are_refused(text: str) -> None:
    assert tree(text) is None


@pytest.mark.parametrize("word", ["pleeease", "pleeeease", "thaaanks"])
def test_a_stretched_word_is_the_word(word: str) -> None:
    assert_means(f"give Bob the chips {word}", "chips>B")


def test_a_stretched_word_that_is_two_words_or_none_stays_unknown() -> None:
    assert tree("give Bob the zzzips") is None


# -- 'it' and conditions ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Carol would like the cup, and Alice the bottle once Carol has it", "cup>C ; bottle>A"),
        ("Bob needs it, the apple I mean", "apple>B"),
        ("Give Bob the chips and when he's taken them give Carol the apple", "chips>B ; apple>C"),
        ("Give Bob the chips, and once he has them hand Carol the apple", "chips>B ; apple>C"),
        ("Put the cup on the shelf, and once it's there give Bob the chips", "cup@shelf ; chips>B"),
    ],
)
def test_it_and_conditions(text: str, want: str) -> None:
    assert_means(text, want)


def test_a_condition_without_a_comma_needs_a_plain_command() -> None:
    # without a comma, only a command in its plain form ends the condition
    assert tree("Give Bob the chips, and once he has them Carol gets the apple") in (
        None,
        tree("Give Bob the chips, and once he has them, Carol gets the apple"),
    )


# -- counts after a choice, 'whoever' ------------------------------------------------------------


def test_the_other_two_after_one_choice_are_the_rest_of_its_kind() -> None:
    got = tree("One pen for Sam and the other two for Priya", OFFICE)
    assert got is not None
    pens = ["pen_black", "pen_blue", "pen_red"]
    # the oracle: every way to give Sam one pen and Priya the other two
    ways = ["(" + " & ".join([f"{p}>B", *(f"{q}>A" for q in pens if q != p)]) + ")" for p in pens]
    assert_means("One pen for Sam and the other two for Priya", " | ".join(ways), OFFICE)
    assert tree("Give Priya a pen and Sam the other three", OFFICE) is None


def test_whoever_after_people_is_either_of_them() -> None:
    assert_means(
        "Mr Lee or Mrs Khan can have the magazine, whoever", "magazine>B | magazine>C", WARD
    )
    assert tree("Whoever wants it, give Bob the apple") is None


# -- blind6's last three misses: descriptions per person, 'the other' after one, 'whichever one
# <person> doesn't get' -----------------------------------------------------------------------

L44 = load_scene(ROOT / "examples/scenes/4-4-line.yaml")


@pytest.mark.parametrize(
    "who", ["each person", "everyone", "every person", "Person A and Person B"]
)
def test_a_description_per_person(who: str) -> None:
    # the oracle: the description said for each person by name
    each = "Give Person A the thing closest to Person A and Person B the thing closest to Person B"
    assert tree(each, L44) is not None
    assert tree(f"Give {who} the thing closest to them", L44) == tree(each, L44)


def test_a_description_per_person_needs_a_clear_nearest_for_each() -> None:
    # Carol's nearest mug is clear, and so is Alice's; with 'the thing' Carol's is not
    assert_means("give Alice and Carol the mug nearest to them", "mug_blue>A & mug_red>C")
    assert tree("give everyone the thing nearest to them") is None


def test_the_other_one_after_a_description_by_name() -> None:
    t24s = load_scene(ROOT / "examples/scenes/2-4-square.yaml")
    assert_means(
        "Give Person B the thing nearest to Person B, and the other one to Person A",
        "bottle>B & chips>A",
        t24s,
    )


def test_whichever_one_someone_does_not_get() -> None:
    assert_means(
        "Give Bob whichever one Alice doesn't get, and give Alice the bottle",
        "chips>B & bottle>A",
        TWO,
    )
    # with more objects left, or no other part for Alice, or a choice: which one? refused
    assert tree("Give Bob whichever one Alice doesn't get, and give Alice the bottle") is None
    assert tree("Give Bob whichever one Alice doesn't get", TWO) is None
    assert (
        tree(
            "Give Bob whichever one Alice doesn't want, and give Alice the bottle or the chips", TWO
        )
        is None
    )


# -- found while probing (session 9): one wrong reading and general misses -----------------------


def test_any_restated_in_its_own_sentence_is_the_same_choice() -> None:
    # it was read as a second mug: both mugs to Carol (a wrong reading on main before session 9)
    assert_means("Carol needs a mug. Any mug.", "mug_red>C | mug_blue>C")
    assert_means("Give Carol a mug! Any of them.", "mug_red>C | mug_blue>C")
    assert tree("Give Carol a mug. Any mug to Bob.") is None


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Bob is starving so could you give him the chips", "chips>B"),
        ("Could Alice maybe get the red mug?", "mug_red>A"),
        (
            "Give one mug to Alice and one to Carol",
            "(mug_red>A & mug_blue>C) | (mug_blue>A & mug_red>C)",
        ),
        (
            "Give the mugs to Alice and Carol, one each",
            "(mug_red>A & mug_blue>C) | (mug_blue>A & mug_red>C)",
        ),
        (
            "Give Alice and Carol the mugs, one each",
            "(mug_red>A & mug_blue>C) | (mug_blue>A & mug_red>C)",
        ),
        (
            "Give the cup and the apple to Alice and Carol, one each",
            "(cup>A & apple>C) | (apple>A & cup>C)",
        ),
    ],
)
def test_what_probing_found(text: str, want: str) -> None:
    assert_means(text, want)


def test_a_description_before_a_recipient() -> None:
    assert_means("Give the pen on the desk to Sam", "pen_blue>B", OFFICE)
    assert_means("Bring the pen that's on the desk to Sam", "pen_blue>B", OFFICE)
    # with 'put' the place is where it goes; a recipient after it is refused
    assert tree("Put the pen on the desk to Sam", OFFICE) is None
    assert tree("Give the mugs to Alice, Bob and Carol, one each") is None  # two mugs, three people
    assert tree("give Alice the cup and could Bob maybe have the chips") is None


def test_a_condition_without_a_comma_after_a_request_is_refused() -> None:
    # 'once …' may condition the clause before it: only after 'and' or a comma is it its own
    assert tree("Give Bob the chips once Alice has the bottle put the cup on the shelf") is None
    assert_same_or_refused(
        "Give Bob the chips and once Alice has the bottle put the cup on the shelf",
        "chips>B & (bottle>A ; cup@shelf)",
    )


def test_i_mean_after_a_new_name_then_more_words_is_refused() -> None:
    # the run-on fuzz read this as the chips alone (Bob's task dropped)
    assert tree("Give Bob the cup, the apple I mean give Alice the chips") is None
    assert_means("Give Bob the cup, the apple I mean", "apple>B")
    assert_means("give Bob the cup I mean the apple", "apple>B")


def test_whatever_is_on_a_surface() -> None:
    assert_means("Give Sam whatever is on the desk", "pen_blue>B", OFFICE)
    assert_means("put whatever's on the desk in the box", "pen_blue@box", OFFICE)
    assert tree("Hand Carol whatever is on the table") is None  # nothing starts there


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("give alice the cup comma and bob the chips", "cup>A & chips>B"),
        ("give alice the cup full stop then bob the chips period", "cup>A ; chips>B"),
        ("cup -> Alice, chips -> Bob", "cup>A & chips>B"),
        ("Carol needs a mug, any colour", "mug_red>C | mug_blue>C"),
    ],
)
def test_dictated_punctuation_arrows_and_any_colour(text: str, want: str) -> None:
    assert_means(text, want)
