"""Session-29 phrasings of issue 12 (engineer 12r): three doubtful readings on main mended (a word
saying 'no' taken off as a filler, 'one thing each' with one person named, an object said after an
exclusion), then blind27's kinds; docs/grounding.md, "Session 29 (engineer 12r)". Each rule with
the sentences it changes and near forms that must still read, or stay refused."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

# -- (1a) a word saying 'no' is the correction cue 'no', never a filler ------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # 'Na' had been taken off as a word the grounder does not know: both objects to Alice
        ("Give Alice the cup. Na, the apple.", "apple>A", CELL),
        ("Give Alice the cup. Nae, the apple.", "apple>A", CELL),
        ("Give Alice the cup. Nein, the apple.", "apple>A", CELL),
        # these were refused as names the scene lacks
        ("Give Alice the cup. Nah, the apple.", "apple>A", CELL),
        ("Give Alice the cup, nah, the apple.", "apple>A", CELL),
        ("Give Alice the cup, nope, the apple.", "apple>A", CELL),
        ("Give Alice the cup. Naw, Bob.", "cup>B", CELL),
        ("Give Alice the cup. Nope, give Bob the apple.", "apple>B", CELL),
        ("Ruth needs the jug. Nah, the pills.", "pills>A", WARD),
        # read before as both objects ('nuh-uh' taken off as a word of no meaning)
        ("Give Alice the cup. Nuh-uh, the apple.", "apple>A", CELL),
        ("Give Alice the cup. Uh-uh, the apple.", "apple>A", CELL),
    ],
)
def test_a_word_saying_no_corrects(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        # 'no' alone after a request names nothing to change to (as "Give Alice the cup. No."):
        # 'Na.' had been taken off as a chat token, 'Nah.' / 'Nope!' as a sentence saying nothing
        "Give Alice the cup. Na.",
        "Give Alice the cup. Nah.",
        "Give Alice the cup. Nope!",
        "Give Alice the cup. Oh, nah.",
        "Give Alice the cup. Uh-uh.",
        "Na, give Alice the cup.",
    ],
)
def test_no_alone_is_refused(text: str) -> None:
    assert_refused(text, CELL)


def test_na_between_commas_names_both_readings() -> None:
    # Hindi English's tag ('…, na?', isn't it) or 'nah': which is unclear before more words
    assert_refused("Give Alice the cup, na, the apple.", CELL, match="could be 'nah'")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # the tag, 'na' of another language and 'nae bother' read as before
        ("Give Alice the cup, na?", "cup>A", CELL),
        ("You will give the cup to Carol, na? She is on the phone since ten.", "cup>C", CELL),
        ("Give Alice the cup. Na gode.", "cup>A", CELL),
        ("Give Alice the cup, nae bother.", "cup>A", CELL),
        ("Give Alice the cup, no worries.", "cup>A", CELL),
        ("Give Alice the cup, uh, thanks.", "cup>A", CELL),
    ],
)
def test_near_forms_read_as_before(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- (1b) 'one thing each' before a list naming one person ---------------------------------------


@pytest.mark.parametrize(
    ("text", "scene", "match"),
    [
        # read before as the one hand-over, 'each' unheard
        ("One thing each: the tape for Mia.", DEPOT, "say what Tom gets as well"),
        ("one item each: the tape for Mia.", DEPOT, "say what Tom gets as well"),
        ("One each: the tape for Mia.", DEPOT, "say what Tom gets as well"),
        ("One apiece, the tape for Mia.", DEPOT, "leave out 'apiece'"),
        ("One thing each: the salt for Lena.", KITCHEN, "what Marco and what Mr Novak get"),
    ],
)
def test_each_with_one_person_is_refused(text: str, scene: Scene, match: str) -> None:
    assert_refused(text, scene, match=match)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("One thing each: the tape for Mia and the scanner for Tom.", "tape>A & scanner>B", DEPOT),
        ("One each: the tape for Mia, the scanner for Tom.", "tape>A & scanner>B", DEPOT),
        ("One thing for Mia: the tape.", "tape>A", DEPOT),
        ("Two things for Mia: the tape and the scanner.", "tape>A & scanner>A", DEPOT),
    ],
)
def test_each_with_each_person_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- (1c) an object said after an exclusion, with no 'and' -------------------------------------


@pytest.mark.parametrize(
    ("text", "match"),
    [
        # read before as the torch and the hammer
        ("Give Kofi the torch, not the drill, the hammer.", "one more thing besides 'torch'"),
        ("Give Kofi the torch, not the drill, the hammer too.", "meant in place of 'torch'"),
        ("The torch, not the drill, the hammer for Kofi.", "meant in place of 'torch'"),
        ("Give Kofi a spanner, not the small one, the hammer.", "one more thing besides"),
        ("Give Kofi the torch - not the drill - the hammer.", "one more thing besides"),
        ("Give Kofi the torch — not the drill — the hammer.", "one more thing besides"),
        # read before as the hammer alone
        ("Give Kofi everything except the drill, the hammer.", "one more left out"),
        ("Give Kofi everything but the drill, the hammer.", "one more left out"),
    ],
)
def test_an_object_after_an_exclusion_is_refused(text: str, match: str) -> None:
    assert_refused(text, WORKSHOP, match=match)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Kofi the torch, not the drill, and the hammer.", "torch>A & hammer>A", WORKSHOP),
        ("Give Kofi the torch and the hammer, not the drill.", "torch>A & hammer>A", WORKSHOP),
        ("Give Kofi the torch, not the drill.", "torch>A", WORKSHOP),
        ("Give Kofi the torch, not the drill, thanks.", "torch>A", WORKSHOP),
        # the one meant: one of those left, of the kind left out, or the same said again
        ("Give Kofi a spanner, not the small one, the big one.", "spanner_large>A", WORKSHOP),
        ("Give Tom a box, not the small one, the large one.", "box_large>B", DEPOT),
        ("Give Tom a box - not the small one - the large one.", "box_large>B", DEPOT),
        ("Give Kofi the torch - not the drill - and the hammer.", "torch>A & hammer>A", WORKSHOP),
        ("The cup to Alice, not the chips, the cup.", "cup>A", CELL),
        # a clause of its own: a person after it, and one before
        (
            "Give Kofi the torch, not the drill, the hammer for Jess.",
            "torch>A & hammer>B",
            WORKSHOP,
        ),
        ("Give Bob the cup, not the apple, the chips for Carol.", "cup>B & chips>C", CELL),
        (
            "Give Kofi everything except the drill and the hammer.",
            "spanner_small>A & screws>A & torch>A & spanner_large>A",
            WORKSHOP,
        ),
    ],
)
def test_near_exclusions_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- (2) blind27's kinds: corrections with a reason ------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # the reason names the person the corrected words name again, 'so' before them
        (
            "The bottle goes to Bob, hang on, no, Alice is the thirsty one, so to Alice.",
            "bottle>A",
            CELL,
        ),
        # a cue opening a sentence, the reason closed by a semicolon
        ("Give Alice the chips. Wait, no, she's fasting; the bottle instead.", "bottle>A", CELL),
        ("Give Alice the chips, no, she's fasting; the bottle instead.", "bottle>A", CELL),
        # a cleft naming the corrected object, its subject the one person named before
        ("Pass Bob the chips, no, that's wrong, it's the bottle he asked for.", "bottle>B", CELL),
        ("Pass Bob the chips, no, it's the bottle Bob wants.", "bottle>B", CELL),
        ("Give Sam the red pen, no, it's the blue pen he wants.", "pen_blue>B", OFFICE),
    ],
)
def test_a_correction_with_a_reason_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # the reason names someone the corrected words do not
        ("The bottle goes to Bob, hang on, no, Alice is the thirsty one, so to Carol.", CELL),
        ("The bottle goes to Bob, hang on, no, Alice is the thirsty one, so the crisps.", CELL),
        # 'so' after a reason about 'she': which person is unclear
        ("The bottle goes to Bob, no, she's thirsty, so to Alice.", CELL),
        # a reason that negates
        ("Give Alice the chips. Wait, no, she's not hungry; the bottle instead.", CELL),
        # the cleft's subject is not the person named before, or two were named
        ("Give Mr Lee the jug, no, it's the pills she asked for.", WARD),
        ("Pass Bob the chips, no, it's the bottle Alice wants.", CELL),
        ("Pass Bob the chips and Carol the cup, no, it's the bottle he asked for.", CELL),
    ],
)
def test_near_corrections_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- (2) choices, counts and sharing -------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Bob can take the bottle or the crisps, whichever comes to hand.",
            "bottle>B | chips>B",
            CELL,
        ),
        (
            "Give Mia the tape or the gloves; pick whichever you can reach.",
            "tape>A | gloves>A",
            DEPOT,
        ),
        ("Mia only needs the tape.", "tape>A", DEPOT),
        (
            "Mia only needs one of them, the tape or the gloves; pick whichever you can reach.",
            "tape>A | gloves>A",
            DEPOT,
        ),
        (
            "Give Ava any one toy, the teddy or a block, whichever.",
            "teddy>C | block_red>C | block_green>C",
            NURSERY,
        ),
        ("There's only one bottle, and Alice should have it.", "bottle>A", CELL),
        (
            "Something each for the two of them: Mia's to get the tape, Tom the scanner.",
            "tape>A & scanner>B",
            DEPOT,
        ),
        (
            "Split the two mugs between Alice and Bob, one apiece.",
            "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
            CELL,
        ),
        (
            "One blanket for each of the two patients, whichever way round.",
            "(blanket_blue>B & blanket_grey>C) | (blanket_grey>B & blanket_blue>C)",
            WARD,
        ),
    ],
)
def test_choices_and_counts_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # how to choose, after no choice of objects
        ("Give Bob the cup, whichever comes to hand.", CELL),
        ("Give Bob or Carol the cup, whichever comes to hand.", CELL),
        # 'them' after objects named before; a kind the list does not name
        ("Give Mia the scanner. She needs one of them, the tape or the gloves.", DEPOT),
        ("Give Ava any one block, the teddy or the wipes.", NURSERY),
        # 'only one' where the scene has two
        ("There's only one mug, and Alice should have it.", CELL),
        # 'each' with one, or a count the list does not give
        ("Something each for the two of them: Mia's to get the tape.", DEPOT),
        ("Something each for the three of them: Mia gets the tape, Tom the scanner.", DEPOT),
        # one thing split
        ("Split the cup between Alice and Bob, one apiece.", CELL),
    ],
)
def test_near_choices_and_counts_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


def test_a_count_of_people_the_scene_lacks_is_refused() -> None:
    # read before as the two patients, the count unheard
    assert_refused(
        "One blanket for each of the three patients.", WARD, match="the scene has 2 .*not 3"
    )
    assert_refused("A book for each of the three students.", CLASSROOM, match="not 3")


# -- (2) negation and exclusion ------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("None of it to Alice; the apple and the cup go to Bob.", "apple>B & cup>B", CELL),
        ("Don't leave the bottle where it is; hand it to Alice.", "bottle>A", CELL),
        (
            "Apart from the bottle, give Alice whatever's there.",
            "cup>A & chips>A & apple>A & mug_red>A & mug_blue>A",
            CELL,
        ),
        (
            "Bob is welcome to the lot, bar the apple and the bottle.",
            "cup>B & chips>B & mug_red>B & mug_blue>B",
            CELL,
        ),
        ("Bob is welcome to the apple.", "apple>B", CELL),
        (
            "Mia wants all the kit except the boxes: that's the scanner, the tape and the gloves.",
            "scanner>A & tape>A & gloves>A",
            DEPOT,
        ),
        ("The chips aren't for Alice; they're Bob's, so hand them over to Bob.", "chips>B", CELL),
    ],
)
def test_negation_said_another_way_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # the request after it gives the person said first, or places
        ("None of it to Alice; the apple and the cup go to Alice.", CELL),
        ("None of it to Alice; put the apple on the shelf.", CELL),
        # the request after it moves something else
        ("Don't leave the bottle where it is; hand the cup to Alice.", CELL),
        # 'whatever's there' with nothing left out first
        ("Give Alice whatever's there.", CELL),
        # the list is not what 'all … except' leaves
        ("Mia wants all the kit except the boxes: that's the scanner and the tape.", DEPOT),
        # the request does not hand them to whose they are said to be
        ("The chips aren't for Alice; they're Bob's, so hand them over to Carol.", CELL),
        ("The chips aren't for Alice; they're Alice's, so hand them over to Alice.", CELL),
    ],
)
def test_near_negations_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


def test_not_the_one_with_a_clause_names_its_readings() -> None:
    # 'but not' must be followed by the objects to leave out: which block is left out?
    assert_refused(
        "Give Grandad a block, but not the one Lily has been chewing.",
        NURSERY,
        match="block_green or block_red",
    )
    assert_reads("Give Grandad a block, but not the red one.", "block_green>B", NURSERY)


# -- (2) who acts, where things must end up, what a header or a cleft says -------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("I don't mind which of your arms does it, give Bob the cup.", "cup>B", CELL),
        ("The bottle needs to reach Alice.", "bottle>A", CELL),
        (
            "Kofi wants the pair of spanners tidied away: both onto the locker.",
            "spanner_small@locker & spanner_large@locker",
            WORKSHOP,
        ),
        (
            "Bob wants the mugs for the office: both onto the shelf.",
            "mug_red@shelf & mug_blue@shelf",
            CELL,
        ),
        (
            "The concierge wants two plates for room service: both of them onto the worktop, "
            "please.",
            "plate_white@counter & plate_blue@counter",
            KITCHEN,
        ),
        (
            "Three things for Bob to take to the dairy: the cup, the apple and the chips.",
            "cup>B & apple>B & chips>B",
            CELL,
        ),
        ("It's the cup Alice wants for the tasting, not the bottle.", "cup>A", CELL),
        ("It's the cup Alice wants, not the bottle.", "cup>A", CELL),
    ],
)
def test_headers_and_clefts_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("I don't mind which cup, give Bob one.", CELL),
        # two mugs; a surface is not reached by a hand-over
        ("The mug needs to reach Alice.", CELL),
        ("The bottle needs to reach the shelf.", CELL),
        # 'both' of one object; a purpose naming a person; a person for a surface
        ("Kofi wants the hammer tidied away: both onto the locker.", WORKSHOP),
        ("Bob wants the mugs for Carol: both onto the shelf.", CELL),
        ("Bob wants the mugs for the office: both onto Carol.", CELL),
        # where they are taken names a person
        ("Three things for Bob to take to Carol: the cup, the apple and the chips.", CELL),
        # the cleft's purpose names a person; its object is one of two
        ("It's the cup Alice wants for Bob, not the bottle.", CELL),
        ("It's the mug Alice wants, not the bottle.", CELL),
    ],
)
def test_near_headers_and_clefts_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- a correction that adds ('too') -------------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        # each read before as the bottle alone ('too' a filler), the chips taken back
        "Give Alice the chips, no, the bottle too.",
        "Give Alice the chips. No, the bottle too.",
        "Give Alice the chips, no wait, the bottle too.",
        "Give Alice the chips, sorry, the bottle too.",
        "Give Alice the chips, no, the bottle as well.",
        "Give Alice the chips, no, also the bottle.",
        # read before as the chips to Bob alone
        "Give Alice the chips, no, Bob too.",
    ],
)
def test_a_correction_that_adds_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="replace what was said before, or add")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Alice the chips, no, the bottle.", "bottle>A"),
        ("Give Alice the chips, no, just the bottle.", "bottle>A"),
        # 'too' of a new request after 'and', or of another sentence
        ("Give Alice the chips, no, Carol, and the apple too.", "chips>C & apple>C"),
        ("Give Alice the chips, oh and the bottle too.", "chips>A & bottle>A"),
        ("Give Alice the chips, no, the bottle. Bob wants the apple too.", "bottle>A & apple>B"),
    ],
)
def test_near_corrections_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


def test_too_saying_how_is_no_addition() -> None:
    # "she's too big": not 'too' adding a thing; since session 33 (12r, `_cue_remark33r`) the
    # remark about Ava is taken off and the correction reads (the bib to Lily alone)
    assert_reads("Bib to Ava, oh no, she's too big for bibs, to Lily.", "bib>A", NURSERY)


# -- what an exclusion leaves out must be said -------------------------------------------------


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # each read before as leaving out both mugs (every other object to Bob)
        ("Give Bob all but one of the mugs.", CELL),
        ("Give Bob all but one mug.", CELL),
        ("Give Bob everything but one of the mugs.", CELL),
        ("Give Bob all except one of the mugs.", CELL),
        ("Give Bob everything but a mug.", CELL),
        ("Give Bob everything but the mug.", CELL),
        ("Give Bob everything except the cup and the mug.", CELL),
        ("Give Tom everything except the box.", DEPOT),
    ],
)
def test_one_of_several_left_out_names_its_readings(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="does not say which one is left out: it could be")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Bob everything but the mugs.", "cup>B & bottle>B & chips>B & apple>B", CELL),
        (
            "Give Bob everything except the red mug.",
            "cup>B & bottle>B & chips>B & apple>B & mug_blue>B",
            CELL,
        ),
        ("Give Bob the mugs, not the red one.", "mug_blue>B", CELL),
        ("Give Tom everything except the boxes.", "scanner>B & tape>B & gloves>B", DEPOT),
        # a contrast: no mug is left out of the cup, which mug does not matter
        ("Give Bob the cup, not the mug.", "cup>B", CELL),
    ],
)
def test_what_is_left_out_said_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


def test_a_correction_after_but_everything_is_refused_as_after_except() -> None:
    # read before as everything but the apple (the correction taken to change what is left out)
    assert_refused(
        "Give Bob everything but the cup, no, the apple.", CELL, match="change what is left out"
    )
    assert_refused("Give Bob everything except the cup, no, the apple.", CELL)
    # 'but' between requests: the correction changes the person, as before
    assert_reads("Give Bob the cup but the apple to Carol, no, Alice.", "cup>B & apple>A", CELL)


# -- 'not the other way round'; 'each' with one person ------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # read before as the swap ('not' taken as the correction's 'no'): a wrong reading
        ("Give Bob the cup and Carol the apple, not the other way round.", "cup>B & apple>C"),
        ("Give Bob the cup and Carol the apple, not vice versa.", "cup>B & apple>C"),
        ("Give Bob the cup and Carol the apple. Not the other way round!", "cup>B & apple>C"),
        (
            "Put the cup on the shelf and the apple on the table, not the other way round.",
            "cup@shelf & apple@table",
        ),
        # the swap and the choice, as before
        ("Give Bob the cup and Carol the apple, no, the other way round.", "apple>B & cup>C"),
        (
            "Give Bob the cup and Carol the apple, or the other way round.",
            "(cup>B & apple>C) | (apple>B & cup>C)",
        ),
    ],
)
def test_not_the_other_way_round_keeps_the_request(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


def test_a_swap_cue_beside_not_is_refused() -> None:
    assert_refused(
        "Give Bob the cup and Carol the apple, no, not the other way round.",
        CELL,
        match="keep what was said, or swap it",
    )


@pytest.mark.parametrize(
    "text",
    [
        # each read before as one mug for Bob, 'each' unheard
        "Give Bob one mug each.",
        "Give Bob a mug each.",
        "Bob gets a mug each.",
        "Give Bob the cup and a mug each.",
    ],
)
def test_each_with_one_person_is_refused_in_the_grammar(text: str) -> None:
    assert_refused(text, CELL, match="shares out among several people")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Give Bob and Carol a mug each.",
            "(mug_red>B & mug_blue>C) | (mug_blue>B & mug_red>C)",
            CELL,
        ),
        (
            "Bob and Carol would each like a mug.",
            "(mug_red>B & mug_blue>C) | (mug_blue>B & mug_red>C)",
            CELL,
        ),
        (
            "Give the students a book each.",
            "(book_red>B & book_green>C) | (book_green>B & book_red>C)",
            CLASSROOM,
        ),
    ],
)
def test_each_with_several_people_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)
