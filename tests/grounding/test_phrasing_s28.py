"""Session-28 phrasings of issue 12 (engineer 12): a take-back after a choice of people, and what
is said after such a choice without a recipient of its own (docs/grounding.md, "Session 28
(engineer 12)")."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding.offline import parse_instruction
from tests.grounding.helpers import CLASSROOM, assert_reads, assert_refused

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
