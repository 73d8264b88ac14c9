"""Session-26 phrasings of issue 12 (engineer 12r): a request taken back and replaced, whatever
commas it holds (offline.py `_taken_back` / `_replaced`), and the speaker's want whose recipient
after a comma may open the next clause (phrasing.py `_listed_on` / `_verb_later`);
docs/grounding.md, "Session 26 (engineer 12r)"."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    SCENES,
    assert_reads,
    assert_refused,
    name_of,
    plain_request,
    unique_objects,
)

# -- (a) a request taken back and replaced -------------------------------------------------------

# the request taken back, said with commas around it (session 25's guard refused all of these)
_WRAPPED = (
    "Could you, please, {req}",
    "{Req}, please",
    "Right, {req}, thanks",
    "Sorry, {req}, no, {req_person}",
    "{Req}, she's been waiting",
)
# the take-back and the new request
_REPLACED = (
    "{old}, no, leave it, {new} instead.",
    "{old}. Actually, never mind that. {New} instead.",
    "{old}. Forget that, sorry. Could you {new}?",
    "{old}. Cancel that. Just {new}.",
    "{old}, wait, forget it, {new}.",
)


def _requests(scene: Scene, k: int) -> tuple[tuple[str, str], tuple[str, str], str]:
    """Two plain requests of ``scene`` naming different objects, and another person's name."""
    old, new = plain_request(scene, k), plain_request(scene, k + 1)
    other = scene.humans[(k + 1) % len(scene.humans)].id
    return old, new, name_of(scene, other)


@settings(max_examples=80, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(_WRAPPED),
    st.sampled_from(_REPLACED),
)
def test_a_request_taken_back_and_replaced_reads_the_new_one(
    scene: Scene, k: int, wrapped: str, replaced: str
) -> None:
    (old, _), (new, want), other = _requests(scene, k)
    if old.split(" the ")[-1] == new.split(" the ")[-1]:
        return  # one object only
    said = wrapped.format(req=old, Req=old[0].upper() + old[1:], req_person=other)
    text = replaced.format(old=said, new=new, New=new[0].upper() + new[1:])
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        # two requests before the take-back: which one it takes back is unclear
        "Give Alice the cup and Bob the apple, no, leave it, give Carol the chips instead.",
        "Give Alice the apple. Give Bob the cup, no, leave it, give Carol the chips instead.",
        "Could you, please, give Alice the cup and Bob the apple? Forget that. Hand Carol the "
        "chips.",
        # the new request points back at the one taken back, adds to it or orders itself after it
        "Could you, please, give Bob the cup, no, leave it, give Carol the apple too.",
        "Could you, please, give Bob the cup, no, leave it, give Carol the apple as well.",
        "Could you, please, give Bob the cup, no, leave it, give Carol the apple first.",
        "Could you, please, give Bob the cup, no, leave it, give Carol the other one.",
        "Right, give Bob the cup, thanks, no, leave it, give it to Carol after that.",
        # what is taken back does not read: nothing says it was one request
        "Could you, please, give Bob the spoon, no, leave it, give Carol the apple instead.",
        # taken back with nothing new after it
        "Could you, please, give Bob the cup, no, leave it.",
        "Could you, please, give Bob the cup, no, leave it, Carol can get it.",
    ],
)
def test_near_forms_of_a_replaced_request_stay_refused(text: str) -> None:
    assert_refused(text, CELL)


def test_replaced_requests_read_as_a_person_would() -> None:
    # session 25's trade-off: the commas of what is replaced no longer matter
    assert_reads(
        "Could you, please, give Bob the cup, no, leave it, give Carol the apple instead",
        "apple>C",
    )
    # what is replaced holds a correction of its own: the whole of it is taken back
    assert_reads("Give Bob the cup, no, Alice, no, leave it, give Bob the apple instead", "apple>B")
    # an earlier take-back, then a later one: the last one replaces what the first made
    assert_reads(
        "Hand Bob the apple. Never mind, give it to Carol instead, no, leave it, give Bob the "
        "crisps instead",
        "chips>B",
    )
    # the new request with its own place or its own two tasks
    assert_reads(
        "Could you, please, give Bob the cup, no, leave it, put the apple on the shelf instead.",
        "apple@shelf",
    )
    assert_reads(
        "Right, give Bob the cup, no, forget it, give Carol the apple and Alice the chips.",
        "apple>C & chips>A",
    )
    # pointing back: read by session 25's correction rules when what it replaces is one stretch
    assert_reads("Give Alice the cup. Forget that, give her the bottle.", "bottle>A")


# -- (b) the speaker's want, and a recipient that may open the next clause -----------------------


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(["We need", "I need", "I'd like", "We'd like"]),
    st.sampled_from(["{o2}, please give.", "the {o2}, hand it over.", "{o2}, pass it, thanks."]),
)
def test_a_recipient_between_a_want_and_a_request_is_refused(
    scene: Scene, k: int, want: str, then: str
) -> None:
    # fuzz wrong since session 25: "We need the chips, for Person B, bottle, please give. Thank
    # you." read chips>B & bottle>B — 'for Person B' may open the clause after it
    objs = unique_objects(scene)
    o1, o2 = objs[k % len(objs)], objs[(k + 1) % len(objs)]
    if o1 == o2:
        return
    p = name_of(scene, scene.humans[k % len(scene.humans)].id)
    text = f"{want} the {name_of(scene, o1)}, for {p}, " + then.format(o2=name_of(scene, o2))
    assert_refused(text, scene)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # the recipient closes the want, or the clause after it names its own person
        ("We need the chips, for Bob.", "chips>B"),
        ("We need the chips, for Bob, please.", "chips>B"),
        ("I need the chips, please, for Bob, thanks", "chips>B"),
        ("We need the chips, for Bob, and the bottle for Alice.", "chips>B & bottle>A"),
        ("We need the chips, for Bob, and give the bottle to Alice", "chips>B & bottle>A"),
        ("We need the chips, for Bob, then give Alice the bottle.", "chips>B ; bottle>A"),
    ],
)
def test_a_recipient_that_closes_the_want_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- (c) greetings, thanks and addresses of other languages --------------------------------------


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(
        [
            "Dobrý den! {Req}, please. Děkuji.",
            "Dobry den, prosím, {req}.",
            "Bună ziua, please, {req}. Mersi mult, you are very kind.",
            "Buna ziua, {req}, vă rog. Mulțumesc.",
            "Vanakkam! {Req}, nandri.",
            "Chale, {req}, eh? Thank you paa.",
            "Akwaaba! {Req}. Medaase.",
        ]
    ),
)
def test_courtesies_of_other_languages_read(scene: Scene, k: int, frame: str) -> None:
    # blind24: Czech, Romanian, Tamil and Ghanaian openers and closers were refused ('Dobrý' is
    # not a word the offline grounder reads; no person called 'Vanakkam' / 'Chale')
    req, want = plain_request(scene, k)
    assert_reads(frame.format(req=req, Req=req[0].upper() + req[1:]), want, scene)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Please give the crisps to Alice ma'am.", "chips>A"),
        ("Vanakkam! Please give the crisps to Bob sir, nandri.", "chips>B"),
        ("Give the cup to Carol madam, then the apple to Bob.", "cup>C ; apple>B"),
    ],
)
def test_an_address_after_a_persons_name_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        # the courtesy word stands for no one: the request still needs its person
        "Dobrý den! Please, give the bottle. Děkuji.",
        "Vanakkam, nandri.",
        # other words of those languages are still not read
        "Dobrý den! Dejte Bobovi láhev.",
        # an address after no person is no one
        "Give the crisps, ma'am.",
        "Give the crisps to Dana ma'am.",
        # courtesies around an object alone: no one to give it to
        "Chale, the bottle, nandri.",
    ],
)
def test_near_forms_of_courtesies_stay_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- (d) the speaker's own want after a request -------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        # 12c's fuzz (session 26): read as more for the last person named
        "Alice should get the cup, and we need the crisps",
        "Give Alice the cup, please. We want the water bottle as well.",
        "Hand Bob the apple, and I need the crisps.",
        "Carol's cold, so give her the cup, and we'd like the apple",
        # the lead's end of session 26 (12c's references fuzz): a want placed for someone does
        # not carry its recipient or surface into the speaker's next want
        "I need the crisps taken to Bob, and we need the water bottle",
        "We need the mugs on the counter, and we need the cup",
        "I'd like the apple brought to Carol and I need the chips.",
    ],
)
def test_the_speakers_own_want_after_a_request_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="the speaker is not a person")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # the speaker's want that names its recipient reads as before
        ("Give Alice the cup, and we need the crisps for Bob.", "cup>A & chips>B"),
        ("I need the apple and the cup brought to Carol", "apple>C & cup>C"),
        ("We need Bob to have the chips", "chips>B"),
        # two wants each naming its own recipient read as two tasks
        ("I need the crisps taken to Bob, and I need the cup taken to Alice", "chips>B & cup>A"),
        ("We need the apple for Carol, and we'd like the cup on the shelf.", "apple>C & cup@shelf"),
        # one want with more objects after the joint reads as before
        ("I need the crisps taken to Bob, and the water bottle", "chips>B & bottle>B"),
    ],
)
def test_the_speakers_want_naming_its_recipient_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)
