"""Session-25 phrasings of issue 12: blind23's three wrong readings fixed as families ('it' after
a list of objects, 'leave it' where it lies, a person getting it themself) and blind23's refusals
by kind (docs/grounding.md, "Session 25")."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.grounding.lexicon import Lexicon
from hltl.grounding.phrasing import starting_on
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    NURSERY,
    OFFICE,
    ROOT,
    SCENES,
    WORKSHOP,
    assert_reads,
    assert_refused,
    name_of,
    plain_request,
    unique_objects,
)

F41 = load_scene(ROOT / "examples/scenes/4-1.yaml")  # bottle, chips, cup, apple; A, B
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # bottle, chips (crisps); Alice, Bob


def _two_people(scene: Scene) -> tuple[tuple[str, str], tuple[str, str]]:
    """Two people of ``scene``, each (a name naming them alone, id)."""
    a, b = scene.humans[0], scene.humans[1]
    return (name_of(scene, a.id), a.id), (name_of(scene, b.id), b.id)


# -- (a) 'it' after a list of objects could mean any of them ------------------------------------


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(
        [
            "Give {p} the {o1} and the {o2}, and then give it to {q}.",
            "Give {p} the {o1} and the {o2}, then give it to {q}.",
            "Hand {p} the {o1} and the {o2} and after that pass it to {q}.",
            "Put the {o1} and the {o2} on the {s}, then give it to {q}.",
        ]
    ),
)
def test_it_after_a_list_of_objects_is_refused_with_each(scene: Scene, k: int, frame: str) -> None:
    # blind23: "Give Priya the black pen and the notepad, and then give it to Sam." read the
    # notepad moved from Priya to Sam: 'it' could be either object of the list
    objs = unique_objects(scene)
    o1, o2 = objs[k % len(objs)], objs[(k + 1) % len(objs)]
    (p, _), (q, _) = _two_people(scene)
    s = scene.surfaces[k % len(scene.surfaces)].id if scene.surfaces else "shelf"
    text = frame.format(p=p, q=q, o1=name_of(scene, o1), o2=name_of(scene, o2), s=s)
    if "{s}" in frame and not scene.surfaces:
        return
    assert_refused(text, scene, match=f"'it' .*could mean any of .*{o1}.*{o2}")


def test_the_blind23_it_sentence_and_its_near_forms() -> None:
    assert_refused(
        "Give Priya the black pen and the notepad, and then give it to Sam.",
        OFFICE,
        match="pen_black, notebook",
    )
    # one object before 'it', or 'them' for the list, or the object said again: read
    assert_reads("Pick up the stapler and give it to Sam.", "stapler>B", OFFICE)
    assert_reads(
        "Give Priya the black pen and the notepad, and then give Sam the stapler.",
        "(pen_black>A & notebook>A) ; stapler>B",
        OFFICE,
    )
    assert_reads(
        "Take the black pen and the notepad and give them to Sam.",
        "pen_black>B & notebook>B",
        OFFICE,
    )
    assert_reads(
        "Give Bob the cup. Then take the apple and put it on the shelf.", "cup>B ; apple@shelf"
    )


# -- (b) 'leave it' where it lies is no task -------------------------------------------------------


def _lying(scene: Scene) -> list[tuple[str, str]]:
    """(object, surface) of each object of ``scene`` that starts on a surface, when no other
    object shares its category."""
    lexicon = Lexicon.of(scene)
    alone = set(unique_objects(scene)) | {o.id for o in scene.objects if any(a for a in o.aliases)}
    return [
        (o, s.id)
        for s in scene.surfaces
        for o in starting_on({x.id for x in scene.objects}, s.id, lexicon)
        if o in alone
    ]


LYING = [(scene, o, s) for scene in SCENES for o, s in _lying(scene)]


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(LYING),
    st.integers(0, 20),
    st.sampled_from(
        [
            "{O}, leave it on the {s}. {req}.",
            "Leave the {o} on the {s} and {req}.",
            "{req}, and leave the {o} on the {s}.",
            "{O}: leave that on the {s}. Then {req}.",
        ]
    ),
)
def test_leaving_an_object_where_it_lies_is_no_task(
    lying: tuple[Scene, str, str], k: int, frame: str
) -> None:
    # blind23: "Red book for Noah. Green book, leave it on the shelf. Globe to Mrs Ortiz." read
    # the green book put on the shelf it lies on
    scene, oid, surface = lying
    req, want = plain_request(scene, k)
    if want.startswith(f"{oid}>"):
        return
    name = name_of(scene, oid)
    text = frame.format(O=name.capitalize(), o=name, s=surface, req=req)
    assert_reads(text, want, scene)


def test_the_blind23_leave_sentence_and_its_near_forms() -> None:
    assert_reads(
        "Red book for Noah. Green book, leave it on the shelf. Globe to Mrs Ortiz.",
        "book_red>B & globe>A",
        CLASSROOM,
    )
    # where it does not lie, 'leave it on the desk' puts it there
    assert_reads(
        "Red book for Noah. Green book, leave it on the desk.",
        "book_red>B & book_green@desk",
        CLASSROOM,
    )
    # leaving it where it lies, and nothing else: nothing to do
    assert_refused("Green book, leave it on the shelf.", CLASSROOM)


# -- (c) a person getting it themself, a request taken back --------------------------------------


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("The bib to Ava, no, to the baby, no, leave it, Ava can get it herself.", NURSERY),
        ("The bib to Ava, no, leave it, she can get it herself.", NURSERY),
        ("Give Ava the bib. Actually no, Ava can get it herself.", NURSERY),
        ("Ava can get the bib herself.", NURSERY),
        ("Bob can fetch the cup himself.", CELL),
        ("Give Bob the cup, no, leave it, he can get it himself.", CELL),
        ("Give Bob the cup, actually, never mind, Bob can grab it himself.", CELL),
    ],
)
def test_a_person_getting_it_themself_is_no_delivery(text: str, scene: Scene) -> None:
    # blind23: "The bib to Ava, no, to the baby, no, leave it, Ava can get it herself." read
    # `bib>C`: 'herself' was taken off as said of a person ('the foreman himself'), leaving
    # 'Ava can get it'
    assert_refused(text, scene)


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(
        [
            "{req}, no, leave it, {q} can get it.",
            "{req}, no, leave it.",
            "{req}. Actually, no, forget it.",
            "{req}, wait, never mind, {q} will sort it.",
            "{req}, sorry, leave that, thanks.",
        ]
    ),
)
def test_a_request_taken_back_is_refused(scene: Scene, k: int, frame: str) -> None:
    # 12c's take-back fuzz (session 25): "give Alice the cup please, no, leave it, Alice can get
    # it" read cup>A
    req, _ = plain_request(scene, k)
    (_, _), (q, _) = _two_people(scene)
    assert_refused(frame.format(req=req[0].upper() + req[1:], q=q), scene, match="takes back")


def test_a_request_taken_back_and_replaced() -> None:
    # one request taken back and a new one said: the new one is read
    assert_reads(
        "Put the cup on the table. Actually no, leave it, put the apple there instead.",
        "apple@table",
    )
    assert_reads("Give Bob the cup, no, leave it, give Carol the apple instead.", "apple>C")
    # two requests before it: which one is taken back is unclear
    assert_refused(
        "Bob wants the cup, hand it to him, and the apple to Alice, no, leave it, give Carol the "
        "chips instead",
        match="takes back",
    )
    # what it replaces is one task said in several stretches (a want and its handover, a remark,
    # a sentence of its own): since session 26 (test_phrasing_s26r.py) all of it is taken back
    # and the new request is read
    for text, want in (
        (
            "Bob wants the cup, hand it to him, no, leave it, give Alice the apple instead",
            "apple>A",
        ),
        (
            "Hand Alice the bottle, she's got a meeting in five, no, leave it, give Carol the "
            "apple instead",
            "apple>C",
        ),
        (
            "Alice needs the chips. Give them to her quickly. Forget that, sorry. Could you give "
            "Alice the cup?",
            "cup>A",
        ),
        (
            "Give Bob the apple, he wants it for lunch. Cancel that. Just hand Carol the cup.",
            "cup>C",
        ),
        (
            "Robot, give Alice the apple. Now. Forget that, sorry. Could you give Alice the cup?",
            "cup>A",
        ),
        (
            "Bottle on the shelf. That's all. Thank you, no, leave it, give Alice the cup instead",
            "cup>A",
        ),
    ):
        assert_reads(text, want)
    # a sentence that takes back one request, then a new one: the new one is read
    assert_reads("Give Alice the cup. Forget that, give her the bottle.", "bottle>A")
    assert_reads("Hand Bob the apple. Never mind, give it to Carol instead.", "apple>C")
    assert_reads("Give Bob the apple. Cancel that. Just hand Carol the cup.", "cup>C")
    # 'leave it on …' is a place, not a take-back
    assert_reads("Give Bob the cup, no, leave it on the shelf.", "cup@shelf")


def test_a_person_said_with_emphasis_still_reads() -> None:
    assert_reads(
        "Small spanner for the apprentice, big spanner for the foreman himself",
        "spanner_small>B & spanner_large>A",
        WORKSHOP,
    )
    assert_reads("The scanner for the supervisor herself", "scanner>A", DEPOT)
    assert_reads("Give the cup to Bob himself.", "cup>B")


# -- (d) courtesy words and titles of other languages; Patois function words --------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Salaam, lotfan give the cup to Person A, merci.", "cup>A", F41),
        ("Permisi, tolong give the bottle to Person A, terima kasih banyak.", "bottle>A", F41),
        (
            "Stapler to Bu Priya, then the notepad to Mas Sam, thank you.",
            "stapler>A ; notebook>B",
            OFFICE,
        ),
        ("Köszönöm, the crisps to Bob.", "chips>B", TWO),
        ("Jó napot! Please give Bob the crisps.", "chips>B", TWO),
        ("Give Person A the bottle, ah no, bebakhshid, the apple.", "apple>A", F41),
        ("Not di bottle, jus di crisps fi Bob.", "chips>B", TWO),
        ("Bless up, mek Bob get di bottle, respect.", "bottle>B", TWO),
        ("Right, listen. Give Bob the crisps.", "chips>B", TWO),
        ("Come on then, the crisps to Bob.", "chips>B", TWO),
        ("Lovely, give Bob the crisps.", "chips>B", TWO),
        ("Give Bob the crisps, eh sorry, the bottle.", "bottle>B", TWO),
        # closing stretches that ask for nothing
        ("Give Bob the crisps, house rules.", "chips>B", TWO),
        ("Give Bob the crisps, then we'll see.", "chips>B", TWO),
        ("Crisps to Bob, bottle to Alice, no more bets", "chips>B & bottle>A", TWO),
        ("Give Bob the crisps, the washing up can wait.", "chips>B", TWO),
        ("Give Bob the crisps, mind the wet floor.", "chips>B", TWO),
    ],
)
def test_courtesies_and_function_words_of_other_languages_read(
    text: str, want: str, scene: Scene
) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # a title before a name the scene does not have stays a name to refuse
        ("Stapler to Bu Dewi.", OFFICE),
        # 'di' before a word the scene does not have names nothing
        ("Put di kettle on the desk.", OFFICE),
        # a courtesy does not make a remark naming nothing a request
        ("Salaam, merci.", F41),
        # a closer naming something of the scene is no closer
        ("Give Bob the crisps, the bottle can wait.", TWO),
        ("Give Bob the crisps, mind the bottle.", TWO),
    ],
)
def test_courtesies_of_other_languages_add_nothing(text: str, scene: Scene) -> None:
    assert_refused(text, scene)
