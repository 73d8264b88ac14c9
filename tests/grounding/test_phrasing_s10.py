"""Session-10 phrasings of issue 12: blind8's misses met by cause, each as a family checked
against an oracle built from the scene, and none of them turning a refusal into a wrong reading."""

from __future__ import annotations

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    ROOT,
    assert_refused,
    assert_same_or_refused,
    fits,
    pronoun_for,
)
from tests.grounding.helpers import assert_reads as assert_means

WARD = load_scene(ROOT / "tests/grounding/paraphrase/scenes/ward.yaml")
DEPOT = load_scene(ROOT / "tests/grounding/paraphrase/scenes/depot.yaml")

# -- a want, a list of objects and a participle: the participle is the whole list's -------------

# per scene: (words, id) of objects, people and surfaces, each said one way the scene names it
Names = list[tuple[str, str]]
FAMILY: dict[str, tuple[Scene, Names, Names, Names]] = {
    "ward": (
        WARD,
        [
            ("thermometer", "thermometer"),
            ("tablets", "pills"),
            ("magazine", "magazine"),
            ("water jug", "jug"),
            ("grey blanket", "blanket_grey"),
        ],
        [("Ruth", "A"), ("Mr Lee", "B"), ("Mrs Khan", "C")],
        [("cart", "trolley"), ("bedside table", "bedside")],
    ),
    "cell": (
        CELL,
        [
            ("cup", "cup"),
            ("apple", "apple"),
            ("bottle", "bottle"),
            ("chips", "chips"),
            ("red mug", "mug_red"),
        ],
        [("Alice", "A"), ("Bob", "B"), ("Carol", "C")],
        [("shelf", "shelf"), ("table", "table")],
    ),
}
WANTS = ["wants", "needs", "would like", "'d like", "really needs"]
TO_PERSON = ["brought to", "given to", "handed to", "taken to", "delivered to", "passed to"]
ON_SURFACE = ["put on", "placed on", "set on", "left on", "moved onto"]
ENDS = ["", ".", " please", ", thanks", "!"]


def _listed(words: list[str], oxford: bool) -> str:
    the = [f"the {w}" for w in words]
    if len(the) == 2:
        return f"{the[0]} and {the[1]}"
    return ", ".join(the[:-1]) + ("," if oxford else "") + f" and {the[-1]}"


@settings(max_examples=80, deadline=None)
@given(
    st.sampled_from(sorted(FAMILY)),
    st.data(),
    st.sampled_from(WANTS),
    st.booleans(),
    st.sampled_from(ENDS),
    st.booleans(),
    st.booleans(),
)
def test_a_want_with_a_list_and_a_participle_moves_every_object(
    where: str, data: st.DataObject, want: str, to_person: bool, end: str, oxford: bool, q: bool
) -> None:
    scene, objects, people, surfaces = FAMILY[where]
    things = data.draw(st.lists(st.sampled_from(objects), min_size=2, max_size=3, unique=True))
    who = data.draw(st.sampled_from(people))
    if to_person:
        verb = data.draw(st.sampled_from(TO_PERSON))
        target = data.draw(st.sampled_from(people))
        expected = " & ".join(f"{i}>{target[1]}" for _, i in things)
    else:
        verb = data.draw(st.sampled_from(ON_SURFACE))
        target = data.draw(st.sampled_from(surfaces))
        expected = " & ".join(f"{i}@{target[1]}" for _, i in things)
    quant = (" both" if len(things) == 2 else " all") if q else ""
    listed = _listed([w for w, _ in things], oxford)
    text = f"{who[0]} {want} {listed}{quant} {verb} the {target[0]}{end}"
    # the oracle: each object goes where the participle says; the one who wants it gets none
    assert_same_or_refused(text, expected, scene)


def test_the_blind8_sentence_and_its_neighbours() -> None:
    assert_means(
        "Ruth wants the thermometer and the tablets put on the cart",
        "thermometer@trolley & pills@trolley",
        WARD,
    )
    assert_means(
        "Ruth wants the thermometer, the tablets and the magazine put on the cart",
        "thermometer@trolley & pills@trolley & magazine@trolley",
        WARD,
    )
    assert_means(
        "Ruth wants the thermometer and the tablets brought to Mr Lee",
        "thermometer>B & pills>B",
        WARD,
    )
    assert_means("Ruth wants the thermometer put on the cart", "thermometer@trolley", WARD)
    # a verb after 'and' is a clause of its own: Ruth gets the thermometer
    assert_means(
        "Ruth wants the thermometer and put the tablets on the cart",
        "thermometer>A & pills@trolley",
        WARD,
    )


def test_a_want_list_and_participle_it_cannot_place_is_refused() -> None:
    for text in (
        # a comma may end the want before the participle's object
        "Ruth wants the thermometer, and the tablets put on the cart",
        "Ruth wants the thermometer and the tablets, put on the cart",
        # no place, or more after it
        "Ruth wants the thermometer and the tablets brought",
        "Ruth wants the thermometer and the tablets put on the cart by the bed",
        # an order inside the list
        "Ruth wants the thermometer, then the tablets put on the cart",
    ):
        assert_refused(text, WARD, match="cannot tell which objects")


# -- the normaliser: each mechanism as a family, against an oracle from the scene --------------

PEOPLE = {"A": "Alice", "B": "Bob", "C": "Carol"}
THINGS = {
    "cup": "cup",
    "bottle": "bottle",
    "chips": "crisps",
    "apple": "apple",
    "mug_red": "red mug",
}
WRAPPERS = [
    "Is there any chance {p} could have the {o}?",
    "Is there any way {p} could get the {o}",
    "Would it be possible for {p} to have the {o}?",
    "Would it be possible for {p} to borrow the {o}?",
    "I was wondering if {p} could get the {o}",
    "We were wondering whether {p} could have the {o}.",
    "I would be most grateful if {p} could be given the {o}",
    "I'd be very grateful if {p} could be provided with the {o}.",
    "Please make sure that {p} gets the {o}",
    "Kindly ensure that {p} receives the {o}.",
    "{p} would be grateful for the {o}",
    "{p} asked if she could have the {o}",
    "Could someone give {p} the {o}?",
]


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(WRAPPERS), st.sampled_from(sorted(PEOPLE)), st.sampled_from(sorted(THINGS)))
def test_a_wrapped_request_means_the_request(form: str, who: str, obj: str) -> None:
    # the oracle: every wrapper asks for one hand-over, the object to the person (session 34:
    # 'she' said of a man's first name is someone else, so the pronoun fits the name)
    text = form.format(p=PEOPLE[who], o=THINGS[obj])
    text = text.replace(" she ", f" {pronoun_for(PEOPLE[who], 'she')} ")
    assert_means(text, f"{obj}>{who}")


ASIDES = ["who is at the front", "who has been waiting", "who's new here", "who came in late"]
APPOSITIONS = ["the lady by the window", "our new colleague", "the one at the end"]


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(sorted(PEOPLE)),
    st.sampled_from(sorted(THINGS)),
    st.sampled_from([*ASIDES, *APPOSITIONS]),
    st.sampled_from(
        ["{p}, {a}, wants the {o}", "Give {p}, {a}, the {o}", "{p}, {a}, needs the {o}"]
    ),
)
def test_an_aside_naming_nothing_is_dropped(who: str, obj: str, aside: str, form: str) -> None:
    assert_means(form.format(p=PEOPLE[who], a=aside, o=THINGS[obj]), f"{obj}>{who}")


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(sorted(PEOPLE)),
    st.sampled_from(sorted(THINGS)),
    st.sampled_from(sorted(THINGS)),
    st.sampled_from(["who has the {x}", "who broke the {x}", "which is next to the {x}"]),
)
def test_an_aside_naming_an_object_is_not_dropped_blindly(
    who: str, obj: str, other: str, aside: str
) -> None:
    # an aside that names an object may pick someone out by it: read exactly or refused
    text = f"Give {PEOPLE[who]}, {aside.format(x=THINGS[other])}, the {THINGS[obj]}"
    assert_same_or_refused(text, f"{obj}>{who}")


REMARKS = ["is about to leave", "has been waiting ages", "is hungry", "is in a hurry"]


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(sorted(PEOPLE)),
    st.sampled_from(sorted(THINGS)),
    st.sampled_from(REMARKS),
    st.sampled_from(
        [", so give {r} the {o}", " - could you hand the {o} to {r}?", ". Give {r} the {o}"]
    ),
    st.sampled_from(["him", "her"]),
)
def test_a_remark_lends_its_person_to_the_request(
    who: str, obj: str, remark: str, form: str, pron: str
) -> None:
    # session 34: a pronoun of the other sex than the person's first name is someone else
    assume(fits(PEOPLE[who], pron))
    text = f"{PEOPLE[who]} {remark}" + form.format(r=pron, o=THINGS[obj])
    assert_means(text, f"{obj}>{who}")


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(sorted(PEOPLE)),
    st.sampled_from(sorted(THINGS)),
    st.sampled_from(sorted(THINGS)),
    st.sampled_from(["is upset about the {x}", "keeps dropping the {x}", "broke the {x} earlier"]),
)
def test_a_remark_naming_another_object_is_not_dropped(
    who: str, obj: str, other: str, remark: str
) -> None:
    text = f"{PEOPLE[who]} {remark.format(x=THINGS[other])}, so give her the {THINGS[obj]}"
    if obj == other:
        assert_same_or_refused(text, f"{obj}>{who}")
    else:
        assert_refused(text)  # the remark may ask for the other object: never dropped


TASKS10 = [
    ("give Alice the cup", "cup>A"),
    ("hand Bob the crisps", "chips>B"),
    ("put the apple on the shelf", "apple@shelf"),
    ("the red mug goes to Carol", "mug_red>C"),
]


@settings(max_examples=40, deadline=None)
@given(
    st.permutations(TASKS10).map(lambda p: p[:2]),
    st.sampled_from(["Last", "Lastly", "Last of all", "Finally"]),
    st.sampled_from(["Before that", "First, though", "But first"]),
)
def test_order_said_apart_is_kept(two: list[tuple[str, str]], last: str, first: str) -> None:
    (late, late_want), (early, early_want) = two
    text = f"{last}, {late}. {first}, {early}."
    assert_means(text, f"{early_want} ; {late_want}")


@settings(max_examples=40, deadline=None)
@given(
    st.permutations([("red", "mug_red"), ("blue", "mug_blue")]),
    st.permutations(sorted(PEOPLE)).map(lambda p: p[:2]),
    st.sampled_from(["{a} one to {p}", "{a} to {p}", "the {a} one to {p}"]),
)
def test_a_note_with_a_header_names_each_object(
    mugs: list[tuple[str, str]], people: list[str], form: str
) -> None:
    parts = [form.format(a=a, p=PEOPLE[p]) for (a, _), p in zip(mugs, people, strict=True)]
    want = " & ".join(f"{m}>{p}" for (_, m), p in zip(mugs, people, strict=True))
    assert_means("Mugs: " + ", ".join(parts), want)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Ms Khan needs the jug", "jug>C"),
        ("Miss Khan needs the jug", "jug>C"),
        (
            "Give each patient a blanket",
            "(blanket_blue>B & blanket_grey>C) | (blanket_grey>B & blanket_blue>C)",
        ),
        ("Bed 2, Mr Lee: water jug please", "jug>B"),
        ("Mrs Khan she want magazine", "magazine>C"),
        ("Mr Lee, then Mrs Khan: the jug for him, the magazine for her", "jug>B ; magazine>C"),
        ("Mrs Khan and Mr Lee: the jug for him, the magazine for her", "jug>B & magazine>C"),
    ],
)
def test_people_said_other_ways(text: str, want: str) -> None:
    assert_means(text, want, WARD)


@pytest.mark.parametrize(
    "text",
    [
        "Mr Khan needs the jug",  # no such man: a title is not changed across sexes
        "Give each patient the magazine",  # one magazine for two
        "Mr Lee, then Mrs Khan: the jug for her, the magazine for him",  # order and titles clash
        "Mrs Khan, then Ruth: the jug for her, the magazine for her",
    ],
)
def test_people_said_other_ways_that_do_not_fit_are_refused(text: str) -> None:
    assert_refused(text, WARD)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # 'first' opening a later sentence orders it before what was said (was dropped: wrong)
        ("Lastly, give Alice the cup. First, though, hand Bob the crisps.", "chips>B ; cup>A"),
        ("Give Alice the cup. First, hand Bob the crisps.", "chips>B ; cup>A"),
        ("Give Bob the chips. Finally, give Alice the cup.", "chips>B ; cup>A"),
    ],
)
def test_first_and_finally_across_sentences(text: str, want: str) -> None:
    assert_means(text, want)


@pytest.mark.parametrize(
    "text",
    [
        "Lastly, give Alice the cup. Then hand Bob the crisps.",
        "Finally, give Alice the cup. Hand Bob the crisps.",
        "Finally give Alice the cup and first hand Bob the crisps",
        "Give Alice the cup. Then first hand Bob the crisps.",
    ],
)
def test_an_order_said_twice_is_refused(text: str) -> None:
    assert_refused(text)


def test_an_object_handed_over_and_then_placed_is_refused() -> None:
    # found by the run-on fuzz: the delivery leaves the object with the person for good
    assert_refused("Give Alice the cup, then put the cup on the shelf", match="gone")
    assert_means("Put the cup on the shelf, then give it to Alice", "cup@shelf ; cup>A")


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # a clause that asks without naming what is not a remark (found by the run-on fuzz)
        ("Put the crisps on the shelf and give Bob the bottle. Alice gets what's left.", "two"),
        # a word the grammar does not know in a remark may be a name: not dropped
        ("Mr Lee has to have the jug, it's important ms Khann needs the jug", "ward"),
        # 'each <role>' is rewritten only as the one request of the text
        ("Ruth needs the jug and the thermometer bring each patient one of the blankets", "ward"),
    ],
)
def test_normaliser_near_misses_stay_refused(text: str, scene: str) -> None:
    from tests.grounding.test_phrasing_s9 import TWO

    assert_refused(text, {"two": TWO, "ward": WARD}[scene])


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("I'd love it if Carol got the apple", "apple>C"),
        ("See that Carol gets the apple", "apple>C"),
        ("It's Carol who needs the apple", "apple>C"),
        ("Carol's the one who wants the apple", "apple>C"),
        ("What Carol needs is the apple", "apple>C"),
        ("Give Bob the chips. To finish, hand Carol the apple.", "chips>B ; apple>C"),
        ("For Bob: chips. For Carol: apple.", "chips>B & apple>C"),
        ("Bob's been after the chips all day", "chips>B"),
        ("Bob is needing the chips", "chips>B"),
        ("Bob is supposed to get the chips", "chips>B"),
        ("Give Bob the chips, thanks, he'll be pleased", "chips>B"),
    ],
)
def test_more_frames_around_a_request(text: str, want: str) -> None:
    assert_means(text, want)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Mister Lee needs the jug", "jug>B"),
        ("Lee needs the jug", "jug>B"),  # the one name of the scene with that word
        ("Sister Ruth wants the thermometer", "thermometer>A"),
    ],
)
def test_titles_and_surnames(text: str, want: str) -> None:
    assert_means(text, want, WARD)


@pytest.mark.parametrize(
    "text",
    [
        "Mrs Lee needs the jug",  # a title of the other sex
        "Missus Lee needs the jug",
        "What does Carol need?",
    ],
)
def test_titles_and_clefts_that_do_not_fit_are_refused(text: str) -> None:
    scene = CELL if "Carol" in text else WARD
    assert_refused(text, scene)
