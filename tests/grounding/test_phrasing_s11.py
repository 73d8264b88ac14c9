"""Session-11 phrasings of issue 12, each as a family checked against an oracle built from the
words the family is made of, and none of them turning a refusal into a wrong reading."""

from __future__ import annotations

from dataclasses import dataclass

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import CELL, ROOT, assert_refused, tree
from tests.grounding.helpers import assert_reads as assert_means

NURSERY = load_scene(ROOT / "tests/grounding/paraphrase/scenes/nursery.yaml")

# -- 'it' / 'that' / 'they' in a condition that waits at a place ('once it's there') ------------
#
# The oracle: what a condition finds at a place is what a step before it took there; the clause
# a trailing condition holds back ('A and B once it's there': B) does not wait for itself; 'there'
# is the one surface named before it; no such step, or two for 'it', is refused.


@dataclass(frozen=True)
class Step:
    words: str  # the clause as said
    objects: tuple[str, ...]  # ids
    target: str  # id
    surface: bool


Names = list[tuple[str, str]]
SCENES: dict[str, tuple[Scene, Names, Names, Names]] = {
    "nursery": (
        NURSERY,
        [("bib", "bib"), ("beaker", "beaker"), ("teddy", "teddy"), ("wipes", "wipes")],
        [("Lily", "A"), ("Grandad", "B"), ("Ava", "C")],
        [("high chair", "highchair"), ("play mat", "mat")],
    ),
    "cell": (
        CELL,
        [("cup", "cup"), ("apple", "apple"), ("chips", "chips"), ("bottle", "bottle")],
        [("Alice", "A"), ("Bob", "B"), ("Carol", "C")],
        [("shelf", "shelf"), ("table", "table")],
    ),
}
PLACE = ["put the {o} on the {s}", "the {o} should go on the {s}", "place the {o} on the {s}"]
GIVE = ["give {p} the {o}", "the {o} should go to {p}", "hand the {o} to {p}"]
WHEN = ["once", "when", "after", "as soon as"]
ONE = ["it's", "it is", "that's", "it has been put"]
MANY = ["they're", "they are", "they have been put"]
TRAILING = [" and ", ", and ", " then ", " and then "]


def _step(data: st.DataObject, scene: str, objects: list[tuple[str, str]], n: int) -> Step:
    _, _, people, surfaces = SCENES[scene]
    things = objects[:n]
    said = " and the ".join(w for w, _ in things)
    if data.draw(st.booleans(), label="on a surface"):
        words, where = data.draw(st.sampled_from(surfaces), label="surface")
        form = data.draw(st.sampled_from(PLACE), label="place form")
        return Step(form.format(o=said, s=words), tuple(i for _, i in things), where, True)
    person, who = data.draw(st.sampled_from(people), label="person")
    form = data.draw(st.sampled_from(GIVE), label="give form")
    return Step(form.format(o=said, p=person), tuple(i for _, i in things), who, False)


def _tasks(step: Step) -> str:
    mark = "@" if step.surface else ">"
    return " & ".join(f"{o}{mark}{step.target}" for o in step.objects)


@settings(max_examples=150, deadline=None)
@given(st.sampled_from(sorted(SCENES)), st.data())
def test_a_condition_at_a_place_waits_for_what_was_taken_there(
    where: str, data: st.DataObject
) -> None:
    scene, objects, _, surfaces = SCENES[where]
    order = data.draw(st.permutations(objects), label="objects")
    size = data.draw(st.sampled_from([1, 1, 2]), label="objects in the first step")
    first = _step(data, where, list(order[:size]), size)
    second = _step(data, where, list(order[size:]), 1)
    plural = data.draw(st.booleans(), label="plural pronoun")
    pronoun = data.draw(st.sampled_from(MANY if plural else ONE), label="pronoun")
    when = data.draw(st.sampled_from(WHEN), label="when")
    trailing = data.draw(st.booleans(), label="trailing")
    named = [s.target for s in ((first, second) if trailing else (first,)) if s.surface]
    there = data.draw(st.booleans(), label="there")
    if there:
        place, at = "there", (named[0] if len(set(named)) == 1 else None)
    else:
        words, at = data.draw(st.sampled_from(surfaces), label="condition surface")
        place = f"on the {words}"
    condition = f"{when} {pronoun} {place}"
    if trailing:
        join = data.draw(st.sampled_from(TRAILING), label="join")
        text = f"{first.words}{join}{second.words} {condition}"
    elif data.draw(st.booleans(), label="two sentences"):
        text = f"{first.words}. {condition[0].upper()}{condition[1:]}, {second.words}."
    else:
        text = f"{first.words}, and {condition}, {second.words}"
    # only the first step can be waited for (the second is held back by it, or comes after it)
    waited = first.surface and first.target == at
    if not waited or (not plural and len(first.objects) > 1):
        assert tree(text, scene) is None, f"{text!r} should be refused"
        return
    want = f"({_tasks(first)}) ; {_tasks(second)}"
    if plural and len(first.objects) == 1 and tree(text, scene) is None:
        return  # 'they' for one object: refusing it is fine too
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # blind9's wrong reading ('it' taken as the beaker, the nearer object)
        (
            "the bib should go on the high chair and the beaker should go to Lily once it's there",
            "bib@highchair ; beaker>A",
        ),
        (
            "Put the bib on the high chair. Give Lily the beaker once it's there.",
            "bib@highchair ; beaker>A",
        ),
        (
            "put the bib and the teddy on the high chair and give Lily the beaker once they're"
            " there",
            "(bib@highchair & teddy@highchair) ; beaker>A",
        ),
    ],
)
def test_what_is_there_is_what_was_put_there(text: str, want: str) -> None:
    assert_means(text, want, NURSERY)


@pytest.mark.parametrize(
    "text",
    [
        # the clause held back does not wait for itself
        "give Lily the beaker then put the bib on the high chair once it's there",
        "put the bib on the high chair once it's there",
        # nothing before goes there: a step of its own, or something someone else does?
        "give Lily the beaker once it's on the high chair",
        "put the bib on the play mat and give Lily the beaker once it's on the high chair",
        "give Lily the beaker once they're on the high chair",
        # two objects went there: which one is 'it'?
        "put the bib and the teddy on the high chair and give Lily the beaker once it's there",
        "put the bib on the high chair, then the teddy on the high chair, and give Ava the beaker"
        " once it's there",
    ],
)
def test_a_condition_at_a_place_with_no_one_step_before_is_refused(text: str) -> None:
    assert_refused(text, NURSERY)


# -- 'it' for an object chosen with 'a': the same object, not another one ----------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "put a block on the high chair and then give it to Lily",
            "(block_red@highchair ; block_red>A) | (block_green@highchair ; block_green>A)",
        ),
        (
            "put a block on the high chair, and once it's there give Lily the beaker",
            "(block_red@highchair | block_green@highchair) ; beaker>A",
        ),
        (
            "give Lily a block and give Ava the beaker once she has it",
            "(block_red>A | block_green>A) ; beaker>C",
        ),
    ],
)
def test_it_for_a_chosen_object_is_that_object(text: str, want: str) -> None:
    assert_means(text, want, NURSERY)


def test_a_block_each_still_means_different_blocks() -> None:
    assert_means(
        "give Lily and Ava a block each",
        "(block_red>A & block_green>C) | (block_green>A & block_red>C)",
        NURSERY,
    )


# -- blind9's causes, each as a family ----------------------------------------------------------

WARD = load_scene(ROOT / "tests/grounding/paraphrase/scenes/ward.yaml")
KITCHEN = load_scene(ROOT / "tests/grounding/paraphrase/scenes/kitchen.yaml")
OFFICE = load_scene(ROOT / "tests/grounding/paraphrase/scenes/office.yaml")
DEPOT = load_scene(ROOT / "tests/grounding/paraphrase/scenes/depot.yaml")
CLASSROOM = load_scene(ROOT / "tests/grounding/paraphrase/scenes/classroom.yaml")

# per scene: objects named alone (words, id), people (words, id), surfaces (words, id)
PLAIN: dict[str, tuple[Scene, Names, Names, Names]] = {
    "cell": SCENES["cell"],
    "ward": (
        WARD,
        [("thermometer", "thermometer"), ("magazine", "magazine"), ("water jug", "jug")],
        [("Ruth", "A"), ("Mr Lee", "B"), ("Mrs Khan", "C")],
        [("cart", "trolley"), ("bedside table", "bedside")],
    ),
    "kitchen": (
        KITCHEN,
        [("knife", "knife"), ("lemon", "lemon"), ("salt", "salt"), ("tongs", "tongs")],
        [("Marco", "A"), ("Lena", "B"), ("Mr Novak", "C")],
        [("counter", "counter"), ("rack", "rack")],
    ),
}
PARTICIPLES = ["given", "handed", "brought", "taken", "delivered"]


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(sorted(PLAIN)), st.data())
def test_an_obligation_in_the_passive_is_the_request(where: str, data: st.DataObject) -> None:
    scene, objects, people, surfaces = PLAIN[where]
    things = data.draw(st.lists(st.sampled_from(objects), min_size=1, max_size=2, unique=True))
    listed = " and the ".join(w for w, _ in things)
    be = data.draw(st.sampled_from(["is to be", "are to be", "should be", "must be"]))
    form = data.draw(st.integers(0, 2))
    if form == 0:  # a person given the objects
        person, who = data.draw(st.sampled_from(people))
        text, want = (
            f"{person} {be} given the {listed}",
            " & ".join(f"{i}>{who}" for _, i in things),
        )
    elif form == 1:  # the objects taken to a person
        person, who = data.draw(st.sampled_from(people))
        verb = data.draw(st.sampled_from(PARTICIPLES))
        text = f"The {listed} {be} {verb} to {person}"
        want = " & ".join(f"{i}>{who}" for _, i in things)
    else:  # the objects put on a surface
        place, at = data.draw(st.sampled_from(surfaces))
        verb = data.draw(st.sampled_from(["put", "placed"]))
        text = f"The {listed} {be} {verb} on the {place}"
        want = " & ".join(f"{i}@{at}" for _, i in things)
    assert_means(text, want, scene)
    # a person 'has been given' something: that is the state a condition waits for
    (first, a), (second, b) = data.draw(
        st.lists(st.sampled_from(objects), min_size=2, max_size=2, unique=True)
    )
    (p, x), (q, y) = data.draw(
        st.lists(st.sampled_from(people), min_size=2, max_size=2, unique=True)
    )
    assert_means(
        f"The {first} should be given to {p} after {q} has been given the {second}",
        f"{b}>{y} ; {a}>{x}",
        scene,
    )


LABELS = [
    "Tidy-up time",
    "Night shift note",
    "End of shift",
    "Handover",
    "Reminder",
    "Morning jobs",
]


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(sorted(PLAIN)),
    st.data(),
    st.sampled_from(LABELS),
    st.sampled_from([": ", " - "]),
)
def test_a_label_before_a_note_is_dropped(
    where: str, data: st.DataObject, label: str, sep: str
) -> None:
    scene, objects, people, _ = PLAIN[where]
    (thing, oid), (person, who) = (
        data.draw(st.sampled_from(objects)),
        data.draw(st.sampled_from(people)),
    )
    assert_means(f"{label}{sep}{person} needs the {thing}", f"{oid}>{who}", scene)
    # a label naming someone is not a label: it may say who gets what
    other = data.draw(st.sampled_from([p for p in people if p[1] != who]))
    got = tree(f"{other[0]}{sep}{person} needs the {thing}", scene)
    assert got is None or got != tree(f"{person} needs the {thing}", scene) or other[1] == who


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(sorted(PLAIN)), st.data())
def test_not_this_one_that_one(where: str, data: st.DataObject) -> None:
    scene, objects, people, _ = PLAIN[where]
    (no, _), (yes, oid) = data.draw(
        st.lists(st.sampled_from(objects), min_size=2, max_size=2, unique=True)
    )
    person, who = data.draw(st.sampled_from(people))
    assert_means(f"Not the {no}, the {yes}, for {person}", f"{oid}>{who}", scene)
    assert_means(f"Give {person} the {yes}. Not the {no}.", f"{oid}>{who}", scene)
    # the same object taken back is no request
    assert_refused(f"Give {person} the {yes}. Not the {yes}.", scene)


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(sorted(PLAIN)), st.data(), st.integers(1, 4))
def test_a_counted_summary_must_count_its_list(where: str, data: st.DataObject, said: int) -> None:
    scene, objects, people, _ = PLAIN[where]
    things = data.draw(st.lists(st.sampled_from(objects), min_size=1, max_size=3, unique=True))
    person, who = data.draw(st.sampled_from(people))
    number = ["one", "two", "three", "four"][said - 1]
    noun = "thing" if said == 1 else "things"
    listed = ", ".join(f"the {w}" for w, _ in things[:-1])
    listed = f"{listed} and the {things[-1][0]}" if listed else f"the {things[-1][0]}"
    text = f"{number.capitalize()} {noun} for {person}: {listed}"
    if said == len(things):
        assert_means(text, " & ".join(f"{i}>{who}" for _, i in things), scene)
    else:
        assert_refused(text, scene)


COLOURED: dict[str, tuple[Scene, str, dict[str, str], Names]] = {
    "cell": (CELL, "mug", {"red": "mug_red", "blue": "mug_blue"}, SCENES["cell"][2]),
    "office": (
        OFFICE,
        "pen",
        {"red": "pen_red", "blue": "pen_blue", "black": "pen_black"},
        [("Priya", "A"), ("Sam", "B")],
    ),
    "kitchen": (
        KITCHEN,
        "plate",
        {"white": "plate_white", "blue": "plate_blue"},
        PLAIN["kitchen"][2],
    ),
}
COLOURS = ["red", "blue", "black", "white", "green"]


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(sorted(COLOURED)), st.data(), st.sampled_from(COLOURS))
def test_a_question_answered_names_the_object(where: str, data: st.DataObject, colour: str) -> None:
    scene, kind, ids, people = COLOURED[where]
    person, who = data.draw(st.sampled_from(people))
    form = data.draw(
        st.sampled_from(
            [
                "Which {k}? The {c} one. It's for {p}.",
                "Which {k}? The {c} one, for {p}.",
                "Which {k}? The {c} one. Give it to {p}.",
                "You asked which {k}: the {c} one, and it's for {p}",
            ]
        )
    )
    text = form.format(k=kind, c=colour, p=person)
    if colour in ids:
        assert_means(text, f"{ids[colour]}>{who}", scene)
    else:
        assert_refused(text, scene)
    # the other colour said against it: 'not the X one, the Y one'
    other = data.draw(st.sampled_from(sorted(ids)))
    if other != colour and colour in ids:
        assert_means(
            f"Not the {other} {kind}, the {colour} one, for {person}", f"{ids[colour]}>{who}", scene
        )


def _on(scene: Scene, kind: str, surface: str) -> list[str]:
    """The oracle: objects of ``kind`` whose position lies in ``surface``'s footprint."""
    s = next(x for x in scene.surfaces if x.id == surface)
    return [
        o.id
        for o in scene.objects
        if o.category == kind
        and abs(o.position[0] - s.center[0]) <= s.size[0] / 2
        and abs(o.position[1] - s.center[1]) <= s.size[1] / 2
    ]


DESCRIBED: dict[str, tuple[Scene, list[str], Names, Names]] = {
    "depot": (
        DEPOT,
        ["box"],
        [("Mia", "A"), ("Tom", "B")],
        [("pallet", "pallet"), ("belt", "conveyor")],
    ),
    "office": (OFFICE, ["pen"], [("Priya", "A"), ("Sam", "B")], [("desk", "desk"), ("box", "box")]),
    "kitchen": (
        KITCHEN,
        ["plate"],
        PLAIN["kitchen"][2],
        [("rack", "rack"), ("counter", "counter")],
    ),
    "classroom": (
        CLASSROOM,
        ["book"],
        [("Noah", "B"), ("Zoe", "C")],
        [("shelf", "shelf"), ("desk", "desk")],
    ),
}


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(sorted(DESCRIBED)), st.data())
def test_the_object_on_a_surface_as_the_subject(where: str, data: st.DataObject) -> None:
    scene, kinds, people, surfaces = DESCRIBED[where]
    kind = data.draw(st.sampled_from(kinds))
    (place, at), (person, who) = (
        data.draw(st.sampled_from(surfaces)),
        data.draw(st.sampled_from(people)),
    )
    form = data.draw(
        st.sampled_from(
            [
                "The {k} on the {s} goes to {p}",
                "The {k} that's on the {s} is for {p}",
                "The {k} on the {s} should go to {p}",
                "The {k} on the {s}, that one's for {p}",
            ]
        )
    )
    text = form.format(k=kind, s=place, p=person)
    there = _on(scene, kind, at)
    if len(there) == 1:
        assert_means(text, f"{there[0]}>{who}", scene)
    else:
        assert_refused(text, scene)


ORDER_WORDS = [("First", 0), ("In between,", 1), ("Last,", 2)]


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(sorted(PLAIN)), st.data())
def test_three_steps_each_with_its_place_in_the_order(where: str, data: st.DataObject) -> None:
    scene, objects, people, _ = PLAIN[where]
    things = data.draw(st.lists(st.sampled_from(objects), min_size=3, max_size=3, unique=True))
    whom = data.draw(st.lists(st.sampled_from(people), min_size=3, max_size=3))
    said = data.draw(st.permutations(range(3)))
    steps = [f"the {t[0]} to {p[0]}" for t, p in zip(things, whom, strict=True)]
    text = " ".join(f"{ORDER_WORDS[r][0]} {steps[r]}." for r in said)
    want = " ; ".join(f"{t[1]}>{p[1]}" for t, p in zip(things, whom, strict=True))
    assert_means(text, want, scene)
    # a place said twice is no order
    twice = " ".join(f"{ORDER_WORDS[min(r, 1)][0]} {steps[r]}." for r in said)
    assert_refused(twice, scene)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(sorted(PLAIN)), st.data(), st.sampled_from(["", " Go.", " Thanks."]))
def test_whose_is_what_is_who_gets_it(where: str, data: st.DataObject, end: str) -> None:
    scene, objects, people, _ = PLAIN[where]
    things = data.draw(st.lists(st.sampled_from(objects), min_size=2, max_size=3, unique=True))
    whom = data.draw(st.lists(st.sampled_from(people), min_size=len(things), max_size=len(things)))
    text = ", ".join(f"{p[0]}'s {t[0]}" for t, p in zip(things, whom, strict=True)) + "." + end
    want = " & ".join(f"{t[1]}>{p[1]}" for t, p in zip(things, whom, strict=True))
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # a title says who 'her' is; without one the one person named is
        ("Mrs Khan is cold, give her the grey blanket", "blanket_grey>C", WARD),
        ("Mr Lee and Mrs Khan are here: give her the magazine", "magazine>C", WARD),
        # (session 34: 'her' said of Bob, a man's first name, is someone else — refused, in
        # test_phrasing_s34s; a name the sex list lacks still lends its person)
        ("Sam is hungry, give her the red pen", "pen_red>B", OFFICE),
        # the last word of a name of two words ('teddy bear'), when nothing else has it
        ("Give Ava the bear", "teddy>C", NURSERY),
        ("Put the bib on the chair", "bib@highchair", NURSERY),
        ("Give Bob the crisps, like, right now", "chips>B", CELL),
        (
            "Kofi ought to get the hammer as soon as possible",
            "hammer>A",
            load_scene(ROOT / "tests/grounding/paraphrase/scenes/workshop.yaml"),
        ),
    ],
)
def test_people_and_words(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Mr Lee is cold, give her the grey blanket", WARD),
        ("Mrs Khan is cold, give him the grey blanket", WARD),
        ("The jug, which Mr Lee has been asking about, should go to her.", WARD),
        ("Mr Lee's jug should go to her", WARD),
        ("Give Lily the chair", NURSERY),  # a surface
        ("Mr Khan needs the jug", WARD),  # no surname alone for a title of the other sex
    ],
)
def test_people_and_words_that_do_not_fit_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- what the filler fuzz found on main (session 11) ---------------------------------------------


@pytest.mark.parametrize(
    "end", ["", ", thanks", ", cheers", ", if that's ok", ", thank you so much", ", please"]
)
def test_politeness_after_a_condition_keeps_the_order(end: str) -> None:
    scene = load_scene(ROOT / "examples/scenes/4-4-line.yaml")
    text = f"Get the cup over to Person B, and once B has it, the apple to Person A{end}"
    assert_means(text, "cup>B ; apple>A", scene)


@pytest.mark.parametrize(
    "text",
    [
        # the condition would swallow the requests after it (order lost): refused
        "Give Bob the cup, and once Bob has it, Alice the apple, Carol the chips",
        "Give Bob the cup, and once Bob has it, the apple to Alice, the chips to Carol",
    ],
)
def test_a_condition_that_cannot_be_split_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="unclear where")


@pytest.mark.parametrize(
    "text",
    [
        "Cancel this: give Bob the cup",  # a label that takes something back is no label
        "give Bob the chips and the apple with Carol",  # 'with Carol' after 'give Bob'
    ],
)
def test_near_forms_of_labels_and_with_are_refused(text: str) -> None:
    assert_refused(text, CELL)


@pytest.mark.parametrize(
    "text",
    [
        # each was read wrongly on main before this change (an exclusion or an order lost, a
        # remark's want dropped while the request gave its object to someone else)
        "Give Carol everything except the mugs. Not the chips.",  # the chips are in everything
        "the cup and the bottle on the shelf, not the cup",
        "Give Bob the cup and the apple, not the cup",
        "Bob first, please: give Alice the cup and Bob the chips",  # an order, not a remark
        "Alice first: the cup to her and the chips to Bob",
        "Bob wants the bottle earlier, so give it to Carol first and then give Bob the chips",
        # 'then' / 'next' after 'last' is said relative to the sentence before, not 'in between'
        "Last, the apple to Alice. Then the chips to Bob. First the cup to Carol.",
        "Finally, the apple to Alice. Next, the chips to Bob. First, the cup to Carol.",
    ],
)
def test_exclusions_orders_and_wants_that_would_be_lost_are_refused(text: str) -> None:
    assert_refused(text, CELL)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("be nice and give Bob the chips", "chips>B"),  # 'be nice' said first asks nothing
        ("Be careful: put the cup on the shelf", "cup@shelf"),
        ("Give Bob the chips. Be gentle and give Alice the cup.", "chips>B & cup>A"),
        ("give Bob the chips and be quick, then give Alice the cup", "chips>B ; cup>A"),
        ("Alice is new, be nice, give her the cup", "cup>A"),
        (
            "Last, the apple to Alice. In between, the chips to Bob. First the cup to Carol.",
            "cup>C ; chips>B ; apple>A",
        ),
    ],
)
def test_manners_and_ranks_still_read(text: str, want: str) -> None:
    assert_means(text, want, CELL)
