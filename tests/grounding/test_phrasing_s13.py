"""Session-13 phrasings of issue 12 (blind11's causes and the classes around them), each as a
family checked against an oracle built from the words the family is made of, and near forms
that must stay refused."""

from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import show_tree
from hltl.errors import GroundingError
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, title_sex
from hltl.grounding.offline import _SEXED, OfflineGrounder
from hltl.grounding.tree import tasks
from hltl.grounding.update import ground_update
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
    SCENES,
    WARD,
    WORKSHOP,
    assert_refused,
    fits,
    name_of,
    tree,
    unique_objects,
)
from tests.grounding.helpers import assert_reads as assert_means

F41 = load_scene(ROOT / "examples/scenes/4-1.yaml")


# -- words that cannot change who gets what ------------------------------------------------------
#
# The oracle: the plain request's own reading. Each wrapper is of a listed class (greetings,
# favours asked, courtesy, closings, the speaker about themselves, what it is for, when): it names
# nothing in the scene and holds no negation, count, choice or order of the request.

OPENERS = [
    "I'm only visiting, but ",
    "Hi, I'm new here. ",
    "Sorry, I'm just covering today, so ",
    "Be an angel and ",
    "Be a dear and ",
    "No rush at all, but ",
    "No hurry, but ",
    "If you wouldn't mind, ",
    "If you would not mind, ",
    "Hello there, yes, ",
    "I am only the babysitter, but ",
    "I'm filling in for the day shift, so if you'd be so good, ",
    "Morning! I'm from the agency. ",
    "We're just here for the tour, so ",
    "Apparently ",
    "FYI ",
    "Just so you know, ",
    "Heads up, ",
    "I'd say ",
    "If I'm not mistaken, ",
    "Be a star and ",
]
CLOSERS = [
    ". Lovely, thanks.",
    ", thank you ever so much",
    ". That would be brilliant!",
    ". Thanks a million.",
    ", thanks so so much",
    ". Perfect, cheers!",
    ", at some point",
    " before he heads off",
    " before the lesson starts",
    " for the party",
    ", ta very much",
    ", bless him",
    ", poor thing",
    ", would be great",
    ", if that's alright with you",
    ". Much obliged.",
    ", you know",
    " for later",
    ", over and out",
    ", when you're free",
]


def _plain_requests(scene: Scene) -> list[tuple[str, str]]:
    objs = unique_objects(scene)
    people = [h.id for h in scene.humans]
    out = []
    for n, oid in enumerate(objs):
        pid = people[n % len(people)]
        o, p = name_of(scene, oid), name_of(scene, pid)
        out.append((f"give {p} the {o}", f"{oid}>{pid}"))
        out.append((f"could {p} have the {o}", f"{oid}>{pid}"))
        if scene.surfaces:
            s = scene.surfaces[n % len(scene.surfaces)]
            out.append((f"put the {o} on the {s.id}", f"{oid}@{s.id}"))
    return out


REQUESTS = [(scene, text, want) for scene in SCENES for text, want in _plain_requests(scene)]


@settings(max_examples=120, deadline=None)
@given(
    st.sampled_from(REQUESTS),
    st.sampled_from(["", *OPENERS]),
    st.sampled_from(["", *CLOSERS]),
)
def test_courtesy_the_speaker_purpose_and_time_change_nothing(
    request: tuple[Scene, str, str], opener: str, closer: str
) -> None:
    scene, text, want = request
    said = f"{opener}{text}{closer}"
    sexes = {
        PRONOUN_SEX[w] for w in re.findall(r"[a-z]+", f"{opener} {closer}") if w in PRONOUN_SEX
    }
    if ">" in want and any(
        title_sex(want.split(">")[1], Lexicon.of(scene)) not in (None, sex) for sex in sexes
    ):
        # session 31 (the lead's decision, 12s): ', bless him' after a request for Mrs Ortiz is
        # about someone the instruction does not name (a title rules her out): refused with
        # the readings, not taken off
        assert_refused(said, scene)
        return
    said_sexes = {PRONOUN_SEX[w.lower()] for w in _SEXED.findall(f"{opener} {closer}")}
    if ">" in want and any(not fits_named(text, want, scene, sex) for sex in said_sexes):
        # session 34 (12s): likewise a first name of the other sex ('give Alice the cup before
        # he heads off': 'he' is not Alice, whom the name says is a woman): refused, readings
        assert_refused(said, scene, match="cannot mean")
        return
    assert_means(said, want, scene)


def fits_named(text: str, want: str, scene: Scene, sex: str) -> bool:
    """Whether a he / she of ``sex`` may be the person ``want`` gives to, as ``text`` names
    them (a first name of the other sex rules it out: session 34)."""
    human = next(h for h in scene.humans if h.id == want.split(">")[1])
    pronoun = "he" if sex == "m" else "she"
    return all(
        fits(name, pronoun)
        for name in (human.name, *human.aliases)
        if " " not in name and re.search(rf"\b{re.escape(name)}\b", text, re.I)
    )


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # the speaker as a recipient, or the speaker's clause naming an object or a task
        ("I'm covering for Ruth, give me the thermometer", WARD),
        ("I'm only here for the lemon", KITCHEN),
        ("I'm giving Jess the torch", WORKSHOP),
        ("I'm the driver, so I need the scanner", DEPOT),
        ("I'm here for the jug, so give Mr Lee the magazine", WARD),
        ("Bring us the jug", WARD),
        ("Put the bowl in the sink for me and hand me the spoon", LAB),
        # a speaker's clause naming a person, before a pronoun that could be them
        ("I'm covering for Ruth, so give her the thermometer", WARD),
        # closings only, or a closing naming something
        ("Lovely, thanks.", KITCHEN),
        ("Be an angel and give the bib to the angel", NURSERY),
        ("If you wouldn't mind, don't give Tom the tape", DEPOT),
        # 'for' a person or an object of the scene is not what it is for
        ("Give the magazine for Mrs Khan's jug", WARD),
        # a time clause naming a task orders it; one about the rest or 'that' is not dropped
        ("Marco needs the knife before he gets the knife", KITCHEN),
        ("Give Bob the chips and the cup before he gets the chips", CELL),
        # a delay is not met by doing it now
        ("Give Omar the spoon after he finishes his lunch", LAB),
        ("Give Mrs Khan the jug when she gets back", WARD),
        ("Give Bob the apple tomorrow", CELL),
    ],
)
def test_near_forms_of_words_that_change_nothing_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Bob the chips before he gets the apple", "chips>B ; apple>B", CELL),
        ("Give Bob the chips before Carol gets the apple", "chips>B ; apple>C", CELL),
        (
            "Give Bob the chips before the others",
            "chips>B ; (cup>B & bottle>B & apple>B & mug_red>B & mug_blue>B)",
            CELL,
        ),
        (
            "Lemon to Marco. Then, once he has it, the white plate to Lena.",
            "lemon>A ; plate_white>B",
            KITCHEN,
        ),
    ],
)
def test_time_clauses_that_order_tasks_stay(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


# -- a negated command beside a request ----------------------------------------------------------
#
# The oracle: the negated command is left out only when none of its tasks is one of the
# request's: then the request alone is what is asked. When it is one of them, the two contradict
# each other: refused.


def _negation_cases() -> list[tuple[Scene, str, str | None]]:
    out: list[tuple[Scene, str, str | None]] = []
    for scene in SCENES:
        objs = unique_objects(scene)
        people = [h.id for h in scene.humans]
        if len(objs) < 2:
            continue
        a, b = objs[0], objs[1]
        p, q = people[0], people[1]
        na, nb, np_, nq = name_of(scene, a), name_of(scene, b), name_of(scene, p), name_of(scene, q)
        out += [
            (scene, f"Give {np_} the {na}. Don't give {np_} the {nb}.", f"{a}>{p}"),
            (scene, f"Give {np_} the {na}, but do not give the {nb} to {nq}", f"{a}>{p}"),
            (scene, f"Give {np_} the {na}. Don't give {nq} the {na}.", f"{a}>{p}"),
            (scene, f"Give {np_} the {na}. Don't give {np_} the {na}.", None),
            (scene, f"Give {np_} the {na}. Never give {np_} the {na}.", None),
            (scene, f"Don't give {np_} the {na}.", None),
            (scene, f"Give {np_} a thing. Don't give {np_} the {na}.", None),
        ]
        if scene.surfaces:
            s = scene.surfaces[0].id
            out += [
                (scene, f"Don't put the {na} on the {s}, give it to {nq}", f"{a}>{q}"),
                (scene, f"Do not hand the {na} to {np_}; put it on the {s}", f"{a}@{s}"),
                (scene, f"Don't put the {na} on the {s}, put it on the {s}", None),
                (scene, f"Don't give the {na} to {np_}, give it to {np_}", None),
                (scene, f"Not on the {s}, the {na} goes to {np_}", f"{a}>{p}"),
            ]
        out += [
            (scene, f"Not to {nq}, the {na} goes to {np_}", f"{a}>{p}"),
            (scene, f"Not to {np_}, the {na} goes to {np_}", None),
        ]
    return out


@pytest.mark.parametrize(("scene", "text", "want"), _negation_cases())
def test_a_negated_command_beside_a_request(scene: Scene, text: str, want: str | None) -> None:
    if want is None:
        assert_refused(text, scene)
    else:
        assert_means(text, want, scene)


def test_a_negated_command_about_what_a_choice_or_plural_covers_is_refused() -> None:
    assert_refused("Give Bob a mug. Don't give him the red mug.")
    assert_refused("Give Bob the mugs. Don't give him the red mug.")
    assert_refused("Give Bob everything. Don't give him the apple.")
    assert_refused("Give Bob the chips, but don't give him anything else")
    # 'it' after the negated command is its object only when the request names none of its own
    assert_means("Don't put the cup on the shelf; take the apple and give it to Bob", "apple>B")


# -- ellipsis, each / any / both, counts ----------------------------------------------------------


def _told_apart(scene: Scene) -> list[tuple[str, str, str]]:
    """(adjective, object id, noun) of objects told apart by a first word ('red' of 'red pen')."""
    out = []
    for o in scene.objects:
        for alias in o.aliases:
            words = alias.split()
            if len(words) == 2 and sum(1 for x in scene.objects if x.category == o.category) > 1:
                out.append((words[0], o.id, o.category))
    return out


ELLIPSES = [
    (scene, a, b)
    for scene in SCENES
    for a in _told_apart(scene)
    for b in _told_apart(scene)
    if a[2] == b[2]
]


@pytest.mark.parametrize(("scene", "first", "second"), ELLIPSES)
def test_a_colour_or_size_said_alone_is_the_one_of_that_kind(
    scene: Scene, first: tuple[str, str, str], second: tuple[str, str, str]
) -> None:
    p, q = scene.humans[0].id, scene.humans[1].id
    np_, nq = name_of(scene, p), name_of(scene, q)
    text = f"{np_} wants the {first[0]} {first[2]}; {nq}, the {second[0]}"
    if first[1] == second[1]:
        assert_refused(text, scene)
    else:
        assert_means(text, f"{first[1]}>{p} & {second[1]}>{q}", scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Mia and Tom can each take a box",
            "(box_small>A & box_medium>B) | (box_small>A & "
            "box_large>B) | (box_medium>A & box_small>B) | (box_medium>A & box_large>B) | "
            "(box_large>A & box_small>B) | (box_large>A & box_medium>B)",
            DEPOT,
        ),
        ("Mia takes the small box; Tom, the large", "box_small>A & box_large>B", DEPOT),
        ("Put any pen you like in the box", "pen_black@box | pen_blue@box | pen_red@box", OFFICE),
        ("Give Lily any block she likes", "block_red>A | block_green>A", NURSERY),
        ("Both the knife and the tongs go to Marco", "knife>A & tongs>A", KITCHEN),
        ("Give Sam a pen, any except the red one", "pen_black>B | pen_blue>B", OFFICE),
        (
            "Give Person B two things, the chips and the cup, and Person A the other two",
            "chips>B & cup>B & bottle>A & apple>A",
            F41,
        ),
        ("Hand Ruth the only thermometer", "thermometer>A", WARD),
        ("Put the only stapler on the desk", "stapler@desk", OFFICE),
    ],
)
def test_each_any_both_and_counts(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Mia takes the small box to Tom", DEPOT),  # Mia carries it: not hers
        ("Priya and Sam can each take the stapler", OFFICE),
        ("Put any box you like on the belt and the pallet", DEPOT),  # one box, two places?
        ("Both the pens go to Sam", OFFICE),
        ("Give Lily a block, any except the red one and the green one", NURSERY),
        ("Give Person A two things, the bottle and the apple, and Person B the other three", F41),
        ("Give Person A three things, the bottle and the apple, and Person B the rest", F41),
        ("Give Sam the only pen", OFFICE),
    ],
)
def test_near_forms_of_each_any_both_and_counts_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- corrections and questions ---------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give the scanner to Tom, wait, Mia, yes Mia", "scanner>A", DEPOT),
        ("Hand the teddy to Ava, no, Lily, yes, Lily", "teddy>A", NURSERY),
        ("Knife to Lena, oops, I meant tongs to Lena", "tongs>B", KITCHEN),
        ("Hammer to Jess, sorry, I meant the drill to Kofi", "drill>A", WORKSHOP),
        ("Any chance Grandad could have the sippy cup?", "beaker>B", NURSERY),
        ("Is there any chance Tom could get the tape?", "tape>B", DEPOT),
        ("Give Marco the salt, sorry.", "salt>A", KITCHEN),
        # session 29 (12s): was refused only because 'I meant' was read as the cue 'I mean' and a
        # stray 't'; read now as 'oops, I mean …' is (the correction replaces the lemon)
        (
            "Salt to Marco and the lemon to Lena, oops, I meant the knife to Lena",
            "salt>A & knife>B",
            KITCHEN,
        ),
    ],
)
def test_corrections_and_chances(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Salt to Marco, oops, I meant", KITCHEN),  # cut off before what it names
        ("Give Marco the salt, no wait", KITCHEN),
        ("Give the scanner to Tom, wait, Mia, yes Tom", DEPOT),
        ("Any chance Lena has the knife?", KITCHEN),  # asks whether she has it
    ],
)
def test_near_forms_of_corrections_and_chances_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- wrong readings on main found by this session's fuzz -------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "No hurry, but would Bob like the cup?",
        "But is the apple on the shelf?",
        "Ok, but does Carol need the apple?",
        "Give Bob the chips and is the apple on the shelf?",
        "Could Bob have the chips, and would Alice like the cup?",
    ],
)
def test_a_question_after_but_or_and_is_not_a_request(text: str) -> None:
    assert_refused(text, match="question")


def test_requests_with_but_and_and_still_read() -> None:
    assert_means("Give Bob the chips, would you?", "chips>B")
    assert_means("Could Bob have the cup and Alice the apple?", "cup>B & apple>A")
    assert_means("And give Bob the chips", "chips>B")


def test_what_is_said_after_a_part_said_last_is_kept_or_refused() -> None:
    # on main the sentence after "…, the red one last." was dropped
    assert_means(
        "Give Priya the pens, the red one last. Give Sam the stapler.",
        "((pen_black>A & pen_blue>A) ; pen_red>A) & stapler>B",
        OFFICE,
    )
    assert_refused("Give Priya the pens, the red one last. Don't give Priya the black pen.", OFFICE)
    assert_refused("Give Priya the pens, the red one last, and Sam the stapler", OFFICE)


def test_a_negated_command_never_drops_a_task_of_the_request() -> None:
    # every task of every grounded request, negated after it, is refused
    for scene, text, _want in REQUESTS[:40]:
        got = tree(text, scene)
        assert got is not None, text
        for t in tasks(got):
            verb = "give" if t.kind == "deliver" else "put"
            o = name_of(scene, t.obj)
            said = (
                f"{text}. Don't give {name_of(scene, t.target)} the {o}."
                if t.kind == "deliver"
                else f"{text}. Don't {verb} the {o} on the {t.target}."
            )
            assert tree(said, scene) is None, f"{said!r} -> {show_tree(tree(said, scene))}"


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # on main 'but the small one' after the place was read as 'and the small one': every box
        (
            "Put every box on the pallet but the small one",
            "box_medium@pallet & box_large@pallet",
            DEPOT,
        ),
        ("Put the mugs on the shelf but the red one", "mug_blue@shelf", CELL),
        ("Give the mugs to Bob, but the red one", "mug_blue>B", CELL),
        ("Give all the mugs to Bob but the red one, please", "mug_blue>B", CELL),
        ("Give Bob the mugs but the red one", "mug_blue>B", CELL),
        # not one of them: 'but' adds, as before
        ("Give Bob the mugs but the apple", "mug_red>B & mug_blue>B & apple>B", CELL),
        ("Give Bob the chips but the apple to Carol", "chips>B & apple>C", CELL),
    ],
)
def test_but_one_of_them_after_the_place_leaves_it_out(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Hand the glue to Zoe or Noah, whoever wants it", "glue>C | glue>B", CLASSROOM),
        ("Could you, um, give the, uh, banana to Emma?", "banana>C", LAB),
        ("Is it possible for Emma to have the banana?", "banana>C", LAB),
        ("Would it be ok if Emma had the banana?", "banana>C", LAB),
        ("I was hoping Emma could have the banana", "banana>C", LAB),
        ("Don't forget to give Bob the chips", "chips>B", CELL),
        ("Make sure you don't give Bob the apple. Give Bob the chips.", "chips>B", CELL),
        (
            "Lily and Ava both want a block",
            "(block_red>A & block_green>C) | (block_green>A & block_red>C)",
            NURSERY,
        ),
        ("Sam's run out of pens, give him the black one", "pen_black>B", OFFICE),
        ("Mr Novak asked for the lemon ages ago", "lemon>C", KITCHEN),
        ("Bob is desperate for the chips", "chips>B", CELL),
        ("The only thing Bob wants is the chips", "chips>B", CELL),
        (
            "give bob three things: the cup, the apple and the chips",
            "cup>B & apple>B & chips>B",
            CELL,
        ),
        ("bob gets 2 things, the cup and the apple", "cup>B & apple>B", CELL),
        ("Bob needs a couple of things: the cup and the apple", "cup>B & apple>B", CELL),
        (
            "a mug for bob and one for carol",
            "(mug_red>B & mug_blue>C) | (mug_blue>B & mug_red>C)",
            CELL,
        ),
        ("I request you to give Tom the gloves", "gloves>B", DEPOT),
        ("For Mr Lee, the jug please", "jug>B", WARD),
        ("Mrs Khan is requesting the magazine", "magazine>C", WARD),
        ("Could you be a darling and bring Ruth the thermometer", "thermometer>A", WARD),
        ("Thermometer needs to get to Ruth asap", "thermometer>A", WARD),
        ("The guest hasn't had his salt yet", "salt>C", KITCHEN),
        ("Mia's on the phone but she needs the tape", "tape>A", DEPOT),
    ],
)
def test_how_more_people_ask(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Hand the glue to Zoe, whoever wants it", CLASSROOM),  # no choice to leave to them
        ("Priya and Sam both need the stapler", OFFICE),  # one stapler for two
        ("Make sure you don't give Bob the chips. Give Bob the chips.", CELL),
        ("Give Bob the apple tomorrow", CELL),
        ("give bob three things: the cup and the apple", CELL),  # the count does not fit
        ("a cup for bob and one for carol", CELL),  # one cup
        ("The guest hasn't had the salt or the lemon yet", KITCHEN),  # neither: both, or one?
        ("The guest hasn't had his salt yet, give him the lemon", KITCHEN),
        # 'to eat' is what is asked (which of them is to eat?), not what it is for
        ("Give Bob something to eat", CELL),
    ],
)
def test_near_forms_of_how_people_ask_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


@pytest.mark.parametrize(
    "text",
    [
        "Give Bob the chips. Don't give him the apple.",
        "Give Carol the cup, but do not give the apple to Bob",
        "Not to Bob, the apple goes to Carol",
    ],
)
def test_an_update_with_a_negated_command_beside_a_new_task_is_refused(text: str) -> None:
    # without a running spec the negated command leaves the apple alone; in an update it could
    # be cancelling the running apple for Bob, so it is refused instead of dropped
    grounder = OfflineGrounder()
    running = grounder.ground("Give Bob the apple", CELL).spec
    with pytest.raises(GroundingError, match="cancel"):
        ground_update(text, CELL, running, grounder)
    assert tree(text) is not None


# -- blind12's wrong readings (fixed after its one measurement, which stands) ----------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Priya the stapler. Put the stapler in the box.", None, OFFICE),
        ("Give Bob the cup and put it on the shelf", None, CELL),
        ("Hand Lily the bib, and the bib goes on the high chair", None, NURSERY),
        # placed first, then handed over, can be done as said
        ("Put the cup on the shelf and give it to Bob", "cup@shelf & cup>B", CELL),
        ("Give Bob the chips and put the cup on the shelf", "chips>B & cup@shelf", CELL),
        # ', any plate' says again that any will do
        (
            "Stick a plate on the worktop, any plate",
            "plate_white@counter | plate_blue@counter",
            KITCHEN,
        ),
        ("Give Lena a plate, either plate", "plate_white>B | plate_blue>B", KITCHEN),
        (
            "Give Bob a mug, any mug, and Carol the apple",
            "(mug_red>B | mug_blue>B) & apple>C",
            CELL,
        ),
        ("Give Lena the blue plate, any plate", None, KITCHEN),
        # found by the last fuzz run: the restated choice before more of the sentence, and an
        # apposition with 'one' after a person (it picks out an object: not dropped)
        (
            "Stick a plate on the worktop, any plate, but do not give the lemon to Marco",
            "plate_white@counter | plate_blue@counter",
            KITCHEN,
        ),
        # (refused in session 13; read in session 14, when "just the one cup …, the green one"
        # became the green cup)
        ("Just the one cup for Omar, the green one, thanks so so much", "cup_green>B", LAB),
    ],
)
def test_blind12_wrong_readings_as_families(text: str, want: str | None, scene: Scene) -> None:
    if want is None:
        assert_refused(text, scene)
    else:
        assert_means(text, want, scene)
