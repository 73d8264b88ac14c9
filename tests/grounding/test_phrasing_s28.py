"""Session-28 phrasings of issue 12 (engineer 12): a take-back after a choice of people, and what
is said after such a choice without a recipient of its own (docs/grounding.md, "Session 28
(engineer 12)")."""

from __future__ import annotations

import re

import pytest

from hltl.errors import GroundingError
from hltl.grounding.offline import parse_instruction
from tests.grounding.helpers import (
    CLASSROOM,
    DEPOT,
    KITCHEN,
    WORKSHOP,
    assert_reads,
    assert_refused,
    fits,
    tree,
)

# -- (a) a take-back after a choice ------------------------------------------------------------
#
# "Noah or Zoe, whichever student's free, give them the globe. Oh, don't bother." had read the
# globe to either student (the take-back fuzz, seed 27): the rewrite of 'P or Q, whichever <noun>
# is free, give them X' dropped every word after the request, and "Oh, don't bother" / "Sorry,
# cancel that" were not take-backs the grounder knew (they were refused only by chance).

CHOICES = [
    "Noah or Zoe, whichever student's free, give them the globe",
    "Noah or Zoe, whichever one is free, give them the globe",
    "Doesn't matter to me if it's Noah or Zoe that ends up with the globe",
    "I don't mind whether it's Noah or Zoe who gets the globe",
    "Give the globe to Noah or Zoe, whichever is free",
    "Give Noah or Zoe the globe, whichever's nearer",
    "Either Noah or Zoe can have the globe",
    "Give Noah the globe",
]
TAKE_BACKS = [
    ". Oh, don't bother.",
    ". Sorry, cancel that.",
    ". On second thoughts, forget it.",
    ", actually, forget the whole thing",
    ". Don't bother.",
    ". Cancel it.",
    ". Actually, never mind.",
    ", no, leave it",
    ". Oops, do not bother.",
]


@pytest.mark.parametrize("request_", CHOICES)
@pytest.mark.parametrize("back", TAKE_BACKS)
def test_a_take_back_after_a_choice_is_refused_as_one(request_: str, back: str) -> None:
    assert_refused(request_ + back, CLASSROOM, match="takes back the request")


@pytest.mark.parametrize("request_", CHOICES[:5])
def test_the_choice_alone_still_reads(request_: str) -> None:
    assert_reads(request_ + ".", "globe>B | globe>C", CLASSROOM)


def test_what_follows_the_whichever_rewrite_is_kept() -> None:
    # the rewrites of session 27 dropped a second request said after the first
    assert_reads(
        "Noah or Zoe, whichever student's free, give them the globe. Then the ruler to Noah.",
        "(globe>B | globe>C) ; ruler>B",
        CLASSROOM,
    )
    assert_reads(
        "Doesn't matter to me if it's Noah or Zoe that ends up with the globe. Also the ruler "
        "to Zoe.",
        "(globe>B | globe>C) & ruler>C",
        CLASSROOM,
    )


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # a new request after the take-back is the instruction
        ("Give Noah the globe. Don't bother, give Zoe the ruler instead.", "ruler>C"),
        ("Give Noah the globe. Actually, cancel that, give Zoe the ruler instead.", "ruler>C"),
        # 'oh' before more of the request is no take-back
        ("Give Noah the globe. Oh, the ruler too.", "globe>B & ruler>B"),
        ("Give Noah the globe. Oh, and the ruler to Zoe.", "globe>B & ruler>C"),
        ("Oh, give Noah the globe.", "globe>B"),
    ],
)
def test_near_sentences_read(text: str, want: str) -> None:
    assert_reads(text, want, CLASSROOM)


@pytest.mark.parametrize(
    "text",
    [
        # 'don't bother' / 'cancel' before more words: not the request taken back, and not read
        "Give Noah the globe. Oh, and don't bother with the ruler.",
        "Don't bother wrapping it, just give Noah the globe.",
    ],
)
def test_near_sentences_refused_otherwise(text: str) -> None:
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, CLASSROOM)
    assert "takes back" not in str(refused.value)


# -- (b) an object said after a choice of recipients or places ---------------------------------
#
# "Give the globe to Noah or Zoe. The ruler too." gave the ruler to Zoe (the last one named), and
# "…, and the ruler too" to Zoe only when she is chosen; the speaker means the ruler goes with the
# globe, to whoever gets it. Such an object now has no recipient to take over: refused, saying so.


@pytest.mark.parametrize(
    "text",
    [
        "Give the globe to Noah or Zoe. The ruler too.",
        "Give the globe to Noah or Zoe. And the ruler.",
        "Give the globe to Noah or Zoe, whichever is free. Oh, the ruler too.",
        "Give the globe to Noah or Zoe, whichever is free. Then the ruler.",
        "Give the globe to Noah or Zoe, and the ruler too.",
        "Give the globe to Noah or Zoe, whichever is free, and the ruler too.",
        "Give the globe to Noah or Zoe, the ruler too",
        "Put the globe on the shelf or the desk, and the ruler too.",
    ],
)
def test_an_object_after_a_choice_of_recipients_is_refused(text: str) -> None:
    assert_refused(text, CLASSROOM, match="choice|whichever is chosen")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # a person before the objects: more objects are that person's
        ("Give Noah the globe or Zoe the ruler and the glue.", "globe>B | (ruler>C & glue>C)"),
        ("Give Noah the globe, or Zoe, the ruler.", "globe>B | ruler>C"),
        ("Give the globe to Noah, Zoe, the ruler.", "globe>B & ruler>C"),
        # a choice of objects for one person keeps its one recipient
        ("Give Noah the globe or the ruler. The glue too.", "(globe>B | ruler>B) & glue>B"),
        # each recipient said
        (
            "Give the globe to Noah or Zoe, and give the ruler to Mrs Ortiz.",
            "(globe>B | globe>C) & ruler>A",
        ),
        ("Give the globe to Noah or to Zoe.", "globe>B | globe>C"),
        ("Give the globe to Noah. The ruler too.", "globe>B & ruler>B"),
    ],
)
def test_near_choices_read(text: str, want: str) -> None:
    assert_reads(text, want, CLASSROOM)


# -- (c) blind26's refusals by kind (politeness, wants, pronouns, lower case, typos, questions) --
#
# A reason said after the request that session 21's rule did not take: a subject of two or three
# words, a past tense, 'both' after a plural pronoun and its 'be', 'seeing as' opening it.


@pytest.mark.parametrize(
    "tail",
    [
        ", the bell ringers are starving",
        ", the late shift ran long",
        ", they're both glazing pots",
        ", we're both mid-shift",
        ", seeing as she's steaming felt",
        ", given that he's tired",
        ", the night crew finished early",
    ],
)
def test_a_reason_after_the_request_is_taken_off(tail: str) -> None:
    # session 34: a he / she that no first name said may be (Bob is a man's, Alice and Carol
    # women's) is someone else: refused naming the others, else the reason is taken off
    for request, want in (
        ("Give Bob the bottle", "bottle>B"),
        ("Chips to Alice and the cup to Carol", "chips>A & cup>C"),
    ):
        pronoun = re.search(r"\b(?:he|she)\b", tail)
        names = re.findall(r"\b(?:Bob|Alice|Carol)\b", request)
        if pronoun and not any(fits(name, pronoun.group(0)) for name in names):
            assert_refused(f"{request}{tail}.", match="cannot mean")
        else:
            assert_reads(f"{request}{tail}.", want)


@pytest.mark.parametrize(
    "tail",
    [
        ", they're both for Alice",  # says who gets them
        ", the other mug is dirty",  # points at an object
        ", the big boss wants it",  # someone the scene lacks wants it
        ", the red mug went cold",  # names an object
        ", they're both wanted by Carol",
        ", the night crew took the apple",
        ", the blue and the red",  # a list of objects left unsaid, no reason ('-ed' is no verb)
    ],
)
def test_a_reason_that_says_more_is_not_taken_off(tail: str) -> None:
    assert tree(f"Give Bob the bottle{tail}.") is None


# typed without apostrophes ('im', 'ive', 'dont' …): the contraction
def test_contractions_typed_without_the_apostrophe() -> None:
    assert_reads("give the crisps to bob pls, im on the till till five", "chips>B")
    assert_reads("the cup for carol, cheers, im off home", "cup>C")
    assert_refused("dont give bob the cup")


# what an object is for, with a possessive or a place after it, or 'ready for'
@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Bob wants the crisps for his break in the staff room, and Alice the cup.",
            "chips>B & cup>A",
        ),
        ("Put the cup on the table for the auditor's tally.", "cup@table"),
        ("The cup on the shelf, ready for the morning shift.", "cup@shelf"),
    ],
)
def test_a_purpose_with_more_words_is_taken_off(text: str, want: str) -> None:
    assert_reads(text, want)


@pytest.mark.parametrize(
    "text",
    [
        "Bob wants the crisps for the cup in the sink.",  # names an object
        "Put the cup on the table for the other one.",  # points back
        "Give Bob the cup for his break in the red mug.",
    ],
)
def test_a_purpose_naming_something_is_kept(text: str) -> None:
    assert tree(text) is None  # refused: never read as the bare request


# 'both' floating after two objects
def test_both_after_two_objects() -> None:
    assert_reads("the cup and the apple both on the shelf", "cup@shelf & apple@shelf")
    assert_reads("bottle and crisps both over to bob", "bottle>B & chips>B")
    # not two objects: 'both' still asks for two of what is named
    assert_refused("the cup and the mugs both on the shelf")
    assert_refused("Put the cup and the mug both on the shelf")  # which mug?


# '<objects>, same again' after a sentence: the task before, with these objects
def test_same_again() -> None:
    assert_reads("Hammer to Kofi. And the drill, same again.", "hammer>A & drill>A", WORKSHOP)
    assert_reads("The drill to Jess. Then the torch, same again.", "drill>B ; torch>B", WORKSHOP)
    assert_refused("Hammer to Kofi. Same again.", WORKSHOP)  # the same what?
    assert_refused("Hammer to Kofi. And Jess, same again.", WORKSHOP)  # a person: not an object


# an object that wants / needs to go somewhere: put there
def test_an_object_that_wants_to_go_somewhere() -> None:
    assert_reads("The small box wants to sit on the pallet.", "box_small@pallet", DEPOT)
    assert_reads("The tape needs to go on the belt, please.", "tape@conveyor", DEPOT)
    assert_refused("The small box needs to stay on the pallet.", DEPOT)  # not to move
    assert_refused("Mia wants to go on the pallet.", DEPOT)  # a person


# courtesies of other languages said alone (Yoruba, Finnish, Albanian), and tags that ask only
# whether the request is all right
def test_courtesies_and_tags() -> None:
    assert_reads("E kaaro. Please give Bob the bottle, e se gan.", "bottle>B")
    assert_reads("Ole hyvä, crisps to Bob, the cup to Alice. Kiitti.", "chips>B & cup>A")
    assert_reads("Moi! The apple to Carol, faleminderit.", "apple>C")
    assert_reads("You will give the cup to Carol, na? She is on the phone since ten.", "cup>C")
    assert_reads("Can the cup go on the shelf, or is that a pain?", "cup@shelf")
    assert_reads("Could Bob have the apple, or is that asking too much?", "apple>B")
    # 'na' before more words may be 'nah' (a correction): not a tag
    assert tree("Give Alice the cup, na, the apple.") is None
    assert_refused("Can the cup go on the shelf, or is that the table?")


# who the speaker or a person is, and where a person is, said beside the request
def test_who_and_where_said_beside_the_request() -> None:
    assert_reads("Hi, the baker here, would you put the cup on the shelf?", "cup@shelf")
    assert_reads("The plumber, Bob, is asking for the apple.", "apple>B")
    assert_reads("Alice, up at the front desk, wants the crisps.", "chips>A")
    # a role or a place of the scene is not taken off
    assert tree("The shelf, Bob, is asking for the apple.") is None
    assert tree("Alice, up on the shelf, wants the crisps.") is None


# an object for a person's thing is for that person; not in a placement
def test_for_a_persons_thing() -> None:
    assert_reads("The crisps for Bob's lunch, please.", "chips>B")
    assert_reads("A lemon for Mr Novak's fish.", "lemon>C", KITCHEN)
    assert_reads("A leemon for Mr Novak.", "lemon>C", KITCHEN)  # a typo of a kind
    assert tree("Put the cup on the shelf for Bob's lunch.") != tree("Give Bob the cup.")


# "If you'd be so good as to X, that'd be grand": X
def test_if_you_would_be_so_good() -> None:
    assert_reads(
        "Morning. If you'd be so good as to take the cup to Carol, that'd be grand.", "cup>C"
    )
    assert_reads("If you wouldn't mind, give Bob the apple.", "apple>B")
    assert_refused("If Bob is free, that'd be grand.")  # no request


# two objects that stay where they are: nothing to do with them
def test_two_objects_stay_put() -> None:
    assert_reads("crisps to alice, cup to bob, apple and bottle stay put", "chips>A & cup>B")
    # not when another clause moves them, or counts every object
    assert tree("Give Bob the apple, apple and bottle stay put.") is None
    assert tree("Everything to Bob, the apple and the bottle stay put.") != tree(
        "Give Bob the cup."
    )


# idioms of handing over
def test_handed_over() -> None:
    assert_reads("Put the crisps in Bob's hands.", "chips>B")
    assert_reads("Put the cup in Carol's hands, then the apple.", "cup>C ; apple>C")
    assert_reads(
        "Both of the bakers want something: Alice the cup, Bob the apple.", "cup>A & apple>B"
    )
    assert_reads("tongs on the rack please, marco needs them out of the way", "tongs@rack", KITCHEN)
    # 'them' given something after one person alone: that person; after two, or none: refused
    assert_reads("Bob's got nothing yet. Give them the crisps.", "chips>B")
    assert_refused("Give them the apple.")
    assert_refused("Alice and Bob are here. Give them the apple.")
    assert_refused("Both of the shelf want something: Alice the cup, Bob the apple.")


# 'since <a past time>' in a remark of how long someone has been at something
def test_since_a_past_time_in_a_remark() -> None:
    assert_reads(
        "Alice wants the cup, she's been on the till since seven, so get it to her.", "cup>A"
    )
    assert_reads(
        "Bob wants the apple, he's been on shift since morning, so hand it over.", "apple>B"
    )
    # 'since' giving a reason is not a time taken off: what follows still counts
    assert (
        tree("Alice wants the cup, she's been on the till since Bob left, so get it to her.")
        is None
    )
